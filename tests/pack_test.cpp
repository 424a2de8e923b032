// ctga::pack<T, L> (support/pack.hpp): lane-wise arithmetic, masks and select, and its cos and sin
// against libm's, lane by lane: at most 1 ulp apart for |x| ≤ 100, 2 ulp up to 2¹⁹ π/2 (the range
// of the three-piece reduction), 1e-30 absolute next to a zero at k π/2, libm's own numbers beyond,
// NaN for NaN and ±∞, −0 kept. And one rigid body per lane: the single-body mechanics and the
// integrators on packs give every lane the double results bit for bit (no cos or sin there),
// motor renormalisation lane by lane with its failures per lane. And row_sum (support/row_sum.hpp):
// −Σ c_e x_e over rows of every length from 1 to 13, in native lanes and one number at a time,
// against the plain sum, at run time and in a constant expression.
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>

#include <ctga/integrators/methods.hpp>
#include <ctga/integrators/rigid_body_motion.hpp>
#include <ctga/mechanics/motor.hpp>
#include <ctga/scenes/body_kinds.hpp>
#include <ctga/support/math.hpp>
#include <ctga/support/pack.hpp>
#include <ctga/support/row_sum.hpp>

#include "support/catch.hpp"

namespace {

using ctga::pack;

// the distance of a and b in units in the last place (both finite)
std::int64_t ulps(double a, double b) {
    const auto key = [](double x) {
        const auto i = std::bit_cast<std::int64_t>(x);
        return i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i;
    };
    const std::int64_t d = key(a) - key(b);
    return d < 0 ? -d : d;
}

// The largest ulp distance of the pack's cos and sin from std::cos and std::sin over `count`
// packs of L lanes uniform in [−range, range].
template <std::size_t L>
std::int64_t worst_ulps(double range, int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-range, range);
    std::int64_t worst = 0;
    for (int i = 0; i < count; ++i) {
        const auto x = pack<double, L>::generate([&](std::size_t) { return u(rng); });
        const auto cs = ctga::math::cos_sin(x);
        for (std::size_t l = 0; l < L; ++l) {
            worst = std::max(worst, ulps(cs.cos[l], std::cos(x[l])));
            worst = std::max(worst, ulps(cs.sin[l], std::sin(x[l])));
        }
    }
    return worst;
}

}  // namespace

TEST_CASE("pack: arithmetic is lane by lane, a number broadcasts to every lane") {
    using P = pack<double, 4>;
    const P a = P::generate([](std::size_t l) { return 1.0 + double(l); });  // 1 2 3 4
    const P b = P::generate([](std::size_t l) { return 0.5 * double(l) - 1.25; });  // −1.25 −0.75 −0.25 0.25
    const P c = (a * b + P(2.0)) / a - b;
    for (std::size_t l = 0; l < 4; ++l) {
        const double al = 1.0 + double(l), bl = 0.5 * double(l) - 1.25;
        CHECK(c[l] == (al * bl + 2.0) / al - bl);
    }
    P d = a;
    d += b, d -= a, d *= a, d /= b;
    for (std::size_t l = 0; l < 4; ++l) CHECK(d[l] == (((a[l] + b[l]) - a[l]) * a[l]) / b[l]);
    CHECK((-a)[2] == -3.0);
}

TEST_CASE("pack: comparisons are masks, select chooses lane by lane, bit for bit") {
    using P = pack<double, 4>;
    const P x = P::generate([](std::size_t l) { return std::array{-1.0, 0.0, 2.0, -0.0}[l]; });
    const auto positive = x > P(0.0);
    CHECK(!positive[0]);
    CHECK(!positive[1]);
    CHECK(positive[2]);
    CHECK(!positive[3]);
    CHECK(ctga::any(positive));
    CHECK(!ctga::all(positive));
    CHECK(ctga::all(positive || !positive));
    CHECK(!ctga::any(positive && !positive));
    const P y = select(positive, x, P(7.0));
    CHECK(y[0] == 7.0);
    CHECK(y[2] == 2.0);
    const P z = select(x == P(0.0), x, P(1.0));  // ±0 kept with their signs
    CHECK(std::signbit(z[3]));
    CHECK(!std::signbit(z[1]));
    CHECK(abs(x)[0] == 1.0);
    static_assert(ctga::lane_wise<P>);
    static_assert(!ctga::lane_wise<double>);
}

TEST_CASE("pack: finite_lanes marks NaN and infinities, sqrt lane by lane") {
    using P = pack<double, 4>;
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    const P x = P::generate([&](std::size_t l) { return std::array{4.0, nan, -inf, 2.0}[l]; });
    const auto f = finite_lanes(x);
    CHECK(f[0]);
    CHECK(!f[1]);
    CHECK(!f[2]);
    CHECK(f[3]);
    const P r = ctga::math::sqrt(x);
    CHECK(r[0] == 2.0);
    CHECK(r[3] == std::sqrt(2.0));
    CHECK(std::isnan(r[1]));
}

