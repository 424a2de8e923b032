// The broadphase (collision/broadphase.hpp) and world boxes (collision/aabb.hpp):
//  - bounds_of, closed form and from support points, against the reference's support functions
//    (tests/support/collision_reference.hpp, long double, written apart from the library):
//    upper_k = h(e_k), lower_k = −h(−e_k), to 1e-12, and every reference surface point inside;
//  - random scenes of spheres, boxes, capsules and cylinders moved over many steps, some
//    destroyed and created, with random filters: the pairs are exactly the pairs of overlapping
//    fat boxes (brute force over all pairs, fat_box(id)) that the filters allow, in order, every
//    pair of overlapping tight boxes among them; the same with a caller's predicate; box and ray
//    queries against brute force; the tree consistent; float and double;
//  - a tree taller than the walks' stack (nested boxes), capacity exceeded (proxies, pairs, the
//    caller's buffer) and recovered from, non-finite and inverted boxes refused.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory_resource>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include <ctga/collision/aabb.hpp>
#include <ctga/collision/broadphase.hpp>

#include "support/catch.hpp"
#include "support/collision_reference.hpp"

namespace {

namespace co = ctga::collision;
namespace ref = collision_ref;
using ctga::vec3;

// A uniformly random rotation (a normally distributed quaternion made unit) and a translation
// uniform in ±spread, as a motor map in T.
template <class T>
ctga::motor_map<T> random_map(std::mt19937_64& rng, double spread) {
    std::normal_distribution<double> n;
    std::uniform_real_distribution<double> u(-spread, spread);
    std::array<double, 4> q{};
    for (double& x : q) x = n(rng);
    const double l = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& x : q) x /= l;
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    ctga::motor_map<T> m{};
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) m.R[i][j] = static_cast<T>(R[i][j]);
        m.t[i] = static_cast<T>(u(rng));
    }
    return m;
}
ref::pose reference_pose(const ctga::motor_map<double>& m) {
    ref::pose p{};
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) p.R[i][j] = m.R[i][j];
        p.t[i] = m.t[i];
    }
    return p;
}

// A convex hull of points grown by a radius: a shape the library does not know, with only
// core_support and core_radius (what the generic bounds_of needs).
struct rounded_points {
    std::vector<vec3<double>> points;
    double radius;
};
vec3<double> core_support(const rounded_points& s, const vec3<double>& d) {
    vec3<double> best = s.points.front();
    for (const vec3<double>& p : s.points)
        if (ctga::linear3::dot(p, d) > ctga::linear3::dot(best, d)) best = p;
    return best;
}
double core_radius(const rounded_points& s) { return s.radius; }

// The reference's box of a posed shape: h along ±e_k, plus `grown` (a radius the reference shape lacks).
template <class S>
void same_box(const co::aabb<double>& got, const S& shape, const ref::pose& pose, double grown = 0) {
    for (std::size_t k = 0; k < 3; ++k) {
        ref::vec3 e{0, 0, 0};
        e[k] = 1;
        const double upper = static_cast<double>(ref::support(shape, pose, e)) + grown;
        e[k] = -1;
        const double lower = -static_cast<double>(ref::support(shape, pose, e)) - grown;
        CHECK(std::abs(got.upper[k] - upper) <= 1e-12);
        CHECK(std::abs(got.lower[k] - lower) <= 1e-12);
    }
    // surface points (support points in random directions) lie inside
    std::mt19937_64 rng(7);
    std::normal_distribution<double> n;
    for (int i = 0; i < 64; ++i) {
        const ref::vec3 u{n(rng), n(rng), n(rng)};
        const ref::vec3 p = ref::support_point(shape, pose, u);
        const ref::real l = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (std::size_t k = 0; k < 3; ++k) {
            const double x = static_cast<double>(p[k] + grown * u[k] / l);
            CHECK(got.lower[k] - 1e-12 <= x);
            CHECK(x <= got.upper[k] + 1e-12);
        }
    }
}

}  // namespace

