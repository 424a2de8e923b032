// A triangle (a, b, c): the piece of a mesh or a height field that the narrowphase meets, a flat
// convex shape of its own (two-sided: its face along either normal ±(b − a) × (c − a)). Its core
// is itself (radius 0); its support point along d the corner farthest along d; its support
// feature (features.hpp) its face when d is within the feature angle of a normal, an edge when
// d is perpendicular to one within it, else a corner (ids: corners 0–2, edges 3–5, faces 6–7).
// A ray o + s u meets it (Möller and Trumbore 1997) at s = (e2 · q)/(e1 · p) with e1 = b − a,
// e2 = c − a, p = u × e2, q = (o − a) × e1, when the barycentric coordinates
// β = ((o − a) · p)/(e1 · p) and γ = (u · q)/(e1 · p) satisfy β, γ ≥ 0 and β + γ ≤ 1.
#pragma once

#include <array>
#include <cstdint>

#include "ctga/collision/features.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {

template <class T = double>
struct triangle {
    std::array<vec3<T>, 3> x;
};

template <class T>
[[nodiscard]] constexpr vec3<T> core_support(const triangle<T>& t, const vec3<T>& u) noexcept {
    const T d0 = linear3::dot(u, t.x[0]), d1 = linear3::dot(u, t.x[1]), d2 = linear3::dot(u, t.x[2]);
    return d0 >= d1 && d0 >= d2 ? t.x[0] : d1 >= d2 ? t.x[1] : t.x[2];
}
template <class T>
[[nodiscard]] constexpr T core_radius(const triangle<T>&) noexcept {
    return T(0);
}

template <class T>
[[nodiscard]] constexpr vec3<T> normal_of(const triangle<T>& t) noexcept {
    const vec3<T> n = linear3::cross(linear3::sub(t.x[1], t.x[0]), linear3::sub(t.x[2], t.x[0]));
    return linear3::scale(T(1) / length(n), n);
}

template <class T>
[[nodiscard]] constexpr feature<T> support_feature(const triangle<T>& t, const motor_map<T>& p, const vec3<T>& d) noexcept {
    using namespace feature_detail;
    feature<T> f;
    f.normal = d;
    const vec3<T> n = linear3::apply(p.R, normal_of(t));
    const T k = linear3::dot(n, d);
    if (absolute(k) >= face_cosine<T>) {
        // counter-clockwise about the face's normal on d's side
        const std::array<std::uint32_t, 3> order = k > T(0) ? std::array<std::uint32_t, 3>{0, 1, 2} : std::array<std::uint32_t, 3>{0, 2, 1};
        for (std::uint32_t i : order) add(f, to_world(p, t.x[i]), i);
        f.normal = k > T(0) ? n : linear3::scale(T(-1), n);
        f.which = k > T(0) ? 6u : 7u;
        return f;
    }
    const vec3<T> u = linear3::apply_transposed(p.R, d);
    std::uint32_t v = 0;
    for (std::uint32_t i = 1; i < 3; ++i)
        if (linear3::dot(u, t.x[i]) > linear3::dot(u, t.x[v])) v = i;
    // the edge at v most perpendicular to d
    std::uint32_t other = 3;
    T least = edge_sine<T>;
    for (std::uint32_t w = 0; w < 3; ++w) {
        if (w == v) continue;
        const vec3<T> e = linear3::sub(t.x[w], t.x[v]);
        const T s = absolute(linear3::dot(e, u)) / length(e);
        if (s <= least) least = s, other = w;
    }
    add(f, to_world(p, t.x[v]), v);
    if (other < 3) add(f, to_world(p, t.x[other]), other);
    f.which = other < 3 ? 2 + v + other : v;  // edges (0,1) 3, (0,2) 4, (1,2) 5
    return f;
}

// The ray's distance to the triangle (both sides), or `limit` when it misses within it; the
// triangle in the ray's frame.
template <class T>
[[nodiscard]] constexpr T ray_distance(const triangle<T>& t, const vec3<T>& origin, const vec3<T>& direction, const T& limit) noexcept {
    const vec3<T> e1 = linear3::sub(t.x[1], t.x[0]), e2 = linear3::sub(t.x[2], t.x[0]);
    const vec3<T> p = linear3::cross(direction, e2);
    const T det = linear3::dot(e1, p);
    if (det == T(0)) return limit;  // the ray in the triangle's plane: it meets an edge first (the neighbours')
    const vec3<T> o = linear3::sub(origin, t.x[0]);
    const T beta = linear3::dot(o, p) / det;
    if (beta < T(0) || beta > T(1)) return limit;
    const vec3<T> q = linear3::cross(o, e1);
    const T gamma = linear3::dot(direction, q) / det;
    if (gamma < T(0) || beta + gamma > T(1)) return limit;
    const T s = linear3::dot(e2, q) / det;
    return s >= T(0) && s < limit ? s : limit;
}

}  // namespace ctga::collision
