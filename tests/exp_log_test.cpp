// §3 of the paper, numerically: the exponential map g = e^{z/2} in closed form against its
// series, the velocity relations dg/dt = ½ s g, exp/log round trips over the whole range of
// angles (θ ∈ [0, π], both ends included) and translations up to 1e6, renormalisation of
// drifted motors, and homogeneous 4×4 matrices (validated, Shepperd's method) against g s g* = H s.
//
// Error measure of the round trips (stated once, used everywhere below): for a result x and the
// reference y of the same type, rel(x, y) = max_i |x_i − y_i| / max(1, max_i |y_i|), the largest
// component error relative to the largest component (or absolute when all are below 1).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <ctga/ctga.hpp>
#include <ctga/mechanics/motor.hpp>

#include "support/catch.hpp"
#include "support/general_reference.hpp"

// Calls on plain numbers stay std's under both using-directives: ctga::exp and ctga::log take
// ctga types only, so they are not viable for a double (and calls on screws find ctga's).
namespace both_namespaces {
using namespace std;
using namespace ctga;
inline double exp_of_number(double x) { return exp(x); }
inline double log_of_number(double x) { return log(x); }
inline float log_of_float(float x) { return log(x); }
inline motor<double> exp_of_screw(const screw<double>& z) { return exp(z); }
inline screw<double> log_of_motor(const motor<double>& g) { return log(g); }
}  // namespace both_namespaces

