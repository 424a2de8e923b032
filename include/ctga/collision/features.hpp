// A convex shape's support feature along a direction d: the part of its core farthest along d,
// as the points a contact manifold is cut from (convex_manifolds.hpp):
//   a face (a polygon, counter-clockwise about its outward normal) when a face normal is within
//   the feature angle of d (cos ≥ face_cosine), an edge (a segment) when an edge is perpendicular
//   to d within that angle, else the one support point.
// A box: its face, edge or corner by the alignment of its axes with d; a hull: its best-aligned
// face, else the edge at the support vertex most perpendicular to d, else that vertex; a cylinder:
// its cap as the four rim points on its x and y axes, or its side as the segment of the two rims'
// points along d; a capsule: its segment, or an end; a sphere: its centre. Every point carries the
// id of the feature it is (a corner, a vertex, an end, a rim point), the feature its own id (a
// face, an edge), the same from step to step while the shapes keep touching by them. The
// points are of the core: the surface lies core_radius farther along the normal.
// The angle (face_cosine = 0.999: 2.6°) lets a face resting tilted by a little keep all its corners
// as points, each with its own separation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "ctga/collision/box.hpp"
#include "ctga/collision/capsule.hpp"
#include "ctga/collision/cylinder.hpp"
#include "ctga/collision/hull.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/collision/sphere.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {

inline constexpr std::size_t max_feature_points = 32;

template <class T>
struct feature {
    std::size_t count = 0;  // 1 a point, 2 a segment, ≥ 3 a face
    std::array<vec3<T>, max_feature_points> x{};  // world points of the core
    std::array<std::uint32_t, max_feature_points> id{};
    vec3<T> normal{};   // a face's outward normal (else the direction asked)
    std::uint32_t which = 0;  // the feature's own id
};

namespace feature_detail {
template <class T>
inline constexpr T face_cosine = T(0.999);
template <class T>
inline constexpr T edge_sine = T(0.0447);  // sin of the same angle: √(1 − 0.999²)

template <class T>
[[nodiscard]] constexpr T absolute(const T& x) noexcept {
    return x < T(0) ? -x : x;
}
template <class T>
constexpr void add(feature<T>& f, const vec3<T>& x, std::uint32_t id) noexcept {
    f.x[f.count] = x;
    f.id[f.count] = id;
    ++f.count;
}
}  // namespace feature_detail

template <class T>
[[nodiscard]] constexpr feature<T> support_feature(const sphere<T>&, const motor_map<T>& p, const vec3<T>& d) noexcept {
    feature<T> f;
    f.normal = d;
    feature_detail::add(f, p.t, 0);
    return f;
}

template <class T>
[[nodiscard]] constexpr feature<T> support_feature(const capsule<T>& c, const motor_map<T>& p, const vec3<T>& d) noexcept {
    using namespace feature_detail;
    feature<T> f;
    f.normal = d;
    const vec3<T> axis = axis_of(p, 2);
    const T k = linear3::dot(axis, d);
    if (absolute(k) <= edge_sine<T>) {
        add(f, linear3::add_scaled(p.t, -c.half_height, axis), 0);
        add(f, linear3::add_scaled(p.t, c.half_height, axis), 1);
        f.which = 2;
    } else {
        add(f, linear3::add_scaled(p.t, k < T(0) ? -c.half_height : c.half_height, axis), k < T(0) ? 0u : 1u);
        f.which = k < T(0) ? 0u : 1u;
    }
    return f;
}

// Corner c of a box: bit i set for +h_i.
template <class T>
[[nodiscard]] constexpr feature<T> support_feature(const box<T>& b, const motor_map<T>& p, const vec3<T>& d) noexcept {
    using namespace feature_detail;
    feature<T> f;
    f.normal = d;
    std::array<T, 3> c{};
    std::size_t big = 0, small = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        c[i] = linear3::dot(d, axis_of(p, i));
        if (absolute(c[i]) > absolute(c[big])) big = i;
        if (absolute(c[i]) < absolute(c[small])) small = i;
    }
    const auto corner = [&](std::uint32_t bits) {
        vec3<T> x = p.t;
        for (std::size_t i = 0; i < 3; ++i) x = linear3::add_scaled(x, (bits >> i) & 1u ? b.half[i] : -b.half[i], axis_of(p, i));
        return x;
    };
    std::uint32_t base = 0;  // the support corner's bits
    for (std::size_t i = 0; i < 3; ++i)
        if (!(c[i] < T(0))) base |= 1u << i;
    if (absolute(c[big]) >= face_cosine<T>) {
        // the face of axis `big`, its corners counter-clockwise about ±x_big: (u, v) = (+,+), (−,+), (−,−), (+,−)
        // with u, v the next two axes, which is counter-clockwise for +x_big and reversed for −x_big
        const std::size_t u = (big + 1) % 3, v = (big + 2) % 3;
        const bool plus = c[big] > T(0);
        constexpr int su[4] = {1, 0, 0, 1}, sv[4] = {1, 1, 0, 0};
        for (std::size_t k = 0; k < 4; ++k) {
            const std::size_t m = plus ? k : 3 - k;
            const std::uint32_t bits = (plus ? 1u << big : 0u) | (std::uint32_t(su[m]) << u) | (std::uint32_t(sv[m]) << v);
            add(f, corner(bits), bits);
        }
        f.normal = linear3::scale(plus ? T(1) : T(-1), axis_of(p, big));
        f.which = std::uint32_t(2 * big + (plus ? 1 : 0));
    } else if (absolute(c[small]) <= edge_sine<T>) {
        const std::uint32_t lo = base & ~(1u << small), hi = base | (1u << small);
        add(f, corner(lo), lo);
        add(f, corner(hi), hi);
        f.which = 8 + 8 * std::uint32_t(small) + lo;
    } else {
        add(f, corner(base), base);
        f.which = 64 + base;
    }
    return f;
}

