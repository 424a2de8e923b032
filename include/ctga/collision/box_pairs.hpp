// Two boxes. First the separating axis test (Gottschalk, Lin and Manocha 1996): the Minkowski
// difference of two boxes is a convex polytope whose face normals are the boxes' face normals a_i,
// b_j and the edge crossings a_i × b_j, so the penetration depth is the least overlap
// r_A(L) + r_B(L) − |L·D| over those 15 unit axes L (r_X(L) = Σ_i h_i |L·x_i|, D = t_B − t_A),
// exact, and n = ±L towards B; all in A's frame from C = R_Aᵀ R_B, stopping at the first axis that
// separates. Apart: GJK's distance and witnesses (gjk.hpp).
// The manifold of a face axis (Box2D's clipping, in three dimensions): the reference face (the
// face of the axis) and the incident face of the other box (its face most against n); the incident
// face's corners clipped by the reference face's four side planes (Sutherland–Hodgman) are the
// candidates, kept within the margin, at most four (the deepest, the farthest from it, then the
// two that span the most area). The part of the incident face within the margin is cut first
// (clip_faces), so that the side planes meet a corner's triangle when the boxes touch. Each
// point's id is its features: the reference face (0–5: axis 2i, + side 1), the incident face, and
// the corner (0–3), the incident edge e cut by side plane p (4 + 4e + p) or the corner of side
// planes p, p' (20 + 4p + p'): no two points of a manifold share one. An edge axis gives one
// point, the closest points of the two edges (id: bit 31, the axes and the edges); apart within
// the margin, GJK's closest points (the axis bounds the distance from below only).
// The separation's witnesses when overlapping are the manifold's deepest point: for a face axis
// the incident box's deepest corner when it lies over the reference face (no clipping needed).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "ctga/collision/box.hpp"
#include "ctga/collision/gjk.hpp"
#include "ctga/collision/manifold.hpp"
#include "ctga/collision/primitive_pairs.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/inline.hpp"

