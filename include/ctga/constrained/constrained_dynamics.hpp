// Constrained forward dynamics of a kinematic tree: q̈ and the constraint forces λ of
//     H q̈ + C(q, q̇) = τ + Jᵀ λ,     J q̈ + J̇ q̇ = a_ref      (bilateral blocks)
//     a = J q̈ + J̇ q̇,  K_μ ∋ λ_i ⊥ ã_i ∈ K*_μ               (contact blocks, at the acceleration level)
// with H of crba, C (rnea's, from the world motion: constraint_rows.hpp's bias_forces), J the rows of constraint_rows.hpp (λ a row's force on A, in B's
// constraint axes; a contact's (n, t1, t2)) and a_ref = −2ω φ̇ − ω² φ (Baumgarte, ω the settings'
// stabilization; 0: none); a limit's row (constraint_set.hpp) λ ≥ 0 ⊥ a ≥ 0, a joint friction's
// |λ| ≤ its bound, a = 0 while inside (both solved with the contacts). Eliminating q̈ leaves the contact problem of constraints/ in λ,
//     a = W λ + J H⁻¹ (τ − C) + J̇ q̇,    W = J H⁻¹ Jᵀ (delassus.hpp),
// solved directly when every block is bilateral (below), and otherwise by
// constraints::solve_contacts to the caller's tolerance on the natural-map residual, with its
// report. Then q̈ = H⁻¹ (τ − C + Jᵀ λ), from the same tree factor.
//
// Redundant constraints (W singular: a planar four-bar closed by a point, whose rows along the
// normal of its plane are zero; two feet welded to one floor), the bilateral case: W = L D Lᵀ
// without pivoting, a pivot below `redundancy` times W's largest diagonal entry marks its row as
// dependent on the rows before it, whose force is set to 0 (W is positive semidefinite: the pivot's
// column below is then zero too, up to rounding). Consistent constraints are met exactly, with
// the forces of the independent rows; inconsistent ones (two frames held at places that cannot
// both be reached) leave a residual ‖W λ + q‖ > 0, reported with converged = false. result.rank
// counts the rows kept. With contacts, a bilateral block's 3 × 3 is regularised by the same
// fraction of W's diagonal before the sweeps invert it.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "ctga/chains/crba.hpp"
#include "ctga/chains/minverse.hpp"
#include "ctga/constrained/constraint_rows.hpp"
#include "ctga/constrained/constraint_set.hpp"
#include "ctga/constrained/delassus.hpp"
#include "ctga/constraints/contact_problem.hpp"
#include "ctga/constraints/newton_polish.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::constrained {

template <class T>
struct constrained_settings {
    constraints::contact_settings<T> solver{};  // with contacts: the tolerance on the residual, the sweeps
    T stabilization = T(0);                      // ω (1/s) of the bilateral rows' a_ref; 0: none
    T redundancy = T(1e-10);                     // (above)
};

template <class Tree, class T, std::size_t Capacity>
struct constrained_result {
    error_code error = error_code::none;
    chains::joint_vector<Tree, T> qdd{};
    std::array<T, 3 * Capacity> force{};  // λ, three per block in block order
    constraints::contact_report<T> report{};
    std::size_t rank = 0;  // bilateral: the rows kept (above)
};

