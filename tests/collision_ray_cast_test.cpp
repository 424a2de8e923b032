// Ray casts (collision/ray_cast.hpp) and the time of impact (collision/time_of_impact.hpp).
// Ray casts of every kind at random poses, near the origin and 10⁴ m from it, against the
// independent brute-force reference (tests/support/collision_reference.hpp: Newton steps on the
// point signed distance along the ray, in long double; ~3 ms a ray) and against distances written
// out here for rays along the axes; misses, rays from inside, grazing rays; the GJK ray cast on
// boxes, cylinders, capsules and spheres against the closed forms, and on hulls against the
// reference; float and double. The time of impact: two spheres in pure translation against the
// root of |p + v t| = r_A + r_B + target, a sphere falling onto a half-space, a turning long box
// sweeping onto a sphere and a tumbling box onto a box against a fine sampling of the motion
// (4,000 instants), a small fast sphere against a 1 cm wall (no tunnelling), a start in overlap.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>

#include <ctga/collision/ray_cast.hpp>
#include <ctga/collision/time_of_impact.hpp>
#include <ctga/mechanics/motor.hpp>

#include "support/catch.hpp"
#include "support/collision_fixtures.hpp"
#include "support/collision_reference.hpp"
#include "support/worst.hpp"

namespace {

using namespace collision_fixtures;
namespace li = ctga::linear3;
constexpr double inf = std::numeric_limits<double>::infinity();

ref::vec3 to_ref(const vec3<double>& a) { return {a[0], a[1], a[2]}; }
double norm(const vec3<double>& a) { return std::sqrt(li::dot(a, a)); }
double max_gap(const vec3<double>& a, const vec3<double>& b) {
    double m = 0;
    for (std::size_t i = 0; i < 3; ++i) m = std::max(m, std::abs(a[i] - b[i]));
    return m;
}
ctga::motor_map<double> placed(const vec3<double>& t) { return {{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, t}; }
ctga::motor_map<float> to_float(const ctga::motor_map<double>& m) {
    ctga::motor_map<float> f{};
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) f.R[i][j] = static_cast<float>(m.R[i][j]);
        f.t[i] = static_cast<float>(m.t[i]);
    }
    return f;
}

// A random ray about a shape posed at `centre`: its origin within ±3 of it (every fifth within
// ±0.1: inside), aimed at a point within ±1 of it (most hit) or in a random direction (most miss);
// max_length unbounded, or 3 (some hits beyond it).
struct drawn_ray {
    vec3<double> origin, direction;
    double max_length;
};
drawn_ray random_ray(std::mt19937_64& rng, const vec3<double>& centre, std::size_t k) {
    std::uniform_real_distribution<double> u(-1, 1);
    vec3<double> o{}, aim{};
    for (std::size_t i = 0; i < 3; ++i) o[i] = centre[i] + (k % 5 == 4 ? 0.1 : 3.0) * u(rng);
    for (std::size_t i = 0; i < 3; ++i) aim[i] = centre[i] + u(rng);
    vec3<double> d = li::sub(aim, o);
    if (k % 4 == 3) d = {u(rng), u(rng), u(rng)};
    return {o, d, k % 3 == 2 ? 3.0 : inf};
}

// `count` rays against a shape of kind K at random poses about `centre`: hit or miss as the
// reference says, the distance within `tol` (absolute), the point o + s d, the normal: the
// reference's at the point moved out by 1e-3 along it (the normal of the nearest surface point:
// the same when the normal is right; at an edge, any normal of its cone). `exact`: a closed form;
// otherwise the GJK cast's guarantee: s ≤ the true one and the point within ε of the shape.
struct tally {
    std::size_t hits = 0, misses = 0, inside = 0;
};
template <class K>
void check_rays(ctga::test::worst& w, tally& n, const char* name, std::size_t count, const vec3<double>& centre, std::uint64_t seed,
                double tol, bool exact = true) {
    std::mt19937_64 rng(seed);
    sizes s{rng};
    std::size_t& hits = n.hits;
    std::size_t& misses = n.misses;
    std::size_t& inside = n.inside;
    for (std::size_t k = 0; k < count; ++k) {
        const auto [shape, rshape] = K::make(s);
        const posed p = random_posed(rng, centre, 0.5);
        const drawn_ray dr = random_ray(rng, p.map.t, k);
        const co::ray<double> r = *co::make_ray_checked(dr.origin, dr.direction, dr.max_length);
        const co::ray_hit<double> got = co::ray_cast(shape, p.map, r);
        const auto want = ref::ray_cast(rshape, p.pose, to_ref(r.origin), to_ref(r.direction), static_cast<ref::real>(r.max_length));
        CAPTURE(name, seed, k, got.hit, got.distance, want.has_value());
        if (!exact && got.hit && !want) {  // a GJK cast passing within ε of the shape counts as a hit
            CHECK(static_cast<double>(ref::point_signed_distance(rshape, p.pose, to_ref(got.point))) <= tol);
            continue;
        }
        REQUIRE(got.hit == want.has_value());
        if (!got.hit) {
            ++misses;
            CHECK(got.distance == r.max_length);
            continue;
        }
        const double s_ref = static_cast<double>(*want);
        CAPTURE(s_ref);
        CHECK(std::abs(norm(got.normal) - 1) <= 1e-14);
        CHECK(max_gap(got.point, li::add_scaled(r.origin, got.distance, r.direction)) == 0);
        if (s_ref == 0) {  // from inside: the origin, against the direction
            ++inside;
            CHECK(got.distance == 0);
            CHECK(w("normal from inside, against −d", max_gap(got.normal, li::scale(-1.0, r.direction))) <= 2.3e-16);
            continue;
        }
        ++hits;
        if (exact) {
            CHECK(w(std::string(name) + ": |distance - reference|", std::abs(got.distance - s_ref)) <= tol);
        } else {
            CHECK(got.distance <= s_ref + 1e-12);
            const double off = static_cast<double>(ref::point_signed_distance(rshape, p.pose, to_ref(got.point)));
            CHECK(w(std::string(name) + ": the point's distance to the shape (GJK)", std::abs(off)) <= tol);
            CHECK(off >= -1e-12);
        }
        const ref::distance_result n = ref::point_query(rshape, p.pose, to_ref(li::add_scaled(got.point, 1e-3, got.normal)));
        const vec3<double> n_ref{static_cast<double>(n.normal[0]), static_cast<double>(n.normal[1]), static_cast<double>(n.normal[2])};
        CHECK(w(std::string(name) + ": normal", max_gap(got.normal, n_ref)) <= (exact ? 1e-10 : 1e-4));
    }
}

