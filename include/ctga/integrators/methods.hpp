// Integrators of one rigid body's motion, written once against the model interface (model.hpp).
//
//   explicit_euler      order 1; g leaves g g* = 1 at O(h²) per step
//   rk4                 classical Runge–Kutta on the flat state (g, s), order 4; the motor is
//                       renormalised after each step (optional)
//   lie_rk4             Runge–Kutta–Munthe-Kaas with the classical tableau, order 4: the motor
//                       is only ever moved by exponentials of screws (§3), so it stays a unit
//                       motor up to rounding (in float, renormalise: see the member); the
//                       velocity is integrated as a vector
//   implicit_midpoint   the midpoint rule with the pose moved by exp (a Lie midpoint), order 2,
//                       symmetric; in the body frame it preserves every quadratic invariant of
//                       the free body's velocity equation: the kinetic energy ½ s_b ∨ (N s_b)
//                       and the Casimirs |p|² and l·p of the body momentum
//
// Each step returns checked<state>: an implicit step whose iteration does not converge reports
// error_code::did_not_converge instead of returning an unconverged state.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <limits>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>

#include "ctga/integrators/model.hpp"
#include "ctga/support/checked.hpp"

namespace ctga {

// What a step returns: the new state, and error_code::none or why there is none; for a model in
// packs (support/pack.hpp: one robot per lane) one error_code per lane (lane_errors).
template <class M>
using step_result = checked<state_of<M>, error_of_t<typename M::scalar_type>>;

namespace integrator_detail {

// x + c k on the flat state, in the model's own types.
template <motion_model M>
[[nodiscard]] constexpr state_of<M> shifted(const state_of<M>& x, const typename M::scalar_type& c,
                                            const state_of<M>& k) {
    using motor_t = typename M::motor_type;
    using screw_t = typename M::screw_type;
    return {motor_t(x.g + c * k.g), screw_t(x.s + c * k.s)};
}
// (dg/dt, ds/dt) at x.
template <motion_model M>
[[nodiscard]] constexpr state_of<M> rates(const M& model, const state_of<M>& x) {
    return {typename M::motor_type(model.motor_rate(x.g, x.s)), typename M::screw_type(model.acceleration(x.g, x.s))};
}

// The inverse of the derivative of exp, truncated after the terms order 4 needs (Hairer,
// Lubich, Wanner, Geometric Numerical Integration, IV.8): with dg/dt = ½ s g and g = exp(θ) g₀,
// dθ/dt = s − ½[θ, s] + (1/12)[θ, [θ, s]] + O(θ³); with dg/dt = ½ g s and g = g₀ exp(θ), the
// first-order term changes sign. [a, b] = ½(ab − ba), the bracket of §3.
template <motion_model M>
[[nodiscard]] constexpr typename M::screw_type dexp_inverse(const M& model, const typename M::screw_type& theta,
                                                           const typename M::screw_type& s) {
    using screw_t = typename M::screw_type;
    using T = typename M::scalar_type;
    const screw_t first = model.bracket(theta, s);
    const screw_t second = model.bracket(theta, first);
    const T sign = M::velocity_frame == frame::fixed ? T(-1) : T(1);
    return screw_t(s + (sign / T(2)) * first + (T(1) / T(12)) * second);
}

}  // namespace integrator_detail

struct explicit_euler {
    static constexpr int order = 1;
    bool renormalize = false;

    template <motion_model M>
    [[nodiscard]] constexpr step_result<M> step(const M& model, const state_of<M>& x,
                                                      const typename M::scalar_type& h) const {
        state_of<M> y = integrator_detail::shifted<M>(x, h, integrator_detail::rates(model, x));
        if (renormalize) y.g = model.renormalize(y.g);
        return {y, {}};
    }
};

struct rk4 {
    static constexpr int order = 4;
    bool renormalize = true;

