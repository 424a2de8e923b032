// The separation of two posed shapes A and B, the answer of every narrowphase routine:
//   distance   signed: > 0 the gap between them, < 0 minus the penetration depth (the length of
//              the shortest translation of B that separates them), 0 touching;
//   normal     the unit direction from A towards B: B moved by −distance · normal just touches A;
//   point_a, point_b  the witness points on A's and B's surfaces, point_b − point_a = distance ·
//              normal: the closest points when apart, the deepest when overlapping.
// For convex A and B, distance = max over unit u of (−h_A(u) − h_B(−u)) with h the support
// function (h_S(u) = max over x in S of u·x); the maximising u is the normal.
// A shape is posed by its body's motor g (mechanics/motor.hpp); the queries read its linear map
// map_of(g) = (R, t), x_world = R x_body + t, formed once per body and step by the caller.
#pragma once

#include <cstddef>

#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

template <class T = double>
struct separation {
    T distance;
    vec3<T> normal;
    vec3<T> point_a, point_b;
};

// The same separation seen from B: the normal reversed, the witness points swapped.
template <class T>
[[nodiscard]] constexpr separation<T> reversed(const separation<T>& s) noexcept {
    return {s.distance, {-s.normal[0], -s.normal[1], -s.normal[2]}, s.point_b, s.point_a};
}

// The world point of a body point: R x + t.
template <class T>
[[nodiscard]] constexpr vec3<T> to_world(const motor_map<T>& pose, const vec3<T>& x) noexcept {
    return linear3::add(linear3::apply(pose.R, x), pose.t);
}
// The body point of a world point: Rᵀ (x − t).
template <class T>
[[nodiscard]] constexpr vec3<T> to_body(const motor_map<T>& pose, const vec3<T>& x) noexcept {
    return linear3::apply_transposed(pose.R, linear3::sub(x, pose.t));
}
// The body's axis i in the world: column i of R.
template <class T>
[[nodiscard]] constexpr vec3<T> axis_of(const motor_map<T>& pose, std::size_t i) noexcept {
    return {pose.R[0][i], pose.R[1][i], pose.R[2][i]};
}

template <class T>
[[nodiscard]] constexpr T length(const vec3<T>& a) noexcept {
    return math::sqrt(linear3::dot(a, a));
}

}  // namespace ctga::collision
