// Ray casts: the first point of a posed shape on a ray x(s) = o + s d, s ∈ [0, max_length]. The ray
// is the broadphase's (aabb.hpp: ray, make_ray); make_ray_checked makes d unit, and then s is a
// length (with d = end − start and max_length = 1 it is the fraction of a segment: every formula
// below takes any d ≠ 0, s in units of d). The answer is a ray_hit: whether it hits, the parameter
// s of the hit ("distance"), the hit point o + s d and the shape's outward unit normal there.
// A ray whose origin is in the solid (the closed set: on its surface too) hits at s = 0, the point
// the origin and the normal −d/|d| (no surface is crossed; a caller tells this case by s = 0, and a
// query from inside a body, a ground check from a foot sunk in the floor, still sees it; some
// engines, Box2D 2.4's casts among them, report a miss instead). A miss has distance max_length,
// point and normal zero.
//
// Closed forms, in the body frame (o and d by Rᵀ: the origin relative to the shape, so that a ray
// and a shape 10⁴ m from the world's origin cost no more digits than at it), the normal turned back:
//   sphere     |o + s d|² = r²: a s² + 2 b s + c = 0 with a = d·d, b = o·d, c = o·o − r². The
//              discriminant b² − a c = a (r² − |o − (b/a) d|²) is formed from the line's distance
//              to the centre (no cancellation of o·o against b²/a: a grazing ray far away keeps its
//              digits), the roots as q/a and c/q with q = −b − sign(b) √(b² − a c) (no cancellation
//              of −b against the root);
//   capsule    the union of the side (x² + y² ≤ r², |z| ≤ h) and the balls at the ends (0, 0, ±h):
//              the first entry into the union is the least of the entries into its parts, and a
//              flat cap is inside its ball, so the side (the quadratic in x, y: d's part across
//              the axis, entered at |z| ≤ h) and the two balls are enough;
//   box        slabs (Kay and Kajiya 1986): |o_i + s d_i| ≤ h_i for each axis i is an interval of s
//              (all s or none when d_i = 0); the ray enters at the largest lower end, through the
//              face of that axis on the side facing −d (normal −sign(d_i) e_i), if it is at most
//              the least upper end;
//   cylinder   the slab |z| ≤ h intersected with the infinite cylinder's interval (the quadratic
//              in x, y); the later entry names the feature: a cap (±z) or the side ((x, y, 0)/r);
//   half-space the plane z = 0 with outward normal n (the body's z axis): s = −(n·(o − t))/(n·d)
//              when the origin is above and d points down.
// A tangent (grazing) ray hits: each shape is closed. Near tangency the distance is ill
// conditioned (the double root of the quadratic: an error δ in the line's distance to the
// surface moves the hit by ~√(r δ)).
//
// Any convex shape with core_support and core_radius (sphere.hpp: the shape is its core grown by
// its radius r): ray_cast_convex, GJK ray casting (G. van den Bergen, "Ray casting against general
// convex objects with application to continuous collision detection", 2004), in the body frame.
// A point x = o + λ d of the ray (λ = 0 first) and a simplex of core support points p_i; v is the
// point of conv{x − p_i} nearest the origin (gjk.hpp's sub-simplex routines), so |v| ≥ the distance
// of x to the core. Each step takes p = s_core(v) and w = x − p. When v·w > r |v| the plane
// v·y = v·p + r |v| separates x from the shape (every core point has v·y ≤ v·p, the grown points
// at most r |v| more): if v·d ≥ 0 the ray never crosses it (a miss), otherwise x advances to it,
// λ ← λ − (v·w − r |v|)/(v·d), which stays before the first hit (the shape lies beyond the plane),
// and the normal becomes v/|v|. It stops when |v| ≤ r + ε (x within ε of the shape: a hit, its
// distance at most the true one, and ≥ it − ε/|n·d| for a unit d, n the normal at the hit: the
// shape lies behind the tangent plane there; a ray passing within ε of the shape counts as a hit),
// when λ passes max_length (a miss), or when the origin is in the simplex (x in the core).
// Rounding: v sums terms of the shape's size, so its direction carries an error ~ε_T size/|v|,
// which tilts the plane through p by ~ε_T size²/|v|; once that exceeds |v| the plane no longer
// separates and x stops advancing (at |v| ~ √ε_T size). A face of the simplex (three points) is
// therefore taken along the normal of its core points, (p₁ − p₀) × (p₂ − p₀), whose direction x's
// rounding does not enter: a polytope's face is then reached to rounding (the hit distance within
// ~1e-15 of its size in double). On a curved core of radius 0 (a cylinder's rim and side, ruled
// between two circles) the simplex's points crowd on the curve and it stalls near 1e-11 of the
// size in double, 1e-5 in float (measured); it stops when |v| has not shrunk in 16 steps (or
// after 128), and the hit is then that much early. A polytope's core ends in a few steps, curved
// parts converge like Newton's method on the distance along the ray (by halves at a grazing hit).
// An origin within ε of the shape counts as inside. ray_cast(shape, pose, ray) for a shape kind
// without a closed form (a convex hull) is ray_cast_convex with ε = √ε_T · (core_reach + r).
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include "ctga/collision/aabb.hpp"
#include "ctga/collision/box.hpp"
#include "ctga/collision/capsule.hpp"
#include "ctga/collision/convex_pairs.hpp"
#include "ctga/collision/cylinder.hpp"
#include "ctga/collision/gjk.hpp"
#include "ctga/collision/half_space.hpp"
#include "ctga/collision/primitive_pairs.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/collision/sphere.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/unit_direction.hpp"

