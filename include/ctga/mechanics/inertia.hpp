// Inertias (paper §2, §5): every representation of a rigid body's (or a general) inertia, the
// operations that use one (momentum, kinetic energy, dN/dt, the velocity a mobility gives) and
// how each moves with the body. Which to use when is tabled in docs/design.md.
//
//   mass_properties  (m, c, I_c): mass, centre of mass, inertia tensor about it; checked input
//   body_inertia     N by its ten parameters (m, h = m c, I_o): the cheapest N in formulas
//   rigid_inertia    N as the 24 blades that are not structurally zero for a rigid body
//   inertia          N as all 36 blades: a general symmetric 6×6 inertia
//   mobility         M = N⁻¹ as 36 blades: velocity from momentum, s = E ∨ (M ∧ P)
//   body_mobility    M by its ten parameters (1/m, c, J = I_c⁻¹): M = (t t̄) M_c (t t̄)*, the
//                    mobility about the centre of mass moved there; the cheapest velocity
//   rigid_body       mass properties with N and M precomputed, for the equations of motion
//
//   N = [[I_c − m Ĉ², m Ĉ], [−m Ĉ, m 1]] = [[I_o, Ĥ], [−Ĥ, m 1]]          (§2, C = Ĉ, h = m c)
//   M = N⁻¹ = [[J, −J Ĉ], [Ĉ J, 1/m − Ĉ J Ĉ]],  J = I_c⁻¹
//
// Entry (i, j) of the 6×6 matrix is the coefficient of one blade (detail/matrix_blades.hpp), so
// §5's diagonal inertia is N = dx a1ae1e + … + m a2a3e2e3 + …, entry by entry the matrix of §2.
//
// Physical validity is checked where the numbers come in (make_mass_properties): finite values,
// m > 0, I_c symmetric positive definite, and principal moments obeying the triangle inequalities
// I_i ≤ I_j + I_k (equivalently, the second moment ½ tr(I)·1 − I is positive semi-definite: some
// mass distribution has these moments). Equality is allowed (a lamina).
#pragma once

#include <cassert>
#include <limits>
#include <tuple>
#include <type_traits>

#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/detail/matrix_blades.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/operations/formula.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/inline.hpp"

