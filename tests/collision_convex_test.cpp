// Convex hulls (collision/hull.hpp) and the convex pairs without a closed form (GJK apart, EPA
// overlapping: convex_pairs.hpp) against the independent brute-force reference
// (tests/support/collision_reference.hpp, written without reading the library's collision code):
// a hull's structure (every point inside, faces flat, convex and counter-clockwise, Euler's
// V − E + F = 2), its mass properties against the reference's quadrature and a box's closed form;
// signed distances, normals and witnesses of hulls, cylinders and capsules against boxes, hulls
// and each other, apart and overlapping, near the origin and 1e4 m away; penetration of
// overlapping boxes as hulls against the separating-axis closed form; bad point sets refused.
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include <ctga/collision/hull.hpp>
#include <ctga/collision/narrowphase.hpp>

#include "support/catch.hpp"
#include "support/collision_fixtures.hpp"
#include "support/collision_reference.hpp"

namespace {
using namespace collision_fixtures;

// Every point within rounding below every face plane; every face's corners on its plane, its
// polygon convex and counter-clockwise about the outward normal; each edge between two faces.
template <std::size_t N>
void check_structure(const co::convex_hull<double, N>& h, const std::vector<vec3<double>>& points) {
    CHECK(static_cast<long>(h.vertex_count) - static_cast<long>(h.edge_count) + static_cast<long>(h.face_count) == 2);
    for (std::size_t f = 0; f < h.face_count; ++f) {
        const co::hull_face<double>& F = h.face[f];
        CHECK(F.count >= 3);
        CHECK(std::abs(co::length(F.normal) - 1) <= 1e-15);
        for (const vec3<double>& p : points) CHECK(ctga::linear3::dot(F.normal, p) <= F.offset + 1e-12);
        for (std::size_t k = 0; k < F.count; ++k) {
            const vec3<double>& a = h.vertex[h.face_vertex[F.first + k]];
            const vec3<double>& b = h.vertex[h.face_vertex[F.first + (k + 1) % F.count]];
            const vec3<double>& c = h.vertex[h.face_vertex[F.first + (k + 2) % F.count]];
            CHECK(std::abs(ctga::linear3::dot(F.normal, a) - F.offset) <= 1e-12);
            CHECK(ctga::linear3::dot(F.normal, ctga::linear3::cross(linear3_sub(b, a), linear3_sub(c, b))) > 0);
        }
    }
    for (std::size_t e = 0; e < h.edge_count; ++e) CHECK(h.edge[e].left != h.edge[e].right);
}

}  // namespace

TEST_CASE("collision: convex hulls: a cube with points inside and on its faces, random point clouds, their structure") {
    // a cube's corners, its face centres and edge midpoints (on the hull, not vertices), and inner points
    std::vector<vec3<double>> cube;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) cube.push_back({0.5 * x, 0.25 * y, 1.5 * z});
    cube.push_back({0.1, 0.1, 0.1});
    const auto h = co::make_hull<32, double>(cube);
    REQUIRE(h);
    CHECK(h->vertex_count == 8);
    CHECK(h->face_count == 6);
    CHECK(h->edge_count == 12);
    for (std::size_t f = 0; f < h->face_count; ++f) CHECK(h->face[f].count == 4);
    check_structure(*h, cube);
    // its mass is the box's
    const auto m = co::mass_of(*h, 7.0);
    const auto mb = co::mass_of(*co::make_box(0.5, 0.25, 1.5), 7.0);
    REQUIRE(m);
    CHECK(std::abs(m->mass - mb->mass) <= 1e-13 * mb->mass);
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(std::abs(m->com[i]) <= 1e-15);
        for (std::size_t j = 0; j < 3; ++j) CHECK(std::abs(m->inertia_c[i][j] - mb->inertia_c[i][j]) <= 1e-13 * mb->inertia_c[2][2]);
    }

    std::mt19937_64 rng(71);
    sizes s{rng};
    for (int trial = 0; trial < 6; ++trial) {
        const auto [hull, rh] = hull_kind::make(s);
        std::vector<vec3<double>> pts;
        for (const auto& p : rh.points) pts.push_back({static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])});
        check_structure(hull, pts);
        CHECK(hull.vertex_count == 20);  // the ellipsoid's points; the 4 inner ones dropped
        // mass properties against the reference's quadrature of the hull it builds itself
        const ref::mass_result want = ref::mass_properties(rh, 2.5L);
        const auto got = co::mass_of(hull, 2.5);
        REQUIRE(got);
        CHECK(std::abs(got->mass - static_cast<double>(want.mass)) <= 1e-13 * got->mass);
        for (std::size_t i = 0; i < 3; ++i) {
            CHECK(std::abs(got->com[i] - static_cast<double>(want.com[i])) <= 1e-14);
            for (std::size_t j = 0; j < 3; ++j)
                CHECK(std::abs(got->inertia_c[i][j] - static_cast<double>(want.inertia_about_com[i][j])) <= 1e-13 * got->mass);
        }
    }
}

