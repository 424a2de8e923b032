// Many bodies of one kind (include/ctga/scenes/batch.hpp): structure-of-arrays storage stepped
// by rk4 on SIMD packs of bodies. Every body gets the states of ctga::integrate(ctga::rk4{},
// body_motion, …) for every lane count (the bodies past the last full pack, and every body in a
// constant expression, stepped with the scalar itself), body_cast broadcasts a body's data, and
// a NaN or an infinity in one body, in a pack or past it, is reported by the step.
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

// Where the target has fused multiply-adds GCC contracts a·b + c into them by default, and may do
// so differently in the pack code and the scalar code: then they agree to rounding.
#if defined(__FP_FAST_FMA) || defined(__FMA__)
constexpr bool bit_for_bit = false;
#else
constexpr bool bit_for_bit = true;
#endif

// 100 random bodies (100 = 12 packs of 8 + 4, 25 of 4, 50 of 2), 1000 steps of the batch against
// integrate(rk4{}, …) per body.
template <class S, class K, std::size_t Lanes>
void same_as_rk4(const char* name, const typename K::template data<double>& body) {
    constexpr std::size_t bodies = 100;
    constexpr double h = 0.01;
    constexpr long long steps = 1000;
    using batch_t = batch<double, S, K, 128, Lanes>;
    auto b = std::make_unique<batch_t>(body);
    std::mt19937_64 rng(20240611);
    std::vector<typename batch_t::state_type> start;
    for (std::size_t i = 0; i < bodies; ++i) {
        start.push_back(random_state<S>(rng));
        REQUIRE(b->add(start.back()));
    }
    REQUIRE(b->size() == bodies);
    for (long long k = 0; k < steps; ++k) REQUIRE(b->step_rk4(h) == error_code::none);

    const body_motion<double, S, K> model{body};
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
    if (bit_for_bit) CHECK(identical == bodies);
    std::printf("batch %-22s %zu lanes, %zu bodies, %lld steps: worst difference from rk4 %.2e (%zu bodies bit-identical)\n",
                name, Lanes, bodies, steps, worst, identical);
}

const kind::general::data<double> tilted = [] {  // a body with products of inertia and an offset centre of mass
    const mat3<double> I{{{0.9, 0.1, -0.05}, {0.1, 1.2, 0.02}, {-0.05, 0.02, 1.5}}};
    return *make_rigid_body(2.0, vec3<double>{0.1, -0.2, 0.05}, I);
}();

}  // namespace

TEST_CASE("the batch gives every body the states of integrate(rk4{}, body_motion), in packs of every width", "[scenes][batch]") {
    same_as_rk4<sub::full, kind::diagonal, 1>("full diagonal", box);
    same_as_rk4<sub::full, kind::diagonal, 2>("full diagonal", box);
    same_as_rk4<sub::full, kind::diagonal, 4>("full diagonal", box);
    same_as_rk4<sub::full, kind::diagonal, 8>("full diagonal", box);
    same_as_rk4<sub::planar, kind::diagonal, native_lanes<double>>("planar diagonal", box);
    same_as_rk4<sub::full, kind::general, 4>("full general", tilted);
    same_as_rk4<sub::full, kind::sphere, 8>("full sphere", kind::sphere::data<double>{3.0, 0.4});
}

TEST_CASE("body_cast broadcasts a body's numbers to every lane", "[scenes][batch]") {
    using P = pack<double, 4>;
    const kind::diagonal::data<P> b = inertia_kind::body_cast<P>(box);
    const kind::general::data<P> g = inertia_kind::body_cast<P>(tilted);
    for (std::size_t l = 0; l < 4; ++l) {
        for (std::size_t i = 0; i < 4; ++i) {
            CHECK(b.value(i)[0][l] == box.value(i)[0]);
            CHECK(b.reciprocal(i)[0][l] == box.reciprocal(i)[0]);
        }
        const auto lane = g.Mb.parameters();
        const auto one = tilted.Mb.parameters();
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            CHECK(((std::get<I>(lane)[0][l] == std::get<I>(one)[0]) && ...));
        }(std::make_index_sequence<std::tuple_size_v<decltype(one)>>{});
    }
}