namespace ctga::collision {

template <class T = double>
struct ray_hit {
    bool hit;
    T distance;      // the parameter s of the hit: a length for a unit direction (make_ray_checked)
    vec3<T> point;   // origin + distance · direction
    vec3<T> normal;  // the shape's outward unit normal at the point (−direction/|direction| from inside)
};

// The ray (aabb.hpp: ray, make_ray, the broadphase's) with its direction made unit
// (unit_direction.hpp), so that distances are lengths. Reported: non_finite (a NaN or an infinity
// in the origin or the direction, a NaN max_length), zero_direction (the zero direction),
// non_positive_size (max_length < 0; 0 is a point, +∞ unbounded).
template <class T>
[[nodiscard]] constexpr checked<ray<T>> make_ray_checked(const vec3<T>& origin, const vec3<T>& direction, const T& max_length) noexcept {
    if (!all_finite(origin[0], origin[1], origin[2]) || max_length != max_length) return {{}, error_code::non_finite};
    const checked<std::array<T, 3>> d = unit_direction(direction[0], direction[1], direction[2]);
    if (!d) return {{}, d.error};
    if (!(max_length >= T(0))) return {{}, error_code::non_positive_size};
    return {make_ray(origin, d.value, max_length), error_code::none};
}

namespace ray_detail {
using primitive_detail::absolute;

template <class T>
[[nodiscard]] constexpr ray_hit<T> miss(const ray<T>& r) noexcept {
    return {false, r.max_length, {}, {}};
}
template <class T>
[[nodiscard]] constexpr ray_hit<T> inside(const ray<T>& r) noexcept {
    return {true, T(0), r.origin, linear3::scale(T(-1) / length(r.direction), r.direction)};
}
// A hit at s with the normal n (world, unit) when s is within the ray's length.
template <class T>
[[nodiscard]] constexpr ray_hit<T> hit_at(const ray<T>& r, const T& s, const vec3<T>& n) noexcept {
    if (!(s <= r.max_length)) return miss(r);
    return {true, s, linear3::add_scaled(r.origin, s, r.direction), n};
}
template <class T>
[[nodiscard]] constexpr vec3<T> unit(const vec3<T>& v) noexcept {
    return linear3::scale(T(1) / length(v), v);
}

// The line o + s d (d ≠ 0) against the ball |y| ≤ r: the interval [enter, exit] of s inside it.
template <class T>
struct span {
    bool any;
    T enter, exit;
};
template <class T>
[[nodiscard]] constexpr span<T> ball_span(const vec3<T>& o, const vec3<T>& d, const T& r) noexcept {
    const T a = linear3::dot(d, d), b = linear3::dot(o, d), c = linear3::dot(o, o) - r * r;
    const vec3<T> across = linear3::add_scaled(o, -b / a, d);  // o's part across the line
    const T disc = a * (r * r - linear3::dot(across, across));
    if (!(disc >= T(0))) return {false, T(0), T(0)};
    const T q = b < T(0) ? -b + math::sqrt(disc) : -b - math::sqrt(disc);
    if (q == T(0)) return {true, T(0), T(0)};  // b = 0 and a c = 0: the origin on the sphere, moving along it
    const T s1 = q / a, s2 = c / q;
    return s1 < s2 ? span<T>{true, s1, s2} : span<T>{true, s2, s1};
}

// The ray's origin and direction in the body frame.
template <class T>
struct local_ray {
    vec3<T> o, d;
};
template <class T>
[[nodiscard]] constexpr local_ray<T> in_body(const motor_map<T>& pose, const ray<T>& r) noexcept {
    return {to_body(pose, r.origin), linear3::apply_transposed(pose.R, r.direction)};
}

// The first entry (s ≥ 0) into the ball of radius rad about c (body frame), the origin outside it.
template <class T>
[[nodiscard]] constexpr span<T> ball_entry(const local_ray<T>& l, const vec3<T>& c, const T& rad) noexcept {
    const span<T> s = ball_span(linear3::sub(l.o, c), l.d, rad);
    return {s.any && s.enter >= T(0), s.enter, s.exit};
}

}  // namespace ray_detail

// ---- closed forms ---------------------------------------------------------------------------

template <class T>
[[nodiscard]] constexpr ray_hit<T> ray_cast(const sphere<T>& x, const motor_map<T>& pose, const ray<T>& r) noexcept {
    using namespace ray_detail;
    const vec3<T> o = linear3::sub(r.origin, pose.t);
    if (linear3::dot(o, o) <= x.radius * x.radius) return inside(r);
    const span<T> s = ball_span(o, r.direction, x.radius);
    if (!s.any || s.enter < T(0)) return miss(r);
    return hit_at(r, s.enter, unit(linear3::add_scaled(o, s.enter, r.direction)));
}

template <class T>
[[nodiscard]] constexpr ray_hit<T> ray_cast(const capsule<T>& x, const motor_map<T>& pose, const ray<T>& r) noexcept {
    using namespace ray_detail;
    const local_ray<T> l = in_body(pose, r);
    const T h = x.half_height, rad = x.radius;
    const vec3<T> foot{T(0), T(0), l.o[2] < -h ? -h : l.o[2] > h ? h : l.o[2]};  // the nearest core point
    const vec3<T> off = linear3::sub(l.o, foot);
    if (linear3::dot(off, off) <= rad * rad) return inside(r);
    T best = std::numeric_limits<T>::infinity();
    vec3<T> normal{};
    const vec3<T> o2{l.o[0], l.o[1], T(0)}, d2{l.d[0], l.d[1], T(0)};
    if (linear3::dot(d2, d2) > T(0)) {  // the side
        const span<T> s = ball_span(o2, d2, rad);
        const T z = l.o[2] + s.enter * l.d[2];
        if (s.any && s.enter >= T(0) && absolute(z) <= h) {
            best = s.enter;
            normal = unit(linear3::add_scaled(o2, s.enter, d2));
        }
    }
    for (const T end : {-h, h}) {  // the balls at the ends
        const vec3<T> c{T(0), T(0), end};
        const span<T> s = ball_entry(l, c, rad);
        if (s.any && s.enter < best) {
            best = s.enter;
            normal = unit(linear3::sub(linear3::add_scaled(l.o, s.enter, l.d), c));
        }
    }
    if (!(best < std::numeric_limits<T>::infinity())) return miss(r);
    return hit_at(r, best, linear3::apply(pose.R, normal));
}

template <class T>
[[nodiscard]] constexpr ray_hit<T> ray_cast(const box<T>& x, const motor_map<T>& pose, const ray<T>& r) noexcept {
    using namespace ray_detail;
    const local_ray<T> l = in_body(pose, r);
    if (absolute(l.o[0]) <= x.half[0] && absolute(l.o[1]) <= x.half[1] && absolute(l.o[2]) <= x.half[2]) return inside(r);
    T enter = -std::numeric_limits<T>::infinity(), exit = std::numeric_limits<T>::infinity();
    std::size_t face = 3;
    for (std::size_t i = 0; i < 3; ++i) {
        if (l.d[i] == T(0)) {
            if (absolute(l.o[i]) > x.half[i]) return miss(r);
            continue;
        }
        const T inv = T(1) / l.d[i];
        T lo = (-x.half[i] - l.o[i]) * inv, hi = (x.half[i] - l.o[i]) * inv;
        if (inv < T(0)) {
            const T m = lo;
            lo = hi, hi = m;
        }
        if (lo > enter) enter = lo, face = i;
        if (hi < exit) exit = hi;
    }
    // (the origin is outside, so some slab excludes it: face < 3 and enter > 0 when the ray enters)
    if (face == 3 || !(enter <= exit) || enter < T(0)) return miss(r);
    return hit_at(r, enter, linear3::scale(l.d[face] < T(0) ? T(1) : T(-1), axis_of(pose, face)));
}

template <class T>
[[nodiscard]] constexpr ray_hit<T> ray_cast(const cylinder<T>& x, const motor_map<T>& pose, const ray<T>& r) noexcept {
    using namespace ray_detail;
    const local_ray<T> l = in_body(pose, r);
    const T h = x.half_height, rad = x.radius;
    const vec3<T> o2{l.o[0], l.o[1], T(0)}, d2{l.d[0], l.d[1], T(0)};
    if (absolute(l.o[2]) <= h && linear3::dot(o2, o2) <= rad * rad) return inside(r);
    constexpr T inf = std::numeric_limits<T>::infinity();
    // the slab |z| ≤ h
    T z_in = -inf, z_out = inf;
    if (l.d[2] == T(0)) {
        if (absolute(l.o[2]) > h) return miss(r);
    } else {
        const T inv = T(1) / l.d[2];
        z_in = (-h - l.o[2]) * inv, z_out = (h - l.o[2]) * inv;
        if (inv < T(0)) {
            const T m = z_in;
            z_in = z_out, z_out = m;
        }
    }
    // the infinite cylinder x² + y² ≤ r²
    T c_in = -inf, c_out = inf;
    if (linear3::dot(d2, d2) > T(0)) {
        const span<T> s = ball_span(o2, d2, rad);
        if (!s.any) return miss(r);
        c_in = s.enter, c_out = s.exit;
    } else if (linear3::dot(o2, o2) > rad * rad) {
        return miss(r);
    }
    const bool cap = z_in >= c_in;
    const T enter = cap ? z_in : c_in, exit = z_out < c_out ? z_out : c_out;
    if (!(enter <= exit) || enter < T(0)) return miss(r);
    const vec3<T> n = cap ? linear3::scale(l.d[2] < T(0) ? T(1) : T(-1), axis_of(pose, 2))
                          : linear3::apply(pose.R, unit(linear3::add_scaled(o2, enter, d2)));
    return hit_at(r, enter, n);
}

template <class T>
[[nodiscard]] constexpr ray_hit<T> ray_cast(const half_space<T>&, const motor_map<T>& pose, const ray<T>& r) noexcept {
    using namespace ray_detail;
    const vec3<T> n = axis_of(pose, 2);
    const T above = linear3::dot(n, linear3::sub(r.origin, pose.t)), down = linear3::dot(n, r.direction);
    if (above <= T(0)) return inside(r);
    if (!(down < T(0))) return miss(r);
    return hit_at(r, above / -down, n);
}

// ---- any convex shape: GJK ray casting ------------------------------------------------------

// The reach of a shape's core about its body's origin: the length of the farthest corner of the
// box spanned by its support points along ±x, ±y, ±z, ≥ max |x| over the core (exact for a point,
// a segment on an axis and a box; √(1 + r²/(r² + h²)) times too large at most for a cylinder). The
// shape is within reach + core_radius of its origin. A kind may overload it with a tighter bound.
template <class S>
[[nodiscard]] constexpr auto core_reach(const S& shape) noexcept {
    using T = decltype(core_radius(shape));
    T r2 = T(0);
    for (std::size_t i = 0; i < 3; ++i) {
        vec3<T> e{};
        e[i] = T(1);
        const T hi = core_support(shape, e)[i];
        e[i] = T(-1);
        const T lo = core_support(shape, e)[i];
        const T m = primitive_detail::absolute(hi) > primitive_detail::absolute(lo) ? primitive_detail::absolute(hi)
                                                                                  : primitive_detail::absolute(lo);
        r2 += m * m;
    }
    return math::sqrt(r2);
}

template <class S, class T>
[[nodiscard]] constexpr ray_hit<T> ray_cast_convex(const S& shape, const motor_map<T>& pose, const ray<T>& r,
                                                   const T& tolerance) noexcept {
    using namespace gjk_detail;
    using ray_detail::miss;
    const ray_detail::local_ray<T> l = ray_detail::in_body(pose, r);
    const T rad = core_radius(shape), stop = (rad + tolerance) * (rad + tolerance);
    T lambda = T(0);
    vec3<T> x = l.o, n{};
    simplex<T> s;  // core points (a), with w = x − a
    const vec3<T> first = core_support(shape, x);
    s.v[0] = {linear3::sub(x, first), first, {}};
    s.n = 1;
    vec3<T> v = s.v[0].w;
    T least = std::numeric_limits<T>::infinity();  // the least |v|² since x last moved
    int idle = 0;                                  // steps since it last shrank
    for (int step = 0; step < 128; ++step) {
        const T vv = linear3::dot(v, v);
        if (vv <= stop) break;
        const vec3<T> p = core_support(shape, v), w = linear3::sub(x, p);
        const T vl = math::sqrt(vv), gap = linear3::dot(v, w) - rad * vl;
        if (gap > T(0)) {
            const T vd = linear3::dot(v, l.d);
            if (!(vd < T(0))) return miss(r);
            lambda -= gap / vd;
            if (!(lambda <= r.max_length)) return miss(r);
            x = linear3::add_scaled(l.o, lambda, l.d);
            n = v;
            least = std::numeric_limits<T>::infinity(), idle = 0;
        } else if (vv < least) {
            least = vv, idle = 0;
        } else if (++idle == 16) {
            break;  // v no shorter in 16 steps: rounding (support points crowding on a curve)
        }
        bool repeated = false;
        for (std::size_t i = 0; i < s.n; ++i) repeated = repeated || s.v[i].a == p;
        if (!repeated) s.v[s.n++] = {{}, p, {}};
        for (std::size_t i = 0; i < s.n; ++i) s.v[i].w = linear3::sub(x, s.v[i].a);
        if (s.n == 1) keep<T>(s, {0}, {T(1)});
        else if (s.n == 2) segment(s);
        else if (s.n == 3) gjk_detail::triangle(s, 0, 1, 2);
        else if (!tetrahedron(s)) break;  // x in the core
        v = s.closest;
        if (s.n == 3) {  // a face: along its normal from the core points (x's rounding does not tilt it)
            const vec3<T> f = linear3::cross(linear3::sub(s.v[1].a, s.v[0].a), linear3::sub(s.v[2].a, s.v[0].a));
            const T ff = linear3::dot(f, f);
            if (ff > T(0)) v = linear3::scale(linear3::dot(f, s.v[0].w) / ff, f);
        }
    }
    if (lambda == T(0)) return ray_detail::inside(r);
    // the normal: a grown core's last v (x less the nearest core point, |v| ≈ r), else the last
    // separating plane's (v is then ≤ ε long and its direction rounding)
    if (rad > T(0) && linear3::dot(v, v) > T(0)) n = v;
    return {true, lambda, linear3::add_scaled(r.origin, lambda, r.direction), linear3::apply(pose.R, ray_detail::unit(n))};
}

// Shape kinds without a closed form here (a convex hull): ray_cast_convex to √ε of their size.
template <class S, class T>
    requires convex_shape<S, T>
[[nodiscard]] constexpr ray_hit<T> ray_cast(const S& shape, const motor_map<T>& pose, const ray<T>& r) noexcept {
    const T size = core_reach(shape) + core_radius(shape);
    return ray_cast_convex(shape, pose, r, math::sqrt(std::numeric_limits<T>::epsilon()) * size);
}

}  // namespace ctga::collision
