// A rigid body's trajectory computed entirely by the compiler: 48 RK4 steps of a free asymmetric
// body (centre of mass off the body origin, products of inertia) in the body frame, inside one
// constant expression, with the kinetic energy and the motor's unit constraint checked by
// static_assert. At run time the same function is called again with inputs the optimiser cannot
// see, and the two results are compared bit for bit.
//
// Two runs: ctga::rk4{} (the motor renormalised after every step) and rk4 without
// renormalisation. The body-frame rates are products and sums only (ṡ from N, M and s; ġ = ½ g s),
// so the run without renormalisation is bit-identical at compile time and at run time.
// Renormalisation takes a square root, which ctga computes by Newton's iteration in constant
// evaluation and by std::sqrt at run time (ctga/mechanics/motor.hpp, motion_detail::sqrt); the
// two round differently for some inputs (Newton's result is 1 ulp off for ~25% of inputs near 1),
// so the renormalised motor ends a few tens of ulps apart while the velocity, which does not
// depend on the pose in the body frame, stays bit-identical. With a correctly rounded constant-
// evaluation square root both runs are bit-identical (checked by swapping in __builtin_sqrt).
//
// lie_rk4 and implicit_midpoint move the pose by ctga::exp, whose cos and sin are ctga::math::cos
// and sin: a reduced Taylor series in constant evaluation, std::cos / std::sin at run time, so the
// two would round differently; this example keeps to rk4, whose rates are products and sums.
//
// Cost of this file (measured with /usr/bin/time -v; x86-64, 2 cores under load from other builds):
//   g++ 12.2 -O3: 7.7-8.2 s wall, 0.56 GB peak RSS (with 1 step per run instead of 48:
//                 3.8 s, 0.32 GB; so ~45 ms and ~2.5 MB per constant-evaluated step)
//   clang++ 14 -O3 with the -fconstexpr-steps=2^25 that ctga::ctga adds: 26 s, 0.19 GB (it also
//                 compiles with 2^24; without the flag Clang stops already in ctga's product
//                 planning, mechanics/convert.hpp)
// One step costs about 3.4e5 of GCC's constexpr operations and GCC 12's default budget per
// constant expression is -fconstexpr-ops-limit=33554432 (2^25), so about 99 steps fit in one.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>

#include <ctga/integrators/integrate.hpp>
#include <ctga/integrators/rigid_body_motion.hpp>

namespace {

using model_type = ctga::rigid_body_motion<double, ctga::frame::body>;
using state_type = ctga::state_of<model_type>;

struct trajectory_result {
    state_type final_state;
    long long steps;
    bool ok;
    double initial_energy, final_energy;
    ctga::motor_defect<double> defect;  // of the final motor: |α|² − 1 and α·β
};

// The body, the initial state and the run: usable in a constant expression and at run time.
template <class Method>
constexpr trajectory_result trajectory(const Method& method, double h, long long steps) {
    // mass 1, centre of mass at (0.1, −0.2, 0.3) in the body frame, inertia about it with products
    const auto made = ctga::make_rigid_body(1.0, ctga::vec3<double>{0.1, -0.2, 0.3},
                                            ctga::mat3<double>{{{2.0, 0.1, 0.0}, {0.1, 2.5, -0.05}, {0.0, -0.05, 3.0}}});
    const model_type model{*made};
    // a rotor given by its numbers (ctga::rotation calls std::cos / std::sin): |α|² = 0.36 + 0.64
    const ctga::motor<double> g0 =
        ctga::rigid_motion(ctga::make_translator(0.5, -1.0, 2.0), ctga::rotor<double>{0.6, 0.8 / 3, 1.6 / 3, 1.6 / 3});
    const ctga::screw<double> s0{0.3, 1.0, -0.4, 0.2, -0.1, 0.5};  // body-frame (ω, v)
    const auto run = ctga::integrate(method, model, {g0, s0}, h, steps);
    return {run.state,
            run.steps,
            static_cast<bool>(made) && static_cast<bool>(run),
            ctga::kinetic_energy(model.body.N, s0),
            ctga::kinetic_energy(model.body.N, run.state.s),
            ctga::unit_defect(run.state.g)};
}

constexpr double h = 0.0625;      // 1/16: exact in binary
constexpr long long steps = 48;   // t = 3
constexpr double abs_of(double x) { return x < 0 ? -x : x; }

// rk4 as it is meant to be used: the motor renormalised after every step.
constexpr trajectory_result at_compile_time = trajectory(ctga::rk4{}, h, steps);
// rk4 on the flat state with no renormalisation: products and sums only.
constexpr trajectory_result plain_at_compile_time = trajectory(ctga::rk4{.renormalize = false}, h, steps);

constexpr double energy_tolerance = 1e-7;      // measured: -7.7e-9 (RK4's truncation error, ∝ h⁴), both runs
constexpr double unit_tolerance = 1e-15;       // measured: 0 and -2.8e-17 (renormalised every step)
constexpr double plain_unit_tolerance = 1e-7;  // measured: -2.8e-9 and -1.2e-8 (RK4's drift off g g* = 1)

constexpr bool energy_conserved(const trajectory_result& r) {
    return abs_of(r.final_energy - r.initial_energy) <= energy_tolerance * r.initial_energy;
}
constexpr bool unit(const trajectory_result& r, double tolerance) {
    return abs_of(r.defect.alpha_norm) <= tolerance && abs_of(r.defect.alpha_beta) <= tolerance;
}

static_assert(at_compile_time.ok && at_compile_time.steps == steps, "the run completes");
static_assert(energy_conserved(at_compile_time),
              "the free body's kinetic energy is conserved to 1e-7 (relative) over 48 RK4 steps");
static_assert(unit(at_compile_time, unit_tolerance), "the final motor is unit (|α|² − 1 and α·β within 1e-15)");
static_assert(plain_at_compile_time.ok && plain_at_compile_time.steps == steps, "the run completes");
static_assert(energy_conserved(plain_at_compile_time), "the same without renormalisation");
static_assert(unit(plain_at_compile_time, plain_unit_tolerance),
              "without renormalisation the motor drifts off g g* = 1 by RK4's truncation error only (1e-7)");

// Distance in units in the last place (0: the same bits; ±0 count as one apart).
long long ulps(double a, double b) {
    const auto ordered = [](double x) {
        const auto i = std::bit_cast<std::int64_t>(x);
        return i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i;
    };
    const std::int64_t d = ordered(a) - ordered(b);
    return d < 0 ? -d : d;
}

// The numbers of a result compared in ulps: the state and the energies (the unit defects are
// residuals near 0, where an ulp means nothing; they are printed as they are).
std::array<double, 16> numbers(const trajectory_result& r) {
    std::array<double, 16> out{};
    for (std::size_t i = 0; i < 8; ++i) out[i] = r.final_state.g[i];
    for (std::size_t i = 0; i < 6; ++i) out[8 + i] = r.final_state.s[i];
    out[14] = r.initial_energy, out[15] = r.final_energy;
    return out;
}

long long max_ulps(const trajectory_result& a, const trajectory_result& b) {
    const auto x = numbers(a), y = numbers(b);
    long long m = 0;
    for (std::size_t i = 0; i < x.size(); ++i) m = ulps(x[i], y[i]) > m ? ulps(x[i], y[i]) : m;
    return m;
}

}  // namespace

