// A sphere of radius r about its body's origin: the points x with |x| ≤ r in the body frame. Its
// support point in a direction u (the point farthest along u) is r u/|u|; its mass at density ρ
// is ρ (4/3) π r³ with inertia (2/5) m r² about every axis through its centre.
#pragma once

#include <numbers>

#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

template <class T = double>
struct sphere {
    T radius;
};

// Reported: non_finite, non_positive_size (r ≤ 0).
template <class T>
[[nodiscard]] constexpr checked<sphere<T>> make_sphere(const T& radius) noexcept {
    if (!is_finite(radius)) return {{}, error_code::non_finite};
    if (!(radius > T(0))) return {{}, error_code::non_positive_size};
    return {sphere<T>{radius}, error_code::none};
}

// The core (sphere.hpp, capsule.hpp: the shape is its core grown by its radius): a point, the
// origin. Its support point in any direction is the origin.
template <class T>
[[nodiscard]] constexpr vec3<T> core_support(const sphere<T>&, const vec3<T>&) noexcept {
    return {T(0), T(0), T(0)};
}
template <class T>
[[nodiscard]] constexpr T core_radius(const sphere<T>& s) noexcept {
    return s.radius;
}

template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> mass_of(const sphere<T>& s, const T& density) noexcept {
    const T r2 = s.radius * s.radius;
    const T m = density * T(4) / T(3) * std::numbers::pi_v<T> * r2 * s.radius;
    const T i = T(2) / T(5) * m * r2;
    return make_principal_mass_properties(m, i, i, i);
}

}  // namespace ctga::collision
