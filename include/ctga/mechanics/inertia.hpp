// Inertias as elements of Cl(0,6,2) (paper §2, §5), built from mass properties
// (mass_properties.hpp). Which inertia to use when is tabled in docs/design.md.
//
//   rigid_inertia    N as the 24 blades that are not structurally zero for a rigid body
//   inertia          N as all 36 blades: a general symmetric 6×6 inertia
//   mobility         M = N⁻¹ as 36 blades: velocity from momentum, s = E ∨ (M ∧ P)
//
//   N = [[I_c − m Ĉ², m Ĉ], [−m Ĉ, m 1]] = [[I_o, Ĥ], [−Ĥ, m 1]]          (§2, C = Ĉ, h = m c)
//   M = N⁻¹ = [[J, −J Ĉ], [Ĉ J, 1/m − Ĉ J Ĉ]],  J = I_c⁻¹
//
// Entry (i, j) of the 6×6 matrix is the coefficient of one blade (detail/matrix_blades.hpp), so
// §5's diagonal inertia is N = dx a1ae1e + … + m a2a3e2e3 + …, entry by entry the matrix of §2.
//
// N and M by ten parameters each are body_inertia.hpp; the 6×6 matrices inertia_matrix.hpp; the
// operations (momentum, energy, dN/dt, velocity) momentum.hpp; the transforms inertia_transform.hpp.
#pragma once

#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/detail/matrix_blades.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"

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

// ---- from mass properties ------------------------------------------------------------------

// The element N of §5 (24 blades; the other 12 entries of the 6×6 matrix vanish for a rigid body).
template <class T>
[[nodiscard]] constexpr rigid_inertia<T> inertia_of(const mass_properties<T>& b) noexcept {
    const T m = b.mass;
    const vec3<T>& c = b.com;
    const vec3<T> h{m * c[0], m * c[1], m * c[2]};  // first moment m c
    mat6<T> N{};
    const mat3<T> I_o = inertia_about_origin(b, h);  // I_c − m Ĉ²
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) N[i][j] = I_o[i][j];
    const mat3<T> H = linear3::hat(h);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            N[i][3 + j] = H[i][j];   // m Ĉ
            N[3 + i][j] = -H[i][j];  // m Ĉᵀ = −m Ĉ
        }
    for (std::size_t i = 0; i < 3; ++i) N[3 + i][3 + i] = m;
    return matrix_blades::from_matrix<false, rigid_inertia<T>>(N);
}

// The mobility M = N⁻¹: the element taking a co-screw (momentum or impulse) to the screw (velocity).
template <class T>
[[nodiscard]] constexpr mobility<T> mobility_of(const mass_properties<T>& b) noexcept {
    const mat3<T> J = linear3::inverse_symmetric(b.inertia_c);
    const mat3<T> C = linear3::hat(b.com);
    mat3<T> CJ{};  // Ĉ J
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) CJ[i][j] = C[i][0] * J[0][j] + C[i][1] * J[1][j] + C[i][2] * J[2][j];
    mat6<T> M{};
    const T inv_m = T(1) / b.mass;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
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

}  // namespace ctga