// 24 rays near the origin, 12 at 10⁴ m; the draw covers hits, misses and starts inside.
template <class K>
void check_rays_near_and_far(ctga::test::worst& w, const char* name, std::uint64_t seed, double near_tol, double far_tol, bool exact = true) {
    tally n;
    check_rays<K>(w, n, name, 24, {0, 0, 0}, seed, near_tol, exact);
    check_rays<K>(w, n, (std::string(name) + " at 1e4 m").c_str(), 12, {1e4, -1e4, 1e4}, seed + 1, far_tol, exact);
    CAPTURE(name, n.hits, n.misses, n.inside);
    CHECK(n.hits >= 6);
    CHECK(n.misses >= 3);
    CHECK(n.inside >= 3);
}

}  // namespace

TEST_CASE("collision: ray casts of every kind against the brute-force reference, near the origin and 1e4 m away") {
    ctga::test::worst w("ray casts against the reference");
    check_rays_near_and_far<sphere_kind>(w, "sphere", 1, 5e-15, 1e-14);
    check_rays_near_and_far<capsule_kind>(w, "capsule", 3, 5e-15, 1e-14);
    check_rays_near_and_far<box_kind>(w, "box", 5, 5e-15, 1e-14);
    check_rays_near_and_far<cylinder_kind>(w, "cylinder", 7, 5e-15, 1e-14);
    check_rays_near_and_far<half_space_kind>(w, "half-space", 9, 5e-15, 1e-14);
    // a hull has no closed form: the GJK cast, within √ε (size ~1) of the shape
    check_rays_near_and_far<hull_kind>(w, "hull", 11, 1e-7, 1e-7, false);
}

TEST_CASE("collision: ray casts along the axes against distances written out, at the origin and 1e4 m away, turned") {
    for (const vec3<double> c : {vec3<double>{0, 0, 0}, vec3<double>{1e4, -1e4, 1e4}}) {
        // the body turned by +90° about z: body x is world y, body y is world −x
        const ctga::motor<double> g = ctga::rigid_motion(ctga::make_translator(c[0], c[1], c[2]), ctga::make_rotor(M_PI / 2, 0.0, 0.0, 1.0));
        const ctga::motor_map<double> P = ctga::map_of(g);
        const double tol = c[0] == 0 ? 2e-15 : 1e-11, ntol = c[0] == 0 ? 2e-15 : 1e-11;
        const auto cast = [&](const auto& shape, const vec3<double>& from, const vec3<double>& dir) {
            return co::ray_cast(shape, P, *co::make_ray_checked(li::add(c, from), dir, inf));
        };
        const auto check = [&](const co::ray_hit<double>& h, double s, const vec3<double>& n) {
            CAPTURE(c[0], s, h.distance, h.normal[0], h.normal[1], h.normal[2]);
            CHECK(h.hit);
            CHECK(std::abs(h.distance - s) <= tol);
            CHECK(max_gap(h.normal, n) <= ntol);
        };
        // box of half extents (1, 2, 3): body x (world y) faces at ±1, body y (world −x) at ±2
        const co::box<double> b = *co::make_box(1.0, 2.0, 3.0);
        check(cast(b, {0.5, -5, 0.25}, {0, 1, 0}), 4, {0, -1, 0});    // along world y into the body −x face
        check(cast(b, {7, 0.5, -0.5}, {-1, 0, 0}), 5, {1, 0, 0});     // along world −x into the body −y face (world +x)
        check(cast(b, {0.1, 0.2, 10}, {0, 0, -2}), 7, {0, 0, 1});     // down the z axis (a direction of length 2)
        // sphere of radius 2: a ray 1.2 off the centre line, s = 5 − √(4 − 1.44)
        check(cast(*co::make_sphere(2.0), {1.2, 0, -5}, {0, 0, 1}), 5 - std::sqrt(4 - 1.44), {0.6, 0, -0.8});
        // capsule r = 0.5, h = 1 (axis world z): the end ball from below, the side across
        const co::capsule<double> cap = *co::make_capsule(0.5, 1.0);
        check(cast(cap, {0, 0, -4}, {0, 0, 1}), 4 - 1.5, {0, 0, -1});
        check(cast(cap, {-3, 0.3, 0.7}, {1, 0, 0}), 3 - 0.4, {-0.8, 0.6, 0});
        check(cast(cap, {0.3, -3, 1.3}, {0, 1, 0}), 3 - std::sqrt(0.07), {0.6, -std::sqrt(0.07) / 0.5, 0.6});  // the ball at z = 1
        // cylinder r = 0.5, h = 1: the cap from above, the side across, the rim
        const co::cylinder<double> cyl = *co::make_cylinder(0.5, 1.0);
        check(cast(cyl, {0.2, 0.1, 4}, {0, 0, -1}), 3, {0, 0, 1});
        check(cast(cyl, {-3, 0.3, 0.7}, {1, 0, 0}), 3 - 0.4, {-0.8, 0.6, 0});
        const co::ray_hit<double> rim = cast(cyl, {-3.5, 0, 4}, {1, 0, -1});  // at 45° onto the rim point (−0.5, 0, 1)
        CHECK(std::abs(rim.distance - 3 * std::sqrt(2.0)) <= 4 * tol);
        CHECK(std::min(max_gap(rim.normal, {0, 0, 1}), max_gap(rim.normal, {-1, 0, 0})) <= ntol);  // the cap's or the side's
        // half-space (the body's z up, turned about z: still up): from height 3 at 60° from the vertical
        const co::ray_hit<double> hs = cast(co::half_space<double>{}, {0, 0, 3}, {std::sqrt(3.0) / 2, 0, -0.5});
        check(hs, 6, {0, 0, 1});
    }
}