namespace ctga {

// ---- the representations ----------------------------------------------------------------------

// A general symmetric inertia: component 6i + j is the entry N(i, j) of the 6×6 matrix of §2.
template <class T = double>
using inertia = multivector<cl062, T, matrix_blades::inertia_layout>;
// A rigid body's inertia: the 24 blades that are not structurally zero, in row-major order.
template <class T = double>
using rigid_inertia = multivector<cl062, T, matrix_blades::rigid_inertia_layout>;
// The inverse inertia as an element: component 6i + j is the entry M(i, j) of M = N⁻¹.
template <class T = double>
using mobility = multivector<cl062, T, matrix_blades::mobility_layout>;

template <class T = double>
struct mass_properties {
    T mass{};
    vec3<T> com{};         // centre of mass
    mat3<T> inertia_c{};   // inertia tensor about the centre of mass, symmetric
};

namespace inertia_detail {

template <class T>
constexpr T abs(const T& x) noexcept {
    return x < T(0) ? -x : x;
}

// Tolerance for the symmetry and the triangle inequalities: rounding of inputs computed in T.
template <class T>
constexpr T tolerance(const mat3<T>& I) noexcept {
    const T scale = abs(I[0][0]) + abs(I[1][1]) + abs(I[2][2]);
    return T(64) * std::numeric_limits<T>::epsilon() * scale;
}

template <class T>
constexpr error_code check(const T& m, const vec3<T>& c, const mat3<T>& I) noexcept {
    for (const auto& row : I)
        if (!all_finite(row[0], row[1], row[2])) return error_code::non_finite;
    if (!all_finite(m, c[0], c[1], c[2])) return error_code::non_finite;
    if (!(m > T(0))) return error_code::non_positive_mass;
    const T tol = tolerance(I);
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (abs(I[i][j] - I[j][i]) > tol) return error_code::not_symmetric;
    // positive definite: the leading principal minors are positive (Sylvester)
    const T m1 = I[0][0], m2 = I[0][0] * I[1][1] - I[0][1] * I[0][1];
    const T m3 = I[0][0] * (I[1][1] * I[2][2] - I[1][2] * I[1][2]) - I[0][1] * (I[0][1] * I[2][2] - I[1][2] * I[0][2]) +
                 I[0][2] * (I[0][1] * I[1][2] - I[1][1] * I[0][2]);
    if (!(m1 > T(0) && m2 > T(0) && m3 > T(0))) return error_code::not_positive_definite;
    // triangle inequalities: Σ = ½ tr(I)·1 − I positive semi-definite, i.e. every principal minor ≥ 0
    const T half_trace = (I[0][0] + I[1][1] + I[2][2]) / T(2);
    mat3<T> S{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) S[i][j] = (i == j ? half_trace : T(0)) - I[i][j];
    const T t2 = tol * half_trace, t3 = t2 * half_trace;
    for (int i = 0; i < 3; ++i)
        if (S[i][i] < -tol) return error_code::triangle_inequality;
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (S[i][i] * S[j][j] - S[i][j] * S[i][j] < -t2) return error_code::triangle_inequality;
    const T det_s = S[0][0] * (S[1][1] * S[2][2] - S[1][2] * S[1][2]) - S[0][1] * (S[0][1] * S[2][2] - S[1][2] * S[0][2]) +
                    S[0][2] * (S[0][1] * S[1][2] - S[1][1] * S[0][2]);
    if (det_s < -t3) return error_code::triangle_inequality;
    return error_code::none;
}

}  // namespace inertia_detail

// Mass properties from the mass, the centre of mass and the inertia tensor about it, checked.
template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> make_mass_properties(const T& mass, const vec3<T>& com,
                                                                         const mat3<T>& inertia_c) noexcept {
    const error_code e = inertia_detail::check(mass, com, inertia_c);
    if (e != error_code::none) return {{}, e};
    mass_properties<T> out{mass, com, inertia_c};
    // symmetrise what the check accepted as symmetric to rounding
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) out.inertia_c[i][j] = out.inertia_c[j][i] = (inertia_c[i][j] + inertia_c[j][i]) / T(2);
    return {out, error_code::none};
}

// §5's principal-axes body: mass m, principal moments (dx, dy, dz) about the centre of mass at the
// origin. The paper's d_i is "the mass times the square of the radius of gyration".
template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> make_principal_mass_properties(const T& m, const T& dx, const T& dy,
                                                                                   const T& dz) noexcept {
    return make_mass_properties(m, vec3<T>{}, mat3<T>{{{dx, T(0), T(0)}, {T(0), dy, T(0)}, {T(0), T(0), dz}}});
}

// ---- the 6×6 matrix of §2 -------------------------------------------------------------------

// 6×6 matrices. The 12 structurally zero entries of a rigid_inertia come out as zeros.
template <class T, auto L>
[[nodiscard]] constexpr mat6<T> inertia_matrix(const multivector<cl062, T, L>& N) noexcept {
    return matrix_blades::to_matrix<false>(N);
}
template <class T, auto L>
[[nodiscard]] constexpr mat6<T> mobility_matrix(const multivector<cl062, T, L>& M) noexcept {
    return matrix_blades::to_matrix<true>(M);
}
// From a matrix: every entry becomes a blade coefficient (a general inertia or mobility; for a
// rigid body's, mass_properties_of checks the physics).
template <class T>
[[nodiscard]] constexpr inertia<T> inertia_from_matrix(const mat6<T>& m) noexcept {
    return matrix_blades::from_matrix<false, inertia<T>>(m);
}
template <class T>
[[nodiscard]] constexpr mobility<T> mobility_from_matrix(const mat6<T>& m) noexcept {
    return matrix_blades::from_matrix<true, mobility<T>>(m);
}

// ---- from mass properties ------------------------------------------------------------------

