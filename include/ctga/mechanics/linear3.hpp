// 3-vectors and 3×3 matrices for the structured forms of §2 (rotation R, translation t, the
// inertia tensor), where a sandwich by a motor has been built once into a linear map.
// Plain arrays, constexpr, no heap: std::array<T, 3> and row-major std::array<std::array<T, 3>, 3>.
#pragma once

#include <array>

namespace ctga {

template <class T>
using vec3 = std::array<T, 3>;
template <class T>
using mat3 = std::array<std::array<T, 3>, 3>;  // row-major: m[row][col]
template <class T>
using vec6 = std::array<T, 6>;
template <class T>
using mat6 = std::array<std::array<T, 6>, 6>;  // row-major

namespace linear3 {

template <class T>
[[nodiscard]] constexpr T dot(const vec3<T>& a, const vec3<T>& b) noexcept {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
[[nodiscard]] constexpr vec3<T> cross(const vec3<T>& a, const vec3<T>& b) noexcept {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
[[nodiscard]] constexpr vec3<T> add(const vec3<T>& a, const vec3<T>& b) noexcept {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
template <class T>
[[nodiscard]] constexpr vec3<T> apply(const mat3<T>& m, const vec3<T>& x) noexcept {
    return {dot(m[0], x), dot(m[1], x), dot(m[2], x)};
}
template <class T>
[[nodiscard]] constexpr vec3<T> apply_transposed(const mat3<T>& m, const vec3<T>& x) noexcept {
    vec3<T> out{};
    for (int j = 0; j < 3; ++j) out[j] = m[0][j] * x[0] + m[1][j] * x[1] + m[2][j] * x[2];
    return out;
}
// R S Rᵀ for a symmetric S, computing the upper triangle and mirroring it (45m 30a).
template <class T>
[[nodiscard]] constexpr mat3<T> rotate_symmetric(const mat3<T>& R, const mat3<T>& S) noexcept {
    mat3<T> RS{};
    for (int i = 0; i < 3; ++i) RS[i] = apply_transposed(S, R[i]);  // row i of R S (S = Sᵀ)
    mat3<T> out{};
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) out[i][j] = out[j][i] = dot(RS[i], R[j]);
    return out;
}
// Ĉ, the antisymmetric matrix with Ĉ x = c × x (§2).
template <class T>
[[nodiscard]] constexpr mat3<T> hat(const vec3<T>& c) noexcept {
    return {{{T(0), -c[2], c[1]}, {c[2], T(0), -c[0]}, {-c[1], c[0], T(0)}}};
}
// The inverse of a symmetric 3×3 matrix by cofactors (the caller has checked det > 0).
template <class T>
[[nodiscard]] constexpr mat3<T> inverse_symmetric(const mat3<T>& S) noexcept {
    const T c00 = S[1][1] * S[2][2] - S[1][2] * S[1][2];
    const T c01 = S[0][2] * S[1][2] - S[0][1] * S[2][2];
    const T c02 = S[0][1] * S[1][2] - S[0][2] * S[1][1];
    const T c11 = S[0][0] * S[2][2] - S[0][2] * S[0][2];
    const T c12 = S[0][1] * S[0][2] - S[0][0] * S[1][2];
    const T c22 = S[0][0] * S[1][1] - S[0][1] * S[0][1];
    const T inv_det = T(1) / (S[0][0] * c00 + S[0][1] * c01 + S[0][2] * c02);
    const T a = c00 * inv_det, b = c01 * inv_det, c = c02 * inv_det, d = c11 * inv_det, e = c12 * inv_det,
            f = c22 * inv_det;
    return {{{a, b, c}, {b, d, e}, {c, e, f}}};
}

}  // namespace linear3
}  // namespace ctga
