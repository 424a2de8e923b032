// The integrators of include/ctga/integrators on ctga's own model: their orders (fitted slopes of
// the error against the step), the implicit midpoint's energy conservation, the drift of the
// motor constraint g g* = 1 over 10⁶ steps with and without renormalisation, float against
// double, and how bad input and blow-ups are reported.
//
// Reference solutions here are small-step RK4 runs (error ≤ 1e-13 at h = 1e-3 over these
// horizons); the closed-form free body is used in integrator_stress_test.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <ctga/ctga.hpp>

#include "support/catch.hpp"

namespace {

using namespace ctga;

template <class T>
rigid_body<T> asymmetric_body() {
    // mass 2, centre of mass off the body origin, inertia with products of inertia
    const auto b = make_rigid_body(T(2), vec3<T>{T(0.1), T(-0.2), T(0.3)},
                                   mat3<T>{{{T(2), T(0.1), T(0)}, {T(0.1), T(2.5), T(-0.05)}, {T(0), T(-0.05), T(3)}}});
    REQUIRE(b);
    return *b;
}

template <class T>
motor<T> some_pose() {
    return rigid_motion(make_translator(T(0.5), T(-1), T(2)), make_rotor(T(0.7), T(1) / T(3), T(2) / T(3), T(2) / T(3)));
}

// The rotation angle between two poses, ‖log(g_ref* g)‖ restricted to ω: the attitude error.
template <class T>
T attitude_error(const motor<T>& g, const motor<T>& ref) {
    const screw<T> z = ctga::log(motor<T>(inverse(ref) * g));
    return std::sqrt(z[0] * z[0] + z[1] * z[1] + z[2] * z[2]);
}

// Least-squares slope of log(e) against log(h).
double fitted_slope(const std::vector<double>& h, const std::vector<double>& e) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = static_cast<double>(h.size());
    for (std::size_t i = 0; i < h.size(); ++i) {
        const double x = std::log(h[i]), y = std::log(e[i]);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

template <class Method, class Model>
double slope_of(const char* name, const Method& method, const Model& model, const state_of<Model>& x0, double t_end,
                std::vector<double> steps) {
    const auto ref = integrate(rk4{}, model, x0, 1e-3, std::llround(t_end / 1e-3));
    REQUIRE(ref);
    std::vector<double> errors;
    for (double h : steps) {
        const auto run = integrate(method, model, x0, h, std::llround(t_end / h));
        REQUIRE(run);
        errors.push_back(attitude_error(run.state.g, ref.state.g));
    }
    const double slope = fitted_slope(steps, errors);
    std::printf("%-5s frame, %-24s attitude errors %.2e … %.2e, slope %.3f\n",
                Model::velocity_frame == frame::body ? "body" : "fixed", name, errors.front(), errors.back(), slope);
    return slope;
}

template <class T>
T energy_of(const rigid_body<T>& b, const screw<T>& s_b) {
    return kinetic_energy(b.N, s_b);
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("each integrator converges at its order (fitted slope within ±0.3)", "[integrators]",
                       ((frame F), F), frame::body, frame::fixed) {
    const rigid_body_motion<double, F> model{asymmetric_body<double>()};
    const state_of<decltype(model)> x0{some_pose<double>(), screw<double>{0.3, 1.0, -0.4, 0.2, -0.1, 0.5}};
    const std::vector<double> coarse{0.2, 0.1, 0.05, 0.025};
    CHECK(std::abs(slope_of("rk4", rk4{}, model, x0, 10.0, coarse) - 4) <= 0.3);
    CHECK(std::abs(slope_of("rk4 (no renormalisation)", rk4{.renormalize = false}, model, x0, 10.0, coarse) - 4) <= 0.3);
    CHECK(std::abs(slope_of("lie_rk4", lie_rk4{}, model, x0, 10.0, coarse) - 4) <= 0.3);
    CHECK(std::abs(slope_of("implicit_midpoint", implicit_midpoint{}, model, x0, 10.0, coarse) - 2) <= 0.3);
    CHECK(std::abs(slope_of("explicit_euler", explicit_euler{}, model, x0, 2.0, {0.004, 0.002, 0.001, 0.0005}) - 1) <= 0.3);
}

TEST_CASE("the implicit midpoint conserves the body-frame kinetic energy over 1e5 steps", "[integrators]") {
    const rigid_body<double> b = asymmetric_body<double>();
    const rigid_body_motion<double, frame::body> model{b};
    const state_of<decltype(model)> x0{some_pose<double>(), screw<double>{0.3, 1.0, -0.4, 0.2, -0.1, 0.5}};
    const double E0 = energy_of(b, x0.s);
    double first_half = 0, second_half = 0;
    const long long n = 100'000;
    const auto run = integrate(implicit_midpoint{}, model, x0, 0.05, n, [&](long long k, const auto& x) {
        const double e = std::abs(energy_of(b, x.s) - E0) / E0;
        (k <= n / 2 ? first_half : second_half) = std::max(k <= n / 2 ? first_half : second_half, e);
    });
    REQUIRE(run);
    std::printf("midpoint, 1e5 steps of 0.05: max relative energy error %.2e (first half), %.2e (second half)\n",
                first_half, second_half);
    // Conserved up to rounding and the iteration's stopping tolerance (a random walk of a few
    // ulps per step), where a drift would grow linearly like RK4's below.
    CHECK(second_half <= 2e-13);
    // RK4 at the same step drifts linearly: the contrast the claim is about.
    const auto rk = integrate(rk4{}, model, x0, 0.05, n);
    REQUIRE(rk);
    const double rk_error = std::abs(energy_of(b, rk.state.s) - E0) / E0;
    std::printf("rk4 at the same step: relative energy error %.2e after 1e5 steps\n", rk_error);
    CHECK(rk_error > 100 * second_half);
}

TEST_CASE("motor constraint drift over 1e6 steps, with and without renormalisation", "[integrators]") {
    const rigid_body_motion<double, frame::body> model{asymmetric_body<double>()};
    const state_of<decltype(model)> x0{some_pose<double>(), screw<double>{0.3, 1.0, -0.4, 0.2, -0.1, 0.5}};
    // |α|² − 1, and α·β relative to |β| (β = ½ t α grows with the distance travelled, and
    // rounding with it)
    const auto defect = [](const motor<double>& g) {
        const motor_defect<double> d = unit_defect(g);
        const double beta = std::sqrt(g[4] * g[4] + g[5] * g[5] + g[6] * g[6] + g[7] * g[7]);
        return std::max(std::abs(d.alpha_norm), std::abs(d.alpha_beta) / std::max(1.0, beta));
    };
    const long long n = 1'000'000;
    const double h = 0.01;
    const auto run_with = [&](const auto& method) {
        double worst = 0;
        const auto run = integrate(method, model, x0, h, n, [&](long long, const auto& x) { worst = std::max(worst, defect(x.g)); });
        REQUIRE(run);
        return worst;
    };
    const double renormalised = run_with(rk4{});
    const double plain = run_with(rk4{.renormalize = false});
    const double lie = run_with(lie_rk4{});
    std::printf("max |g g* − 1| over 1e6 steps of 0.01: rk4 renormalised %.2e, rk4 plain %.2e, lie_rk4 %.2e\n",
                renormalised, plain, lie);
    CHECK(renormalised <= 2e-15);
    CHECK(lie <= 1e-12);                 // exp keeps g a motor; only rounding accumulates
    CHECK(plain > 100 * renormalised);   // without renormalisation RK4 leaves the group
}

TEST_CASE("float and double runs of the same problem", "[integrators]") {
    const auto energy_error = [](auto zero) {
        using T = decltype(zero);
        const rigid_body<T> b = asymmetric_body<T>();
        const rigid_body_motion<T, frame::body> model{b};
        const state_of<decltype(model)> x0{some_pose<T>(), screw<T>{T(0.3), T(1), T(-0.4), T(0.2), T(-0.1), T(0.5)}};
        const T E0 = energy_of(b, x0.s);
        T worst = 0;
        const auto run = integrate(lie_rk4{.renormalize = std::is_same_v<T, float>}, model, x0, T(0.01), 10'000,
                                   [&](long long, const auto& x) {
            worst = std::max(worst, std::abs(energy_of(b, x.s) - E0) / E0);
        });
        REQUIRE(run);
        const motor_defect<T> d = unit_defect(run.state.g);
        return std::array<double, 2>{double(worst), double(std::max(std::abs(d.alpha_norm), std::abs(d.alpha_beta)))};
    };
    const auto f = energy_error(0.0f);
    const auto d = energy_error(0.0);
    std::printf("lie_rk4, 1e4 steps of 0.01 (float renormalised): energy error float %.2e, double %.2e; "
                "|g g* − 1| float %.2e, double %.2e\n",
                f[0], d[0], f[1], d[1]);
    // float: rounding dominates (ε = 1.2e-7 over 1e4 steps); double: the method's truncation error
    CHECK(f[0] <= 1e-5);
    CHECK(d[0] <= 1e-10);
    CHECK(f[1] <= 2e-6);
    CHECK(d[1] <= 1e-13);
}

TEST_CASE("bad input and blow-ups are reported, never returned as a state", "[integrators][errors]") {
    const rigid_body<double> b = asymmetric_body<double>();
    const rigid_body_motion<double, frame::body> model{b};
    const state_of<decltype(model)> x0{some_pose<double>(), screw<double>{0.3, 1.0, -0.4, 0.2, -0.1, 0.5}};
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();

    SECTION("zero mass, NaN or infinite inertia: the body is refused") {
        const mat3<double> I{{{1, 0, 0}, {0, 2, 0}, {0, 0, 3}}};
        CHECK(make_rigid_body(0.0, vec3<double>{}, I).error == error_code::non_positive_mass);
        CHECK(make_rigid_body(nan, vec3<double>{}, I).error == error_code::non_finite);
        CHECK(make_rigid_body(1.0, vec3<double>{inf, 0, 0}, I).error == error_code::non_finite);
        CHECK(make_rigid_body(1.0, vec3<double>{}, mat3<double>{{{nan, 0, 0}, {0, 2, 0}, {0, 0, 3}}}).error ==
              error_code::non_finite);
    }
    SECTION("a non-finite initial state or step") {
        auto bad = x0;
        bad.s[4] = nan;
        const auto r1 = integrate(rk4{}, model, bad, 0.01, 10);
        CHECK(r1.error == error_code::non_finite);
        CHECK(r1.steps == 0);
        bad = x0;
        bad.g[6] = inf;
        CHECK(integrate(lie_rk4{}, model, bad, 0.01, 10).error == error_code::non_finite);
        CHECK(integrate(rk4{}, model, x0, inf, 10).error == error_code::non_finite);
        CHECK(integrate(rk4{}, model, x0, nan, 10).error == error_code::non_finite);
    }
    SECTION("an initial pose that is not a unit motor is refused, not integrated") {
        // the rotor an axis (0, 0, 5) taken as unit gave: cos ½ + 5 sin ½ e1e2, |α| = 2.5
        auto bad = x0;
        bad.g = motor<double>{std::cos(0.5), 0.0, 0.0, 5 * std::sin(0.5), 0.0, 0.0, 0.0, 0.0};
        const auto r = integrate(rk4{}, model, bad, 0.01, 10);
        CHECK(r.error == error_code::not_a_motor);
        CHECK(r.steps == 0);
        // translation and rotation parts that disagree (α·β ≠ 0 beyond rounding)
        bad = x0;
        bad.g[4] += 1e-3;
        CHECK(integrate(lie_rk4{}, model, bad, 0.01, 10).error == error_code::not_a_motor);
        // rounding-sized drift is a pose
        bad = x0;
        for (std::size_t k = 0; k < 8; ++k) bad.g[k] *= 1 + 1e-13;
        CHECK(integrate(rk4{}, model, bad, 0.01, 10));
    }
    SECTION("a wrench that turns NaN stops the run at the last good state") {
        struct failing_wrench {
            int* calls;
            wrench<double> operator()(const motor<double>&, const screw<double>&) const {
                return ++*calls > 10 ? wrench<double>{0, 0, std::numeric_limits<double>::quiet_NaN(), 0, 0, 0}
                                     : wrench<double>{0, 0, 0.1, 0, 0, 0};
            }
        };
        int calls = 0;
        const rigid_body_motion<double, frame::body, failing_wrench> forced{b, {&calls}};
        const auto run = integrate(rk4{}, forced, {x0.g, x0.s}, 0.01, 100);
        CHECK(run.error == error_code::non_finite);
        CHECK(run.steps == 2);  // 4 wrench calls per step: step 3 sees call 11
        CHECK(forced.finite(run.state.g, run.state.s));
    }
    SECTION("explicit Euler's blow-up at a large step is reported") {
        const state_of<decltype(model)> fast{x0.g, screw<double>{30, 60, -40, 0, 0, 0}};
        const auto run = integrate(explicit_euler{}, model, fast, 0.5, 100'000);
        CHECK(run.error == error_code::non_finite);
        CHECK(run.steps < 100'000);
        CHECK(model.finite(run.state.g, run.state.s));
        std::printf("explicit Euler, h|ω| = 40: non-finite after %lld steps, reported\n", run.steps);
    }
    SECTION("the implicit midpoint refuses a step it cannot converge") {
        const state_of<decltype(model)> fast{x0.g, screw<double>{30, 60, -40, 0, 0, 0}};
        const auto run = integrate(implicit_midpoint{.solver = implicit_solver::fixed_point}, model, fast, 0.5, 10);
        CHECK(run.error == error_code::did_not_converge);
        CHECK(run.steps == 0);
        CHECK(std::string(describe(run.error)).find("did not converge") != std::string::npos);
        // Newton's method with the exact ∂a/∂s (the default) gets further at the same h|ω| = 40;
        // where it stops, it stops with the same report, on the last converged state
        const auto newton = integrate(implicit_midpoint{}, model, fast, 0.5, 10);
        CHECK(newton.steps > run.steps);
        CHECK((newton.error == error_code::none || newton.error == error_code::did_not_converge));
        CHECK(model.finite(newton.state.g, newton.state.s));
        std::printf("implicit midpoint at h|ω| = 40: fixed point refuses the first step, Newton took %lld (%s)\n",
                    newton.steps, describe(newton.error));
    }
}