    template <motion_model M>
    [[nodiscard]] constexpr step_result<M> step(const M& model, const state_of<M>& x,
                                                      const typename M::scalar_type& h) const {
        using namespace integrator_detail;
        using T = typename M::scalar_type;
        using motor_t = typename M::motor_type;
        using screw_t = typename M::screw_type;
        const state_of<M> k1 = rates(model, x);
        const state_of<M> k2 = rates(model, shifted<M>(x, h / T(2), k1));
        const state_of<M> k3 = rates(model, shifted<M>(x, h / T(2), k2));
        const state_of<M> k4 = rates(model, shifted<M>(x, h, k3));
        const T w = h / T(6);
        state_of<M> y{motor_t(x.g + w * (k1.g + T(2) * (k2.g + k3.g) + k4.g)),
                      screw_t(x.s + w * (k1.s + T(2) * (k2.s + k3.s) + k4.s))};
        if (renormalize) y.g = model.renormalize(y.g);
        return {y, {}};
    }
};

// RKMK4: stage i moves the pose by exp(θ_i) with θ_i = h Σ a_ij K_j and evaluates the velocity's
// increment K_i = dexp⁻¹_{θ_i}(s_i) in the Lie algebra, with the classical RK4 tableau for both
// θ and the velocity s.
struct lie_rk4 {
    static constexpr int order = 4;
    // exp(z) of a small step rounds |α|² − 1 the same way every step, so in float the defect
    // grows linearly (5.8e-4 after 1e4 steps; double: ~1e-13 after 1e6): renormalise there.
    bool renormalize = false;

    template <motion_model M>
    [[nodiscard]] constexpr step_result<M> step(const M& model, const state_of<M>& x,
                                                      const typename M::scalar_type& h) const {
        using namespace integrator_detail;
        using T = typename M::scalar_type;
        using screw_t = typename M::screw_type;
        // stage 1: θ = 0, K = s
        const screw_t K1 = x.s;
        const screw_t L1 = model.acceleration(x.g, x.s);
        // stages 2–4: θ = c h K_prev, s = s₀ + c h L_prev
        const auto stage = [&](const T& c, const screw_t& K, const screw_t& L, screw_t& K_out, screw_t& L_out) {
            const screw_t theta(c * h * K);
            const screw_t s(x.s + c * h * L);
            K_out = dexp_inverse(model, theta, s);
            L_out = screw_t(model.acceleration(advance_pose(model, x.g, theta), s));
        };
        screw_t K2, L2, K3, L3, K4, L4;
        stage(T(1) / T(2), K1, L1, K2, L2);
        stage(T(1) / T(2), K2, L2, K3, L3);
        stage(T(1), K3, L3, K4, L4);
        const T w = h / T(6);
        const screw_t theta(w * (K1 + T(2) * (K2 + K3) + K4));
        state_of<M> y{advance_pose(model, x.g, theta), screw_t(x.s + w * (L1 + T(2) * (L2 + L3) + L4))};
        if (renormalize) y.g = model.renormalize(y.g);
        return {y, {}};
    }
};

namespace integrator_detail {
// An N×N matrix factored once (P A = L U, partial pivoting) and solved for several right-hand sides.
template <class T, std::size_t N>
struct lu {
    static constexpr std::size_t size = N;
    std::array<std::array<T, N>, N> a{};  // L below the diagonal (unit diagonal), U on and above
    std::array<std::size_t, N> row = [] {
        std::array<std::size_t, N> r{};
        for (std::size_t i = 0; i < N; ++i) r[i] = i;
        return r;
    }();
    bool singular = false;

