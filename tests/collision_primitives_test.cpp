// The collision layer's shapes and closed-form pairs (collision/primitive_pairs.hpp) against an
// independent brute-force reference (tests/support/collision_reference.hpp: support functions
// maximised over directions, quadrature, in long double, written without reading the library's
// collision code): signed distances, normals and witness points of every closed-form pair at
// random sizes and poses, apart and overlapping, near the origin and 10⁴ m from it; the shapes'
// mass properties against quadrature; bad sizes refused at construction.
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <string_view>
#include <utility>

#include <ctga/collision/gjk.hpp>
#include <ctga/collision/line_of_action.hpp>
#include <ctga/mechanics/screw.hpp>
#include <ctga/collision/narrowphase.hpp>
#include <ctga/mechanics/motor.hpp>

#include "support/catch.hpp"
#include "support/collision_fixtures.hpp"
#include "support/collision_reference.hpp"

namespace {

using namespace collision_fixtures;

}  // namespace

TEST_CASE("collision: closed-form pairs and boxes against the brute-force reference, apart and overlapping, near and 1e4 m away") {
    check_pair_near_and_far<sphere_kind, sphere_kind>(1);
    check_pair_near_and_far<capsule_kind, sphere_kind>(3);
    check_pair_near_and_far<sphere_kind, capsule_kind>(5);  // the same routine, seen from the sphere
    check_pair_near_and_far<capsule_kind, capsule_kind>(7);
    check_pair_near_and_far<box_kind, sphere_kind>(9);
    check_pair_near_and_far<half_space_kind, sphere_kind>(11);
    check_pair_near_and_far<half_space_kind, capsule_kind>(13);
    check_pair_near_and_far<half_space_kind, box_kind>(15);
    check_pair_near_and_far<box_kind, half_space_kind>(17);
    check_pair_near_and_far<half_space_kind, cylinder_kind>(19);
    check_pair_near_and_far<box_kind, box_kind>(21);  // GJK apart, the separating axes overlapping
}