// The element N of §5 (24 blades; the other 12 entries of the 6×6 matrix vanish for a rigid body).
template <class T>
[[nodiscard]] constexpr rigid_inertia<T> inertia_of(const mass_properties<T>& b) noexcept {
    const T m = b.mass;
    const vec3<T>& c = b.com;
    const vec3<T> h{m * c[0], m * c[1], m * c[2]};  // first moment m c
    mat6<T> N{};
    // I_o = I_c − m Ĉ² = I_c + m(|c|² 1 − c cᵀ), the parallel-axis theorem
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) N[i][j] = b.inertia_c[i][j] + (i == j ? linear3::dot(h, c) : T(0)) - h[i] * c[j];
    const mat3<T> H = linear3::hat(h);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            N[i][3 + j] = H[i][j];   // m Ĉ
            N[3 + i][j] = -H[i][j];  // m Ĉᵀ = −m Ĉ
        }
    for (int i = 0; i < 3; ++i) N[3 + i][3 + i] = m;
    return matrix_blades::from_matrix<false, rigid_inertia<T>>(N);
}

// The mobility M = N⁻¹: the element taking a co-screw (momentum or impulse) to the screw (velocity).
template <class T>
[[nodiscard]] constexpr mobility<T> mobility_of(const mass_properties<T>& b) noexcept {
    const mat3<T> J = linear3::inverse_symmetric(b.inertia_c);
    const mat3<T> C = linear3::hat(b.com);
    mat3<T> CJ{};  // Ĉ J
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) CJ[i][j] = C[i][0] * J[0][j] + C[i][1] * J[1][j] + C[i][2] * J[2][j];
    mat6<T> M{};
    const T inv_m = T(1) / b.mass;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            M[i][j] = J[i][j];
            M[3 + i][j] = CJ[i][j];
            M[i][3 + j] = CJ[j][i];  // −J Ĉ = (Ĉ J)ᵀ
            // 1/m − Ĉ J Ĉ = 1/m + (Ĉ J) Ĉᵀ
            M[3 + i][3 + j] = (i == j ? inv_m : T(0)) - (CJ[i][0] * C[0][j] + CJ[i][1] * C[1][j] + CJ[i][2] * C[2][j]);
        }
    return matrix_blades::from_matrix<true, mobility<T>>(M);
}

// §5: the diagonal inertia N = dx a1ae1e + dy a2ae2e + dz a3ae3e + m (a2a3e2e3 + a3a1e3e1 + a1a2e1e2),
// assembled directly from the paper's formula (unchecked: see make_principal_mass_properties).
template <class T>
[[nodiscard]] constexpr rigid_inertia<T> diagonal_inertia(const T& m, const T& dx, const T& dy, const T& dz) noexcept {
    return (dx * cl062::basis<"a1ae1e"> + dy * cl062::basis<"a2ae2e"> + dz * cl062::basis<"a3ae3e"> +
                m * (cl062::basis<"a2a3e2e3"> + cl062::basis<"a3a1e3e1"> + cl062::basis<"a1a2e1e2">));
}

// Mass properties read back from a rigid body's 6×6 inertia (or its element), checked: the mass
// block must be m·1, the coupling block m Ĉ antisymmetric, and the result physically valid.
template <class T, auto L>
[[nodiscard]] constexpr checked<mass_properties<T>> mass_properties_of(const multivector<cl062, T, L>& N) noexcept {
    const mat6<T> n = inertia_matrix(N);
    const T m = n[3][3];
    const T tol = T(64) * std::numeric_limits<T>::epsilon() *
                  (inertia_detail::abs(n[0][0]) + inertia_detail::abs(n[1][1]) + inertia_detail::abs(n[2][2]) + inertia_detail::abs(m));
    bool rigid = true;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            rigid = rigid && inertia_detail::abs(n[3 + i][3 + j] - (i == j ? m : T(0))) <= tol;
            rigid = rigid && inertia_detail::abs(n[i][3 + j] + n[3 + i][j]) <= tol;
            rigid = rigid && inertia_detail::abs(n[i][3 + j] + n[j][3 + i]) <= tol;
        }
    if (!all_finite(m)) return {{}, error_code::non_finite};
    if (!(m > T(0))) return {{}, error_code::non_positive_mass};
    if (!rigid) return {{}, error_code::not_a_rigid_inertia};
    const vec3<T> c{n[2][4] / m, n[0][5] / m, n[1][3] / m};  // m Ĉ = [[0, −m cz, m cy], [m cz, 0, −m cx], …]
    mat3<T> Ic{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Ic[i][j] = n[i][j] - m * ((i == j ? linear3::dot(c, c) : T(0)) - c[i] * c[j]);
    return make_mass_properties(m, c, Ic);
}