    constexpr explicit lu(const std::array<std::array<T, N>, N>& A) noexcept : a(A) {
        for (std::size_t c = 0; c < N; ++c) {
            if constexpr (!lane_wise<T>) {
                std::size_t p = c;
                for (std::size_t r = c + 1; r < N; ++r)
                    if ((a[r][c] < T(0) ? -a[r][c] : a[r][c]) > (a[p][c] < T(0) ? -a[p][c] : a[p][c])) p = r;
                if (!(a[p][c] != T(0))) {
                    singular = true;
                    return;
                }
                std::swap(a[p], a[c]);
                std::swap(row[p], row[c]);
            }
            // packs (one robot per lane) are not pivoted: rows cannot be swapped lane by lane. The
            // Newton matrix 1 − O(h) is near the identity; a lane with a zero pivot gets
            // non-finite numbers, and the midpoint's iteration reports that lane
            for (std::size_t r = c + 1; r < N; ++r) {
                a[r][c] = a[r][c] / a[c][c];
                for (std::size_t k = c + 1; k < N; ++k) a[r][k] = a[r][k] - a[r][c] * a[c][k];
            }
        }
    }
    // A⁻¹ b
    [[nodiscard]] constexpr std::array<T, N> solve(const std::array<T, N>& b) const noexcept {
        std::array<T, N> x{};
        for (std::size_t i = 0; i < N; ++i) {
            T v = b[row[i]];
            for (std::size_t k = 0; k < i; ++k) v = v - a[i][k] * x[k];
            x[i] = v;
        }
        for (std::size_t i = N; i-- > 0;) {
            T v = x[i];
            for (std::size_t k = i + 1; k < N; ++k) v = v - a[i][k] * x[k];
            x[i] = v / a[i][i];
        }
        return x;
    }
};
// A model that gives ∂a/∂s (N × N, row-major, N the screw's dimension): the implicit midpoint's
// Newton iteration uses it.
template <class M>
concept with_acceleration_jacobian = requires(const M& m, const typename M::motor_type& g, const typename M::screw_type& s) {
    { m.acceleration_jacobian(g, s)[0][0] } -> std::convertible_to<typename M::scalar_type>;
};
// A model that gives ∂a/∂g as well (in the tangent space: g moved by exp(δ) in the model's frame)
// with ∂a/∂s, as .configuration and .velocity (a kinematic tree: chains/motion.hpp, from
// aba_derivatives): the pose's dependence on s₁ enters the Newton matrix too.
template <class M>
concept with_acceleration_partials = requires(const M& m, const typename M::motor_type& g, const typename M::screw_type& s) {
    { m.acceleration_partials(g, s).configuration[0][0] } -> std::convertible_to<typename M::scalar_type>;
    { m.acceleration_partials(g, s).velocity[0][0] } -> std::convertible_to<typename M::scalar_type>;
};
// The Newton matrix of the midpoint equation F(s₁) = s₁ − s₀ − h a(g_m, s_m): with s_m = ½(s₀ + s₁)
// and g_m = g₀ moved by exp(½ h s_m), ∂F/∂s₁ = 1 − h (½ ∂a/∂s + ¼ h ∂a/∂g) (∂a/∂g at g_m, the
// exponential's derivative taken as 1: O(h) off, which Newton's method absorbs).
template <motion_model M>
constexpr auto newton_matrix(const M& model, const typename M::motor_type& g_m, const typename M::screw_type& s_m,
                             const typename M::scalar_type& h) {
    using T = typename M::scalar_type;
    if constexpr (with_acceleration_partials<M>) {
        const auto p = model.acceleration_partials(g_m, s_m);
        auto J = p.velocity;
        for (std::size_t r = 0; r < J.size(); ++r)
            for (std::size_t c = 0; c < J.size(); ++c)
                J[r][c] = (r == c ? T(1) : T(0)) - h * (J[r][c] / T(2) + h / T(4) * p.configuration[r][c]);
        return J;
    } else {
        auto J = model.acceleration_jacobian(g_m, s_m);
        for (std::size_t r = 0; r < J.size(); ++r)
            for (std::size_t c = 0; c < J.size(); ++c) J[r][c] = (r == c ? T(1) : T(0)) - h / T(2) * J[r][c];
        return J;
    }
}
// The factored Newton matrix's type (none for a model without derivatives).
template <class M, bool = with_acceleration_jacobian<M> || with_acceleration_partials<M>>
struct newton_factor {
    using type = lu<typename M::scalar_type, 1>;  // never formed
};
template <class M>
struct newton_factor<M, true> {
    using matrix = decltype(newton_matrix(std::declval<const M&>(), std::declval<const typename M::motor_type&>(),
                                          std::declval<const typename M::screw_type&>(),
                                          std::declval<const typename M::scalar_type&>()));
    using type = lu<typename M::scalar_type, std::tuple_size_v<matrix>>;
};
}  // namespace integrator_detail

namespace integrator_detail {
// The implicit midpoint's tests for a scalar (a bool) and for packs (lane masks, pack.hpp).
template <class T>
struct number {
    using type = T;
};
template <lane_wise T>
struct number<T> {
    using type = typename T::value_type;
};
template <class T>
using number_of = typename number<T>::type;  // the scalar of one lane
template <class V>
[[nodiscard]] constexpr V choose(bool m, const V& a, const V& b) {
    return m ? a : b;
}
template <class M, class V>
    requires(!std::is_same_v<M, bool>)
[[nodiscard]] constexpr V choose(const M& m, const V& a, const V& b) {
    return select(m, a, b);
}
[[nodiscard]] constexpr bool all_of(bool m) noexcept { return m; }
[[nodiscard]] constexpr bool any_of(bool m) noexcept { return m; }
template <class M>
[[nodiscard]] constexpr bool all_of(const M& m) noexcept {
    return all(m);
}
template <class M>
[[nodiscard]] constexpr bool any_of(const M& m) noexcept {
    return any(m);
}
// The update is finite: the model's test for a scalar; for packs lane by lane, through the
// magnitudes' sum (a lane's magnitude is NaN when a component is not finite: chains/motion.hpp)
template <motion_model M>
[[nodiscard]] constexpr auto finite_update(const M& model, const state_of<M>& x, const typename M::screw_type& next,
                                           const typename M::scalar_type& magnitudes) {
    if constexpr (lane_wise<typename M::scalar_type>) return finite_lanes(magnitudes);
    else return model.finite(x.g, next);
}
}  // namespace integrator_detail

// How the implicit midpoint solves its equation for s₁.
enum class implicit_solver {
    newton,       // Newton's method with the model's exact ∂a/∂s (ctga::jacobian of the EOM; a
                  // tree's ∂q̈/∂(q, q̇) from aba_derivatives); the fixed-point iteration for a model
                  // that gives neither
    fixed_point,  // s₁ ← s₀ + h a(g_m, s_m), repeated
};

// s₁ = s₀ + h a(g_m, s_m), s_m = ½(s₀ + s₁), g_m = the pose moved by exp(½ h s_m), and
// g₁ = the pose moved by exp(h s_m). The implicit equation F(s₁) = s₁ − s₀ − h a(g_m, s_m) = 0
// is solved from an explicit Euler guess, by default with (simplified) Newton's method,
//   s₁ ← s₁ − (∂F/∂s₁)⁻¹ F(s₁),  ∂F/∂s₁ = 1 − ½ h ∂a/∂s (− ¼ h² ∂a/∂g, for a model that gives it:
// a tree), the matrix taken at the first midpoint and again only when an update contracts by less
// than ½ (without ∂a/∂g, g_m's dependence on s₁ is left out: it does not enter a free body's
// body-frame acceleration, and elsewhere it only slows the convergence to linear), or by the fixed-point
// iteration s₁ ← s₀ + h a(g_m, s_m), which contracts only when h‖∂a/∂s‖ < 2 (for h|ω| below about
// 1). Either stops when an update changes s₁ by at most ε (relative, in max |component|), or when
// it stalls at the rounding level; otherwise the step reports did_not_converge. `iterations`,
// when set, receives the count of each step (added to it).
struct implicit_midpoint {
    static constexpr int order = 2;
    int max_iterations = 60;
    bool renormalize = false;  // as for lie_rk4: the pose moves by exp, which drifts in float
    implicit_solver solver = implicit_solver::newton;
    long* iterations = nullptr;

