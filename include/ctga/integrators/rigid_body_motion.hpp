// The library's own model of one rigid body's motion (the interface is model.hpp): the pose a
// unit motor and the velocity a screw (§3), in the body or the fixed frame, the acceleration from
// the equations of motion (dynamics.hpp, §6) and its exact Jacobian ∂ṡ/∂s (ctga::jacobian,
// operations/jacobian.hpp), which the implicit midpoint's Newton iteration uses (methods.hpp).
#pragma once

#include <array>
#include <cstddef>

#include "ctga/integrators/model.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/dynamics.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/rigid_body.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/operations/jacobian.hpp"
#include "ctga/support/math.hpp"

namespace ctga {

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
    [[nodiscard]] constexpr bool unit(const motor<T>& g) const noexcept { return near_unit(g); }
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