namespace dynamics_detail {
// Σ_k a_k b_k over k < n in four interleaved parts (k ≡ 0, 1, 2, 3 mod 4), added at the end:
// four multiply-adds in flight rather than a chain, each waiting on the last (measured, the
// velocities of a grasp's 24 rows in the sweeps: 10 % of its step as one chain).
template <class T>
[[nodiscard]] constexpr T dot_in_parts(const T* a, const T* b, std::size_t n) noexcept {
    std::array<T, 4> part{};
    const std::size_t whole = n - n % 4;
    for (std::size_t k = 0; k < whole; k += 4)
        for (std::size_t j = 0; j < 4; ++j) part[j] += a[k + j] * b[k + j];
    for (std::size_t k = whole; k < n; ++k) part[k - whole] += a[k] * b[k];
    return (part[0] + part[1]) + (part[2] + part[3]);
}

// W λ = −q for a positive semidefinite W of m rows (above); returns the rows kept. LDLᵀ by rows,
// L kept both ways (Lt = Lᵀ) so that both substitutions run by columns, y_i −= L(i, k) y_k for all
// i at once after y_k is final, on contiguous rows (measured, 12 rows: 466 ns with the
// substitutions' sums over j < i, 364 ns so).
template <class T, std::size_t N>
constexpr std::size_t semidefinite_solve(const std::array<std::array<T, N>, N>& W, std::size_t m, const std::array<T, N>& q,
                                         const T& redundancy, std::array<T, N>& x) noexcept {
    std::array<std::array<T, N>, N> L, Lt;
    std::array<T, N> d, v;
    T scale = T(0);
    for (std::size_t i = 0; i < m; ++i) scale = W[i][i] > scale ? W[i][i] : scale;
    const T floor = redundancy * scale;
    std::size_t kept = 0;
    for (std::size_t k = 0; k < m; ++k) {
        for (std::size_t j = 0; j < k; ++j) v[j] = L[k][j] * d[j];
        T dk = W[k][k];
        for (std::size_t j = 0; j < k; ++j) dk -= L[k][j] * v[j];
        const bool keep = dk > floor;
        d[k] = keep ? dk : T(0);
        kept += keep;
        const T inv = keep ? T(1) / dk : T(0);
        for (std::size_t i = k + 1; i < m; ++i) {
            T s = W[i][k];
            for (std::size_t j = 0; j < k; ++j) s -= L[i][j] * v[j];
            L[i][k] = Lt[k][i] = keep ? s * inv : T(0);
        }
    }
    for (std::size_t i = 0; i < m; ++i) x[i] = -q[i];
    for (std::size_t k = 0; k < m; ++k)  // L y = −q
        for (std::size_t i = k + 1; i < m; ++i) x[i] -= Lt[k][i] * x[k];
    for (std::size_t i = 0; i < m; ++i) x[i] = d[i] > T(0) ? x[i] / d[i] : T(0);
    for (std::size_t k = m; k-- > 0;)  // Lᵀ λ = D⁻¹ y
        for (std::size_t i = 0; i < k; ++i) x[i] -= L[k][i] * x[k];
    return kept;
}

// The conditions of each block's kind (contact_problem.hpp's optional members): point and
// orientation blocks bilateral (their 3 × 3 regularised, above), a limit's row bounded below by 0,
// a joint friction's row by ± its bound (times `scale`: 1 for forces, the step for impulses), the
// limit's and friction's empty rows bounded to 0.
template <class T>
struct block_conditions {
    std::span<const constraint_block<T>> kinds;
    T regularised, scale;

