// Fixtures of the collision tests: random poses (a motor's map, and the same pose for the
// independent reference of collision_reference.hpp), random shapes of each kind in both forms, and
// the pair check against the reference's signed distance.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <ctga/collision/hull.hpp>
#include <ctga/collision/narrowphase.hpp>
#include <ctga/mechanics/motor.hpp>

#include "support/catch.hpp"
#include "support/collision_reference.hpp"

namespace collision_fixtures {

namespace co = ctga::collision;
namespace ref = collision_ref;
using ctga::vec3;

// A random rigid motion as the library poses bodies (a motor), its map, and the same map for the
// reference in long double. Translations uniform in a cube of half size `spread` about `centre`.
struct posed {
    ctga::motor_map<double> map;
    ref::pose pose;
};
inline posed random_posed(std::mt19937_64& rng, const vec3<double>& centre, double spread) {
    std::normal_distribution<double> n;
    std::uniform_real_distribution<double> u(-spread, spread);
    // a uniformly random rotation: a normally distributed quaternion made unit
    std::array<double, 4> q{n(rng), n(rng), n(rng), n(rng)};
    const double l = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& x : q) x /= l;
    const double x = u(rng), y = u(rng), z = u(rng);  // (drawn in order: the same poses with every compiler)
    const ctga::motor<double> g = ctga::rigid_motion(ctga::make_translator(centre[0] + x, centre[1] + y, centre[2] + z),
                                                     ctga::rotor<double>{q[0], q[1], q[2], q[3]});
    posed p{ctga::map_of(g), {}};
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) p.pose.R[i][j] = p.map.R[i][j];
        p.pose.t[i] = p.map.t[i];
    }
    return p;
}

// The library's shape and the reference's, with random sizes in [0.2, 1.2].
struct sizes {
    std::mt19937_64& rng;
    double next() { return std::uniform_real_distribution<double>(0.2, 1.2)(rng); }
};
struct sphere_kind {
    static auto make(sizes& s) {
        const double r = s.next();
        return std::pair{*co::make_sphere(r), ref::sphere{r}};
    }
};
struct capsule_kind {
    static auto make(sizes& s) {
        const double r = s.next(), h = s.next();
        return std::pair{*co::make_capsule(r, h), ref::capsule{r, h}};
    }
};
struct box_kind {
    static auto make(sizes& s) {
        const double a = s.next(), b = s.next(), c = s.next();
        return std::pair{*co::make_box(a, b, c), ref::box{{a, b, c}}};
    }
};
struct cylinder_kind {
    static auto make(sizes& s) {
        const double r = s.next(), h = s.next();
        return std::pair{*co::make_cylinder(r, h), ref::cylinder{r, h}};
    }
};
// A hull of 24 points: 20 on an ellipsoid of random half axes, 4 inside (dropped by the hull).
struct hull_kind {
    static auto make(sizes& s) {
        std::normal_distribution<double> n;
        const vec3<double> axes{s.next(), s.next(), s.next()};
        std::array<vec3<double>, 24> p{};
        std::vector<ref::vec3> points;
        for (std::size_t i = 0; i < p.size(); ++i) {
            vec3<double> d{n(s.rng), n(s.rng), n(s.rng)};
            const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) * (i < 20 ? 1.0 : 3.0);
            for (std::size_t k = 0; k < 3; ++k) p[i][k] = axes[k] * d[k] / l;
            points.push_back({p[i][0], p[i][1], p[i][2]});
        }
        return std::pair{*co::make_hull(p), ref::hull{points}};
    }
};
struct half_space_kind {
    static auto make(sizes&) { return std::pair{co::half_space<double>{}, ref::half_space{}}; }
};

inline vec3<double> linear3_sub(const vec3<double>& a, const vec3<double>& b) { return ctga::linear3::sub(a, b); }

inline double gap(const vec3<double>& a, const ref::vec3& b) {
    double m = 0;
    for (std::size_t i = 0; i < 3; ++i) m = std::max(m, std::abs(a[i] - static_cast<double>(b[i])));
    return m;
}

// `count` random configurations of the pair (A, B) about `centre`, poses within ±0.6 and ±8 in
// turn (the first mostly overlapping, the second mostly apart): the distance to 1e-12 (relative to the shapes' size, ~1, and to the pose's
// magnitude: 1e-12 at 10⁴ m is ~1e4 ulp of the coordinates' own rounding... both within 1e-12 of
// the reference); the normal when the reference's is unique (apart, or overlapping with one
// deepest direction); the witness points on the shapes' surfaces with point_b − point_a = d n.
template <class KA, class KB>
void check_pair(std::size_t count, const vec3<double>& centre, std::uint64_t seed, double tolerance = 1e-12) {
    std::mt19937_64 rng(seed);
    sizes s{rng};
    std::size_t apart = 0, overlapping = 0;
    const double scale = 1 + std::abs(centre[0]) + std::abs(centre[1]) + std::abs(centre[2]);
    for (std::size_t k = 0; k < count; ++k) {
        const auto [a, ra] = KA::make(s);
        const auto [b, rb] = KB::make(s);
        const double spread = k % 2 == 0 ? 0.6 : 8.0;  // mostly overlapping, then mostly apart
        const posed pa = random_posed(rng, centre, spread), pb = random_posed(rng, centre, spread);
        const co::separation<double> got = co::separation_of(a, pa.map, b, pb.map);
        const ref::distance_result want = ref::signed_distance(ra, pa.pose, rb, pb.pose);
        CAPTURE(seed, k, want.distance, got.distance);
        CHECK(std::abs(got.distance - static_cast<double>(want.distance)) <= tolerance * scale);
        (want.distance > 0 ? apart : overlapping) += 1;
        // the normal: unique apart, and overlapping where the reference finds one deepest direction
        if (want.distance > 1e-6 || want.witness_unique) CHECK(gap(got.normal, want.normal) <= std::max(1e-8, 1e3 * tolerance));
        CHECK(std::abs(co::length(got.normal) - 1) <= 1e-15);
        // the witness points: on the surfaces, and d n apart
        const ref::vec3 wa{got.point_a[0], got.point_a[1], got.point_a[2]}, wb{got.point_b[0], got.point_b[1], got.point_b[2]};
        CHECK(std::abs(static_cast<double>(ref::point_signed_distance(ra, pa.pose, wa))) <= tolerance * scale);
        CHECK(std::abs(static_cast<double>(ref::point_signed_distance(rb, pb.pose, wb))) <= tolerance * scale);
        for (std::size_t i = 0; i < 3; ++i)
            CHECK(std::abs(got.point_b[i] - got.point_a[i] - got.distance * got.normal[i]) <= 1e-12 * scale);
    }
    // the draw covers both sides
    CHECK(apart >= count / 10);
    CHECK(overlapping >= count / 10);
}

template <class KA, class KB>
void check_pair_near_and_far(std::uint64_t seed, double tolerance = 1e-12) {
    check_pair<KA, KB>(24, {0, 0, 0}, seed, tolerance);
    check_pair<KA, KB>(12, {1e4, -1e4, 1e4}, seed + 1, tolerance);
}


}  // namespace collision_fixtures