TEST_CASE("collision: ray casts that miss, stop short, start inside or on the surface, grazing rays") {
    const ctga::motor_map<double> P = placed({1, 2, 3});
    const co::sphere<double> sp = *co::make_sphere(1.0);
    const co::box<double> b = *co::make_box(1.0, 1.0, 1.0);
    const co::capsule<double> cap = *co::make_capsule(0.5, 1.0);
    const co::cylinder<double> cyl = *co::make_cylinder(0.5, 1.0);
    const co::half_space<double> hs{};
    const auto ray = [](const vec3<double>& o, const vec3<double>& d, double L) { return *co::make_ray_checked(o, d, L); };
    // pointing away, passing beside, stopping short
    for (const auto& r : {ray({1, 2, 6}, {0, 0, 1}, inf), ray({1, 4, 6}, {0, 0, -1}, inf), ray({1, 2, 6}, {0, 0, -1}, 1.4)}) {
        CHECK_FALSE(co::ray_cast(sp, P, r).hit);
        CHECK_FALSE(co::ray_cast(b, P, r).hit);
        CHECK_FALSE(co::ray_cast(cap, P, r).hit);
        CHECK_FALSE(co::ray_cast(cyl, P, r).hit);
        CHECK_FALSE(co::ray_cast_convex(b, P, r, 1e-9).hit);
        CHECK(co::ray_cast(sp, P, r).distance == r.max_length);
    }
    // max_length exactly at the hit: a hit (the interval is closed)
    CHECK(co::ray_cast(b, P, ray({1, 2, 6}, {0, 0, -1}, 2.0)).hit);
    CHECK_FALSE(co::ray_cast(hs, P, ray({0, 0, 6}, {1, 0, 0}, inf)).hit);  // parallel above the plane
    CHECK_FALSE(co::ray_cast(hs, P, ray({0, 0, 6}, {0, 0, 1}, inf)).hit);
    // from inside (and from the surface, pointing out): distance 0, the origin, the normal −d
    const vec3<double> d = {0.6, 0, 0.8};
    for (const vec3<double> o : {vec3<double>{1.2, 2.1, 3.3}, vec3<double>{1, 2, 4}}) {  // inside; on the top of the sphere and the box
        for (const co::ray_hit<double> h : {co::ray_cast(sp, P, ray(o, d, inf)), co::ray_cast(b, P, ray(o, d, inf)),
                                            co::ray_cast_convex(b, P, ray(o, d, inf), 1e-9), co::ray_cast(hs, placed({0, 0, 5}), ray(o, d, inf))}) {
            CHECK(h.hit);
            CHECK(h.distance == 0);
            CHECK(h.point == o);
            CHECK(max_gap(h.normal, {-0.6, 0, -0.8}) <= 2.3e-16);
        }
    }
    CHECK(co::ray_cast(cap, P, ray({1.2, 2.1, 4.2}, d, inf)).distance == 0);
    CHECK(co::ray_cast(cyl, P, ray({1.2, 2.1, 3.9}, d, inf)).distance == 0);
    // grazing a sphere of radius 1: a line 1 − δ from the centre hits at L − √(2δ − δ²), at 1 + δ misses
    for (const double delta : {1e-4, 1e-8, 1e-12}) {
        const co::ray_hit<double> in = co::ray_cast(sp, P, ray({1 - 5, 2 + 1 - delta, 3}, {1, 0, 0}, inf));
        CHECK(in.hit);
        CHECK(std::abs(in.distance - (5 - std::sqrt(2 * delta - delta * delta))) <= 1e-15 / std::sqrt(delta));
        CHECK_FALSE(co::ray_cast(sp, P, ray({1 - 5, 2 + 1 + delta, 3}, {1, 0, 0}, inf)).hit);
        // a cylinder's side, a capsule's side the same way (radius 0.5)
        CHECK(co::ray_cast(cyl, P, ray({1 - 5, 2 + 0.5 - delta, 3}, {1, 0, 0}, inf)).hit);
        CHECK_FALSE(co::ray_cast(cyl, P, ray({1 - 5, 2 + 0.5 + delta, 3}, {1, 0, 0}, inf)).hit);
        CHECK(co::ray_cast(cap, P, ray({1 - 5, 2 + 0.5 - delta, 3}, {1, 0, 0}, inf)).hit);
        CHECK_FALSE(co::ray_cast(cap, P, ray({1 - 5, 2 + 0.5 + delta, 3}, {1, 0, 0}, inf)).hit);
    }
    // along a box's face plane (z = 4 exactly): it touches the closed box, at the edge x = 0; just above it misses
    const co::ray_hit<double> edge = co::ray_cast(b, P, ray({-4, 2, 4}, {1, 0, 0}, inf));
    CHECK(edge.hit);
    CHECK(edge.distance == 4);
    CHECK_FALSE(co::ray_cast(b, P, ray({-4, 2, 4 + 1e-12}, {1, 0, 0}, inf)).hit);
    // along a cylinder's cap plane and along its side line
    CHECK(co::ray_cast(cyl, P, ray({-4, 2, 4}, {1, 0, 0}, inf)).distance == 4.5);
    CHECK(co::ray_cast(cyl, P, ray({1.5, 2, -5}, {0, 0, 1}, inf)).distance == 7);
}

