// Closed-form separations (separation.hpp) of the pairs whose answer is a formula: spheres and
// capsules among themselves, a box and a sphere (a half-space and any convex shape: convex_pairs.hpp).
// Spheres and capsules are a point or a segment (the core) grown by the radius, so their
// separation is that of the cores' closest points less the radii: a = closest point of core A,
// b = of core B, δ = |b − a|, distance = δ − r_A − r_B, normal (b − a)/δ. This is exact also when
// they overlap: A ⊕ (−B) is (core_A − core_B) grown by r_A + r_B, and the origin's depth in it is
// r_A + r_B − δ. When the cores meet (δ = 0) the normal is any direction perpendicular to both.
// Against a half-space with outward normal n through point o: distance = min over X of n·(x − o)
// = n·(s − o) with s the support point of X along −n (its deepest point): `below`.
// Plain 3-vectors: each formula is a handful of dot products (a sphere pair 3 subtractions, a dot
// product, a square root and a division); points, planes and lines of ctga::pga add nothing here.
#pragma once

#include <cstddef>

#include "ctga/collision/box.hpp"
#include "ctga/collision/capsule.hpp"
#include "ctga/collision/cylinder.hpp"
#include "ctga/collision/half_space.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/collision/sphere.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {
namespace primitive_detail {

template <class T>
[[nodiscard]] constexpr T absolute(const T& x) noexcept {
    return x < T(0) ? -x : x;
}
template <class T>
[[nodiscard]] constexpr T clamp_unit(const T& x) noexcept {  // to [−1, 1], by selects
    const T up = x < T(1) ? x : T(1);
    return up > T(-1) ? up : T(-1);
}
// Two balls: centres a, b, radii ra, rb; across() the normal to use when the centres coincide
// (called only then: it costs a cross product and a square root).
template <class T, class Across>
[[nodiscard]] constexpr separation<T> balls(const vec3<T>& a, const T& ra, const vec3<T>& b, const T& rb, Across&& across) noexcept {
    const vec3<T> d = linear3::sub(b, a);
    const T l = length(d);
    const vec3<T> n = l > T(0) ? linear3::scale(T(1) / l, d) : across();
    return {l - ra - rb, n, linear3::add_scaled(a, ra, n), linear3::add_scaled(b, -rb, n)};
}

// A unit vector perpendicular to u (u ≠ 0): u × the coordinate axis least aligned with u.
template <class T>
[[nodiscard]] constexpr vec3<T> perpendicular(const vec3<T>& u) noexcept {
    const std::size_t k = absolute(u[0]) <= absolute(u[1]) && absolute(u[0]) <= absolute(u[2]) ? 0 : absolute(u[1]) <= absolute(u[2]) ? 1 : 2;
    vec3<T> e{};
    e[k] = T(1);
    const vec3<T> p = linear3::cross(u, e);
    return linear3::scale(T(1) / length(p), p);
}

// A capsule's core in the world: its centre and the half segment h · (body z axis).
template <class T>
struct segment {
    vec3<T> centre, half;
};
template <class T>
[[nodiscard]] constexpr segment<T> core_of(const capsule<T>& c, const motor_map<T>& pose) noexcept {
    return {pose.t, linear3::scale(c.half_height, axis_of(pose, 2))};
}

// The closest point of segment s to point p: centre + τ half, τ = clamp((p − centre)·half / |half|², ±1).
template <class T>
[[nodiscard]] constexpr vec3<T> closest_on(const segment<T>& s, const vec3<T>& p) noexcept {
    const T hh = linear3::dot(s.half, s.half);
    if (!(hh > T(0))) return s.centre;
    const T tau = clamp_unit(linear3::dot(linear3::sub(p, s.centre), s.half) / hh);
    return linear3::add_scaled(s.centre, tau, s.half);
}

// The closest points of two segments P(σ) = c_A + σ h_A, Q(τ) = c_B + τ h_B, σ, τ ∈ [−1, 1]:
// minimise |P − Q|² over σ for the unclamped τ(σ) = h_B·(P − c_B)/|h_B|², clamping each in turn
// (Ericson, Real-Time Collision Detection, §5.1.9, on centres and half segments); parallel
// segments take σ = 0 (a closest pair, not the only one).
template <class T>
struct closest_pair {
    vec3<T> p, q;
};
template <class T>
[[nodiscard]] constexpr closest_pair<T> closest_points(const segment<T>& A, const segment<T>& B) noexcept {
    const vec3<T> r = linear3::sub(A.centre, B.centre);
    const T a = linear3::dot(A.half, A.half), e = linear3::dot(B.half, B.half), f = linear3::dot(B.half, r);
    T s = T(0), t = T(0);
    if (!(a > T(0)) && !(e > T(0))) {
    } else if (!(a > T(0))) {
        t = clamp_unit(f / e);
    } else {
        const T c = linear3::dot(A.half, r);
        if (!(e > T(0))) s = clamp_unit(-c / a);
        else {
            // (selects, not branches: which end clamps is a coin toss for random segments; the
            // three reciprocals at once, not one division waiting for the other)
            const T b = linear3::dot(A.half, B.half), denom = a * e - b * b;
            const T inv_denom = T(1) / denom, inv_e = T(1) / e, inv_a = T(1) / a;
            const T s0 = denom > T(0) ? clamp_unit((b * f - c * e) * inv_denom) : T(0);
            const T t0 = (b * s0 + f) * inv_e, t1 = clamp_unit(t0);
            const T s1 = clamp_unit((b * t1 - c) * inv_a);
            s = t0 == t1 ? s0 : s1;
            t = t1;
        }
    }
    return {linear3::add_scaled(A.centre, s, A.half), linear3::add_scaled(B.centre, t, B.half)};
}

// The normal when two cores meet: perpendicular to both segments (to the one that is not a point).
template <class T>
[[nodiscard]] constexpr vec3<T> across(const vec3<T>& u, const vec3<T>& v) noexcept {
    const vec3<T> c = linear3::cross(u, v);
    const T l = length(c);
    if (l > T(0)) return linear3::scale(T(1) / l, c);
    if (linear3::dot(u, u) > T(0)) return perpendicular(u);
    if (linear3::dot(v, v) > T(0)) return perpendicular(v);
    return {T(0), T(0), T(1)};
}

// Against a half-space: its outward normal n, the world support point s of the other shape along
// −n; distance n·(s − o), point_a the foot of s on the boundary.
template <class T>
[[nodiscard]] constexpr separation<T> below(const motor_map<T>& plane, const vec3<T>& n, const vec3<T>& s) noexcept {
    const T d = linear3::dot(n, linear3::sub(s, plane.t));
    return {d, n, linear3::add_scaled(s, -d, n), s};
}

}  // namespace primitive_detail

