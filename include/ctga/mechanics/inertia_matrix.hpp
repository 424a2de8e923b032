// The 6×6 matrices of §2 for the inertia elements (inertia.hpp): entry (i, j) of the matrix is
// the coefficient of one blade (detail/matrix_blades.hpp), so each conversion is a copy. A rigid
// body's mass properties are read back from its 6×6 inertia checked (mass_properties_of).
#pragma once

#include <limits>

#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/detail/matrix_blades.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga {

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

// Mass properties read back from a rigid body's 6×6 inertia (or its element), checked: the mass
// block must be m·1, the coupling block m Ĉ antisymmetric, and the result physically valid.
template <class T, auto L>
[[nodiscard]] constexpr checked<mass_properties<T>> mass_properties_of(const multivector<cl062, T, L>& N) noexcept {
    const mat6<T> n = inertia_matrix(N);
    const T m = n[3][3];
    const T tol = T(64) * std::numeric_limits<T>::epsilon() *
                  (inertia_detail::abs(n[0][0]) + inertia_detail::abs(n[1][1]) + inertia_detail::abs(n[2][2]) + inertia_detail::abs(m));
    bool rigid = true;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            rigid = rigid && inertia_detail::abs(n[3 + i][3 + j] - (i == j ? m : T(0))) <= tol;
            rigid = rigid && inertia_detail::abs(n[i][3 + j] + n[3 + i][j]) <= tol;
            rigid = rigid && inertia_detail::abs(n[i][3 + j] + n[j][3 + i]) <= tol;
        }
    if (!all_finite(m)) return {{}, error_code::non_finite};
    if (!(m > T(0))) return {{}, error_code::non_positive_mass};
    if (!rigid) return {{}, error_code::not_a_rigid_inertia};
    const vec3<T> c{n[2][4] / m, n[0][5] / m, n[1][3] / m};  // m Ĉ = [[0, −m cz, m cy], [m cz, 0, −m cx], …]
    mat3<T> Ic{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) Ic[i][j] = n[i][j] - m * ((i == j ? linear3::dot(c, c) : T(0)) - c[i] * c[j]);
    return make_mass_properties(m, c, Ic);
}

}  // namespace ctga
