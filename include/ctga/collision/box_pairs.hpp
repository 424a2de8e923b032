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
// two that span the most area). Each point's id is its features: the reference face (0–5: axis
// 2i, + side 1), the incident face, and the corner (0–3) or the incident edge (4 + 4e) cut by side
// plane p (+ p). An edge axis gives one point, the closest points of the two edges (id: bit 31,
// the axes and the edges).
// The separation's witnesses when overlapping are the manifold's deepest point: for a face axis
// the incident box's deepest corner when it lies over the reference face (no clipping needed).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "ctga/collision/box.hpp"
#include "ctga/collision/gjk.hpp"
#include "ctga/collision/manifold.hpp"
#include "ctga/collision/primitive_pairs.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"

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
    const auto answer = [&](std::size_t k, const T& depth, const T& l) {
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

// The face of box b (pose p) whose outward normal is most against n: axis k, side ±1.
template <class T>
struct face {
    std::size_t axis;
    T side;
};
template <class T>
[[nodiscard]] constexpr face<T> most_against(const motor_map<T>& p, const vec3<T>& n) noexcept {
    std::size_t k = 0;
    for (std::size_t i = 1; i < 3; ++i)
        if (absolute(linear3::dot(n, axis_of(p, i))) > absolute(linear3::dot(n, axis_of(p, k)))) k = i;
    return {k, linear3::dot(n, axis_of(p, k)) > T(0) ? T(-1) : T(1)};
}
template <class T>
[[nodiscard]] constexpr std::uint32_t face_id(const face<T>& f) noexcept {
    return static_cast<std::uint32_t>(2 * f.axis + (f.side > T(0) ? 1 : 0));
}

// A clipped corner: its position and its feature (corner 0–3, or 4 + 4 edge + side plane).
template <class T>
struct corner {
    vec3<T> x;
    std::uint32_t feature;
};

// Face manifold: reference box R (pose pr) with face axis i along n (n pointing away from R
// towards the incident box I), incident box I.
template <class T>
[[nodiscard]] constexpr manifold<T> clip_faces(const box<T>& R, const motor_map<T>& pr, std::size_t i, const vec3<T>& n,
                                               const box<T>& I, const motor_map<T>& pi, const T& margin) noexcept {
    const face<T> ref{i, linear3::dot(n, axis_of(pr, i)) > T(0) ? T(1) : T(-1)};
    const face<T> inc = most_against(pi, n);
    // the incident face's corners in R's frame (a cycle around the face), where the side planes
    // are |x_u| ≤ h_u, |x_v| ≤ h_v: clipping compares one coordinate
    const std::size_t u = (inc.axis + 1) % 3, v = (inc.axis + 2) % 3;
    const vec3<T> centre = to_body(pr, linear3::add_scaled(pi.t, inc.side * I.half[inc.axis], axis_of(pi, inc.axis)));
    const vec3<T> eu = linear3::apply_transposed(pr.R, linear3::scale(I.half[u], axis_of(pi, u)));
    const vec3<T> ev = linear3::apply_transposed(pr.R, linear3::scale(I.half[v], axis_of(pi, v)));
    constexpr int su[4] = {1, -1, -1, 1}, sv[4] = {1, 1, -1, -1};
    std::array<std::array<corner<T>, 8>, 2> buffer;  // ping-pong (written before read)
    std::size_t in = 0, count = 4;
    for (std::uint32_t c = 0; c < 4; ++c)
        buffer[0][c] = {linear3::add_scaled(linear3::add_scaled(centre, T(su[c]), eu), T(sv[c]), ev), c};
    std::uint32_t plane = 0;
    for (std::size_t s = 1; s < 3; ++s) {
        const std::size_t k = (i + s) % 3;
        for (int sign = -1; sign <= 1; sign += 2, ++plane) {
            const std::array<corner<T>, 8>& poly = buffer[in];
            std::array<corner<T>, 8>& next = buffer[1 - in];
            std::size_t m = 0;
            for (std::size_t e = 0; e < count; ++e) {
                const corner<T>& p = poly[e];
                const corner<T>& q = poly[e + 1 == count ? 0 : e + 1];
                const T dp = T(sign) * p.x[k] - R.half[k], dq = T(sign) * q.x[k] - R.half[k];
                if (dp <= T(0)) next[m++] = p;
                if ((dp <= T(0)) != (dq <= T(0))) {
                    const T t = dp / (dp - dq);
                    const std::uint32_t edge = (p.feature) < 4 ? p.feature : ((p.feature - 4) / 4) % 4;
                    next[m++] = {linear3::add_scaled(p.x, t, linear3::sub(q.x, p.x)), 4 + 4 * edge + plane};
                }
            }
            in = 1 - in;
            count = m;
        }
    }
    // candidates within the margin: their height over the reference face; in R's frame, the normal
    // ±e_i, turned to the world for the four kept
    std::array<contact_point<T>, 8> cand;
    std::size_t nc = 0;
    for (std::size_t e = 0; e < count; ++e) {
        const vec3<T>& x = buffer[in][e].x;
        const T sep = ref.side * x[i] - R.half[i];
        if (sep <= margin) {
            vec3<T> foot = x;
            foot[i] = ref.side * R.half[i];
            cand[nc++] = {foot, x, sep, face_id(ref) | (face_id(inc) << 3) | (buffer[in][e].feature << 6)};
        }
    }
    vec3<T> local_n{};
    local_n[i] = ref.side;
    manifold<T> local(local_n);
    add_best_four(local, std::span<const contact_point<T>>(cand.data(), nc));
    manifold<T> out(n);
    for (std::size_t e = 0; e < local.count; ++e) {
        const vec3<T> on_b = to_world(pr, local.points[e].point_b);  // its foot on the face: sep · n below
        out.add({linear3::add_scaled(on_b, -local.points[e].separation, n), on_b, local.points[e].separation, local.points[e].id});
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
    if (ax.kind == 0) return clip_faces(a, pa, ax.i, ax.normal, b, pb, margin);
    if (ax.kind == 1) return reversed(clip_faces(b, pb, ax.j, linear3::scale(T(-1), ax.normal), a, pa, margin));
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
    return box_detail::overlap_manifold(a, pa, b, pb, ax, margin);
}

}  // namespace ctga::collision