    [[nodiscard]] constexpr std::size_t contacts() const noexcept { return kinds.size(); }
    [[nodiscard]] constexpr bool bilateral(std::size_t i) const noexcept {
        return kinds[i].kind == block_kind::point || kinds[i].kind == block_kind::orientation;
    }
    [[nodiscard]] constexpr bool bounded(std::size_t i) const noexcept { return on_joint(kinds[i].kind); }
    [[nodiscard]] constexpr std::array<vec3<T>, 2> bounds(std::size_t i) const noexcept {
        constexpr T inf = std::numeric_limits<T>::infinity();
        const T f = scale * kinds[i].bound;
        return kinds[i].kind == block_kind::joint_friction ? std::array<vec3<T>, 2>{vec3<T>{-f, T(0), T(0)}, vec3<T>{f, T(0), T(0)}}
                                                           : std::array<vec3<T>, 2>{vec3<T>{}, vec3<T>{inf, T(0), T(0)}};
    }
};

// W = Y D⁻¹ Yᵀ as constraints/ uses it (contact_problem.hpp's delassus_operator), without forming
// W: the dofs' share s = D⁻¹ Yᵀ r is kept as r changes, so that W r = Y s; block i's velocity is
// q_i + Σ_k Y(i, k) s_k over the dofs reaching block i only, and a change dr of r_i adds
// D_k⁻¹ Y(i, k)ᵀ dr to s_k for those dofs. Only W's diagonal blocks are formed. A sweep costs
// each block twice its reach (a grasp's finger block: 7 dofs) where W's rows cost the rows in use
// (24), and W's m² entries are not summed (measured, steps: a grasp's 3.19 → 2.80 µs, the humanoid's
// 18.5 → 16.5 µs).
template <class Tree, class T, std::size_t Capacity>
struct tree_delassus : block_conditions<T> {
    static_assert(Tree::nv < 65536, "ctga::constrained: a tree of at most 65,535 dofs");
    const delassus_parts<Tree, T, Capacity>& P;
    const chains::algorithm_detail::tree_factor<Tree, T>& f;
    std::span<const T> q;
    std::array<mat3<T>, Capacity> diagonal;
    std::array<T, Tree::nv> s;
    std::array<std::size_t, Capacity + 1> first;            // block i's dofs: dofs[first[i], first[i + 1])
    std::array<std::uint16_t, Capacity * Tree::nv> dofs;

    // At the impulses r (the warm start); `redundancy` times W's largest diagonal entry
    // regularises the bilateral blocks.
    constexpr tree_delassus(const delassus_parts<Tree, T, Capacity>& parts, const chains::algorithm_detail::tree_factor<Tree, T>& factor,
                            const constraint_rows<Tree, T, Capacity>& R, std::span<const T> qv, std::span<const constraint_block<T>> kinds,
                            const T& redundancy, const T& scale, std::span<const T> r) noexcept
        : block_conditions<T>{kinds, T(0), scale}, P(parts), f(factor), q(qv) {
        const std::size_t m = kinds.size();
        std::array<std::size_t, Capacity + 1> count{};
        for (std::size_t k = 0; k < Tree::nv; ++k)
            for (std::uint64_t mask = R.reach[k]; mask != 0; mask &= mask - 1) ++count[static_cast<std::size_t>(std::countr_zero(mask)) + 1];
        first[0] = 0;
        for (std::size_t i = 0; i < m; ++i) first[i + 1] = first[i] + count[i + 1], count[i + 1] = first[i];
        for (std::size_t k = 0; k < Tree::nv; ++k)
            for (std::uint64_t mask = R.reach[k]; mask != 0; mask &= mask - 1)
                dofs[count[static_cast<std::size_t>(std::countr_zero(mask)) + 1]++] = static_cast<std::uint16_t>(k);
        T largest = T(0);
        for (std::size_t i = 0; i < m; ++i) {
            mat3<T> A{};
            for (std::size_t n = first[i]; n < first[i + 1]; ++n) {
                const std::size_t k = dofs[n];
                const T* y = &P.Y[k][3 * i];
                for (std::size_t a = 0; a < 3; ++a)
                    for (std::size_t b = a; b < 3; ++b) A[a][b] += f.inv_D[k] * y[a] * y[b];
            }
            A[1][0] = A[0][1], A[2][0] = A[0][2], A[2][1] = A[1][2];
            diagonal[i] = A;
            for (std::size_t a = 0; a < 3; ++a) largest = A[a][a] > largest ? A[a][a] : largest;
        }
        this->regularised = redundancy * largest;
        for (std::size_t k = 0; k < Tree::nv; ++k) {
            const auto [begin, end] = row_span(R.reach[k]);
            s[k] = f.inv_D[k] * dot_in_parts(P.Y[k].data() + begin, r.data() + begin, end - begin);
        }
    }

