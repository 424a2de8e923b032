// What an integrator needs from a representation of one rigid body's motion (a model); the
// library's own model is rigid_body_motion.hpp.
//
// The state is a pose g (a unit motor, §3) and a velocity screw s, either in the fixed frame (the
// paper's choice, §6: dg/dt = ½ s g) or in the body frame (s_b = g* s g, dg/dt = ½ g s_b). A
// model supplies, in its own types:
//   acceleration(g, s)   ds/dt from the equations of motion (§6), in the model's frame
//   motor_rate(g, s)     dg/dt: ½ s g (fixed) or ½ g s (body)
//   exp(z)               e^{z/2} (§3): the motor reached in unit time at constant velocity z
//   compose(g, h)        the motor product g h
//   bracket(a, b)        ½(a b − b a), the Lie bracket of screws (§3)
//   renormalize(g)       the nearest unit motor to a drifted one
//   unit(g)              g is a unit motor up to rounding (near_unit, motor.hpp): a pose
//   finite(g, s)         every number finite
//   magnitude(z)         max |component| of a screw (for convergence tests)
// and its motors and screws form vector spaces under +, − and multiplication by a scalar (as
// ctga multivectors, the dense reference's multivectors and Eigen vectors all do). The
// integrators (methods.hpp: explicit_euler, rk4, lie_rk4, implicit_midpoint) are written once
// against this interface, so the same method runs on ctga, on the dense 256-blade reference and
// on the 6×6 matrix formalism, and their trajectories can be compared number for number.
#pragma once

#include <concepts>

namespace ctga {

// Which frame the velocity screw (and the wrench) of a state is written in.
enum class frame { fixed, body };

template <class Motor, class Screw>
struct motion_state {
    Motor g;  // pose: a unit motor
    Screw s;  // velocity, in the model's frame
};

template <class M>
concept motion_model = requires(const M& m, const typename M::motor_type& g, const typename M::screw_type& s,
                                const typename M::scalar_type& h) {
    { M::velocity_frame } -> std::convertible_to<frame>;
    { m.acceleration(g, s) } -> std::convertible_to<typename M::screw_type>;
    { m.motor_rate(g, s) } -> std::convertible_to<typename M::motor_type>;
    { m.exp(s) } -> std::convertible_to<typename M::motor_type>;
    { m.compose(g, g) } -> std::convertible_to<typename M::motor_type>;
    { m.bracket(s, s) } -> std::convertible_to<typename M::screw_type>;
    { m.renormalize(g) } -> std::convertible_to<typename M::motor_type>;
    { m.unit(g) } -> std::convertible_to<bool>;
    { m.finite(g, s) } -> std::convertible_to<bool>;
    { m.magnitude(s) } -> std::convertible_to<typename M::scalar_type>;
    requires std::constructible_from<typename M::motor_type, decltype(g + h * g)>;
    requires std::constructible_from<typename M::screw_type, decltype(s + h * s)>;
};

template <motion_model M>
using state_of = motion_state<typename M::motor_type, typename M::screw_type>;

// The motor reached from g by the motion e^{z/2} applied in the model's frame: exp(z) g for
// fixed-frame velocities (a motion of space), g exp(z) for body-frame ones.
template <motion_model M>
[[nodiscard]] constexpr typename M::motor_type advance_pose(const M& model, const typename M::motor_type& g,
                                                            const typename M::screw_type& z) {
    if constexpr (M::velocity_frame == frame::fixed) return model.compose(model.exp(z), g);
    else return model.compose(g, model.exp(z));
}

}  // namespace ctga
