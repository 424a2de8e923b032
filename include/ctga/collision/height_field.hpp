// A height field, for static ground: heights h_ij on a grid of `rows` × `columns` points, point
// (i, j) at (j dx, i dy, h_ij) in its body's frame (row-major: heights[i · columns + j]). Cell
// (i, j) is the two triangles (p_ij, p_i,j+1, p_i+1,j+1) and (p_ij, p_i+1,j+1, p_i+1,j),
// counter-clockwise seen from above; like a mesh's (mesh.hpp), they are two-sided surfaces. The
// cells are the items of a bounding-volume hierarchy (bvh.hpp) in the caller's storage
// (bvh_nodes_for(cells) nodes, cells indices), so that the queries of surface_queries.hpp serve a
// mesh and a height field alike.
// Reported at construction: size_mismatch (fewer than 2 × 2 points, or heights not rows × columns),
// non_positive_size (dx or dy ≤ 0), non_finite (a height or a spacing), capacity_exceeded (storage).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "ctga/collision/aabb.hpp"
#include "ctga/collision/bvh.hpp"
#include "ctga/collision/triangle.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

template <class T = double>
struct height_field {
    std::size_t rows, columns;
    T dx, dy;
    std::span<const T> height;
    bvh<T> tree;  // its items: the cells, (i, j) as i (columns − 1) + j

    [[nodiscard]] constexpr vec3<T> point(std::size_t i, std::size_t j) const noexcept {
        return {T(j) * dx, T(i) * dy, height[i * columns + j]};
    }
    // Calls visit(triangle, id) for the two triangles of cell c (ids 2c, 2c + 1).
    template <class Visit>
    constexpr void for_each_triangle(std::uint32_t c, Visit&& visit) const noexcept {
        const std::size_t i = c / (columns - 1), j = c % (columns - 1);
        const vec3<T> p00 = point(i, j), p01 = point(i, j + 1), p11 = point(i + 1, j + 1), p10 = point(i + 1, j);
        visit(triangle<T>{{p00, p01, p11}}, 2 * c);
        visit(triangle<T>{{p00, p11, p10}}, 2 * c + 1);
    }
};

template <class T>
[[nodiscard]] constexpr checked<height_field<T>> make_height_field(std::size_t rows, std::size_t columns, const T& dx, const T& dy,
                                                                   std::span<const T> heights, std::span<bvh_node<T>> nodes,
                                                                   std::span<std::uint32_t> order) noexcept {
    if (rows < 2 || columns < 2 || heights.size() != rows * columns) return {{}, error_code::size_mismatch};
    if (!is_finite(dx) || !is_finite(dy)) return {{}, error_code::non_finite};
    if (!(dx > T(0)) || !(dy > T(0))) return {{}, error_code::non_positive_size};
    for (const T& h : heights)
        if (!is_finite(h)) return {{}, error_code::non_finite};
    const std::size_t cells = (rows - 1) * (columns - 1);
    if (nodes.size() < bvh_nodes_for(cells) || order.size() < cells) return {{}, error_code::capacity_exceeded};
    height_field<T> f{rows, columns, dx, dy, heights, {}};
    f.tree = build_bvh<T>(
        cells,
        [&](std::uint32_t c) {
            const std::size_t i = c / (columns - 1), j = c % (columns - 1);
            aabb<T> b{f.point(i, j), f.point(i, j)};
            for (const vec3<T>& p : {f.point(i, j + 1), f.point(i + 1, j), f.point(i + 1, j + 1)}) b = merged(b, aabb<T>{p, p});
            return b;
        },
        nodes, order);
    return {f, error_code::none};
}

}  // namespace ctga::collision
