// Inertias moving with the body: (g ḡ) N (g ḡ)* (paper §5), for every representation of an
// inertia (mass_properties.hpp, inertia.hpp, body_inertia.hpp).
//
// A sandwich by a unit motor is a linear map; on the grade-4 elements it is the congruence with
// H⁻ᵀ (the outermorphism of the sandwich, §5: h(a ∧ b)h* = (h a h*) ∧ (h b h*)), N' = H⁻ᵀ N H⁻¹,
// and M' = H M Hᵀ for a mobility. Each is applied through the motor_map (motor.hpp).
#pragma once

#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/detail/matrix_blades.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/inertia_matrix.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/inline.hpp"

namespace ctga {

// Mass properties move with the body: c' = R c + t, I_c' = R I_c Rᵀ (54m 39a).
template <class T>
[[nodiscard]] constexpr mass_properties<T> transform(const motor_map<T>& G, const mass_properties<T>& b) noexcept {
    return {b.mass, linear3::add(linear3::apply(G.R, b.com), G.t), linear3::rotate_symmetric(G.R, b.inertia_c)};
}

namespace transform_detail {

// A rigid body's inertia parameters moved by a motor map: the mass is unchanged, and
template <class T>
struct moved_inertia {
    vec3<T> h;                        // h' = R h + m t
    T xx, yy, zz, xy, xz, yz;         // I_o'
};
// (g ḡ) N (g ḡ)* = H⁻ᵀ N H⁻¹ for N = [[I_o, Ĥ], [−Ĥ, m 1]] (h = m c): m' = m, h' = R h + m t and,
// with u = R h + h' (= 2z for z = R h + (m/2) t),
//   I_o' = R I_o Rᵀ + (u·t) 1 − (t uᵀ + u tᵀ)/2   (parallel axes: Ĉ² terms of c and of R c + t),
// i.e. Σ_{k≠i} t_k u_k added on the diagonal and −(t_i u_j + u_i t_j)/2 off it.
// (R I_o Rᵀ)_ij = R_i·(I_o R_j) for the rows R_i of R; R is a rotation, so tr(R I_o Rᵀ) = tr I_o
// gives the last diagonal entry and only I_o R_0 and I_o R_1 are formed (54m 50a, 3 halvings).
// The statement order (R I_o Rᵀ first, then h' and the parallel-axis terms) keeps the live values
// few: other orders measured 10–25 more instructions (spills) with g++ 12. With R of shape S
// (linear3.hpp: an aligned joint's turn about a coordinate axis) every product with a row of R
// skips its zeros.
template <linear3::shape S = linear3::dense, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr moved_inertia<T> move_inertia(const motor_map<T>& G, const T& m, const vec3<T>& h,
                                                                         const mat3<T>& Io) noexcept {
    using linear3::row_dot;
    const mat3<T>& R = G.R;
    const vec3<T>& t = G.t;
    // R I_o Rᵀ, column by column (I_o R_i: row i of R dotted with each row of I_o, I_o symmetric)
    const vec3<T> a0{row_dot<S, 0>(R, Io[0]), row_dot<S, 0>(R, Io[1]), row_dot<S, 0>(R, Io[2])};
    const T r00 = row_dot<S, 0>(R, a0), r20 = row_dot<S, 2>(R, a0);
    const vec3<T> a1{row_dot<S, 1>(R, Io[0]), row_dot<S, 1>(R, Io[1]), row_dot<S, 1>(R, Io[2])};
    const T r01 = row_dot<S, 0>(R, a1), r11 = row_dot<S, 1>(R, a1), r21 = row_dot<S, 2>(R, a1);
    const T r22 = Io[2][2] + (Io[0][0] - r00) + (Io[1][1] - r11);  // the trace is invariant
    // h' and the parallel-axis terms
    const vec3<T> y = linear3::apply<S>(R, h);
    const vec3<T> h2{y[0] + m * t[0], y[1] + m * t[1], y[2] + m * t[2]};
    const vec3<T> u{y[0] + h2[0], y[1] + h2[1], y[2] + h2[2]};
    const T xy = r01 - (t[0] * u[1] + u[0] * t[1]) / T(2);
    const T xz = r20 - (t[0] * u[2] + u[0] * t[2]) / T(2);
    const T yz = r21 - (t[1] * u[2] + u[1] * t[2]) / T(2);
    const vec3<T> q{t[0] * u[0], t[1] * u[1], t[2] * u[2]};
    return {h2, r00 + (q[1] + q[2]), r11 + (q[0] + q[2]), r22 + (q[0] + q[1]), xy, xz, yz};
}

}  // namespace transform_detail

// (g ḡ) N (g ḡ)* for the 24 stored blades of a rigid body's N (transform_detail::move_inertia).
template <class T>
[[nodiscard]] constexpr rigid_inertia<T> transform(const motor_map<T>& G, const rigid_inertia<T>& N) noexcept {
    using matrix_blades::entry_of;
    using matrix_blades::set_entry;
    const T m = entry_of<false, 3, 3>(N);
    const vec3<T> h{entry_of<false, 2, 4>(N), entry_of<false, 0, 5>(N), entry_of<false, 1, 3>(N)};  // m Ĉ = Ĥ
    const mat3<T> Io{{{entry_of<false, 0, 0>(N), entry_of<false, 0, 1>(N), entry_of<false, 0, 2>(N)},
                      {entry_of<false, 1, 0>(N), entry_of<false, 1, 1>(N), entry_of<false, 1, 2>(N)},
                      {entry_of<false, 2, 0>(N), entry_of<false, 2, 1>(N), entry_of<false, 2, 2>(N)}}};
    const transform_detail::moved_inertia<T> n = transform_detail::move_inertia(G, m, h, Io);
    const vec3<T>& h2 = n.h;
    rigid_inertia<T> out;
    set_entry<false, 0, 0>(out, n.xx);
    set_entry<false, 1, 1>(out, n.yy);
    set_entry<false, 2, 2>(out, n.zz);
    set_entry<false, 0, 1>(out, n.xy), set_entry<false, 1, 0>(out, n.xy);
    set_entry<false, 0, 2>(out, n.xz), set_entry<false, 2, 0>(out, n.xz);
    set_entry<false, 1, 2>(out, n.yz), set_entry<false, 2, 1>(out, n.yz);
    // m Ĉ' = Ĥ' in the upper right, −Ĥ' in the lower left; m 1 in the mass block
    set_entry<false, 0, 4>(out, -h2[2]), set_entry<false, 0, 5>(out, h2[1]), set_entry<false, 1, 3>(out, h2[2]);
    set_entry<false, 1, 5>(out, -h2[0]), set_entry<false, 2, 3>(out, -h2[1]), set_entry<false, 2, 4>(out, h2[0]);
    set_entry<false, 4, 0>(out, -h2[2]), set_entry<false, 5, 0>(out, h2[1]), set_entry<false, 3, 1>(out, h2[2]);
    set_entry<false, 5, 1>(out, -h2[0]), set_entry<false, 3, 2>(out, -h2[1]), set_entry<false, 4, 2>(out, h2[0]);
    set_entry<false, 3, 3>(out, m), set_entry<false, 4, 4>(out, m), set_entry<false, 5, 5>(out, m);
    return out;
}

namespace transform_detail {

// L X Lᵀ for L = [[R, 0], [T R, R]] and any 6×6 X: rotate each 3×3 block (R B Rᵀ), then shear
// by S = [[1, 0], [T, 1]], whose action is a cross product with t column by column.
template <class T>
constexpr mat6<T> congruence(const motor_map<T>& G, const mat6<T>& X) noexcept {
    mat6<T> Y{};
    for (std::size_t bi = 0; bi < 2; ++bi)
        for (std::size_t bj = 0; bj < 2; ++bj) {
            mat3<T> RB{};  // R B
            for (std::size_t i = 0; i < 3; ++i)
                for (std::size_t j = 0; j < 3; ++j)
                    RB[i][j] = G.R[i][0] * X[3 * bi][3 * bj + j] + G.R[i][1] * X[3 * bi + 1][3 * bj + j] +
                               G.R[i][2] * X[3 * bi + 2][3 * bj + j];
            for (std::size_t i = 0; i < 3; ++i)
                for (std::size_t j = 0; j < 3; ++j) Y[3 * bi + i][3 * bj + j] = linear3::dot(RB[i], G.R[j]);  // (R B) Rᵀ
        }
    // rows: [A; C] ↦ [A; T A + C] (left multiplication by S)
    for (std::size_t j = 0; j < 6; ++j) {
        const vec3<T> tc = linear3::cross(G.t, vec3<T>{Y[0][j], Y[1][j], Y[2][j]});
        for (std::size_t i = 0; i < 3; ++i) Y[3 + i][j] += tc[i];
    }
    // columns: [A B] ↦ [A, A Tᵀ + B] (right multiplication by Sᵀ); row x ↦ x Tᵀ = (T xᵀ)ᵀ = t × x
    for (std::size_t i = 0; i < 6; ++i) {
        const vec3<T> tr = linear3::cross(G.t, vec3<T>{Y[i][0], Y[i][1], Y[i][2]});
        for (std::size_t j = 0; j < 3; ++j) Y[i][3 + j] += tr[j];
    }
    return Y;
}

// P X P with P = [[0, 1], [1, 0]]: H⁻ᵀ = P H P, so a co-screw-side congruence is a screw-side one.
template <class T>
constexpr mat6<T> swap_halves(const mat6<T>& X) noexcept {
    mat6<T> Y{};
    for (std::size_t i = 0; i < 6; ++i)
        for (std::size_t j = 0; j < 6; ++j) Y[i][j] = X[(i + 3) % 6][(j + 3) % 6];
    return Y;
}

}  // namespace transform_detail

// A general inertia (any 36 coefficients): N' = H⁻ᵀ N H⁻¹.
template <class T>
[[nodiscard]] constexpr inertia<T> transform(const motor_map<T>& G, const inertia<T>& N) noexcept {
    using namespace transform_detail;
    // H⁻ᵀ = P H P, so H⁻ᵀ N H⁻¹ = P H (P N P) Hᵀ P
    return inertia_from_matrix(swap_halves(congruence(G, swap_halves(inertia_matrix(N)))));
}

// A mobility transforms as the inverse of an inertia: M' = H M Hᵀ (so that (N')⁻¹ = M').
template <class T>
[[nodiscard]] constexpr mobility<T> transform(const motor_map<T>& G, const mobility<T>& M) noexcept {
    return mobility_from_matrix(transform_detail::congruence(G, mobility_matrix(M)));
}

// (g ḡ) N (g ḡ)* on the ten parameters (transform_detail::move_inertia, 54m 50a).
template <linear3::shape S = linear3::dense, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr body_inertia<T> transform(const motor_map<T>& G, const body_inertia<T>& N) noexcept {
    using s = typename body_inertia<T>::scalar;
    const transform_detail::moved_inertia<T> n = transform_detail::move_inertia<S>(G, N.mass(), N.first_moment(), N.inertia_o());
    return {N.m, s{n.h[0]}, s{n.h[1]}, s{n.h[2]}, s{n.xx}, s{n.yy}, s{n.zz}, s{n.xy}, s{n.xz}, s{n.yz}};
}

}  // namespace ctga