    [[nodiscard]] constexpr mat3<T> block(std::size_t i) const noexcept {
        mat3<T> out = diagonal[i];
        if (this->bilateral(i))
            for (std::size_t a = 0; a < 3; ++a) out[a][a] += this->regularised;
        return out;
    }
    [[nodiscard]] constexpr vec3<T> velocity(std::size_t i, std::span<const T>) const noexcept {
        vec3<T> u{q[3 * i], q[3 * i + 1], q[3 * i + 2]};
        for (std::size_t n = first[i]; n < first[i + 1]; ++n) {
            const std::size_t k = dofs[n];
            for (std::size_t a = 0; a < 3; ++a) u[a] += P.Y[k][3 * i + a] * s[k];
        }
        return u;
    }
    constexpr void apply(std::size_t i, const vec3<T>& dr) noexcept {
        for (std::size_t n = first[i]; n < first[i + 1]; ++n) {
            const std::size_t k = dofs[n];
            s[k] += f.inv_D[k] * (P.Y[k][3 * i] * dr[0] + P.Y[k][3 * i + 1] * dr[1] + P.Y[k][3 * i + 2] * dr[2]);
        }
    }
};

// J H⁻¹ b = Y D⁻¹ z for z = L⁻ᵀ b: each dof's D⁻¹ z_k spread over the rows of the blocks reaching it.
template <class Tree, class T, std::size_t Capacity>
constexpr void rows_of(const chains::algorithm_detail::tree_factor<Tree, T>& f, const std::array<T, Tree::nv>& z,
                       const constraint_rows<Tree, T, Capacity>& R, const delassus_parts<Tree, T, Capacity>& P,
                       std::array<T, 3 * Capacity>& out) noexcept {
    out.fill(T(0));
    for (std::size_t k = 0; k < Tree::nv; ++k) {  // (Y_k is zero off its blocks: over their span, delassus.hpp)
        const T c = f.inv_D[k] * z[k];
        const auto [first, last] = row_span(R.reach[k]);
        for (std::size_t r = first; r < last; ++r) out[r] += P.Y[k][r] * c;
    }
}

// The rows at (q, q̇) from the world motion g, W from the factor f, and q = J H⁻¹ b for z = L⁻ᵀ b
// (before the bias terms each level adds): what both levels (forces here, impulses in
// impulse_dynamics.hpp) solve; J̇ q̇ (Bias) for forces only.
template <class Tree, class T, std::size_t Capacity>
struct rows_problem {
    constraint_rows<Tree, T, Capacity> R;
    delassus_parts<Tree, T, Capacity> P;
    std::array<T, 3 * Capacity> qv;
};
template <bool Bias, class Tree, class T, std::size_t Capacity>
constexpr void fill_problem(rows_problem<Tree, T, Capacity>& x, const tree_motion<Tree, T>& g, const chains::configuration<Tree, T>& q,
                            const chains::joint_vector<Tree, T>& qd, const constraint_set<Tree, T, Capacity>& C,
                            const chains::algorithm_detail::tree_factor<Tree, T>& f, const std::array<T, Tree::nv>& z) noexcept {
    fill_rows<Bias>(x.R, g, C, q, qd);
    fill_sweep(x.P, f, x.R);  // (W itself only where a solve needs it: solve_rows)
    rows_of(f, z, x.R, x.P, x.qv);
}

// z ← L⁻¹ D⁻¹ (z + Yᵀ λ): H⁻¹ (b + Jᵀ λ) for z = L⁻ᵀ b, the rows' forces λ added.
template <class Tree, class T, std::size_t Capacity>
constexpr void add_forces(const chains::algorithm_detail::tree_factor<Tree, T>& f, std::array<T, Tree::nv>& z,
                          const constraint_rows<Tree, T, Capacity>& R, const delassus_parts<Tree, T, Capacity>& P,
                          std::span<const T> force) noexcept {
    for (std::size_t k = 0; k < Tree::nv; ++k) {
        const auto [first, last] = row_span(R.reach[k]);
        z[k] += dot_in_parts(P.Y[k].data() + first, force.data() + first, last - first);
    }
    chains::algorithm_detail::lower_sweep(f, z.data());
}

// Scratch for solve_rows' Newton finish on a set of up to Capacity blocks: W and q compact, then
// newton_polish.hpp's own.
[[nodiscard]] constexpr std::size_t polish_scratch_size(std::size_t capacity) noexcept {
    return 9 * capacity * capacity + 3 * capacity + constraints::newton_scratch_size(capacity);
}

// λ with W λ + q in the blocks' sets (bilateral sets directly, above; else by solve_contacts from
// the warm start in λ), then z ← L⁻¹ D⁻¹ (z + Yᵀ λ): H⁻¹ (b + Jᵀ λ) for z = L⁻ᵀ b. `scale` as in
// blocks_delassus. With scratch of polish_scratch_size(Capacity) numbers the sweeps are
// accelerated (contact_problem.hpp's conjugate directions) and a solve they leave above the
// tolerance is finished by Newton (newton_polish.hpp: a few steps where Gauss–Seidel needs
// hundreds, as on a body lying on many contacts). Returns the rows kept (bilateral) or all rows.
template <class Tree, class T, std::size_t Capacity>
constexpr std::size_t solve_rows(const chains::algorithm_detail::tree_factor<Tree, T>& f, std::array<T, Tree::nv>& z,
                                 const constraint_rows<Tree, T, Capacity>& R, delassus_parts<Tree, T, Capacity>& P,
                                 const std::array<T, 3 * Capacity>& qv, const constraint_set<Tree, T, Capacity>& C,
                                 const constrained_settings<T>& settings, const T& scale, std::array<T, 3 * Capacity>& force,
                                 constraints::contact_report<T>& report, std::span<T> scratch = {}) noexcept {
    std::size_t rank = R.count;
    if (C.bilateral()) {
        fill_w(P, f, R);
        rank = semidefinite_solve(P.W, R.count, qv, settings.redundancy, force);
        T sum = T(0);
        for (std::size_t r = 0; r < R.count; ++r) {
            const T u = qv[r] + dot_in_parts(P.W[r].data(), force.data(), R.count);
            sum += u * u;
        }
        report.residual = math::sqrt(sum);
        report.converged = report.residual <= settings.solver.tolerance;
        if (!is_finite(report.residual)) report.error = error_code::non_finite;
    } else {
        const std::size_t m = C.size(), n = R.count;
        tree_delassus<Tree, T, Capacity> D(P, f, R, std::span<const T>(qv.data(), n), C.blocks(), settings.redundancy, scale,
                                           std::span<const T>(force.data(), n));
        std::array<T, Capacity> mu{};
        for (std::size_t i = 0; i < m; ++i) mu[i] = C.blocks()[i].mu;
        const bool polish = scratch.size() >= polish_scratch_size(Capacity);
        report = constraints::solve_contacts<T>(D, std::span<const T>(mu.data(), m), std::span<T>(force.data(), n), settings.solver,
                                                polish ? scratch : std::span<T>{});
        if (polish && report.error == error_code::none && !report.converged) {  // (W formed for Newton only)
            fill_w(P, f, R);
            const std::span<T> W = scratch.subspan(0, n * n), q = scratch.subspan(n * n, n), rest = scratch.subspan(n * n + n);
            std::array<unsigned char, Capacity> kind{};
            std::array<std::array<vec3<T>, 2>, Capacity> bounds{};
            for (std::size_t i = 0; i < m; ++i) {
                kind[i] = D.bounded(i) ? constraints::bounded_block : D.bilateral(i) ? constraints::bilateral_block : constraints::contact_block;
                bounds[i] = D.bounds(i);
            }
            for (std::size_t r = 0; r < n; ++r) {
                q[r] = qv[r];
                for (std::size_t c = 0; c < n; ++c) W[r * n + c] = P.W[r][c];
            }
            const constraints::contact_report<T> newton =
                constraints::newton_polish<T>(W, q, std::span<const T>(mu.data(), m), std::span<T>(force.data(), n), rest,
                                              settings.solver.tolerance, 30, std::span<const unsigned char>(kind.data(), m),
                                              std::span<const std::array<vec3<T>, 2>>(bounds.data(), m));
            report.residual = newton.residual;
            report.converged = newton.converged;
            report.polish_steps = newton.sweeps;
            report.error = newton.error;
        }
    }
    if (report.error != error_code::none) return rank;
    add_forces(f, z, R, P, std::span<const T>(force));
    return rank;
}

// Every number of the arrays (q, q̇, τ) finite.
template <class... V>
[[nodiscard]] constexpr bool finite_state(const V&... v) noexcept {
    const auto finite = [](const auto& x) {
        for (const auto& e : x)
            if (!is_finite(e)) return false;
        return true;
    };
    return (finite(v) && ...);
}
}  // namespace dynamics_detail

