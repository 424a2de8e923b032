// A convex hull, built once from points in its body's frame: its vertices, its faces (convex
// polygons, counter-clockwise seen from outside, with outward unit normal n and offset d: n·x ≤ d
// inside) and its edges (two vertices and the faces on either side).
// Construction: quickhull (Barber, Dobkin and Huhdanpaa 1996) on the triangle surface of
// polytope.hpp, from the tetrahedron of four extreme points, adding each time the point farthest
// above a triangle until none is above any by more than ε = 2⁷ ε_T times the points' extent; then
// triangles whose neighbour's far corner lies within ε of their plane are one face, and each
// face's polygon is the 2-D convex hull of its corners in its plane (Andrew's monotone chain),
// which drops corners in line with an edge. V − E + F = 2 holds for the result.
// Capacity N (a template argument) bounds the vertices: at most 2N − 4 faces and 3N − 6 edges, so
// the hull is a value of fixed size with no heap.
// Its mass at density ρ: the solid split into tetrahedra from the vertices' mean c to each face's
// fan; a tetrahedron of corners p0…p3 (from c) has volume det(p1 − p0, p2 − p0, p3 − p0)/6 and
// second moment ∫ x xᵀ = V/20 (Σ p_i p_iᵀ + (Σ p_i)(Σ p_i)ᵀ); the inertia about the centre G is
// tr(C) 1 − C with C = ρ ∫ (x − G)(x − G)ᵀ.
// Reported at construction: too_few_points (< 4), capacity_exceeded (more than N points),
// non_finite, coplanar_points (all within ε of one plane, or of one line, or one point).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "ctga/collision/polytope.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

template <class T>
struct hull_face {
    vec3<T> normal;  // unit, outward
    T offset;        // normal · x ≤ offset inside
    std::uint16_t first, count;  // its corners: face_vertex[first … first + count)
};
struct hull_edge {
    std::uint16_t a, b;        // vertices; face `left` has the edge a → b counter-clockwise
    std::uint16_t left, right;  // faces
};

template <class T, std::size_t N>
struct convex_hull {
    static_assert(N >= 4 && N <= 8192, "ctga::collision::convex_hull: the capacity N must be between 4 and 8192 vertices");
    static constexpr std::size_t max_faces = 2 * N - 4, max_edges = 3 * N - 6;
    std::size_t vertex_count = 0, face_count = 0, edge_count = 0;
    std::array<vec3<T>, N> vertex{};
    std::array<hull_face<T>, max_faces> face{};
    std::array<std::uint16_t, 2 * max_edges> face_vertex{};
    std::array<hull_edge, max_edges> edge{};
};

