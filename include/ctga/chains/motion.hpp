// A kinematic tree as a model for the integrators (integrators/model.hpp), so that a chain is
// simulated with the same calls as a body or a scene:
//
//   chains::tree_motion<arm> sim{m};                       // passive: τ = 0
//   auto run = ctga::integrate(ctga::lie_rk4{}, sim, {q0, qd0}, 1e-3, 10'000);
//
// The state is (q, q̇). The configuration space is a product of groups: the real line for each
// revolute or prismatic joint, and for a floating joint the group of motors (§3), whose
// velocity is the body-frame screw s with dg/dt = ½ g s. In the model's terms:
//   motor_rate(q, q̇)   q̇ for a 1-dof joint, ½ g s for a floating one
//   exp(z)             z for a 1-dof joint, e^{z/2} (§3) for a floating one
//   compose(a, b)      a + b,                 the motor product a b
//   bracket(a, b)      0,                     the Lie bracket of the two screws (§3)
//   renormalize(q)     each floating motor renormalised
// so lie_rk4 and implicit_midpoint move a floating base on the group (its motor stays a unit
// motor), rk4 moves it in the flat coordinates and renormalises; acceleration(q, q̇) is
// forward dynamics by the articulated body algorithm with the actuation's τ(q, q̇), and
// acceleration_partials its derivatives (aba_derivatives), for the implicit midpoint's Newton
// iteration.
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include "ctga/chains/aba.hpp"
#include "ctga/chains/aba_derivatives.hpp"
#include "ctga/chains/checked_call.hpp"
#include "ctga/chains/configuration_space.hpp"
#include "ctga/chains/energy.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/integrators/model.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/math.hpp"

namespace ctga::chains {

// N numbers with the vector-space operations the integrators use (x + c y, x − y, c x).
template <std::size_t N, class T = double>
struct coordinates {
    std::array<T, N> x{};

    [[nodiscard]] static constexpr std::size_t size() noexcept { return N; }
    [[nodiscard]] constexpr T& operator[](std::size_t i) noexcept { return x[i]; }
    [[nodiscard]] constexpr const T& operator[](std::size_t i) const noexcept { return x[i]; }
    [[nodiscard]] friend constexpr coordinates operator+(const coordinates& a, const coordinates& b) noexcept {
        coordinates out;
        for (std::size_t i = 0; i < N; ++i) out.x[i] = a.x[i] + b.x[i];
        return out;
    }
    [[nodiscard]] friend constexpr coordinates operator-(const coordinates& a, const coordinates& b) noexcept {
        coordinates out;
        for (std::size_t i = 0; i < N; ++i) out.x[i] = a.x[i] - b.x[i];
        return out;
    }
    [[nodiscard]] friend constexpr coordinates operator*(const T& c, const coordinates& a) noexcept {
        coordinates out;
        for (std::size_t i = 0; i < N; ++i) out.x[i] = c * a.x[i];
        return out;
    }
};

// No joint forces: the tree moves under gravity alone.
struct passive {
    template <std::size_t NQ, std::size_t NV, class T>
    [[nodiscard]] constexpr std::array<T, NV> operator()(const std::array<T, NQ>&, const std::array<T, NV>&) const noexcept {
        return {};
    }
};


template <class Tree, class T = double, class Actuation = passive>
struct tree_motion {
    using scalar_type = T;
    using motor_type = coordinates<Tree::nq, T>;  // q
    using screw_type = coordinates<Tree::nv, T>;  // q̇ (a floating base's: its body-frame screw)
    static constexpr ctga::frame velocity_frame = ctga::frame::body;

    model<Tree, T> m;
    Actuation actuation{};  // τ(q, q̇), joint forces

    [[nodiscard]] constexpr screw_type acceleration(const motor_type& q, const screw_type& qd) const noexcept {
        return {aba(m, q.x, qd.x, actuation(q.x, qd.x))};
    }
    // ∂q̈/∂q (tangent space: a floating motor moved by g exp(δ), as the integrators move it) and
    // ∂q̈/∂q̇ at the actuation's τ(q, q̇), held fixed (aba_derivatives.hpp): the implicit midpoint's
    // Newton matrix. (An actuation that depends on the state is left out of them: its feedback
    // only slows Newton's convergence to linear.)
    struct partials {
        std::array<std::array<T, Tree::nv>, Tree::nv> configuration, velocity;
    };
    [[nodiscard]] constexpr partials acceleration_partials(const motor_type& q, const screw_type& qd) const noexcept {
        const aba_partials<Tree, T> d = aba_derivatives(m, q.x, qd.x, actuation(q.x, qd.x));
        return {d.dqdd_dq.dense(), d.dqdd_dv.dense()};
    }