namespace ctga::collision {
namespace box_detail {
using primitive_detail::absolute;

// The least-overlap axis: kind 0 a face of A (index i), 1 a face of B (j), 2 edges a_i × b_j.
template <class T>
struct axis_choice {
    T depth;
    vec3<T> normal;  // from A towards B
    int kind;
    std::size_t i, j;
};
// In A's frame (Gottschalk, Lin and Manocha's table): C = R_Aᵀ R_B (C_ij = a_i·b_j), D = R_Aᵀ (t_B −
// t_A); along a_i the overlap is h_A,i + Σ_j h_B,j |C_ij| − |D_i|, along b_j Σ_i h_A,i |C_ij| +
// h_B,j − |Σ_i D_i C_ij|, and along L = a_i × b_j (with (i, i1, i2) and (j, j1, j2) cyclic:
// L = (…, −C_i2j, C_i1j) in A's frame, |L| = √(C_i1j² + C_i2j²)) it is
// (h_A,i1 |C_i2j| + h_A,i2 |C_i1j| + h_B,j1 |C_ij2| + h_B,j2 |C_ij1| − |D_i2 C_i1j − D_i1 C_i2j|) / |L|.
// The scan stops at the first face axis whose depth is below `stop` (−margin: apart by more than
// the margin; 0: apart, which is all a distance query needs to know before GJK).
template <class T>
[[nodiscard]] constexpr axis_choice<T> least_overlap(const box<T>& a, const motor_map<T>& pa, const box<T>& b, const motor_map<T>& pb,
                                                    const T& stop) noexcept {
    constexpr std::size_t next[3] = {1, 2, 0}, after[3] = {2, 0, 1};
    std::array<T, 9> C{}, A{};  // row-major, A = |C|
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            C[3 * i + j] = pa.R[0][i] * pb.R[0][j] + pa.R[1][i] * pb.R[1][j] + pa.R[2][i] * pb.R[2][j];
            A[3 * i + j] = absolute(C[3 * i + j]);
        }
    const vec3<T> D = to_body(pa, pb.t);
    const vec3<T>& ha = a.half;
    const vec3<T>& hb = b.half;
    // the 15 axes' overlaps x (to be divided by the axis length l) and L·D = s: faces 0–5, then
    // the edges 6 + 3i + j, each a straight-line formula (the compiler keeps them in registers and
    // takes the nine square roots together)
    std::array<T, 15> x{}, s{};
    const auto answer = [&](std::size_t k, const T& depth, const T& l) CTGA_INLINE_LAMBDA {
        vec3<T> L{};
        axis_choice<T> out{depth, {}, k < 3 ? 0 : k < 6 ? 1 : 2, 0, 0};
        if (k < 3) L[k] = T(1), out.i = k;
        else if (k < 6) L = {C[k - 3], C[3 + k - 3], C[6 + k - 3]}, out.j = k - 3;
        else {
            const std::size_t i = (k - 6) / 3, j = (k - 6) % 3;
            out.i = i, out.j = j;
            L[next[i]] = -C[3 * after[i] + j] / l;
            L[after[i]] = C[3 * next[i] + j] / l;
        }
        out.normal = linear3::apply(pa.R, s[k] < T(0) ? linear3::scale(T(-1), L) : L);
        return out;
    };
    for (std::size_t i = 0; i < 3; ++i) {
        s[i] = D[i];
        x[i] = ha[i] + hb[0] * A[3 * i] + hb[1] * A[3 * i + 1] + hb[2] * A[3 * i + 2] - absolute(D[i]);
        if (x[i] < stop) return answer(i, x[i], T(1));
    }
    for (std::size_t j = 0; j < 3; ++j) {
        s[3 + j] = D[0] * C[j] + D[1] * C[3 + j] + D[2] * C[6 + j];
        x[3 + j] = ha[0] * A[j] + ha[1] * A[3 + j] + ha[2] * A[6 + j] + hb[j] - absolute(s[3 + j]);
        if (x[3 + j] < stop) return answer(3 + j, x[3 + j], T(1));
    }
    std::array<T, 9> l{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            const std::size_t k = 3 * i + j, i1 = next[i], i2 = after[i];
            l[k] = C[3 * i1 + j] * C[3 * i1 + j] + C[3 * i2 + j] * C[3 * i2 + j];
            s[6 + k] = D[i2] * C[3 * i1 + j] - D[i1] * C[3 * i2 + j];
            x[6 + k] = ha[i1] * A[3 * i2 + j] + ha[i2] * A[3 * i1 + j] + hb[next[j]] * A[3 * i + after[j]] +
                       hb[after[j]] * A[3 * i + next[j]] - absolute(s[6 + k]);
        }
    for (std::size_t k = 0; k < 9; ++k) l[k] = math::sqrt(l[k]);
    // the least: faces first; an edge axis (made unit: x/l) wins only by more than `bias` (a
    // relative 1e-9 of the sizes), and is skipped when a_i ∥ b_j (the face axes cover it); the
    // comparison x < (best − bias) l divides only the axis that wins
    std::size_t best = 0;
    T depth = x[0];
    for (std::size_t k = 1; k < 6; ++k)
        if (x[k] < depth) depth = x[k], best = k;
    const T bias = T(1e-9) * (ha[0] + hb[0]);
    for (std::size_t k = 0; k < 9; ++k)
        if (l[k] > T(1e-6) && x[6 + k] < (depth - bias) * l[k]) {
            depth = x[6 + k] / l[k], best = 6 + k;
            if (depth < stop) break;
        }
    return answer(best, depth, best < 6 ? T(1) : l[best - 6]);
}

// A point of the incident face in the reference face's coordinates: u, v along the reference
// box's two axes across its face (i + 1, i + 2: with the face axis i a right-handed frame), s its
// separation (its height over the face); the incident edge it lies on (a corner: the edge that
// leaves it), the lines it lies on (bits 0–3 the side planes, bit 4 the depth line s = margin,
// where the part within the margin was cut from the face), and its feature: corner 0–3, incident
// edge e cut by side plane p 4 + 4e + p, or the corner of side planes p < p' 20 + 4p + p'.
template <class T>
struct face_point {
    T u, v, s;
    std::uint32_t feature;
    std::uint8_t edge, lines;
};
inline constexpr std::uint8_t depth_line = 16;

// One plane, sign · coordinate ≤ bound (Sutherland–Hodgman), the coordinate a member (every
// access at a fixed offset: an element written at an index known only at run time and read back
// as a vector stalls the store forwarding). A segment joining two points on one line lies on that
// line: cut there, it gives the corner of two side planes (or a point of the depth line); else
// it runs along its first point's incident edge.
template <auto coordinate, class T>
[[nodiscard]] constexpr std::size_t clip_by(const std::array<face_point<T>, 8>& poly, std::size_t count, std::array<face_point<T>, 8>& next,
                                            const T& sign, const T& bound, std::uint32_t plane) noexcept {
    std::size_t m = 0;
    for (std::size_t e = 0; e < count; ++e) {
        const face_point<T>& p = poly[e];
        const face_point<T>& q = poly[e + 1 == count ? 0 : e + 1];
        const T dp = sign * (p.*coordinate) - bound, dq = sign * (q.*coordinate) - bound;
        if (dp <= T(0)) next[m++] = p;
        if ((dp <= T(0)) != (dq <= T(0))) {
            const T t = dp / (dp - dq);
            const std::uint32_t shared = p.lines & q.lines & 15u;
            const std::uint32_t first = (shared & 1u) ? 0 : (shared & 2u) ? 1 : (shared & 4u) ? 2 : 3;
            const std::uint32_t feature = shared != 0 ? 20 + 4 * first + plane : 4 + 4 * std::uint32_t(p.edge) + plane;
            next[m++] = {p.u + t * (q.u - p.u), p.v + t * (q.v - p.v), p.s + t * (q.s - p.s), feature, p.edge,
                         static_cast<std::uint8_t>((p.lines & q.lines) | (1u << plane))};
        }
    }
    return m;
}

// Face manifold: the reference face is box R's (pose pr) on axis i, facing the incident box I
// along m (unit, from R towards I); n is the manifold's normal (from A to B: m, or −m when R is
// B). The incident face is I's face most against m. The candidates are the corners of the
// incident face clipped by the reference face's four side planes |u| ≤ h_R,i+1, |v| ≤ h_R,i+2
// that lie within the margin (s ≤ margin): the same as the corners of the incident face's part
// within the margin, so clipped, but for those on its depth line s = margin. That part is
// clipped first (it is small when the boxes touch: a corner's triangle), and a side plane it
// lies within is passed over.
template <class T>
[[nodiscard]] constexpr manifold<T> clip_faces(const box<T>& R, const motor_map<T>& pr, std::size_t i, const vec3<T>& m, const box<T>& I,
                                               const motor_map<T>& pi, const vec3<T>& n, bool reference_is_a, const T& margin) noexcept {
    constexpr std::size_t next[3] = {1, 2, 0}, after[3] = {2, 0, 1};
    const vec3<T> a0 = axis_of(pr, i), a1 = axis_of(pr, next[i]), a2 = axis_of(pr, after[i]);
    const T side = linear3::dot(m, a0) > T(0) ? T(1) : T(-1);  // the reference face: outward along m
    // the incident face: I's axis k most along m, its side against m
    const T d0 = linear3::dot(m, axis_of(pi, 0)), d1 = linear3::dot(m, axis_of(pi, 1)), d2 = linear3::dot(m, axis_of(pi, 2));
    const T b0 = absolute(d0), b1 = absolute(d1), b2 = absolute(d2);
    const std::size_t k = b0 >= b1 ? (b0 >= b2 ? 0 : 2) : (b1 >= b2 ? 1 : 2);
    const T dk = k == 0 ? d0 : k == 1 ? d1 : d2;
    const T inc_side = dk > T(0) ? T(-1) : T(1);
    const std::size_t ku = next[k], kv = after[k];
    const vec3<T> centre = linear3::sub(linear3::add_scaled(pi.t, inc_side * I.half[k], axis_of(pi, k)), pr.t);
    const vec3<T> eu = linear3::scale(I.half[ku], axis_of(pi, ku)), ev = linear3::scale(I.half[kv], axis_of(pi, kv));
    const vec3<T> out_of_face = linear3::scale(side, a0);
    const auto local = [&](const vec3<T>& x) { return vec3<T>{linear3::dot(x, a1), linear3::dot(x, a2), linear3::dot(x, out_of_face)}; };
    const vec3<T> c = linear3::sub(local(centre), vec3<T>{T(0), T(0), R.half[i]}), cu = local(eu), cv = local(ev);
    constexpr int su[4] = {1, -1, -1, 1}, sv[4] = {1, 1, -1, -1};  // a cycle around the face
    std::array<std::array<face_point<T>, 8>, 2> buffer;  // ping-pong (written before read)
    for (std::uint32_t e = 0; e < 4; ++e)
        buffer[1][e] = {c[0] + T(su[e]) * cu[0] + T(sv[e]) * cv[0], c[1] + T(su[e]) * cu[1] + T(sv[e]) * cv[1],
                        c[2] + T(su[e]) * cu[2] + T(sv[e]) * cv[2], e, static_cast<std::uint8_t>(e), 0};
    std::size_t count = clip_by<&face_point<T>::s>(buffer[1], 4, buffer[0], T(1), margin, 4);
    std::size_t in = 0;
    const T hu = R.half[next[i]], hv = R.half[after[i]];
    T u_low = buffer[0][0].u, u_high = u_low, v_low = buffer[0][0].v, v_high = v_low;
    for (std::size_t e = 1; e < count; ++e) {
        u_low = buffer[0][e].u < u_low ? buffer[0][e].u : u_low;
        u_high = buffer[0][e].u > u_high ? buffer[0][e].u : u_high;
        v_low = buffer[0][e].v < v_low ? buffer[0][e].v : v_low;
        v_high = buffer[0][e].v > v_high ? buffer[0][e].v : v_high;
    }
    if (count > 0 && (u_low < -hu || u_high > hu || v_low < -hv || v_high > hv)) {
        const auto side_plane = [&]<auto coordinate>(const T& sign, const T& bound, std::uint32_t plane) {
            bool outside = false;
            for (std::size_t e = 0; e < count; ++e) outside = outside || sign * (buffer[in][e].*coordinate) > bound;
            if (outside) count = clip_by<coordinate>(buffer[in], count, buffer[1 - in], sign, bound, plane), in = 1 - in;
        };
        side_plane.template operator()<&face_point<T>::u>(T(-1), hu, 0);
        side_plane.template operator()<&face_point<T>::u>(T(1), hu, 1);
        side_plane.template operator()<&face_point<T>::v>(T(-1), hv, 2);
        side_plane.template operator()<&face_point<T>::v>(T(1), hv, 3);
    }
    // the candidates (not on the depth line), at most four kept (best_four in the frame (u, v, s),
    // its normal (0, 0, 1)), turned to the world
    std::array<std::uint8_t, 8> pick;
    std::size_t np = 0;
    for (std::size_t e = 0; e < count; ++e)
        if (!(buffer[in][e].lines & depth_line) && buffer[in][e].s <= margin) pick[np++] = static_cast<std::uint8_t>(e);
    const std::uint32_t faces = static_cast<std::uint32_t>(2 * i + (side > T(0) ? 1 : 0)) |
                                (static_cast<std::uint32_t>(2 * k + (inc_side > T(0) ? 1 : 0)) << 3);
    if (np > 4) {
        std::array<contact_point<T>, 8> cand;
        for (std::size_t e = 0; e < np; ++e) {
            const face_point<T>& x = buffer[in][pick[e]];
            cand[e] = {{x.u, x.v, T(0)}, {x.u, x.v, x.s}, x.s, 0};
        }
        const four_of kept = best_four(std::span<const contact_point<T>>(cand.data(), np), vec3<T>{T(0), T(0), T(1)});
        const std::array<std::uint8_t, 8> all = pick;
        for (std::size_t e = 0; e < kept.count; ++e) pick[e] = all[kept.index[e]];
        np = kept.count;
    }
    const vec3<T> face_centre = linear3::add_scaled(pr.t, side * R.half[i], a0);
    manifold<T> out(n);
    for (std::size_t e = 0; e < np; ++e) {
        const face_point<T>& x = buffer[in][pick[e]];
        const vec3<T> foot = linear3::add_scaled(linear3::add_scaled(face_centre, x.u, a1), x.v, a2);
        const vec3<T> on_incident = linear3::add_scaled(foot, x.s, out_of_face);
        const std::uint32_t id = faces | (x.feature << 6);
        out.add(reference_is_a ? contact_point<T>{foot, on_incident, x.s, id} : contact_point<T>{on_incident, foot, x.s, id});
    }
    return out;
}

// Edge manifold: the edges of A along a_i and of B along b_j that support n and −n; one point.
template <class T>
[[nodiscard]] constexpr manifold<T> edge_point(const box<T>& a, const motor_map<T>& pa, std::size_t i, const box<T>& b,
                                               const motor_map<T>& pb, std::size_t j, const vec3<T>& n, const T& margin) noexcept {
    const auto edge = [](const box<T>& x, const motor_map<T>& p, std::size_t k, const vec3<T>& d) {
        vec3<T> centre = p.t;
        std::uint32_t id = 0;
        for (std::size_t m = 0; m < 3; ++m) {
            if (m == k) continue;
            const T s = linear3::dot(d, axis_of(p, m)) < T(0) ? T(-1) : T(1);
            centre = linear3::add_scaled(centre, s * x.half[m], axis_of(p, m));
            id = id * 2 + (s > T(0) ? 1u : 0u);
        }
        return std::pair{primitive_detail::segment<T>{centre, linear3::scale(x.half[k], axis_of(p, k))}, id};
    };
    const auto [ea, ida] = edge(a, pa, i, n);
    const auto [eb, idb] = edge(b, pb, j, linear3::scale(T(-1), n));
    const primitive_detail::closest_pair<T> c = primitive_detail::closest_points(ea, eb);
    const T sep = linear3::dot(n, linear3::sub(c.q, c.p));
    manifold<T> out(n);
    if (sep <= margin)
        out.add({c.p, c.q, sep, static_cast<std::uint32_t>((1u << 31) | ((3 * i + j) << 4) | (ida << 2) | idb)});
    return out;
}

template <class T>
[[nodiscard]] constexpr manifold<T> overlap_manifold(const box<T>& a, const motor_map<T>& pa, const box<T>& b,
                                                     const motor_map<T>& pb, const axis_choice<T>& ax, const T& margin) noexcept {
    if (ax.kind == 0) return clip_faces(a, pa, ax.i, ax.normal, b, pb, ax.normal, true, margin);
    if (ax.kind == 1) return clip_faces(b, pb, ax.j, linear3::scale(T(-1), ax.normal), a, pa, ax.normal, false, margin);
    return edge_point(a, pa, ax.i, b, pb, ax.j, ax.normal, margin);
}
}  // namespace box_detail

