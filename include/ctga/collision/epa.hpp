// The penetration of two overlapping convex cores by EPA, the expanding polytope algorithm (van
// den Bergen, "Proximity queries and penetration depth computation on 3D game objects", 2001).
// The cores overlap when the origin lies in their Minkowski difference D = A − B; the depth is the
// origin's distance to D's boundary, min over unit u of h_D(u) (h the support function), and the
// minimising u is the normal from A towards B: B moved by depth · u just touches A.
// A polytope P ⊆ D around the origin (GJK's last tetrahedron, or the tetrahedron of extreme
// support points) bounds the depth from below by the distance to P's nearest face (plane n·x = d):
// h_D(n) ≥ d. The support point w of D along n gives the upper bound n·w ≥ depth; when the gap
// n·w − d is within `tolerance` of the size of D the answer is d and n, else w joins P
// (polytope.hpp) and the nearest face is sought again. For polytopes (boxes, hulls) D is a
// polytope and the gap closes to rounding after a few steps; curved cores converge as the support
// points sample them (a deep capsule in a cylinder: about 100 steps). At most 136 points in all.
// The witnesses: the nearest face's point d n in barycentric weights λ of its corners w_i = a_i −
// b_i gives point_a = Σ λ_i a_i (and Σ λ_i b_i = point_a − d n: point_b, exactly so on polytopes).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "ctga/collision/gjk.hpp"
#include "ctga/collision/hull.hpp"
#include "ctga/collision/polytope.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {

template <class T = double>
struct penetration {
    T depth;        // ≥ 0
    vec3<T> normal;  // from A towards B
    vec3<T> point_a, point_b;  // point_a − point_b = depth · normal
    int steps;
};

namespace epa_detail {
inline constexpr std::size_t max_points = 136;  // a tetrahedron, six axis supports and 126 steps

template <class T>
struct points {
    std::array<vec3<T>, max_points> w, a, b;  // [0, n) in use (no fill)
    std::size_t n = 0;
    constexpr void add(const vec3<T>& wi, const vec3<T>& ai, const vec3<T>& bi) noexcept {
        w[n] = wi, a[n] = ai, b[n] = bi;
        ++n;
    }
};

// Barycentric weights of the point p on triangle (x0, x1, x2).
template <class T>
[[nodiscard]] constexpr std::array<T, 3> barycentric(const vec3<T>& p, const vec3<T>& x0, const vec3<T>& x1, const vec3<T>& x2) noexcept {
    const vec3<T> e1 = linear3::sub(x1, x0), e2 = linear3::sub(x2, x0), q = linear3::sub(p, x0);
    const T d11 = linear3::dot(e1, e1), d12 = linear3::dot(e1, e2), d22 = linear3::dot(e2, e2);
    const T q1 = linear3::dot(q, e1), q2 = linear3::dot(q, e2), det = d11 * d22 - d12 * d12;
    const T l1 = (d22 * q1 - d12 * q2) / det, l2 = (d11 * q2 - d12 * q1) / det;
    return {T(1) - l1 - l2, l1, l2};
}
}  // namespace epa_detail

// A and B's cores overlap (gjk_detail::run reported it, with its last simplex `start`).
template <class A, class B, class T>
[[nodiscard]] constexpr penetration<T> epa(const A& a, const motor_map<T>& pa, const B& b, const motor_map<T>& pb,
                                           const gjk_detail::simplex<T>& start, const T& tolerance) noexcept {
    using namespace epa_detail;
    points<T> x;
    const auto support = [&](const vec3<T>& d) {
        const vec3<T> sa = gjk_detail::world_support(a, pa, d), sb = gjk_detail::world_support(b, pb, linear3::scale(T(-1), d));
        x.add(linear3::sub(sa, sb), sa, sb);
    };
    // the starting points: GJK's simplex and D's support points along ±x, ±y, ±z; of these the
    // tetrahedron of four extreme ones (hull.hpp), which GJK's own is when it holds the origin
    for (std::size_t i = 0; i < start.n; ++i) x.add(start.v[i].w, start.v[i].a, start.v[i].b);
    std::array<std::uint16_t, 4> corner{};
    if (start.n == 4) corner = {0, 1, 2, 3};
    for (std::size_t k = 0; k < 3 && start.n < 4; ++k)
        for (const T s : {T(1), T(-1)}) {
            vec3<T> d{};
            d[k] = s;
            support(d);
        }
    T size = T(0);
    for (std::size_t i = 0; i < x.n; ++i)
        for (std::size_t k = 0; k < 3; ++k) size = x.w[i][k] > size ? x.w[i][k] : -x.w[i][k] > size ? -x.w[i][k] : size;
    const T eps = T(128) * std::numeric_limits<T>::epsilon() * size;
    const std::span<const vec3<T>> w(x.w.data(), x.n);
    polytope<T, 2 * max_points> P;
    if (start.n < 4 && !hull_detail::extreme_four(w, eps, corner))
        return {T(0), length(start.closest) > T(0) ? start.closest : vec3<T>{T(0), T(0), T(1)}, start.v[0].a, start.v[0].b, 0};  // D flat
    (void)start_tetrahedron(P, w, corner[0], corner[1], corner[2], corner[3]);

    int step = 0;
    std::size_t nearest = 0;
    for (;; ++step) {
        nearest = 0;
        for (std::size_t t = 1; t < P.count; ++t)
            if (P.triangle[t].offset < P.triangle[nearest].offset) nearest = t;
        if (x.n == max_points) break;
        const polytope_triangle<T> f = P.triangle[nearest];
        support(f.normal);
        const T gap = linear3::dot(f.normal, x.w[x.n - 1]) - f.offset;
        if (gap <= tolerance * size + eps) break;
        if (grow(P, std::span<const vec3<T>>(x.w.data(), x.n), static_cast<std::uint16_t>(x.n - 1), eps) != grow_result::added) break;
    }
    const polytope_triangle<T>& f = P.triangle[nearest];
    const T depth = f.offset > T(0) ? f.offset : T(0);
    const std::array<T, 3> l = barycentric(linear3::scale(f.offset, f.normal), x.w[f.v[0]], x.w[f.v[1]], x.w[f.v[2]]);
    vec3<T> on_a{};
    for (std::size_t i = 0; i < 3; ++i) on_a = linear3::add_scaled(on_a, l[i], x.a[f.v[i]]);
    // B's witness d n from A's (the weights' own b point differs from it by the gap, on curved cores)
    return {depth, f.normal, on_a, linear3::add_scaled(on_a, -depth, f.normal), step};
}

}  // namespace ctga::collision