    [[nodiscard]] constexpr motor_type motor_rate(const motor_type& q, const screw_type& qd) const noexcept {
        return per_joint<motor_type>([&](auto joint, std::size_t qo, std::size_t vo, motor_type& out) {
            using J = decltype(joint);
            if constexpr (J::nq == 8) configuration_detail::put(motor<T>(half * configuration_detail::motor_at(&q[qo]) * configuration_detail::screw_at(&qd[vo])), 8, &out[qo]);
            else if constexpr (J::nq == 1) out[qo] = qd[vo];
        });
    }
    [[nodiscard]] constexpr motor_type exp(const screw_type& z) const noexcept {
        return per_joint<motor_type>([&](auto joint, std::size_t qo, std::size_t vo, motor_type& out) {
            using J = decltype(joint);
            if constexpr (J::nq == 8) configuration_detail::put(ctga::exp(configuration_detail::screw_at(&z[vo])), 8, &out[qo]);
            else if constexpr (J::nq == 1) out[qo] = z[vo];
        });
    }
    [[nodiscard]] constexpr motor_type compose(const motor_type& a, const motor_type& b) const noexcept {
        return per_joint<motor_type>([&](auto joint, std::size_t qo, std::size_t, motor_type& out) {
            using J = decltype(joint);
            if constexpr (J::nq == 8) configuration_detail::put(motor<T>(configuration_detail::motor_at(&a[qo]) * configuration_detail::motor_at(&b[qo])), 8, &out[qo]);
            else if constexpr (J::nq == 1) out[qo] = a[qo] + b[qo];
        });
    }
    [[nodiscard]] constexpr screw_type bracket(const screw_type& a, const screw_type& b) const noexcept {
        return per_joint<screw_type>([&](auto joint, std::size_t, std::size_t vo, screw_type& out) {
            using J = decltype(joint);
            if constexpr (J::nv == 6) configuration_detail::put(ctga::bracket(configuration_detail::screw_at(&a[vo]), configuration_detail::screw_at(&b[vo])), 6, &out[vo]);
        });
    }
    [[nodiscard]] constexpr motor_type renormalize(const motor_type& q) const noexcept {
        motor_type out = q;
        per_joint<motor_type>([&](auto joint, std::size_t qo, std::size_t, motor_type&) {
            if constexpr (decltype(joint)::nq == 8) configuration_detail::put(ctga::renormalize(configuration_detail::motor_at(&q[qo])), 8, &out[qo]);
        });
        return out;
    }
    // every floating joint's eight numbers a unit motor up to rounding (near_unit); integrate
    // reports one that is not as not_a_unit_base (checked_call.hpp)
    static constexpr error_code not_unit_error = error_code::not_a_unit_base;
    [[nodiscard]] constexpr bool unit(const motor_type& q) const noexcept {
        bool ok = true;
        per_joint<motor_type>([&](auto joint, std::size_t qo, std::size_t, motor_type&) {
            if constexpr (decltype(joint)::nq == 8) ok = ok && near_unit(configuration_detail::motor_at(&q[qo]));
        });
        return ok;
    }
    [[nodiscard]] constexpr bool finite(const motor_type& q, const screw_type& qd) const noexcept {
        return algorithm_detail::finite_all<T>(q.x) && algorithm_detail::finite_all<T>(qd.x);
    }
    [[nodiscard]] constexpr T magnitude(const screw_type& z) const noexcept {
        T out = T(0);
        if constexpr (lane_wise<T>) {
            // lane by lane; NaN in a lane with a NaN or infinite component (the implicit
            // midpoint's lane-wise iteration reads its failures there)
            auto finite = finite_lanes(out);
            for (const T& c : z.x) {
                out = select(abs(c) > out, abs(c), out);
                finite = finite && finite_lanes(c);
            }
            return select(finite, out, T(std::numeric_limits<typename T::value_type>::quiet_NaN()));
        } else {
            for (const T& c : z.x) out = (c < T(0) ? -c : c) > out ? (c < T(0) ? -c : c) : out;
            return out;
        }
    }

    // The total energy: kinetic plus potential in the model's gravity.
    [[nodiscard]] constexpr T energy(const motor_type& q, const screw_type& qd) const noexcept {
        return tree_kinetic_energy(m, q.x, qd.x) + tree_potential_energy(m, q.x);
    }

private:
    // f(joint, q offset, v offset, out) for every body's joint, in body order.
    template <class Out, class F>
    static constexpr Out per_joint(F&& f) noexcept {
        Out out{};
        algorithm_detail::forward<Tree::size>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            f(typename Tree::template joint_at<i>{}, Tree::q_offset[i], Tree::v_offset[i], out);
        });
        return out;
    }
};

}  // namespace ctga::chains