namespace {
co::sphere<float> as_float(const co::sphere<double>& x) { return {float(x.radius)}; }
co::capsule<float> as_float(const co::capsule<double>& x) { return {float(x.radius), float(x.half_height)}; }
co::box<float> as_float(const co::box<double>& x) { return {{float(x.half[0]), float(x.half[1]), float(x.half[2])}}; }
co::cylinder<float> as_float(const co::cylinder<double>& x) { return {float(x.radius), float(x.half_height)}; }

// `count` random rays against a shape of kind K: the GJK cast (ε = 1e-9) against the closed form,
// and in float both against double's closed form.
template <class K>
void compare_gjk(ctga::test::worst& w, const char* name, std::size_t count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    sizes s{rng};
    std::size_t hits = 0;
    const double eps = 1e-9;
    const float eps_f = 1e-4f;
    for (std::size_t k = 0; k < count; ++k) {
        const auto [shape, rshape] = K::make(s);
        const posed p = random_posed(rng, {0, 0, 0}, 0.5);
        const drawn_ray dr = random_ray(rng, p.map.t, k);
        const co::ray<double> r = *co::make_ray_checked(dr.origin, dr.direction, dr.max_length);
        const co::ray_hit<double> want = co::ray_cast(shape, p.map, r);
        const co::ray_hit<double> got = co::ray_cast_convex(shape, p.map, r, eps);
        CAPTURE(name, k, want.hit, got.hit, want.distance, got.distance);
        // a hit where the closed form misses: the ray passes within ε (the point's distance to the shape)
        if (got.hit && !want.hit) {
            CHECK(static_cast<double>(ref::point_signed_distance(rshape, p.pose, to_ref(got.point))) <= eps * 1.001);
            continue;
        }
        REQUIRE(got.hit == want.hit);
        if (!want.hit || want.distance == 0) {
            if (want.hit) CHECK(got.distance == 0);
            continue;
        }
        ++hits;
        // s ≤ the true one, and at most ε/|n·d| less (n the normal at the hit)
        const double cosine = -li::dot(want.normal, r.direction);
        CHECK(got.distance <= want.distance + 1e-13);
        CHECK(w(std::string(name) + ": (true − GJK distance) · |n·d| / ε", (want.distance - got.distance) * cosine / eps) <= 1.0001);
        if (cosine > 0.2) CHECK(w(std::string(name) + ": GJK normal where |n·d| > 0.2", max_gap(got.normal, want.normal)) <= 1e-4);
        // float: the closed form (to float's rounding of the inputs: ~1e-7 of the lengths, more near grazing) and the GJK cast
        const auto shape_f = as_float(shape);
        const ctga::motor_map<float> pf = to_float(p.map);
        const co::ray<float> rf = *co::make_ray_checked<float>({float(r.origin[0]), float(r.origin[1]), float(r.origin[2])},
                                                               {float(r.direction[0]), float(r.direction[1]), float(r.direction[2])},
                                                               std::numeric_limits<float>::infinity());
        const co::ray_hit<float> cf = co::ray_cast(shape_f, pf, rf);
        const co::ray_hit<float> gf = co::ray_cast_convex(shape_f, pf, rf, eps_f);
        if (cosine > 0.2) {
            CHECK(cf.hit);
            CHECK(gf.hit);
            CHECK(w(std::string(name) + ": float closed form, |Δdistance| where |n·d| > 0.2", std::abs(cf.distance - want.distance)) <= 1e-5);
            CHECK(w(std::string(name) + ": float GJK, (true − distance) · |n·d| / ε_f", (want.distance - gf.distance) * cosine / eps_f) <= 1.01);
            CHECK(gf.distance <= want.distance + 1e-5);
        }
    }
    CHECK(hits >= count / 5);
}
}  // namespace

TEST_CASE("collision: the GJK ray cast against the closed forms on boxes, cylinders, capsules and spheres, double and float") {
    ctga::test::worst w("GJK ray cast against the closed forms");
    compare_gjk<box_kind>(w, "box", 200, 21);
    compare_gjk<cylinder_kind>(w, "cylinder", 200, 23);
    compare_gjk<capsule_kind>(w, "capsule", 200, 25);
    compare_gjk<sphere_kind>(w, "sphere", 200, 27);
}

TEST_CASE("collision: ray construction refuses a zero or non-finite direction, a NaN or negative length") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(co::make_ray_checked<double>({0, 0, 0}, {0, 0, 0}, 1.0).error == ctga::error_code::zero_direction);
    CHECK(co::make_ray_checked<double>({0, 0, 0}, {nan, 0, 1}, 1.0).error == ctga::error_code::non_finite);
    CHECK(co::make_ray_checked<double>({0, inf, 0}, {0, 0, 1}, 1.0).error == ctga::error_code::non_finite);
    CHECK(co::make_ray_checked<double>({0, 0, 0}, {0, 0, 1}, nan).error == ctga::error_code::non_finite);
    CHECK(co::make_ray_checked<double>({0, 0, 0}, {0, 0, 1}, -1.0).error == ctga::error_code::non_positive_size);
    const auto r = co::make_ray_checked<double>({1, 2, 3}, {0, 3e-300, 4e-300}, inf);  // any length, made unit
    REQUIRE(r);
    CHECK(max_gap(r->direction, {0, 0.6, 0.8}) <= 1e-16);
    CHECK(r->max_length == inf);
    CHECK(co::make_ray_checked<float>({0, 0, 0}, {1, 1, 0}, 0.0f));
}

// ---- time of impact ----------------------------------------------------------------------------

