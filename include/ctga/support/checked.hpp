// Checked results: what can be wrong at run time (a non-finite number, a non-positive mass, an
// inertia tensor violating the triangle inequalities, a matrix that is not a rigid motion, an
// implicit step that does not converge) is reported as a value, never propagated into a state
// that looks fine.
//
//   auto body = ctga::make_mass_properties(m, com, tensor);   // checked<mass_properties<double>>
//   if (!body) std::puts(ctga::describe(body.error));
//   use(*body);
//
// No exceptions and no heap: a checked<V> is the value plus an error code. Reading the value of a
// failed check is a logic error; it asserts in debug builds.
#pragma once

#include <array>
#include <cassert>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "ctga/support/math.hpp"

namespace ctga {

enum class error_code : unsigned char {
    none,
    // inputs
    non_finite,             // a NaN or an infinity among the inputs
    non_positive_mass,      // m ≤ 0
    not_symmetric,          // an inertia tensor with I_ij ≠ I_ji beyond rounding
    not_positive_definite,  // a principal moment ≤ 0
    triangle_inequality,    // principal moments with I_i > I_j + I_k: no mass distribution has them
    not_a_rotation,         // the 3×3 block of a homogeneous matrix is not orthonormal with det +1
    not_homogeneous,        // the bottom row of a homogeneous matrix is not (0, 0, 0, 1)
    not_a_motor,            // g g* = 1 fails beyond rounding (or the rotor part is zero)
    not_a_rigid_inertia,    // a 6×6 inertia without the form [[I, m Ĉ], [m Ĉᵀ, m 1]] of §2
    not_a_unit_axis,        // a joint axis u with ‖u‖ ≠ 1 beyond rounding
    not_aligned,            // a turned or aligned joint's placement has another rotation (chains::turned, aligned); a body's shape off its principal frame
    zero_direction,         // an axis or direction given as the zero vector
    massless_subtree,       // a moving joint that meets no inertia: H singular, ABA's D = 0 (chains::massless_subtree)
    unknown_frame,          // a frame name the tree does not have (chains::tree::find_frame)
    not_a_unit_base,        // a floating joint's 8 numbers are not a unit motor (a pose in another layout?)
    negative_armature,      // a joint's armature (rotor inertia) below zero
    limits_reversed,        // a joint limit with lower > upper
    negative_limit,         // a velocity or effort limit, a damping or a friction below zero
    unbounded,              // a bound needed (random_configuration) is infinite
    non_positive_size,      // a shape's radius, half extent or half height ≤ 0 (collision/); a distance joint's length
    too_few_points,         // a convex hull of fewer than four points
    coplanar_points,        // a convex hull of points on one plane (no volume)
    degenerate_triangle,    // a mesh triangle of zero area (two vertices equal, or on a line)
    capacity_exceeded,      // more items than the capacity given at construction (a broadphase's proxies)
    bad_index,              // a mesh triangle's vertex index past the vertices
    size_mismatch,          // a mesh without triangles; a height field whose heights are not rows × columns; a contact problem's arrays
    negative_friction,      // a friction coefficient μ < 0 (constraints/)
    joint_to_itself,        // a joint whose two sides are one body (scenes/world.hpp)
    not_supported,          // a combination a stepper does not handle (a robot in a world stepped softly)
    // computations
    did_not_converge,       // an implicit integration step's iteration did not converge
};

[[nodiscard]] constexpr const char* describe(error_code e) noexcept {
    switch (e) {
        case error_code::none: return "ok";
        case error_code::non_finite: return "ctga: non-finite input (NaN or infinity)";
        case error_code::non_positive_mass: return "ctga: the mass must be positive";
        case error_code::not_symmetric: return "ctga: the inertia tensor must be symmetric";
        case error_code::not_positive_definite: return "ctga: the inertia tensor must be positive definite";
        case error_code::triangle_inequality:
            return "ctga: the principal moments violate the triangle inequality I_i <= I_j + I_k";
        case error_code::not_a_rotation: return "ctga: the 3x3 block is not a rotation (orthonormal, det +1)";
        case error_code::not_homogeneous: return "ctga: the bottom row of a homogeneous matrix must be 0 0 0 1";
        case error_code::not_a_rigid_inertia:
            return "ctga: not a rigid body's inertia (mass block m*1, coupling block m*C antisymmetric)";
        case error_code::not_a_unit_axis: return "ctga: a joint axis must be a unit vector";
        case error_code::not_aligned:
            return "ctga: a turned or aligned joint's placement must have the rotation its type names (aligned: none); a "
                   "moving body's shape must have its centre of mass at its origin on principal axes (a hull: "
                   "collision::on_principal_axes)";
        case error_code::massless_subtree:
            return "ctga: a moving joint meets no inertia (no mass, or no rotational inertia for a revolute joint, in "
                   "its subtree, and no armature): the mass matrix is singular";
        case error_code::unknown_frame: return "ctga: the tree has no frame of this name";
        case error_code::not_a_unit_base:
            return "ctga: a floating base's 8 numbers are not a unit motor (g g* = 1 fails): for a position and a "
                   "quaternion [x y z qx qy qz qw] (Pinocchio, ROS) use chains::floating_base_configuration";
        case error_code::negative_armature: return "ctga: a joint's armature (rotor inertia) must not be negative";
        case error_code::limits_reversed: return "ctga: a joint limit has lower > upper";
        case error_code::negative_limit:
            return "ctga: a joint's velocity or effort limit, damping or friction must not be negative";
        case error_code::unbounded:
            return "ctga: a position bound is infinite where a finite one is needed (a prismatic joint or a floating "
                   "base's position in random_configuration)";
        case error_code::non_positive_size:
            return "ctga: a shape's size must be positive (a sphere's, capsule's or cylinder's radius, a box's half "
                   "extents, a cylinder's half height; a capsule's half height may be 0)";
        case error_code::too_few_points: return "ctga: a convex hull needs at least four points";
        case error_code::coplanar_points: return "ctga: a convex hull's points all lie on one plane (it has no volume)";
        case error_code::degenerate_triangle:
            return "ctga: a mesh triangle has zero area (two vertices equal, or all three on one line)";
        case error_code::capacity_exceeded:
            return "ctga: more items than the capacity given at construction (a broadphase's proxies, a mesh's triangles)";
        case error_code::bad_index: return "ctga: a mesh triangle names a vertex index past the mesh's vertices";
        case error_code::size_mismatch:
            return "ctga: a mesh has no triangles, a height field's heights do not number rows x columns (at least 2 x 2), or "
                   "a contact problem's arrays disagree with its contact count (mu: m, impulses: 3m)";
        case error_code::negative_friction: return "ctga: a friction coefficient must not be negative";
        case error_code::joint_to_itself: return "ctga: a joint joins two different bodies (or a body and the ground)";
        case error_code::not_supported: return "ctga: a combination the stepper does not handle (a robot in a world with substeps > 0)";
        case error_code::zero_direction: return "ctga: an axis must have a direction (it is the zero vector)";
        case error_code::not_a_motor: return "ctga: not a rigid motion (g g* = 1 fails beyond rounding, or the rotor part is zero)";
        case error_code::did_not_converge:
            return "ctga: the implicit step did not converge (the step is too large for the angular velocity)";
    }
    return "ctga: unknown error";
}

// The error of each lane of a pack of L robots (support/pack.hpp): lane l failed with lane[l].
template <std::size_t L>
struct lane_errors {
    std::array<error_code, L> lane{};  // none in every lane

