// Queries against a triangle surface, a mesh (mesh.hpp) or a height field (height_field.hpp):
// anything with a bounding-volume hierarchy `tree` over items and for_each_triangle(item, visit).
// The surface's queries run in its body frame (B's pose relative to it: Rᵀ R_B, Rᵀ (t_B − t)),
// their answers turned back to the world.
//   separation: the least over its triangles of the triangle's separation from the convex shape
//     B (convex_pairs.hpp), by branch and bound on the hierarchy: a node is visited only while the
//     gap between its box and B's box is below the best distance so far (a lower bound of every
//     distance inside it), so that a far shape meets the few triangles nearest it.
//   contacts: the manifolds (convex_manifolds.hpp) of the triangles within the margin of B (found
//     by B's box grown by the margin), gathered into groups whose normals agree within the feature
//     angle (features.hpp: a box on a floor of many coplanar triangles is one manifold of its four
//     corners), each reduced to four points (add_best_four), deepest group first; point ids mix
//     the triangle's id with the point's own. contact_of gives the deepest group.
//   ray cast: the nearest triangle hit (triangle.hpp: Möller–Trumbore) among those whose boxes
//     the ray enters before the nearest hit so far; the normal the triangle's, facing the ray.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "ctga/collision/aabb.hpp"
#include "ctga/collision/bvh.hpp"
#include "ctga/collision/convex_manifolds.hpp"
#include "ctga/collision/convex_pairs.hpp"
#include "ctga/collision/features.hpp"
#include "ctga/collision/height_field.hpp"
#include "ctga/collision/manifold.hpp"
#include "ctga/collision/mesh.hpp"
#include "ctga/collision/ray_cast.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/collision/triangle.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {

template <class S, class T>
concept triangle_surface = requires(const S& s, std::uint32_t i) {
    { s.tree } -> std::convertible_to<bvh<T>>;
    s.for_each_triangle(i, [](const triangle<T>&, std::uint32_t) {});
};

namespace surface_detail {
// B's pose in the surface's frame.
template <class T>
[[nodiscard]] constexpr motor_map<T> relative(const motor_map<T>& surface, const motor_map<T>& b) noexcept {
    motor_map<T> out{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            T s = T(0);
            for (std::size_t k = 0; k < 3; ++k) s += surface.R[k][i] * b.R[k][j];
            out.R[i][j] = s;
        }
    out.t = to_body(surface, b.t);
    return out;
}
template <class T>
inline constexpr motor_map<T> identity{{{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}}, {T(0), T(0), T(0)}};

template <class T>
[[nodiscard]] constexpr separation<T> to_world(const motor_map<T>& p, const separation<T>& s) noexcept {
    return {s.distance, linear3::apply(p.R, s.normal), collision::to_world(p, s.point_a), collision::to_world(p, s.point_b)};
}

inline constexpr std::size_t max_groups = 8, group_points = 32;
template <class T>
struct group {
    vec3<T> normal;
    std::array<contact_point<T>, group_points> point;
    std::size_t count;
    T deepest;
};
}  // namespace surface_detail

template <class S, class B, class T>
    requires triangle_surface<S, T> && convex_shape<B, T>
[[nodiscard]] constexpr separation<T> separation_between(const S& s, const motor_map<T>& ps, const B& b, const motor_map<T>& pb) noexcept {
    using namespace surface_detail;
    const motor_map<T> local = relative(ps, pb);
    separation<T> best{std::numeric_limits<T>::infinity(), {T(0), T(0), T(1)}, {}, {}};
    (void)nearest(s.tree, bounds_of(b, local), std::numeric_limits<T>::infinity(), [&](std::uint32_t item, const T&) {
        s.for_each_triangle(item, [&](const triangle<T>& t, std::uint32_t) {
            const separation<T> e = convex_separation(t, identity<T>, b, local);
            if (e.distance < best.distance) best = e;
        });
        return best.distance;
    });
    return surface_detail::to_world(ps, best);
}

// What contacts_of found: `count` manifolds written; `overflow` when more groups were met than
// `out` (or 8) holds, the shallowest left out.
struct surface_contacts {
    std::size_t count;
    bool overflow;
};

template <class S, class B, class T>
    requires triangle_surface<S, T> && convex_shape<B, T>