TEST_CASE("broadphase: bounds_of, closed form and from support points, against the reference") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.2, 1.5);
    for (int trial = 0; trial < 40; ++trial) {
        const ctga::motor_map<double> m = random_map<double>(rng, 10);
        const ref::pose p = reference_pose(m);
        const double r = u(rng), h = u(rng), c = u(rng);
        const co::sphere<double> sphere{r};
        const co::capsule<double> capsule{r, h};
        const co::box<double> box{{r, h, c}};
        const co::cylinder<double> cylinder{r, h};
        same_box(co::bounds_of(sphere, m), ref::sphere{r}, p);
        same_box(co::bounds_of(capsule, m), ref::capsule{r, h}, p);
        same_box(co::bounds_of(box, m), ref::box{{r, h, c}}, p);
        same_box(co::bounds_of(cylinder, m), ref::cylinder{r, h}, p);
        same_box(co::support_bounds(sphere, m), ref::sphere{r}, p);
        same_box(co::support_bounds(capsule, m), ref::capsule{r, h}, p);
        same_box(co::support_bounds(box, m), ref::box{{r, h, c}}, p);
        same_box(co::support_bounds(cylinder, m), ref::cylinder{r, h}, p);
        // a shape known only by its support points
        rounded_points rp{{}, trial % 2 == 0 ? 0.0 : 0.3};
        ref::hull hull;
        std::uniform_real_distribution<double> v(-1, 1);
        for (int i = 0; i < 12; ++i) {
            rp.points.push_back({v(rng), v(rng), v(rng)});
            hull.points.push_back({rp.points.back()[0], rp.points.back()[1], rp.points.back()[2]});
        }
        same_box(co::bounds_of(rp, m), hull, p, rp.radius);
    }
    // in float, to float rounding of the double box
    for (int trial = 0; trial < 20; ++trial) {
        const ctga::motor_map<double> m = random_map<double>(rng, 10);
        ctga::motor_map<float> f{};
        for (std::size_t i = 0; i < 3; ++i) {
            for (std::size_t j = 0; j < 3; ++j) f.R[i][j] = static_cast<float>(m.R[i][j]);
            f.t[i] = static_cast<float>(m.t[i]);
        }
        const co::aabb<double> d = co::bounds_of(co::cylinder<double>{0.5, 0.8}, m);
        const co::aabb<float> g = co::bounds_of(co::cylinder<float>{0.5f, 0.8f}, f);
        for (std::size_t k = 0; k < 3; ++k) {
            CHECK(std::abs(g.lower[k] - d.lower[k]) <= 1e-5);
            CHECK(std::abs(g.upper[k] - d.upper[k]) <= 1e-5);
        }
    }
    // in a constant expression
    constexpr co::aabb<double> b = co::bounds_of(co::capsule<double>{0.5, 1.0}, ctga::motor_map<double>{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {1, 2, 3}});
    static_assert(b.lower == vec3<double>{0.5, 1.5, 1.5} && b.upper == vec3<double>{1.5, 2.5, 4.5});
}

TEST_CASE("broadphase: boxes: overlap (touching counts), containment, union, growth, area, rays") {
    const co::aabb<double> a{{0, 0, 0}, {1, 2, 3}}, touching{{1, 2, 3}, {4, 4, 4}}, apart{{1.5, 0, 0}, {2, 1, 1}};
    CHECK(co::overlaps(a, touching));
    CHECK(co::overlaps(touching, a));
    CHECK(!co::overlaps(a, apart));
    CHECK(co::contains(co::merged(a, apart), a));
    CHECK(co::contains(co::merged(a, apart), apart));
    CHECK(co::merged(a, apart) == co::aabb<double>{{0, 0, 0}, {2, 2, 3}});
    CHECK(co::fattened(a, 0.5) == co::aabb<double>{{-0.5, -0.5, -0.5}, {1.5, 2.5, 3.5}});
    CHECK(!co::contains(a, co::fattened(a, 0.5)));
    CHECK(co::surface_area(a) == 2.0 * (2 + 6 + 3));
    CHECK(co::is_valid(a));
    CHECK(!co::is_valid(co::aabb<double>{{0, 0, 0}, {-1, 1, 1}}));
    // rays: entry distance, a start inside (0), a miss, one too short, one along a face plane
    const co::ray<double> r = co::make_ray<double>({-2, 1, 1}, {1, 0, 0}, 10);
    CHECK(co::ray_entry(a, r, 10.0) == 2.0);
    CHECK(co::ray_entry(a, r, 1.5) < 0);
    CHECK(co::ray_entry(a, co::make_ray<double>({0.5, 1, 1}, {0, 0, -1}, 10), 10.0) == 0.0);
    CHECK(co::ray_entry(a, co::make_ray<double>({-2, 5, 1}, {1, 0, 0}, 10), 10.0) < 0);
    CHECK(co::ray_entry(a, co::make_ray<double>({-2, 2, 3}, {1, 0, 0}, 10), 10.0) == 2.0);  // along an edge: closed box
    CHECK(co::ray_entry(a, co::make_ray<double>({-1, -1, 0}, {1, 1, 0}, 10), 10.0) == 1.0);
}

