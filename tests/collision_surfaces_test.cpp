// Triangle meshes and height fields (collision/mesh.hpp, height_field.hpp, surface_queries.hpp):
// the separation of convex shapes from a bumpy surface against the independent reference (the
// least over the triangles of the reference's signed distance to each, a triangle being the
// reference's hull of its three corners), the hierarchy's branch and bound equal to the loop over
// every triangle, near and far; a height field equal to the mesh of its triangles; ray casts
// against the loop over every triangle and a flat field's closed form; contact manifolds of a box
// on a floor of many triangles and in a crease; bad meshes and fields refused.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <ctga/collision/narrowphase.hpp>
#include <ctga/collision/shape_set.hpp>

#include "support/catch.hpp"
#include "support/collision_fixtures.hpp"
#include "support/collision_reference.hpp"

namespace {
using namespace collision_fixtures;

// A bumpy n × n grid of heights, spacing 0.5: the same surface as a height field and as a mesh.
struct terrain {
    std::size_t n;
    double spacing = 0.5;
    std::vector<double> height;
    std::vector<vec3<double>> vertex;
    std::vector<std::array<std::uint32_t, 3>> index;
    std::vector<co::bvh_node<double>> mesh_nodes, field_nodes;
    std::vector<std::uint32_t> mesh_order, field_order;

    explicit terrain(std::size_t size, std::uint64_t seed) : n(size) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> bump(-0.3, 0.3);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                height.push_back(bump(rng));
                vertex.push_back({double(j) * spacing, double(i) * spacing, height.back()});
            }
        for (std::uint32_t i = 0; i + 1 < n; ++i)
            for (std::uint32_t j = 0; j + 1 < n; ++j) {
                const std::uint32_t p00 = i * std::uint32_t(n) + j, p01 = p00 + 1, p10 = p00 + std::uint32_t(n), p11 = p10 + 1;
                index.push_back({p00, p01, p11});
                index.push_back({p00, p11, p10});
            }
        mesh_nodes.resize(co::bvh_nodes_for(index.size()));
        mesh_order.resize(index.size());
        field_nodes.resize(co::bvh_nodes_for((n - 1) * (n - 1)));
        field_order.resize((n - 1) * (n - 1));
    }
    co::triangle_mesh<double> mesh() {
        return *co::make_triangle_mesh<double>(vertex, index, mesh_nodes, mesh_order);
    }
    co::height_field<double> field() { return *co::make_height_field<double>(n, n, spacing, spacing, height, field_nodes, field_order); }
    std::vector<ref::hull> reference_triangles(const ref::pose&) const {
        std::vector<ref::hull> out;
        for (const auto& t : index) {
            ref::hull h;
            for (std::uint32_t v : t) h.points.push_back({vertex[v][0], vertex[v][1], vertex[v][2]});
            out.push_back(h);
        }
        return out;
    }
};

// The separation of B from the surface by looping over every triangle (no hierarchy).
template <class B>
co::separation<double> every_triangle(const co::triangle_mesh<double>& m, const ctga::motor_map<double>& pm, const B& b,
                                      const ctga::motor_map<double>& pb) {
    co::separation<double> best{std::numeric_limits<double>::infinity(), {}, {}, {}};
    for (std::uint32_t i = 0; i < m.index.size(); ++i)
        m.for_each_triangle(i, [&](const co::triangle<double>& t, std::uint32_t) {
            const co::separation<double> s = co::separation_of(t, pm, b, pb);
            if (s.distance < best.distance) best = s;
        });
    return best;
}