namespace {
constexpr double target = 1e-3, tolerance = 2.5e-4;
// The sampled motions turn fast (up to 3–7 rad in a step) and some graze past: conservative
// advancement then crawls (steps of (d − target)/μ with μ the bound of the turning), beyond the
// default 64 calls in ~1% of such draws (a failed state with a safe t); these checks give it 1,000.
constexpr int budget = 1000;

// A unit motor: translation t after a uniformly random rotation.
ctga::motor<double> random_motor(std::mt19937_64& rng, const vec3<double>& t) {
    std::normal_distribution<double> n;
    std::array<double, 4> q{n(rng), n(rng), n(rng), n(rng)};
    const double l = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& x : q) x /= l;
    return ctga::rigid_motion(ctga::make_translator(t[0], t[1], t[2]), ctga::rotor<double>{q[0], q[1], q[2], q[3]});
}
vec3<double> random_vector(std::mt19937_64& rng, double half) {
    std::uniform_real_distribution<double> u(-half, half);
    const double x = u(rng), y = u(rng), z = u(rng);
    return {x, y, z};
}
// The body-frame screw (ω, v) whose origin moves with world velocity v_world (g's rotation R: v = Rᵀ v_world).
ctga::screw<double> body_screw(const ctga::motor<double>& g, const vec3<double>& omega, const vec3<double>& v_world) {
    const vec3<double> v = li::apply_transposed(ctga::map_of(g).R, v_world);
    return {omega[0], omega[1], omega[2], v[0], v[1], v[2]};
}
// The same spinning at `rate` about the direction of travel (v ∥ ω: the origin still moves straight).
ctga::screw<double> spinning(const ctga::motor<double>& g, const vec3<double>& v_world, double rate) {
    const double l = norm(v_world);
    return body_screw(g, l > 0 ? li::scale(rate / l, li::apply_transposed(ctga::map_of(g).R, v_world)) : vec3<double>{}, v_world);
}
// The pose at s of g exp(s z), formed here from mechanics' exp (the motion the sweep stands for).
ctga::motor_map<double> pose_of(const ctga::motor<double>& g, const ctga::screw<double>& z, double s) {
    return ctga::map_of(ctga::motor<double>(g * ctga::exp(ctga::screw<double>{s * z[0], s * z[1], s * z[2], s * z[3], s * z[4], s * z[5]})));
}
// The signed distance of a box and a sphere of centre c, written out: c in the box's frame,
// clamped to it; inside, the nearest face.
double box_sphere(const co::box<double>& b, const ctga::motor_map<double>& P, const vec3<double>& c, double r) {
    const vec3<double> x = li::apply_transposed(P.R, li::sub(c, P.t));
    double out2 = 0, in = inf;
    for (std::size_t i = 0; i < 3; ++i) {
        const double e = std::abs(x[i]) - b.half[i];
        if (e > 0) out2 += e * e;
        in = std::min(in, -e);
    }
    return (out2 > 0 ? std::sqrt(out2) : -in) - r;
}

// The first of n + 1 instants s_i = i/n at which f(s) ≤ target, or 2 if none; the least f seen.
template <class F>
std::pair<double, double> first_sample(const F& f, int n) {
    double least = inf;
    for (int i = 0; i <= n; ++i) {
        const double s = double(i) / n, d = f(s);
        least = std::min(least, d);
        if (d <= target) return {s, least};
    }
    return {2.0, least};
}

// The time of impact against a sampled motion: when some sample reaches the target, touching at
// t ≤ that sample with the separation at t in [target, target + tolerance] (f(t): the distance
// written out); otherwise separated (t = 1), or touching within the tolerance above the target.
template <class F>
void check_against_samples(ctga::test::worst& w, const char* name, const co::impact<double>& got, const F& f) {
    const auto [first, least] = first_sample(f, 4000);
    CAPTURE(name, first, least, got.t, got.at.distance, got.iterations, int(got.state));
    w(std::string(name) + ": narrowphase calls (max)", got.iterations);
    REQUIRE(got.state != co::impact_state::failed);
    REQUIRE(got.state != co::impact_state::overlapping);
    if (first <= 1) {
        REQUIRE(got.state == co::impact_state::touching);
        CHECK(got.t <= first + 1e-12);
        w(std::string(name) + ": first sample at the target − t", first - got.t);
    }
    if (got.state == co::impact_state::touching) {
        const double d = f(got.t);
        CHECK(w(std::string(name) + ": |separation at t − written out|", std::abs(d - got.at.distance)) <= 1e-12);
        CHECK(d >= target - 1e-12);
        CHECK(d <= target + tolerance);
    } else {
        CHECK(got.t == 1);
        CHECK(least > target);
    }
}
}  // namespace

TEST_CASE("collision: time of impact of two spheres in pure translation (and spinning about their direction of travel) against the closed form") {
    ctga::test::worst w("time of impact, two spheres");
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> u(0, 1);
    std::size_t hits = 0, misses = 0;
    for (std::size_t k = 0; k < 400; ++k) {
        const double ra = 0.2 + u(rng), rb = 0.2 + u(rng);
        const vec3<double> ca = random_vector(rng, 2);
        vec3<double> p = random_vector(rng, 1);
        p = li::scale((ra + rb + 0.05 + 5 * u(rng)) / norm(p), p);
        const vec3<double> cb = li::add(ca, p);
        // velocities over the step: random, B's biased towards A
        const vec3<double> va = random_vector(rng, 3), vb0 = random_vector(rng, 3);  // (drawn one by one: the same with every compiler)
        const vec3<double> vb = li::add_scaled(vb0, -1.5 * u(rng), p);
        const ctga::motor<double> ga = random_motor(rng, ca), gb = random_motor(rng, cb);
        // odd draws spin each sphere about its direction of travel (v ∥ ω: the centre still moves straight)
        const auto spin = [&](const ctga::motor<double>& g, const vec3<double>& v) { return spinning(g, v, k % 2 == 1 ? 20 * u(rng) : 0.0); };
        const co::sweep<double> sa = co::sweep_of(ga, spin(ga, va), 1.0), sb = co::sweep_of(gb, spin(gb, vb), 1.0);
        const co::impact<double> got =
            co::time_of_impact(*co::make_sphere(ra), sa, *co::make_sphere(rb), sb, target, tolerance);
        // |p + v t| = ra + rb + target, the smaller root
        const vec3<double> v = li::sub(vb, va);
        const double R = ra + rb + target, a = li::dot(v, v), b = li::dot(p, v), c = li::dot(p, p) - R * R;
        const double disc = b * b - a * c;
        const double t_star = b < 0 && disc >= 0 ? c / (-b + std::sqrt(disc)) : inf;
        const auto gap_at = [&](double t) { return norm(li::add_scaled(p, t, v)) - ra - rb; };
        CAPTURE(k, t_star, got.t, got.at.distance, got.iterations, int(got.state));
        w("narrowphase calls (max)", got.iterations);
        if (t_star <= 1) {
            ++hits;
            REQUIRE(got.state == co::impact_state::touching);
            CHECK(got.t <= t_star + 1e-14);
            CHECK(w("|separation at t − |p + v t| + r_A + r_B|", std::abs(got.at.distance - gap_at(got.t))) <= 1e-13);
            CHECK(got.at.distance >= target - 1e-13);
            CHECK(got.at.distance <= target + tolerance);
            w("t* − t", t_star - got.t);
        } else {
            ++misses;
            const double closest = std::clamp(-b / a, 0.0, 1.0);
            if (got.state == co::impact_state::touching) CHECK(got.at.distance <= target + tolerance);
            else {
                REQUIRE(got.state == co::impact_state::separated);
                CHECK(got.t == 1);
                CHECK(gap_at(closest) > target);
            }
        }
    }
    CHECK(hits >= 50);
    CHECK(misses >= 50);
}