TEST_CASE("broadphase: filters: category against mask both ways, a shared group overrides") {
    const co::filter all{}, one{1, 2, 0}, two{2, 1, 0}, mute{1, 0, 0};
    CHECK(co::may_pair(all, all));
    CHECK(co::may_pair(one, two));
    CHECK(!co::may_pair(one, one));
    CHECK(!co::may_pair(mute, all));
    CHECK(co::may_pair(co::filter{1, 0, 3}, co::filter{1, 0, 3}));             // group > 0: always
    CHECK(!co::may_pair(co::filter{1, ~0ull, -3}, co::filter{1, ~0ull, -3}));  // group < 0: never
    CHECK(co::may_pair(co::filter{1, ~0ull, -3}, co::filter{1, ~0ull, -4}));   // other groups: the bits
}

namespace {

// A scene of posed shapes of four kinds moving under constant velocities (reflected at ±spread),
// its tight boxes from bounds_of, and the checks of a broadphase over it against brute force.
template <class T>
class random_scene {
public:
    struct body {
        int kind;  // 0 sphere, 1 capsule, 2 box, 3 cylinder
        co::box<T> size;
        ctga::motor_map<T> pose;
        vec3<T> velocity;
        co::proxy_id id;
        bool alive;
    };
    std::mt19937_64 rng;
    std::vector<body> bodies;
    co::broadphase<T> bp;
    std::vector<co::proxy_pair> out;
    double spread;

    random_scene(std::uint64_t seed, std::size_t capacity, double spread_)
        : rng(seed), bp(capacity, capacity * capacity / 2, T(0.1)), out(capacity * capacity / 2), spread(spread_) {}

