// The distance of two convex shapes by GJK (Gilbert, Johnson and Keerthi, 1988): the point v of
// the Minkowski difference A − B = {a − b} closest to the origin, found by a simplex of support
// points w = s_A(−v) − s_B(v) that closes in on it; |v| is the distance of the shapes' cores and
// v = a − b for witness points a, b (the same barycentric weights on the simplex's a and b parts).
// Each step adds w, then keeps the face of the simplex (a point, an edge, a triangle) nearest the
// origin by its Voronoi regions (Ericson, Real-Time Collision Detection, §5.1.5–5.1.6); a
// tetrahedron that holds the origin means the cores overlap (reported: penetration is another
// routine's). It stops when w gains less than `tolerance` · |v|² on v (|v|² − v·w ≤ tol |v|²: the
// distance is then within tol/2 relative of the true one), when w repeats a vertex, or after
// 64 steps. Polytopes (boxes) end exactly in a few steps; curved parts (a cylinder's rim)
// converge as the support points sample the curve.
// Spheres and capsules enter as their cores (a point, a segment) and give back their radii.
#pragma once

#include <array>
#include <cstddef>

#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

template <class T = double>
struct gjk_result {
    bool overlap;  // the cores overlap (or touch): distance 0, no witnesses
    T distance;    // of the cores
    vec3<T> point_a, point_b;
    int steps;
};