TEST_CASE("collision: time of impact of a sphere falling onto a half-space, and of a box tumbling onto it, against the closed form and samples") {
    ctga::test::worst w("time of impact onto a half-space");
    std::mt19937_64 rng(43);
    std::uniform_real_distribution<double> u(0, 1);
    for (std::size_t k = 0; k < 50; ++k) {
        // a tilted ground through a random point, static (its sweep between equal poses: no motion)
        const ctga::motor<double> ground = random_motor(rng, random_vector(rng, 2));
        const co::sweep<double> still = co::sweep_between(ground, ground);
        const ctga::motor_map<double> G = ctga::map_of(ground);
        const vec3<double> n = co::axis_of(G, 2);
        // a sphere at height h above it, falling by D along −n over the step, sliding and spinning
        const double r = 0.1 + u(rng), h = r + 0.1 + 2 * u(rng), D = h - r + 2 * u(rng) - 0.5;
        const vec3<double> drawn = random_vector(rng, 3);
        const vec3<double> c = li::add_scaled(li::add(G.t, li::add_scaled(drawn, -li::dot(n, drawn), n)), h, n);  // h above a point of the plane
        const vec3<double> slide = random_vector(rng, 2), v = li::add_scaled(li::add_scaled(slide, -li::dot(slide, n), n), -D, n);
        const ctga::motor<double> g = random_motor(rng, c);
        const co::impact<double> got = co::time_of_impact(co::half_space<double>{}, still, *co::make_sphere(r),
                                                          co::sweep_of(g, spinning(g, v, 10 * u(rng)), 1.0), target, tolerance);
        const double t_star = (h - r - target) / D;
        CAPTURE(k, t_star, got.t, got.iterations, int(got.state));
        w("sphere: narrowphase calls (max)", got.iterations);
        if (D > 0 && t_star <= 1) {
            REQUIRE(got.state == co::impact_state::touching);
            CHECK(got.t <= t_star + 1e-14);
            CHECK(w("sphere: (t* − t) · D", (t_star - got.t) * D) <= tolerance);
        } else {
            CHECK(got.state == co::impact_state::separated);
        }
        // a box tumbling onto it: its lowest corner n·t − Σ h_i |n·x_i|, sampled
        const double bx = 0.1 + u(rng), by = 0.1 + u(rng), bz = 0.05 + 0.2 * u(rng);
        const co::box<double> b = *co::make_box(bx, by, bz);
        const ctga::motor<double> gb = random_motor(rng, li::add_scaled(G.t, 2.5, n));
        const vec3<double> omega = random_vector(rng, 4), drift = random_vector(rng, 1);
        const ctga::screw<double> z = body_screw(gb, omega, li::add(drift, li::scale(-(2 + 2 * u(rng)), n)));
        const co::impact<double> tumble = co::time_of_impact(co::half_space<double>{}, still, b, co::sweep_of(gb, z, 1.0), target, tolerance, budget);
        check_against_samples(w, "tumbling box", tumble, [&](double s) {
            const ctga::motor_map<double> P = pose_of(gb, z, s);
            double lowest = li::dot(n, li::sub(P.t, G.t));
            for (std::size_t i = 0; i < 3; ++i) lowest -= b.half[i] * std::abs(li::dot(n, co::axis_of(P, i)));
            return lowest;
        });
    }
}

TEST_CASE("collision: time of impact of a turning long box sweeping onto a sphere, and of a box tumbling onto a box, against samples") {
    ctga::test::worst w("time of impact, turning boxes");
    std::mt19937_64 rng(47);
    std::uniform_real_distribution<double> u(0, 1);
    const co::box<double> rod = *co::make_box(1.5, 0.1, 0.1);
    std::size_t touching = 0;
    for (std::size_t k = 0; k < 60; ++k) {
        const ctga::motor<double> g = random_motor(rng, random_vector(rng, 0.5));
        vec3<double> axis = random_vector(rng, 1);
        axis = li::scale((0.5 + 2.5 * u(rng)) / norm(axis), axis);
        const ctga::screw<double> z{axis[0], axis[1], axis[2], 0.5 * (u(rng) - 0.5), 0.5 * (u(rng) - 0.5), 0.5 * (u(rng) - 0.5)};
        const double r = 0.1 + 0.2 * u(rng);
        // the sphere where the rod will be at a random instant (even draws: most touch), or anywhere near
        vec3<double> c;
        do {
            const ctga::motor_map<double> later = pose_of(g, z, u(rng));
            c = k % 2 == 0 ? ctga::collision::to_world(later, {1.5 * (2 * u(rng) - 1), 0.3 * (2 * u(rng) - 1), 0.3 * (2 * u(rng) - 1)})
                           : li::add(ctga::map_of(g).t, random_vector(rng, 2));
        } while (box_sphere(rod, ctga::map_of(g), c, r) < 0.05);
        const ctga::motor<double> gs = random_motor(rng, c);
        const co::impact<double> got =
            co::time_of_impact(rod, co::sweep_of(g, z, 1.0), *co::make_sphere(r), co::sweep_between(gs, gs), target, tolerance, budget);
        check_against_samples(w, "long box and sphere", got, [&](double s) { return box_sphere(rod, pose_of(g, z, s), c, r); });
        touching += got.state == co::impact_state::touching;
    }
    CHECK(touching >= 25);
    // a box tumbling onto a wide box (box pairs: GJK apart), against samples of separation_of
    for (std::size_t k = 0; k < 20; ++k) {
        const co::box<double> table = *co::make_box(3.0, 3.0, 0.3), b = *co::make_box(0.3, 0.2, 0.05 + 0.1 * u(rng));
        const ctga::motor<double> gt = random_motor(rng, {0, 0, 0});
        const ctga::motor_map<double> T = ctga::map_of(gt);
        const ctga::motor<double> gb = random_motor(rng, li::add_scaled(T.t, 1.5, co::axis_of(T, 2)));
        const vec3<double> omega = random_vector(rng, 4), drift = random_vector(rng, 1);
        const ctga::screw<double> z = body_screw(gb, omega, li::add(drift, li::scale(-3.0, co::axis_of(T, 2))));
        const co::impact<double> got = co::time_of_impact(table, co::sweep_between(gt, gt), b, co::sweep_of(gb, z, 1.0), target, tolerance, budget);
        check_against_samples(w, "box onto box", got, [&](double s) { return co::separation_of(table, T, b, pose_of(gb, z, s)).distance; });
    }
}

