// The configuration space of a tree, as users know it from Pinocchio: q ⊕ v, q₁ ⊖ q₀, geodesic
// interpolation, the neutral configuration and random configurations within the joint limits.
//
//   auto q1 = chains::integrate(m, q, v);           // q ⊕ v: where velocity v for unit time leads
//   auto v  = chains::difference(m, q0, q1);        // q₁ ⊖ q₀: integrate(m, q0, v) = q1
//   auto qt = chains::interpolate(m, q0, q1, 0.25); // q₀ ⊕ t (q₁ ⊖ q₀)
//   auto q0 = chains::neutral(m);                   // every joint at 0, a floating base at identity
//   auto qr = chains::random_configuration(m, limits, rng);   // checked: a bound it needs is infinite
//
// The space is a product of groups (motion.hpp): the real line for a joint of one degree of
// freedom, q ⊕ v = q + v; the motors (§3) for a floating joint, whose velocity numbers are the
// body-frame screw s (dg/dt = ½ g s), so that q ⊕ v = g e^{v/2} = g exp(v) and q₁ ⊖ q₀ =
// log(g₀* g₁) (motor.hpp's exp and log; g₀* = g₀⁻¹ for a unit motor). This is the tangent space of
// the derivatives (rnea_derivatives.hpp: X(q ⊕ δ) = X(q) exp(δ S)), so ∂τ/∂q is the derivative of
// δ ↦ rnea(integrate(m, q, δ), …) at δ = 0. Mimic and fixed joints have no numbers of their own.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <numbers>
#include <random>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/joint_limits.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::chains {

namespace configuration_detail {
// f(J, q offset, v offset) for every body's joint J, in body order.
template <class Tree, class F>
constexpr void each_joint(F&& f) noexcept {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (f(typename Tree::template joint_at<I>{}, Tree::q_offset[I], Tree::v_offset[I]), ...);
    }(std::make_index_sequence<Tree::size>{});
}
template <class T>
constexpr motor<T> motor_at(const T* q) noexcept {
    return motor<T>{q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]};
}
template <class T>
constexpr screw<T> screw_at(const T* v) noexcept {
    return screw<T>{v[0], v[1], v[2], v[3], v[4], v[5]};
}
template <class X, class T>
constexpr void put(const X& x, std::size_t n, T* out) noexcept {
    for (std::size_t i = 0; i < n; ++i) out[i] = x[i];
}
}  // namespace configuration_detail

struct integrate_t {
    // q ⊕ v: a 1-dof joint's q + v, a floating joint's g exp(v).
    template <class Tree, class T>
    [[nodiscard]] constexpr configuration<Tree, T> operator()(const model<Tree, T>&, const configuration<Tree, T>& q,
                                                              const joint_vector<Tree, T>& v) const noexcept {
        using namespace configuration_detail;
        configuration<Tree, T> out{};
        each_joint<Tree>([&](auto joint, std::size_t qo, std::size_t vo) {
            using J = decltype(joint);
            if constexpr (J::nq == 8) put(motor<T>(motor_at(&q[qo]) * ctga::exp(screw_at(&v[vo]))), 8, &out[qo]);
            else if constexpr (J::nq == 1) out[qo] = q[qo] + v[vo];
        });
        return out;
    }
};
inline constexpr algorithm<integrate_t, "integrate"> integrate{};

struct difference_t {
    // q₁ ⊖ q₀, the v with integrate(m, q₀, v) = q₁: a 1-dof joint's q₁ − q₀, a floating joint's
    // log(g₀* g₁) (the shorter way round: a turn by at most π).
    template <class Tree, class T>
    [[nodiscard]] constexpr joint_vector<Tree, T> operator()(const model<Tree, T>&, const configuration<Tree, T>& q0,
                                                             const configuration<Tree, T>& q1) const noexcept {
        using namespace configuration_detail;
        joint_vector<Tree, T> out{};
        each_joint<Tree>([&](auto joint, std::size_t qo, std::size_t vo) {
            using J = decltype(joint);
            if constexpr (J::nq == 8) put(ctga::log(motor<T>(inverse(motor_at(&q0[qo])) * motor_at(&q1[qo]))), 6, &out[vo]);
            else if constexpr (J::nq == 1) out[vo] = q1[qo] - q0[qo];
        });
        return out;
    }
};
inline constexpr algorithm<difference_t, "difference"> difference{};

