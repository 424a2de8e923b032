// Many bodies of one kind in structure-of-arrays layout (include/ctga/scenes/batch.hpp): the
// batch's RK4 step gives each body the states of ctga::integrate(ctga::rk4{}, body_motion, …),
// its branch-free square root is std::sqrt's correctly rounded result, its renormalisation is
// motor.hpp's, and a NaN or an infinity in one body is reported by the step.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include <ctga/ctga.hpp>
#include <ctga/scenes/batch.hpp>

#include "support/catch.hpp"

namespace {

using namespace ctga;
namespace sub = ctga::subspace;
namespace kind = ctga::inertia_kind;

template <class X>
double rel(const X& a, const X& b) {
    double d = 0, s = 1;
    for (std::size_t i = 0; i < X::size(); ++i) d = std::max(d, std::abs(a[i] - b[i])), s = std::max(s, std::abs(b[i]));
    return d / s;
}

// A random rigid motion (axis uniform on the sphere, angle in (−π, π), translation in a 4-box)
// and a random body-frame velocity, both narrowed to the subspace S.
template <class S>
motion_state<typename S::template motor_type<double>, typename S::template screw_type<double>> random_state(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::normal_distribution<double> n;
    double ax = n(rng), ay = n(rng), az = n(rng);
    const double len = std::sqrt(ax * ax + ay * ay + az * az);
    ax /= len, ay /= len, az /= len;
    const double angle = 3.1 * u(rng);
    double tx = 2 * u(rng), ty = 2 * u(rng), tz = 2 * u(rng);
    screw<double> s{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
    if constexpr (std::is_same_v<S, sub::planar>) ax = ay = 0, az = 1, tz = 0;
    const motor<double> g = rigid_motion(make_translator(tx, ty, tz), make_rotor(angle, ax, ay, az));
    return {project<typename S::template motor_type<double>>(g), project<typename S::template screw_type<double>>(s)};
}

constexpr kind::diagonal::data<double> box{2.0, 2.0, 2.5, 3.0};  // m, dx, dy, dz

// 100 random bodies, 1000 steps of the batch against integrate(rk4{}, …) per body.
template <class S, batch_renormalization R>
void same_as_rk4(const char* name) {
    constexpr std::size_t bodies = 100;
    constexpr double h = 0.01;
    constexpr long long steps = 1000;
    using batch_t = batch<double, S, kind::diagonal, 128, R>;
    auto b = std::make_unique<batch_t>(box);
    std::mt19937_64 rng(20240611);
    std::vector<typename batch_t::state_type> start;
    for (std::size_t i = 0; i < bodies; ++i) {
        start.push_back(random_state<S>(rng));
        REQUIRE(b->add(start.back()));
    }
    REQUIRE(b->size() == bodies);
    for (long long k = 0; k < steps; ++k) REQUIRE(b->step_rk4(h) == error_code::none);

    const body_motion<double, S, kind::diagonal> model{box};
    double worst = 0;
    std::size_t identical = 0;
    for (std::size_t i = 0; i < bodies; ++i) {
        const auto run = integrate(rk4{}, model, start[i], h, steps);
        REQUIRE(run);
        const double e = std::max(rel(b->pose(i), run.state.g), rel(b->velocity(i), run.state.s));
        worst = std::max(worst, e);
        identical += e == 0;
        CHECK(e <= 1e-13);
    }
    std::printf("batch %-14s %zu bodies, %lld steps: worst difference from rk4 %.2e (%zu bodies bit-identical)\n",
                name, bodies, steps, worst, identical);
}

static_assert(batch_detail::rsqrt_steps<float> == 3 && batch_detail::rsqrt_steps<double> == 3 &&
              batch_detail::rsqrt_steps<long double> == 4);

// In constant evaluation too, the batch's step is rk4's (both take motor.hpp's √ there).
constexpr bool constexpr_step_is_rk4 = [] {
    const motor<double> g{0.9, 0.1, -0.2, 0.3, 0.05, 0.5, -0.1, 0.1};  // drifted: renormalisation matters
    const screw<double> s{0.3, 1.0, -0.4, 0.2, -0.1, 0.5};
    batch<double, sub::full, kind::diagonal, 3> b{box};
    b.add(g, s);
    if (b.step_rk4(0.01) != error_code::none) return false;
    const auto one = rk4{}.step(body_motion<double, sub::full, kind::diagonal>{box}, {g, s}, 0.01).value;
    for (std::size_t c = 0; c < 8; ++c)
        if (b.pose(0)[c] != one.g[c]) return false;
    for (std::size_t c = 0; c < 6; ++c)
        if (b.velocity(0)[c] != one.s[c]) return false;
    return true;
}();
static_assert(constexpr_step_is_rk4);

}  // namespace

TEST_CASE("the SoA batch gives every body the states of integrate(rk4{}, body_motion)", "[scenes][batch]") {
    same_as_rk4<sub::full, batch_renormalization::exact>("full");
    same_as_rk4<sub::planar, batch_renormalization::exact>("planar");
    same_as_rk4<sub::full, batch_renormalization::fast>("full, fast");
    same_as_rk4<sub::planar, batch_renormalization::fast>("planar, fast");
}

TEST_CASE("the batch's square root on [1, 4] is std::sqrt's, bit for bit", "[scenes][batch]") {
    using batch_detail::sqrt_1_4;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(1.0, 4.0);
    long long wrong = 0;
    for (int i = 0; i < 1'000'000; ++i) {
        const double x = u(rng);
        wrong += sqrt_1_4(x) != std::sqrt(x);
    }
    // the hardest cases: x next to the square of a midpoint between two doubles in [1, 2]
    std::uniform_int_distribution<std::uint64_t> mantissa(0, (std::uint64_t(1) << 52) - 1);
    for (int i = 0; i < 1'000'000; ++i) {
        const double y = std::ldexp(double((std::uint64_t(1) << 52) + mantissa(rng)), -52);  // in [1, 2)
        const long double mid = static_cast<long double>(y) + std::ldexp(0.5L, -52);         // y + u/2, exact
        double x = static_cast<double>(mid * mid);                                           // next to mid²
        for (int k = 0; k < 3; ++k) {
            if (x >= 1.0 && x <= 4.0) wrong += sqrt_1_4(x) != std::sqrt(x);
            x = std::nextafter(x, 5.0);
        }
        x = std::nextafter(x, 0.0);
        for (int k = 0; k < 5; ++k, x = std::nextafter(x, 0.0))
            if (x >= 1.0 && x <= 4.0) wrong += sqrt_1_4(x) != std::sqrt(x);
    }
    for (double x : {1.0, std::nextafter(1.0, 2.0), 2.0, std::nextafter(2.0, 0.0), std::nextafter(2.0, 4.0), 3.0,
                     std::nextafter(4.0, 0.0), 4.0})
        wrong += sqrt_1_4(x) != std::sqrt(x);
    CHECK(wrong == 0);
    // the closest any x in [1, 4] comes to the square of a midpoint y + u/2 (u = 2⁻⁵²): with
    // y = Y u and x = X u, X 2⁵² = Y² + Y + c for a small even c (solutions of the congruence
    // Y² + Y + c ≡ 0 mod 2⁵², by Hensel lifting), so x − (y + u/2)² = (c − ¼) u². A faithful
    // rounding gets 6 of these 21 wrong; the exact tests of sqrt_1_4's last step get them all.
    long long hardest = 0;
    for (double x : {0x1.0000000000007p+0, 0x1.ffffffffffff9p+1, 0x1.283741a1bef08p+0, 0x1.77483d37ce205p+1,
                     0x1.a881d1831fabdp+0, 0x1.0000000000005p+0, 0x1.ffffffffffffbp+1, 0x1.256565cadcbf4p+0,
                     0x1.0000000000003p+0, 0x1.ffffffffffffdp+1, 0x1.0000000000001p+0, 0x1.fffffffffffffp+1,
                     0x1.5b95344972fe2p+1, 0x1.d407bb3641da5p+0, 0x1.2b035c1197f48p+0, 0x1.4eb5f85e783a9p+1,
                     0x1.e99893042c2cbp+0, 0x1.ba44c2a0737a2p+0, 0x1.270ac7cec9d2ap+0, 0x1.8444088dbdcb5p+1,
                     0x1.955d8279a3c0fp+0})
        hardest += sqrt_1_4(x) != std::sqrt(x);
    CHECK(hardest == 0);
    CHECK(std::isnan(sqrt_1_4(std::numeric_limits<double>::quiet_NaN())));
    // float: exhaustively over [1, 4]
    long long wrong_float = 0;
    for (float x = 1.0f; x <= 4.0f; x = std::nextafter(x, 5.0f)) wrong_float += sqrt_1_4(x) != std::sqrt(x);
    CHECK(wrong_float == 0);
}

// Where the target has fused multiply-adds GCC contracts a·b + c into them by default, and may do
// so differently in renormalize and in the batch's renormalizer: then they agree to rounding.
#if defined(__FP_FAST_FMA)
constexpr double contraction_tolerance = 4 * std::numeric_limits<double>::epsilon();
#else
constexpr double contraction_tolerance = 0;
#endif

TEST_CASE("the batch's branch-free renormalisation is motor.hpp's renormalize", "[scenes][batch]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double worst = 0;
    for (int i = 0; i < 100'000; ++i) {
        // a rigid motion, scaled, with drift in every component (sizes from 1e-3 to 1e3)
        const motor<double> g = random_state<sub::full>(rng).g;
        const double scale = std::pow(10.0, 3 * u(rng));
        motor<double> drifted;
        for (std::size_t c = 0; c < 8; ++c) drifted[c] = scale * (g[c] + 1e-3 * u(rng));
        worst = std::max(worst, rel(batch_detail::renormalize_unguarded(drifted), renormalize(drifted)));
    }
    CHECK(worst <= contraction_tolerance);  // without contraction: bit for bit
    // the fast variant: within a few ulps
    double worst_fast = 0;
    for (int i = 0; i < 100'000; ++i) {
        const motor<double> g = random_state<sub::full>(rng).g;
        const double scale = std::pow(10.0, 3 * u(rng));
        motor<double> drifted;
        for (std::size_t c = 0; c < 8; ++c) drifted[c] = scale * (g[c] + 1e-3 * u(rng));
        const motor<double> a = batch_detail::renormalize_unguarded<batch_renormalization::fast>(drifted);
        worst_fast = std::max(worst_fast, rel(a, renormalize(drifted)));
    }
    std::printf("fast renormalisation: worst difference from renormalize %.2e\n", worst_fast);
    CHECK(worst_fast <= 8 * std::numeric_limits<double>::epsilon());
    // a subspace motor: the same as the model's renormalize (project ∘ renormalize ∘ full motor)
    using planar_motor = sub::planar::motor_type<double>;
    const body_motion<double, sub::planar, kind::diagonal> planar{box};
    for (int i = 0; i < 10'000; ++i) {
        const planar_motor g = random_state<sub::planar>(rng).g;
        const planar_motor drifted{1.01 * g[0], 0.98 * g[1], g[2] + 1e-3, g[3] - 2e-3};
        CHECK(rel(batch_detail::renormalize_unguarded(drifted), planar.renormalize(drifted)) <= contraction_tolerance);
    }
}

namespace {

template <batch_renormalization R>
void reports_non_finite() {
    using batch_t = batch<double, sub::full, kind::diagonal, 64, R>;
    auto b = std::make_unique<batch_t>(box);
    std::mt19937_64 rng(3);
    for (int i = 0; i < 50; ++i) REQUIRE(b->add(random_state<sub::full>(rng)));
    REQUIRE(b->step_rk4(0.01) == error_code::none);
    REQUIRE(b->first_non_finite() == b->size());

    const batch_t before = *b;
    CHECK(b->step_rk4(std::numeric_limits<double>::quiet_NaN()) == error_code::non_finite);  // nothing stepped
    CHECK(rel(b->pose(0), before.pose(0)) == 0);

    // a NaN in body 37's velocity: reported after the step, and the other bodies are stepped
    const body_motion<double, sub::full, kind::diagonal> model{box};
    screw<double> s = b->velocity(37);
    s[4] = std::numeric_limits<double>::quiet_NaN();
    b->set(37, b->pose(37), s);
    CHECK(b->step_rk4(0.01) == error_code::non_finite);
    CHECK(b->first_non_finite() == 37);
    for (std::size_t i : {std::size_t(0), std::size_t(36), std::size_t(38), std::size_t(49)}) {
        const auto one = rk4{}.step(model, before.state(i), 0.01);
        CHECK(rel(b->pose(i), one.value.g) <= 1e-15);
        CHECK(rel(b->velocity(i), one.value.s) <= 1e-15);
    }
    CHECK(b->step_rk4(0.01) == error_code::non_finite);  // it stays non-finite

    // an infinity in a motor, and a motor with no rotation part (α = 0: not a motor)
    *b = before;
    motor<double> g = b->pose(5);
    g[6] = std::numeric_limits<double>::infinity();
    b->set(5, g, b->velocity(5));
    CHECK(b->step_rk4(0.01) == error_code::non_finite);
    CHECK(b->first_non_finite() == 5);
    *b = before;
    b->set(9, motor<double>{0, 0, 0, 0, 0.1, 0.2, 0.3, 0.4}, screw<double>{});
    CHECK(b->step_rk4(0.01) == error_code::non_finite);
    CHECK(b->first_non_finite() == 9);
}

}  // namespace

TEST_CASE("a NaN or an infinity in one body is reported by the batch's step", "[scenes][batch]") {
    reports_non_finite<batch_renormalization::exact>();
    reports_non_finite<batch_renormalization::fast>();
}

TEST_CASE("a batch of several blocks (and a partial one) steps every body", "[scenes][batch]") {
    using batch_t = batch<double, sub::full, kind::diagonal, 1024>;
    const auto b = std::make_unique<batch_t>(box);
    std::mt19937_64 rng(17);
    std::vector<batch_t::state_type> x;
    for (int i = 0; i < 701; ++i) {
        x.push_back(random_state<sub::full>(rng));
        REQUIRE(b->add(x.back()));
    }
    const body_motion<double, sub::full, kind::diagonal> model{box};
    for (int k = 0; k < 10; ++k) {
        REQUIRE(b->step_rk4(0.01) == error_code::none);
        for (auto& y : x) y = rk4{}.step(model, y, 0.01).value;
    }
    double worst = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
        worst = std::max({worst, rel(b->pose(i), x[i].g), rel(b->velocity(i), x[i].s)});
    CHECK(worst <= 1e-15);
}

TEST_CASE("a batch holds at most its capacity; the AoS reference steps like rk4", "[scenes][batch]") {
    batch<double, sub::planar, kind::diagonal, 3> b{box};
    std::mt19937_64 rng(5);
    const auto x = random_state<sub::planar>(rng);
    CHECK(b.add(x));
    CHECK(b.add(x));
    CHECK(b.add(x));
    CHECK_FALSE(b.add(x));
    CHECK(b.size() == 3);
    CHECK(rel(b.pose(2), x.g) == 0);
    CHECK(rel(b.velocity(2), x.s) == 0);

    using model_t = body_motion<double, sub::planar, kind::diagonal>;
    const model_t model{box};
    std::array<state_of<model_t>, 3> states{x, x, x};
    CHECK(aos_step_rk4(model, states, 0.01) == error_code::none);
    const auto one = rk4{}.step(model, x, 0.01);
    CHECK(rel(states[1].g, one.value.g) == 0);
    CHECK(rel(states[1].s, one.value.s) == 0);
    states[2].s[0] = std::numeric_limits<double>::quiet_NaN();
    CHECK(aos_step_rk4(model, states, 0.01) == error_code::non_finite);
}
