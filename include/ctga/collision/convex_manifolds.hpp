// The contact manifold of any two convex shapes (and of a convex shape on a half-space) from their
// separation and support features (features.hpp), as Box2D and Box3D cut it for polygons:
//   1. the separation (narrowphase) gives the normal n from A to B; farther than the margin, none;
//   2. A's feature along n and B's along −n; if either is a single point, the separation's
//      witnesses are the one point;
//   3. the reference is the face (≥ 3 points) better aligned with n, A's on a tie; the other
//      feature, the incident one, is clipped by the reference face's side planes (Sutherland–
//      Hodgman): for corners p_i counter-clockwise about the outward normal m, x is inside side i
//      when (x − p_i)·((p_{i+1} − p_i) × m) ≤ 0; a half-space's plane has no sides;
//   4. each clipped point x of the incident core is a candidate, its separation its height above
//      the reference plane less both radii, its witnesses x − r_I m on the incident surface and
//      its foot on the reference plane + r_R m; two parallel segments (no face, within the feature
//      angle) keep the incident segment's part beside the reference one, each point against its
//      closest point there;
//   5. the candidates within the margin, at most four (manifold.hpp: add_best_four); none left
//      (crossing segments, rounding): the separation's witnesses.
// The manifold's normal is the reference face's (towards B), so that a resting contact keeps one
// normal from step to step. A point's id combines the reference feature, the incident feature
// and the point's own (a corner, or the incident side k cut by the reference side i), bit 31 set
// when B holds the reference.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "ctga/collision/features.hpp"
#include "ctga/collision/half_space.hpp"
#include "ctga/collision/manifold.hpp"
#include "ctga/collision/primitive_pairs.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {
namespace convex_manifold_detail {

template <class T>
struct clipped {
    vec3<T> x;
    std::uint32_t id;
};
inline constexpr std::size_t max_clipped = 2 * max_feature_points + 4;

[[nodiscard]] constexpr std::uint32_t mix(std::uint32_t a, std::uint32_t b, std::uint32_t c) noexcept {
    std::uint32_t h = a * 0x9E3779B1u;
    h = (h ^ (b + 0x7F4A7C15u + (h << 6) + (h >> 2))) * 0x85EBCA77u;
    h = (h ^ (c + 0x165667B1u + (h << 6) + (h >> 2))) * 0xC2B2AE3Du;
    return h & 0x7FFFFFFFu;
}

// The incident feature I clipped by the reference face R's side planes (R with ≥ 3 corners; a
// half-space: R.count == 0, no sides).
template <class T>
[[nodiscard]] constexpr std::size_t clip(const feature<T>& R, const feature<T>& I, std::array<clipped<T>, max_clipped>& out) noexcept {
    std::array<clipped<T>, max_clipped> next{};
    std::size_t count = I.count;
    for (std::size_t k = 0; k < I.count; ++k) out[k] = {I.x[k], I.id[k]};
    for (std::size_t i = 0; i < R.count && count > 0; ++i) {
        const vec3<T> p = R.x[i], q = R.x[(i + 1) % R.count];
        const vec3<T> side = linear3::cross(linear3::sub(q, p), R.normal);
        const auto outside = [&](const vec3<T>& x) { return linear3::dot(linear3::sub(x, p), side); };
        std::size_t m = 0;
        // a segment (two points) is clipped as a segment, not as a closed polygon
        const std::size_t edges = count == 2 ? 1 : count;
        if (count == 1) {
            if (outside(out[0].x) <= T(0)) next[m++] = out[0];
        } else {
            if (count == 2 && outside(out[0].x) <= T(0)) next[m++] = out[0];
            for (std::size_t e = 0; e < edges; ++e) {
                const clipped<T>& a = out[e];
                const clipped<T>& b = out[(e + 1) % count];
                const T da = outside(a.x), db = outside(b.x);
                if (count > 2 && da <= T(0)) next[m++] = a;
                if ((da <= T(0)) != (db <= T(0)))
                    next[m++] = {linear3::add_scaled(a.x, da / (da - db), linear3::sub(b.x, a.x)), 0x40000000u | (a.id << 8) | std::uint32_t(i)};
                if (count == 2 && db <= T(0)) next[m++] = b;
            }
        }
        for (std::size_t k = 0; k < m; ++k) out[k] = next[k];
        count = m;
    }
    return count;
}

// The manifold with A's feature as the reference (A's radius ra, B's rb); n the separation's normal.
template <class T>
[[nodiscard]] constexpr manifold<T> cut(const feature<T>& R, const T& rr, const feature<T>& I, const T& ri, const vec3<T>& n,
                                        const vec3<T>& plane_point, const T& margin) noexcept {
    manifold<T> m(n);
    std::array<contact_point<T>, max_clipped> cand{};
    std::size_t nc = 0;
    if (R.count >= 3 || R.count == 0) {
        const vec3<T> mn = R.normal;  // outward from the reference, towards the incident shape
        m.normal = mn;
        std::array<clipped<T>, max_clipped> pts{};
        const std::size_t count = clip(R, I, pts);
        for (std::size_t k = 0; k < count; ++k) {
            const T h = linear3::dot(mn, linear3::sub(pts[k].x, plane_point));
            const T sep = h - rr - ri;
            if (sep <= margin)
                cand[nc++] = {linear3::add_scaled(pts[k].x, rr - h, mn), linear3::add_scaled(pts[k].x, -ri, mn), sep,
                              mix(R.which, I.which, pts[k].id)};
        }
    } else {
        // two segments: the incident one's part beside the reference one, each point to its closest
        const primitive_detail::segment<T> S{linear3::scale(T(0.5), linear3::add(R.x[0], R.x[1])),
                                             linear3::scale(T(0.5), linear3::sub(R.x[1], R.x[0]))};
        const vec3<T> e = linear3::sub(R.x[1], R.x[0]);
        const T ee = linear3::dot(e, e);
        const vec3<T> a = I.x[0], b = I.x[1];
        const vec3<T> c = linear3::cross(e, linear3::sub(b, a));
        // not parallel within the feature angle: they touch at one point
        if (linear3::dot(c, c) > feature_detail::edge_sine<T> * feature_detail::edge_sine<T> * ee * linear3::dot(linear3::sub(b, a), linear3::sub(b, a)))
            return m;
        const T ta = linear3::dot(linear3::sub(a, R.x[0]), e) / ee, tb = linear3::dot(linear3::sub(b, R.x[0]), e) / ee;
        if (ta == tb) return m;
        for (std::uint32_t end = 0; end < 2; ++end) {
            const T want = end == 0 ? (ta < tb ? ta : tb) : (ta < tb ? tb : ta);
            const T t = want < T(0) ? T(0) : want > T(1) ? T(1) : want;  // within the reference's span
            const vec3<T> x = linear3::add_scaled(a, (t - ta) / (tb - ta), linear3::sub(b, a));
            const separation<T> s = primitive_detail::balls(primitive_detail::closest_on(S, x), rr, x, ri, [&] { return n; });
            if (s.distance <= margin) cand[nc++] = {s.point_a, s.point_b, s.distance, mix(R.which, I.which, end)};
        }
    }
    add_best_four(m, std::span<const contact_point<T>>(cand.data(), nc));
    return m;
}
}  // namespace convex_manifold_detail