    co::aabb<T> tight(const body& b) const {
        switch (b.kind) {
            case 0: return co::bounds_of(co::sphere<T>{b.size.half[0]}, b.pose);
            case 1: return co::bounds_of(co::capsule<T>{b.size.half[0], b.size.half[1]}, b.pose);
            case 2: return co::bounds_of(b.size, b.pose);
            default: return co::bounds_of(co::cylinder<T>{b.size.half[0], b.size.half[1]}, b.pose);
        }
    }
    co::filter random_filter() {
        std::uniform_int_distribution<int> f(0, 9);
        const int x = f(rng);
        if (x < 6) return {};                          // the default: pairs with all
        if (x == 6) return {2, ~std::uint64_t{2}, 0};  // category 2, not with itself
        if (x == 7) return {4, ~std::uint64_t{0}, f(rng) % 2 ? 1 : -1};  // a group pairing always or never within
        return {1, ~std::uint64_t{0}, -2};             // a group that never pairs within
    }
    void add(std::size_t user) {
        std::uniform_real_distribution<double> s(0.1, 0.8), v(-0.3, 0.3);
        std::uniform_int_distribution<int> k(0, 3);
        body b{k(rng), co::box<T>{{T(s(rng)), T(s(rng)), T(s(rng))}}, random_map<T>(rng, spread), {T(v(rng)), T(v(rng)), T(v(rng))}, 0, true};
        const auto id = bp.create_proxy(tight(b), user, random_filter());
        REQUIRE(id);
        b.id = *id;
        if (user < bodies.size()) bodies[user] = b;
        else bodies.push_back(b);
    }
    // Moves every body (and turns it: a new random rotation now and then), with or without a displacement.
    void step(bool displacement) {
        std::uniform_int_distribution<int> turn(0, 4);
        for (body& b : bodies) {
            if (!b.alive) continue;
            for (std::size_t k = 0; k < 3; ++k) {
                b.pose.t[k] += b.velocity[k];
                if (std::abs(static_cast<double>(b.pose.t[k])) > spread) b.velocity[k] = -b.velocity[k];
            }
            if (turn(rng) == 0) b.pose.R = random_map<T>(rng, 1).R;
            const vec3<T> d = displacement ? ctga::linear3::scale(T(2), b.velocity) : vec3<T>{};
            CHECK(bp.move_proxy(b.id, tight(b), d) == ctga::error_code::none);
        }
    }
    // The contract: the pairs are the overlapping fat boxes the filters and the predicate allow,
    // each once, a < b, in order; they include every pair of overlapping tight boxes so allowed.
    template <class Predicate>
    void check_pairs(Predicate&& may_collide) {
        const auto n = bp.pairs(out, may_collide);
        REQUIRE(n);
        std::vector<co::aabb<T>> tight_box(bodies.size()), fat_box(bodies.size());
        for (std::size_t i = 0; i < bodies.size(); ++i)
            if (bodies[i].alive) tight_box[i] = tight(bodies[i]), fat_box[i] = bp.fat_box(bodies[i].id);
        std::vector<co::proxy_pair> want;
        std::size_t tight_pairs = 0;
        for (std::size_t i = 0; i < bodies.size(); ++i)
            for (std::size_t j = 0; j < bodies.size(); ++j) {
                const body &a = bodies[i], &b = bodies[j];
                if (!a.alive || !b.alive || a.id >= b.id) continue;
                if (!co::may_pair(bp.filter_of(a.id), bp.filter_of(b.id)) || !may_collide(bp.user_of(a.id), bp.user_of(b.id))) continue;
                if (co::overlaps(fat_box[i], fat_box[j])) want.push_back({a.id, b.id});
                tight_pairs += co::overlaps(tight_box[i], tight_box[j]);
            }
        std::sort(want.begin(), want.end(), [](const co::proxy_pair& x, const co::proxy_pair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
        REQUIRE(*n == want.size());
        CHECK(std::equal(want.begin(), want.end(), out.begin()));
        std::size_t found_tight = 0;
        for (std::size_t k = 0; k < *n; ++k)
            found_tight += co::overlaps(tight_box[static_cast<std::size_t>(bp.user_of(out[k].a))], tight_box[static_cast<std::size_t>(bp.user_of(out[k].b))]);
        CHECK(found_tight == tight_pairs);
    }
    void check_tree() {
        CHECK(bp.is_consistent());
        for (const body& b : bodies)
            if (b.alive) CHECK(co::contains(bp.fat_box(b.id), tight(b)));
    }
    // Box and ray queries against brute force over the fat boxes.
    void check_queries() {
        std::uniform_real_distribution<double> p(-spread, spread), w(0.1, 3);
        std::normal_distribution<double> n;
        for (int q = 0; q < 10; ++q) {
            const vec3<T> c{T(p(rng)), T(p(rng)), T(p(rng))};
            const co::aabb<T> box = co::fattened(co::aabb<T>{c, c}, T(w(rng)));
            std::vector<co::proxy_id> got, want;
            bp.query(box, [&](co::proxy_id id) { got.push_back(id); });
            for (const body& b : bodies)
                if (b.alive && co::overlaps(box, bp.fat_box(b.id))) want.push_back(b.id);
            std::sort(got.begin(), got.end());
            std::sort(want.begin(), want.end());
            CHECK(got == want);
            // a ray: every box it enters within the length, at the entry; then only the nearest
            vec3<T> d{T(n(rng)), T(n(rng)), T(n(rng))};
            d = ctga::linear3::scale(T(1) / std::sqrt(ctga::linear3::dot(d, d)), d);
            const T length = T(2 * spread);
            const co::ray<T> r = co::make_ray(c, d, length);
            std::vector<std::pair<co::proxy_id, T>> hits, brute;
            bp.ray_query(c, d, length, [&](co::proxy_id id, T s) {
                hits.push_back({id, s});
                return length;
            });
            T nearest = length;
            bool any = false;
            for (const body& b : bodies)
                if (b.alive) {
                    const T s = co::ray_entry(bp.fat_box(b.id), r, length);
                    if (s >= T(0)) brute.push_back({b.id, s}), nearest = std::min(nearest, s), any = true;
                }
            std::sort(hits.begin(), hits.end());
            std::sort(brute.begin(), brute.end());
            CHECK(hits == brute);
            T closest = length;
            bool hit = false;
            bp.ray_query(c, d, length, [&](co::proxy_id, T s) {
                closest = std::min(closest, s), hit = true;
                return s;
            });
            CHECK(hit == any);
            if (any) CHECK(closest == nearest);
        }
    }
};

// The pairs of users of the same parity are "jointed": excluded by the predicate.
constexpr auto not_jointed = [](std::uint64_t a, std::uint64_t b) { return (a + b) % 2 == 1 || a % 3 == 0; };

}  // namespace

TEMPLATE_TEST_CASE("broadphase: random moving scenes: pairs, queries and the tree against brute force", "[broadphase]", float, double) {
    using T = TestType;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        CAPTURE(seed);
        random_scene<T> s(seed, 320, 6.0);
        for (std::size_t i = 0; i < 300; ++i) s.add(i);
        s.check_pairs([](std::uint64_t, std::uint64_t) { return true; });
        std::uniform_int_distribution<std::size_t> pick(0, 299);
        for (int step = 0; step < 40; ++step) {
            CAPTURE(step);
            s.step(step % 3 == 2);
            // some destroyed, some created (ids reused), a filter changed
            for (int k = 0; k < 4; ++k) {
                const std::size_t i = pick(s.rng);
                if (s.bodies[i].alive) {
                    s.bp.destroy_proxy(s.bodies[i].id);
                    s.bodies[i].alive = false;
                } else {
                    s.add(i);
                }
            }
            const std::size_t f = pick(s.rng);
            if (s.bodies[f].alive) s.bp.set_filter(s.bodies[f].id, s.random_filter());
            if (step % 2 == 0) s.check_pairs([](std::uint64_t, std::uint64_t) { return true; });
            else s.check_pairs(not_jointed);
            if (step % 4 == 0) {
                s.check_tree();
                s.check_queries();
            }
        }
        // the same calls give the same pairs, bit for bit
        random_scene<T> again(seed, 320, 6.0);
        for (std::size_t i = 0; i < 300; ++i) again.add(i);
        std::vector<co::proxy_pair> first_pairs;
        (void)again.bp.for_each_pair([&](co::proxy_id a, co::proxy_id b) { first_pairs.push_back({a, b}); });
        random_scene<T> third(seed, 320, 6.0);
        for (std::size_t i = 0; i < 300; ++i) third.add(i);
        std::vector<co::proxy_pair> second_pairs;
        (void)third.bp.for_each_pair([&](co::proxy_id a, co::proxy_id b) { second_pairs.push_back({a, b}); });
        CHECK(first_pairs == second_pairs);
        CHECK(!first_pairs.empty());
    }
}

TEST_CASE("broadphase: a tree taller than the walks' stack (nested boxes) is walked without one") {
    co::broadphase<double> bp(100, 5000, 0.0);
    for (std::size_t i = 0; i < 100; ++i) {
        const double h = std::ldexp(1.0, static_cast<int>(i) / 4) * (1 + 0.1 * static_cast<double>(i % 4));
        REQUIRE(bp.create_proxy({{-h, -h, -h}, {h, h, h}}, i));
    }
    CHECK(bp.height() >= 64);
    CHECK(bp.is_consistent());
    std::vector<co::proxy_pair> out(5000);
    const auto n = bp.pairs(out);
    REQUIRE(n);
    CHECK(*n == 100 * 99 / 2);
    std::size_t seen = 0;
    bp.query({{100, 100, 100}, {101, 101, 101}}, [&](co::proxy_id id) {
        CHECK(bp.fat_box(id).upper[0] >= 100);
        ++seen;
        return true;
    });
    std::size_t want = 0;
    for (std::size_t i = 0; i < 100; ++i) want += bp.fat_box(static_cast<co::proxy_id>(i)).upper[0] >= 100;
    CHECK(seen == want);
    std::size_t rays = 0;
    bp.ray_query({0, 0, 0}, {1, 0, 0}, 1.0, [&](co::proxy_id, double s) {
        CHECK(s == 0.0);
        ++rays;
        return 1.0;
    });
    CHECK(rays == 100);
    // stopped by the callback
    std::size_t first = 0;
    bp.query({{0, 0, 0}, {0, 0, 0}}, [&](co::proxy_id) { return ++first < 3; });
    CHECK(first == 3);
}

TEST_CASE("broadphase: capacities exceeded are reported, and the pair set recovers") {
    using ctga::error_code;
    co::broadphase<double> bp(4, 3, 0.1);
    const co::aabb<double> unit{{0, 0, 0}, {1, 1, 1}};
    std::array<co::proxy_id, 4> id{};
    for (std::size_t i = 0; i < 4; ++i) id[i] = *bp.create_proxy(unit, i);
    CHECK(bp.create_proxy(unit, 4).error == error_code::capacity_exceeded);
    CHECK(bp.proxy_count() == 4);
    // six overlapping pairs, room for three
    std::array<co::proxy_pair, 8> out{};
    const auto n = bp.pairs(out);
    CHECK(n.error == error_code::capacity_exceeded);
    // two of them moved away: three pairs left, found again from all proxies
    CHECK(bp.move_proxy(id[2], {{10, 0, 0}, {11, 1, 1}}) == error_code::none);
    CHECK(bp.move_proxy(id[3], {{20, 0, 0}, {21, 1, 1}}) == error_code::none);
    const auto m = bp.pairs(out);
    REQUIRE(m);
    CHECK(*m == 1);
    CHECK(out[0] == co::proxy_pair{id[0], id[1]});
    CHECK(bp.move_proxy(id[2], unit) == error_code::none);
    const auto k = bp.pairs(out);
    REQUIRE(k);
    CHECK(*k == 3);
    // the caller's buffer too short: reported with the number needed, the first pairs written
    std::array<co::proxy_pair, 2> few{};
    const auto f = bp.pairs(few);
    CHECK(f.error == error_code::capacity_exceeded);
    CHECK(f.value == 3);
    CHECK(few[0] == out[0]);
    CHECK(few[1] == out[1]);
    // a freed proxy makes room
    bp.destroy_proxy(id[3]);
    CHECK(bp.create_proxy(unit, 9));
}

TEST_CASE("broadphase: non-finite and inverted boxes are refused, the proxy keeps its box") {
    using ctga::error_code;
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    co::broadphase<double> bp(4, 8, 0.1);
    CHECK(bp.create_proxy({{nan, 0, 0}, {1, 1, 1}}, 0).error == error_code::non_finite);
    CHECK(bp.create_proxy({{0, 0, 0}, {1, inf, 1}}, 0).error == error_code::non_finite);
    CHECK(bp.create_proxy({{0, 0, 2}, {1, 1, 1}}, 0).error == error_code::non_positive_size);
    CHECK(bp.proxy_count() == 0);
    const auto id = bp.create_proxy({{0, 0, 0}, {1, 1, 1}}, 0);
    REQUIRE(id);
    const co::aabb<double> fat = bp.fat_box(*id);
    CHECK(bp.move_proxy(*id, {{0, 0, 0}, {nan, 1, 1}}) == error_code::non_finite);
    CHECK(bp.move_proxy(*id, {{5, 5, 5}, {6, 6, 6}}, {nan, 0, 0}) == error_code::non_finite);
    CHECK(bp.move_proxy(*id, {{0, 0, 0}, {-1, 1, 1}}) == error_code::non_positive_size);
    CHECK(bp.fat_box(*id) == fat);
    CHECK(bp.is_consistent());
    // a float broadphase the same
    co::broadphase<float> bf(2, 2, 0.1f);
    CHECK(bf.create_proxy({{0, 0, 0}, {std::numeric_limits<float>::infinity(), 1, 1}}, 0).error == error_code::non_finite);
}

TEST_CASE("broadphase: storage from a caller's buffer (no heap): bytes_for suffices and the pairs are the heap's") {
    constexpr std::size_t proxies = 200, pairs = 2000;
    static std::array<std::byte, co::broadphase<double>::bytes_for(proxies, pairs)> buffer;
    std::pmr::monotonic_buffer_resource arena(buffer.data(), buffer.size(), std::pmr::null_memory_resource());
    co::broadphase<double> in_buffer(proxies, pairs, 0.1, &arena);  // (null behind it: running out would abort)
    co::broadphase<double> on_heap(proxies, pairs, 0.1);
    std::mt19937_64 rng(57);
    std::uniform_real_distribution<double> at(0.0, 6.0), size(0.1, 0.6);
    for (std::size_t i = 0; i < proxies; ++i) {
        const ctga::vec3<double> lo{at(rng), at(rng), at(rng)};
        const co::aabb<double> b{lo, {lo[0] + size(rng), lo[1] + size(rng), lo[2] + size(rng)}};
        REQUIRE(in_buffer.create_proxy(b, i));
        REQUIRE(on_heap.create_proxy(b, i));
    }
    std::vector<co::proxy_pair> a(pairs), b(pairs);
    const auto na = in_buffer.pairs(a), nb = on_heap.pairs(b);
    REQUIRE(na);
    REQUIRE(nb);
    CHECK(*na == *nb);
    CHECK(*na > 50);
    for (std::size_t k = 0; k < *na; ++k) CHECK(a[k] == b[k]);
}