// The cap's four rim points on the body's ±x, ±y (counter-clockwise about the cap's normal), or
// the side's segment along d, or the rim's support point.
template <class T>
[[nodiscard]] constexpr feature<T> support_feature(const cylinder<T>& c, const motor_map<T>& p, const vec3<T>& d) noexcept {
    using namespace feature_detail;
    feature<T> f;
    f.normal = d;
    const vec3<T> axis = axis_of(p, 2);
    const T k = linear3::dot(axis, d);
    const T side = k < T(0) ? T(-1) : T(1);
    if (absolute(k) >= face_cosine<T>) {
        const vec3<T> centre = linear3::add_scaled(p.t, side * c.half_height, axis);
        const vec3<T> ex = axis_of(p, 0), ey = linear3::scale(side, axis_of(p, 1));
        add(f, linear3::add_scaled(centre, c.radius, ex), 0);
        add(f, linear3::add_scaled(centre, c.radius, ey), 1);
        add(f, linear3::add_scaled(centre, -c.radius, ex), 2);
        add(f, linear3::add_scaled(centre, -c.radius, ey), 3);
        f.normal = linear3::scale(side, axis);
        f.which = side > T(0) ? 1u : 0u;
    } else if (absolute(k) <= edge_sine<T>) {
        const vec3<T> radial = linear3::add_scaled(d, -k, axis);
        const vec3<T> out = linear3::add_scaled(p.t, c.radius / length(radial), radial);
        add(f, linear3::add_scaled(out, -c.half_height, axis), 4);
        add(f, linear3::add_scaled(out, c.half_height, axis), 5);
        f.which = 2;
    } else {
        add(f, to_world(p, core_support(c, linear3::apply_transposed(p.R, d))), 6);
        f.which = 3;
    }
    return f;
}

template <class T, std::size_t N>
[[nodiscard]] constexpr feature<T> support_feature(const convex_hull<T, N>& h, const motor_map<T>& p, const vec3<T>& d) noexcept {
    using namespace feature_detail;
    feature<T> f;
    f.normal = d;
    const vec3<T> u = linear3::apply_transposed(p.R, d);  // d in the hull's frame
    std::size_t best = 0;
    for (std::size_t k = 1; k < h.face_count; ++k)
        if (linear3::dot(h.face[k].normal, u) > linear3::dot(h.face[best].normal, u)) best = k;
    const hull_face<T>& F = h.face[best];
    if (linear3::dot(F.normal, u) >= face_cosine<T> && F.count <= max_feature_points) {
        for (std::size_t k = 0; k < F.count; ++k) add(f, to_world(p, h.vertex[h.face_vertex[F.first + k]]), h.face_vertex[F.first + k]);
        f.normal = linear3::apply(p.R, F.normal);
        f.which = std::uint32_t(best);
        return f;
    }
    std::size_t v = 0;
    for (std::size_t k = 1; k < h.vertex_count; ++k)
        if (linear3::dot(h.vertex[k], u) > linear3::dot(h.vertex[v], u)) v = k;
    // the edge at v most perpendicular to d
    std::size_t other = h.vertex_count;
    T least = edge_sine<T>;
    for (std::size_t e = 0; e < h.edge_count; ++e) {
        if (h.edge[e].a != v && h.edge[e].b != v) continue;
        const std::size_t w = h.edge[e].a == v ? h.edge[e].b : h.edge[e].a;
        const vec3<T> t = linear3::sub(h.vertex[w], h.vertex[v]);
        const T s = absolute(linear3::dot(t, u)) / length(t);
        if (s <= least) least = s, other = w;
    }
    add(f, to_world(p, h.vertex[v]), std::uint32_t(v));
    if (other < h.vertex_count) add(f, to_world(p, h.vertex[other]), std::uint32_t(other));
    f.which = other < h.vertex_count ? std::uint32_t(0x10000 + (v < other ? v * 8192 + other : other * 8192 + v)) : std::uint32_t(0x8000000 + v);
    return f;
}

}  // namespace ctga::collision