// ---- the pairs (A, B): the normal points from A to B --------------------------------------

template <class T>
[[nodiscard]] constexpr separation<T> separation_between(const sphere<T>& a, const motor_map<T>& pa, const sphere<T>& b,
                                               const motor_map<T>& pb) noexcept {
    return primitive_detail::balls(pa.t, a.radius, pb.t, b.radius, [] { return vec3<T>{T(0), T(0), T(1)}; });
}

template <class T>
[[nodiscard]] constexpr separation<T> separation_between(const capsule<T>& a, const motor_map<T>& pa, const sphere<T>& b,
                                               const motor_map<T>& pb) noexcept {
    using namespace primitive_detail;
    const segment<T> A = core_of(a, pa);
    return balls(closest_on(A, pb.t), a.radius, pb.t, b.radius, [&] { return across(A.half, vec3<T>{}); });
}

template <class T>
[[nodiscard]] constexpr separation<T> separation_between(const capsule<T>& a, const motor_map<T>& pa, const capsule<T>& b,
                                               const motor_map<T>& pb) noexcept {
    using namespace primitive_detail;
    const segment<T> A = core_of(a, pa), B = core_of(b, pb);
    const closest_pair<T> c = closest_points(A, B);
    return balls(c.p, a.radius, c.q, b.radius, [&] { return across(A.half, B.half); });
}

// A box A and a sphere B: the sphere's centre c in the box's frame, clamped to the box, is the
// box's closest point when c is outside; inside, the nearest face (least h_i − |c_i|) is the way
// out, and the depth is that margin plus the radius.
template <class T>
[[nodiscard]] constexpr separation<T> separation_between(const box<T>& a, const motor_map<T>& pa, const sphere<T>& b,
                                               const motor_map<T>& pb) noexcept {
    const vec3<T> c = to_body(pa, pb.t);
    vec3<T> q{};
    for (std::size_t i = 0; i < 3; ++i) {  // (selects, not branches: which axes clamp is a coin toss)
        const T up = c[i] < a.half[i] ? c[i] : a.half[i];
        q[i] = up > -a.half[i] ? up : -a.half[i];
    }
    const bool inside = q[0] == c[0] && q[1] == c[1] && q[2] == c[2];
    if (!inside) return primitive_detail::balls(to_world(pa, q), T(0), pb.t, b.radius, [] { return vec3<T>{T(0), T(0), T(1)}; });
    std::size_t k = 0;
    for (std::size_t i = 1; i < 3; ++i)
        if (a.half[i] - primitive_detail::absolute(c[i]) < a.half[k] - primitive_detail::absolute(c[k])) k = i;
    const T side = c[k] < T(0) ? T(-1) : T(1);
    q[k] = side * a.half[k];
    const vec3<T> n = linear3::scale(side, axis_of(pa, k));
    const T depth = a.half[k] - primitive_detail::absolute(c[k]);
    return {-(depth + b.radius), n, to_world(pa, q), linear3::add_scaled(pb.t, -b.radius, n)};
}

}  // namespace ctga::collision