namespace {

using namespace ctga;
using ld = long double;

constexpr double pi = 3.14159265358979323846;

using ctga::test::rel;  // support/general_reference.hpp
// Against g or −g, the same rigid motion.
template <class X, class Y>
double rel_pm(const X& x, const Y& y) {
    Y minus_y = y;
    for (std::size_t i = 0; i < Y::size(); ++i) minus_y[i] = -y[i];
    return std::min(rel(x, y), rel(x, minus_y));
}

template <class To, class From>
To cast(const From& x) {
    To out;
    for (std::size_t i = 0; i < From::size(); ++i) out[i] = static_cast<typename To::scalar_type>(x[i]);
    return out;
}

template <class T, class Rng>
std::array<T, 3> random_unit(Rng& rng) {
    std::normal_distribution<double> n(0, 1);
    for (;;) {
        const double x = n(rng), y = n(rng), z = n(rng), r = std::sqrt(x * x + y * y + z * z);
        if (r > 1e-3) return {T(x / r), T(y / r), T(z / r)};
    }
}

template <class T>
screw<T> make_screw(const std::array<T, 3>& w, const std::array<T, 3>& v) {
    return screw<T>{w[0], w[1], w[2], v[0], v[1], v[2]};
}

// 1 + z/2 + (z/2)²/2! + … with the library's geometric product, in long double.
motor<ld> exp_series(const screw<ld>& z, int terms = 80) {
    const screw<ld> h{z[0] / 2, z[1] / 2, z[2] / 2, z[3] / 2, z[4] / 2, z[5] / 2};
    motor<ld> term{1.0L, 0.0L, 0.0L, 0.0L, 0.0L, 0.0L, 0.0L, 0.0L};
    motor<ld> sum = term;
    for (int k = 1; k <= terms; ++k) {
        const motor<ld> next = term * h;
        for (std::size_t i = 0; i < motor<ld>::size(); ++i) term[i] = next[i] / static_cast<ld>(k);
        sum = sum + term;
    }
    return sum;
}

// The paper's Lie bracket [s1, s2] = ½(s1 s2 − s2 s1); as a formula, the normal form sees the
// scalar and grade-4 parts cancel, so the result is a screw.
constexpr auto lie = formula([](auto a, auto b) { return half * (a * b - b * a); });

template <class T>
screw<T> axpy(const T& a, const screw<T>& x, const screw<T>& y) {
    screw<T> out;
    for (std::size_t i = 0; i < 6; ++i) out[i] = a * x[i] + y[i];
    return out;
}
template <class T>
screw<T> scaled(const T& a, const screw<T>& x) {
    return axpy(a, x, screw<T>{});
}

// Richardson-extrapolated central difference of a motor-valued function at t (error O(h⁴)).
template <class F>
motor<ld> derivative(const F& g, ld t, ld h) {
    motor<ld> out;
    const motor<ld> a = g(t + h), b = g(t - h), c = g(t + h / 2), d = g(t - h / 2);
    for (std::size_t i = 0; i < 8; ++i) {
        const ld coarse = (a[i] - b[i]) / (2 * h), fine = (c[i] - d[i]) / h;
        out[i] = (4 * fine - coarse) / 3;
    }
    return out;
}

TEST_CASE("§3 g = e^{z/2}: the closed form agrees with the series 1 + z/2 + (z/2)²/2 + …",
          "[mechanics][exp_log]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1), angle(0, 6);
    double worst_double = 0, worst_long = 0, worst_float = 0;
    for (int trial = 0; trial < 300; ++trial) {
        // |ω| = θ up to 6 (beyond π, the series does not care), |v| up to about 5
        const auto axis = random_unit<double>(rng);
        const double theta = trial < 20 ? 1e-3 * trial : angle(rng);
        const screw<double> z =
            make_screw<double>({theta * axis[0], theta * axis[1], theta * axis[2]}, {3 * u(rng), 3 * u(rng), 3 * u(rng)});
        const motor<ld> reference = exp_series(cast<screw<ld>>(z));
        worst_double = std::max(worst_double, rel(ctga::exp(z), reference));
        worst_long = std::max(worst_long, rel(ctga::exp(cast<screw<ld>>(z)), reference));
        worst_float = std::max(worst_float, rel(ctga::exp(cast<screw<float>>(z)), reference));
    }
    WARN("exp vs series, worst rel: double " << worst_double << ", long double " << worst_long << ", float "
                                             << worst_float);
    CHECK(worst_double <= 1e-14);
    CHECK(worst_long <= 1e-17);
    CHECK(worst_float <= 1e-5);

    // the closed form is the motor of §3: a pure rotation is the rotor, a pure translation the
    // translator (exactly), and g g* = 1
    const motor<double> rot = ctga::exp(make_screw<double>({0, 0, pi / 2}, {0, 0, 0}));
    const motor<double> r = make_rotor(pi / 2, 0.0, 0.0, 1.0);
    CHECK(rel(rot, r) <= 1e-16);
    const motor<double> tr = ctga::exp(make_screw<double>({0, 0, 0}, {1.5, -2.25, 1e6}));
    CHECK(tr == motor<double>(make_translator(1.5, -2.25, 1e6)));
    const motor_defect<double> d = unit_defect(ctga::exp(make_screw<double>({0.3, -1.2, 2.0}, {4, 5, 6})));
    CHECK(std::fabs(d.alpha_norm) <= 1e-15);
    CHECK(std::fabs(d.alpha_beta) <= 1e-15);
}

TEST_CASE("§3 dg/dt = ½ s0 g for the uniform motion g = e^{t s0/2}", "[mechanics][exp_log]") {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(-1, 1);
    double worst = 0;
    for (int trial = 0; trial < 50; ++trial) {
        const screw<ld> s0{u(rng) * 2, u(rng) * 2, u(rng) * 2, u(rng) * 2, u(rng) * 2, u(rng) * 2};
        const ld t = 3 * u(rng);
        const auto g = [&](ld tau) { return ctga::exp(scaled(tau, s0)); };
        const motor<ld> rate = derivative(g, t, 2e-4L);
        const motor<ld> expected = half * s0 * g(t);
        worst = std::max(worst, rel(rate, expected));
    }
    // truncation O(h⁴) ≈ 1e-15 and rounding ε_ld/h ≈ 1e-15 at h = 2e-4
    WARN("dg/dt vs ½ s0 g (Richardson central difference, h = 2e-4), worst rel: " << worst);
    CHECK(worst <= 1e-13);
}

TEST_CASE("§3 the velocity series s = Σ ad^i(z) ż/(i+1)! gives dg/dt = ½ s g for g = e^{z(t)/2}",
          "[mechanics][exp_log]") {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(-1, 1);
    double worst = 0, least_gap = 1e300;
    for (int trial = 0; trial < 50; ++trial) {
        // z(t) = z0 + t z1 + t² z2 + sin(t) z3: a non-uniform motion whose z and ż do not commute
        std::array<screw<ld>, 4> c;
        for (auto& zi : c)
            for (std::size_t i = 0; i < 6; ++i) zi[i] = u(rng);
        const auto z = [&](ld t) { return axpy(std::sin(t), c[3], axpy(t * t, c[2], axpy(t, c[1], c[0]))); };
        const auto z_dot = [&](ld t) { return axpy(std::cos(t), c[3], axpy(2 * t, c[2], c[1])); };
        const ld t = u(rng);

        // s = Σ_{i≥0} ad^i(z) ż / (i+1)!, ad(z) y = [z, y]
        const screw<ld> zt = z(t);
        screw<ld> term = z_dot(t), s = term;
        for (int i = 1; i <= 60; ++i) {
            const screw<ld> next = lie(zt, term);
            term = scaled(1.0L / static_cast<ld>(i + 1), next);
            s = axpy(1.0L, term, s);
        }
        const auto g = [&](ld tau) { return ctga::exp(z(tau)); };
        const motor<ld> rate = derivative(g, t, 2e-4L);
        const motor<ld> expected = half * s * g(t);
        worst = std::max(worst, rel(rate, expected));
        least_gap = std::min(least_gap, rel(s, z_dot(t)));  // the series is not just ż
    }
    WARN("dg/dt vs ½ s g with the ad series (Richardson central difference, h = 2e-4), worst rel: " << worst);
    CHECK(worst <= 1e-13);
    CHECK(least_gap > 1e-2);
}

// The angles of the round trips: exact 0; log-spaced in [1e-12, 1]; π − δ with δ log-spaced
// in [1e-9, 1]; uniform in [1, π − 1].
std::vector<double> round_trip_angles() {
    std::vector<double> a{0.0};
    for (int i = 0; i <= 120; ++i) a.push_back(std::pow(10.0, -12.0 + 12.0 * i / 120));
    for (int i = 0; i <= 90; ++i) a.push_back(pi - std::pow(10.0, -9.0 + 9.0 * i / 90));
    for (int i = 1; i < 60; ++i) a.push_back(1.0 + (pi - 2.0) * i / 60);
    return a;
}
// Translation sizes: 0 (pure rotation) and 1e-6 … 1e6.
constexpr std::array<double, 8> magnitudes{0.0, 1e-6, 1e-3, 1e-1, 1.0, 1e2, 1e4, 1e6};

struct range_worst {
    double near_zero = 0, middle = 0, near_pi = 0;
    void add(double theta, double err) {
        double& w = theta < 1e-3 ? near_zero : (theta > pi - 1e-3 ? near_pi : middle);
        w = std::max(w, err);
    }
    [[nodiscard]] double all() const { return std::max({near_zero, middle, near_pi}); }
};

// Every round-trip case: each angle of round_trip_angles() with each magnitude, three random
// axis/direction pairs each; f(θ, |t|, axis, direction). Returns the number of cases.
template <class F>
int for_each_round_trip_case(std::uint64_t seed, F f) {
    std::mt19937_64 rng(seed);
    int cases = 0;
    for (const double theta : round_trip_angles())
        for (const double size : magnitudes)
            for (int rep = 0; rep < 3; ++rep, ++cases) {
                const auto axis = random_unit<double>(rng);
                f(theta, size, axis, random_unit<double>(rng));
            }
    return cases;
}

TEST_CASE("§3 exp(log(±g)) = g for motors g = t r, θ ∈ [0, π − 1e-9], |t| ≤ 1e6", "[mechanics][exp_log]") {
    range_worst worst;
    const int samples = for_each_round_trip_case(14, [&](double theta, double size, const auto& axis, const auto& dir) {
                const motor<double> g = rigid_motion(make_translator(size * dir[0], size * dir[1], size * dir[2]),
                                                     make_rotor(theta, axis[0], axis[1], axis[2]));
                worst.add(theta, rel(ctga::exp(ctga::log(g)), g));
                // −g is the same motion; log flips it to α0 ≥ 0 and exp returns g
                motor<double> minus_g = g;
                for (std::size_t i = 0; i < 8; ++i) minus_g[i] = -g[i];
                worst.add(theta, rel(ctga::exp(ctga::log(minus_g)), g));
            });
    WARN("exp(log(±g)) = g over " << samples << " motors, worst rel: θ < 1e-3: " << worst.near_zero
                                 << ", 1e-3 ≤ θ ≤ π − 1e-3: " << worst.middle << ", θ > π − 1e-3: " << worst.near_pi);
    CHECK(worst.all() <= 1e-14);
}

TEST_CASE("§3 log(exp(z)) = z for screws with |ω| = θ ∈ [0, π − 1e-9], |v| ≤ 1e6", "[mechanics][exp_log]") {
    range_worst worst, worst_omega;
    const int samples = for_each_round_trip_case(15, [&](double theta, double size, const auto& axis, const auto& dir) {
                const screw<double> z = make_screw<double>({theta * axis[0], theta * axis[1], theta * axis[2]},
                                                           {size * dir[0], size * dir[1], size * dir[2]});
                const screw<double> back = ctga::log(ctga::exp(z));
                worst.add(theta, rel(back, z));
                // the stricter measure on ω alone (not diluted by |v|)
                const screw<double> w{z[0], z[1], z[2], 0, 0, 0}, wb{back[0], back[1], back[2], 0, 0, 0};
                worst_omega.add(theta, rel(wb, w));
            });
    WARN("log(exp(z)) = z over " << samples << " screws, worst rel: θ < 1e-3: " << worst.near_zero
                                 << ", middle: " << worst.middle << ", θ > π − 1e-3: " << worst.near_pi
                                 << "; ω part alone: " << worst_omega.all());
    CHECK(worst.all() <= 1e-14);
    CHECK(worst_omega.all() <= 1e-14);
}

TEST_CASE("§3 exp and log: exact cases, the sign of g, θ = π, float and long double", "[mechanics][exp_log]") {
    // pure translations, both ways, exactly
    const screw<double> v{0, 0, 0, 1e6, -3.5, 1e-300};
    CHECK(ctga::exp(v) == motor<double>(make_translator(1e6, -3.5, 1e-300)));
    CHECK(ctga::log(ctga::exp(v)) == v);
    CHECK(ctga::log(motor<double>{1, 0, 0, 0, 0, 0, 0, 0}) == screw<double>{});
    CHECK(ctga::exp(screw<double>{}) == motor<double>{1, 0, 0, 0, 0, 0, 0, 0});

    // g and −g: log picks θ ∈ [0, π]; a rotation by 3π/2 comes back as −π/2
    const motor<double> g = rigid_motion(make_translator(1.0, 2.0, 3.0), make_rotor(1.5 * pi, 0.0, 0.0, 1.0));
    REQUIRE(g[0] < 0);
    const screw<double> z = ctga::log(g);
    CHECK(z[2] == Approx(-pi / 2).epsilon(1e-15));
    CHECK(rel(ctga::exp(z), g) > 1);  // exp(log g) = −g …
    CHECK(rel_pm(ctga::exp(z), g) <= 1e-15);
    const screw<double> moved = adjoint(ctga::exp(z), screw<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6});
    CHECK(rel(moved, screw<double>(adjoint(g, screw<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6}))) <= 1e-15);  // … same motion

    // θ = π exactly (α0 = 0): finite, and back
    const motor<double> h = renormalize(motor<double>{0.0, 0.0, 0.6, 0.8, -0.4, 0.7, 0.3, 0.0});  // α·β made 0
    REQUIRE(h[0] == 0);
    const screw<double> zh = ctga::log(h);
    CHECK(std::hypot(zh[0], zh[1], zh[2]) == Approx(pi).epsilon(1e-15));
    CHECK(rel_pm(ctga::exp(zh), h) <= 1e-15);

    // other scalar types
    std::mt19937_64 rng(16);
    std::uniform_real_distribution<double> u(-1, 1);
    double worst_float = 0, worst_long = 0;
    for (int trial = 0; trial < 500; ++trial) {
        const auto axis = random_unit<double>(rng);
        const double theta = trial % 2 ? pi * (1 + u(rng)) / 2 : std::pow(10.0, -12 * (1 + u(rng)) / 2);
        const screw<double> zd =
            make_screw<double>({theta * axis[0], theta * axis[1], theta * axis[2]}, {10 * u(rng), 10 * u(rng), 10 * u(rng)});
        const auto zf = cast<screw<float>>(zd);
        const auto zl = cast<screw<ld>>(zd);
        worst_float = std::max({worst_float, rel(ctga::log(ctga::exp(zf)), zf)});
        worst_long = std::max({worst_long, rel(ctga::log(ctga::exp(zl)), zl)});
        const motor<ld> gl = ctga::exp(zl);
        worst_long = std::max(worst_long, rel(ctga::exp(ctga::log(gl)), gl));
    }
    WARN("log(exp(z)) worst rel: float " << worst_float << ", long double " << worst_long);
    CHECK(worst_float <= 1e-5);
    CHECK(worst_long <= 1e-17);

    // the using-directive namespace: std for numbers, ctga for screws
    CHECK(both_namespaces::exp_of_number(1.0) == std::exp(1.0));
    CHECK(both_namespaces::log_of_number(2.0) == std::log(2.0));
    CHECK(both_namespaces::log_of_float(2.0f) == std::log(2.0f));
    const screw<double> zz{0.1, 0.2, 0.3, 1, 2, 3};
    CHECK(both_namespaces::log_of_motor(both_namespaces::exp_of_screw(zz)) == ctga::log(ctga::exp(zz)));
}