struct constrained_forward_dynamics_t {
    template <class Tree, class T, std::size_t Capacity>
    [[nodiscard]] constexpr constrained_result<Tree, T, Capacity> operator()(const chains::model<Tree, T>& m, const chains::configuration<Tree, T>& q,
                                                                             const chains::joint_vector<Tree, T>& qd,
                                                                             const chains::joint_vector<Tree, T>& tau,
                                                                             const constraint_set<Tree, T, Capacity>& C,
                                                                             const constrained_settings<T>& settings = {}) const noexcept {
        static_assert(!Tree::has_mimic, "ctga::constrained: trees with mimic joints are not supported yet (their H is not the tree factor's)");
        using namespace chains::algorithm_detail;
        constrained_result<Tree, T, Capacity> out;
        if (!dynamics_detail::finite_state(q, qd, tau)) return out.error = error_code::non_finite, out;
        // H = Lᵀ D L; the joints' maps evaluated once for H and the world motion, from which C
        // (bias_forces) and the rows; z = L⁻ᵀ (τ − C)
        joint_maps<Tree, T> X;
        fill_joint_maps(X, m, q);
        tree_factor<Tree, T> f{mass_matrix(m, q, X), {}, true};  // (H built in place, factored there)
        factor_tree(f);
        if (!f.positive_definite) return out.error = error_code::massless_subtree, out;
        tree_motion<Tree, T> g(uninitialized);
        fill_tree_motion(g, m, q, qd, X);
        std::array<T, Tree::nv> z = bias_forces(m, g);
        for (std::size_t k = 0; k < Tree::nv; ++k) z[k] = tau[k] - z[k];
        transposed_sweep(f, [&](std::size_t k, std::size_t i, const T& l) { z[i] -= l * z[k]; });
        // the rows, W, and q = J H⁻¹ (τ − C) + J̇ q̇ − a_ref
        dynamics_detail::rows_problem<Tree, T, Capacity> x;
        dynamics_detail::fill_problem<true>(x, g, q, qd, C, f, z);
        auto& [R, P, qv] = x;
        const T w = settings.stabilization;
        for (std::size_t r = 0; r < R.count; ++r) {
            qv[r] += R.bias[r];
            const block_kind kind = C.blocks()[r / 3].kind;
            if (kind == block_kind::point || kind == block_kind::orientation) qv[r] += T(2) * w * R.rate[r] + w * w * R.gap[r];
        }
        // λ, then q̈ = L⁻¹ D⁻¹ (z + Yᵀ λ)
        out.rank = dynamics_detail::solve_rows(f, z, R, P, qv, C, settings, T(1), out.force, out.report);
        if (out.report.error != error_code::none) return out.error = out.report.error, out;
        out.qdd = z;
        return out;
    }
};
// (q̈, λ, the solver's report) of a tree under the constraints of C.
inline constexpr constrained_forward_dynamics_t constrained_forward_dynamics{};

}  // namespace ctga::constrained
