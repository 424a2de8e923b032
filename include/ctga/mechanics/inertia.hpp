// A rigid body's inertia (§5): from its mass properties to the element N of Cl(0,6,2) that maps
// velocities to momenta, P = A ∨ (N ∧ s), and to the mobility M = N⁻¹, s = E ∨ (M ∧ P).
//
//   mass properties (m, c, I_c): mass, centre of mass, inertia tensor about c (frame axes)
//   N = [[I_c − m Ĉ², m Ĉ], [−m Ĉ, m 1]]                                    (§2, C = Ĉ)
//   M = N⁻¹ = [[J, −J Ĉ], [Ĉ J, 1/m − Ĉ J Ĉ]],  J = I_c⁻¹
//
// Physical validity is checked where the numbers come in (make_mass_properties): finite values,
// m > 0, I_c symmetric positive definite, and principal moments obeying the triangle inequalities
// I_i ≤ I_j + I_k (equivalently, the second moment ½ tr(I)·1 − I is positive semi-definite: some
// mass distribution has these moments). Equality is allowed (a lamina).
#pragma once

#include <cassert>
#include <limits>

#include "ctga/mechanics/checked.hpp"
#include "ctga/mechanics/convert.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/spatial.hpp"

namespace ctga {

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
constexpr input_error check(const T& m, const vec3<T>& c, const mat3<T>& I) noexcept {
    for (const auto& row : I)
        if (!all_finite(row[0], row[1], row[2])) return input_error::non_finite;
    if (!all_finite(m, c[0], c[1], c[2])) return input_error::non_finite;
    if (!(m > T(0))) return input_error::non_positive_mass;
    const T tol = tolerance(I);
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (abs(I[i][j] - I[j][i]) > tol) return input_error::not_symmetric;
    // positive definite: the leading principal minors are positive (Sylvester)
    const T m1 = I[0][0], m2 = I[0][0] * I[1][1] - I[0][1] * I[0][1];
    const T m3 = I[0][0] * (I[1][1] * I[2][2] - I[1][2] * I[1][2]) - I[0][1] * (I[0][1] * I[2][2] - I[1][2] * I[0][2]) +
                 I[0][2] * (I[0][1] * I[1][2] - I[1][1] * I[0][2]);
    if (!(m1 > T(0) && m2 > T(0) && m3 > T(0))) return input_error::not_positive_definite;
    // triangle inequalities: Σ = ½ tr(I)·1 − I positive semi-definite, i.e. every principal minor ≥ 0
    const T half_trace = (I[0][0] + I[1][1] + I[2][2]) / T(2);
    mat3<T> S{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) S[i][j] = (i == j ? half_trace : T(0)) - I[i][j];
    const T t2 = tol * half_trace, t3 = t2 * half_trace;
    for (int i = 0; i < 3; ++i)
        if (S[i][i] < -tol) return input_error::triangle_inequality;
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (S[i][i] * S[j][j] - S[i][j] * S[i][j] < -t2) return input_error::triangle_inequality;
    const T det_s = S[0][0] * (S[1][1] * S[2][2] - S[1][2] * S[1][2]) - S[0][1] * (S[0][1] * S[2][2] - S[1][2] * S[0][2]) +
                    S[0][2] * (S[0][1] * S[1][2] - S[1][1] * S[0][2]);
    if (det_s < -t3) return input_error::triangle_inequality;
    return input_error::none;
}

}  // namespace inertia_detail

// Mass properties from the mass, the centre of mass and the inertia tensor about it, checked.
template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> make_mass_properties(const T& mass, const vec3<T>& com,
                                                                         const mat3<T>& inertia_c) noexcept {
    const input_error e = inertia_detail::check(mass, com, inertia_c);
    if (e != input_error::none) return {{}, e};
    mass_properties<T> out{mass, com, inertia_c};
    // symmetrise what the check accepted as symmetric to rounding
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) out.inertia_c[i][j] = out.inertia_c[j][i] = (inertia_c[i][j] + inertia_c[j][i]) / T(2);
    return {out, input_error::none};
}

// §5's principal-axes body: mass m, principal moments (dx, dy, dz) about the centre of mass at the
// origin. The paper's d_i is "the mass times the square of the radius of gyration".
template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> make_principal_mass_properties(const T& m, const T& dx, const T& dy,
                                                                                   const T& dz) noexcept {
    return make_mass_properties(m, vec3<T>{}, mat3<T>{{{dx, T(0), T(0)}, {T(0), dy, T(0)}, {T(0), T(0), dz}}});
}

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
    return spatial_detail::from_matrix<false, rigid_inertia<T>>(N);
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
    return spatial_detail::from_matrix<true, mobility<T>>(M);
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
    if (!all_finite(m)) return {{}, input_error::non_finite};
    if (!(m > T(0))) return {{}, input_error::non_positive_mass};
    if (!rigid) return {{}, input_error::not_a_rigid_inertia};
    const vec3<T> c{n[2][4] / m, n[0][5] / m, n[1][3] / m};  // m Ĉ = [[0, −m cz, m cy], [m cz, 0, −m cx], …]
    mat3<T> Ic{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Ic[i][j] = n[i][j] - m * ((i == j ? linear3::dot(c, c) : T(0)) - c[i] * c[j]);
    return make_mass_properties(m, c, Ic);
}

}  // namespace ctga
