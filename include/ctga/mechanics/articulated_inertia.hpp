// The articulated-body inertia (Featherstone, "Rigid Body Dynamics Algorithms" (2008), §7.2):
// the inertia a body shows at its joint frame with everything it carries attached by joints.
// It is a symmetric 6×6 inertia, so in the paper's algebra it is an element of the same kind as a
// rigid body's N (§5): N = Σ N(i, j) α_i ε̃_j (detail/matrix_blades.hpp), the momentum
// (here: the force it takes to accelerate the articulated body) A ∨ (N ∧ s), the pairing P(s).
// It differs from a rigid body's N only in having no structural zeros, and in being moved into
// a parent's frame by the same law N' = H⁻ᵀ N H⁻¹ (§5: (g ḡ) N (g ḡ)*).
//
//   articulated_inertia   N by its 21 distinct entries (the upper triangle): one leaf each in
//                         a formula, as body_inertia's ten parameters are
//
// With the blocks N = [[A, B], [Bᵀ, C]] acting on screws (ω, v) and giving co-screws (n, f):
//   a rigid body's N is the special case A = I_o, B = Ĥ, C = m 1 (articulated_inertia_of);
//   the joint's share is removed by the rank-one update N − U Uᵀ / D, U = N S, D = U(S)
//   (Featherstone eq. 7.41; minus_joint);
//   a 6-dof joint (S = 1) needs s = N⁻¹ P (solve: Cholesky of the symmetric positive N).
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <tuple>
#include <utility>

#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/detail/matrix_blades.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/inertia_matrix.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga {

namespace articulated_detail {

// Entry (i, j), i ≤ j, of the upper triangle, row by row: k = 0 … 20.
constexpr std::size_t upper_index(std::size_t i, std::size_t j) noexcept { return i * 6 - i * (i - 1) / 2 + (j - i); }
struct row_col {
    std::size_t i, j;
};
inline constexpr std::array<row_col, 21> upper_entries = [] {
    std::array<row_col, 21> out{};
    for (std::size_t i = 0; i < 6; ++i)
        for (std::size_t j = i; j < 6; ++j) out[upper_index(i, j)] = {i, j};
    return out;
}();

// The blade α_i ε̃_j of entry (i, j), spelled as a name the algebra reads (matrix_blades::join).
template <std::size_t I, std::size_t J>
inline constexpr auto entry_name = [] {
    constexpr std::string_view a = matrix_blades::coscrew_blade[I], b = matrix_blades::screw_blade[(J + 3) % 6];
    fixed_string<a.size() + b.size() + 1> s;
    std::size_t n = 0;
    for (char ch : a) s.chars[n++] = ch;
    for (char ch : b) s.chars[n++] = ch;
    return s;
}();
// Entry k of the upper triangle as an element: α_i ε̃_j + α_j ε̃_i (one blade on the diagonal).
template <std::size_t K>
CTGA_ALWAYS_INLINE constexpr auto symmetric_pair() noexcept {
    constexpr std::size_t i = upper_entries[K].i, j = upper_entries[K].j;
    if constexpr (i == j) return cl062::basis<entry_name<i, j>>;
    else return cl062::basis<entry_name<i, j>> + cl062::basis<entry_name<j, i>>;
}

}  // namespace articulated_detail

template <class T = double>
struct articulated_inertia {
    using scalar = cl062::mv<T, "1">;
    std::array<scalar, 21> n{};  // N(i, j) for i ≤ j, row by row (articulated_detail::upper_index)

    // Entries not cleared, for a result every entry of which is written (support/uninitialized.hpp:
    // for packs of 8 lanes the clearing was a 1.3 KB memset per inertia the compiler kept).
    [[nodiscard]] static constexpr articulated_inertia uninitialized_value() noexcept {
        return articulated_inertia{uninitialized_array<scalar, 21>()};
    }

    [[nodiscard]] constexpr T operator()(std::size_t i, std::size_t j) const noexcept {
        return i <= j ? n[articulated_detail::upper_index(i, j)][0] : n[articulated_detail::upper_index(j, i)][0];
    }
    constexpr void set(std::size_t i, std::size_t j, const T& x) noexcept {
        n[i <= j ? articulated_detail::upper_index(i, j) : articulated_detail::upper_index(j, i)] = scalar{x};
    }

    // Inertias in one frame add (§5: N is linear in the mass distribution): 21a.
    [[nodiscard]] friend constexpr articulated_inertia operator+(const articulated_inertia& a,
                                                                 const articulated_inertia& b) noexcept {
        articulated_inertia out = uninitialized_value();
        for (std::size_t k = 0; k < 21; ++k) out.n[k] = a.n[k] + b.n[k];
        return out;
    }