// In constant evaluation every body is stepped with the scalar: rk4's numbers.
constexpr bool constexpr_step_is_rk4 = [] {
    const motor<double> g{0.9, 0.1, -0.2, 0.3, 0.05, 0.5, -0.1, 0.1};  // drifted: renormalisation matters
    const screw<double> s{0.3, 1.0, -0.4, 0.2, -0.1, 0.5};
    batch<double, sub::full, kind::diagonal, 3, 4> b{box};
    b.add(g, s);
    b.add(g, -s);
    if (b.step_rk4(0.01) != error_code::none) return false;
    const body_motion<double, sub::full, kind::diagonal> model{box};
    const auto one = rk4{}.step(model, {g, s}, 0.01).value;
    const auto two = rk4{}.step(model, {g, -s}, 0.01).value;
    for (std::size_t c = 0; c < 8; ++c)
        if (b.pose(0)[c] != one.g[c] || b.pose(1)[c] != two.g[c]) return false;
    for (std::size_t c = 0; c < 6; ++c)
        if (b.velocity(0)[c] != one.s[c] || b.velocity(1)[c] != two.s[c]) return false;
    return true;
}();
static_assert(constexpr_step_is_rk4);

namespace {

// 50 bodies: in 4 lanes bodies 0 … 47 in packs, 48 and 49 past them.
template <std::size_t Lanes>
void reports_non_finite() {
    using batch_t = batch<double, sub::full, kind::diagonal, 64, Lanes>;
    auto b = std::make_unique<batch_t>(box);
    std::mt19937_64 rng(3);
    for (int i = 0; i < 50; ++i) REQUIRE(b->add(random_state<sub::full>(rng)));
    REQUIRE(b->step_rk4(0.01) == error_code::none);
    REQUIRE(b->first_non_finite() == b->size());

    const batch_t before = *b;
    CHECK(b->step_rk4(std::numeric_limits<double>::quiet_NaN()) == error_code::non_finite);  // nothing stepped
    CHECK(rel(b->pose(0), before.pose(0)) == 0);

    // a NaN in one body's velocity (in a pack, past the packs): reported after the step, and the
    // other bodies are stepped, the poisoned body's pack-mates included
    const body_motion<double, sub::full, kind::diagonal> model{box};
    for (std::size_t poisoned : {std::size_t(37), std::size_t(49)}) {
        *b = before;
        screw<double> s = b->velocity(poisoned);
        s[4] = std::numeric_limits<double>::quiet_NaN();
        b->set(poisoned, b->pose(poisoned), s);
        CHECK(b->step_rk4(0.01) == error_code::non_finite);
        CHECK(b->first_non_finite() == poisoned);
        for (std::size_t i : {std::size_t(0), std::size_t(36), std::size_t(38), std::size_t(39), std::size_t(48)}) {
            if (i == poisoned) continue;
            const auto one = rk4{}.step(model, before.state(i), 0.01);
            CHECK(rel(b->pose(i), one.value.g) <= 1e-15);
            CHECK(rel(b->velocity(i), one.value.s) <= 1e-15);
        }
        CHECK(b->step_rk4(0.01) == error_code::non_finite);  // it stays non-finite
    }

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
    reports_non_finite<1>();
    reports_non_finite<4>();
    reports_non_finite<8>();
}

TEST_CASE("a float batch in 16 lanes steps like rk4 in float", "[scenes][batch]") {
    const kind::diagonal::data<float> body{2.0f, 2.0f, 2.5f, 3.0f};
    batch<float, sub::full, kind::diagonal, 40, 16> b{body};
    const body_motion<float, sub::full, kind::diagonal> model{body};
    std::mt19937_64 rng(23);
    std::vector<state_of<body_motion<float, sub::full, kind::diagonal>>> x;
    for (int i = 0; i < 37; ++i) {  // 2 packs of 16 and 5 bodies past them
        const auto d = random_state<sub::full>(rng);
        motor<float> g;
        screw<float> s;
        for (std::size_t c = 0; c < 8; ++c) g[c] = float(d.g[c]);
        for (std::size_t c = 0; c < 6; ++c) s[c] = float(d.s[c]);
        x.push_back({g, s});
        REQUIRE(b.add(g, s));
    }
    for (int k = 0; k < 100; ++k) {
        REQUIRE(b.step_rk4(0.01f) == error_code::none);
        for (auto& y : x) y = rk4{}.step(model, y, 0.01f).value;
    }
    float worst = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t c = 0; c < 8; ++c) worst = std::max(worst, std::abs(b.pose(i)[c] - x[i].g[c]));
    if (bit_for_bit) CHECK(worst == 0);
    CHECK(worst <= 1e-5f);
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

TEST_CASE("a batch holds at most its capacity, the AoS reference steps like rk4", "[scenes][batch]") {
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
