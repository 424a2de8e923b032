// Momenta, wrenches and inertias in Cl(0,6,2) (paper §5–6): the algebra Cl(0,3,1) of §3 doubled.
// The generators a1 a2 a3 a carry co-screws, e1 e2 e3 e carry screws; the bar involution swaps
// them (ā_i = e_i, ā = e).
//
//   co-screw   P = lx a1a + ly a2a + lz a3a + px a2a3 + py a3a1 + pz a1a2      (l, p)
//   inertia    N = Σ N(i,j) α_i ε̃_j                                           (§5)
//   mobility   M = Σ M(i,j) α̃_j ε_i                                           (N⁻¹ as an element)
//
// with α = (a1a, a2a, a3a, a2a3, a3a1, a1a2) the co-screw blades in (l, p) order,
// ε = (e2e3, e3e1, e1e2, e1e, e2e, e3e) the screw blades in (ω, v) order, and x̃ the complement
// of a blade within its half (ε̃_j = ε_{j±3}, so ε̃_j ∧ ε_j = e1e2e3e = E). With these orientations
// the coefficient of a blade is exactly the entry of the 6×6 matrix of §2:
//
//   A ∨ (N ∧ s) = N s      (the momentum, §5)        E ∨ (M ∧ P) = M P     (the velocity)
//
// so the diagonal inertia of §5 is N = dx a1ae1e + … + m a2a3e2e3 + …, and the paper's
// translation example reads entry by entry off the 6×6 matrix printed beside it.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

#include "ctga/algebra/operations.hpp"
#include "ctga/algebras.hpp"
#include "ctga/expr/inline.hpp"
#include "ctga/mechanics/motion.hpp"

