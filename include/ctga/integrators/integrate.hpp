// Driving an integrator over many steps, with every step checked.
//
//   ctga::rigid_body_motion<double, ctga::frame::body> model{body};
//   auto run = ctga::integrate(ctga::lie_rk4{}, model, {g0, s0}, 1e-3, 10'000);
//   if (!run) std::puts(ctga::describe(run.error));   // the state is the last good one
//
// A non-finite step size or initial state, an initial pose that is not a unit motor up to
// rounding (not_a_motor, or the model's not_unit_error: integrating it would move a shape that no rigid motion gives), a step producing a NaN or an infinity (a blow-up of
// an unstable method, a wrench returning NaN) and an implicit step that does not converge all
// stop the run and are reported with the number of steps completed: a corrupted state is never
// returned as if it were a result.
#pragma once

#include "ctga/integrators/methods.hpp"
#include "ctga/integrators/model.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga {

template <class State>
struct run_result {
    State state;         // after `steps` good steps
    long long steps{};   // steps completed
    error_code error = error_code::none;

    [[nodiscard]] constexpr explicit operator bool() const noexcept { return error == error_code::none; }
};

struct ignore_steps {
    template <class State>
    constexpr void operator()(long long, const State&) const noexcept {}
};

// What a model reports for a pose that is no unit motor: its own code when it names one (a tree's
// floating base: not_a_unit_base, whose message names the conversion from a position and a
// quaternion), else not_a_motor.
template <class M>
[[nodiscard]] constexpr error_code not_unit_error() noexcept {
    if constexpr (requires { M::not_unit_error; }) return M::not_unit_error;
    else return error_code::not_a_motor;
}

// `steps` steps of size h from x; observe(n, state) after step n (n = 1 … steps).
template <class Method, motion_model M, class Observer = ignore_steps>
[[nodiscard]] constexpr run_result<state_of<M>> integrate(const Method& method, const M& model, state_of<M> x,
                                                          const typename M::scalar_type& h, long long steps,
                                                          Observer&& observe = {}) {
    if (!is_finite(h) || !model.finite(x.g, x.s)) return {x, 0, error_code::non_finite};
    if (!model.unit(x.g)) return {x, 0, not_unit_error<M>()};  // a pose that is no rigid motion
    for (long long n = 0; n < steps; ++n) {
        const checked<state_of<M>> next = method.step(model, x, h);
        if (!next) return {x, n, next.error};
        if (!model.finite(next.value.g, next.value.s)) return {x, n, error_code::non_finite};
        x = next.value;
        observe(n + 1, x);
    }
    return {x, steps, error_code::none};
}

}  // namespace ctga
