// An axis-aligned box in the world: the points x with lower_k ≤ x_k ≤ upper_k on each axis k,
// closed, so that two boxes touching along a face overlap. Two boxes overlap exactly when their
// intervals overlap on all three axes (a_lo ≤ b_hi and b_lo ≤ a_hi on each).
// The tight box of a posed shape S (x_world = R x + t) on world axis k is [t_k − h(−d), t_k + h(d)]
// with h the shape's support function in its body frame and d = Rᵀ e_k = row k of R, since
// e_k · (R x + t) = (row k of R) · x + t_k. Closed forms of h along a unit d (|d| = 1, R being a
// rotation), all symmetric (h(−d) = h(d)):
//   sphere r:                   r
//   capsule r, h (segment on z): h |d_z| + r
//   box with half extents a:    Σ_j a_j |d_j|
//   cylinder r, h (axis z):      h |d_z| + r √(d_x² + d_y²)   (= r √(1 − d_z²), without cancellation)
// Any other shape with core_support(shape, d) (a farthest point of its core along d) and
// core_radius(shape) (the shape is its core grown by that radius): h(d) = d · core_support(d) + r.
// A ray o + s u (u ≠ 0) meets the box at the s of the slabs' overlap (Kay and Kajiya): on each
// axis with u_k ≠ 0 it is inside the slab for s between (lower_k − o_k)/u_k and (upper_k − o_k)/u_k;
// on an axis with u_k = 0, for all s when lower_k ≤ o_k ≤ upper_k, for none otherwise.
#pragma once

#include <concepts>
#include <cstddef>

#include "ctga/collision/box.hpp"
#include "ctga/collision/capsule.hpp"
#include "ctga/collision/cylinder.hpp"
#include "ctga/collision/sphere.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

template <class T = double>
struct aabb {
    vec3<T> lower, upper;

    friend constexpr bool operator==(const aabb&, const aabb&) = default;
};

namespace aabb_detail {
template <class T>
[[nodiscard]] constexpr T absolute(const T& x) noexcept {
    return x < T(0) ? -x : x;
}
template <class T>
[[nodiscard]] constexpr T smaller(const T& a, const T& b) noexcept {
    return b < a ? b : a;
}
template <class T>
[[nodiscard]] constexpr T larger(const T& a, const T& b) noexcept {
    return a < b ? b : a;
}
// The box t ± e.
template <class T>
[[nodiscard]] constexpr aabb<T> centred(const vec3<T>& t, const vec3<T>& e) noexcept {
    return {{t[0] - e[0], t[1] - e[1], t[2] - e[2]}, {t[0] + e[0], t[1] + e[1], t[2] + e[2]}};
}
}  // namespace aabb_detail

// Finite bounds with lower ≤ upper on every axis (a NaN fails).
template <class T>
[[nodiscard]] constexpr bool is_valid(const aabb<T>& a) noexcept {
    for (std::size_t k = 0; k < 3; ++k)
        if (!is_finite(a.lower[k]) || !is_finite(a.upper[k]) || !(a.lower[k] <= a.upper[k])) return false;
    return true;
}

template <class T>
[[nodiscard]] constexpr bool overlaps(const aabb<T>& a, const aabb<T>& b) noexcept {
    // the six comparisons counted rather than chained: no branch for each (a tree walk's tests go
    // either way at random, and mispredicted branches cost more than the comparisons)
    return (a.lower[0] <= b.upper[0]) + (b.lower[0] <= a.upper[0]) + (a.lower[1] <= b.upper[1]) + (b.lower[1] <= a.upper[1]) +
               (a.lower[2] <= b.upper[2]) + (b.lower[2] <= a.upper[2]) ==
           6;
}

// Whether `inner` lies within `outer`.
template <class T>
[[nodiscard]] constexpr bool contains(const aabb<T>& outer, const aabb<T>& inner) noexcept {
    return outer.lower[0] <= inner.lower[0] && outer.lower[1] <= inner.lower[1] && outer.lower[2] <= inner.lower[2] &&
           inner.upper[0] <= outer.upper[0] && inner.upper[1] <= outer.upper[1] && inner.upper[2] <= outer.upper[2];
}

// The smallest box holding both.
template <class T>
[[nodiscard]] constexpr aabb<T> merged(const aabb<T>& a, const aabb<T>& b) noexcept {
    using aabb_detail::larger, aabb_detail::smaller;
    return {{smaller(a.lower[0], b.lower[0]), smaller(a.lower[1], b.lower[1]), smaller(a.lower[2], b.lower[2])},
            {larger(a.upper[0], b.upper[0]), larger(a.upper[1], b.upper[1]), larger(a.upper[2], b.upper[2])}};
}

// The box grown by `margin` on every side (lower − m and upper + m as computed: a rounded
// difference never passes the exact one, so the result holds the box for any margin ≥ 0).
template <class T>
[[nodiscard]] constexpr aabb<T> fattened(const aabb<T>& a, const T& margin) noexcept {
    return {{a.lower[0] - margin, a.lower[1] - margin, a.lower[2] - margin}, {a.upper[0] + margin, a.upper[1] + margin, a.upper[2] + margin}};
}

