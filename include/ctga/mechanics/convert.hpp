// To and from the 6-vectors and 6×6 matrices of §2, for data exchange with libraries built on
// them (Eigen, Pinocchio, RBDL): screws (ω, v), co-screws (l, p), inertias N with P = N s,
// mobilities M with s = M P. Plain std::array, so no dependency; with Eigen,
// Eigen::Map<Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(m[0].data()) views a mat6.
#pragma once

#include <cstddef>
#include <type_traits>

#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/spatial.hpp"

namespace ctga {

namespace spatial_detail {

// Where each stored component of an element with layout L sits in the 6×6 matrix it
// represents (read as an inertia or as a mobility), with the orientation factor ±1.
struct placed_entry {
    entry at;
    int sign;
};
template <auto L, bool AsMobility>
constexpr auto entry_table() {
    std::array<placed_entry, L.size()> out{};
    for (std::size_t k = 0; k < L.size(); ++k) {
        out[k] = {{-1, -1}, 0};
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) {
                const parsed_blade b = AsMobility ? mobility_blade({i, j}) : inertia_blade({i, j});
                if (b.mask == L.masks[k]) out[k] = {{i, j}, b.sign * L.signs[k]};
            }
    }
    return out;
}
template <auto L, bool AsMobility>
constexpr bool every_entry_placed() {
    for (const auto& e : entry_table<L, AsMobility>())
        if (e.sign == 0) return false;
    return true;
}

template <auto L, bool AsMobility>
constexpr int index_of_entry(int row, int col) {
    const auto table = entry_table<L, AsMobility>();
    for (std::size_t i = 0; i < L.size(); ++i)
        if (table[i].at.row == row && table[i].at.col == col) return static_cast<int>(i);
    return -1;
}

// Entry (I, J) of an element read as a matrix, by a component index fixed at compile time
// (zero when the type does not store that blade).
template <bool AsMobility, int I, int J, class T, auto L>
constexpr T entry_of(const multivector<cl062, T, L>& x) noexcept {
    constexpr int k = index_of_entry<L, AsMobility>(I, J);
    if constexpr (k < 0) {
        return T(0);
    } else {
        constexpr int sign = entry_table<L, AsMobility>()[k].sign;
        return sign > 0 ? x[k] : -x[k];
    }
}
template <bool AsMobility, int I, int J, class T, auto L>
constexpr void set_entry(multivector<cl062, T, L>& x, const T& v) noexcept {
    constexpr int k = index_of_entry<L, AsMobility>(I, J);
    static_assert(k >= 0, "ctga: the element's type does not store this matrix entry");
    constexpr int sign = entry_table<L, AsMobility>()[k].sign;
    x[k] = sign > 0 ? v : -v;
}

template <bool AsMobility, class T, auto L>
constexpr mat6<T> to_matrix(const multivector<cl062, T, L>& x) noexcept {
    static_assert(every_entry_placed<L, AsMobility>(),
                  "ctga: only elements made of (a-bivector)(e-bivector) blades are 6x6 matrices (§5)");
    constexpr auto table = entry_table<L, AsMobility>();
    mat6<T> m{};
    for (std::size_t k = 0; k < L.size(); ++k)
        m[static_cast<std::size_t>(table[k].at.row)][static_cast<std::size_t>(table[k].at.col)] =
            table[k].sign > 0 ? x[k] : -x[k];
    return m;
}

template <bool AsMobility, class Target, class T>
constexpr Target from_matrix(const mat6<T>& m) noexcept {
    constexpr auto L = Target::layout;
    static_assert(every_entry_placed<L, AsMobility>(),
                  "ctga: only elements made of (a-bivector)(e-bivector) blades are 6x6 matrices (§5)");
    constexpr auto table = entry_table<L, AsMobility>();
    Target x;
    for (std::size_t k = 0; k < L.size(); ++k) {
        const T v = m[static_cast<std::size_t>(table[k].at.row)][static_cast<std::size_t>(table[k].at.col)];
        x[k] = table[k].sign > 0 ? v : -v;
    }
    return x;
}

}  // namespace spatial_detail

// 6-vectors: a screw is (ω, v), a co-screw (l, p), in the order the types store them.
template <class T, auto L>
[[nodiscard]] constexpr vec6<T> to_vector6(const multivector<cl031, T, L>& s) noexcept {
    static_assert(std::is_same_v<multivector<cl031, T, L>, screw<T>>, "ctga: to_vector6 takes a screw (or a co-screw)");
    return {s[0], s[1], s[2], s[3], s[4], s[5]};
}
template <class T, auto L>
[[nodiscard]] constexpr vec6<T> to_vector6(const multivector<cl062, T, L>& P) noexcept {
    static_assert(std::is_same_v<multivector<cl062, T, L>, coscrew<T>>, "ctga: to_vector6 takes a co-screw (or a screw)");
    return {P[0], P[1], P[2], P[3], P[4], P[5]};
}
template <class T>
[[nodiscard]] constexpr screw<T> screw_from_vector6(const vec6<T>& v) noexcept {
    return screw<T>{v[0], v[1], v[2], v[3], v[4], v[5]};
}
template <class T>
[[nodiscard]] constexpr coscrew<T> coscrew_from_vector6(const vec6<T>& v) noexcept {
    return coscrew<T>{v[0], v[1], v[2], v[3], v[4], v[5]};
}

// 6×6 matrices. The 12 structurally zero entries of a rigid_inertia come out as zeros.
template <class T, auto L>
[[nodiscard]] constexpr mat6<T> inertia_matrix(const multivector<cl062, T, L>& N) noexcept {
    return spatial_detail::to_matrix<false>(N);
}
template <class T, auto L>
[[nodiscard]] constexpr mat6<T> mobility_matrix(const multivector<cl062, T, L>& M) noexcept {
    return spatial_detail::to_matrix<true>(M);
}
// From a matrix: every entry becomes a blade coefficient (a general inertia or mobility; for a
// rigid body's, see make_inertia, which checks the physics).
template <class T>
[[nodiscard]] constexpr inertia<T> inertia_from_matrix(const mat6<T>& m) noexcept {
    return spatial_detail::from_matrix<false, inertia<T>>(m);
}
template <class T>
[[nodiscard]] constexpr mobility<T> mobility_from_matrix(const mat6<T>& m) noexcept {
    return spatial_detail::from_matrix<true, mobility<T>>(m);
}

}  // namespace ctga