namespace hull_detail {
using index = std::uint16_t;

template <class T>
[[nodiscard]] constexpr T line_distance2(const vec3<T>& a, const vec3<T>& b, const vec3<T>& q) noexcept {
    const vec3<T> ab = linear3::sub(b, a), c = linear3::cross(ab, linear3::sub(q, a));
    return linear3::dot(c, c) / linear3::dot(ab, ab);
}

// The starting tetrahedron's corners: the lowest x, the farthest from it, the farthest from their
// line, the farthest from their plane (false: the points span no volume).
template <class T>
[[nodiscard]] constexpr bool extreme_four(std::span<const vec3<T>> x, const T& eps, std::array<index, 4>& out) noexcept {
    index i0 = 0, i1 = 0, i2 = 0, i3 = 0;
    for (index i = 1; i < x.size(); ++i)
        if (x[i][0] < x[i0][0]) i0 = i;
    T best = T(0);
    for (index i = 0; i < x.size(); ++i) {
        const vec3<T> d = linear3::sub(x[i], x[i0]);
        if (linear3::dot(d, d) > best) best = linear3::dot(d, d), i1 = i;
    }
    if (!(best > eps * eps)) return false;
    best = T(0);
    for (index i = 0; i < x.size(); ++i)
        if (const T d = line_distance2(x[i0], x[i1], x[i]); d > best) best = d, i2 = i;
    if (!(best > eps * eps)) return false;
    const vec3<T> n = linear3::cross(linear3::sub(x[i1], x[i0]), linear3::sub(x[i2], x[i0]));
    const T nl = length(n);
    best = T(0);
    for (index i = 0; i < x.size(); ++i) {
        const T d = linear3::dot(n, linear3::sub(x[i], x[i0])) / nl;
        if ((d < T(0) ? -d : d) > best) best = d < T(0) ? -d : d, i3 = i;
    }
    if (!(best > eps)) return false;
    out = {i0, i1, i2, i3};
    return true;
}

template <std::size_t M>
[[nodiscard]] constexpr std::size_t find(std::array<std::size_t, M>& parent, std::size_t i) noexcept {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// Andrew's monotone chain on the points' coordinates (u·x, v·x): the convex polygon's corners
// counter-clockwise (seen from u × v), collinear ones dropped; returns their number.
template <class T, std::size_t M>
[[nodiscard]] constexpr std::size_t polygon(std::span<const vec3<T>> x, std::array<index, M>& ids, std::size_t n, const vec3<T>& u,
                                            const vec3<T>& v, const T& eps) noexcept {
    const auto less = [&](index a, index b) {
        const T ua = linear3::dot(u, x[a]), ub = linear3::dot(u, x[b]);
        return ua < ub || (ua == ub && linear3::dot(v, x[a]) < linear3::dot(v, x[b]));
    };
    for (std::size_t i = 1; i < n; ++i)  // insertion sort: faces have few corners
        for (std::size_t j = i; j > 0 && less(ids[j], ids[j - 1]); --j) {
            const index s = ids[j];
            ids[j] = ids[j - 1];
            ids[j - 1] = s;
        }
    const auto turn = [&](index o, index a, index b) {
        const vec3<T> oa = linear3::sub(x[a], x[o]), ob = linear3::sub(x[b], x[o]);
        return linear3::dot(u, oa) * linear3::dot(v, ob) - linear3::dot(v, oa) * linear3::dot(u, ob);
    };
    // a turn counts as left only beyond rounding: eps times the longer side
    const auto left = [&](index o, index a, index b) {
        return turn(o, a, b) > eps * (length(linear3::sub(x[a], x[o])) + length(linear3::sub(x[b], x[o])));
    };
    std::array<index, M + 1> chain{};
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
        while (k >= 2 && !left(chain[k - 2], chain[k - 1], ids[i])) --k;
        chain[k++] = ids[i];
    }
    for (std::size_t i = n - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && !left(chain[k - 2], chain[k - 1], ids[i])) --k;
        chain[k++] = ids[i];
    }
    const std::size_t count = k > 1 ? k - 1 : k;  // the last repeats the first
    for (std::size_t i = 0; i < count; ++i) ids[i] = chain[i];
    return count;
}
}  // namespace hull_detail