TEST_CASE("collision: convex pairs by GJK and EPA against the brute-force reference, apart and overlapping, near and 1e4 m away") {
    check_pair_near_and_far<hull_kind, hull_kind>(101);
    check_pair_near_and_far<hull_kind, box_kind>(103);
    check_pair_near_and_far<sphere_kind, hull_kind>(105);
    check_pair_near_and_far<capsule_kind, hull_kind>(107);
    check_pair_near_and_far<capsule_kind, box_kind>(109);
    check_pair_near_and_far<half_space_kind, hull_kind>(111);
    // curved cores: the rim sampled by support points, to the iterations' tolerance
    check_pair_near_and_far<cylinder_kind, box_kind>(113, 1e-7);
    check_pair_near_and_far<cylinder_kind, cylinder_kind>(115, 1e-7);
    check_pair_near_and_far<hull_kind, cylinder_kind>(117, 1e-7);
    check_pair_near_and_far<capsule_kind, cylinder_kind>(119, 1e-7);
}

TEST_CASE("collision: EPA's penetration of overlapping boxes built as hulls equals the separating-axis closed form") {
    std::mt19937_64 rng(131);
    sizes s{rng};
    for (int k = 0; k < 40; ++k) {
        const double a0 = s.next(), a1 = s.next(), a2 = s.next(), b0 = s.next(), b1 = s.next(), b2 = s.next();
        const auto corners = [](double x, double y, double z) {
            std::array<vec3<double>, 8> c{};
            for (std::size_t i = 0; i < 8; ++i) c[i] = {(i & 1) ? x : -x, (i & 2) ? y : -y, (i & 4) ? z : -z};
            return *co::make_hull(c);
        };
        const posed pa = random_posed(rng, {0, 0, 0}, 0.4), pb = random_posed(rng, {0, 0, 0}, 0.4);
        const co::separation<double> hulls = co::separation_of(corners(a0, a1, a2), pa.map, corners(b0, b1, b2), pb.map);
        const co::separation<double> boxes = co::separation_of(*co::make_box(a0, a1, a2), pa.map, *co::make_box(b0, b1, b2), pb.map);
        CAPTURE(k, hulls.distance, boxes.distance);
        CHECK(std::abs(hulls.distance - boxes.distance) <= 1e-12);
        if (boxes.distance < -1e-6) CHECK(gap(hulls.normal, ref::vec3{boxes.normal[0], boxes.normal[1], boxes.normal[2]}) <= 1e-9);
    }
}

TEST_CASE("collision: bad point sets for a hull are refused, naming what is wrong") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(co::make_hull<8, double>(std::vector<vec3<double>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).error == ctga::error_code::too_few_points);
    CHECK(co::make_hull<8, double>(std::vector<vec3<double>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}}).error ==
          ctga::error_code::coplanar_points);
    CHECK(co::make_hull<8, double>(std::vector<vec3<double>>{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}).error == ctga::error_code::coplanar_points);
    CHECK(co::make_hull<8, double>(std::vector<vec3<double>>(5, vec3<double>{1, 2, 3})).error == ctga::error_code::coplanar_points);
    CHECK(co::make_hull<8, double>(std::vector<vec3<double>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, nan}}).error == ctga::error_code::non_finite);
    CHECK(co::make_hull<4, double>(std::vector<vec3<double>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}}).error ==
          ctga::error_code::capacity_exceeded);
    CHECK(static_cast<bool>(co::make_hull<4, double>(std::vector<vec3<double>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}})));
}

TEST_CASE("collision: float hulls and convex pairs") {
    std::array<vec3<float>, 8> c{};
    for (std::size_t i = 0; i < 8; ++i) c[i] = {(i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? 0.5f : -0.5f};
    const auto h = co::make_hull(c);
    REQUIRE(h);
    const ctga::motor_map<float> pa{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}}, pb{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0.9f, 0, 0}};
    const co::separation<float> s = co::separation_of(*h, pa, *co::make_cylinder(0.5f, 0.5f), pb);
    CHECK(std::abs(s.distance + 0.1f) <= 1e-5f);
    CHECK(std::abs(s.normal[0] - 1) <= 1e-5f);
}