// A rigid body's N by its ten parameters: the mass m, the first moment h = m c and the inertia
// tensor about the body origin I_o (six numbers, symmetric). N = [[I_o, Ĥ], [−Ĥ, m 1]] has 24
// non-zero blades but only ten distinct coefficients: I_o(i, j) and I_o(j, i) are one number, m
// sits on three blades and each h_k on four. Inside a formula each parameter is one leaf, so
// A ∨ (N ∧ s) reads ten numbers instead of 24 and shares their products exactly where the
// hand-written spatial code does (24m 18a either way).
template <class T = double>
struct body_inertia {
    using scalar = cl062::mv<T, "1">;
    scalar m, hx, hy, hz;            // mass and first moment h = m c
    scalar ixx, iyy, izz, ixy, ixz, iyz;  // I_o, the inertia tensor about the body origin

    [[nodiscard]] constexpr T mass() const noexcept { return m[0]; }
    [[nodiscard]] constexpr vec3<T> first_moment() const noexcept { return {hx[0], hy[0], hz[0]}; }
    [[nodiscard]] constexpr mat3<T> inertia_o() const noexcept {
        return {{{ixx[0], ixy[0], ixz[0]}, {ixy[0], iyy[0], iyz[0]}, {ixz[0], iyz[0], izz[0]}}};
    }

    // Two bodies' inertias in one frame add (§5: N is linear in the mass distribution), so a
    // composite of rigid bodies has a rigid body's N: its ten parameters are the sums (10a).
    [[nodiscard]] friend constexpr body_inertia operator+(const body_inertia& a, const body_inertia& b) noexcept {
        return {a.m + b.m, a.hx + b.hx, a.hy + b.hy, a.hz + b.hz, a.ixx + b.ixx,
                a.iyy + b.iyy, a.izz + b.izz, a.ixy + b.ixy, a.ixz + b.ixz, a.iyz + b.iyz};
    }

    // As an argument of a formula (formula.hpp): ten leaves, and N as the expression they make,
    //   N = Σ I_o(i,j) (α_i ε̃_j + α_j ε̃_i)/(1 + δ_ij) + m (a2a3e2e3 + a3a1e3e1 + a1a2e1e2) + Ĥ blocks,
    // entry (i, j) being the blade α_i ε̃_j (detail/matrix_blades.hpp).
    [[nodiscard]] constexpr auto parameters() const noexcept { return std::tie(m, hx, hy, hz, ixx, iyy, izz, ixy, ixz, iyz); }
    static constexpr auto element = [](auto m, auto hx, auto hy, auto hz, auto ixx, auto iyy, auto izz, auto ixy,
                                       auto ixz, auto iyz) {
        using G = cl062;
        return ixx * G::basis<"a1ae1e"> + iyy * G::basis<"a2ae2e"> + izz * G::basis<"a3ae3e"> +
               ixy * (G::basis<"a1ae2e"> + G::basis<"a2ae1e">) + ixz * (G::basis<"a1ae3e"> + G::basis<"a3ae1e">) +
               iyz * (G::basis<"a2ae3e"> + G::basis<"a3ae2e">) +
               m * (G::basis<"a2a3e2e3"> + G::basis<"a3a1e3e1"> + G::basis<"a1a2e1e2">) +
               // Ĥ in the upper right, −Ĥ = Ĥᵀ in the lower left
               hx * (G::basis<"a3ae3e1"> - G::basis<"a2ae1e2"> + G::basis<"a3a1e3e"> - G::basis<"a1a2e2e">) +
               hy * (G::basis<"a1ae1e2"> - G::basis<"a3ae2e3"> - G::basis<"a2a3e3e"> + G::basis<"a1a2e1e">) +
               hz * (G::basis<"a2ae2e3"> - G::basis<"a1ae3e1"> + G::basis<"a2a3e2e"> - G::basis<"a3a1e1e">);
    };
};

