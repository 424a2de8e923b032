// A bounding-volume hierarchy over fixed items (a mesh's triangles, a height field's cells): a
// binary tree of axis-aligned boxes (aabb.hpp), each node's box holding its items' boxes, built
// once top-down: a node's items are split at the median of their centres along the longest axis
// of those centres' box (std::nth_element, O(n log n) in all), until at most `leaf_size` remain.
// A query visits a node only when its box can hold an answer, so that a contact query on a mesh
// of n triangles meets O(log n) nodes plus the triangles near the shape:
//   overlaps:  the items whose boxes overlap a box;
//   ray:       the items whose boxes the ray enters before the nearest hit found so far;
//   nearest:   branch and bound on a lower bound of the signed distance (the gap between
//              boxes; −∞ for boxes that overlap, which can hold any depth), the nearer child
//              first, a node skipped when its bound is not below the best.
// Storage is the caller's (nodes: 2n − 1, order: n), filled at construction; no heap.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "ctga/collision/aabb.hpp"
#include "ctga/mechanics/linear3.hpp"

namespace ctga::collision {

template <class T>
struct bvh_node {
    aabb<T> box;
    std::uint32_t first;  // a leaf: its items order[first … first + count); inside: the children first, first + 1
    std::uint32_t count;  // 0 inside
};

template <class T>
struct bvh {
    std::span<const bvh_node<T>> node;   // node[0] the root
    std::span<const std::uint32_t> order;  // the items, leaf by leaf
};

inline constexpr std::size_t bvh_leaf_size = 4;
inline constexpr std::size_t bvh_max_depth = 64;

// The nodes a BVH of n items needs.
[[nodiscard]] constexpr std::size_t bvh_nodes_for(std::size_t n) noexcept {
    return n == 0 ? 1 : 2 * n - 1;
}

// Builds the hierarchy of n items, item(i) the box of item i, into the caller's storage (sizes
// as bvh_nodes_for(n) and n; the caller checks them).
template <class T, class Bounds>
[[nodiscard]] constexpr bvh<T> build_bvh(std::size_t n, Bounds&& item, std::span<bvh_node<T>> node, std::span<std::uint32_t> order) noexcept {
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
    const auto centre = [&](std::uint32_t i, std::size_t k) { return item(i).lower[k] + item(i).upper[k]; };
    std::size_t used = 1;
    node[0] = {n > 0 ? item(0) : aabb<T>{}, 0, static_cast<std::uint32_t>(n)};
    // the nodes still to split: (node, first item, item count); a split pushes both children
    std::array<std::array<std::size_t, 3>, bvh_max_depth + 1> todo{};
    std::size_t top = 0;
    todo[top++] = {0, 0, n};
    while (top > 0) {
        const auto [at, first, count] = todo[--top];
        aabb<T> box = item(order[first]);
        aabb<T> centres{{centre(order[first], 0), centre(order[first], 1), centre(order[first], 2)},
                        {centre(order[first], 0), centre(order[first], 1), centre(order[first], 2)}};
        for (std::size_t i = first + 1; i < first + count; ++i) {
            box = merged(box, item(order[i]));
            const vec3<T> c{centre(order[i], 0), centre(order[i], 1), centre(order[i], 2)};
            centres = merged(centres, aabb<T>{c, c});
        }
        node[at] = {box, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(count)};
        if (count <= bvh_leaf_size || top + 2 > todo.size()) continue;
        std::size_t axis = 0;
        for (std::size_t k = 1; k < 3; ++k)
            if (centres.upper[k] - centres.lower[k] > centres.upper[axis] - centres.lower[axis]) axis = k;
        const std::size_t half = count / 2;
        std::nth_element(order.begin() + first, order.begin() + first + half, order.begin() + first + count,
                         [&](std::uint32_t a, std::uint32_t b) { return centre(a, axis) < centre(b, axis); });
        node[at].first = static_cast<std::uint32_t>(used);
        node[at].count = 0;
        todo[top++] = {used, first, half};
        todo[top++] = {used + 1, first + half, count - half};
        used += 2;
    }
    return {std::span<const bvh_node<T>>(node.data(), used), std::span<const std::uint32_t>(order.data(), n)};
}

// Calls visit(item) for each item whose box overlaps `box`.
template <class T, class Visit>
constexpr void for_each_overlap(const bvh<T>& h, const aabb<T>& box, Visit&& visit) noexcept {
    std::array<std::uint32_t, bvh_max_depth + 2> stack{};
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const bvh_node<T>& v = h.node[stack[--top]];
        if (!overlaps(v.box, box)) continue;
        if (v.count > 0)
            for (std::uint32_t i = v.first; i < v.first + v.count; ++i) visit(h.order[i]);
        else
            stack[top++] = v.first, stack[top++] = v.first + 1;
    }
}

// The gap between two boxes: a lower bound of the signed distance of anything in one to anything
// in the other; −∞ when they overlap (what overlaps can be in any depth).
template <class T>
[[nodiscard]] constexpr T gap(const aabb<T>& a, const aabb<T>& b) noexcept {
    if (overlaps(a, b)) return -std::numeric_limits<T>::infinity();
    T g2 = T(0);
    for (std::size_t k = 0; k < 3; ++k) {
        const T d = a.lower[k] > b.upper[k] ? a.lower[k] - b.upper[k] : b.lower[k] > a.upper[k] ? b.lower[k] - a.upper[k] : T(0);
        g2 += d * d;
    }
    return math::sqrt(g2);
}

// Branch and bound: measure(item, best) returns the item's distance (it may stop early past
// `best`); nodes whose gap to `box` is not below the best so far are skipped. Returns the best.
template <class T, class Measure>
constexpr T nearest(const bvh<T>& h, const aabb<T>& box, T best, Measure&& measure) noexcept {
    std::array<std::uint32_t, bvh_max_depth + 2> stack{};
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const bvh_node<T>& v = h.node[stack[--top]];
        if (!(gap(v.box, box) < best)) continue;
        if (v.count > 0) {
            for (std::uint32_t i = v.first; i < v.first + v.count; ++i) {
                const T d = measure(h.order[i], best);
                best = d < best ? d : best;
            }
        } else {
            // the nearer child last on the stack: visited first
            const T g0 = gap(h.node[v.first].box, box), g1 = gap(h.node[v.first + 1].box, box);
            stack[top++] = g0 < g1 ? v.first + 1 : v.first;
            stack[top++] = g0 < g1 ? v.first : v.first + 1;
        }
    }
    return best;
}

// Calls hit(item, limit) → the item's hit distance (or limit when it misses) for the items whose
// boxes the ray enters before the nearest hit so far; returns the nearest (max_length: none).
template <class T, class Hit>
constexpr T first_hit(const bvh<T>& h, const ray<T>& r, Hit&& hit) noexcept {
    T best = r.max_length;
    std::array<std::uint32_t, bvh_max_depth + 2> stack{};
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const bvh_node<T>& v = h.node[stack[--top]];
        if (ray_entry(v.box, r, best) < T(0)) continue;
        if (v.count > 0) {
            for (std::uint32_t i = v.first; i < v.first + v.count; ++i) {
                const T s = hit(h.order[i], best);
                best = s < best ? s : best;
            }
        } else {
            stack[top++] = v.first, stack[top++] = v.first + 1;
        }
    }
    return best;
}

}  // namespace ctga::collision
