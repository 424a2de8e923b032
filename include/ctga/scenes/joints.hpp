// The joints a physics_world holds between two bodies, or a body and the ground (world.hpp's
// add_joint), and the blocks of rows each is made of (constraints/joint_rows.hpp):
//
//   spherical_joint  a point of a held at a point of b                      point
//   revolute_joint   the same, and a's axis kept along b's (a hinge)        point + hinge
//   prismatic_joint  b's anchor on a's axis, no relative rotation (a slide)  line + weld
//   fixed_joint      a point held and the relative rotation kept (a weld)   point + weld
//   distance_joint   two points kept a length apart (a rod with ball ends)  distance
//
// Anchors and axes are in their bodies' frames (the world's for the ground). A fixed or
// prismatic joint keeps the relative rotation the bodies have when it is added. A revolute or
// prismatic joint with limits or a motor has a third block, twist or slide.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "ctga/constraints/joint_rows.hpp"
#include "ctga/mechanics/linear3.hpp"

namespace ctga {

// A moving body named by its kind and its index among that kind's (add_body's value), or the
// ground: the world's frame, where a joint's anchor is a fixed point.
struct body_ref {
    std::size_t kind, index;
    friend constexpr bool operator==(const body_ref&, const body_ref&) = default;
};
template <std::size_t I>
[[nodiscard]] constexpr body_ref body(std::size_t index) noexcept {
    return {I, index};
}
inline constexpr body_ref ground{~std::size_t{0}, ~std::size_t{0}};

// A revolute or prismatic joint's limits on its angle (rad) or position (m), b relative to a
// (infinite: none), and its motor: it drives the joint's speed to `speed` with at most `effort`
// (N·m or N; zero: no motor).
template <class T = double>
struct joint_limits {
    T lower = -std::numeric_limits<T>::infinity(), upper = std::numeric_limits<T>::infinity();
};
template <class T = double>
struct joint_motor {
    T speed = T(0), effort = T(0);
};

template <class T = double>
struct spherical_joint {
    body_ref a, b;
    vec3<T> anchor_a, anchor_b;
};
template <class T = double>
struct revolute_joint {
    body_ref a, b;
    vec3<T> anchor_a, anchor_b;
    vec3<T> axis_a, axis_b;  // the hinge's axis in each body's frame
    joint_limits<T> limits{};  // on the angle about axis_a from where b is when the joint is added
    joint_motor<T> motor{};
};
template <class T = double>
struct prismatic_joint {
    body_ref a, b;
    vec3<T> anchor_a, anchor_b;
    vec3<T> axis_a;  // the slide's direction in a's frame
    joint_limits<T> limits{};  // on the position axis_a · (p_b − p_a) of b's anchor from a's
    joint_motor<T> motor{};
};
template <class T = double>
struct fixed_joint {
    body_ref a, b;
    vec3<T> anchor_a, anchor_b;
};
template <class T = double>
struct distance_joint {
    body_ref a, b;
    vec3<T> anchor_a, anchor_b;
    T length;
};

template <class J, class T>
inline constexpr bool is_joint_v = std::is_same_v<J, spherical_joint<T>> || std::is_same_v<J, revolute_joint<T>> ||
                                   std::is_same_v<J, prismatic_joint<T>> || std::is_same_v<J, fixed_joint<T>> ||
                                   std::is_same_v<J, distance_joint<T>>;

namespace joint_detail {
template <class J>
[[nodiscard]] constexpr bool limited(const J& j) noexcept {
    return j.limits.lower != -std::numeric_limits<decltype(j.limits.lower)>::infinity() ||
           j.limits.upper != std::numeric_limits<decltype(j.limits.upper)>::infinity() || j.motor.effort != 0;
}
// The limits and motor of b relative to a, or, the joint turned around, of a relative to b.
template <class J, class T>
constexpr void take_limits(const J& j, bool turned, constraints::joint_block<T>& x) noexcept {
    x.lower = turned ? -j.limits.upper : j.limits.lower, x.upper = turned ? -j.limits.lower : j.limits.upper;
    x.speed = turned ? -j.motor.speed : j.motor.speed, x.effort = j.motor.effort;
}
// The joint's blocks (constraints/joint_rows.hpp) for bodies a and b (global ids, b no_body for
// the ground) at rotations R_a and R_b, into out; their number. The moving body is the blocks'
// a: a joint given with the ground as a is turned around (anchors and axes swapped, a prismatic
// joint's axis moved into the moving body's frame).
template <class T, class J>
constexpr std::size_t blocks_of(const J& j, std::uint32_t a, std::uint32_t b, const mat3<T>& Ra, const mat3<T>& Rb,
                                std::array<constraints::joint_block<T>, 3>& out) noexcept {
    using kind = constraints::joint_block_kind;
    const bool turned = a == constraints::no_body;
    constraints::joint_block<T> base;
    base.a = turned ? b : a, base.b = turned ? a : b;
    base.anchor_a = turned ? j.anchor_b : j.anchor_a, base.anchor_b = turned ? j.anchor_a : j.anchor_b;
    const mat3<T>&RA = turned ? Rb : Ra, &RB = turned ? Ra : Rb;
    const auto block = [&](kind k) {
        constraints::joint_block<T> x = base;
        x.kind = k;
        return x;
    };
    if constexpr (std::is_same_v<J, spherical_joint<T>>) {
        out[0] = block(kind::point);
        return 1;
    } else if constexpr (std::is_same_v<J, distance_joint<T>>) {
        out[0] = block(kind::distance);
        out[0].length = j.length;
        out[0].axis_a = {T(1), T(0), T(0)};
        return 1;
    } else if constexpr (std::is_same_v<J, revolute_joint<T>>) {
        out[0] = block(kind::point);
        out[1] = block(kind::hinge);
        out[1].axis_a = turned ? j.axis_b : j.axis_a, out[1].axis_b = turned ? j.axis_a : j.axis_b;
        if (!limited(j)) return 2;
        out[2] = block(kind::twist);
        out[2].axis_a = out[1].axis_a;
        out[2].reference_a = constraints::tangents(out[2].axis_a)[0];
        out[2].reference_b = linear3::apply_transposed(RB, linear3::apply(RA, out[2].reference_a));
        take_limits(j, turned, out[2]);
        return 3;
    } else {
        // fixed and prismatic: the relative rotation kept
        out[1] = block(kind::weld);
        out[1].reference = constraints::weld_reference(RA, RB);
        if constexpr (std::is_same_v<J, fixed_joint<T>>) {
            out[0] = block(kind::point);
        } else {
            out[0] = block(kind::line);
            // the axis in the world, then in the blocks' a's frame
            out[0].axis_a = linear3::apply_transposed(RA, linear3::apply(Ra, j.axis_a));
            if (limited(j)) {
                out[2] = block(kind::slide);
                out[2].axis_a = out[0].axis_a;
                take_limits(j, turned, out[2]);
                return 3;
            }
        }
        return 2;
    }
}
}  // namespace joint_detail

}  // namespace ctga