template <class K>
void check_against_reference(terrain& T, std::uint64_t seed, std::size_t count) {
    std::mt19937_64 rng(seed);
    sizes s{rng};
    const auto mesh = T.mesh();
    const auto field = T.field();
    const posed ground = random_posed(rng, {0, 0, 0}, 1.0);
    const auto tris = T.reference_triangles(ground.pose);
    std::size_t touching = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const auto [b, rb] = K::make(s);
        // above the middle of the terrain, in its frame, at heights from inside it to 2 m above
        std::uniform_real_distribution<double> across(0.3, double(T.n - 1) * T.spacing - 0.3), up(-0.3, 2.0);
        const double x = across(rng), y = across(rng), z = up(rng);
        posed pb = random_posed(rng, {0, 0, 0}, 0.0);
        pb.map.t = co::to_world(ground.map, vec3<double>{x, y, z});
        for (std::size_t i = 0; i < 3; ++i) pb.pose.t[i] = pb.map.t[i];
        const co::separation<double> got = co::separation_of(mesh, ground.map, b, pb.map);
        ref::real want = std::numeric_limits<ref::real>::infinity();
        for (const ref::hull& t : tris) want = std::min(want, ref::signed_distance(t, ground.pose, rb, pb.pose).distance);
        CAPTURE(k, got.distance, static_cast<double>(want));
        CHECK(std::abs(got.distance - static_cast<double>(want)) <= 1e-9);
        touching += got.distance < 0.1 ? 1 : 0;
        // the hierarchy's answer is the loop's, and the height field's the mesh's
        const co::separation<double> loop = every_triangle(mesh, ground.map, b, pb.map);
        CHECK(std::abs(got.distance - loop.distance) <= 1e-13);  // (the loop in the world frame: rounding apart)
        CHECK(co::separation_of(field, ground.map, b, pb.map).distance == got.distance);
        for (std::size_t i = 0; i < 3; ++i) CHECK(std::abs(got.point_b[i] - got.point_a[i] - got.distance * got.normal[i]) <= 1e-12);
    }
    CHECK(touching >= 1);
}
}  // namespace