// 2 (xy + yz + zx) of its edge lengths: the expected cost of visiting a node in a tree of boxes is
// proportional to it (the chance that a random box or ray meets it).
template <class T>
[[nodiscard]] constexpr T surface_area(const aabb<T>& a) noexcept {
    const T x = a.upper[0] - a.lower[0], y = a.upper[1] - a.lower[1], z = a.upper[2] - a.lower[2];
    return T(2) * (x * y + y * z + z * x);
}

// ---- the tight box of a posed shape ----

// From the support points of the core along ± each row of R, for any shape with core_support and
// core_radius (six support points).
template <class S, class T>
    requires requires(const S& s, const vec3<T>& d) {
        { core_support(s, d) } -> std::convertible_to<vec3<T>>;
        { core_radius(s) } -> std::convertible_to<T>;
    }
[[nodiscard]] constexpr aabb<T> support_bounds(const S& shape, const motor_map<T>& pose) noexcept {
    const T r = core_radius(shape);
    aabb<T> out{};
    for (std::size_t k = 0; k < 3; ++k) {
        const vec3<T>& d = pose.R[k];
        const vec3<T> minus_d{-d[0], -d[1], -d[2]};
        out.upper[k] = pose.t[k] + linear3::dot(d, core_support(shape, d)) + r;
        out.lower[k] = pose.t[k] + linear3::dot(d, core_support(shape, minus_d)) - r;
    }
    return out;
}

// The closed forms.
template <class T>
[[nodiscard]] constexpr aabb<T> bounds_of(const sphere<T>& s, const motor_map<T>& pose) noexcept {
    return aabb_detail::centred(pose.t, vec3<T>{s.radius, s.radius, s.radius});
}
template <class T>
[[nodiscard]] constexpr aabb<T> bounds_of(const capsule<T>& c, const motor_map<T>& pose) noexcept {
    using aabb_detail::absolute;
    vec3<T> e{};
    for (std::size_t k = 0; k < 3; ++k) e[k] = c.half_height * absolute(pose.R[k][2]) + c.radius;
    return aabb_detail::centred(pose.t, e);
}
template <class T>
[[nodiscard]] constexpr aabb<T> bounds_of(const box<T>& b, const motor_map<T>& pose) noexcept {
    using aabb_detail::absolute;
    vec3<T> e{};
    for (std::size_t k = 0; k < 3; ++k)
        e[k] = b.half[0] * absolute(pose.R[k][0]) + b.half[1] * absolute(pose.R[k][1]) + b.half[2] * absolute(pose.R[k][2]);
    return aabb_detail::centred(pose.t, e);
}
template <class T>
[[nodiscard]] constexpr aabb<T> bounds_of(const cylinder<T>& c, const motor_map<T>& pose) noexcept {
    using aabb_detail::absolute;
    vec3<T> e{};
    for (std::size_t k = 0; k < 3; ++k) {
        const vec3<T>& d = pose.R[k];
        e[k] = c.half_height * absolute(d[2]) + c.radius * math::sqrt(d[0] * d[0] + d[1] * d[1]);
    }
    return aabb_detail::centred(pose.t, e);
}
// Any other shape: by its support points.
template <class S, class T>
    requires requires(const S& s, const motor_map<T>& p) { support_bounds(s, p); }
[[nodiscard]] constexpr aabb<T> bounds_of(const S& shape, const motor_map<T>& pose) noexcept {
    return support_bounds(shape, pose);
}

// ---- rays ----

// The ray o + s u for 0 ≤ s ≤ max_length, with 1/u_k formed once (where u_k = 0 the slab test is
// the other one).
template <class T = double>
struct ray {
    vec3<T> origin, direction, inverse;
    T max_length;
};
template <class T>
[[nodiscard]] constexpr ray<T> make_ray(const vec3<T>& origin, const vec3<T>& direction, const T& max_length) noexcept {
    ray<T> out{origin, direction, {}, max_length};
    for (std::size_t k = 0; k < 3; ++k) out.inverse[k] = direction[k] == T(0) ? T(0) : T(1) / direction[k];
    return out;
}

// The least s in [0, limit] at which the ray is in the box, or −1 when there is none.
template <class T>
[[nodiscard]] constexpr T ray_entry(const aabb<T>& box, const ray<T>& r, const T& limit) noexcept {
    T enter = T(0), leave = limit;
    for (std::size_t k = 0; k < 3; ++k) {
        if (r.direction[k] == T(0)) {
            if (r.origin[k] < box.lower[k] || box.upper[k] < r.origin[k]) return T(-1);
            continue;
        }
        T near = (box.lower[k] - r.origin[k]) * r.inverse[k], far = (box.upper[k] - r.origin[k]) * r.inverse[k];
        if (far < near) {
            const T swap = near;
            near = far;
            far = swap;
        }
        enter = aabb_detail::larger(enter, near);
        leave = aabb_detail::smaller(leave, far);
    }
    return enter <= leave ? enter : T(-1);
}

}  // namespace ctga::collision
