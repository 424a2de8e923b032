// A cylinder of radius r and half height h on its body's z axis: x² + y² ≤ r², |z| ≤ h. Its mass
// at density ρ is ρ π r² 2h with Izz = m r²/2 and Ixx = Iyy = m (3r² + (2h)²)/12 = m (r²/4 + h²/3).
#pragma once

#include <numbers>

#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

template <class T = double>
struct cylinder {
    T radius;
    T half_height;
};

// Reported: non_finite, non_positive_size (r ≤ 0 or h ≤ 0).
template <class T>
[[nodiscard]] constexpr checked<cylinder<T>> make_cylinder(const T& radius, const T& half_height) noexcept {
    if (!is_finite(radius) || !is_finite(half_height)) return {{}, error_code::non_finite};
    if (!(radius > T(0)) || !(half_height > T(0))) return {{}, error_code::non_positive_size};
    return {cylinder<T>{radius, half_height}, error_code::none};
}

// The support point along u: the rim point of the cap on u's side farthest along u's part across
// the axis (the cap's centre when u is along the axis). Its own core (radius 0).
template <class T>
[[nodiscard]] constexpr vec3<T> core_support(const cylinder<T>& c, const vec3<T>& u) noexcept {
    const T z = u[2] < T(0) ? -c.half_height : c.half_height;
    const T l = math::sqrt(u[0] * u[0] + u[1] * u[1]);
    if (!(l > T(0))) return {T(0), T(0), z};
    return {c.radius * u[0] / l, c.radius * u[1] / l, z};
}
template <class T>
[[nodiscard]] constexpr T core_radius(const cylinder<T>&) noexcept {
    return T(0);
}

template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> mass_of(const cylinder<T>& c, const T& density) noexcept {
    const T r2 = c.radius * c.radius, h = c.half_height;
    const T m = density * std::numbers::pi_v<T> * r2 * T(2) * h;
    const T ixx = m * (r2 / T(4) + h * h / T(3));
    return make_principal_mass_properties(m, ixx, ixx, m * r2 / T(2));
}

}  // namespace ctga::collision