TEST_CASE("§3 inverse(g) = g* and unit_defect are the two relations of g g* = 1", "[mechanics][motion]") {
    static_assert(inverse(motor<double>{1, 2, 3, 4, 5, 6, 7, 8}) == conj(motor<double>{1, 2, 3, 4, 5, 6, 7, 8}));
    static_assert(unit_defect(motor<double>{0.6, 0.8, 0, 0, 0.8, -0.6, 3, 0}).alpha_norm == 0);
    static_assert(unit_defect(motor<double>{0.6, 0.8, 0, 0, 0.8, -0.6, 3, 0}).alpha_beta == 0);
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 100; ++trial) {
        const motor<double> g{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
        CHECK(inverse(g) == conj(g));
        const motor_defect<double> d = unit_defect(g);
        const auto gg = eval(g * conj(g));  // = (1 + alpha_norm) − 2 alpha_beta e1e2e3e
        CHECK(scalar_part(gg) - 1 == Approx(d.alpha_norm).margin(1e-15));
        CHECK(get<"e1e2e3e">(gg) == Approx(-2 * d.alpha_beta).margin(1e-15));
        const auto axis = random_unit<double>(rng);
        const motor<double> h = rigid_motion(make_translator(5 * u(rng), 5 * u(rng), 5 * u(rng)),
                                             make_rotor(3 * u(rng), axis[0], axis[1], axis[2]));
        CHECK(rel(motor<double>(h * inverse(h)), motor<double>{1, 0, 0, 0, 0, 0, 0, 0}) <= 1e-15);
    }
}

