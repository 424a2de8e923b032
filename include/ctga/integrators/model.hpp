// What an integrator needs from a representation of one rigid body's motion, and the library's
// own representation.
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
//   finite(g, s)         every number finite
//   magnitude(z)         max |component| of a screw (for convergence tests)
// and its motors and screws form vector spaces under +, − and multiplication by a scalar (as
// ctga multivectors, the dense reference's multivectors and Eigen vectors all do). The
// integrators (methods.hpp: explicit_euler, rk4, lie_rk4, implicit_midpoint) are written once
// against this interface, so the same method runs on ctga, on the dense 256-blade reference and
// on the 6×6 matrix formalism, and their trajectories can be compared number for number.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>

#include "ctga/support/checked.hpp"
#include "ctga/mechanics/dynamics.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/operations/jacobian.hpp"

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

// ---- the library's representation ------------------------------------------------------------

// No applied wrench: a free body.
struct no_wrench {
    template <class T>
    [[nodiscard]] constexpr wrench<T> operator()(const motor<T>&, const screw<T>&) const noexcept {
        return wrench<T>{};
    }
};

// How the fixed-frame acceleration is evaluated: about the body's own frame and moved out
// (dynamics.hpp: ṡ = g ṡ_b g*; the default: its error stays at ε|t| for a body at distance |t|,
// and it is cheaper, 178 multiplications against 280, since the body's N and M are used as
// stored), or with the inertia moved to the fixed frame, as the paper writes it (§6; its error
// grows like ε|t|², docs/accuracy.md).
enum class fixed_frame_evaluation { about_body, in_space };

// One rigid body in ctga types.
template <class T = double, frame Frame = frame::body, class Wrench = no_wrench,
          fixed_frame_evaluation Evaluation = fixed_frame_evaluation::about_body>
struct rigid_body_motion {
    using scalar_type = T;
    using motor_type = motor<T>;
    using screw_type = screw<T>;
    static constexpr frame velocity_frame = Frame;

    rigid_body<T> body;  // mass properties, N and M in the body frame
    Wrench applied{};    // the applied wrench, applied(g, s), in the model's frame

    [[nodiscard]] constexpr screw<T> acceleration(const motor<T>& g, const screw<T>& s) const noexcept {
        const ctga::wrench<T> W = applied(g, s);
        if constexpr (Frame == frame::body) return ctga::acceleration(body, s, W);
        else if constexpr (Evaluation == fixed_frame_evaluation::in_space) return fixed_frame_rates(body, g, s, W).s_dot;
        else return fixed_frame_rates_about_body(body, g, s, W).s_dot;
    }
    // ∂ṡ/∂s, 6 × 6 row-major (screw components (ω, v) both ways), at the wrench applied at (g, s)
    // (a wrench that depends on s contributes nothing here): the exact Jacobian of the EOM formula
    // motion_rate (ctga::jacobian). In the fixed frame ṡ = H ṡ_b(H⁻¹ s) (dynamics.hpp), so
    // ∂ṡ/∂s = H (∂ṡ_b/∂s_b) H⁻¹, column by column.
    [[nodiscard]] constexpr std::array<std::array<T, 6>, 6> acceleration_jacobian(const motor<T>& g,
                                                                               const screw<T>& s) const noexcept {
        const ctga::wrench<T> W = applied(g, s);
        if constexpr (Frame == frame::body) {
            return jacobian<2, lifted_screw<T>>(motion_rate, body.Nb, body.M, s, W).dense();
        } else {
            const motor_map<T> G = map_of(g);
            const auto Jb = jacobian<2, lifted_screw<T>>(motion_rate, body.Nb, body.M, transform_inverse(G, s),
                                                         transform_inverse(G, W))
                                .dense();
            std::array<std::array<T, 6>, 6> J{};
            for (std::size_t c = 0; c < 6; ++c) {
                screw<T> e{};
                e[c] = T(1);
                const screw<T> u = transform_inverse(G, e);
                screw<T> y{};
                for (std::size_t r = 0; r < 6; ++r)
                    for (std::size_t k = 0; k < 6; ++k) y[r] = y[r] + Jb[r][k] * u[k];
                const screw<T> col = transform(G, y);
                for (std::size_t r = 0; r < 6; ++r) J[r][c] = col[r];
            }
            return J;
        }
    }
    [[nodiscard]] constexpr motor<T> motor_rate(const motor<T>& g, const screw<T>& s) const noexcept {
        if constexpr (Frame == frame::body) return half * g * s;
        else return half * s * g;
    }
    [[nodiscard]] constexpr motor<T> exp(const screw<T>& z) const noexcept { return ctga::exp(z); }
    [[nodiscard]] constexpr motor<T> compose(const motor<T>& a, const motor<T>& b) const noexcept { return a * b; }
    [[nodiscard]] constexpr screw<T> bracket(const screw<T>& a, const screw<T>& b) const noexcept {
        return ctga::bracket(a, b);
    }
    [[nodiscard]] constexpr motor<T> renormalize(const motor<T>& g) const noexcept { return ctga::renormalize(g); }
    [[nodiscard]] constexpr bool finite(const motor<T>& g, const screw<T>& s) const noexcept {
        for (std::size_t i = 0; i < 8; ++i)
            if (!is_finite(g[i])) return false;
        for (std::size_t i = 0; i < 6; ++i)
            if (!is_finite(s[i])) return false;
        return true;
    }
    [[nodiscard]] constexpr T magnitude(const screw<T>& z) const noexcept {
        T out = T(0);
        for (std::size_t i = 0; i < 6; ++i) out = z[i] > out ? z[i] : (-z[i] > out ? -z[i] : out);
        return out;
    }
};

}  // namespace ctga
