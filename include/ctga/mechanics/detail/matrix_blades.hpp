// The 6×6 matrices of §2 as elements of Cl(0,6,2) (§5): which blade holds entry (i, j).
//
// With α = (a1a, a2a, a3a, a2a3, a3a1, a1a2) the co-screw blades in (l, p) order,
// ε = (e2e3, e3e1, e1e2, e1e, e2e, e3e) the screw blades in (ω, v) order, and x̃ the complement
// of a blade within its half (ε̃_j = ε_{j±3}, so ε̃_j ∧ ε_j = e1e2e3e = E):
//
//   inertia    N = Σ N(i,j) α_i ε̃_j,    A ∨ (N ∧ s) = N s      (the momentum, §5)
//   mobility   M = Σ M(i,j) α̃_j ε_i,    E ∨ (M ∧ P) = M P      (the velocity)
//
// so the coefficient of a blade is exactly the entry of the matrix. This header builds those
// layouts and reads and writes entries by index; inertia.hpp names the types.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/linear3.hpp"

namespace ctga::matrix_blades {

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

// The blade of every entry (i, j), at 6i + j, read once per translation unit.
template <bool AsMobility>
inline constexpr std::array<parsed_blade, 36> entry_blades = [] {
    std::array<parsed_blade, 36> out{};
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            out[static_cast<std::size_t>(6 * i + j)] = AsMobility ? mobility_blade({i, j}) : inertia_blade({i, j});
    return out;
}();

// Where each stored component of an element with layout L sits in the 6×6 matrix it
// represents (read as an inertia or as a mobility), with the orientation factor ±1.
// The tables are variables, computed once per (L, AsMobility): GCC memoizes constexpr calls,
// Clang does not, and recomputing them for every entry_of/set_entry made the mechanics
// translation unit take 73 s with Clang 14 instead of 4 s.
struct placed_entry {
    entry at;
    int sign;
};
template <auto L, bool AsMobility>
inline constexpr std::array<placed_entry, L.size()> entry_table = [] {
    std::array<placed_entry, L.size()> out{};
    for (std::size_t k = 0; k < L.size(); ++k) {
        out[k] = {{-1, -1}, 0};
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) {
                const parsed_blade& b = entry_blades<AsMobility>[static_cast<std::size_t>(6 * i + j)];
                if (b.mask == L.masks[k]) out[k] = {{i, j}, b.sign * L.signs[k]};
            }
    }
    return out;
}();
template <auto L, bool AsMobility>
inline constexpr bool every_entry_placed = [] {
    for (const auto& e : entry_table<L, AsMobility>)
        if (e.sign == 0) return false;
    return true;
}();

// The component index of entry (i, j) at 6i + j, −1 where the layout has no such blade.
template <auto L, bool AsMobility>
inline constexpr std::array<int, 36> entry_index = [] {
    std::array<int, 36> out{};
    out.fill(-1);
    for (std::size_t k = 0; k < L.size(); ++k) {
        const placed_entry& e = entry_table<L, AsMobility>[k];
        if (e.sign == 0) continue;
        int& slot = out[static_cast<std::size_t>(6 * e.at.row + e.at.col)];
        if (slot < 0) slot = static_cast<int>(k);
    }
    return out;
}();

// Entry (I, J) of an element read as a matrix, by a component index fixed at compile time
// (zero when the type does not store that blade).
template <bool AsMobility, int I, int J, class T, auto L>
constexpr T entry_of(const multivector<cl062, T, L>& x) noexcept {
    constexpr int k = entry_index<L, AsMobility>[6 * I + J];
    if constexpr (k < 0) {
        return T(0);
    } else {
        constexpr int sign = entry_table<L, AsMobility>[k].sign;
        return sign > 0 ? x[k] : -x[k];
    }
}
template <bool AsMobility, int I, int J, class T, auto L>
constexpr void set_entry(multivector<cl062, T, L>& x, const T& v) noexcept {
    constexpr int k = entry_index<L, AsMobility>[6 * I + J];
    static_assert(k >= 0, "ctga: the element's type does not store this matrix entry");
    constexpr int sign = entry_table<L, AsMobility>[k].sign;
    x[k] = sign > 0 ? v : -v;
}

template <bool AsMobility, class T, auto L>
constexpr mat6<T> to_matrix(const multivector<cl062, T, L>& x) noexcept {
    static_assert(every_entry_placed<L, AsMobility>,
                  "ctga: only elements made of (a-bivector)(e-bivector) blades are 6x6 matrices (§5)");
    constexpr const auto& table = entry_table<L, AsMobility>;
    mat6<T> m{};
    for (std::size_t k = 0; k < L.size(); ++k)
        m[static_cast<std::size_t>(table[k].at.row)][static_cast<std::size_t>(table[k].at.col)] =
            table[k].sign > 0 ? x[k] : -x[k];
    return m;
}

template <bool AsMobility, class Target, class T>
constexpr Target from_matrix(const mat6<T>& m) noexcept {
    constexpr auto L = Target::layout;
    static_assert(every_entry_placed<L, AsMobility>,
                  "ctga: only elements made of (a-bivector)(e-bivector) blades are 6x6 matrices (§5)");
    constexpr const auto& table = entry_table<L, AsMobility>;
    Target x;
    for (std::size_t k = 0; k < L.size(); ++k) {
        const T v = m[static_cast<std::size_t>(table[k].at.row)][static_cast<std::size_t>(table[k].at.col)];
        x[k] = table[k].sign > 0 ? v : -v;
    }
    return x;
}

}  // namespace ctga::matrix_blades