template <std::size_t N, class T>
[[nodiscard]] constexpr checked<convex_hull<T, N>> make_hull(std::span<const vec3<T>> points) noexcept {
    using namespace hull_detail;
    using H = convex_hull<T, N>;
    if (points.size() < 4) return {{}, error_code::too_few_points};
    if (points.size() > N) return {{}, error_code::capacity_exceeded};
    T extent = T(0);
    for (const vec3<T>& p : points)
        for (std::size_t k = 0; k < 3; ++k) {
            if (!is_finite(p[k])) return {{}, error_code::non_finite};
            const T d = p[k] - points[0][k];
            extent = d > extent ? d : -d > extent ? -d : extent;
        }
    const T eps = T(128) * std::numeric_limits<T>::epsilon() * extent;
    std::array<index, 4> start{};
    if (!extreme_four(points, eps, start)) return {{}, error_code::coplanar_points};

    // quickhull: the farthest point above any triangle, until none is above by more than ε
    polytope<T, 2 * N> surface;
    (void)start_tetrahedron(surface, points, start[0], start[1], start[2], start[3]);
    std::array<bool, N> done{};
    for (index s : start) done[s] = true;
    for (;;) {
        T best = eps;
        std::size_t pick = points.size();
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (done[i]) continue;
            T above = -std::numeric_limits<T>::infinity();
            for (std::size_t t = 0; t < surface.count; ++t) {
                const T h = height(surface.triangle[t], points[i]);
                above = h > above ? h : above;
            }
            if (!(above > eps)) done[i] = true;  // inside now, so inside for good
            else if (above > best) best = above, pick = i;
        }
        if (pick == points.size()) break;
        done[pick] = true;
        (void)grow(surface, points, static_cast<index>(pick), eps);  // capacity 2N suffices; degenerate: skipped
    }

    // faces: neighbouring triangles whose far corner is within ε of the plane are one face
    std::array<std::size_t, 2 * N> parent{};
    for (std::size_t t = 0; t < surface.count; ++t) parent[t] = t;
    for (std::size_t t = 0; t < surface.count; ++t)
        for (std::size_t u = t + 1; u < surface.count; ++u)
            for (std::size_t e = 0; e < 3; ++e)
                for (std::size_t f = 0; f < 3; ++f) {
                    const auto& A = surface.triangle[t].v;
                    const auto& B = surface.triangle[u].v;
                    if (A[e] != B[(f + 1) % 3] || A[(e + 1) % 3] != B[f]) continue;
                    if (height(surface.triangle[t], points[B[(f + 2) % 3]]) > -eps) parent[find(parent, u)] = find(parent, t);
                }

    H out{};
    std::array<index, N> renumber{};
    for (index& r : renumber) r = std::numeric_limits<index>::max();
    std::array<index, N> corner{};
    std::size_t used = 0;
    for (std::size_t root = 0; root < surface.count; ++root) {
        if (find(parent, root) != root) continue;
        // the face's normal: the area-weighted mean of its triangles'
        vec3<T> n{};
        std::size_t c = 0;
        std::array<bool, N> in{};
        for (std::size_t t = 0; t < surface.count; ++t) {
            if (find(parent, t) != root) continue;
            const auto& v = surface.triangle[t].v;
            n = linear3::add(n, linear3::cross(linear3::sub(points[v[1]], points[v[0]]), linear3::sub(points[v[2]], points[v[0]])));
            for (index k : v)
                if (!in[k]) in[k] = true, corner[c++] = k;
        }
        n = linear3::scale(T(1) / length(n), n);
        // (u, v, n) right-handed: counter-clockwise in (u, v) is counter-clockwise seen from outside
        const vec3<T> a = (n[0] < T(0) ? -n[0] : n[0]) < T(0.6) ? vec3<T>{T(1), T(0), T(0)} : vec3<T>{T(0), T(1), T(0)};
        const vec3<T> u = linear3::scale(T(1) / length(linear3::cross(a, n)), linear3::cross(a, n));
        const std::size_t count = polygon(points, corner, c, u, linear3::cross(n, u), eps);
        hull_face<T>& f = out.face[out.face_count++];
        f.normal = n;
        f.offset = -std::numeric_limits<T>::infinity();
        f.first = static_cast<index>(used);
        f.count = static_cast<index>(count);
        for (std::size_t k = 0; k < count; ++k) {
            const T d = linear3::dot(n, points[corner[k]]);
            f.offset = d > f.offset ? d : f.offset;
            if (renumber[corner[k]] == std::numeric_limits<index>::max()) {
                renumber[corner[k]] = static_cast<index>(out.vertex_count);
                out.vertex[out.vertex_count++] = points[corner[k]];
            }
            out.face_vertex[used++] = renumber[corner[k]];
        }
    }
    // edges: each face's side a → b meets the face that has b → a
    for (std::size_t f = 0; f < out.face_count; ++f) {
        const hull_face<T>& F = out.face[f];
        for (std::size_t k = 0; k < F.count; ++k) {
            const index a = out.face_vertex[F.first + k], b = out.face_vertex[F.first + (k + 1) % F.count];
            if (a > b) continue;  // counted from the other face
            for (std::size_t g = 0; g < out.face_count; ++g) {
                const hull_face<T>& G = out.face[g];
                for (std::size_t m = 0; m < G.count; ++m)
                    if (out.face_vertex[G.first + m] == b && out.face_vertex[G.first + (m + 1) % G.count] == a)
                        out.edge[out.edge_count++] = {a, b, static_cast<index>(f), static_cast<index>(g)};
            }
        }
    }
    return {out, error_code::none};
}
// The hull of an array of points, of capacity M.
template <class T, std::size_t M>
[[nodiscard]] constexpr checked<convex_hull<T, M>> make_hull(const std::array<vec3<T>, M>& points) noexcept {
    return make_hull<M, T>(std::span<const vec3<T>>(points));
}