template <class T>
[[nodiscard]] constexpr separation<T> separation_between(const box<T>& a, const motor_map<T>& pa, const box<T>& b,
                                                         const motor_map<T>& pb) noexcept {
    const box_detail::axis_choice<T> ax = box_detail::least_overlap(a, pa, b, pb, T(0));
    if (ax.depth < T(0)) {  // apart: GJK's distance
        const gjk_result<T> g = gjk(a, pa, b, pb, T(1e-14));
        const vec3<T> d = linear3::sub(g.point_b, g.point_a);
        const T l = length(d);
        if (!g.overlap && l > T(0)) return {l, linear3::scale(T(1) / l, d), g.point_a, g.point_b};
    }
    // a face axis: the incident box's deepest corner, when it lies over the reference face, is the
    // deepest point of the clipped face (the manifold's), found without clipping
    if (ax.kind != 2) {
        const bool on_a = ax.kind == 0;
        const box<T>& R = on_a ? a : b;
        const motor_map<T>& pr = on_a ? pa : pb;
        const std::size_t k = on_a ? ax.i : ax.j;
        const vec3<T> into = on_a ? linear3::scale(T(-1), ax.normal) : ax.normal;  // the incident's deepest way
        const vec3<T> corner = gjk_detail::world_support(on_a ? b : a, on_a ? pb : pa, into);
        const vec3<T> c = to_body(pr, corner);
        const std::size_t u = (k + 1) % 3, v = (k + 2) % 3;
        if (box_detail::absolute(c[u]) <= R.half[u] && box_detail::absolute(c[v]) <= R.half[v]) {
            const vec3<T> across = linear3::scale(ax.depth, ax.normal);
            return on_a ? separation<T>{-ax.depth, ax.normal, linear3::add(corner, across), corner}
                        : separation<T>{-ax.depth, ax.normal, corner, linear3::sub(corner, across)};
        }
    }
    const manifold<T> m = box_detail::overlap_manifold(a, pa, b, pb, ax, T(0));
    if (m.count == 0) return {-ax.depth, ax.normal, pa.t, pb.t};  // (clipping lost every point: rounding)
    std::size_t deepest = 0;
    for (std::size_t e = 1; e < m.count; ++e)
        if ((m.points[e].separation) < (m.points[deepest].separation)) deepest = e;
    return {-ax.depth, ax.normal, m.points[deepest].point_a, m.points[deepest].point_b};
}

template <class T>
[[nodiscard]] constexpr manifold<T> manifold_between(const box<T>& a, const motor_map<T>& pa, const box<T>& b,
                                                     const motor_map<T>& pb, const T& margin) noexcept {
    const box_detail::axis_choice<T> ax = box_detail::least_overlap(a, pa, b, pb, -margin);
    // apart by more than the margin along an axis: no contact (a lower bound of the distance)
    if (-ax.depth > margin) return manifold<T>(ax.normal);
    // apart along an edge axis, within the margin: the axis gives a lower bound of the distance,
    // and the supporting edges' closest points need not lie along it; the point is the closest
    // points (GJK), its id the edges'
    if (ax.kind == 2 && ax.depth < T(0)) {
        const separation<T> d = separation_between(a, pa, b, pb);
        const manifold<T> edges = box_detail::edge_point(a, pa, ax.i, b, pb, ax.j, ax.normal, std::numeric_limits<T>::infinity());
        manifold<T> out(d.normal);
        if (d.distance <= margin) out.add({d.point_a, d.point_b, d.distance, edges.points[0].id});
        return out;
    }
    return box_detail::overlap_manifold(a, pa, b, pb, ax, margin);
}

}  // namespace ctga::collision