    // As an argument of a formula (formula.hpp): 21 leaves, N = Σ_{i≤j} N(i,j)(α_i ε̃_j + α_j ε̃_i).
    [[nodiscard]] constexpr auto parameters() const noexcept {
        return [&]<std::size_t... K>(std::index_sequence<K...>) { return std::tie(n[K]...); }(std::make_index_sequence<21>{});
    }
    static constexpr auto element = [](auto... p) {
        static_assert(sizeof...(p) == 21, "an articulated inertia has 21 parameters");
        const std::tuple<decltype(p)...> leaf{p...};
        return [&]<std::size_t... K>(std::index_sequence<K...>) {
            return ((std::get<K>(leaf) * articulated_detail::symmetric_pair<K>()) + ...);
        }(std::make_index_sequence<21>{});
    };
};

// A rigid body's N = [[I_o, Ĥ], [−Ĥ, m 1]] (§2) as an articulated inertia: the body alone.
template <class T>
[[nodiscard]] constexpr articulated_inertia<T> articulated_inertia_of(const body_inertia<T>& N) noexcept {
    using s = typename articulated_inertia<T>::scalar;
    const s zero{T(0)};
    // rows of the upper triangle: (I_o row 0, Ĥ row 0), (I_o row 1, Ĥ row 1), (I_o, Ĥ row 2), m 1
    return {{N.ixx, N.ixy, N.ixz, zero, s{-N.hz[0]}, N.hy,   //
             N.iyy, N.iyz, N.hz, zero, s{-N.hx[0]},          //
             N.izz, s{-N.hy[0]}, N.hx, zero,                 //
             N.m, zero, zero,                                //
             N.m, zero,                                      //
             N.m}};
}

// The joint's share removed (Featherstone eq. 7.41): N − U Uᵀ / D for U = N S and D = U(S) of a
// one-degree-of-freedom joint, given U and 1/D. What the parent sees through the joint (27m 21a).
// (N − U Uᵀ/D) S = U − U D/D = 0: when S is the single blade of screw component Null (an axis
// joint), row and column Null are exactly zero, and are set so rather than computed (15m fewer,
// and no rounding left where the algebra has none). Null = 6: no such component.
template <std::size_t Null = 6, class T>
[[nodiscard]] constexpr articulated_inertia<T> minus_joint(const articulated_inertia<T>& N, const coscrew<T>& U,
                                                           const T& D_inverse) noexcept {
    std::array<T, 6> W;  // U / D
    for (std::size_t i = 0; i < 6; ++i) W[i] = U[i] * D_inverse;
    articulated_inertia<T> out = articulated_inertia<T>::uninitialized_value();
    [&]<std::size_t... K>(std::index_sequence<K...>) {
        ((out.n[K] = typename articulated_inertia<T>::scalar{
              articulated_detail::upper_entries[K].i == Null || articulated_detail::upper_entries[K].j == Null
                  ? T(0)
                  : N.n[K][0] - W[articulated_detail::upper_entries[K].i] * U[articulated_detail::upper_entries[K].j]}),
         ...);
    }(std::make_index_sequence<21>{});
    return out;
}

namespace articulated_detail {
// R X Rᵀ for R of shape S (linear3.hpp) and a 3×3 block X whose row RowSkip and column ColSkip
// are zero (3: none): each dot product skips the entries either side knows to be zero.
template <std::size_t RowSkip, std::size_t ColSkip, linear3::shape S, class T>
CTGA_ALWAYS_INLINE constexpr mat3<T> rotate_block(const mat3<T>& R, const mat3<T>& X) noexcept {
    constexpr linear3::shape by_col = linear3::with_zero_column(S, ColSkip), by_row = linear3::with_zero_column(S, RowSkip);
    mat3<T> XRt{};  // X Rᵀ: entry (k, j) = row j of R · row k of X
    for (std::size_t k = 0; k < 3; ++k)
        if (k != RowSkip) {
            XRt[k][0] = linear3::row_dot<by_col, 0>(R, X[k]);
            XRt[k][1] = linear3::row_dot<by_col, 1>(R, X[k]);
            XRt[k][2] = linear3::row_dot<by_col, 2>(R, X[k]);
        }
    mat3<T> out;  // R (X Rᵀ): entry (i, j) = row i of R · column j of X Rᵀ
    for (std::size_t j = 0; j < 3; ++j) {
        const vec3<T> column{XRt[0][j], XRt[1][j], XRt[2][j]};
        out[0][j] = linear3::row_dot<by_row, 0>(R, column);
        out[1][j] = linear3::row_dot<by_row, 1>(R, column);
        out[2][j] = linear3::row_dot<by_row, 2>(R, column);
    }
    return out;
}
}  // namespace articulated_detail