// A and B convex (features.hpp), s their separation.
template <class A, class B, class T>
[[nodiscard]] constexpr manifold<T> convex_manifold(const A& a, const motor_map<T>& pa, const B& b, const motor_map<T>& pb,
                                                    const separation<T>& s, const T& margin) noexcept {
    using namespace convex_manifold_detail;
    manifold<T> m(s.normal);
    if (!(s.distance <= margin)) return m;
    const feature<T> fa = support_feature(a, pa, s.normal), fb = support_feature(b, pb, linear3::scale(T(-1), s.normal));
    if (fa.count == 1 || fb.count == 1) {
        m.add({s.point_a, s.point_b, s.distance, mix(fa.which, fb.which, 0)});
        return m;
    }
    const T ra = core_radius(a), rb = core_radius(b);
    const bool b_reference = fb.count >= 3 && (fa.count < 3 || -linear3::dot(fb.normal, s.normal) > linear3::dot(fa.normal, s.normal));
    manifold<T> r = b_reference ? reversed(cut(fb, rb, fa, ra, linear3::scale(T(-1), s.normal), fb.x[0], margin))
                                : cut(fa, ra, fb, rb, s.normal, fa.x[0], margin);
    for (std::size_t k = 0; b_reference && k < r.count; ++k) r.points[k].id |= 0x80000000u;
    if (r.count == 0) r.add({s.point_a, s.point_b, s.distance, mix(fa.which, fb.which, 0)});  // (clipping left none: the witnesses)
    return r;
}

// A half-space A and a convex shape B: B's feature along −n, every point of it (no sides).
template <class B, class T>
[[nodiscard]] constexpr manifold<T> half_space_manifold(const motor_map<T>& pa, const B& b, const motor_map<T>& pb, const T& margin) noexcept {
    feature<T> plane;  // count 0: no sides
    plane.normal = axis_of(pa, 2);
    plane.which = 0;
    const feature<T> fb = support_feature(b, pb, linear3::scale(T(-1), plane.normal));
    return convex_manifold_detail::cut(plane, T(0), fb, core_radius(b), plane.normal, pa.t, margin);
}

}  // namespace ctga::collision