namespace ctga {

namespace spatial_detail {

inline constexpr std::array<std::string_view, 6> screw_blade{"e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e"};
inline constexpr std::array<std::string_view, 6> coscrew_blade{"a1a", "a2a", "a3a", "a2a3", "a3a1", "a1a2"};

// The blade a·b written as the two names side by side, read by the algebra (orientation included).
constexpr parsed_blade join(std::string_view a, std::string_view b) noexcept {
    std::array<char, 16> buf{};
    std::size_t n = 0;
    for (char c : a) buf[n++] = c;
    for (char c : b) buf[n++] = c;
    return cl062::parse_blade(std::string_view(buf.data(), n));
}

// Entry (i, j) of a 6×6 matrix as a blade: α_i ε̃_j for inertias, α̃_j ε_i for mobilities.
struct entry {
    int row, col;
};
constexpr parsed_blade inertia_blade(entry e) noexcept {
    return join(coscrew_blade[static_cast<std::size_t>(e.row)], screw_blade[static_cast<std::size_t>((e.col + 3) % 6)]);
}
constexpr parsed_blade mobility_blade(entry e) noexcept {
    return join(coscrew_blade[static_cast<std::size_t>((e.col + 3) % 6)], screw_blade[static_cast<std::size_t>(e.row)]);
}

// A rigid body's inertia [[I_o, m Ĉ], [m Ĉᵀ, m 1]] (§2) has structural zeros: the mass block is
// m times the identity and the coupling block m Ĉ is antisymmetric, so 12 of the 36 entries are
// zero in every frame (the transformation law H⁻ᵀ N H⁻¹ preserves the form).
constexpr bool rigid_structural_zero(entry e) noexcept {
    const bool mass_block_off_diagonal = e.row >= 3 && e.col >= 3 && e.row != e.col;
    const bool coupling_diagonal = (e.row + 3) % 6 == e.col && (e.row < 3) != (e.col < 3);
    return mass_block_off_diagonal || coupling_diagonal;
}

template <std::size_t N>
struct matrix_entries {
    std::array<entry, N> at{};
};

template <bool Rigid>
constexpr auto entries() {
    constexpr std::size_t n = Rigid ? 24 : 36;
    matrix_entries<n> out;
    std::size_t k = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            if (!Rigid || !rigid_structural_zero({i, j})) out.at[k++] = {i, j};
    return out;
}

template <std::size_t N, class Blade>
constexpr layout<N> matrix_layout(const matrix_entries<N>& e, Blade blade) {
    layout<N> l;
    for (std::size_t k = 0; k < N; ++k) {
        const parsed_blade b = blade(e.at[k]);
        l.masks[k] = b.mask;
        l.signs[k] = static_cast<signed char>(b.sign);
    }
    return l;
}

inline constexpr auto all_entries = entries<false>();
inline constexpr auto rigid_entries = entries<true>();
inline constexpr auto inertia_layout = matrix_layout(all_entries, inertia_blade);
inline constexpr auto rigid_inertia_layout = matrix_layout(rigid_entries, inertia_blade);
inline constexpr auto mobility_layout = matrix_layout(all_entries, mobility_blade);

// Cl(0,3,1) sits in Cl(0,6,2) as the subalgebra of e1 e2 e3 e: generator k of cl031 is
// generator k + 4 of cl062, in the same order, so orientations carry over unchanged.
inline constexpr int e_offset = 4;

template <auto L>
constexpr auto shifted_layout() {
    layout<L.size()> out = L;
    for (auto& m : out.masks) m <<= e_offset;
    return out;
}
template <auto L>
constexpr auto unshifted_layout() {
    layout<L.size()> out = L;
    for (auto& m : out.masks) m >>= e_offset;
    return out;
}
template <auto L>
constexpr bool only_e_blades() {
    for (auto m : L.masks)
        if (m & ((blade_mask{1} << e_offset) - 1)) return false;
    return true;
}

}  // namespace spatial_detail

// ---- the types of §5 ------------------------------------------------------------------------

// A screw of §3 placed on the e's of Cl(0,6,2): the same coefficients, (ω, v).
template <class T = double>
using lifted_screw = cl062::mv<T, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
// A co-screw: momentum (l, p) or wrench (τ, F), in the order of the paper's 6-vectors.
template <class T = double>
using coscrew = cl062::mv<T, "a1a", "a2a", "a3a", "a2a3", "a3a1", "a1a2">;
template <class T = double>
using wrench = coscrew<T>;
// A general symmetric inertia: component 6i + j is the entry N(i, j) of the 6×6 matrix of §2.
template <class T = double>
using inertia = multivector<cl062, T, spatial_detail::inertia_layout>;
// A rigid body's inertia: the 24 blades that are not structurally zero, in row-major order.
template <class T = double>
using rigid_inertia = multivector<cl062, T, spatial_detail::rigid_inertia_layout>;
// The inverse inertia as an element: component 6i + j is the entry M(i, j) of M = N⁻¹.
template <class T = double>
using mobility = multivector<cl062, T, spatial_detail::mobility_layout>;

// The invariants of §5–6 as exact constants: A = a1a2a3a, E = Ā = e1e2e3e, and Q0, the element
// pairing co-screws with screws (P(s) = P ∨ (Q0 ∧ s)).
namespace invariants {
inline constexpr auto A = cl062::basis<"a1a2a3a">;
inline constexpr auto E = cl062::basis<"e1e2e3e">;
inline constexpr auto Q0 = cl062::basis<"a2a3e1e"> + cl062::basis<"a3a1e2e"> + cl062::basis<"a1a2e3e"> +
                           cl062::basis<"a1ae2e3"> + cl062::basis<"a2ae3e1"> + cl062::basis<"a3ae1e2">;
}  // namespace invariants

// x viewed in Cl(0,6,2): an element of Cl(0,3,1) (multivector or expression) embedded as the
// e-half, lazily: the expression reads x's own components, nothing is copied. An element of
// Cl(0,6,2) is returned unchanged, so the formulas below accept screws of either algebra.
template <operand X>
[[nodiscard]] constexpr decltype(auto) lift(X&& x) noexcept {
    using alg = typename std::remove_cvref_t<X>::algebra_type;
    static_assert(std::is_same_v<alg, cl031> || std::is_same_v<alg, cl062>,
                  "ctga: lift takes an element of Cl(0,3,1) (or of Cl(0,6,2), returned unchanged)");
    if constexpr (std::is_same_v<alg, cl062>) return std::forward<X>(x);
    else return expr::apply_map<rules::embedding_of<spatial_detail::e_offset>::template rule, cl062>(std::forward<X>(x));
}
// The inverse on e-only elements of Cl(0,6,2): the same coefficients in Cl(0,3,1).
template <class T, auto L>
[[nodiscard]] constexpr auto lower(const multivector<cl062, T, L>& x) noexcept {
    static_assert(spatial_detail::only_e_blades<L>(),
                  "ctga: lower() takes an element of the e-half of Cl(0,6,2) (no a-generators)");
    multivector<cl031, T, spatial_detail::unshifted_layout<L>()> out;
    for (std::size_t i = 0; i < L.size(); ++i) out[i] = x[i];
    return out;
}

// ---- the paper's formulas, lazily (compose them; assign or eval to run) ----------------------
//
// Each is a ctga::formula: an argument used twice is one leaf, so cancellations are found.
// s is a screw (of Cl(0,3,1), or lifted), P a co-screw, N an inertia, M a mobility.
namespace paper {
using invariants::A;
using invariants::E;
using invariants::Q0;

// §3: the Lie bracket [s1, s2] = ½(s1 s2 − s2 s1) = (ω1×ω2, ω1×v2 − ω2×v1).
inline constexpr auto bracket = formula([](auto s1, auto s2) { return half * (s1 * s2 - s2 * s1); });
// §5: the evaluation P(s) = P ∨ (Q0 ∧ s) = ω·l + v·p.
inline constexpr auto evaluation = formula([](auto P, auto s) { return P & (Q0 ^ lift(s)); });
// §5: the momentum P = A ∨ (N ∧ s).
inline constexpr auto momentum = formula([](auto N, auto s) { return A & (N ^ lift(s)); });
// §5: twice the kinetic energy, 2E_k = s̄ ∨ (N ∧ s).
inline constexpr auto twice_kinetic_energy = formula([](auto N, auto s) { return bar(lift(s)) & (N ^ lift(s)); });
// §6: the coadjoint action {s, P} = ½(s̄P − Ps̄) = (ω×l + v×p, ω×p).
inline constexpr auto coadjoint = formula([](auto s, auto P) { return half * (bar(lift(s)) * P - P * bar(lift(s))); });
// §6: dN/dt = ½(sN − Ns) + ½(s̄N − Ns̄) for a body moving with velocity s.
inline constexpr auto inertia_rate = formula([](auto N, auto s) {
    const auto x = lift(s);
    return half * (x * N - N * x) + half * (bar(x) * N - N * bar(x));
});
// The velocity a mobility gives a co-screw: s = E ∨ (M ∧ P).
inline constexpr auto velocity = formula([](auto M, auto P) { return E & (M ^ P); });
// §6: the left-hand side of N ∧ ṡ + ½((s̄N − Ns̄) ∧ s) = W E.
inline constexpr auto motion_lhs = formula([](auto N, auto s, auto sdot) {
    const auto x = lift(s);
    return (N ^ lift(sdot)) + half * ((bar(x) * N - N * bar(x)) ^ x);
});
}  // namespace paper

// ---- the same, on concrete types --------------------------------------------------------------
// Thin wrappers over the formulas, always inlined: each is a few lines of straight-line code.

template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr screw<T> bracket(const screw<T>& s1, const screw<T>& s2) noexcept {
    return paper::bracket(s1, s2);
}
template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr T evaluation(const coscrew<T>& P, const screw<T>& s) noexcept {
    return scalar_part(paper::evaluation(P, s));
}
template <class T, auto L>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr coscrew<T> momentum(const multivector<cl062, T, L>& N, const screw<T>& s) noexcept {
    return paper::momentum(N, s);
}
template <class T, auto L>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr T kinetic_energy(const multivector<cl062, T, L>& N, const screw<T>& s) noexcept {
    return scalar_part(paper::twice_kinetic_energy(N, s)) / T(2);
}
template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr coscrew<T> coadjoint(const screw<T>& s, const coscrew<T>& P) noexcept {
    return paper::coadjoint(s, P);
}
template <class T, auto L>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr inertia<T> inertia_rate(const multivector<cl062, T, L>& N, const screw<T>& s) noexcept {
    return paper::inertia_rate(N, s);
}
template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr screw<T> velocity(const mobility<T>& M, const coscrew<T>& P) noexcept {
    return lower(lifted_screw<T>(paper::velocity(M, P)));
}

}  // namespace ctga