TEST_CASE("§3 renormalize: g g* = 1 restored to rounding, and no further than the drift", "[mechanics][motion]") {
    constexpr motor<double> scaled_motor = renormalize(motor<double>{2, 0, 0, 0, 1, 1, 0, 0});
    static_assert(scaled_motor == motor<double>{1, 0, 0, 0, 0, 0.5, 0, 0});

    std::mt19937_64 rng(18);
    std::uniform_real_distribution<double> u(-1, 1);
    double worst_norm = 0, worst_ab = 0, worst_alpha_move = 0, worst_beta_move = 0, worst_exact = 0, worst_scaled = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const auto axis = random_unit<double>(rng);
        const double size = std::pow(10.0, 3 * u(rng));  // |t| from 1e-3 to 1e3
        const auto dir = random_unit<double>(rng);
        const motor<double> g = rigid_motion(make_translator(size * dir[0], size * dir[1], size * dir[2]),
                                             make_rotor(pi * u(rng), axis[0], axis[1], axis[2]));
        motor<double> drifted = g;
        for (std::size_t i = 0; i < 8; ++i) drifted[i] += 1e-6 * u(rng);
        const motor<double> r = renormalize(drifted);
        const motor_defect<double> d = unit_defect(r);
        const double beta = std::sqrt(r[4] * r[4] + r[5] * r[5] + r[6] * r[6] + r[7] * r[7]);
        worst_norm = std::max(worst_norm, std::fabs(d.alpha_norm));
        worst_ab = std::max(worst_ab, std::fabs(d.alpha_beta) / std::max(1.0, beta));

        // The rotor part moves radially, by ||α̃| − 1| ≤ |α̃ − α| = its perturbation; the dual
        // part by at most its perturbation plus the lever arm 2|β̃||n_α| (removing (α̂·β̃)α̂ and
        // the scale |α̃|): any rigid motion near g̃ must turn β with α.
        double na = 0, nb = 0, ma = 0, mb = 0, bt = 0;
        for (std::size_t i = 0; i < 4; ++i) {
            na += (drifted[i] - g[i]) * (drifted[i] - g[i]);
            nb += (drifted[4 + i] - g[4 + i]) * (drifted[4 + i] - g[4 + i]);
            ma += (r[i] - drifted[i]) * (r[i] - drifted[i]);
            mb += (r[4 + i] - drifted[4 + i]) * (r[4 + i] - drifted[4 + i]);
            bt += drifted[4 + i] * drifted[4 + i];
        }
        na = std::sqrt(na), nb = std::sqrt(nb), ma = std::sqrt(ma), mb = std::sqrt(mb), bt = std::sqrt(bt);
        worst_alpha_move = std::max(worst_alpha_move, ma / na);
        worst_beta_move = std::max(worst_beta_move, mb / (nb + 2 * bt * na));

        // an exact motor stays (to rounding); λ g and (1 + ε μ) g come back to g
        worst_exact = std::max(worst_exact, rel(renormalize(g), g));
        motor<double> off = g;
        const double lambda = 1 + 0.5 * u(rng), mu = u(rng);
        for (std::size_t i = 0; i < 4; ++i) off[4 + i] = lambda * (g[4 + i] + mu * g[i]), off[i] = lambda * g[i];
        worst_scaled = std::max(worst_scaled, rel(renormalize(off), g));
    }
    WARN("renormalize after 1e-6 noise: |α·α − 1| ≤ " << worst_norm << ", |α0β0 + α·β|/max(1,|β|) ≤ " << worst_ab
                                                      << ", α moved/|n_α| ≤ " << worst_alpha_move
                                                      << ", β moved/(|n_β| + 2|β||n_α|) ≤ " << worst_beta_move
                                                      << "; exact motors moved " << worst_exact << ", λ(1+εμ)g → g "
                                                      << worst_scaled);
    CHECK(worst_norm <= 1e-15);
    CHECK(worst_ab <= 1e-15);
    CHECK(worst_alpha_move <= 1 + 1e-9);
    CHECK(worst_beta_move <= 1 + 1e-9);
    CHECK(worst_exact <= 1e-15);
    CHECK(worst_scaled <= 1e-14);

    // failures are reported, not returned as motors
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    CHECK(renormalize_checked(motor<double>{0, 0, 0, 0, 1, 2, 3, 4}).error == error_code::not_a_motor);
    CHECK(renormalize_checked(motor<double>{1, 0, 0, nan, 0, 0, 0, 0}).error == error_code::non_finite);
    CHECK(renormalize_checked(motor<double>{1, 0, 0, 0, 0, inf, 0, 0}).error == error_code::non_finite);
    CHECK(renormalize_checked(motor<double>{1e-300, 0, 0, 0, 1e300, 0, 0, 0}).error == error_code::not_a_motor);
    CHECK(renormalize_checked(motor<double>{1e-300, 1e-300, 0, 0, 0, 1e-300, 0, 0}));  // tiny but fine
    CHECK(renormalize_checked(motor<double>{1e300, 1e300, 0, 0, 0, 1e300, 0, 0}));     // huge but fine
    CHECK(std::string(describe(error_code::not_a_motor)).find("not a rigid motion") != std::string::npos);
}