struct interpolate_t {
    // q₀ ⊕ t (q₁ ⊖ q₀): q₀ at t = 0, q₁ at t = 1, along the group's geodesic (a floating base turns
    // about one axis while its origin moves along a helix: a screw motion, §3).
    template <class Tree, class T>
    [[nodiscard]] constexpr configuration<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q0,
                                                              const configuration<Tree, T>& q1, const T& t) const noexcept {
        joint_vector<Tree, T> v = difference(m, q0, q1);
        for (T& x : v) x = t * x;
        return integrate(m, q0, v);
    }
};
inline constexpr algorithm<interpolate_t, "interpolate"> interpolate{};

// Every joint at 0, every floating joint at the identity motor.
template <class Tree, class T>
[[nodiscard]] constexpr configuration<Tree, T> neutral(const model<Tree, T>&) noexcept {
    configuration<Tree, T> out{};
    configuration_detail::each_joint<Tree>([&](auto joint, std::size_t qo, std::size_t) {
        if constexpr (decltype(joint)::nq == 8) out[qo] = T(1);
    });
    return out;
}

// A configuration drawn uniformly within the limits (joint_limits.hpp) with rng, a uniform random
// bit generator (std::mt19937_64): a 1-dof joint's q in [lower, upper], a revolute joint without
// bounds in [−π, π]; a floating joint's origin in its box and its rotation uniform on SO(3)
// (Shoemake's unit quaternion from three uniform numbers). Reported: unbounded, when a bound it
// needs is infinite (a prismatic joint's, a floating base's position), and the limits' own
// errors (check_limits).
template <class Tree, class T, class Rng>
[[nodiscard]] checked<configuration<Tree, T>> random_configuration(const model<Tree, T>&,
                                                                            const joint_limits<Tree, T>& limits,
                                                                            Rng& rng) {
    if (const auto c = check_limits(limits); !c) return {{}, c.error};
    const auto uniform = [&](const T& lo, const T& hi) {
        return lo + (hi - lo) * std::generate_canonical<T, std::numeric_limits<T>::digits>(rng);
    };
    const auto bounded = [](const T& x) { return x > -std::numeric_limits<T>::max() && x < std::numeric_limits<T>::max(); };
    configuration<Tree, T> out{};
    error_code e = error_code::none;
    configuration_detail::each_joint<Tree>([&](auto joint, std::size_t qo, std::size_t vo) {
        using J = decltype(joint);
        const T* lo = &limits.lower[vo];
        const T* hi = &limits.upper[vo];
        if constexpr (J::nq == 1) {
            if (bounded(lo[0]) && bounded(hi[0])) out[qo] = uniform(lo[0], hi[0]);
            else if (turns<J> && !bounded(lo[0]) && !bounded(hi[0])) out[qo] = uniform(-std::numbers::pi_v<T>, std::numbers::pi_v<T>);
            else e = error_code::unbounded;
        } else if constexpr (J::nq == 8) {
            vec3<T> p{};
            for (std::size_t k = 0; k < 3; ++k) {
                if (!bounded(lo[3 + k]) || !bounded(hi[3 + k])) e = error_code::unbounded;
                else p[k] = uniform(lo[3 + k], hi[3 + k]);
            }
            const T u1 = uniform(T(0), T(1)), a = T(2) * std::numbers::pi_v<T> * uniform(T(0), T(1)),
                    b = T(2) * std::numbers::pi_v<T> * uniform(T(0), T(1));
            const T r1 = math::sqrt(T(1) - u1), r2 = math::sqrt(u1);
            const rotor<T> r{r2 * std::cos(b), r1 * std::sin(a), r1 * std::cos(a), r2 * std::sin(b)};
            configuration_detail::put(rigid_motion(make_translator(p[0], p[1], p[2]), r), 8, &out[qo]);
        }
    });
    if (e != error_code::none) return {{}, e};
    return {out, error_code::none};
}

}  // namespace ctga::chains