// The support point along u: the vertex farthest along u (the first of equals). Its own core.
template <class T, std::size_t N>
[[nodiscard]] constexpr vec3<T> core_support(const convex_hull<T, N>& h, const vec3<T>& u) noexcept {
    std::size_t best = 0;
    T far = linear3::dot(u, h.vertex[0]);
    for (std::size_t i = 1; i < h.vertex_count; ++i)
        if (const T d = linear3::dot(u, h.vertex[i]); d > far) far = d, best = i;
    return h.vertex[best];
}
template <class T, std::size_t N>
[[nodiscard]] constexpr T core_radius(const convex_hull<T, N>&) noexcept {
    return T(0);
}

template <class T, std::size_t N>
[[nodiscard]] constexpr checked<mass_properties<T>> mass_of(const convex_hull<T, N>& h, const T& density) noexcept {
    vec3<T> c{};
    for (std::size_t i = 0; i < h.vertex_count; ++i) c = linear3::add(c, h.vertex[i]);
    c = linear3::scale(T(1) / T(h.vertex_count), c);
    T volume = T(0);
    vec3<T> first{};  // ∫ x, x from c
    mat3<T> second{};  // ∫ x xᵀ
    for (std::size_t f = 0; f < h.face_count; ++f) {
        const hull_face<T>& F = h.face[f];
        const vec3<T> p1 = linear3::sub(h.vertex[h.face_vertex[F.first]], c);
        for (std::size_t k = 1; k + 1 < F.count; ++k) {
            const vec3<T> p2 = linear3::sub(h.vertex[h.face_vertex[F.first + k]], c);
            const vec3<T> p3 = linear3::sub(h.vertex[h.face_vertex[F.first + k + 1]], c);
            const T v = linear3::dot(p1, linear3::cross(p2, p3)) / T(6);  // p0 = 0 (the point c)
            const vec3<T> s = linear3::add(linear3::add(p1, p2), p3);
            volume += v;
            first = linear3::add_scaled(first, v / T(4), s);
            for (std::size_t i = 0; i < 3; ++i)
                for (std::size_t j = 0; j < 3; ++j)
                    second[i][j] += v / T(20) * (p1[i] * p1[j] + p2[i] * p2[j] + p3[i] * p3[j] + s[i] * s[j]);
        }
    }
    const T m = density * volume;
    const vec3<T> g = linear3::scale(T(1) / volume, first);  // the centre from c
    mat3<T> C{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) C[i][j] = density * (second[i][j] - volume * g[i] * g[j]);
    const T trace = C[0][0] + C[1][1] + C[2][2];
    mat3<T> I{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) I[i][j] = (i == j ? trace : T(0)) - C[i][j];
    if (!is_finite(density)) return {{}, error_code::non_finite};
    return make_mass_properties(m, linear3::add(c, g), I);
}

// A hull moved to the frame a moving body needs (scenes/body_kinds.hpp: the origin at the centre
// of mass, the axes principal): the frame of its inertia's eigenvectors V at its centre c
// (mass_of above), in which a point x of the given frame is Vᵀ (x − c), a face's normal Vᵀ n and
// its offset d − n·c; and that frame as a motor in the given one (c, V): a body placed at a pose g
// in the given frame is at g · frame. Reported as mass_of.
template <class T, std::size_t N>
struct principal_hull {
    convex_hull<T, N> shape;
    motor<T> frame;
};
template <class T, std::size_t N>
[[nodiscard]] constexpr checked<principal_hull<T, N>> on_principal_axes(const convex_hull<T, N>& h, const T& density) noexcept {
    const checked<mass_properties<T>> p = mass_of(h, density);
    if (!p) return {{}, p.error};
    const vec3<T> c = p->com;
    const mat3<T> V = linear3::eigen_symmetric(p->inertia_c).V;
    principal_hull<T, N> out{h, rigid_motion(make_translator(c[0], c[1], c[2]), rotor_of(V))};
    for (std::size_t i = 0; i < h.vertex_count; ++i) out.shape.vertex[i] = linear3::apply_transposed(V, linear3::sub(h.vertex[i], c));
    for (std::size_t f = 0; f < h.face_count; ++f) {
        out.shape.face[f].normal = linear3::apply_transposed(V, h.face[f].normal);
        out.shape.face[f].offset = h.face[f].offset - linear3::dot(h.face[f].normal, c);
    }
    return {out, error_code::none};
}

}  // namespace ctga::collision