    [[nodiscard]] constexpr const error_code& operator[](std::size_t l) const noexcept { return lane[l]; }
    [[nodiscard]] constexpr error_code& operator[](std::size_t l) noexcept { return lane[l]; }
    friend constexpr bool operator==(const lane_errors&, const lane_errors&) = default;
};

// What a computation in scalar type T reports: one error_code, or one per lane for a pack.
template <class T>
struct error_of {
    using type = error_code;
};
template <lane_wise T>
struct error_of<T> {
    using type = lane_errors<T::size>;
};
template <class T>
using error_of_t = typename error_of<T>::type;

// A value and what went wrong: E is error_code, or lane_errors<L> for a value made of packs
// (each lane its own robot; the failed lanes' values are meaningless, the others' valid).
template <class V, class E = error_code>
struct checked {
    V value{};
    E error{};  // error_code::none (in every lane)

    [[nodiscard]] constexpr explicit operator bool() const noexcept { return error == E{}; }
    [[nodiscard]] constexpr const V& operator*() const noexcept {
        assert(error == E{} && "ctga: reading the value of a failed check");
        return value;
    }
    [[nodiscard]] constexpr const V* operator->() const noexcept { return &**this; }
};

// The value of a check the caller knows succeeds (renormalize, make_rotor: the unchecked forms of
// the *_checked functions). A failure asserts in debug builds; in release builds it gives V with
// every component NaN, so that it shows in every later result instead of passing for a value.
// V: a type with size() and operator[] (a multivector).
template <class V>
[[nodiscard]] constexpr V value_or_nan(const checked<V>& r) noexcept {
    assert(r.error == error_code::none && "ctga: the unchecked form of a *_checked function failed; call the checked one");
    if (r.error == error_code::none) return r.value;
    V out{};
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = std::numeric_limits<std::remove_cvref_t<decltype(out[i])>>::quiet_NaN();
    return out;
}

}  // namespace ctga
