// To and from the 6-vectors and matrices of §2, for data exchange with libraries built on them
// (Eigen, Pinocchio, RBDL): screws (ω, v) and co-screws (l, p) as 6-vectors, motors as 4×4
// homogeneous matrices [R t; 0 0 0 1]. Plain std::array, so no dependency; with Eigen,
// Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(m[0].data()) views a matrix. The 6×6
// matrices of inertias and mobilities are in inertia_matrix.hpp (inertia_matrix,
// inertia_from_matrix, …).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga {

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

// ---- homogeneous 4×4 matrices -----------------------------------------------------------

// Row-major [R t; 0 0 0 1]: m[row][col], R = the 3×3 block, t = (m[0][3], m[1][3], m[2][3]).
template <class T>
using homogeneous_matrix = std::array<std::array<T, 4>, 4>;

// How far from a rigid motion from_homogeneous accepts a matrix, entrywise (R's entries are at
// most 1 in size, so this is both absolute and relative): |RᵀR − I|ij ≤ tol, |bottom row −
// (0 0 0 1)| ≤ tol. 1e-9 for double and long double: matrices printed with ten significant
// digits, or composed from thousands of products, pass. For float, 1024 ε ≈ 1.2e-4 (1e-9 is
// below float's own rounding of R).
template <class T>
inline constexpr T homogeneous_tolerance = T(1e-9) > T(1024) * std::numeric_limits<T>::epsilon()
                                               ? T(1e-9)
                                               : T(1024) * std::numeric_limits<T>::epsilon();

// The 4×4 matrix [R t; 0 0 0 1] of a unit motor g = t r: its motor_map. For a motor off
// g g* = 1, renormalize first.
template <class T>
[[nodiscard]] constexpr homogeneous_matrix<T> to_homogeneous(const motor<T>& g) noexcept {
    const motor_map<T> G = map_of(g);
    homogeneous_matrix<T> m{};
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) m[i][j] = G.R[i][j];
        m[i][3] = G.t[i];
    }
    m[3][3] = T(1);
    return m;
}

// The motor g = t r of a homogeneous matrix [R t; 0 0 0 1], or why it is not one:
//   error_code::non_finite       an entry is NaN or ±∞;
//   error_code::not_homogeneous  the bottom row is not (0, 0, 0, 1) within tol;
//   error_code::not_a_rotation   R is not orthonormal within tol (|RᵀR − I|ij ≤ tol), or
//                                 det R < 0 (a reflection).
// The rotor by Shepperd's method: of 4w² = 1 + tr R, 4x² = 1 + R00 − R11 − R22,
// 4y² = 1 − R00 + R11 − R22, 4z² = 1 − R00 − R11 + R22, take the root of the largest, which is
// at least 1 (w² + x² + y² + z² = 1, so the largest is ≥ ¼): no cancellation, also near θ = π
// where 1 + tr R → 0. The other three come from the off-diagonal differences and sums
// R21 − R12 = 4wx, R02 − R20 = 4wy, R10 − R01 = 4wz, R01 + R10 = 4xy, R02 + R20 = 4xz,
// R12 + R21 = 4yz, divided by that root.
// The rotor is then normalised (absorbing R's tolerated non-orthogonality) and chosen with
// α0 ≥ 0; −g is the same rigid motion. Then β = ½ t α: β0 = −½ t·α⃗, β⃗ = ½(α0 t + t × α⃗).
template <class T>
[[nodiscard]] constexpr checked<motor<T>> from_homogeneous(const homogeneous_matrix<T>& m,
                                                           const T& tol = homogeneous_tolerance<T>) noexcept {
    for (const auto& row : m)
        for (const T& v : row)
            if (!is_finite(v)) return {motor<T>{}, error_code::non_finite};
    const auto off = [](const T& v) { return v < T(0) ? -v : v; };
    if (off(m[3][0]) > tol || off(m[3][1]) > tol || off(m[3][2]) > tol || off(m[3][3] - T(1)) > tol)
        return {motor<T>{}, error_code::not_homogeneous};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i; j < 3; ++j) {
            const T rtr = m[0][i] * m[0][j] + m[1][i] * m[1][j] + m[2][i] * m[2][j];
            if (off(rtr - (i == j ? T(1) : T(0))) > tol) return {motor<T>{}, error_code::not_a_rotation};
        }
    const T det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (!(det > T(0))) return {motor<T>{}, error_code::not_a_rotation};

    const T r00 = m[0][0], r11 = m[1][1], r22 = m[2][2];
    const T tr = r00 + r11 + r22;
    T w, x, y, z;
    if (tr >= r00 && tr >= r11 && tr >= r22) {
        const T h = math::sqrt(T(1) + tr);  // 2|w|
        w = h / T(2);
        x = (m[2][1] - m[1][2]) / (T(2) * h);
        y = (m[0][2] - m[2][0]) / (T(2) * h);
        z = (m[1][0] - m[0][1]) / (T(2) * h);
    } else if (r00 >= r11 && r00 >= r22) {
        const T h = math::sqrt(T(1) + r00 - r11 - r22);  // 2|x|
        x = h / T(2);
        w = (m[2][1] - m[1][2]) / (T(2) * h);
        y = (m[0][1] + m[1][0]) / (T(2) * h);
        z = (m[0][2] + m[2][0]) / (T(2) * h);
    } else if (r11 >= r22) {
        const T h = math::sqrt(T(1) - r00 + r11 - r22);  // 2|y|
        y = h / T(2);
        w = (m[0][2] - m[2][0]) / (T(2) * h);
        x = (m[0][1] + m[1][0]) / (T(2) * h);
        z = (m[1][2] + m[2][1]) / (T(2) * h);
    } else {
        const T h = math::sqrt(T(1) - r00 - r11 + r22);  // 2|z|
        z = h / T(2);
        w = (m[1][0] - m[0][1]) / (T(2) * h);
        x = (m[0][2] + m[2][0]) / (T(2) * h);
        y = (m[1][2] + m[2][1]) / (T(2) * h);
    }
    T n = math::sqrt(w * w + x * x + y * y + z * z);
    if (w < T(0)) n = -n;
    w /= n, x /= n, y /= n, z /= n;

    const T tx = m[0][3], ty = m[1][3], tz = m[2][3];
    const T b0 = -(tx * x + ty * y + tz * z) / T(2);
    const T bx = (w * tx + (ty * z - tz * y)) / T(2);
    const T by = (w * ty + (tz * x - tx * z)) / T(2);
    const T bz = (w * tz + (tx * y - ty * x)) / T(2);
    return {motor<T>{w, x, y, z, b0, bx, by, bz}, error_code::none};
}

}  // namespace ctga