namespace gjk_detail {
template <class T>
struct vertex {
    vec3<T> w, a, b;  // w = a − b
};
template <class T>
struct simplex {
    std::array<vertex<T>, 4> v{};
    std::array<T, 4> weight{};
    std::size_t n = 0;
    vec3<T> closest{};  // Σ weight_i v_i.w
};

// A sub-simplex: which vertices stay (at most three), their weights and the point they give.
// The Voronoi tests below only read the points w and return one of these; the simplex itself is
// rewritten once, by apply, and lives in the caller's frame (its vertices hold a, b and w: copies
// of it were what a step cost most, measured: two boxes apart 282 → 126 ns).
template <class T>
struct reduction {
    std::size_t n;
    std::array<std::size_t, 3> index;
    std::array<T, 3> weight;
    vec3<T> closest;
};
template <class T>
[[nodiscard]] constexpr reduction<T> reduce(const simplex<T>& s, std::initializer_list<std::size_t> which,
                                            std::initializer_list<T> weights) noexcept {
    reduction<T> r{which.size(), {}, {}, {}};
    std::size_t k = 0;
    for (std::size_t i : which) r.index[k++] = i;
    k = 0;
    for (const T& w : weights) {
        r.weight[k] = w;
        r.closest = linear3::add_scaled(r.closest, w, s.v[r.index[k]].w);
        ++k;
    }
    return r;
}
template <class T>
constexpr void apply(simplex<T>& s, const reduction<T>& r) noexcept {
    std::array<vertex<T>, 3> v;
    for (std::size_t k = 0; k < r.n; ++k) v[k] = s.v[r.index[k]];
    for (std::size_t k = 0; k < r.n; ++k) s.v[k] = v[k], s.weight[k] = r.weight[k];
    s.n = r.n;
    s.closest = r.closest;
}
template <class T>
constexpr void keep(simplex<T>& s, std::initializer_list<std::size_t> which, std::initializer_list<T> weights) noexcept {
    apply(s, reduce(s, which, weights));
}

// The nearest point of segment v0 v1 to the origin.
template <class T>
[[nodiscard]] constexpr reduction<T> on_segment(const simplex<T>& s) noexcept {
    const vec3<T> a = s.v[0].w, ab = linear3::sub(s.v[1].w, a);
    const T t = -linear3::dot(a, ab), l = linear3::dot(ab, ab);
    if (!(t > T(0))) return reduce<T>(s, {0}, {T(1)});
    if (!(t < l)) return reduce<T>(s, {1}, {T(1)});
    return reduce<T>(s, {0, 1}, {T(1) - t / l, t / l});
}
template <class T>
constexpr void segment(simplex<T>& s) noexcept {
    apply(s, on_segment(s));
}

// The nearest point of triangle v_i v_j v_k to the origin, by its regions.
template <class T>
[[nodiscard]] constexpr reduction<T> on_triangle(const simplex<T>& s, std::size_t i, std::size_t j, std::size_t k) noexcept {
    const vec3<T> a = s.v[i].w, b = s.v[j].w, c = s.v[k].w;
    const vec3<T> ab = linear3::sub(b, a), ac = linear3::sub(c, a);
    const T d1 = -linear3::dot(ab, a), d2 = -linear3::dot(ac, a);
    if (d1 <= T(0) && d2 <= T(0)) return reduce<T>(s, {i}, {T(1)});
    const T d3 = -linear3::dot(ab, b), d4 = -linear3::dot(ac, b);
    if (d3 >= T(0) && d4 <= d3) return reduce<T>(s, {j}, {T(1)});
    const T vc = d1 * d4 - d3 * d2;
    if (vc <= T(0) && d1 >= T(0) && d3 <= T(0)) {
        const T t = d1 / (d1 - d3);
        return reduce<T>(s, {i, j}, {T(1) - t, t});
    }
    const T d5 = -linear3::dot(ab, c), d6 = -linear3::dot(ac, c);
    if (d6 >= T(0) && d5 <= d6) return reduce<T>(s, {k}, {T(1)});
    const T vb = d5 * d2 - d1 * d6;
    if (vb <= T(0) && d2 >= T(0) && d6 <= T(0)) {
        const T t = d2 / (d2 - d6);
        return reduce<T>(s, {i, k}, {T(1) - t, t});
    }
    const T va = d3 * d6 - d5 * d4;
    if (va <= T(0) && d4 - d3 >= T(0) && d5 - d6 >= T(0)) {
        const T t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return reduce<T>(s, {j, k}, {T(1) - t, t});
    }
    const T inv = T(1) / (va + vb + vc), v = vb * inv, w = vc * inv;
    return reduce<T>(s, {i, j, k}, {T(1) - v - w, v, w});
}
template <class T>
constexpr void triangle(simplex<T>& s, std::size_t i, std::size_t j, std::size_t k) noexcept {
    apply(s, on_triangle(s, i, j, k));
}

// Whether the origin and vertex d lie on opposite sides of the plane a b c (strictly).
template <class T>
[[nodiscard]] constexpr bool origin_outside(const vec3<T>& a, const vec3<T>& b, const vec3<T>& c, const vec3<T>& d) noexcept {
    const vec3<T> n = linear3::cross(linear3::sub(b, a), linear3::sub(c, a));
    const T sp = -linear3::dot(a, n), sd = linear3::dot(linear3::sub(d, a), n);
    return sp * sd < T(0) || sd == T(0);
}

// The nearest point of tetrahedron v0…v3 to the origin: the best of the faces the origin is outside
// of; inside all four: the origin is in it (n = 0).
template <class T>
[[nodiscard]] constexpr reduction<T> on_tetrahedron(const simplex<T>& s) noexcept {
    constexpr std::size_t face[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
    reduction<T> best{0, {}, {}, {}};
    T best_d = T(0);
    for (const auto& f : face) {
        if (!origin_outside(s.v[f[0]].w, s.v[f[1]].w, s.v[f[2]].w, s.v[f[3]].w)) continue;
        const reduction<T> r = on_triangle(s, f[0], f[1], f[2]);
        const T d = linear3::dot(r.closest, r.closest);
        if (best.n == 0 || d < best_d) best = r, best_d = d;
    }
    return best;
}
template <class T>
constexpr bool tetrahedron(simplex<T>& s) noexcept {
    const reduction<T> r = on_tetrahedron(s);
    if (r.n > 0) apply(s, r);
    return r.n > 0;
}

template <class S, class T>
[[nodiscard]] constexpr vec3<T> world_support(const S& shape, const motor_map<T>& pose, const vec3<T>& d) noexcept {
    return to_world(pose, core_support(shape, linear3::apply_transposed(pose.R, d)));
}

// The run itself: its result, its last simplex left in `s` (a tetrahedron around the origin when
// the cores overlap: EPA's start, epa.hpp). `start`: the first search direction (from A towards B;
// zero: along t_B − t_A).
template <class A, class B, class T>
[[nodiscard]] constexpr gjk_result<T> run(const A& a, const motor_map<T>& pa, const B& b, const motor_map<T>& pb, const T& tolerance,
                                          simplex<T>& s, const vec3<T>& start = {}) noexcept {
    const auto support = [&](const vec3<T>& d) {
        const vec3<T> sa = world_support(a, pa, d), sb = world_support(b, pb, linear3::scale(T(-1), d));
        return vertex<T>{linear3::sub(sa, sb), sa, sb};
    };
    vec3<T> d0 = linear3::dot(start, start) > T(0) ? start : linear3::sub(pb.t, pa.t);
    if (!(linear3::dot(d0, d0) > T(0))) d0 = {T(1), T(0), T(0)};
    s.v[0] = support(d0);
    s.n = 1;
    s.weight[0] = T(1);
    s.closest = s.v[0].w;
    int step = 0;
    for (; step < 64; ++step) {
        const vec3<T> v = s.closest;
        const T vv = linear3::dot(v, v);
        if (!(vv > T(0))) return {true, T(0), {}, {}, step};
        const vertex<T> w = support(linear3::scale(T(-1), v));
        if (vv - linear3::dot(v, w.w) <= tolerance * vv) break;
        bool repeated = false;
        for (std::size_t i = 0; i < s.n; ++i) repeated = repeated || (s.v[i].a == w.a && s.v[i].b == w.b);
        if (repeated) break;
        s.v[s.n] = w;  // (counted in once the step is taken)
        const reduction<T> r = s.n == 1 ? on_segment(s)
                             : s.n == 2 ? on_triangle(s, 0, 1, 2)
                                        : on_tetrahedron(s);
        if (s.n == 3 && r.n == 0) {
            s.n = 4;
            return {true, T(0), {}, {}, step};
        }
        if (!(linear3::dot(r.closest, r.closest) < vv)) break;  // no progress (rounding): the simplex before stands
        apply(s, r);
    }
    vec3<T> on_a{}, on_b{};
    for (std::size_t i = 0; i < s.n; ++i) {
        on_a = linear3::add_scaled(on_a, s.weight[i], s.v[i].a);
        on_b = linear3::add_scaled(on_b, s.weight[i], s.v[i].b);
    }
    return {false, length(s.closest), on_a, on_b, step};
}
}  // namespace gjk_detail

template <class A, class B, class T>
[[nodiscard]] constexpr gjk_result<T> gjk(const A& a, const motor_map<T>& pa, const B& b, const motor_map<T>& pb, const T& tolerance) noexcept {
    gjk_detail::simplex<T> s;
    return gjk_detail::run(a, pa, b, pb, tolerance, s);
}

}  // namespace ctga::collision