    // One iteration for a scalar and for packs (one robot per lane): every test is a mask, a bool
    // for a scalar. A lane stops when its own update is small and keeps its s₁ from then on; the
    // Newton matrix is taken again when a lane still iterating contracts by less than ½ (so a
    // lane may take other iterates than its scalar run: the two s₁ agree to the stopping
    // tolerance). A lane whose iterate is not finite, or that has not converged after
    // max_iterations, reports did_not_converge and keeps its initial state.
    template <motion_model M>
    [[nodiscard]] constexpr step_result<M> step(const M& model, const state_of<M>& x,
                                                const typename M::scalar_type& h) const {
        using namespace integrator_detail;
        using T = typename M::scalar_type;
        using screw_t = typename M::screw_type;
        using mask = decltype(T(0) < T(0));  // bool, or a pack's lanes
        const T eps(std::numeric_limits<number_of<T>>::epsilon());
        const auto midpoint_pose = [&](const screw_t& s_m, const T& c) {
            return advance_pose(model, x.g, screw_t(c * h * s_m));
        };
        screw_t s1(x.s + h * model.acceleration(x.g, x.s));
        T previous(std::numeric_limits<number_of<T>>::infinity());
        using factor = typename newton_factor<M>::type;
        std::optional<factor> newton;  // ∂F/∂s₁, factored
        mask done = T(0) != T(0), failed = done;  // no lane yet
        int i = 0;
        for (; i < max_iterations && !all_of(done || failed); ++i) {
            const screw_t s_m(T(1) / T(2) * (x.s + s1));
            const auto g_m = midpoint_pose(s_m, T(1) / T(2));
            screw_t next(x.s + h * model.acceleration(g_m, s_m));  // the fixed-point update
            if constexpr (with_acceleration_jacobian<M> || with_acceleration_partials<M>) {
                if (solver == implicit_solver::newton) {
                    // Newton: ∂F/∂s₁ Δ = s₀ + h a − s₁ = next − s₁, the matrix taken at the first
                    // midpoint and factored once (a simplified Newton method: it moves by O(h)
                    // within the step), and taken again where an update contracts by less than ½
                    if (!newton) {
                        newton.emplace(newton_matrix(model, g_m, s_m, h));
                        if (newton->singular) break;  // (packs are not pivoted: never singular)
                    }
                    std::array<T, factor::size> residual;
                    for (std::size_t r = 0; r < residual.size(); ++r) residual[r] = next[r] - s1[r];
                    const auto delta = newton->solve(residual);
                    for (std::size_t r = 0; r < residual.size(); ++r) next[r] = s1[r] + delta[r];
                }
            }
            const T change = model.magnitude(screw_t(next - s1));
            const T scale = model.magnitude(next) + model.magnitude(x.s);
            failed = failed || (!done && !finite_update(model, x, next, change + scale));  // it diverged
            const mask iterating = !(done || failed);
            s1 = choose(iterating, next, s1);
            const mask converged =
                iterating && (change <= eps * scale || (change >= previous && change <= T(1024) * eps * scale));
            done = done || converged;
            // a slow contraction: the matrix of the first midpoint no longer fits; take it anew
            if (any_of(iterating && !converged && change > previous / T(2))) newton.reset();
            previous = choose(iterating, change, previous);
        }
        if (iterations) *iterations += i;
        const screw_t s_mid(T(1) / T(2) * (x.s + s1));
        state_of<M> y{midpoint_pose(s_mid, T(1)), s1};
        if (renormalize) y.g = model.renormalize(y.g);
        error_of_t<T> e{};
        if constexpr (lane_wise<T>) {
            for (std::size_t l = 0; l < T::size; ++l) e[l] = done[l] ? error_code::none : error_code::did_not_converge;
        } else {
            e = done ? error_code::none : error_code::did_not_converge;
        }
        return {{choose(done, y.g, x.g), choose(done, y.s, x.s)}, e};
    }
};

}  // namespace ctga
