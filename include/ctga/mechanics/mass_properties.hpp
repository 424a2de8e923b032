// Mass properties (paper §2, §5): a rigid body's mass m, centre of mass c and inertia tensor I_c
// about the centre of mass, the checked input every inertia representation is built from
// (inertia.hpp, body_inertia.hpp, rigid_body.hpp).
//
// Physical validity is checked where the numbers come in (make_mass_properties): finite values,
// m > 0, I_c symmetric positive definite, and principal moments obeying the triangle inequalities
// I_i ≤ I_j + I_k (equivalently, the second moment ½ tr(I)·1 − I is positive semi-definite: some
// mass distribution has these moments). Equality is allowed (a lamina).
//
// Robot descriptions as they come carry physically questionable data (a camera's tensor that
// violates the triangle inequality, principal moments of ±4e-22 by rounding) and massless links.
// mass_check::as_given accepts them as given, as Pinocchio and MuJoCo do: finite numbers, m ≥ 0
// and a symmetric tensor are still required (the URDF tool warns about the rest, urdf_to_ctga.py).
#pragma once

#include <limits>

#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga {

template <class T = double>
struct mass_properties {
    T mass{};
    vec3<T> com{};         // centre of mass
    mat3<T> inertia_c{};   // inertia tensor about the centre of mass, symmetric
};

// The inertia tensor about the body origin, I_o = I_c + m(|c|² 1 − c cᵀ) (the parallel-axis
// theorem), with h = m c. A diagonal entry's m(|c|² − c_i²) is summed as h_j c_j + h_k c_k:
// written as |c|² − c_i² it cancels when c lies far along axis i and near it (iCub's head: ABA's
// error against long double 3.3e-7 → 2.2e-8, docs/accuracy.md).
template <class T>
[[nodiscard]] constexpr mat3<T> inertia_about_origin(const mass_properties<T>& b, const vec3<T>& h) noexcept {
    mat3<T> I_o{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            const std::size_t k = (i + 1) % 3, l = (i + 2) % 3;
            I_o[i][j] = i == j ? b.inertia_c[i][i] + (h[k] * b.com[k] + h[l] * b.com[l]) : b.inertia_c[i][j] - h[i] * b.com[j];
        }
    return I_o;
}

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
constexpr error_code check_as_given(const T& m, const vec3<T>& c, const mat3<T>& I) noexcept {
    for (const auto& row : I)
        if (!all_finite(row[0], row[1], row[2])) return error_code::non_finite;
    if (!all_finite(m, c[0], c[1], c[2])) return error_code::non_finite;
    if (m < T(0)) return error_code::non_positive_mass;
    const T tol = tolerance(I);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i + 1; j < 3; ++j)
            if (abs(I[i][j] - I[j][i]) > tol) return error_code::not_symmetric;
    return error_code::none;
}

template <class T>
constexpr error_code check(const T& m, const vec3<T>& c, const mat3<T>& I) noexcept {
    if (const error_code e = check_as_given(m, c, I); e != error_code::none) return e;
    if (!(m > T(0))) return error_code::non_positive_mass;
    const T tol = tolerance(I);
    // positive definite: the leading principal minors are positive (Sylvester)
    const T m1 = I[0][0], m2 = I[0][0] * I[1][1] - I[0][1] * I[0][1];
    const T m3 = I[0][0] * (I[1][1] * I[2][2] - I[1][2] * I[1][2]) - I[0][1] * (I[0][1] * I[2][2] - I[1][2] * I[0][2]) +
                 I[0][2] * (I[0][1] * I[1][2] - I[1][1] * I[0][2]);
    if (!(m1 > T(0) && m2 > T(0) && m3 > T(0))) return error_code::not_positive_definite;
    // triangle inequalities: Σ = ½ tr(I)·1 − I positive semi-definite, i.e. every principal minor ≥ 0
    const T half_trace = (I[0][0] + I[1][1] + I[2][2]) / T(2);
    mat3<T> S{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) S[i][j] = (i == j ? half_trace : T(0)) - I[i][j];
    const T t2 = tol * half_trace, t3 = t2 * half_trace;
    for (std::size_t i = 0; i < 3; ++i)
        if (S[i][i] < -tol) return error_code::triangle_inequality;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i + 1; j < 3; ++j)
            if (S[i][i] * S[j][j] - S[i][j] * S[i][j] < -t2) return error_code::triangle_inequality;
    const T det_s = S[0][0] * (S[1][1] * S[2][2] - S[1][2] * S[1][2]) - S[0][1] * (S[0][1] * S[2][2] - S[1][2] * S[0][2]) +
                    S[0][2] * (S[0][1] * S[1][2] - S[1][1] * S[0][2]);
    if (det_s < -t3) return error_code::triangle_inequality;
    return error_code::none;
}

}  // namespace inertia_detail

// What make_mass_properties checks: a physical rigid body (the default), or the numbers as given.
enum class mass_check {
    physical,  // finite, m > 0, I_c symmetric positive definite, the triangle inequalities
    as_given,  // finite, m ≥ 0 (0: a massless frame), I_c symmetric
};

// Mass properties from the mass, the centre of mass and the inertia tensor about it, checked.
template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> make_mass_properties(const T& mass, const vec3<T>& com,
                                                                         const mat3<T>& inertia_c,
                                                                         mass_check what = mass_check::physical) noexcept {
    const error_code e = what == mass_check::physical ? inertia_detail::check(mass, com, inertia_c)
                                                      : inertia_detail::check_as_given(mass, com, inertia_c);
    if (e != error_code::none) return {{}, e};
    mass_properties<T> out{mass, com, inertia_c};
    // symmetrise what the check accepted as symmetric to rounding
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i + 1; j < 3; ++j) out.inertia_c[i][j] = out.inertia_c[j][i] = (inertia_c[i][j] + inertia_c[j][i]) / T(2);
    return {out, error_code::none};
}

// §5's principal-axes body: mass m, principal moments (dx, dy, dz) about the centre of mass at the
// origin. The paper's d_i is "the mass times the square of the radius of gyration".
template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> make_principal_mass_properties(const T& m, const T& dx, const T& dy,
                                                                                   const T& dz) noexcept {
    return make_mass_properties(m, vec3<T>{}, mat3<T>{{{dx, T(0), T(0)}, {T(0), dy, T(0)}, {T(0), T(0), dz}}});
}

}  // namespace ctga
