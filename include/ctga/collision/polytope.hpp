// A convex polytope as a closed surface of triangles, grown one point at a time: the mechanism
// shared by the convex hull's construction (hull.hpp) and EPA's expansion (epa.hpp).
// Each triangle (i, j, k) is counter-clockwise seen from outside, with its unit outward normal n
// and offset d (n·x = d on its plane). A point p is outside the polytope when it is above some
// triangle's plane, n·p − d > ε; adding p (Barber, Dobkin and Huhdanpaa, "The quickhull algorithm
// for convex hulls", 1996, §3) removes the triangles p sees and joins p to the horizon, the edges
// between a seen and an unseen triangle. The seen triangles are one patch, grown across edges from
// the triangle p is farthest above (rounding cannot split it into pieces with a broken horizon). Every edge (a, b) of a closed surface appears reversed,
// (b, a), in exactly one other triangle, so an edge of a seen triangle is on the horizon exactly
// when its reverse is in no seen triangle; the new triangle (a, b, p) keeps the edge's direction
// and is counter-clockwise from outside because p lies above the seen triangle's plane. Points
// within ε of the planes are taken as inside: a face of coplanar points stays flat. A point in
// line with a horizon edge would make a triangle of no area; it cannot happen when each point
// added is an extreme point (the farthest above some plane, as quickhull and EPA choose them), as
// an extreme point cannot lie beyond a vertex in line with an edge; it is refused as degenerate.
// Storage is fixed (Capacity triangles), so growing needs no heap; a point that would exceed it is
// refused and the polytope left as it was.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"

namespace ctga::collision {

template <class T>
struct polytope_triangle {
    std::array<std::uint16_t, 3> v;  // counter-clockwise from outside
    vec3<T> normal;                  // unit, outward
    T offset;                        // normal · x on the plane
};

template <class T, std::size_t Capacity>
struct polytope {
    std::array<polytope_triangle<T>, Capacity> triangle;  // [0, count) in use (no fill: EPA makes one per call)
    std::size_t count = 0;
};

// The triangle (i, j, k) of the points, its plane through them (false: no area).
template <class T>
[[nodiscard]] constexpr bool make_triangle(std::span<const vec3<T>> x, std::uint16_t i, std::uint16_t j, std::uint16_t k,
                                           polytope_triangle<T>& out) noexcept {
    const vec3<T> n = linear3::cross(linear3::sub(x[j], x[i]), linear3::sub(x[k], x[i]));
    const T l = length(n);
    if (!(l > T(0))) return false;
    out.v = {i, j, k};
    out.normal = linear3::scale(T(1) / l, n);
    // the offset from the three vertices' mean: the plane is as close to each as rounding allows
    out.offset = (linear3::dot(out.normal, x[i]) + linear3::dot(out.normal, x[j]) + linear3::dot(out.normal, x[k])) / T(3);
    return true;
}

// The tetrahedron of points i, j, k, l (not coplanar) as four outward triangles.
template <class T, std::size_t Capacity>
constexpr bool start_tetrahedron(polytope<T, Capacity>& p, std::span<const vec3<T>> x, std::uint16_t i, std::uint16_t j,
                                 std::uint16_t k, std::uint16_t l) noexcept {
    static_assert(Capacity >= 4, "ctga::collision::polytope: room for at least a tetrahedron's four triangles");
    // (i, j, k) counter-clockwise from outside when l is below its plane; else swap j and k
    if (linear3::dot(linear3::cross(linear3::sub(x[j], x[i]), linear3::sub(x[k], x[i])), linear3::sub(x[l], x[i])) > T(0)) {
        const std::uint16_t s = j;
        j = k;
        k = s;
    }
    p.count = 4;
    return make_triangle(x, i, j, k, p.triangle[0]) && make_triangle(x, i, l, j, p.triangle[1]) &&
           make_triangle(x, j, l, k, p.triangle[2]) && make_triangle(x, k, l, i, p.triangle[3]);
}

// The height of point q above triangle t's plane.
template <class T>
[[nodiscard]] constexpr T height(const polytope_triangle<T>& t, const vec3<T>& q) noexcept {
    return linear3::dot(t.normal, q) - t.offset;
}

enum class grow_result { added, inside, full, degenerate };

// The triangle across edge (a, b): the one holding (b, a); p.count if none.
template <class T, std::size_t Capacity>
[[nodiscard]] constexpr std::size_t across(const polytope<T, Capacity>& p, std::uint16_t a, std::uint16_t b) noexcept {
    for (std::size_t u = 0; u < p.count; ++u)
        for (std::size_t f = 0; f < 3; ++f)
            if (p.triangle[u].v[f] == b && p.triangle[u].v[(f + 1) % 3] == a) return u;
    return p.count;
}

// Adds point x[index] (see the header). inside: within ε of every plane; full: the new triangles
// would exceed the capacity; degenerate: in line with a horizon edge. Only `added` changes p.
template <class T, std::size_t Capacity>
constexpr grow_result grow(polytope<T, Capacity>& p, std::span<const vec3<T>> x, std::uint16_t index, const T& epsilon) noexcept {
    const vec3<T>& q = x[index];
    // the seen triangles: grown from the one q is farthest above, across edges to neighbours q is
    // above by more than ε, so that they form one patch whatever rounding does to far planes
    std::size_t first = 0;
    for (std::size_t t = 1; t < p.count; ++t)
        if (height(p.triangle[t], q) > height(p.triangle[first], q)) first = t;
    if (!(height(p.triangle[first], q) > epsilon)) return grow_result::inside;
    std::array<bool, Capacity> seen{};
    std::array<std::uint16_t, Capacity> stack;  // (written before read: no fill)
    std::size_t top = 0, seen_count = 1;
    seen[first] = true;
    stack[top++] = static_cast<std::uint16_t>(first);
    std::array<std::array<std::uint16_t, 2>, Capacity + 2> horizon;
    std::size_t h = 0;
    while (top > 0) {
        const std::size_t t = stack[--top];
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint16_t a = p.triangle[t].v[e], b = p.triangle[t].v[(e + 1) % 3];
            const std::size_t u = across(p, a, b);
            if (u < p.count && seen[u]) continue;
            if (u < p.count && height(p.triangle[u], q) > epsilon) {
                seen[u] = true, ++seen_count;
                stack[top++] = static_cast<std::uint16_t>(u);
            } else {
                if (h == horizon.size()) return grow_result::full;
                horizon[h++] = {a, b};
            }
        }
    }
    // (a horizon edge found before its neighbour joined the patch is no longer on it)
    std::size_t kept_h = 0;
    for (std::size_t e = 0; e < h; ++e) {
        const std::size_t u = across(p, horizon[e][0], horizon[e][1]);
        if (!(u < p.count && seen[u])) horizon[kept_h++] = horizon[e];
    }
    h = kept_h;
    if (p.count - seen_count + h > Capacity) return grow_result::full;
    std::array<polytope_triangle<T>, Capacity + 2> fresh;  // the new triangles, checked before any change
    for (std::size_t e = 0; e < h; ++e)
        if (!make_triangle(x, horizon[e][0], horizon[e][1], index, fresh[e])) return grow_result::degenerate;
    // in place: the unseen triangles moved down, the new ones after them
    std::size_t n = 0;
    for (std::size_t t = 0; t < p.count; ++t)
        if (!seen[t]) p.triangle[n++] = p.triangle[t];
    for (std::size_t e = 0; e < h; ++e) p.triangle[n++] = fresh[e];
    p.count = n;
    return grow_result::added;
}

}  // namespace ctga::collision
