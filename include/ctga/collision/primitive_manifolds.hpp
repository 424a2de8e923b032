// Contact manifolds (manifold.hpp) of the closed-form pairs whose touching set can be more than a
// point: a capsule or a box against a half-space (its ends, its corners), two capsules side by
// side (the overlap of their cores). The other pairs touch at one point, the separation's witness
// points (narrowphase.hpp: contact_of). A point is kept when its separation is at most the margin
// (speculative contacts: a solver sees a point before it closes).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "ctga/collision/box.hpp"
#include "ctga/collision/capsule.hpp"
#include "ctga/collision/half_space.hpp"
#include "ctga/collision/manifold.hpp"
#include "ctga/collision/primitive_pairs.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {
namespace manifold_detail {
// The point of B at world position s (on B's surface) against the half-space with outward normal
// n through o: separation n·(s − o), A's witness its foot on the boundary.
template <class T>
[[nodiscard]] constexpr contact_point<T> on_plane(const motor_map<T>& plane, const vec3<T>& n, const vec3<T>& s, std::uint32_t id) noexcept {
    const T d = linear3::dot(n, linear3::sub(s, plane.t));
    return {linear3::add_scaled(s, -d, n), s, d, id};
}
}  // namespace manifold_detail

// A capsule on a half-space: each end's lowest point (ids 0: the −z end, 1: the +z end).
template <class T>
[[nodiscard]] constexpr manifold<T> manifold_between(const half_space<T>&, const motor_map<T>& pa, const capsule<T>& b,
                                                     const motor_map<T>& pb, const T& margin) noexcept {
    const vec3<T> n = axis_of(pa, 2);
    const primitive_detail::segment<T> B = primitive_detail::core_of(b, pb);
    manifold<T> m(n);
    for (std::uint32_t end = 0; end < 2; ++end) {
        const vec3<T> e = linear3::add_scaled(B.centre, end == 0 ? T(-1) : T(1), B.half);
        const contact_point<T> p = manifold_detail::on_plane(pa, n, linear3::add_scaled(e, -b.radius, n), end);
        if (p.separation <= margin) m.add(p);
    }
    return m;
}

// A box on a half-space: its corners within the margin, the deepest four (a box resting on a face
// gives that face's corners; tilted onto an edge, the edge's two). Corner id: bit i set for +h_i.
// Corner c is t_B + Σ ±h_i x_i, its height n·(t_B − o) + Σ ±h_i (n·x_i): three projections and
// eight sums, the world points formed for the kept corners only.
template <class T>
[[nodiscard]] constexpr manifold<T> manifold_between(const half_space<T>&, const motor_map<T>& pa, const box<T>& b,
                                                     const motor_map<T>& pb, const T& margin) noexcept {
    const vec3<T> n = axis_of(pa, 2);
    std::array<vec3<T>, 3> e{};  // h_i x_i
    std::array<T, 3> k{};        // h_i (n·x_i)
    for (std::size_t i = 0; i < 3; ++i) {
        e[i] = linear3::scale(b.half[i], axis_of(pb, i));
        k[i] = linear3::dot(n, e[i]);
    }
    const T base = linear3::dot(n, linear3::sub(pb.t, pa.t));
    std::array<T, 8> height{};
    for (std::uint32_t c = 0; c < 8; ++c)
        height[c] = base + ((c & 1u) ? k[0] : -k[0]) + ((c & 2u) ? k[1] : -k[1]) + ((c & 4u) ? k[2] : -k[2]);
    // the four deepest, by selection (each pass takes the deepest left, ties to the lower id)
    manifold<T> m(n);
    std::uint32_t taken = 0;
    for (std::size_t pass = 0; pass < 4; ++pass) {
        std::uint32_t best = 8;
        for (std::uint32_t c = 0; c < 8; ++c)
            if (!((taken >> c) & 1u) && (best == 8 || height[c] < height[best])) best = c;
        if (!(height[best] <= margin)) break;
        taken |= 1u << best;
        vec3<T> x = pb.t;
        for (std::size_t i = 0; i < 3; ++i) x = linear3::add_scaled(x, (best >> i) & 1u ? T(1) : T(-1), e[i]);
        m.add({linear3::add_scaled(x, -height[best], n), x, height[best], best});
    }
    return m;
}

// Two capsules whose cores are parallel to rounding (|d_A × d_B| ≤ 1e-6 |d_A||d_B|) and overlap
// along them: the two ends of the overlap on B's core, each with its closest point on A's core (ids
// 0 and 1); otherwise the one point of the separation. Two lying side by side touch along a
// segment, and its ends carry it.
template <class T>
[[nodiscard]] constexpr manifold<T> manifold_between(const capsule<T>& a, const motor_map<T>& pa, const capsule<T>& b,
                                                     const motor_map<T>& pb, const T& margin) noexcept {
    using namespace primitive_detail;
    const segment<T> A = core_of(a, pa), B = core_of(b, pb);
    const separation<T> s = separation_between(a, pa, b, pb);
    manifold<T> m(s.normal);
    if (!(s.distance <= margin)) return m;
    const T la = linear3::dot(A.half, A.half), lb = linear3::dot(B.half, B.half);
    const vec3<T> c = linear3::cross(A.half, B.half);
    if (la > T(0) && lb > T(0) && linear3::dot(c, c) <= T(1e-12) * la * lb) {
        // B's core in A's axis coordinate τ (A's core is τ ∈ [−1, 1]), clipped to A's
        const T c0 = linear3::dot(linear3::sub(B.centre, A.centre), A.half) / la, dc = linear3::dot(B.half, A.half) / la;
        const T lo0 = c0 - absolute(dc), hi0 = c0 + absolute(dc);
        const T lo = lo0 > T(-1) ? lo0 : T(-1), hi = hi0 < T(1) ? hi0 : T(1);
        if (lo < hi && dc != T(0)) {
            for (std::uint32_t end = 0; end < 2; ++end) {
                const T tau = end == 0 ? lo : hi;
                const vec3<T> on_b = linear3::add_scaled(B.centre, (tau - c0) / dc, B.half);  // B's core point at τ
                const vec3<T> on_a = closest_on(A, on_b);
                const separation<T> e = balls(on_a, a.radius, on_b, b.radius, [&] { return s.normal; });
                if (e.distance <= margin) m.add({e.point_a, e.point_b, e.distance, end});
            }
            if (m.count == 2) {
                m.normal = s.normal;
                return m;
            }
            m.count = 0;
        }
    }
    m.add({s.point_a, s.point_b, s.distance, 0});
    return m;
}

}  // namespace ctga::collision
