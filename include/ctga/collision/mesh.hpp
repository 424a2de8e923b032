// A triangle mesh, for static surroundings: vertices and triangles (three vertex indices each,
// counter-clockwise seen from the side their normal (b − a) × (c − a) points to) in its body's
// frame, with a bounding-volume hierarchy over the triangles (bvh.hpp). The mesh is a surface,
// not a solid: each triangle is two-sided (triangle.hpp), so that a shape is pushed out of it by
// the shorter way, and a shape wholly inside a closed mesh does not touch it.
// The mesh reads the caller's vertices and triangles (spans: kept alive by the caller) and builds
// its hierarchy into the caller's node and order storage (bvh_nodes_for(n) nodes, n indices):
// no heap. Reported at construction: size_mismatch (no triangles), non_finite (a vertex), bad_index (an index past the
// vertices), degenerate_triangle (area ≤ 64 ε of its two longer edges' product: two corners
// equal or all three in line), capacity_exceeded (the storage too small).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "ctga/collision/aabb.hpp"
#include "ctga/collision/bvh.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/collision/triangle.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

template <class T = double>
struct triangle_mesh {
    std::span<const vec3<T>> vertex;
    std::span<const std::array<std::uint32_t, 3>> index;
    bvh<T> tree;  // its items: the triangles

    // Calls visit(triangle, id) for the triangle of item i (id = i).
    template <class Visit>
    constexpr void for_each_triangle(std::uint32_t i, Visit&& visit) const noexcept {
        visit(triangle<T>{{vertex[index[i][0]], vertex[index[i][1]], vertex[index[i][2]]}}, i);
    }
};

namespace mesh_detail {
template <class T>
[[nodiscard]] constexpr aabb<T> bounds(const triangle<T>& t) noexcept {
    return merged(merged(aabb<T>{t.x[0], t.x[0]}, aabb<T>{t.x[1], t.x[1]}), aabb<T>{t.x[2], t.x[2]});
}
// Zero area to rounding: |e1 × e2| ≤ 64 ε |e1| |e2| for the two longer edges.
template <class T>
[[nodiscard]] constexpr bool degenerate(const triangle<T>& t) noexcept {
    const vec3<T> e0 = linear3::sub(t.x[1], t.x[0]), e1 = linear3::sub(t.x[2], t.x[1]), e2 = linear3::sub(t.x[0], t.x[2]);
    const T l0 = length(e0), l1 = length(e1), l2 = length(e2);
    const T shortest = l0 < l1 ? (l0 < l2 ? l0 : l2) : (l1 < l2 ? l1 : l2);
    const T product = l0 * l1 * l2 / (shortest > T(0) ? shortest : T(1));
    return !(length(linear3::cross(e0, e1)) > T(64) * std::numeric_limits<T>::epsilon() * product) || !(shortest > T(0));
}
}  // namespace mesh_detail

template <class T>
[[nodiscard]] constexpr checked<triangle_mesh<T>> make_triangle_mesh(std::span<const vec3<T>> vertices,
                                                                     std::span<const std::array<std::uint32_t, 3>> triangles,
                                                                     std::span<bvh_node<T>> nodes, std::span<std::uint32_t> order) noexcept {
    for (const vec3<T>& v : vertices)
        if (!is_finite(v[0]) || !is_finite(v[1]) || !is_finite(v[2])) return {{}, error_code::non_finite};
    for (const auto& t : triangles) {
        if (t[0] >= vertices.size() || t[1] >= vertices.size() || t[2] >= vertices.size()) return {{}, error_code::bad_index};
        if (mesh_detail::degenerate(triangle<T>{{vertices[t[0]], vertices[t[1]], vertices[t[2]]}})) return {{}, error_code::degenerate_triangle};
    }
    if (triangles.empty()) return {{}, error_code::size_mismatch};
    if (nodes.size() < bvh_nodes_for(triangles.size()) || order.size() < triangles.size()) return {{}, error_code::capacity_exceeded};
    triangle_mesh<T> m{vertices, triangles, {}};
    m.tree = build_bvh<T>(
        triangles.size(),
        [&](std::uint32_t i) {
            aabb<T> b{};
            m.for_each_triangle(i, [&](const triangle<T>& t, std::uint32_t) { b = mesh_detail::bounds(t); });
            return b;
        },
        nodes, order);
    return {m, error_code::none};
}

}  // namespace ctga::collision