// N' = H⁻ᵀ N H⁻¹ (§5: (g ḡ) N (g ḡ)*), for G = (R, t) the map of the child's frame into the
// parent's, H = [[R, 0], [T R, R]] (T = t̂, as transform(G, s) moves a screw). With the rotated
// blocks A' = R A Rᵀ, B' = R B Rᵀ, C' = R C Rᵀ, and Y = T C', X = T B'ᵀ:
//   C'' = C',  B'' = B' + Y,  A'' = A' + X + Xᵀ − Y T
// ([[1, T], [0, 1]] [[A', B'], [B'ᵀ, C']] [[1, 0], [−T, 1]]; Y T = T C' T is symmetric, and row
// i of −Y T is t × (row i of Y)). 189m 150a for a full N; with a zero row and column Null
// (minus_joint after an axis joint) the rotations skip it: 159m for a revolute joint's N; with R
// of shape S (an aligned joint's turn about a coordinate axis) they skip its zeros too.
namespace articulated_detail {
template <std::size_t Null, linear3::shape S, class T>
CTGA_ALWAYS_INLINE constexpr articulated_inertia<T> transform(const motor_map<T>& G, const articulated_inertia<T>& N) noexcept {
    using linear3::cross;
    constexpr std::size_t skip_w = Null < 3 ? Null : 3, skip_v = Null >= 3 && Null < 6 ? Null - 3 : 3;
    const mat3<T>& R = G.R;
    const vec3<T>& t = G.t;
    mat3<T> A, B, C;  // every entry written
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) A[i][j] = N(i, j), B[i][j] = N(i, j + 3), C[i][j] = N(i + 3, j + 3);
    const mat3<T> A1 = articulated_detail::rotate_block<skip_w, skip_w, S>(R, A);
    const mat3<T> B1 = articulated_detail::rotate_block<skip_w, skip_v, S>(R, B);
    const mat3<T> C1 = articulated_detail::rotate_block<skip_v, skip_v, S>(R, C);
    // Y = T C' column by column (C' symmetric: its columns are its rows); B'' = B' + Y
    mat3<T> Y;
    for (std::size_t j = 0; j < 3; ++j) {
        const vec3<T> y = cross(t, C1[j]);
        for (std::size_t i = 0; i < 3; ++i) Y[i][j] = y[i];
    }
    // X = T B'ᵀ: column j is t × (row j of B')
    mat3<T> X;
    for (std::size_t j = 0; j < 3; ++j) {
        const vec3<T> x = cross(t, B1[j]);
        for (std::size_t i = 0; i < 3; ++i) X[i][j] = x[i];
    }
    articulated_inertia<T> out = articulated_inertia<T>::uninitialized_value();  // all 21 entries set below
    for (std::size_t i = 0; i < 3; ++i) {
        const vec3<T> z = cross(t, Y[i]);  // row i of −Y T
        for (std::size_t j = i; j < 3; ++j) out.set(i, j, A1[i][j] + X[i][j] + X[j][i] + z[j]);
        for (std::size_t j = 0; j < 3; ++j) out.set(i, j + 3, B1[i][j] + Y[i][j]);
        for (std::size_t j = i; j < 3; ++j) out.set(i + 3, j + 3, C1[i][j]);
    }
    return out;
}
template <std::size_t Null, linear3::shape S, class T>
CTGA_SCALAR_CODE constexpr articulated_inertia<T> transform_scalar(const motor_map<T>& G, const articulated_inertia<T>& N) noexcept {
    return articulated_detail::transform<Null, S>(G, N);
}
}  // namespace articulated_detail
template <std::size_t Null = 6, linear3::shape S = linear3::dense, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr articulated_inertia<T> transform(const motor_map<T>& G, const articulated_inertia<T>& N) noexcept {
    if constexpr (lane_wise<T>) return articulated_detail::transform<Null, S>(G, N);
    else return articulated_detail::transform_scalar<Null, S>(G, N);
}

// s = N⁻¹ P, the screw the articulated inertia takes to P (N symmetric positive definite, as a
// body with positive mass makes it): N = L D Lᵀ with L unit lower triangular, then two triangular
// solves (6×6: 70m 6 divisions; no square roots, so it is a constant expression too).
template <class T>
[[nodiscard]] constexpr screw<T> solve(const articulated_inertia<T>& N, const coscrew<T>& P) noexcept {
    T L[6][6]{}, D[6]{}, inv_D[6]{};
    for (std::size_t j = 0; j < 6; ++j) {
        T d = N(j, j);
        for (std::size_t k = 0; k < j; ++k) d -= L[j][k] * L[j][k] * D[k];
        D[j] = d;
        inv_D[j] = T(1) / d;
        for (std::size_t i = j + 1; i < 6; ++i) {
            T x = N(i, j);
            for (std::size_t k = 0; k < j; ++k) x -= L[i][k] * L[j][k] * D[k];
            L[i][j] = x * inv_D[j];
        }
    }
    T y[6]{};
    for (std::size_t i = 0; i < 6; ++i) {  // L y = P
        T x = P[i];
        for (std::size_t k = 0; k < i; ++k) x -= L[i][k] * y[k];
        y[i] = x;
    }
    T s[6]{};
    for (std::size_t i = 6; i-- > 0;) {  // D Lᵀ s = y
        T x = y[i] * inv_D[i];
        for (std::size_t k = i + 1; k < 6; ++k) x -= L[k][i] * s[k];
        s[i] = x;
    }
    return screw<T>{s[0], s[1], s[2], s[3], s[4], s[5]};
}

}  // namespace ctga