template <class T>
[[nodiscard]] constexpr body_inertia<T> body_inertia_of(const mass_properties<T>& b) noexcept {
    const T m = b.mass;
    const vec3<T>& c = b.com;
    const vec3<T> h{m * c[0], m * c[1], m * c[2]};
    const T hc = linear3::dot(h, c);
    // I_o = I_c + m(|c|² 1 − c cᵀ), the parallel-axis theorem
    const auto io = [&](int i, int j) { return b.inertia_c[i][j] + (i == j ? hc : T(0)) - h[i] * c[j]; };
    using s = typename body_inertia<T>::scalar;
    return {s{m}, s{h[0]}, s{h[1]}, s{h[2]}, s{io(0, 0)}, s{io(1, 1)}, s{io(2, 2)}, s{io(0, 1)}, s{io(0, 2)}, s{io(1, 2)}};
}

// The same element with its 24 blades stored.
template <class T>
[[nodiscard]] constexpr rigid_inertia<T> to_rigid_inertia(const body_inertia<T>& N) noexcept {
    return formula([](auto element) { return element; })(N);
}

// A rigid body's mobility M = N⁻¹ by its ten parameters: 1/m, the centre of mass c and
// J = I_c⁻¹ (six numbers, symmetric). About its centre of mass a rigid body's inertia is block
// diagonal, N_c = [[I_c, 0], [0, m 1]], and so is its mobility, M_c = [[J, 0], [0, (1/m) 1]]:
//   M_c = Σ J(i,j) α̃_j ε_i + (1/m)(a1ae1e + a2ae2e + a3ae3e)          (i, j < 3)
// (for principal axes §5's diagonal N with the blocks swapped: 1/d_i on a2a3e2e3, …, 1/m on
// a1ae1e, …). A mobility moves as an inertia does, M → (g ḡ) M (g ḡ)* (§5: the sandwich by g ḡ
// distributes over ∧ and ∨ and fixes E, so s = E ∨ (M ∧ P) moves to g s g* = E ∨ (M' ∧ ḡ P ḡ*);
// as a matrix M' = H M Hᵀ). The body's M is therefore M_c moved by the translation to the centre
// of mass, t = 1 + ½(cx e1e + cy e2e + cz e3e) (§3):
//   M = (t t̄) M_c (t t̄)*                                               (element, below)
// and, since (t t̄)* (t t̄) = 1 and t commutes with co-screws, t̄ with screws (even elements on
// disjoint generators), the velocity it gives is
//   E ∨ (M ∧ P) = t (E ∨ (M_c ∧ (t̄* P t̄))) t*                          (velocity, below)
// i.e. l' = l − c × p, then ω = J l', v' = p/m, then v = v' + c × ω: Featherstone's §2.13 solve
// with the inverse rotational inertia, 24m 18a against 36m 30a for the 36 blades of mobility_of.
template <class T = double>
struct body_mobility {
    using scalar = cl062::mv<T, "1">;
    scalar inv_m, cx, cy, cz;             // 1/m and the centre of mass c
    scalar jxx, jyy, jzz, jxy, jxz, jyz;  // J = I_c⁻¹