namespace {
ctga::motor_map<double> turned(double angle, std::size_t axis, const vec3<double>& t) {
    const double c = std::cos(angle), s = std::sin(angle);
    ctga::motor_map<double> p{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, t};
    const std::size_t u = (axis + 1) % 3, v = (axis + 2) % 3;
    p.R[u][u] = c, p.R[u][v] = -s, p.R[v][u] = s, p.R[v][v] = c;
    return p;
}
co::convex_hull<double, 8> cube_hull(double hx, double hy, double hz) {
    std::array<vec3<double>, 8> c{};
    for (std::size_t i = 0; i < 8; ++i) c[i] = {(i & 1) ? hx : -hx, (i & 2) ? hy : -hy, (i & 4) ? hz : -hz};
    return *co::make_hull(c);
}
// Every point: its witnesses d n apart, on the right surfaces (B's point at height `top` + its
// separation when A is the support below, or as the caller checks).
void check_points(const co::manifold<double>& m) {
    for (std::size_t i = 0; i < m.count; ++i)
        for (std::size_t k = 0; k < 3; ++k)
            CHECK(std::abs(m.points[i].point_b[k] - m.points[i].point_a[k] - m.points[i].separation * m.normal[k]) <= 1e-14);
}
}  // namespace

TEST_CASE("collision: manifolds of convex pairs: a hull resting flat on a box gives its face's corners, turned 45° the four best of eight") {
    const auto table = *co::make_box(2.0, 2.0, 0.5);
    const ctga::motor_map<double> ground{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, -0.5}};  // top face at z = 0
    // a 0.6 × 0.4 × 0.2 hull box 1 mm into the table
    const auto flat = co::contact_of(table, ground, cube_hull(0.3, 0.2, 0.1), turned(0, 2, {0.1, -0.2, 0.099}), 0.0);
    REQUIRE(flat.count == 4);
    CHECK(std::abs(flat.normal[2] - 1) <= 1e-15);
    check_points(flat);
    for (std::size_t i = 0; i < 4; ++i) {
        CHECK(std::abs(flat.points[i].separation + 0.001) <= 1e-14);
        CHECK(std::abs(std::abs(flat.points[i].point_b[0] - 0.1) - 0.3) <= 1e-14);
        CHECK(std::abs(std::abs(flat.points[i].point_b[1] + 0.2) - 0.2) <= 1e-14);
        CHECK(std::abs(flat.points[i].point_a[2]) <= 1e-15);
        for (std::size_t j = i + 1; j < 4; ++j) CHECK(flat.points[i].id != flat.points[j].id);
    }
    // the same moved a little: the same ids
    const auto moved = co::contact_of(table, ground, cube_hull(0.3, 0.2, 0.1), turned(0.001, 2, {0.1002, -0.2, 0.0995}), 0.0);
    REQUIRE(moved.count == 4);
    for (std::size_t i = 0; i < 4; ++i) {
        bool found = false;
        for (std::size_t j = 0; j < 4; ++j) found = found || moved.points[j].id == flat.points[i].id;
        CHECK(found);
    }
    // a square hull turned 45° about z on a square hull of the same size: the octagon's four best
    const double h = 0.5;
    const auto oct = co::contact_of(cube_hull(h, h, h), turned(0, 2, {0, 0, -h}), cube_hull(h, h, h), turned(std::acos(-1.0) / 4, 2, {0, 0, h - 0.002}), 0.0);
    REQUIRE(oct.count == 4);
    check_points(oct);
    for (std::size_t i = 0; i < 4; ++i) {
        CHECK(std::abs(oct.points[i].separation + 0.002) <= 1e-14);
        // on the octagon's boundary: inside both squares, on the side of one
        const double x = oct.points[i].point_b[0], y = oct.points[i].point_b[1];
        CHECK(std::max(std::abs(x), std::abs(y)) <= h + 1e-14);
        CHECK((std::abs(x) + std::abs(y)) / std::sqrt(2.0) <= h + 1e-14);
        CHECK(std::max(std::max(std::abs(x), std::abs(y)), (std::abs(x) + std::abs(y)) / std::sqrt(2.0)) >= h - 1e-14);
    }
}

