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

template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> mass_of(const cylinder<T>& c, const T& density) noexcept {
    const T r2 = c.radius * c.radius, h = c.half_height;
    const T m = density * std::numbers::pi_v<T> * r2 * T(2) * h;
    const T ixx = m * (r2 / T(4) + h * h / T(3));
    return make_principal_mass_properties(m, ixx, ixx, m * r2 / T(2));
}

}  // namespace ctga::collision