int main() {
    // Inputs the optimiser cannot fold: these calls are evaluated at run time.
    volatile double h_in = h;
    volatile long long steps_in = steps;
    const trajectory_result at_run_time = trajectory(ctga::rk4{}, h_in, steps_in);
    const trajectory_result plain_at_run_time = trajectory(ctga::rk4{.renormalize = false}, h_in, steps_in);

    std::printf("free asymmetric body, body frame, rk4, h = %g, %lld steps (t = %g)\n", h, steps,
                h * static_cast<double>(steps));
    std::printf("%-10s %-24s %-24s %s\n", "", "compile time", "run time", "ulps");
    const char* const names[16] = {"g[1]",   "g[e2e3]", "g[e3e1]", "g[e1e2]", "g[ee1e2e3]", "g[e1e]", "g[e2e]", "g[e3e]",
                                   "s[wx]",  "s[wy]",   "s[wz]",   "s[vx]",   "s[vy]",      "s[vz]",  "E(0)",   "E(t)"};
    const auto c = numbers(at_compile_time), r = numbers(at_run_time);
    for (std::size_t i = 0; i < c.size(); ++i)
        std::printf("%-10s %-24.17g %-24.17g %lld\n", names[i], c[i], r[i], ulps(c[i], r[i]));
    std::printf("%-10s %-24.3g %.3g\n", "|a|^2-1", at_compile_time.defect.alpha_norm, at_run_time.defect.alpha_norm);
    std::printf("%-10s %-24.3g %.3g\n", "a.b", at_compile_time.defect.alpha_beta, at_run_time.defect.alpha_beta);
    std::printf("relative energy change %.2e (static_assert: within %g)\n",
                (at_compile_time.final_energy - at_compile_time.initial_energy) / at_compile_time.initial_energy,
                energy_tolerance);

    const long long renormalised = max_ulps(at_compile_time, at_run_time);
    const long long plain = max_ulps(plain_at_compile_time, plain_at_run_time);
    const trajectory_result& p = plain_at_compile_time;
    std::printf("without renormalisation: E(t) %.17g, |a|^2-1 %.2e, a.b %.2e (identical at run time: %s)\n",
                p.final_energy, p.defect.alpha_norm, p.defect.alpha_beta,
                p.defect.alpha_norm == plain_at_run_time.defect.alpha_norm &&
                        p.defect.alpha_beta == plain_at_run_time.defect.alpha_beta
                    ? "yes"
                    : "no");
    std::printf("compile time vs run time, largest difference: %lld ulps renormalised, %lld ulps without\n",
                renormalised, plain);
    if (plain == 0 && renormalised == 0) std::puts("the compile-time and run-time trajectories are bit-identical");
    if (renormalised != 0)
        std::puts("the renormalised motor differs: renormalize's square root is Newton's iteration in constant\n"
                  "evaluation and std::sqrt at run time, and the two can round differently");
    return plain == 0 && at_run_time.ok && plain_at_run_time.ok ? 0 : 1;
}