    [[nodiscard]] constexpr auto parameters() const noexcept {
        return std::tie(inv_m, cx, cy, cz, jxx, jyy, jzz, jxy, jxz, jyz);
    }
    // M_c, the mobility about the centre of mass (entry (i, j) is the blade α̃_j ε_i).
    static constexpr auto about_centre = [](auto inv_m, auto jxx, auto jyy, auto jzz, auto jxy, auto jxz, auto jyz) {
        using G = cl062;
        return jxx * G::basis<"a2a3e2e3"> + jyy * G::basis<"a3a1e3e1"> + jzz * G::basis<"a1a2e1e2"> +
               jxy * (G::basis<"a3a1e2e3"> + G::basis<"a2a3e3e1">) + jxz * (G::basis<"a1a2e2e3"> + G::basis<"a2a3e1e2">) +
               jyz * (G::basis<"a1a2e3e1"> + G::basis<"a3a1e1e2">) +
               inv_m * (G::basis<"a1ae1e"> + G::basis<"a2ae2e"> + G::basis<"a3ae3e">);
    };
    // t = 1 + ½(cx e1e + cy e2e + cz e3e), the translation to the centre of mass (§3), in Cl(0,6,2).
    static constexpr auto to_centre = [](auto cx, auto cy, auto cz) {
        using G = cl062;
        return G::basis<"1"> + half * (cx * G::basis<"e1e"> + cy * G::basis<"e2e"> + cz * G::basis<"e3e">);
    };
    // As an argument of a formula: M = (t t̄) M_c (t t̄)*, the element mobility_of stores.
    static constexpr auto element = [](auto inv_m, auto cx, auto cy, auto cz, auto jxx, auto jyy, auto jzz, auto jxy,
                                       auto jxz, auto jyz) {
        // (t t̄) M_c (t t̄)* = t (t̄ M_c t̄*) t*: one sandwich at a time, each fully expanded
        const auto t = to_centre(cx, cy, cz);
        return t * (bar(t) * about_centre(inv_m, jxx, jyy, jzz, jxy, jxz, jyz) * conj(bar(t))) * conj(t);
    };
    // The velocity of a co-screw P, t (E ∨ (M_c ∧ (t̄* P t̄))) t* (24m 18a): as a formula's body
    // (velocity_of, for larger formulas) and as the formula velocity(M, P) runs.
    static constexpr auto velocity_of = [](auto P, auto inv_m, auto cx, auto cy, auto cz, auto jxx, auto jyy, auto jzz,
                                           auto jxy, auto jxz, auto jyz) {
        const auto t = to_centre(cx, cy, cz);
        const auto P_c = conj(bar(t)) * P * bar(t);  // P about the centre of mass: (l − c × p, p)
        const auto s_c = invariants::E & (about_centre(inv_m, jxx, jyy, jzz, jxy, jxz, jyz) ^ P_c);  // (J l', p/m)
        return t * s_c * conj(t);  // (ω, v' + c × ω)
    };
    static constexpr auto velocity = formula(velocity_of);
};

template <class T>
[[nodiscard]] constexpr body_mobility<T> body_mobility_of(const mass_properties<T>& b) noexcept {
    const mat3<T> J = linear3::inverse_symmetric(b.inertia_c);
    using s = typename body_mobility<T>::scalar;
    return {s{T(1) / b.mass}, s{b.com[0]}, s{b.com[1]}, s{b.com[2]},
            s{J[0][0]},       s{J[1][1]},  s{J[2][2]},  s{J[0][1]}, s{J[0][2]}, s{J[1][2]}};
}

// The same element with its 36 blades stored.
template <class T>
[[nodiscard]] constexpr mobility<T> to_mobility(const body_mobility<T>& M) noexcept {
    return formula([](auto element) { return element; })(M);
}

// A rigid body's inertia in its own frame, with what the dynamics needs precomputed once: N and M
// as elements (24 and 36 blades), and both again by their ten parameters, side by side, for the
// equations of motion (acceleration(body, s, W): 24m for the momentum, 24m for the solve).
template <class T = double>
struct rigid_body {
    mass_properties<T> mass;  // in the body frame
    rigid_inertia<T> N;       // inertia_of(mass)
    mobility<T> M;            // mobility_of(mass) = N⁻¹
    body_inertia<T> Nb;       // N by (m, h = m c, I_o): body_inertia_of(mass)
    body_mobility<T> Mb;      // M by (1/m, c, J = I_c⁻¹): body_mobility_of(mass)
};