TEST_CASE("collision: manifolds of convex pairs: a capsule lying on a box touches at its two ends, a cylinder on its cap at four rim points and on its side at two") {
    const auto table = *co::make_box(2.0, 2.0, 0.5);
    const ctga::motor_map<double> ground{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, -0.5}};
    const double half_pi = std::acos(0.0);
    // a capsule of radius 0.1 and half length 0.4 along x, its core at height 0.098 (2 mm deep)
    const auto lying = co::contact_of(table, ground, *co::make_capsule(0.1, 0.4), turned(half_pi, 1, {0.3, 0.2, 0.098}), 0.0);
    REQUIRE(lying.count == 2);
    check_points(lying);
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK(std::abs(lying.points[i].separation + 0.002) <= 1e-14);
        CHECK(std::abs(std::abs(lying.points[i].point_b[0] - 0.3) - 0.4) <= 1e-14);
        CHECK(std::abs(lying.points[i].point_b[2] + 0.002) <= 1e-14);
    }
    CHECK(lying.points[0].id != lying.points[1].id);
    // tilted by 1° about y: still both ends, the lower one deeper by 0.8 sin 1°
    const auto tilted = co::contact_of(table, ground, *co::make_capsule(0.1, 0.4), turned(half_pi + 0.0174533, 1, {0, 0, 0.1}), 0.01);
    REQUIRE(tilted.count == 2);
    CHECK(std::abs(std::abs(tilted.points[0].separation - tilted.points[1].separation) - 0.8 * std::sin(0.0174533)) <= 1e-14);
    // a cylinder (r 0.3, half height 0.2) standing 1 mm deep: its rim's four points at r from the axis
    const auto standing = co::contact_of(table, ground, *co::make_cylinder(0.3, 0.2), turned(0.3, 2, {0.5, 0.5, 0.199}), 0.0);
    REQUIRE(standing.count == 4);
    check_points(standing);
    for (std::size_t i = 0; i < 4; ++i) {
        CHECK(std::abs(standing.points[i].separation + 0.001) <= 1e-14);
        CHECK(std::abs(std::hypot(standing.points[i].point_b[0] - 0.5, standing.points[i].point_b[1] - 0.5) - 0.3) <= 1e-14);
    }
    // lying on its side along y: the two ends of its lowest line
    const auto side = co::contact_of(table, ground, *co::make_cylinder(0.3, 0.2), turned(half_pi, 0, {0, 0, 0.299}), 0.0);
    REQUIRE(side.count == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK(std::abs(side.points[i].separation + 0.001) <= 1e-14);
        CHECK(std::abs(std::abs(side.points[i].point_b[1]) - 0.2) <= 1e-14);
    }
    // two capsules crossed at right angles, one on the other: one point
    const auto crossed = co::contact_of(*co::make_capsule(0.1, 0.5), turned(half_pi, 1, {0, 0, 0}), *co::make_capsule(0.1, 0.5),
                                        turned(half_pi, 0, {0, 0, 0.19}), 0.0);
    REQUIRE(crossed.count == 1);
    CHECK(std::abs(crossed.points[0].separation + 0.01) <= 1e-14);
}

TEST_CASE("collision: manifolds on a half-space: a hull tilted by 1° keeps its face's four corners, each at its own depth, tilted 20°, its edge's two") {
    const co::half_space<double> floor{};
    const ctga::motor_map<double> ground{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
    for (const double tilt : {0.0174533, 0.349066}) {
        const ctga::motor_map<double> p = turned(tilt, 0, {0.2, 0.1, 0.1});
        const auto m = co::contact_of(floor, ground, cube_hull(0.3, 0.2, 0.1), p, 0.1);
        // the corners' heights, from the pose
        std::vector<double> heights;
        for (std::size_t c = 0; c < 8; ++c) {
            const vec3<double> x{(c & 1) ? 0.3 : -0.3, (c & 2) ? 0.2 : -0.2, (c & 4) ? 0.1 : -0.1};
            heights.push_back(co::to_world(p, x)[2]);
        }
        std::sort(heights.begin(), heights.end());
        REQUIRE(m.count == (tilt < 0.1 ? 4u : 2u));
        check_points(m);
        std::vector<double> got;
        for (std::size_t i = 0; i < m.count; ++i) got.push_back(m.points[i].separation);
        std::sort(got.begin(), got.end());
        for (std::size_t i = 0; i < m.count; ++i) CHECK(std::abs(got[i] - heights[i]) <= 1e-14);
    }
}
