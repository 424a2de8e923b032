// 3-vectors and 3×3 matrices for the structured forms of §2 (rotation R, translation t, the
// inertia tensor), where a sandwich by a motor has been built once into a linear map.
// Plain arrays, constexpr, no heap: std::array<T, 3> and row-major std::array<std::array<T, 3>, 3>.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "ctga/support/math.hpp"

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
[[nodiscard]] constexpr vec3<T> sub(const vec3<T>& a, const vec3<T>& b) noexcept {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class T>
[[nodiscard]] constexpr vec3<T> scale(const T& s, const vec3<T>& a) noexcept {
    return {s * a[0], s * a[1], s * a[2]};
}
// a + s b
template <class T>
[[nodiscard]] constexpr vec3<T> add_scaled(const vec3<T>& a, const T& s, const vec3<T>& b) noexcept {
    return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}
// Which entries of a 3×3 matrix are known at compile time to be 0, 1 or −1 (a shape): the rotation
// of a joint whose frame is aligned with its parent's is a turn about one coordinate axis, with five
// such entries, and that of a joint turned by multiples of π/2 the same turn with its rows moved
// and negated (chains/joints.hpp, turned). Applying the matrix skips the zeros and does not
// multiply by ±1 (it adds or subtracts); the dense shape is the plain product.
enum class entry : unsigned char { zero, one, minus_one, any };
struct shape {
    std::array<entry, 9> e;  // row-major
    [[nodiscard]] constexpr entry at(std::size_t row, std::size_t col) const noexcept { return e[3 * row + col]; }
};
inline constexpr shape dense{{entry::any, entry::any, entry::any, entry::any, entry::any, entry::any, entry::any, entry::any, entry::any}};
inline constexpr shape identity{{entry::one, entry::zero, entry::zero, entry::zero, entry::one, entry::zero, entry::zero, entry::zero, entry::one}};

namespace shape_detail {
struct nothing {};  // no term summed yet
// Σ_c m(Row, c) x_c (m(c, Row) when Transposed) from column C on, left to right, over the entries S
// does not know to be 0; an entry known to be 1 adds x_c, one known to be −1 subtracts it (the
// first term: −x_c). (All zero: 0.)
template <shape S, bool Transposed, int Row, int C, class T, class Sum>
constexpr T row_sum(const mat3<T>& m, const vec3<T>& x, const Sum& sum) noexcept {
    if constexpr (C == 3) {
        if constexpr (std::is_same_v<Sum, nothing>) return T(0);
        else return sum;
    } else {
        constexpr entry e = Transposed ? S.at(C, Row) : S.at(Row, C);
        if constexpr (e == entry::zero) {
            return row_sum<S, Transposed, Row, C + 1>(m, x, sum);
        } else if constexpr (e == entry::minus_one && !std::is_same_v<Sum, nothing>) {
            return row_sum<S, Transposed, Row, C + 1>(m, x, T(sum - x[C]));
        } else {
            const T term = [&] {
                if constexpr (e == entry::one) return x[C];
                else if constexpr (e == entry::minus_one) return T(-x[C]);
                else return (Transposed ? m[C][Row] : m[Row][C]) * x[C];
            }();
            if constexpr (std::is_same_v<Sum, nothing>) return row_sum<S, Transposed, Row, C + 1>(m, x, term);
            else return row_sum<S, Transposed, Row, C + 1>(m, x, T(sum + term));
        }
    }
}
}  // namespace shape_detail

// The flops of m x for m of shape S: per row, a multiplication for each entry that is not known
// (0, ±1) and an addition for each non-zero entry but the first (dense: 15; a turn about a
// coordinate axis, turned or not: 6; the identity: 0; a row whose only entry is −1 negates, not counted).
[[nodiscard]] constexpr std::size_t apply_cost(const shape& S) noexcept {
    std::size_t c = 0;
    for (std::size_t r = 0; r < 3; ++r) {
        std::size_t nonzero = 0;
        for (std::size_t j = 0; j < 3; ++j) {
            nonzero += S.at(r, j) != entry::zero ? std::size_t{1} : 0;
            c += S.at(r, j) == entry::any ? std::size_t{1} : 0;
        }
        c += nonzero > 0 ? nonzero - 1 : 0;
    }
    return c;
}

// Row Row of m (shape S) dotted with x.
template <shape S, int Row, class T>
[[nodiscard]] constexpr T row_dot(const mat3<T>& m, const vec3<T>& x) noexcept {
    return shape_detail::row_sum<S, false, Row, 0>(m, x, shape_detail::nothing{});
}
// S with column Col known to be zero too (Col = 3: S): a product with a vector whose entry Col is a
// structural zero.
[[nodiscard]] constexpr shape with_zero_column(shape S, std::size_t col) noexcept {
    if (col < 3)
        for (std::size_t r = 0; r < 3; ++r) S.e[3 * r + col] = entry::zero;
    return S;
}

// m x and mᵀ x for m of shape S (dense: 9m 6a; a turn about a coordinate axis: 4m 2a).
template <shape S = dense, class T>
[[nodiscard]] constexpr vec3<T> apply(const mat3<T>& m, const vec3<T>& x) noexcept {
    using shape_detail::row_sum, shape_detail::nothing;
    return {row_sum<S, false, 0, 0>(m, x, nothing{}), row_sum<S, false, 1, 0>(m, x, nothing{}), row_sum<S, false, 2, 0>(m, x, nothing{})};
}
template <shape S = dense, class T>
[[nodiscard]] constexpr vec3<T> apply_transposed(const mat3<T>& m, const vec3<T>& x) noexcept {
    using shape_detail::row_sum, shape_detail::nothing;
    return {row_sum<S, true, 0, 0>(m, x, nothing{}), row_sum<S, true, 1, 0>(m, x, nothing{}), row_sum<S, true, 2, 0>(m, x, nothing{})};
}
// R S Rᵀ for a symmetric S, computing the upper triangle and mirroring it (45m 30a).
template <class T>
[[nodiscard]] constexpr mat3<T> rotate_symmetric(const mat3<T>& R, const mat3<T>& S) noexcept {
    mat3<T> RS{};
    for (std::size_t i = 0; i < 3; ++i) RS[i] = apply_transposed(S, R[i]);  // row i of R S (S = Sᵀ)
    mat3<T> out{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i; j < 3; ++j) out[i][j] = out[j][i] = dot(RS[i], R[j]);
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

// A symmetric S as V diag(d) Vᵀ: cyclic Jacobi rotations (Golub and Van Loan, §8.5), each zeroing
// one off-diagonal entry, until the off-diagonal part is below rounding (quadratic convergence:
// a few sweeps). V's columns are the eigenvectors; V is a rotation (det +1: a column's sign is
// free, the last is turned when det is −1).
template <class T>
struct symmetric_eigen {
    mat3<T> V;
    vec3<T> d;
};
template <class T>
[[nodiscard]] constexpr symmetric_eigen<T> eigen_symmetric(mat3<T> A) noexcept {
    mat3<T> V{{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}};
    const T scale = A[0][0] * A[0][0] + A[1][1] * A[1][1] + A[2][2] * A[2][2] +
                    T(2) * (A[0][1] * A[0][1] + A[0][2] * A[0][2] + A[1][2] * A[1][2]);
    const T tiny = std::numeric_limits<T>::epsilon() * std::numeric_limits<T>::epsilon() * scale;
    for (int sweep = 0; sweep < 32; ++sweep) {
        if (A[0][1] * A[0][1] + A[0][2] * A[0][2] + A[1][2] * A[1][2] <= tiny) break;
        for (const auto& [p, q] : {std::array<std::size_t, 2>{0, 1}, {0, 2}, {1, 2}}) {
            if (A[p][q] == T(0)) continue;
            // the rotation J in the (p, q) plane with (Jᵀ A J)_pq = 0: t = tan of its angle, the
            // smaller root of t² + 2θt − 1 = 0, θ = (A_qq − A_pp) / (2 A_pq)
            const T theta = (A[q][q] - A[p][p]) / (T(2) * A[p][q]);
            const T t = (theta >= T(0) ? T(1) : T(-1)) / ((theta >= T(0) ? theta : -theta) + math::sqrt(theta * theta + T(1)));
            const T c = T(1) / math::sqrt(t * t + T(1)), s = t * c;
            for (std::size_t k = 0; k < 3; ++k) {  // A ← A J (columns p, q), V ← V J
                const T akp = A[k][p], akq = A[k][q];
                A[k][p] = c * akp - s * akq, A[k][q] = s * akp + c * akq;
                const T vkp = V[k][p], vkq = V[k][q];
                V[k][p] = c * vkp - s * vkq, V[k][q] = s * vkp + c * vkq;
            }
            for (std::size_t k = 0; k < 3; ++k) {  // A ← Jᵀ A (rows p, q)
                const T apk = A[p][k], aqk = A[q][k];
                A[p][k] = c * apk - s * aqk, A[q][k] = s * apk + c * aqk;
            }
        }
    }
    const vec3<T> c0{V[0][0], V[1][0], V[2][0]}, c1{V[0][1], V[1][1], V[2][1]}, c2{V[0][2], V[1][2], V[2][2]};
    if (dot(cross(c0, c1), c2) < T(0))
        for (std::size_t k = 0; k < 3; ++k) V[k][2] = -V[k][2];
    return {V, {A[0][0], A[1][1], A[2][2]}};
}

}  // namespace linear3
}  // namespace ctga