TEST_CASE("collision: a bumpy mesh and height field against the reference, the hierarchy equal to every triangle") {
    terrain T(5, 301);
    check_against_reference<sphere_kind>(T, 303, 8);
    check_against_reference<box_kind>(T, 305, 8);
    check_against_reference<capsule_kind>(T, 307, 6);
    check_against_reference<hull_kind>(T, 309, 6);
    // a far query on a large terrain: the branch and bound equals the loop
    terrain big(40, 311);
    const auto mesh = big.mesh();
    std::mt19937_64 rng(313);
    for (int k = 0; k < 20; ++k) {
        const posed pb = random_posed(rng, {10, 10, 0}, 30.0);
        const auto b = *co::make_box(0.3, 0.2, 0.4);
        const ctga::motor_map<double> id{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
        CHECK(std::abs(co::separation_of(mesh, id, b, pb.map).distance - every_triangle(mesh, id, b, pb.map).distance) <= 1e-12);
    }
}

TEST_CASE("collision: ray casts on a mesh equal the nearest of every triangle, on a flat field the plane's closed form") {
    terrain T(12, 321);
    const auto mesh = T.mesh();
    const ctga::motor_map<double> id{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
    std::mt19937_64 rng(323);
    std::uniform_real_distribution<double> u(0.0, 5.5), dir(-1, 1);
    std::size_t hits = 0;
    for (int k = 0; k < 200; ++k) {
        vec3<double> d{dir(rng), dir(rng), -1.0};
        const double l = co::length(d);
        for (double& c : d) c /= l;
        const auto r = co::make_ray(vec3<double>{u(rng), u(rng), 1.0}, d, 10.0);
        const auto got = co::ray_cast(mesh, id, r);
        double want = 10.0;
        for (std::uint32_t i = 0; i < T.index.size(); ++i)
            mesh.for_each_triangle(i, [&](const co::triangle<double>& t, std::uint32_t) { want = std::min(want, co::ray_distance(t, r.origin, d, want)); });
        CHECK(got.hit == (want < 10.0));
        if (got.hit) {
            ++hits;
            CHECK(got.distance == want);
            CHECK(got.normal[2] > 0);  // facing the ray, which comes from above
        }
    }
    CHECK(hits > 100);
    // a flat field at height 0.25, posed turned and moved: the plane's distance along the ray
    std::vector<double> flat(16, 0.25);
    std::vector<co::bvh_node<double>> nodes(co::bvh_nodes_for(9));
    std::vector<std::uint32_t> order(9);
    const auto field = *co::make_height_field<double>(4, 4, 1.0, 1.0, flat, nodes, order);
    const posed p = random_posed(rng, {100, -50, 3}, 0.0);
    for (int k = 0; k < 20; ++k) {
        std::uniform_real_distribution<double> inside(0.5, 2.5);  // (the ray drifts at most 0.35 across)
        const vec3<double> o = co::to_world(p.map, vec3<double>{inside(rng), inside(rng), 2.0});
        vec3<double> d = ctga::linear3::apply(p.map.R, vec3<double>{dir(rng) * 0.2, dir(rng) * 0.2, -1.0});
        const double l = co::length(d);
        for (double& c : d) c /= l;
        const auto got = co::ray_cast(field, p.map, co::make_ray(o, d, 10.0));
        const vec3<double> n = co::axis_of(p.map, 2);
        const double want = -(ctga::linear3::dot(n, linear3_sub(o, p.map.t)) - 0.25) / ctga::linear3::dot(n, d);
        REQUIRE(got.hit);
        CHECK(std::abs(got.distance - want) <= 1e-12 * 100);
        CHECK(gap(got.normal, ref::vec3{n[0], n[1], n[2]}) <= 1e-15);
    }
}

TEST_CASE("collision: a box on a floor of many triangles is one manifold of its four corners, in a crease, two") {
    // a flat 6 × 6 field, spacing 0.25: the box's face spans several cells
    std::vector<double> flat(36, 0.0);
    std::vector<co::bvh_node<double>> nodes(co::bvh_nodes_for(25));
    std::vector<std::uint32_t> order(25);
    const auto field = *co::make_height_field<double>(6, 6, 0.25, 0.25, flat, nodes, order);
    const ctga::motor_map<double> id{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
    const auto box = *co::make_box(0.3, 0.2, 0.1);
    const ctga::motor_map<double> pb{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0.6, 0.6, 0.099}};
    const auto m = co::contact_of(field, id, box, pb, 0.0);
    REQUIRE(m.count == 4);
    CHECK(std::abs(m.normal[2] - 1) <= 1e-15);
    for (std::size_t i = 0; i < 4; ++i) {
        CHECK(std::abs(m.points[i].separation + 0.001) <= 1e-14);
        CHECK(std::abs(std::abs(m.points[i].point_b[0] - 0.6) - 0.3) <= 1e-14);
        CHECK(std::abs(std::abs(m.points[i].point_b[1] - 0.6) - 0.2) <= 1e-14);
        for (std::size_t j = i + 1; j < 4; ++j) CHECK(m.points[i].id != m.points[j].id);
    }
    // a V-shaped crease along y (walls at ±45°): a box sunk into it touches both walls
    const std::vector<vec3<double>> v{{-1, -1, 1}, {-1, 1, 1}, {0, -1, 0}, {0, 1, 0}, {1, -1, 1}, {1, 1, 1}};
    const std::vector<std::array<std::uint32_t, 3>> tri{{0, 2, 3}, {0, 3, 1}, {2, 4, 5}, {2, 5, 3}};
    std::vector<co::bvh_node<double>> mn(co::bvh_nodes_for(4));
    std::vector<std::uint32_t> mo(4);
    const auto crease = *co::make_triangle_mesh<double>(v, tri, mn, mo);
    std::array<co::manifold<double>, 4> out{};
    const ctga::motor_map<double> in{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0.3}};
    const auto c = co::contacts_of(crease, id, *co::make_sphere(0.25), in, 0.01, std::span<co::manifold<double>>(out));
    REQUIRE(c.count == 2);
    CHECK(!c.overflow);
    for (std::size_t k = 0; k < 2; ++k) {
        CHECK(std::abs(std::abs(out[k].normal[0]) - std::sqrt(0.5)) <= 1e-12);
        CHECK(std::abs(out[k].points[0].separation - (0.3 * std::sqrt(0.5) - 0.25)) <= 1e-12);
    }
}

TEST_CASE("collision: bad meshes and height fields are refused, naming what is wrong") {
    std::vector<co::bvh_node<double>> nodes(16);
    std::vector<std::uint32_t> order(8);
    const std::vector<vec3<double>> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    const auto mesh = [&](std::vector<vec3<double>> vs, std::vector<std::array<std::uint32_t, 3>> t, std::size_t room = 16) {
        return co::make_triangle_mesh<double>(vs, t, std::span(nodes).first(room), order).error;
    };
    CHECK(mesh(v, {{0, 1, 2}}) == ctga::error_code::none);
    CHECK(mesh(v, {{0, 1, 3}}) == ctga::error_code::degenerate_triangle);  // in line
    CHECK(mesh(v, {{0, 1, 1}}) == ctga::error_code::degenerate_triangle);  // a repeated corner
    CHECK(mesh(v, {{0, 1, 4}}) == ctga::error_code::bad_index);
    CHECK(mesh({{0, 0, 0}, {1, 0, std::numeric_limits<double>::quiet_NaN()}, {0, 1, 0}}, {{0, 1, 2}}) == ctga::error_code::non_finite);
    CHECK(mesh(v, {}) == ctga::error_code::size_mismatch);
    CHECK(mesh(v, {{0, 1, 2}, {1, 2, 3}}, 2) == ctga::error_code::capacity_exceeded);
    const std::vector<double> h(6, 0.0);
    const auto field = [&](std::size_t r, std::size_t c, double dx, std::vector<double> hs) {
        return co::make_height_field<double>(r, c, dx, 1.0, hs, nodes, order).error;
    };
    CHECK(field(2, 3, 1.0, h) == ctga::error_code::none);
    CHECK(field(3, 3, 1.0, h) == ctga::error_code::size_mismatch);
    CHECK(field(1, 6, 1.0, h) == ctga::error_code::size_mismatch);
    CHECK(field(2, 3, 0.0, h) == ctga::error_code::non_positive_size);
    CHECK(field(2, 3, 1.0, {0, 0, 0, std::numeric_limits<double>::infinity(), 0, 0}) == ctga::error_code::non_finite);
}

TEST_CASE("collision: a scene's shape kinds as variants: the queries visit only their kinds' pairs, each answer the pair's own") {
    using moving = co::shape<co::sphere<double>, co::box<double>, co::convex_hull<double, 24>>;
    using fixed = co::shape<co::half_space<double>, co::height_field<double>>;
    std::vector<double> h(25, 0.0);
    for (std::size_t i = 0; i < h.size(); ++i) h[i] = 0.05 * double(i % 3);
    std::vector<co::bvh_node<double>> nodes(co::bvh_nodes_for(16));
    std::vector<std::uint32_t> order(16);
    const std::array<fixed, 2> ground{co::half_space<double>{}, *co::make_height_field<double>(5, 5, 0.5, 0.5, h, nodes, order)};
    std::mt19937_64 rng(331);
    sizes s{rng};
    const std::array<moving, 3> bodies{*co::make_sphere(0.3), *co::make_box(0.3, 0.2, 0.1), hull_kind::make(s).first};
    const ctga::motor_map<double> id{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
    for (int k = 0; k < 6; ++k) {
        posed p = random_posed(rng, {1, 1, 0.2}, 0.3);
        for (const moving& b : bodies) {
            for (const fixed& g : ground) {
                const co::separation<double> got = co::separation_of(g, id, b, p.map);
                const co::separation<double> want = std::visit([&](const auto& x, const auto& y) { return co::separation_of(x, id, y, p.map); }, g, b);
                CHECK(got.distance == want.distance);
                const co::manifold<double> m = co::contact_of(b, p.map, g, id, 0.05);
                CHECK(m.count <= 4);
            }
            for (const moving& c : bodies) {
                const double direct = std::visit([&](const auto& x, const auto& y) { return co::separation_of(x, p.map, y, id).distance; }, b, c);
                CHECK(co::separation_of(b, p.map, c, id).distance == direct);
            }
            // its box holds it: the support points along ±axes lie within
            const co::aabb<double> box = co::bounds_of(b, p.map);
            for (std::size_t k3 = 0; k3 < 3; ++k3) CHECK(box.lower[k3] < box.upper[k3]);
        }
    }
}

TEST_CASE("collision: float meshes and height fields") {
    std::vector<float> h(16, 0.5f);
    std::vector<co::bvh_node<float>> nodes(co::bvh_nodes_for(9));
    std::vector<std::uint32_t> order(9);
    const auto field = co::make_height_field<float>(4, 4, 1.0f, 1.0f, h, nodes, order);
    REQUIRE(field);
    const ctga::motor_map<float> id{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
    const ctga::motor_map<float> above{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {1.3f, 1.7f, 1.0f}};
    const co::separation<float> s = co::separation_of(*field, id, *co::make_sphere(0.25f), above);
    CHECK(std::abs(s.distance - 0.25f) <= 1e-6f);
    CHECK(std::abs(s.normal[2] - 1.0f) <= 1e-6f);
    const auto hit = co::ray_cast(*field, id, co::make_ray(ctga::vec3<float>{1.3f, 1.7f, 2.0f}, ctga::vec3<float>{0, 0, -1}, 5.0f));
    REQUIRE(hit.hit);
    CHECK(std::abs(hit.distance - 1.5f) <= 1e-6f);
    const co::manifold<float> m = co::contact_of(*field, id, *co::make_box(0.3f, 0.2f, 0.1f), ctga::motor_map<float>{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {1.5f, 1.5f, 0.599f}}, 0.0f);
    CHECK(m.count == 4);
}