TEST_CASE("collision: a small fast sphere does not pass through a 1 cm wall in one step, starts in overlap and touching, failures") {
    // a sphere of radius 5 cm at 200 m/s towards a wall 1 cm thick, 1 m away, over a step of 1/60 s:
    // it moves 3.33 m, and is clear of the wall at both ends of the step
    const co::box<double> wall = *co::make_box(0.005, 1.0, 1.0);
    const co::sphere<double> ball = *co::make_sphere(0.05);
    const ctga::motor<double> gw = ctga::rigid_motion(ctga::make_translator(0.0, 0.0, 0.0), ctga::make_rotor(0.3, 0.0, 0.0, 1.0));
    const ctga::motor_map<double> W = ctga::map_of(gw);
    const vec3<double> across = co::axis_of(W, 0);  // the wall's normal
    const double dt = 1.0 / 60, speed = 200;
    const ctga::motor<double> g0 = ctga::rigid_motion(ctga::make_translator(-across[0], -across[1], -across[2]), ctga::make_rotor(1.0, 1.0, 2.0, 3.0));
    const co::sweep<double> fly = co::sweep_of(g0, spinning(g0, li::scale(speed, across), 30), dt);  // spinning at 30 rad/s
    const co::sweep<double> fixed = co::sweep_between(gw, gw);
    CHECK(co::separation_of(wall, W, ball, co::pose_at(fly, 0.0)).distance > 0.9);
    CHECK(co::separation_of(wall, W, ball, co::pose_at(fly, 1.0)).distance > 2);  // the discrete step tunnels
    const co::impact<double> hit = co::time_of_impact(wall, fixed, ball, fly, target, tolerance);
    const double t_star = (1 - 0.005 - 0.05 - target) / (speed * dt);
    CAPTURE(hit.t, t_star, hit.iterations);
    REQUIRE(hit.state == co::impact_state::touching);
    CHECK(hit.t <= t_star + 1e-14);
    CHECK((t_star - hit.t) * speed * dt <= tolerance);
    CHECK(hit.iterations <= 3);
    CHECK(max_gap(hit.at.normal, li::scale(-1.0, across)) <= 1e-12);
    // the same in float
    {
        const auto f = [](const ctga::motor<double>& g) {
            return ctga::motor<float>{float(g[0]), float(g[1]), float(g[2]), float(g[3]), float(g[4]), float(g[5]), float(g[6]), float(g[7])};
        };
        ctga::screw<float> z{};
        for (std::size_t i = 0; i < 6; ++i) z[i] = float(fly.motion[i]);
        const co::impact<float> hf =
            co::time_of_impact(co::box<float>{{0.005f, 1.f, 1.f}}, co::sweep_between(f(gw), f(gw)), co::sphere<float>{0.05f}, co::sweep<float>{f(g0), z}, 1e-3f, 2.5e-4f);
        CAPTURE(hf.t, hf.iterations);
        REQUIRE(hf.state == co::impact_state::touching);
        CHECK(hf.t <= float(t_star) + 1e-6f);
        CHECK((float(t_star) - hf.t) * float(speed * dt) <= 2.5e-4f + 1e-6f);
        CHECK(hf.at.distance >= 1e-3f - 1e-6f);
    }
    // overlapping at the start: reported at t = 0 with the (negative) separation
    const co::impact<double> over = co::time_of_impact(wall, fixed, ball, co::sweep_between(gw, gw), target, tolerance);
    CHECK(over.state == co::impact_state::overlapping);
    CHECK(over.t == 0);
    CHECK(std::abs(over.at.distance + 0.055) <= 1e-15);
    // touching at the start (0 ≤ d ≤ target + tolerance): t = 0
    const ctga::motor<double> near = ctga::rigid_motion(ctga::make_translator(-0.0555 * across[0], -0.0555 * across[1], -0.0555 * across[2]), ctga::rotor<double>{1, 0, 0, 0});
    const co::impact<double> touch = co::time_of_impact(wall, fixed, ball, co::sweep_of(near, body_screw(near, {}, li::scale(speed, across)), dt), target, tolerance);
    CHECK(touch.state == co::impact_state::touching);
    CHECK(touch.t == 0);
    // moving away: separated, t = 1, the separation at the end
    const co::impact<double> away = co::time_of_impact(wall, fixed, ball, co::sweep_of(g0, body_screw(g0, {}, li::scale(-speed, across)), dt), target, tolerance);
    CHECK(away.state == co::impact_state::separated);
    CHECK(away.t == 1);
    CHECK(std::abs(away.at.distance - (1 + speed * dt - 0.055)) <= 1e-12);
    CHECK(away.iterations == 2);
    // failures: a turning half-space, a target ≤ 0, a non-finite pose
    const ctga::motor<double> id{1, 0, 0, 0, 0, 0, 0, 0};
    CHECK(co::time_of_impact(co::half_space<double>{}, co::sweep_of(id, ctga::screw<double>{0.1, 0, 0, 0, 0, 0}, 1.0), ball, fly, target, tolerance).state ==
          co::impact_state::failed);
    CHECK(co::time_of_impact(wall, fixed, ball, fly, 0.0, tolerance).state == co::impact_state::failed);
    CHECK(co::time_of_impact(wall, fixed, ball, co::sweep_of(g0, ctga::screw<double>{std::nan(""), 0, 0, 0, 0, 0}, 1.0), target, tolerance).state ==
          co::impact_state::failed);
    // too few iterations to get there: failed, at the last instant evaluated (before the contact)
    const co::impact<double> short_run = co::time_of_impact(wall, fixed, ball, fly, target, tolerance, 1);
    CHECK(short_run.state == co::impact_state::failed);
    CHECK(short_run.t == 0);
}