// Rodrigues: the rotation matrix of angle θ about the unit axis u, independently of the rotor.
std::array<std::array<double, 3>, 3> rodrigues(const std::array<double, 3>& u, double theta) {
    const double c = std::cos(theta), s = std::sin(theta), k = 1 - c;
    return {{{c + u[0] * u[0] * k, u[0] * u[1] * k - u[2] * s, u[0] * u[2] * k + u[1] * s},
             {u[1] * u[0] * k + u[2] * s, c + u[1] * u[1] * k, u[1] * u[2] * k - u[0] * s},
             {u[2] * u[0] * k - u[1] * s, u[2] * u[1] * k + u[0] * s, c + u[2] * u[2] * k}}};
}

template <class T>
double matrix_rel(const homogeneous_matrix<T>& a, const homogeneous_matrix<T>& b) {
    double d = 0, m = 1;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            d = std::max(d, static_cast<double>(std::fabs(a[i][j] - b[i][j])));
            m = std::max(m, static_cast<double>(std::fabs(b[i][j])));
        }
    return d / m;
}

TEST_CASE("§2–3 homogeneous matrices: g = t r ↔ [R t, 0 1], round trips, and g s g* = H s", "[mechanics][motion]") {
    constexpr homogeneous_matrix<double> shift{{{1, 0, 0, 2}, {0, 1, 0, 4}, {0, 0, 1, 6}, {0, 0, 0, 1}}};
    static_assert(from_homogeneous(shift).value == motor<double>{1, 0, 0, 0, 0, 1, 2, 3});
    static_assert(to_homogeneous(motor<double>{1, 0, 0, 0, 0, 1, 2, 3}) == shift);

    std::mt19937_64 rng(19);
    std::uniform_real_distribution<double> u(-1, 1);
    double worst_motor = 0, worst_matrix = 0, worst_rodrigues = 0, worst_near_pi = 0, worst_h = 0, worst_compose = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        const auto axis = random_unit<double>(rng);
        // a quarter of the angles within 1e-12 … 1 of π, and exactly π; the rest uniform in [0, π]
        double theta = pi * (1 + u(rng)) / 2;
        if (trial % 4 == 0) theta = pi - std::pow(10.0, -6 * (1 + u(rng)));
        if (trial % 100 == 0) theta = pi;
        const double size = std::pow(10.0, 3 * u(rng));
        const auto dir = random_unit<double>(rng);
        const std::array<double, 3> t{size * dir[0], size * dir[1], size * dir[2]};
        const motor<double> g = rigid_motion(make_translator(t[0], t[1], t[2]), make_rotor(theta, axis[0], axis[1], axis[2]));

        const homogeneous_matrix<double> m = to_homogeneous(g);
        const auto R = rodrigues(axis, theta);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) worst_rodrigues = std::max(worst_rodrigues, std::fabs(m[i][j] - R[i][j]));
            worst_rodrigues = std::max(worst_rodrigues, std::fabs(m[i][3] - t[i]) / std::max(1.0, size));
        }
        const checked<motor<double>> back = from_homogeneous(m);
        REQUIRE(back);
        const double e = rel_pm(*back, g);
        worst_motor = std::max(worst_motor, e);
        if (theta > pi - 1e-3) worst_near_pi = std::max(worst_near_pi, e);
        worst_matrix = std::max(worst_matrix, matrix_rel(to_homogeneous(*back), m));

        // g s g* = H s with the 6×6 H = [[R, 0], [T R, R]] built from the matrix (§2)
        const screw<double> s{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
        const std::array<std::array<double, 3>, 3> T{
            {{0, -m[2][3], m[1][3]}, {m[2][3], 0, -m[0][3]}, {-m[1][3], m[0][3], 0}}};  // T x = t × x
        std::array<std::array<double, 6>, 6> H{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                H[i][j] = H[3 + i][3 + j] = m[i][j];
                for (int k = 0; k < 3; ++k) H[3 + i][j] += T[i][k] * m[k][j];
            }
        std::array<double, 6> hs{};
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) hs[i] += H[i][j] * s[j];
        const screw<double> moved = adjoint(g, s);
        for (std::size_t i = 0; i < 6; ++i)
            worst_h = std::max(worst_h, std::fabs(moved[i] - hs[i]) / std::max(1.0, size));

        // composition: the matrix of g h is the product of the matrices
        const auto axis2 = random_unit<double>(rng);
        const motor<double> h = rigid_motion(make_translator(u(rng), u(rng), u(rng)), make_rotor(3 * u(rng), axis2[0], axis2[1], axis2[2]));
        const homogeneous_matrix<double> mh = to_homogeneous(h);
        homogeneous_matrix<double> prod{};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                for (int k = 0; k < 4; ++k) prod[i][j] += m[i][k] * mh[k][j];
        worst_compose = std::max(worst_compose, matrix_rel(to_homogeneous(motor<double>(g * h)), prod));
    }
    WARN("homogeneous round trips over 1000 motors, worst rel: g → M → g " << worst_motor << " (θ > π − 1e-3: "
                                                                         << worst_near_pi << "), M → g → M " << worst_matrix
                                                                         << "; R vs Rodrigues, t " << worst_rodrigues
                                                                         << "; g s g* vs H s " << worst_h
                                                                         << "; composition " << worst_compose);
    CHECK(worst_motor <= 1e-14);
    CHECK(worst_matrix <= 1e-14);
    CHECK(worst_rodrigues <= 1e-14);
    CHECK(worst_h <= 1e-14);
    CHECK(worst_compose <= 1e-14);
}