template <class T>
[[nodiscard]] constexpr rigid_body<T> make_rigid_body(const mass_properties<T>& b) noexcept {
    return {b, inertia_of(b), mobility_of(b), body_inertia_of(b), body_mobility_of(b)};
}
// Checked all the way from the raw numbers.
template <class T>
[[nodiscard]] constexpr checked<rigid_body<T>> make_rigid_body(const T& mass, const vec3<T>& com,
                                                               const mat3<T>& inertia_c) noexcept {
    const auto b = make_mass_properties(mass, com, inertia_c);
    if (!b) return {{}, b.error};
    return {make_rigid_body(*b), error_code::none};
}

// ---- the operations of §5–6 --------------------------------------------------------------
//
// N is any of the elements above (body_inertia passes its ten parameters), s a screw of Cl(0,3,1)
// or lifted, P a co-screw, M a mobility.

// §5: the momentum P = A ∨ (N ∧ s); 24m 18a for a rigid body's N.
inline constexpr operation momentum{formula([](auto N, auto s) { return invariants::A & (N ^ lift(s)); }),
                                    into<coscrew>};

// §5: the kinetic energy E_k = ½ s̄ ∨ (N ∧ s) (the formula is twice it).
inline constexpr operation kinetic_energy{formula([](auto N, auto s) { return bar(lift(s)) & (N ^ lift(s)); }),
                                          scalar_over<2>};

// §6: dN/dt = ½(sN − Ns) + ½(s̄N − Ns̄) for a body moving with velocity s.
inline constexpr operation inertia_rate{formula([](auto N, auto s) {
                                            const auto x = lift(s);
                                            return half * (x * N - N * x) + half * (bar(x) * N - N * bar(x));
                                        }),
                                        into<inertia>};

// The velocity a mobility gives a co-screw: s = E ∨ (M ∧ P), a screw of Cl(0,3,1).
struct lowered_screw_t {
    template <class E>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr screw<typename E::scalar_type> operator()(const E& e) const noexcept {
        return lower(lifted_screw<typename E::scalar_type>(e));
    }
};
namespace inertia_detail {
inline constexpr auto velocity_formula = [](auto M, auto P) { return invariants::E & (M ^ P); };
using velocity_operation = operation<std::remove_const_t<decltype(velocity_formula)>, lowered_screw_t>;
}  // namespace inertia_detail
// velocity(M, P) for any mobility element; a body_mobility and a co-screw take the form about the
// centre of mass, t (E ∨ (M_c ∧ (t̄* P t̄))) t* (body_mobility), the same s at 24m 18a. The lazy
// velocity.formula is E ∨ (M ∧ P) for every M.
struct velocity_t : inertia_detail::velocity_operation {
    using inertia_detail::velocity_operation::operator();
    // A rigid body's mobility by its ten parameters: t (E ∨ (M_c ∧ (t̄* P t̄))) t* (body_mobility)
    // in coordinates, P = (l, p): l' = l − c × p (P about the centre of mass), ω = J l', v' = p/m
    // (M_c), v = v' + c × ω (back by t). The same 24m 18a as body_mobility::velocity, whose
    // symbolic normal form (eleven arguments, three sandwiches) costs a translation unit about
    // 1.3 s and 150 MB to compile: the formula stays for larger formulas (the scenes' body
    // kinds), this call is the one the equations of motion make. tests/body_mobility_test.cpp
    // checks both against the 36 blades and against Gaussian elimination on §2's 6×6 N.
    template <class T>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr screw<T> operator()(const body_mobility<T>& M, const coscrew<T>& P) const noexcept {
        const vec3<T> c{M.cx[0], M.cy[0], M.cz[0]}, p{P[3], P[4], P[5]};
        const vec3<T> cp = linear3::cross(c, p);
        const vec3<T> l{P[0] - cp[0], P[1] - cp[1], P[2] - cp[2]};
        const vec3<T> w{M.jxx[0] * l[0] + M.jxy[0] * l[1] + M.jxz[0] * l[2], M.jxy[0] * l[0] + M.jyy[0] * l[1] + M.jyz[0] * l[2],
                        M.jxz[0] * l[0] + M.jyz[0] * l[1] + M.jzz[0] * l[2]};
        const vec3<T> cw = linear3::cross(c, w);
        const T inv_m = M.inv_m[0];
        return screw<T>{w[0], w[1], w[2], inv_m * p[0] + cw[0], inv_m * p[1] + cw[1], inv_m * p[2] + cw[2]};
    }
};
inline constexpr velocity_t velocity{{formula(inertia_detail::velocity_formula), lowered_screw_t{}}};