constexpr surface_contacts contacts_of(const S& s, const motor_map<T>& ps, const B& b, const motor_map<T>& pb, const T& margin,
                                       std::span<manifold<T>> out) noexcept {
    using namespace surface_detail;
    const motor_map<T> local = relative(ps, pb);
    std::array<group<T>, max_groups> g{};
    std::size_t groups = 0;
    bool overflow = false;
    for_each_overlap(s.tree, fattened(bounds_of(b, local), margin), [&](std::uint32_t item) {
        s.for_each_triangle(item, [&](const triangle<T>& t, std::uint32_t id) {
            const separation<T> e = convex_separation(t, identity<T>, b, local);
            if (!(e.distance <= margin)) return;
            const manifold<T> m = convex_manifold(t, identity<T>, b, local, e, margin);
            std::size_t k = 0;
            while (k < groups && linear3::dot(g[k].normal, m.normal) < feature_detail::face_cosine<T>) ++k;
            if (k == groups) {
                if (groups == max_groups) {
                    overflow = true;
                    return;
                }
                g[groups++] = {m.normal, {}, 0, std::numeric_limits<T>::infinity()};
            }
            for (std::size_t i = 0; i < m.count; ++i) {
                if (g[k].count == group_points) {  // full: its best four stay
                    manifold<T> four(g[k].normal);
                    add_best_four(four, std::span<const contact_point<T>>(g[k].point.data(), g[k].count));
                    for (std::size_t j = 0; j < four.count; ++j) g[k].point[j] = four.points[j];
                    g[k].count = four.count;
                }
                contact_point<T> p = m.points[i];
                p.id = convex_manifold_detail::mix(id, p.id, 0x5u);
                g[k].point[g[k].count++] = p;
                if ((p.separation) < (g[k].deepest)) g[k].deepest = p.separation;
            }
        });
    });
    // deepest group first
    std::array<std::size_t, max_groups> rank{};
    for (std::size_t k = 0; k < groups; ++k) rank[k] = k;
    for (std::size_t i = 1; i < groups; ++i)
        for (std::size_t j = i; j > 0 && g[rank[j]].deepest < g[rank[j - 1]].deepest; --j) {
            const std::size_t r = rank[j];
            rank[j] = rank[j - 1];
            rank[j - 1] = r;
        }
    const std::size_t count = groups < out.size() ? groups : out.size();
    for (std::size_t k = 0; k < count; ++k) {
        const group<T>& G = g[rank[k]];
        manifold<T> m(G.normal);
        add_best_four(m, std::span<const contact_point<T>>(G.point.data(), G.count));
        m.normal = linear3::apply(ps.R, m.normal);
        for (std::size_t i = 0; i < m.count; ++i) {
            m.points[i].point_a = collision::to_world(ps, m.points[i].point_a);
            m.points[i].point_b = collision::to_world(ps, m.points[i].point_b);
        }
        out[k] = m;
    }
    return {count, overflow || groups > out.size()};
}

template <class S, class B, class T>
    requires triangle_surface<S, T> && convex_shape<B, T>
[[nodiscard]] constexpr manifold<T> manifold_between(const S& s, const motor_map<T>& ps, const B& b, const motor_map<T>& pb,
                                                     const T& margin) noexcept {
    std::array<manifold<T>, 1> one{};
    const surface_contacts c = contacts_of(s, ps, b, pb, margin, std::span<manifold<T>>(one));
    if (c.count == 0) return manifold<T>(separation_between(s, ps, b, pb).normal);
    return one[0];
}

template <class S, class T>
    requires triangle_surface<S, T>
[[nodiscard]] constexpr ray_hit<T> ray_cast(const S& s, const motor_map<T>& ps, const ray<T>& r) noexcept {
    const vec3<T> o = to_body(ps, r.origin), d = linear3::apply_transposed(ps.R, r.direction);
    const ray<T> local = make_ray(o, d, r.max_length);
    vec3<T> normal{};
    const T s_hit = first_hit(s.tree, local, [&](std::uint32_t item, const T& limit) {
        T best = limit;
        s.for_each_triangle(item, [&](const triangle<T>& t, std::uint32_t) {
            const T h = ray_distance(t, o, d, best);
            if (h < best) {
                best = h;
                const vec3<T> n = normal_of(t);
                normal = linear3::dot(n, d) > T(0) ? linear3::scale(T(-1), n) : n;
            }
        });
        return best;
    });
    if (!(s_hit < r.max_length)) return {false, r.max_length, {}, {}};
    return {true, s_hit, linear3::add_scaled(r.origin, s_hit, r.direction), linear3::apply(ps.R, normal)};
}

}  // namespace ctga::collision
