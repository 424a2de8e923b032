// A floating base's numbers (joints.hpp's floating joint) to and from the layout of Pinocchio and
// ROS: the base pose as position and unit quaternion (x, y, z, w), the base velocity as (linear,
// angular).
//
// ctga's floating joint reads the 8 coefficients of the base's motor g relative to the joint
// frame (the world, for the tool's identity placement), g = t r with r = w + x e2e3 + y e3e1 +
// z e1e2 the quaternion under e2e3 ↦ i, e3e1 ↦ j, e1e2 ↦ k (motor.hpp), and its 6 velocity
// numbers are the base's body-frame screw (ω, v): the angular velocity and the velocity of the
// base's origin, in base axes. Pinocchio's free flyer has q = (p, x, y, z, w), p the origin in the
// world and the quaternion rotating base coordinates into world ones, and v = (v, ω) in the
// same base axes: the same numbers, the velocity halves swapped.
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include "ctga/mechanics/motor.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::chains {

template <class T = double>
struct base_pose {
    vec3<T> position{};                             // the base's origin, world
    std::array<T, 4> quaternion{T(0), T(0), T(0), T(1)};  // (x, y, z, w): base axes into world axes
};

// The floating joint's 8 numbers for a base pose. A quaternion off unit length beyond rounding
// (√ε, as near_unit) is not a rotation (not_a_rotation); within it, it is normalised.
template <class T>
[[nodiscard]] constexpr checked<std::array<T, 8>> floating_base_configuration(const base_pose<T>& pose) noexcept {
    const auto& p = pose.position;
    const auto& q = pose.quaternion;
    if (!all_finite(p[0], p[1], p[2], q[0], q[1], q[2], q[3])) return {{}, error_code::non_finite};
    const T n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    const T d = n2 - T(1);
    if ((d < T(0) ? -d : d) > math::sqrt(std::numeric_limits<T>::epsilon())) return {{}, error_code::not_a_rotation};
    const T s = T(1) / math::sqrt(n2);
    const motor<T> g = rigid_motion(make_translator(p[0], p[1], p[2]), rotor<T>{q[3] * s, q[0] * s, q[1] * s, q[2] * s});
    std::array<T, 8> out{};
    for (std::size_t i = 0; i < 8; ++i) out[i] = g[i];
    return {out, error_code::none};
}

// The base pose of the floating joint's 8 numbers (the quaternion normalised, sign as stored).
template <class T>
[[nodiscard]] constexpr base_pose<T> floating_base_pose(const std::array<T, 8>& q) noexcept {
    const motor<T> g{q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]};
    const motor_map<T> G = map_of(g);
    const T s = T(1) / math::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    return {G.t, {g.template get<"e2e3">() * s, g.template get<"e3e1">() * s, g.template get<"e1e2">() * s, q[0] * s}};
}

// The floating joint's 6 velocity numbers (ω, v) from the base's (linear, angular) velocity in
// base axes, and back.
template <class T>
[[nodiscard]] constexpr std::array<T, 6> floating_base_velocity(const vec3<T>& linear, const vec3<T>& angular) noexcept {
    return {angular[0], angular[1], angular[2], linear[0], linear[1], linear[2]};
}
template <class T>
[[nodiscard]] constexpr std::array<T, 6> linear_angular(const std::array<T, 6>& v) noexcept {
    return {v[3], v[4], v[5], v[0], v[1], v[2]};
}

}  // namespace ctga::chains