TEST_CASE("pack: cos and sin within 1 ulp of libm's for |x| <= 100, 2 ulp to 2^19 pi/2") {
    CHECK(worst_ulps<4>(0.8, 50'000, 1) <= 1);
    CHECK(worst_ulps<8>(4.0, 50'000, 2) <= 1);
    CHECK(worst_ulps<2>(100.0, 50'000, 3) <= 1);
    CHECK(worst_ulps<4>(823'549.0, 50'000, 4) <= 2);
}

TEST_CASE("pack: cos and sin at the edges: NaN, infinities, far lanes from libm alone, -0, multiples of pi/2") {
    using P = pack<double, 8>;
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    const std::array<double, 8> xs{nan, inf, -inf, 1e300, -0.0, 3 * 1.5707963267948966, 0.3, -1e7};
    const P x = P::generate([&](std::size_t l) { return xs[l]; });
    const auto cs = ctga::math::cos_sin(x);
    for (std::size_t l = 0; l < 3; ++l) {
        CHECK(std::isnan(cs.cos[l]));
        CHECK(std::isnan(cs.sin[l]));
    }
    CHECK(cs.cos[3] == std::cos(1e300));
    CHECK(cs.sin[3] == std::sin(1e300));
    CHECK(cs.cos[7] == std::cos(-1e7));
    CHECK(cs.sin[7] == std::sin(-1e7));
    CHECK(cs.sin[4] == 0.0);
    CHECK(std::signbit(cs.sin[4]));
    CHECK(cs.cos[4] == 1.0);
    CHECK(std::abs(cs.cos[5] - std::cos(xs[5])) <= 1e-30);  // cos(3π/2 rounded) = −1.8e-16: its ulp is 2.5e-32
    CHECK(ulps(cs.sin[5], std::sin(xs[5])) <= 1);
    // a lane's numbers do not depend on its neighbours (lane 6 alone, and among the far lanes)
    const auto alone = ctga::math::cos_sin(P(0.3));
    CHECK(cs.cos[6] == alone.cos[6]);
    CHECK(cs.sin[6] == alone.sin[6]);
    CHECK(ulps(cs.cos[6], std::cos(0.3)) <= 1);
}

TEST_CASE("pack: float lanes, evaluated in double and rounded: within 1 ulp of float(libm's double)") {
    using P = pack<float, 8>;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f);
    int worst = 0;
    for (int i = 0; i < 10'000; ++i) {
        const P x = P::generate([&](std::size_t) { return u(rng); });
        const auto cs = ctga::math::cos_sin(x);
        for (std::size_t l = 0; l < 8; ++l) {
            const float c = static_cast<float>(std::cos(double(x[l]))), s = static_cast<float>(std::sin(double(x[l])));
            const auto d = [](float a, float b) {
                return std::abs(std::bit_cast<std::int32_t>(a) - std::bit_cast<std::int32_t>(b));
            };
            if (std::signbit(c) == std::signbit(cs.cos[l])) worst = std::max(worst, d(c, cs.cos[l]));
            if (std::signbit(s) == std::signbit(cs.sin[l])) worst = std::max(worst, d(s, cs.sin[l]));
        }
    }
    CHECK(worst <= 1);
}

#if defined(__FP_FAST_FMA) || defined(__FMA__)
constexpr double contraction = 1e-14;  // 50 steps
#else
constexpr double contraction = 0;
#endif

TEST_CASE("pack: one free body per lane, stepped by rk4 and lie_rk4: every lane the double step bit for bit") {
    using P = pack<double, 4>;
    namespace kind = ctga::inertia_kind;
    using sub = ctga::subspace::full;
    const kind::diagonal::data<double> box{2.0, 2.0, 2.5, 3.0};
    const kind::diagonal::data<P> box_p{P(2.0), P(2.0), P(2.5), P(3.0)};
    const ctga::body_motion<double, sub, kind::diagonal> one{box};
    const ctga::body_motion<P, sub, kind::diagonal> lanes{box_p};
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-1, 1);
    std::array<ctga::state_of<decltype(one)>, 4> x;
    ctga::state_of<decltype(lanes)> xp;
    for (std::size_t l = 0; l < 4; ++l) {
        x[l].g = ctga::renormalize(ctga::motor<double>{1 + u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)});
        x[l].s = ctga::screw<double>{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
        for (std::size_t c = 0; c < 8; ++c) xp.g[c].set(l, x[l].g[c]);
        for (std::size_t c = 0; c < 6; ++c) xp.s[c].set(l, x[l].s[c]);
    }
    for (int k = 0; k < 50; ++k) {
        const auto a = ctga::rk4{}.step(lanes, xp, P(1e-2));
        const auto b = ctga::lie_rk4{}.step(lanes, xp, P(1e-2));
        CHECK(a);
        for (std::size_t l = 0; l < 4; ++l) {
            const auto a1 = ctga::rk4{}.step(one, x[l], 1e-2).value;
            const auto b1 = ctga::lie_rk4{}.step(one, x[l], 1e-2).value;
            // bit for bit, unless the target has FMA: then GCC contracts a·b + c into fused
            // multiply-adds where it chooses, differently in the two codes (to rounding)
            for (std::size_t c = 0; c < 8; ++c) CHECK(std::abs(a.value.g[c][l] - a1.g[c]) <= contraction * (1 + std::abs(a1.g[c])));
            for (std::size_t c = 0; c < 6; ++c) CHECK(std::abs(a.value.s[c][l] - a1.s[c]) <= contraction * (1 + std::abs(a1.s[c])));
            for (std::size_t c = 0; c < 8; ++c) CHECK(std::abs(b.value.g[c][l] - b1.g[c]) <= 1e-15);
            x[l] = a1;
        }
        xp = a.value;
    }
}

TEST_CASE("pack: renormalize_checked lane by lane: a NaN lane and a zero rotor reported, the others renormalised") {
    using P = pack<double, 4>;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::array<ctga::motor<double>, 4> g{ctga::motor<double>{2, 0, 0, 0, 0, 1, 0, 0}, ctga::motor<double>{nan, 0, 0, 0, 0, 0, 0, 0},
                                               ctga::motor<double>{0, 0, 0, 0, 1, 0, 0, 0}, ctga::motor<double>{0.5, 0.5, 0.5, 0.5, 0.1, 0.2, 0.3, 0.4}};
    ctga::motor<P> gp;
    for (std::size_t l = 0; l < 4; ++l)
        for (std::size_t c = 0; c < 8; ++c) gp[c].set(l, g[l][c]);
    const auto r = ctga::renormalize_checked(gp);
    CHECK(!r);
    CHECK(r.error[0] == ctga::error_code::none);
    CHECK(r.error[1] == ctga::error_code::non_finite);
    CHECK(r.error[2] == ctga::error_code::not_a_motor);
    CHECK(r.error[3] == ctga::error_code::none);
    for (const std::size_t l : {0u, 3u}) {
        const ctga::motor<double> one = ctga::renormalize(g[l]);
        for (std::size_t c = 0; c < 8; ++c) CHECK(r.value[c][l] == one[c]);
    }
    for (std::size_t c = 0; c < 8; ++c) CHECK(std::isnan(r.value[c][2]));
}


namespace {
// row_sum<T, Count, L> against the plain loop −Σ_e c_e x_e[i] (rows of a 5 × 16 table), by each()
// and by store(); every entry within 4 ulp of the sum of magnitudes (the order of operations is the
// same; a target that fuses the multiply-adds rounds less).
template <class T, std::size_t Count, std::size_t L>
void check_row_sum(const std::array<std::array<T, 16>, 5>& x, const std::array<T, 5>& c) {
    ctga::row_sum<T, Count, L> s;
    for (std::size_t e = 0; e < 5; ++e) s.subtract(c[e], x[e].data());
    std::array<T, Count> by_each{}, stored{};
    std::size_t seen = 0;
    s.each([&](std::size_t i, const T& v) {
        CHECK(i == seen++);  // in order, each once
        by_each[i] = v;
    });
    CHECK(seen == Count);
    s.store(stored.data());
    for (std::size_t i = 0; i < Count; ++i) {
        T plain = T(0), size = T(0);
        for (std::size_t e = 0; e < 5; ++e) {
            plain -= c[e] * x[e][i];
            size += std::abs(c[e] * x[e][i]);
        }
        const T tol = 4 * std::numeric_limits<T>::epsilon() * size;
        CHECK(std::abs(by_each[i] - plain) <= tol);
        CHECK(stored[i] == by_each[i]);
    }
}
template <class T, std::size_t... Count>
void check_row_sums(std::index_sequence<Count...>) {
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<T> u(T(-2), T(2));
    std::array<std::array<T, 16>, 5> x{};
    std::array<T, 5> c{};
    for (auto& row : x)
        for (T& v : row) v = u(rng);
    for (T& v : c) v = u(rng);
    (check_row_sum<T, Count + 1, ctga::row_lanes<T>>(x, c), ...);
    (check_row_sum<T, Count + 1, 1>(x, c), ...);
}
// In a constant expression (one number at a time): 1·(1, 2, 3) + 2·(4, 5, 6) subtracted.
constexpr std::array<double, 3> constant_row_sum() {
    const double x[2][3] = {{1, 2, 3}, {4, 5, 6}};
    ctga::row_sum<double, 3, 1> s;
    s.subtract(1, x[0]);
    s.subtract(2, x[1]);
    std::array<double, 3> out{};
    s.store(out.data());
    return out;
}
static_assert(constant_row_sum() == std::array<double, 3>{-9, -12, -15}, "row_sum in a constant expression");
}  // namespace

TEST_CASE("row_sum: -sum c_e x_e for rows of 1 to 13 numbers, in native lanes and one at a time, as the plain sum") {
    check_row_sums<double>(std::make_index_sequence<13>{});
    check_row_sums<float>(std::make_index_sequence<13>{});
}
