// Making Cl(3,0,1)'s elements from numbers, with the signs written once here (pga.hpp lists
// them all). The scalar type is double unless given: make_point(1, 2, 3) is a point<double>,
// make_point<float>(1, 2, 3) a point<float>.
//
//   make_point(x, y, z)            x e032 + y e013 + z e021 + e123 (w = 1)
//   make_direction(x, y, z)        x e032 + y e013 + z e021
//   make_plane(a, b, c, d)         a e1 + b e2 + c e3 + d e0: the plane a x + b y + c z + d = 0
//   make_translator(dx, dy, dz)    1 − ½(dx e01 + dy e02 + dz e03): moves points by +d
//   make_rotor(θ, x, y, z)         cos(θ/2) − sin(θ/2)(ux e23 + uy e31 + uz e12), u = (x, y, z)/|(x, y, z)|:
//                                  +θ about the axis u through the origin (right-hand rule)
//   make_line(p, q), make_line(p, v)   the line from point p to point q, or through p along direction v
#pragma once

#include <array>
#include <type_traits>

#include "ctga/geometry/pga_operations.hpp"
#include "ctga/geometry/pga_types.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/unit_direction.hpp"

namespace ctga::pga {

template <class T = double>
[[nodiscard]] constexpr point<T> make_point(std::type_identity_t<T> x, std::type_identity_t<T> y,
                                            std::type_identity_t<T> z) noexcept {
    return point<T>{x, y, z, T(1)};
}

template <class T = double>
[[nodiscard]] constexpr direction<T> make_direction(std::type_identity_t<T> x, std::type_identity_t<T> y,
                                                    std::type_identity_t<T> z) noexcept {
    return direction<T>{x, y, z};
}

template <class T = double>
[[nodiscard]] constexpr plane<T> make_plane(std::type_identity_t<T> a, std::type_identity_t<T> b, std::type_identity_t<T> c,
                                            std::type_identity_t<T> d) noexcept {
    return plane<T>{a, b, c, d};
}

// The translation by d: sandwich(make_translator(dx, dy, dz), p) is p + d.
template <class T = double>
[[nodiscard]] constexpr translator<T> make_translator(std::type_identity_t<T> dx, std::type_identity_t<T> dy,
                                                      std::type_identity_t<T> dz) noexcept {
    return translator<T>{T(1), -dx / T(2), -dy / T(2), -dz / T(2)};
}

// The rotation by angle θ (radians) about the axis through the origin along (x, y, z), which
// need not be unit (support/unit_direction.hpp): +θ turns counter-clockwise seen from the tip of
// the axis (right-hand rule), so make_rotor(π/2, 0, 0, 1) takes (1, 0, 0) to (0, 1, 0). Or a
// failure: error_code::non_finite (θ or an axis component is NaN or ±∞), zero_direction (the
// zero axis).
template <class T = double>
[[nodiscard]] constexpr checked<rotor<T>> make_rotor_checked(std::type_identity_t<T> angle, std::type_identity_t<T> x,
                                                             std::type_identity_t<T> y,
                                                             std::type_identity_t<T> z) noexcept {
    if (!is_finite(angle)) return {rotor<T>{}, error_code::non_finite};
    const checked<std::array<T, 3>> u = unit_direction(x, y, z);
    if (!u) return {rotor<T>{}, u.error};
    const auto cs = math::cos_sin(angle / T(2));  // of half the angle
    return {rotor<T>{cs.cos, -cs.sin * u.value[0], -cs.sin * u.value[1], -cs.sin * u.value[2]}, error_code::none};
}

// make_rotor_checked for an axis known to be non-zero and finite (value_or_nan: asserts in debug
// builds, a rotor of NaNs in release builds, never a rotor that looks fine).
template <class T = double>
[[nodiscard]] constexpr rotor<T> make_rotor(std::type_identity_t<T> angle, std::type_identity_t<T> x,
                                            std::type_identity_t<T> y, std::type_identity_t<T> z) noexcept {
    return value_or_nan(make_rotor_checked<T>(angle, x, y, z));
}

// The line through p and q, directed from p to q: join(p, q), direction w_p q − w_q p (q − p for
// normalised points), moment p × q.
template <class T>
[[nodiscard]] constexpr line<T> make_line(const point<T>& p, const point<T>& q) noexcept {
    return join(p, q);
}

// The line through p along v: join(p, v), direction w_p v (v when p is normalised), moment p × v.
template <class T>
[[nodiscard]] constexpr line<T> make_line(const point<T>& p, const direction<T>& v) noexcept {
    return join(p, v);
}

}  // namespace ctga::pga