// ---- moving with the body: (g ḡ) N (g ḡ)* (§5) ----------------------------------------------
//
// A sandwich by a unit motor is a linear map; on the grade-4 elements it is the congruence with
// H⁻ᵀ (the outermorphism of the sandwich, §5: h(a ∧ b)h* = (h a h*) ∧ (h b h*)), N' = H⁻ᵀ N H⁻¹,
// and M' = H M Hᵀ for a mobility. Each is applied through the motor_map (motor.hpp).

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
// few: other orders measured 10–25 more instructions (spills) with g++ 12.
template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr moved_inertia<T> move_inertia(const motor_map<T>& G, const T& m, const vec3<T>& h,
                                                                         const mat3<T>& Io) noexcept {
    using linear3::dot;
    const mat3<T>& R = G.R;
    const vec3<T>& t = G.t;
    // R I_o Rᵀ, column by column
    const vec3<T> a0 = linear3::apply(Io, R[0]);
    const T r00 = dot(R[0], a0), r20 = dot(R[2], a0);
    const vec3<T> a1 = linear3::apply(Io, R[1]);
    const T r01 = dot(R[0], a1), r11 = dot(R[1], a1), r21 = dot(R[2], a1);
    const T r22 = Io[2][2] + (Io[0][0] - r00) + (Io[1][1] - r11);  // the trace is invariant
    // h' and the parallel-axis terms
    const vec3<T> y = linear3::apply(R, h);
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
    for (int bi = 0; bi < 2; ++bi)
        for (int bj = 0; bj < 2; ++bj) {
            mat3<T> RB{};  // R B
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    RB[i][j] = G.R[i][0] * X[3 * bi][3 * bj + j] + G.R[i][1] * X[3 * bi + 1][3 * bj + j] +
                               G.R[i][2] * X[3 * bi + 2][3 * bj + j];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) Y[3 * bi + i][3 * bj + j] = linear3::dot(RB[i], G.R[j]);  // (R B) Rᵀ
        }
    // rows: [A; C] ↦ [A; T A + C] (left multiplication by S)
    for (int j = 0; j < 6; ++j) {
        const vec3<T> tc = linear3::cross(G.t, vec3<T>{Y[0][j], Y[1][j], Y[2][j]});
        for (int i = 0; i < 3; ++i) Y[3 + i][j] += tc[i];
    }
    // columns: [A B] ↦ [A, A Tᵀ + B] (right multiplication by Sᵀ); row x ↦ x Tᵀ = (T xᵀ)ᵀ = t × x
    for (int i = 0; i < 6; ++i) {
        const vec3<T> tr = linear3::cross(G.t, vec3<T>{Y[i][0], Y[i][1], Y[i][2]});
        for (int j = 0; j < 3; ++j) Y[i][3 + j] += tr[j];
    }
    return Y;
}

// P X P with P = [[0, 1], [1, 0]]: H⁻ᵀ = P H P, so a co-screw-side congruence is a screw-side one.
template <class T>
constexpr mat6<T> swap_halves(const mat6<T>& X) noexcept {
    mat6<T> Y{};
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) Y[i][j] = X[(i + 3) % 6][(j + 3) % 6];
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
template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr body_inertia<T> transform(const motor_map<T>& G, const body_inertia<T>& N) noexcept {
    using s = typename body_inertia<T>::scalar;
    const transform_detail::moved_inertia<T> n = transform_detail::move_inertia(G, N.mass(), N.first_moment(), N.inertia_o());
    return {N.m, s{n.h[0]}, s{n.h[1]}, s{n.h[2]}, s{n.xx}, s{n.yy}, s{n.zz}, s{n.xy}, s{n.xz}, s{n.yz}};
}

}  // namespace ctga