TEST_CASE("from_homogeneous rejects what is not a rigid motion, with the reason", "[mechanics][motion]") {
    const homogeneous_matrix<double> ok = to_homogeneous(
        motor<double>(rigid_motion(make_translator(1.0, -2.0, 3.0), make_rotor(2.0, 0.0, 0.6, 0.8))));
    REQUIRE(from_homogeneous(ok));

    homogeneous_matrix<double> reflection = ok;
    for (int j = 0; j < 3; ++j) reflection[2][j] = -reflection[2][j];  // det −1, still orthonormal
    CHECK(from_homogeneous(reflection).error == error_code::not_a_rotation);

    homogeneous_matrix<double> sheared = ok;
    sheared[0][1] += 1e-6;
    CHECK(from_homogeneous(sheared).error == error_code::not_a_rotation);
    homogeneous_matrix<double> stretched = ok;
    for (int i = 0; i < 3; ++i) stretched[i][0] *= 1.001;
    CHECK(from_homogeneous(stretched).error == error_code::not_a_rotation);

    homogeneous_matrix<double> bottom = ok;
    bottom[3][0] = 0.5;
    CHECK(from_homogeneous(bottom).error == error_code::not_homogeneous);
    bottom = ok;
    bottom[3][3] = 2;
    CHECK(from_homogeneous(bottom).error == error_code::not_homogeneous);

    homogeneous_matrix<double> nan = ok;
    nan[1][2] = std::numeric_limits<double>::quiet_NaN();
    CHECK(from_homogeneous(nan).error == error_code::non_finite);
    homogeneous_matrix<double> inf = ok;
    inf[0][3] = std::numeric_limits<double>::infinity();
    CHECK(from_homogeneous(inf).error == error_code::non_finite);

    // the tolerance: 1e-12 off orthonormality passes (and is absorbed), 1e-8 does not
    homogeneous_matrix<double> close = ok;
    close[0][1] += 1e-12;
    const checked<motor<double>> near_ok = from_homogeneous(close);
    REQUIRE(near_ok);
    CHECK(std::fabs(unit_defect(*near_ok).alpha_norm) <= 1e-15);
    CHECK(std::fabs(unit_defect(*near_ok).alpha_beta) <= 1e-15);
    CHECK(matrix_rel(to_homogeneous(*near_ok), ok) <= 1e-12);
    homogeneous_matrix<double> far = ok;
    far[0][1] += 1e-8;
    CHECK(from_homogeneous(far).error == error_code::not_a_rotation);
    CHECK(from_homogeneous(far, 1e-7));  // an explicit, looser tolerance

    // float: its own tolerance (1024 ε), round trip at float precision
    const homogeneous_matrix<float> okf = to_homogeneous(cast<motor<float>>(*from_homogeneous(ok)));
    REQUIRE(from_homogeneous(okf));
    CHECK(matrix_rel(to_homogeneous(*from_homogeneous(okf)), okf) <= 1e-6);
    static_assert(homogeneous_tolerance<double> == 1e-9);
    static_assert(homogeneous_tolerance<float> == 1024 * std::numeric_limits<float>::epsilon());
}

}  // namespace