TEST_CASE("collision: sweeps: from the poses at the ends (the screw motion between them) and from a velocity over a step") {
    std::mt19937_64 rng(53);
    for (std::size_t k = 0; k < 20; ++k) {
        const ctga::motor<double> g0 = random_motor(rng, random_vector(rng, 5)), g1 = random_motor(rng, random_vector(rng, 5));
        const co::sweep<double> w = co::sweep_between(g0, g1);
        const ctga::motor_map<double> a = co::pose_at(w, 0.0), b = co::pose_at(w, 1.0), A = ctga::map_of(g0), B = ctga::map_of(g1);
        for (std::size_t i = 0; i < 3; ++i) {
            CHECK(max_gap(a.R[i], A.R[i]) <= 1e-15);
            CHECK(max_gap(b.R[i], B.R[i]) <= 1e-14);
        }
        CHECK(max_gap(a.t, A.t) <= 1e-14);
        CHECK(max_gap(b.t, B.t) <= 1e-13);
        // the turn is at most π
        const double angle = norm({w.motion[0], w.motion[1], w.motion[2]});
        CHECK(angle <= M_PI + 1e-12);
        // a velocity over a step: the same motion as the screw times the step
        const co::sweep<double> v = co::sweep_of(g0, ctga::screw<double>{w.motion[0] * 60, w.motion[1] * 60, w.motion[2] * 60, w.motion[3] * 60,
                                                                         w.motion[4] * 60, w.motion[5] * 60},
                                                 1.0 / 60);
        CHECK(max_gap(co::pose_at(v, 0.5).t, co::pose_at(w, 0.5).t) <= 1e-13);
        // equal poses: no motion at all
        const co::sweep<double> still = co::sweep_between(g1, g1);
        for (std::size_t i = 0; i < 6; ++i) CHECK(still.motion[i] == 0);
    }
}

TEST_CASE("collision: time of impact of kinds without a closed-form pair: a hull onto a half-space, a cylinder onto a sphere, a capsule onto a box") {
    // a cube as a hull (half size 0.5), turned about z (its bottom face stays flat), falling 3 m in a step from 1 m above the ground
    std::array<vec3<double>, 8> corners{};
    for (std::size_t c = 0; c < 8; ++c) corners[c] = {(c & 1u) ? 0.5 : -0.5, (c & 2u) ? 0.5 : -0.5, (c & 4u) ? 0.5 : -0.5};
    const auto cube = co::make_hull(corners);
    REQUIRE(cube);
    const ctga::motor<double> ground{1, 0, 0, 0, 0, 0, 0, 0};
    const ctga::motor<double> g = ctga::rigid_motion(ctga::make_translator(2.0, -1.0, 1.5), ctga::make_rotor(0.4, 0.0, 0.0, 1.0));
    const co::impact<double> hull_drop = co::time_of_impact(co::half_space<double>{}, co::sweep_between(ground, ground), *cube,
                                                            co::sweep_of(g, spinning(g, {0, 0, -3}, 5), 1.0), target, tolerance);
    CAPTURE(hull_drop.t, hull_drop.iterations);
    REQUIRE(hull_drop.state == co::impact_state::touching);
    const double t_hull = (1 - target) / 3;
    CHECK(hull_drop.t <= t_hull + 1e-14);
    CHECK((t_hull - hull_drop.t) * 3 <= tolerance);
    // a cylinder (r 0.3, h 0.4) falling along its axis onto a sphere (r 0.5) below: its cap meets the sphere's top
    const ctga::motor<double> gc = ctga::rigid_motion(ctga::make_translator(0.0, 0.0, 2.0), ctga::rotor<double>{1, 0, 0, 0});
    const ctga::motor<double> gs = ctga::rigid_motion(ctga::make_translator(0.0, 0.0, 0.0), ctga::rotor<double>{1, 0, 0, 0});
    const co::impact<double> cyl = co::time_of_impact(*co::make_cylinder(0.3, 0.4), co::sweep_of(gc, spinning(gc, {0, 0, -4}, 2), 1.0),
                                                      *co::make_sphere(0.5), co::sweep_between(gs, gs), target, tolerance);
    CAPTURE(cyl.t, cyl.iterations, cyl.at.distance);
    REQUIRE(cyl.state == co::impact_state::touching);
    const double t_cyl = (2 - 0.4 - 0.5 - target) / 4;
    CHECK(cyl.t <= t_cyl + 1e-12);
    CHECK((t_cyl - cyl.t) * 4 <= tolerance + 1e-12);
    // a capsule lying along x, dropping onto a box's top face (z = 0.25) while sliding along it
    const ctga::motor<double> gk = ctga::rigid_motion(ctga::make_translator(0.0, 0.0, 1.5), ctga::make_rotor(M_PI / 2, 0.0, 1.0, 0.0));
    const co::impact<double> cap = co::time_of_impact(*co::make_box(2.0, 2.0, 0.25), co::sweep_between(gs, gs), *co::make_capsule(0.2, 0.6),
                                                      co::sweep_of(gk, body_screw(gk, {}, {0.5, 0, -2}), 1.0), target, tolerance);
    CAPTURE(cap.t, cap.iterations, cap.at.distance);
    REQUIRE(cap.state == co::impact_state::touching);
    const double t_cap = (1.5 - 0.2 - 0.25 - target) / 2;
    CHECK(cap.t <= t_cap + 1e-12);
    CHECK((t_cap - cap.t) * 2 <= tolerance + 1e-12);
}
