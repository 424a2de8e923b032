// The unit vector along a given direction (x, y, z), for rotation axes given by any non-zero
// vector: ctga::make_rotor (mechanics/motor.hpp) and ctga::pga::make_rotor
// (geometry/pga_constructors.hpp).
#pragma once

#include <array>

#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga {

// (x, y, z)/‖(x, y, z)‖, or why there is none: non_finite for a NaN or an infinity,
// zero_direction for the zero vector. The components are divided by the largest |component|
// first, so that neither the squares nor the length overflow or underflow (an axis of length
// 1e-300 or 1e300 works). A unit vector comes back unchanged up to one rounding of each component.
template <class T>
[[nodiscard]] constexpr checked<std::array<T, 3>> unit_direction(const T& x, const T& y, const T& z) noexcept {
    if (!all_finite(x, y, z)) return {{}, error_code::non_finite};
    const auto magnitude = [](const T& c) { return c < T(0) ? -c : c; };
    T m = magnitude(x);
    if (magnitude(y) > m) m = magnitude(y);
    if (magnitude(z) > m) m = magnitude(z);
    if (!(m > T(0))) return {{}, error_code::zero_direction};
    const T sx = x / m, sy = y / m, sz = z / m;
    const T length = math::sqrt(sx * sx + sy * sy + sz * sz);  // in [1, √3]
    return {{sx / length, sy / length, sz / length}, error_code::none};
}

}  // namespace ctga