// ctga::math::cos_sin in constant evaluation (a reduced Taylor series: what the revolute joints
// and exp use when the compiler evaluates them) against std::cos and std::sin at run time.
TEST_CASE("math::cos_sin: constant evaluation agrees with std::cos and std::sin to a few ulps") {
    constexpr int n = 401;
    constexpr auto x_at = [](int i) { return -60.0 + 0.3 * i + 1e-3 * (i % 7); };
    constexpr auto table = [&] {
        std::array<ctga::math::cos_sin_pair<double>, n> out{};
        for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)] = ctga::math::cos_sin(x_at(i));
        return out;
    }();
    constexpr auto table_f = [&] {
        std::array<ctga::math::cos_sin_pair<float>, n> out{};
        for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)] = ctga::math::cos_sin(static_cast<float>(x_at(i)));
        return out;
    }();
    for (int i = 0; i < n; ++i) {
        const double x = x_at(i);
        const auto& cs = table[static_cast<std::size_t>(i)];
        INFO("x = " << x);
        CHECK(std::abs(cs.cos - std::cos(x)) <= 4e-16 * (1 + std::abs(x) / 8));
        CHECK(std::abs(cs.sin - std::sin(x)) <= 4e-16 * (1 + std::abs(x) / 8));
        const float xf = static_cast<float>(x);
        CHECK(std::abs(table_f[static_cast<std::size_t>(i)].cos - std::cos(xf)) <= 3e-7f * (1 + std::abs(xf) / 8));
        CHECK(std::abs(table_f[static_cast<std::size_t>(i)].sin - std::sin(xf)) <= 3e-7f * (1 + std::abs(xf) / 8));
    }
    static_assert(ctga::math::cos_sin(0.0).cos == 1.0 && ctga::math::cos_sin(0.0).sin == 0.0);
}