TEST_CASE("collision: a sphere inside a box leaves by the nearest face, crossing capsule cores part perpendicular to both") {
    const ctga::motor_map<double> I{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
    ctga::motor_map<double> P = I;
    P.t = {0.1, -0.7, 0.2};  // nearest face y = −1 (margin 0.3)
    const auto s = co::separation_of(*co::make_box(1.0, 1.0, 1.0), I, *co::make_sphere(0.25), P);
    CHECK(s.distance == -(0.3 + 0.25));
    CHECK(s.normal == vec3<double>{0, -1, 0});
    // two capsules whose cores cross at the origin, along x and along y: depth r_a + r_b along ±z
    const ctga::motor_map<double> X{{{{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}}}, {0, 0, 0}};  // body z along world x
    const ctga::motor_map<double> Y{{{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}}, {0, 0, 0}};  // body z along world y
    const auto c = co::separation_of(*co::make_capsule(0.2, 1.0), X, *co::make_capsule(0.3, 1.0), Y);
    CHECK(c.distance == -0.5);
    CHECK(std::abs(std::abs(c.normal[2]) - 1) == 0);
}

TEST_CASE("collision: mass properties of the shapes against quadrature") {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> u(0.2, 1.5);
    const auto same = [](const ctga::mass_properties<double>& got, const ref::mass_result& want) {
        const double m = static_cast<double>(want.mass);
        CHECK(std::abs(got.mass - m) <= 1e-13 * m);
        for (std::size_t i = 0; i < 3; ++i) {
            CHECK(std::abs(got.com[i] - static_cast<double>(want.com[i])) <= 1e-13);
            for (std::size_t j = 0; j < 3; ++j)
                CHECK(std::abs(got.inertia_c[i][j] - static_cast<double>(want.inertia_about_com[i][j])) <=
                      1e-13 * static_cast<double>(want.inertia_about_com[0][0] + want.inertia_about_com[1][1] + want.inertia_about_com[2][2]));
        }
    };
    for (int k = 0; k < 5; ++k) {
        const double r = u(rng), h = u(rng), c = u(rng), rho = 100 * u(rng);
        same(*co::mass_of(*co::make_sphere(r), rho), ref::mass_properties(ref::sphere{r}, rho));
        same(*co::mass_of(*co::make_capsule(r, h), rho), ref::mass_properties(ref::capsule{r, h}, rho));
        same(*co::mass_of(*co::make_cylinder(r, h), rho), ref::mass_properties(ref::cylinder{r, h}, rho));
        same(*co::mass_of(*co::make_box(r, h, c), rho), ref::mass_properties(ref::box{{r, h, c}}, rho));
    }
    // a capsule of half height 0 is the sphere
    const auto cap = *co::mass_of(*co::make_capsule(0.5, 0.0), 7.0);
    const auto sph = *co::mass_of(*co::make_sphere(0.5), 7.0);
    CHECK(std::abs(cap.mass - sph.mass) <= 1e-15 * sph.mass);
    CHECK(std::abs(cap.inertia_c[0][0] - sph.inertia_c[0][0]) <= 1e-15 * sph.inertia_c[0][0]);
    // a density that is not positive is refused as the mass it gives
    CHECK(co::mass_of(*co::make_sphere(1.0), 0.0).error == ctga::error_code::non_positive_mass);
}

TEST_CASE("collision: bad sizes are refused at construction, naming what is wrong") {
    using ctga::error_code;
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    CHECK(co::make_sphere(0.0).error == error_code::non_positive_size);
    CHECK(co::make_sphere(-1.0).error == error_code::non_positive_size);
    CHECK(co::make_sphere(nan).error == error_code::non_finite);
    CHECK(co::make_capsule(0.5, -0.1).error == error_code::non_positive_size);
    CHECK(co::make_capsule(0.0, 1.0).error == error_code::non_positive_size);
    CHECK(co::make_capsule(0.5, 0.0).error == error_code::none);  // a sphere
    CHECK(co::make_capsule(inf, 1.0).error == error_code::non_finite);
    CHECK(co::make_box(1.0, 0.0, 1.0).error == error_code::non_positive_size);
    CHECK(co::make_box(1.0, 1.0, nan).error == error_code::non_finite);
    CHECK(co::make_cylinder(1.0, 0.0).error == error_code::non_positive_size);
    CHECK(co::make_cylinder(-inf, 1.0).error == error_code::non_finite);
    CHECK(std::string_view(ctga::describe(error_code::non_positive_size)).find("radius") != std::string_view::npos);
}

TEST_CASE("collision: float shapes and queries") {
    const ctga::motor_map<float> I{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
    ctga::motor_map<float> P = I;
    P.t = {0, 0, 0.75f};
    const auto s = co::separation_of(co::half_space<float>{}, I, *co::make_capsule(0.25f, 1.0f), P);
    CHECK(s.distance == -0.5f);  // the lower end at z = −0.25, less the radius
    constexpr float d = [] {
        const ctga::motor_map<float> J{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
        ctga::motor_map<float> Q = J;
        Q.t = {3, 4, 0};
        return co::separation_of(*co::make_sphere(1.0f), J, *co::make_sphere(1.5f), Q).distance;
    }();
    static_assert(d == 2.5f, "separation_of in a constant expression");
}

namespace {
// A motor map turning by θ about the body x axis and placing the origin at t (written out here, not
// through the library's motor, so that the expected corners are independent of it).
ctga::motor_map<double> turned_about_x(double theta, const vec3<double>& t) {
    const double c = std::cos(theta), s = std::sin(theta);
    return {{{{1, 0, 0}, {0, c, -s}, {0, s, c}}}, t};
}
const ctga::motor_map<double> ground{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
}  // namespace

TEST_CASE("collision: manifolds: a box resting flat gives its face's four corners, tilted onto an edge that edge's two") {
    const co::box<double> b = *co::make_box(0.5, 0.3, 0.2);
    // flat, 0.01 into the ground: the four corners of the bottom face (z = −0.2, ids without bit 2)
    const ctga::motor_map<double> flat = turned_about_x(0, {1, 2, 0.19});
    const co::manifold<double> m = co::contact_of(co::half_space<double>{}, ground, b, flat, 0.005);
    REQUIRE(m.count == 4);
    CHECK(m.normal == vec3<double>{0, 0, 1});
    unsigned seen = 0;
    for (std::size_t i = 0; i < m.count; ++i) {
        const auto& p = m.points[i];
        CHECK((p.id & 4u) == 0u);
        seen |= 1u << p.id;
        CHECK(std::abs(p.separation + 0.01) <= 1e-15);
        CHECK(std::abs(p.point_b[0] - (1 + ((p.id & 1u) ? 0.5 : -0.5))) <= 1e-15);
        CHECK(std::abs(p.point_b[1] - (2 + ((p.id & 2u) ? 0.3 : -0.3))) <= 1e-15);
        CHECK(std::abs(p.point_a[2]) <= 1e-15);  // on the ground
    }
    CHECK(seen == 0b1111u);
    // tilted by 0.3 rad about x onto the edge y = +0.3 (or −0.3): the two corners of the lowest edge
    const double th = 0.3;
    const double lowest = std::min({0.3 * std::sin(th) - 0.2 * std::cos(th), -0.3 * std::sin(th) - 0.2 * std::cos(th)});
    const ctga::motor_map<double> tilted = turned_about_x(th, {0, 0, -lowest - 0.01});
    const co::manifold<double> e = co::contact_of(co::half_space<double>{}, ground, b, tilted, 0.005);
    REQUIRE(e.count == 2);
    for (std::size_t i = 0; i < e.count; ++i) {
        const auto& p = e.points[i];
        // the corner's height from the rotation written out: y' z' of (±0.3, −0.2) turned by θ
        const double y = (p.id & 2u) ? 0.3 : -0.3, z = (p.id & 4u) ? 0.2 : -0.2;
        CHECK(std::abs(p.point_b[2] - (std::sin(th) * y + std::cos(th) * z - lowest - 0.01)) <= 1e-15);
        CHECK(std::abs(p.separation + 0.01) <= 1e-15);
    }
    CHECK((e.points[0].id & 1u) != (e.points[1].id & 1u));  // the edge along x: both x ends
    // a small motion keeps the features, so the ids
    const co::manifold<double> later = co::contact_of(co::half_space<double>{}, ground, b, turned_about_x(1e-4, {1.001, 2, 0.1901}), 0.005);
    REQUIRE(later.count == 4);
    unsigned seen_later = 0;
    for (std::size_t i = 0; i < later.count; ++i) seen_later |= 1u << later.points[i].id;
    CHECK(seen_later == seen);
    // apart by more than the margin: no point; within it: the face's four, speculative (> 0)
    CHECK(co::contact_of(co::half_space<double>{}, ground, b, turned_about_x(0, {0, 0, 0.3}), 0.05).count == 0);
    const co::manifold<double> near = co::contact_of(co::half_space<double>{}, ground, b, turned_about_x(0, {0, 0, 0.22}), 0.05);
    CHECK(near.count == 4);
    CHECK(std::abs(near.points[0].separation - 0.02) <= 1e-15);
    // seen from the box: the normal reversed, the witnesses swapped
    const co::manifold<double> r = co::contact_of(b, flat, co::half_space<double>{}, ground, 0.005);
    CHECK(r.normal == vec3<double>{-0.0, -0.0, -1});
    CHECK(r.points[0].point_a == m.points[0].point_b);
}

TEST_CASE("collision: manifolds: a capsule lying down touches at both ends, two parallel capsules along their overlap") {
    const co::capsule<double> c = *co::make_capsule(0.1, 0.5);
    // lying along y (body z turned onto world y), 0.02 into the ground
    const co::manifold<double> lying = co::contact_of(co::half_space<double>{}, ground, c, turned_about_x(-std::acos(0.0), {0, 0, 0.08}), 0.01);
    REQUIRE(lying.count == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK(std::abs(lying.points[i].separation + 0.02) <= 1e-15);
        CHECK(std::abs(std::abs(lying.points[i].point_b[1]) - 0.5) <= 1e-15);
    }
    // standing: one end
    CHECK(co::contact_of(co::half_space<double>{}, ground, c, turned_about_x(0, {0, 0, 0.58}), 0.01).count == 1);
    // two capsules side by side along x, 0.15 apart (radii 0.1 each), B shifted by 0.4 along x:
    // the overlap of the cores x ∈ [−0.1, 0.5] (B's from −0.1 to 0.9), both ends at separation −0.05
    const ctga::motor_map<double> along_x{{{{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}}}, {0, 0, 0}};
    ctga::motor_map<double> beside = along_x;
    beside.t = {0.4, 0.15, 0};
    const co::manifold<double> side = co::contact_of(c, along_x, c, beside, 0.01);
    REQUIRE(side.count == 2);
    for (std::size_t i = 0; i < 2; ++i) CHECK(std::abs(side.points[i].separation + 0.05) <= 1e-15);
    CHECK(side.points[0].id != side.points[1].id);
    CHECK(std::abs(std::min(side.points[0].point_b[0], side.points[1].point_b[0]) + 0.1) <= 1e-15);
    CHECK(std::abs(std::max(side.points[0].point_b[0], side.points[1].point_b[0]) - 0.5) <= 1e-15);
    CHECK(std::abs(side.normal[1] - 1) <= 1e-15);
    // crossing: one point
    const co::manifold<double> cross = co::contact_of(c, along_x, c, turned_about_x(-std::acos(0.0), {0, 0, 0.15}), 0.01);
    CHECK(cross.count == 1);
    CHECK(std::abs(cross.points[0].separation + 0.05) <= 1e-15);
}

namespace {
// GJK's distance of the cores less the radii against the reference's signed distance, for pairs
// with no closed form, at random poses (±4.5: mostly apart): whenever GJK finds the cores apart,
// that is the shapes' signed distance (also overlapping, for a capsule or a sphere: its core grown
// by the radius) within `tol` relative to max(1, |d|); shapes apart by more than 1e-9 have cores
// apart; cores of radius 0 overlapping by more than 1e-9 are reported overlapping.
template <class KA, class KB>
void check_gjk(std::size_t count, const vec3<double>& centre, double tol, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    sizes s{rng};
    std::size_t apart = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const auto [a, ra] = KA::make(s);
        const auto [b, rb] = KB::make(s);
        const posed pa = random_posed(rng, centre, 4.5), pb = random_posed(rng, centre, 4.5);
        const co::gjk_result<double> g = co::gjk(a, pa.map, b, pb.map, 1e-14);
        const double want = static_cast<double>(ref::signed_distance(ra, pa.pose, rb, pb.pose).distance);
        const double got = g.distance - co::core_radius(a) - co::core_radius(b);
        CAPTURE(k, want, got, g.steps, g.overlap);
        if (!g.overlap) {
            ++apart;
            CHECK(std::abs(got - want) <= tol * std::max(1.0, std::abs(want)));
            // witnesses: the cores' points, g.distance apart
            CHECK(std::abs(co::length(linear3_sub(g.point_b, g.point_a)) - g.distance) <= 1e-12 * std::max(1.0, g.distance));
        }
        if (want > 1e-9) CHECK_FALSE(g.overlap);
        if (want < -1e-9 && co::core_radius(a) == 0 && co::core_radius(b) == 0) CHECK(g.overlap);
    }
    CHECK(apart >= count / 2);
}
}  // namespace

TEST_CASE("collision: GJK distances of separated cores against the reference (boxes exact, cylinders iterative)") {
    check_gjk<box_kind, box_kind>(30, {0, 0, 0}, 1e-12, 31);
    check_gjk<box_kind, box_kind>(16, {1e4, -1e4, 1e4}, 1e-11, 33);
    check_gjk<capsule_kind, box_kind>(30, {0, 0, 0}, 1e-12, 35);
    check_gjk<sphere_kind, box_kind>(16, {0, 0, 0}, 1e-12, 37);
    check_gjk<box_kind, cylinder_kind>(30, {0, 0, 0}, 1e-9, 39);
    check_gjk<cylinder_kind, cylinder_kind>(30, {0, 0, 0}, 1e-9, 41);
    check_gjk<capsule_kind, cylinder_kind>(30, {0, 0, 0}, 1e-9, 43);
}

TEST_CASE("collision: manifolds: a box resting on a box gives its bottom corners, a big box on a small one the small one's top") {
    const co::box<double> table = *co::make_box(2.0, 2.0, 0.5), small = *co::make_box(0.5, 0.3, 0.2);
    // on top, 0.01 deep, turned by 0.4 rad about z: its four bottom corners, each 0.01 below the top face
    const double c = std::cos(0.4), s = std::sin(0.4);
    const ctga::motor_map<double> on_top{{{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}}, {0.3, -0.2, 0.5 + 0.2 - 0.01}};
    const co::manifold<double> m = co::contact_of(table, ground, small, on_top, 0.005);
    REQUIRE(m.count == 4);
    CHECK(std::abs(m.normal[2] - 1) <= 1e-15);
    for (std::size_t i = 0; i < m.count; ++i) {
        const auto& p = m.points[i];
        CHECK(std::abs(p.separation + 0.01) <= 1e-15);
        CHECK(std::abs(p.point_b[2] - 0.49) <= 1e-15);
        CHECK(std::abs(p.point_a[2] - 0.5) <= 1e-15);
        // a corner of the small box: (±0.5, ±0.3) turned by 0.4 about (0.3, −0.2)
        const double x = p.point_b[0] - 0.3, y = p.point_b[1] + 0.2;
        const double bx = c * x + s * y, by = -s * x + c * y;  // back into the small box's frame
        CHECK(std::abs(std::abs(bx) - 0.5) <= 1e-14);
        CHECK(std::abs(std::abs(by) - 0.3) <= 1e-14);
    }
    for (std::size_t i = 0; i < m.count; ++i)
        for (std::size_t j = i + 1; j < m.count; ++j) CHECK(m.points[i].id != m.points[j].id);
    // the table resting on the small box (upside down): the contact is the small box's top face,
    // whose four corners are where the table's bottom face is clipped
    const ctga::motor_map<double> below{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, -0.2 - 0.5 + 0.01}};
    const co::manifold<double> u = co::contact_of(small, below, table, ground, 0.005);
    REQUIRE(u.count == 4);
    for (std::size_t i = 0; i < u.count; ++i) {
        CHECK(std::abs(u.points[i].separation + 0.01) <= 1e-15);
        CHECK(std::abs(std::abs(u.points[i].point_a[0]) - 0.5) <= 1e-15);
        CHECK(std::abs(std::abs(u.points[i].point_a[1]) - 0.3) <= 1e-15);
    }
    // apart by more than the margin: nothing; seen from the other box: reversed
    CHECK(co::contact_of(table, ground, small, ctga::motor_map<double>{on_top.R, {0.3, -0.2, 1.0}}, 0.005).count == 0);
    const co::manifold<double> r = co::contact_of(small, on_top, table, ground, 0.005);
    REQUIRE(r.count == 4);
    CHECK(std::abs(r.normal[2] + 1) <= 1e-15);
}

TEST_CASE("collision: box-box manifolds at random poses: distinct ids, witnesses on the boxes, separations along the normal") {
    // facts of any correct manifold, whatever produced it: each point's witnesses lie on (or in)
    // their box, point_b − point_a = separation · n, the separation at most the margin and at least
    // the penetration depth; no two points share an id (a solver warm starts by id)
    std::mt19937_64 rng(97);
    std::uniform_real_distribution<double> size(0.1, 0.6), margin_of(0.0, 0.05);
    const auto inside = [](const co::box<double>& b, const ctga::motor_map<double>& p, const vec3<double>& x) {
        const vec3<double> y = co::to_body(p, x);
        double out = 0;
        for (std::size_t k = 0; k < 3; ++k) out = std::max(out, std::abs(y[k]) - b.half[k]);
        return out;  // > 0: outside by that much
    };
    std::size_t manifolds = 0, points = 0;
    for (int it = 0; it < 3000; ++it) {
        const co::box<double> a = *co::make_box(size(rng), size(rng), size(rng)), b = *co::make_box(size(rng), size(rng), size(rng));
        const ctga::motor_map<double> pa = random_posed(rng, {0, 0, 0}, 0.5).map, pb = random_posed(rng, {0, 0, 0}, 0.5).map;
        const double margin = it % 2 ? 0.0 : margin_of(rng);
        const co::manifold<double> m = co::contact_of(a, pa, b, pb, margin);
        const co::separation<double> d = co::separation_of(a, pa, b, pb);
        if (m.count == 0) {
            CHECK(d.distance > margin - 1e-12);
            continue;
        }
        ++manifolds, points += m.count;
        for (std::size_t i = 0; i < m.count; ++i) {
            const co::contact_point<double>& c = m.points[i];
            CHECK(inside(a, pa, c.point_a) <= 1e-12);
            CHECK(inside(b, pb, c.point_b) <= 1e-12);
            CHECK(c.separation <= margin + 1e-12);
            CHECK(c.separation >= d.distance - 1e-12);
            for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(c.point_b[k] - c.point_a[k] - c.separation * m.normal[k]) <= 1e-12);
            for (std::size_t j = i + 1; j < m.count; ++j) CHECK(c.id != m.points[j].id);
        }
    }
    CHECK(manifolds > 1000);
    CHECK(points > 2 * manifolds);  // faces as well as edges
}

TEST_CASE("collision: a contact's normal force is a line, a co-screw whose pairing with a body's screw is the point's normal speed") {
    std::mt19937_64 rng(91);
    std::normal_distribution<double> g;
    for (int k = 0; k < 50; ++k) {
        const vec3<double> x{g(rng), g(rng), g(rng)}, w{g(rng), g(rng), g(rng)}, v{g(rng), g(rng), g(rng)};
        vec3<double> n{g(rng), g(rng), g(rng)};
        n = ctga::linear3::scale(1 / co::length(n), n);
        const ctga::coscrew<double> P = co::line_of_action(x, n);
        // a line: moment ⟂ direction
        CHECK(std::abs(P[0] * P[3] + P[1] * P[4] + P[2] * P[5]) <= 1e-14);
        // the pairing (the paper's P ∨ (Q0 ∧ s)) is the speed along n of the body point at x
        const ctga::screw<double> s{w[0], w[1], w[2], v[0], v[1], v[2]};
        const double speed = ctga::linear3::dot(n, ctga::linear3::add(v, ctga::linear3::cross(w, x)));
        CHECK(std::abs(ctga::pairing(P, s) - speed) <= 1e-13);
    }
}
