// collision_reference.hpp: an independent, brute-force reference for the collision tests.
//
// Nothing here is taken from ctga's collision code; every quantity is computed, in long double,
// by a method chosen because it is simple and evidently right rather than fast:
//
//  * signed_distance (bounded A, bounded B): the support-function identity
//        signed_distance(A, B) = max over unit u of f(u),   f(u) = -h_A(u) - h_B(-u),
//    h_S(u) = max over x in S of u.x, valid both apart (the gap) and overlapping (minus the
//    penetration depth); the maximiser u is the normal (from A towards B). With D = A - B,
//    f = -h_D. f is maximised, deterministically, in three steps:
//    1. samples: the direction between the poses' origins, the axes of both poses and the
//       centres of a cube-sphere grid of 1,944 cells, then of 9,600 cells unless some sample
//       (or one bisection around the best, for nearly touching shapes) is already > 0;
//    2. local refinement from the best sample in a gnomonic chart around it,
//       by nested bisection driven by cutting planes built from support points only (the
//       supergradient s_D(w) = s_A(w) - s_B(-w) of -f, corrected for the normalisation of w),
//       so that it works on the kinks of f (faces, edges) as well as on its smooth peaks and is
//       not limited by the rounding of f's values. Apart, f's superlevel sets are convex in the
//       chart and every cut provably keeps the maximiser; overlapping, the cuts are exact to
//       second order in the bracket, and the bracket shrinks to 2^-44 (tolerance 2^-63);
//    3. branch and bound over the grid's cells, which makes the maximum global: -h_D is
//       concave on R^3, so every point s of D bounds f(u) <= -s.u everywhere, which gives an
//       upper bound of f over each cell's circumscribed cap from the support point at its
//       centre (tightened across kinks by mixing in support points of neighbouring
//       directions). Cells whose bound does not exceed the best value are dropped, the others
//       quartered; a better centre restarts the refinement. It stops when the surviving cells
//       lie within 1e-7 rad of the best direction (inside the refinement's last brackets), or,
//       for flat optima where any maximiser is right (concentric spheres, a sphere centred on
//       a capsule's axis), beyond 1,500 cells.
//    Last, f is probed on circles of radii 1e-1 ... 1e-13 around the result (a better value
//    restarts the refinement). Half-spaces (unbounded) use the closed support-function form
//    (see signed_distance).
//  * point queries (point_query, point_signed_distance): the same with the point as the second
//    shape (h_point(u) = u.p).
//  * ray_cast: the point signed distance phi(s) along the ray is convex; from s = 0 the Newton
//    step s - phi/phi' (phi' = normal.direction, from the point query) stays below the first
//    root and is at least the sphere-tracing step; a step that lands in the shape is the root
//    to rounding (bisection remains as a fallback). The ray misses when phi' >= 0 while
//    phi > 0, or when a lower bound passes max_length. No closed-form ray-shape intersection.
//  * mass_properties: quadrature of 1, x, x x^T: tensor Gauss-Legendre (8 nodes) in cylindrical
//    coordinates (z, rho in [0, R(z)], midpoint rule in phi) for sphere, capsule (caps with a
//    z-dependent radius) and cylinder; tensor Gauss-Legendre for the box; for a hull its faces
//    are computed here (every supporting plane through three points; the coplanar points of a
//    plane form a face, ordered by a 2-D convex hull) and the solid is split into tetrahedra
//    from the mean of the points, each integrated with the 4-point degree-2 rule. All these
//    rules are exact for the polynomial integrands, so only rounding remains.
//  * contains: closed-form point-shape signed distances for the primitives (box, cylinder,
//    capsule, sphere, half-space) and the face planes for a hull.
//
// Accuracy, measured (shapes of size ~1, distances of order 1; see the self-checks reported
// with this file): signed_distance agrees with closed forms (sphere-sphere, sphere-box,
// capsule-capsule, box-half-space, overlapping box-box against the 15 separating axes) to
// <= 1e-18 absolute, its normal to <= 1e-17 where it is unique, and an independent
// multi-start search (2,880 random pairs of all kinds) never found a larger f by more than
// 8e-19; with poses ~1e4 from the origin the results move by ~1e-15, the rounding of the
// inputs themselves. The normal is arbitrary where the optimum is flat (concentric spheres);
// the witness points are exact when witness_unique, otherwise one valid support point each.
// Point queries: the same. ray_cast: <= 2e-18 against closed forms, but ~3e-9 for grazing
// (tangent) hits, where the root is double. mass_properties: <= 2e-18 relative (rounding).
// Cost per call (g++ 12, x86-64, CPU time at -O2 / at the tests' -Og): signed_distance
// 1.1-1.6 / 1.4-1.8 ms apart, 1.7-2.4 / 2.2-3.2 ms overlapping for primitives, 3.5-7 / 5-9 ms
// for hulls of 64 points (at most ~10 ms seen), up to ~10 ms for flat optima (a sphere centred
// on a capsule's axis); point queries ~0.8 / 1.4 ms; ray casts ~2-4 / 3.5 ms; mass_properties
// of a 64-point hull 2.4 / 4.5 ms (its faces are found in O(n^4)). The direction grids are
// built once per process (~4 ms).
//
// Conventions: a pose maps local to world, x_world = R x_local + t (R row-major). Shapes in their
// local frame: sphere {radius} about the origin; capsule {radius, half_height} around the segment
// (0,0,-half_height)-(0,0,half_height); box {half} = [-hx,hx]x[-hy,hy]x[-hz,hz]; cylinder
// {radius, half_height} about the z axis; half_space {} = {z <= 0}; hull {points} = their convex
// hull. Support points break ties towards +: a zero component of the local direction picks the
// + side (box, capsule, cylinder), a direction along the cylinder's axis picks its cap centre,
// a hull picks the first point attaining the maximum.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <set>
#include <type_traits>
#include <utility>
#include <vector>

namespace collision_ref {

using real = long double;
using vec3 = std::array<real, 3>;
using mat3 = std::array<std::array<real, 3>, 3>;

// ---------------------------------------------------------------------------------------------
// Shapes and poses
// ---------------------------------------------------------------------------------------------

struct sphere {
    real radius;
};
struct capsule {
    real radius;
    real half_height;
};
struct box {
    vec3 half;
};
struct cylinder {
    real radius;
    real half_height;
};
struct half_space {};
struct hull {
    std::vector<vec3> points;
};

struct pose {
    mat3 R;
    vec3 t;
};

namespace detail {

inline constexpr real eps = std::numeric_limits<real>::epsilon();
inline constexpr real pi = std::numbers::pi_v<real>;

inline vec3 add(const vec3& a, const vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline vec3 sub(const vec3& a, const vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline vec3 mul(real s, const vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline vec3 neg(const vec3& a) { return {-a[0], -a[1], -a[2]}; }
inline real dot(const vec3& a, const vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline vec3 cross(const vec3& a, const vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline real norm(const vec3& a) { return std::sqrt(dot(a, a)); }
inline vec3 normalized(const vec3& a) {
    const real n = norm(a);
    return n > 0 ? mul(1 / n, a) : vec3{0, 0, 0};
}
// R v and R^T v
inline vec3 rot(const mat3& R, const vec3& v) {
    return {R[0][0] * v[0] + R[0][1] * v[1] + R[0][2] * v[2],
            R[1][0] * v[0] + R[1][1] * v[1] + R[1][2] * v[2],
            R[2][0] * v[0] + R[2][1] * v[1] + R[2][2] * v[2]};
}
inline vec3 rotT(const mat3& R, const vec3& v) {
    return {R[0][0] * v[0] + R[1][0] * v[1] + R[2][0] * v[2],
            R[0][1] * v[0] + R[1][1] * v[1] + R[2][1] * v[2],
            R[0][2] * v[0] + R[1][2] * v[1] + R[2][2] * v[2]};
}
inline real sgn(real x) { return x < 0 ? real(-1) : real(1); }
// angle between two unit vectors, accurate for tiny angles
inline real angle(const vec3& a, const vec3& b) {
    return 2 * std::asin(std::min<real>(1, norm(sub(a, b)) / 2));
}

// A single point, the second shape of a point query (local frame: the point is the origin).
struct point_shape {};

// ---- local support functions h(v) = max x.v, support points, uniqueness, bounding radius ----

inline real local_support(const sphere& s, const vec3& v) { return s.radius * norm(v); }
inline vec3 local_support_point(const sphere& s, const vec3& v) {
    const real n = norm(v);
    return n > 0 ? mul(s.radius / n, v) : vec3{0, 0, 0};
}
inline bool local_unique(const sphere&, const vec3&, real) { return true; }
inline real local_radius(const sphere& s) { return s.radius; }

inline real local_support(const capsule& s, const vec3& v) {
    return s.radius * norm(v) + s.half_height * std::abs(v[2]);
}
inline vec3 local_support_point(const capsule& s, const vec3& v) {
    const real n = norm(v);
    vec3 p = n > 0 ? mul(s.radius / n, v) : vec3{0, 0, 0};
    p[2] += s.half_height * sgn(v[2]);
    return p;
}
inline bool local_unique(const capsule& s, const vec3& v, real tol) {
    return s.half_height == 0 || std::abs(v[2]) > tol * norm(v);
}
inline real local_radius(const capsule& s) { return s.radius + s.half_height; }

inline real local_support(const box& s, const vec3& v) {
    return s.half[0] * std::abs(v[0]) + s.half[1] * std::abs(v[1]) + s.half[2] * std::abs(v[2]);
}
inline vec3 local_support_point(const box& s, const vec3& v) {
    return {s.half[0] * sgn(v[0]), s.half[1] * sgn(v[1]), s.half[2] * sgn(v[2])};
}
inline bool local_unique(const box& s, const vec3& v, real tol) {
    const real n = norm(v);
    for (int i = 0; i < 3; ++i)
        if (s.half[static_cast<std::size_t>(i)] > 0 &&
            !(std::abs(v[static_cast<std::size_t>(i)]) > tol * n))
            return false;
    return true;
}
inline real local_radius(const box& s) { return norm(s.half); }

inline real local_support(const cylinder& s, const vec3& v) {
    return s.radius * std::sqrt(v[0] * v[0] + v[1] * v[1]) + s.half_height * std::abs(v[2]);
}
inline vec3 local_support_point(const cylinder& s, const vec3& v) {
    const real rho = std::sqrt(v[0] * v[0] + v[1] * v[1]);
    if (rho > 0) return {s.radius * v[0] / rho, s.radius * v[1] / rho, s.half_height * sgn(v[2])};
    return {0, 0, s.half_height * sgn(v[2])};
}
inline bool local_unique(const cylinder& s, const vec3& v, real tol) {
    const real n = norm(v);
    const bool side_ok = s.half_height == 0 || std::abs(v[2]) > tol * n;
    const bool cap_ok = s.radius == 0 || std::hypot(v[0], v[1]) > tol * n;
    return side_ok && cap_ok;
}
inline real local_radius(const cylinder& s) { return std::hypot(s.radius, s.half_height); }

inline real local_support(const hull& s, const vec3& v) {
    real m = -std::numeric_limits<real>::infinity();
    for (const vec3& p : s.points) m = std::max(m, dot(p, v));
    return m;
}
inline vec3 local_support_point(const hull& s, const vec3& v) {
    real m = -std::numeric_limits<real>::infinity();
    vec3 best{0, 0, 0};
    for (const vec3& p : s.points) {
        const real x = dot(p, v);
        if (x > m) {
            m = x;
            best = p;
        }
    }
    return best;
}
inline real hull_extent(const hull& s) {
    real e = 0;
    for (const vec3& p : s.points) e = std::max(e, norm(sub(p, s.points.front())));
    return e;
}
inline bool local_unique(const hull& s, const vec3& v, real tol) {
    const vec3 u = normalized(v);
    const vec3 best = local_support_point(s, u);
    const real m = dot(best, u), ext = hull_extent(s);
    for (const vec3& p : s.points)
        if (dot(p, u) >= m - tol * ext && norm(sub(p, best)) > tol * ext) return false;
    return true;
}
inline real local_radius(const hull& s) {
    real r = 0;
    for (const vec3& p : s.points) r = std::max(r, norm(p));
    return r;
}

inline real local_support(const point_shape&, const vec3&) { return 0; }
inline vec3 local_support_point(const point_shape&, const vec3&) { return {0, 0, 0}; }
inline bool local_unique(const point_shape&, const vec3&, real) { return true; }
inline real local_radius(const point_shape&) { return 0; }

template <class S>
inline constexpr bool is_bounded_v =
    std::is_same_v<S, sphere> || std::is_same_v<S, capsule> || std::is_same_v<S, box> ||
    std::is_same_v<S, cylinder> || std::is_same_v<S, hull>;

}  // namespace detail

template <class S>
concept bounded_shape = detail::is_bounded_v<S>;
template <class S>
concept any_shape = detail::is_bounded_v<S> || std::is_same_v<S, half_space>;

// ---------------------------------------------------------------------------------------------
// Poses
// ---------------------------------------------------------------------------------------------

inline pose identity_pose() { return {{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}}; }

// Rotation from a quaternion q = (w, x, y, z) (normalised here; a zero quaternion gives the
// identity), then translation t.
inline pose make_pose_quaternion(real w, real x, real y, real z, const vec3& t) {
    const real n = std::sqrt(w * w + x * x + y * y + z * z);
    if (!(n > 0)) return {identity_pose().R, t};
    w /= n, x /= n, y /= n, z /= n;
    pose p;
    p.R = {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
    p.t = t;
    return p;
}

// Rotation by `angle` (radians, right-handed) about `axis` (normalised here; a zero axis gives
// the identity), then translation t.
inline pose make_pose(const vec3& axis, real angle, const vec3& t) {
    const vec3 a = detail::normalized(axis);
    const real s = std::sin(angle / 2), c = std::cos(angle / 2);
    if (detail::norm(a) == 0) return {identity_pose().R, t};
    return make_pose_quaternion(c, s * a[0], s * a[1], s * a[2], t);
}

// Uniformly random rotation (Shoemake's uniform quaternion) and a translation uniform in
// [-translation_scale, translation_scale]^3. Deterministic for a given generator state and
// independent of the standard library's distributions.
inline pose random_pose(std::mt19937_64& rng, real translation_scale) {
    auto uniform = [&rng] { return std::ldexp(static_cast<real>(rng()), -64); };  // [0, 1)
    const real u1 = uniform(), u2 = uniform(), u3 = uniform();
    const real a = std::sqrt(1 - u1), b = std::sqrt(u1);
    const real t1 = 2 * detail::pi * u2, t2 = 2 * detail::pi * u3;
    vec3 t;
    for (real& c : t) c = translation_scale * (2 * uniform() - 1);
    return make_pose_quaternion(b * std::cos(t2), a * std::sin(t1), a * std::cos(t1),
                                b * std::sin(t2), t);
}

// ---------------------------------------------------------------------------------------------
// Support functions of posed bounded shapes (u need not be unit; h is positively homogeneous)
// ---------------------------------------------------------------------------------------------

template <bounded_shape S>
real support(const S& s, const pose& P, const vec3& u) {
    return detail::dot(u, P.t) + detail::local_support(s, detail::rotT(P.R, u));
}
template <bounded_shape S>
vec3 support_point(const S& s, const pose& P, const vec3& u) {
    return detail::add(P.t, detail::rot(P.R, detail::local_support_point(s, detail::rotT(P.R, u))));
}

// ---------------------------------------------------------------------------------------------
// Signed distance
// ---------------------------------------------------------------------------------------------

struct distance_result {
    real distance;          // > 0: gap; < 0: minus the penetration depth
    vec3 normal;            // unit, from A towards B
    vec3 point_a, point_b;  // support point of A along normal, of B along -normal
    bool witness_unique;    // both support points unique (tolerance 1e-9 on the local direction)
};

namespace detail {

inline constexpr real unique_tol = 1e-9L;

// f(u) = u.d - hA(RA^T u) - hB(-RB^T u), d = tB - tA; support point of D = A - B relative to
// the difference of the origins: s(u) = RA pA - RB pB - d, so that f(u) = -u.s(u).
template <class A, class B>
class problem {
public:
    problem(const A& a, const pose& pa, const B& b, const pose& pb)
        : a_(a), b_(b), RA_(pa.R), RB_(pb.R), d_(sub(pb.t, pa.t)) {
        lip_ = norm(d_) + local_radius(a) + local_radius(b);
        noise_ = 64 * eps * std::max<real>(lip_, std::numeric_limits<real>::min());
    }
    real value(const vec3& u) const {
        return dot(u, d_) - local_support(a_, rotT(RA_, u)) - local_support(b_, neg(rotT(RB_, u)));
    }
    struct eval_t {
        real F;
        vec3 s;
    };
    eval_t eval(const vec3& u) const {
        const vec3 pa = local_support_point(a_, rotT(RA_, u));
        const vec3 pb = local_support_point(b_, neg(rotT(RB_, u)));
        const vec3 s = sub(sub(rot(RA_, pa), rot(RB_, pb)), d_);
        return {-dot(u, s), s};
    }
    real lip() const { return lip_; }
    real noise() const { return noise_; }
    const vec3& d() const { return d_; }
    std::vector<vec3> special_directions() const {
        std::vector<vec3> v;
        if (norm(d_) > 0) {
            v.push_back(normalized(d_));
            v.push_back(neg(normalized(d_)));
        }
        for (const mat3* R : {&RA_, &RB_})
            for (std::size_t j = 0; j < 3; ++j) {
                const vec3 c{(*R)[0][j], (*R)[1][j], (*R)[2][j]};
                v.push_back(normalized(c));
                v.push_back(neg(normalized(c)));
            }
        return v;
    }

private:
    A a_;
    B b_;
    mat3 RA_, RB_;
    vec3 d_;
    real lip_, noise_;
};

// Cube-sphere grid: each face of the cube [-1,1]^3 is cut into n x n cells, equal in angle
// (edges at a = tan(alpha), alpha uniform in [-pi/4, pi/4]); a cell is a rectangle
// [a0,a1] x [b0,b1] of the face's gnomonic coordinates, the directions normalised(n + a e1 + b e2)
// (a spherical quadrilateral with great-circle edges, so its vertices are its farthest points
// from any direction inside it).
struct grid_cell {
    int face;
    real a0, a1, b0, b1;
};
inline vec3 cube_direction(int face, real a, real b) {
    const auto i = static_cast<std::size_t>(face / 2);
    vec3 w{0, 0, 0};
    w[i] = face % 2 ? -1 : 1;
    w[(i + 1) % 3] = a;
    w[(i + 2) % 3] = b;
    return normalized(w);
}
inline vec3 cell_centre(const grid_cell& q) {
    return cube_direction(q.face, (q.a0 + q.a1) / 2, (q.b0 + q.b1) / 2);
}
inline real cell_radius(const grid_cell& q, const vec3& c) {
    real r = 0;
    for (real a : {q.a0, q.a1})
        for (real b : {q.b0, q.b1}) r = std::max(r, angle(c, cube_direction(q.face, a, b)));
    return r * (1 + 1e-12L) + 1e-18L;
}
struct direction_set {
    std::vector<grid_cell> cells;
    std::vector<vec3> dirs;  // cell centres
    std::vector<real> radius;
    std::size_t n;  // cells per face edge; cell (face f, row i, column j) is f n^2 + i n + j
    real spacing;   // sqrt(4 pi / number of cells)
};
inline direction_set make_direction_set(int n) {
    direction_set s;
    s.n = static_cast<std::size_t>(n);
    std::vector<real> edge(static_cast<std::size_t>(n) + 1);
    for (int k = 0; k <= n; ++k)
        edge[static_cast<std::size_t>(k)] =
            std::tan(pi / 2 * (static_cast<real>(k) / static_cast<real>(n) - 0.5L));
    edge.front() = -1, edge.back() = 1;
    for (int f = 0; f < 6; ++f)
        for (std::size_t i = 0; i + 1 < edge.size(); ++i)
            for (std::size_t j = 0; j + 1 < edge.size(); ++j) {
                const grid_cell q{f, edge[i], edge[i + 1], edge[j], edge[j + 1]};
                s.cells.push_back(q);
                s.dirs.push_back(cell_centre(q));
                s.radius.push_back(cell_radius(q, s.dirs.back()));
            }
    s.spacing = std::sqrt(4 * pi / static_cast<real>(s.cells.size()));
    return s;
}
inline const direction_set& coarse_directions() {  // 1,944 directions
    static const direction_set s = make_direction_set(18);
    return s;
}
inline const direction_set& dense_directions() {  // 9,600 directions
    static const direction_set s = make_direction_set(40);
    return s;
}

struct chart {
    vec3 u0, e1, e2;
};
inline chart make_chart(const vec3& u0) {
    std::size_t k = 0;
    if (std::abs(u0[1]) < std::abs(u0[k])) k = 1;
    if (std::abs(u0[2]) < std::abs(u0[k])) k = 2;
    vec3 ax{0, 0, 0};
    ax[k] = 1;
    const vec3 e1 = normalized(cross(u0, ax));
    return {u0, e1, normalized(cross(u0, e1))};
}

struct probe {
    real F;
    vec3 u;
    real ga, gb;  // cut normal in the chart: the maximiser lies in {g.(x - x_probe) >= 0}
};

// Direction w = u0 + a e1 + b e2. The cut normal is -(s + c w/|w|) projected on the chart, with
// c = F (the gradient of f in the chart, up to a positive factor, wherever f is differentiable;
// a supergradient-type cut at kinks). When the shapes are apart (sep), points with F <= 0 use
// c = 0: that cut keeps every direction with f > 0.
template <class P>
probe probe_at(const P& pb, const chart& c, real a, real b, bool sep) {
    const vec3 u = normalized(add(c.u0, add(mul(a, c.e1), mul(b, c.e2))));
    const auto e = pb.eval(u);
    const real coef = (sep && !(e.F > 0)) ? real(0) : e.F;
    const vec3 q = add(e.s, mul(coef, u));
    return {e.F, u, -dot(q, c.e1), -dot(q, c.e2)};
}

struct bisection_result {
    probe last;  // the point the bisection converged to (precise in position)
    probe best;  // the best value seen
    bool hit;    // converged near the edge of the bracket
};

// Nested bisection on [-W, W]^2: for each a the inner bisection on b keeps two points of the
// line with cut normals whose b components have opposite signs (the bracket's ends count as
// cuts (0, +-1)); a convex combination of the two cuts with no b component then tells on which
// side of a the maximiser lies.
template <class P>
bisection_result nested_bisection(const P& pb, const vec3& u0, real W, real tau, bool sep) {
    const chart c = make_chart(u0);
    probe best{-std::numeric_limits<real>::infinity(), u0, 0, 0};
    auto track = [&best](const probe& p) {
        if (p.F > best.F) best = p;
    };
    struct inner_t {
        real blo, bhi, loa, lob, hia, hib;
    };
    auto inner = [&](real a) {
        inner_t r{-W, W, 0, 1, 0, -1};
        while (r.bhi - r.blo > tau) {
            const real m = (r.blo + r.bhi) / 2;
            if (m <= r.blo || m >= r.bhi) break;
            const probe p = probe_at(pb, c, a, m, sep);
            track(p);
            if (p.gb > 0) {
                r.blo = m, r.loa = p.ga, r.lob = p.gb;
            } else if (p.gb < 0) {
                r.bhi = m, r.hia = p.ga, r.hib = p.gb;
            } else {
                r.blo = r.bhi = m, r.loa = r.hia = p.ga, r.lob = r.hib = 0;
                break;
            }
        }
        return r;
    };
    real alo = -W, ahi = W;
    while (ahi - alo > tau) {
        const real am = (alo + ahi) / 2;
        if (am <= alo || am >= ahi) break;
        const inner_t r = inner(am);
        const real lb = r.lob, hb = -r.hib;
        const real gamma =
            lb + hb > 0 ? (hb * r.loa + lb * r.hia) / (lb + hb) : (r.loa + r.hia) / 2;
        if (gamma > 0)
            alo = am;
        else if (gamma < 0)
            ahi = am;
        else {
            alo = ahi = am;
            break;
        }
    }
    const real a = (alo + ahi) / 2;
    const inner_t r = inner(a);
    const real b = (r.blo + r.bhi) / 2;
    const probe last = probe_at(pb, c, a, b, sep);
    track(last);
    // near the edge: the maximiser may lie beyond it (a ridge leaving the bracket at a shallow
    // angle ends up to tau times its slope inside)
    const bool hit = std::max(std::abs(a), std::abs(b)) > W * (1 - std::ldexp(real(1), -10));
    return {last, best, hit};
}

struct optimum {
    vec3 u;
    real F;
};

// Coarse stage: bracket W (W0, a few sample spacings, at first), relative tolerance 2^-24. The
// bracket is re-centred while the result sits on its edge with a gain. It is narrowed 8 times
// (down to W0 / 2^12) when the bisection was misled (overlapping cuts in a bracket too wide:
// the point it converged to is worse, beyond its tolerance, than one it saw) or sits on the
// edge without a gain (f flat there, or misled too).
template <class P>
optimum refine_coarse(const P& pb, optimum o, real W0) {
    const real noise = pb.noise();
    real W = W0;
    for (int it = 0; it < 24; ++it) {
        const real tau = std::ldexp(W, -24);
        const auto r = nested_bisection(pb, o.u, W, tau, o.F > 0);
        const bool misled = r.last.F < r.best.F - noise - 2 * pb.lip() * tau;
        const probe& p = misled ? r.best : r.last;
        const bool gain = p.F > o.F + noise;
        if (p.F >= o.F - noise) o = {p.u, p.F};
        if (!r.hit && !misled) break;
        if (misled || !gain) {
            W /= 8;
            if (W < std::ldexp(W0, -12)) break;
        }
    }
    return o;
}

// Fine stage: tolerance max(2^-63, W 2^-40) on brackets shrinking W -> min(16 W^2, W/16) down
// to 2^-44 (the cuts of the overlapping case are exact only to second order in the bracket). On
// the edge of a bracket it widens it, up to W0 / 256; beyond, it sets `escaped` and returns.
template <class P>
optimum refine_fine(const P& pb, optimum o, real W0, bool& escaped) {
    const real noise = pb.noise(), tau = std::ldexp(real(1), -63),
               Wfloor = std::ldexp(real(1), -44);
    real W = std::max(std::ldexp(W0, -18), Wfloor);
    escaped = false;
    for (int it = 0; it < 40; ++it) {
        const auto r = nested_bisection(pb, o.u, W, std::max(tau, std::ldexp(W, -40)), o.F > 0);
        const probe& p = r.last.F >= r.best.F - noise ? r.last : r.best;
        const bool gain = p.F > o.F + noise;
        if (p.F >= o.F - noise) o = {p.u, p.F};
        if (r.hit && !gain) break;  // f flat to rounding: nothing better beyond the edge
        if (r.hit) {
            W *= 8;
            if (W > std::ldexp(W0, -8)) {
                escaped = true;
                break;
            }
            continue;
        }
        if (W <= Wfloor) break;
        W = std::max(std::min(16 * W * W, W / 16), Wfloor);
    }
    return o;
}

// Probes of f on circles of radii 1e-1 ... 1e-13 around o.u; returns a better direction if any.
template <class P>
std::optional<optimum> find_better_nearby(const P& pb, const optimum& o) {
    const chart c = make_chart(o.u);
    std::optional<optimum> better;
    real bestF = o.F + pb.noise();
    for (int k = 1; k <= 13; ++k) {
        const real r = std::pow(real(10), -static_cast<real>(k));
        for (int j = 0; j < 12; ++j) {
            const real phi = 2 * pi * static_cast<real>(j) / 12 + static_cast<real>(k) * 0.37L;
            const vec3 u = normalized(
                add(c.u0, add(mul(r * std::cos(phi), c.e1), mul(r * std::sin(phi), c.e2))));
            const real F = pb.value(u);
            if (F > bestF) {
                bestF = F;
                better = optimum{u, F};
            }
        }
    }
    return better;
}

// Coarse then fine stage; back to the coarse stage when the fine one had to leave its brackets.
template <class P>
optimum refine(const P& pb, optimum o, real W0) {
    for (int round = 0; round < 4; ++round) {
        bool escaped = false;
        o = refine_fine(pb, refine_coarse(pb, o, W0), W0, escaped);
        if (!escaped) break;
    }
    return o;
}

template <class P>
optimum polish(const P& pb, optimum o, real W0) {
    for (int k = 0; k < 4; ++k) {
        const auto b = find_better_nearby(pb, o);
        if (!b) break;
        o = refine(pb, *b, W0);
    }
    return o;
}

// Upper bounds of f over the cap of angular radius rho around the unit vector c. -h_D is
// concave on R^3, so f(u) <= -s.u for every point s of D and every u; for s a support point
// of D at c (f(c) = F = -s.c) and angle(u, c) = theta <= rho <= pi/2, with t the part of s
// orthogonal to c: -s.u = cos(theta) F - sin(theta) (s.t-direction) <= bound below.
struct cap {
    real cos_rho, sin_rho;
    explicit cap(real rho) : cos_rho(std::cos(rho)), sin_rho(std::sin(rho)) {}
};
inline real cap_upper_bound(const vec3& c, real F, const vec3& s, const cap& k) {
    const real st = norm(sub(s, mul(dot(s, c), c)));
    return (F < 0 ? k.cos_rho * F : F) + k.sin_rho * st;
}
// The same with any point of the segment [s0, s1] of D (support points at c and at a
// neighbouring direction): lambda chosen to minimise the bound, which is then evaluated exactly.
// Across a kink of f (two sides with different support points) this is much tighter.
inline real pair_upper_bound(const vec3& c, const vec3& s0, const vec3& s1, const cap& cp) {
    const vec3 ds = sub(s1, s0);
    const vec3 t0 = sub(s0, mul(dot(s0, c), c)), dt = sub(ds, mul(dot(ds, c), c));
    const real beta = -cp.cos_rho * dot(ds, c), sigma = cp.sin_rho, ndt = norm(dt);
    real lambda;
    if (!(sigma * ndt > 0)) {
        lambda = beta > 0 ? 0 : 1;
    } else {
        const real k = beta / (sigma * ndt);
        if (k >= 1) {
            lambda = 0;
        } else if (k <= -1) {
            lambda = 1;
        } else {
            const vec3 e = mul(1 / ndt, dt);
            const real q = dot(t0, e), p = norm(sub(t0, mul(q, e)));
            lambda = std::clamp<real>((-k * p / std::sqrt(1 - k * k) - q) / ndt, 0, 1);
        }
    }
    const vec3 sb = add(s0, mul(lambda, ds));
    return cap_upper_bound(c, -dot(sb, c), sb, cp);
}

// max over unit u of f(u)
template <class P>
optimum maximise(const P& pb) {
    const real noise = pb.noise();
    const std::vector<vec3> specials = pb.special_directions();
    optimum best{{0, 0, 1}, -std::numeric_limits<real>::infinity()};
    auto consider = [&best](const vec3& u, real F) {
        if (F > best.F) best = {u, F};
    };
    for (const vec3& u : specials) consider(u, pb.value(u));
    // Samples: the coarse grid, and the dense one unless the shapes are seen apart (f > 0
    // somewhere: then f's superlevel sets above 0 are convex and there is one local maximum).
    const direction_set* grid = &coarse_directions();
    std::vector<real> val;
    std::vector<vec3> sup;
    auto sample = [&](const direction_set& g) {
        val.resize(g.dirs.size());
        sup.resize(g.dirs.size());
        for (std::size_t i = 0; i < g.dirs.size(); ++i) {
            const auto e = pb.eval(g.dirs[i]);
            val[i] = e.F;
            sup[i] = e.s;
            consider(g.dirs[i], e.F);
        }
    };
    sample(*grid);
    if (!(best.F > 0)) {
        // nearly touching: a separating direction may lie between the samples; the cuts of the
        // separated case keep every one of them, so one bisection around the best sample finds
        // them when they are within its bracket and not narrower than its tolerance
        const real W = 3 * grid->spacing;
        const auto r = nested_bisection(pb, best.u, W, std::ldexp(W, -32), true);
        const probe& p = r.best.F > r.last.F ? r.best : r.last;
        if (p.F > 0) best = {p.u, p.F};
    }
    if (!(best.F > 0)) {
        grid = &dense_directions();
        sample(*grid);
    }
    const direction_set& ds = *grid;
    const std::size_t N = ds.dirs.size();
    const real W0 = 3 * ds.spacing;

    // Local refinement from the best sample (a special direction if it is the best: the exact
    // optimum of many aligned configurations) ...
    optimum o = refine(pb, best, W0);
    // ... then branch and bound over the grid's cells: a cell whose upper bound (cap_upper_bound
    // over its circumscribed cap) does not exceed the best value is discarded, the others are
    // cut into four; a centre better than the best restarts the local refinement from it. Stops
    // when the surviving cells lie within 1e-7 of the best direction (then the refinement around
    // it, exact to second order on brackets that small, holds the maximum), or, for flat optima
    // where everything survives, beyond 1,500 cells or below a radius of 1e-12.
    struct cell {
        grid_cell q;
        vec3 c, s;  // centre, support point of D there
        real rho;   // circumscribed cap
    };
    std::vector<cell> cells;
    const std::size_t n = ds.n;
    for (std::size_t i = 0; i < N && cells.size() <= 1500; ++i) {
        const cap cp(ds.radius[i]);
        real b = cap_upper_bound(ds.dirs[i], val[i], sup[i], cp);
        const std::size_t a = (i / n) % n, c = i % n;
        for (std::size_t j :
             {a > 0 ? i - n : i, a + 1 < n ? i + n : i, c > 0 ? i - 1 : i, c + 1 < n ? i + 1 : i})
            if (j != i && b > o.F + noise)
                b = std::min(b, pair_upper_bound(ds.dirs[i], sup[i], sup[j], cp));
        if (b > o.F + noise) cells.push_back({ds.cells[i], ds.dirs[i], sup[i], ds.radius[i]});
    }
    for (int level = 0; level < 60 && !cells.empty() && cells.size() <= 1500; ++level) {
        real spread = 0, rmax = 0;
        for (const cell& c : cells) {
            spread = std::max(spread, angle(c.c, o.u) + c.rho);
            rmax = std::max(rmax, c.rho);
        }
        if (spread <= 1e-7L || rmax < 1e-12L) break;
        std::vector<cell> kids;
        std::vector<real> kval;
        optimum bc{{0, 0, 1}, -std::numeric_limits<real>::infinity()};
        for (const cell& c : cells) {
            const real am = (c.q.a0 + c.q.a1) / 2, bm = (c.q.b0 + c.q.b1) / 2;
            for (int k = 0; k < 4; ++k) {
                grid_cell q = c.q;
                (k & 1 ? q.a0 : q.a1) = am;
                (k & 2 ? q.b0 : q.b1) = bm;
                const vec3 u = cell_centre(q);
                const auto e = pb.eval(u);
                kids.push_back({q, u, e.s, cell_radius(q, u)});
                kval.push_back(e.F);
                if (e.F > bc.F) bc = {u, e.F};
            }
        }
        if (bc.F > o.F + noise) {
            const optimum r = refine(pb, bc, W0);
            o = r.F > bc.F ? r : bc;
        }
        std::vector<cell> next;
        for (std::size_t k = 0; k < kids.size(); ++k) {
            const cell& c = kids[k];
            const cap cp(c.rho);
            real b = cap_upper_bound(c.c, kval[k], c.s, cp);
            const std::size_t g = k / 4 * 4;  // the siblings, then the parent
            for (std::size_t j = g; j < g + 4 && b > o.F + noise; ++j)
                if (j != k) b = std::min(b, pair_upper_bound(c.c, c.s, kids[j].s, cp));
            if (b > o.F + noise) b = std::min(b, pair_upper_bound(c.c, c.s, cells[k / 4].s, cp));
            // a kink of f along the cell's edge (the grid's lines are great circles, so are the
            // kinks of aligned configurations): support points just across each edge
            const real da = c.q.a1 - c.q.a0, db = c.q.b1 - c.q.b0;
            const real am = (c.q.a0 + c.q.a1) / 2, bm = (c.q.b0 + c.q.b1) / 2;
            for (int side = 0; side < 4 && b > o.F + noise; ++side) {
                const real a = am + (side == 0 ? da : side == 1 ? -da : 0);
                const real bb = bm + (side == 2 ? db : side == 3 ? -db : 0);
                const auto e = pb.eval(cube_direction(c.q.face, a, bb));
                b = std::min(b, pair_upper_bound(c.c, c.s, e.s, cp));
            }
            if (b > o.F + noise) next.push_back(c);
        }
        cells = std::move(next);
    }
    if (best.F > o.F) o = refine(pb, best, W0);  // never worse than the samples
    return polish(pb, o, W0);
}

template <class A, class B>
distance_result bounded_distance(const A& a, const pose& pa, const B& b, const pose& pb) {
    const problem<A, B> pr(a, pa, b, pb);
    const optimum o = maximise(pr);
    const vec3 u = o.u;
    const vec3 va = rotT(pa.R, u), vb = neg(rotT(pb.R, u));
    distance_result r;
    r.distance = pr.value(u);
    r.normal = u;
    r.point_a = add(pa.t, rot(pa.R, local_support_point(a, va)));
    r.point_b = add(pb.t, rot(pb.R, local_support_point(b, vb)));
    r.witness_unique = local_unique(a, va, unique_tol) && local_unique(b, vb, unique_tol);
    return r;
}

inline vec3 plane_normal(const pose& p) { return {p.R[0][2], p.R[1][2], p.R[2][2]}; }

}  // namespace detail

// Signed distance between A (pose pa) and B (pose pb); see distance_result.
//  * both bounded: max over unit u of -h_A(u) - h_B(-u), maximised numerically (see the top).
//  * A a half-space {n.(x - tA) <= 0}, n = RA e_z, B bounded: the normal is n and
//        distance = min over x in B of n.(x - tA) = n.(tB - tA) - hB_local(-RB^T n)
//    (the shortest translation separating B is along n); point_b = the support point of B along
//    -n, point_a = its projection on the plane.
//  * A bounded, B a half-space with plane normal n = RB e_z: the normal is -n and
//        distance = min over x in A of n.(x - tB); point_a = the support point of A along -n,
//    point_b = its projection on the plane.
//  For the half-space pairs witness_unique tells whether the bounded shape's support point is
//  unique (the half-space's is its projection). Two half-spaces are not supported.
template <any_shape A, any_shape B>
distance_result signed_distance(const A& a, const pose& pa, const B& b, const pose& pb) {
    using namespace detail;
    static_assert(!(std::is_same_v<A, half_space> && std::is_same_v<B, half_space>),
                  "collision_ref: the distance between two half-spaces is not defined here");
    distance_result r;
    if constexpr (std::is_same_v<A, half_space>) {
        const vec3 n = plane_normal(pa);
        const vec3 v = neg(rotT(pb.R, n));
        r.distance = dot(n, sub(pb.t, pa.t)) - local_support(b, v);
        r.normal = n;
        r.point_b = add(pb.t, rot(pb.R, local_support_point(b, v)));
        r.point_a = sub(r.point_b, mul(r.distance, n));
        r.witness_unique = local_unique(b, v, unique_tol);
        (void)a;
    } else if constexpr (std::is_same_v<B, half_space>) {
        const vec3 n = plane_normal(pb);
        const vec3 v = neg(rotT(pa.R, n));
        r.distance = dot(n, sub(pa.t, pb.t)) - local_support(a, v);
        r.normal = neg(n);
        r.point_a = add(pa.t, rot(pa.R, local_support_point(a, v)));
        r.point_b = sub(r.point_a, mul(r.distance, n));
        r.witness_unique = local_unique(a, v, unique_tol);
        (void)b;
    } else {
        r = bounded_distance(a, pa, b, pb);
    }
    return r;
}

// ---------------------------------------------------------------------------------------------
// Point queries
// ---------------------------------------------------------------------------------------------

// Signed distance from the shape to the point p (> 0 outside, < 0 inside: minus the distance to
// the boundary). normal: unit, the maximiser u (outward from the shape towards p: the gradient
// of the signed distance); point_a: the support point of the shape along the normal (the
// closest boundary point when witness_unique); point_b = p.
template <any_shape S>
distance_result point_query(const S& s, const pose& P, const vec3& p) {
    using namespace detail;
    distance_result r;
    if constexpr (std::is_same_v<S, half_space>) {
        const vec3 n = plane_normal(P);
        r.distance = dot(n, sub(p, P.t));
        r.normal = n;
        r.point_b = p;
        r.point_a = sub(p, mul(r.distance, n));
        r.witness_unique = true;
        (void)s;
    } else {
        r = bounded_distance(s, P, point_shape{}, pose{identity_pose().R, p});
    }
    return r;
}

template <any_shape S>
real point_signed_distance(const S& s, const pose& P, const vec3& p) {
    return point_query(s, P, p).distance;
}

// ---------------------------------------------------------------------------------------------
// Containment (closed-form point-shape distances; hull: its face planes)
// ---------------------------------------------------------------------------------------------

namespace detail {

struct hull_face {
    vec3 normal;                    // outward unit normal
    real offset;                    // the face plane is normal.x = offset
    std::vector<std::size_t> loop;  // vertex indices, counter-clockwise seen from outside
};

// Faces of the convex hull of P: every plane through three points with no point strictly
// outside it (tolerance 1e-13 of the extent) is a supporting plane; the points on it form a
// face, ordered by a 2-D convex hull (Andrew's monotone chain). Empty when P spans no volume.
inline std::vector<hull_face> hull_faces(const std::vector<vec3>& P) {
    std::vector<hull_face> faces;
    const std::size_t n = P.size();
    if (n < 4) return faces;
    real ext = 0;
    for (const vec3& p : P) ext = std::max(ext, norm(sub(p, P[0])));
    if (!(ext > 0)) return faces;
    const real tol = 1e-13L * ext;
    std::set<std::vector<std::size_t>> seen;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            for (std::size_t k = j + 1; k < n; ++k) {
                vec3 nn = cross(sub(P[j], P[i]), sub(P[k], P[i]));
                if (!(norm(nn) > 1e-10L * ext * ext)) continue;
                nn = normalized(nn);
                bool pos = false, negv = false;
                for (std::size_t m = 0; m < n && !(pos && negv); ++m) {
                    const real h = dot(nn, sub(P[m], P[i]));
                    pos = pos || h > tol;
                    negv = negv || h < -tol;
                }
                if (pos && negv) continue;
                if (!pos && !negv) return {};  // all points on one plane: no volume
                if (pos) nn = neg(nn);
                std::vector<std::size_t> on;
                for (std::size_t m = 0; m < n; ++m)
                    if (std::abs(dot(nn, sub(P[m], P[i]))) <= tol) on.push_back(m);
                if (!seen.insert(on).second) continue;
                // 2-D hull of the points on the plane, in the basis (e1, e2 = n x e1)
                const chart c = make_chart(nn);
                const vec3 e1 = c.e1, e2 = cross(nn, e1);
                struct q2 {
                    real x, y;
                    std::size_t idx;
                };
                std::vector<q2> pts;
                for (std::size_t m : on) pts.push_back({dot(P[m], e1), dot(P[m], e2), m});
                std::sort(pts.begin(), pts.end(), [](const q2& a, const q2& b) {
                    return a.x < b.x || (a.x == b.x && a.y < b.y);
                });
                auto turn = [](const q2& o, const q2& a, const q2& b) {
                    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
                };
                std::vector<q2> H(2 * pts.size());
                std::size_t h = 0;
                for (std::size_t m = 0; m < pts.size(); ++m) {
                    while (h >= 2 && turn(H[h - 2], H[h - 1], pts[m]) <= tol * ext) --h;
                    H[h++] = pts[m];
                }
                for (std::size_t m = pts.size() - 1, lower = h + 1; m-- > 0;) {
                    while (h >= lower && turn(H[h - 2], H[h - 1], pts[m]) <= tol * ext) --h;
                    H[h++] = pts[m];
                }
                if (h > 0) --h;  // the last point repeats the first
                if (h < 3) continue;
                hull_face f;
                f.normal = nn;
                f.offset = dot(nn, P[i]);
                for (std::size_t m = 0; m < h; ++m) f.loop.push_back(H[m].idx);
                faces.push_back(std::move(f));
            }
    return faces;
}

inline real box_sdf(const vec3& h, const vec3& p) {
    vec3 q;
    for (std::size_t i = 0; i < 3; ++i) q[i] = std::abs(p[i]) - h[i];
    const vec3 o{std::max<real>(q[0], 0), std::max<real>(q[1], 0), std::max<real>(q[2], 0)};
    return norm(o) + std::min<real>(std::max({q[0], q[1], q[2]}), 0);
}

}  // namespace detail

// True when the point is in the shape or within `tolerance` of it (for a hull: within
// `tolerance` of every face plane).
template <any_shape S>
bool contains(const S& s, const pose& P, const vec3& point, real tolerance) {
    using namespace detail;
    const vec3 p = rotT(P.R, sub(point, P.t));
    if constexpr (std::is_same_v<S, sphere>) {
        return norm(p) - s.radius <= tolerance;
    } else if constexpr (std::is_same_v<S, capsule>) {
        const real z = std::clamp(p[2], -s.half_height, s.half_height);
        return norm(sub(p, vec3{0, 0, z})) - s.radius <= tolerance;
    } else if constexpr (std::is_same_v<S, box>) {
        return box_sdf(s.half, p) <= tolerance;
    } else if constexpr (std::is_same_v<S, cylinder>) {
        const real dr = std::hypot(p[0], p[1]) - s.radius, dz = std::abs(p[2]) - s.half_height;
        const real sd = std::min<real>(std::max(dr, dz), 0) +
                        std::hypot(std::max<real>(dr, 0), std::max<real>(dz, 0));
        return sd <= tolerance;
    } else if constexpr (std::is_same_v<S, half_space>) {
        (void)s;
        return p[2] <= tolerance;
    } else {
        // the faces of the last hull seen by this thread are kept (compared point by point)
        thread_local std::vector<vec3> last_points;
        thread_local std::vector<hull_face> faces;
        if (last_points != s.points || faces.empty()) {
            faces = hull_faces(s.points);
            last_points = s.points;
        }
        if (faces.empty()) return point_signed_distance(s, P, point) <= tolerance;  // flat hull
        real m = -std::numeric_limits<real>::infinity();
        for (const auto& f : faces) m = std::max(m, dot(f.normal, p) - f.offset);
        return m <= tolerance;
    }
}

// ---------------------------------------------------------------------------------------------
// Ray casts
// ---------------------------------------------------------------------------------------------

// Smallest s in [0, max_length] with origin + s direction in the shape (0 when the origin is in
// it), or nullopt. `direction` is normally unit (s is measured in its units).
template <any_shape S>
std::optional<real> ray_cast(const S& s, const pose& P, const vec3& origin, const vec3& direction,
                             real max_length) {
    using namespace detail;
    if (!(max_length >= 0)) return std::nullopt;
    auto point = [&](real t) { return add(origin, mul(t, direction)); };
    real radius = 0;
    if constexpr (!std::is_same_v<S, half_space>) radius = local_radius(s);
    // |phi| below this is rounding: the point is on the boundary
    auto touch = [&](real t) { return 16 * eps * (norm(sub(point(t), P.t)) + radius); };
    distance_result q = point_query(s, P, origin);
    if (q.distance <= 0) return real(0);
    real lo = 0, phi = q.distance, dphi = dot(q.normal, direction);
    const real dlen = norm(direction);
    if (!(dlen > 0)) return std::nullopt;
    std::optional<real> hi;  // a parameter known to be inside
    for (int it = 0; it < 400; ++it) {
        if (phi <= touch(lo)) return lo;
        if (!hi && !(dphi < 0))
            return std::nullopt;      // phi convex and not decreasing: no root ahead
        real next = lo + phi / dlen;  // sphere-tracing step: |phi'| <= |d|
        if (dphi < 0) next = std::max(next, lo - phi / dphi);  // Newton step: still below the root
        if (hi) {
            if (!(next < *hi)) next = (lo + *hi) / 2;
        } else if (next > max_length) {
            return std::nullopt;
        }
        if (!(next > lo)) return lo;
        // next is below the first root (Newton and sphere-tracing steps are lower bounds), so
        // when it is in the shape it is the root to rounding; contains (closed form) spares the
        // point query its costly overlapping branch there
        if (!hi && contains(s, P, point(next), 0)) return next;
        q = point_query(s, P, point(next));
        if (q.distance <= 0) {
            if (q.distance >= -touch(next)) return next;
            hi = next;
            if (*hi - lo <= 4 * eps * std::max<real>(1, *hi)) return *hi;
        } else {
            lo = next;
            phi = q.distance;
            dphi = dot(q.normal, direction);
        }
    }
    return hi ? *hi : lo;
}

// ---------------------------------------------------------------------------------------------
// Mass properties by quadrature
// ---------------------------------------------------------------------------------------------

struct mass_result {
    real mass;
    vec3 com;                // local frame
    mat3 inertia_about_com;  // integral of density (|r|^2 1 - r r^T), r from the com, local axes
};

namespace detail {

struct moments {
    real m0 = 0;
    vec3 m1{0, 0, 0};
    mat3 m2{};
    void add(const vec3& x, real w) {
        m0 += w;
        for (std::size_t i = 0; i < 3; ++i) {
            m1[i] += w * x[i];
            for (std::size_t j = 0; j < 3; ++j) m2[i][j] += w * x[i] * x[j];
        }
    }
};

// Gauss-Legendre nodes and weights on [-1, 1], 8 points (exact for degree 15).
inline const std::vector<std::pair<real, real>>& gauss_legendre() {
    static const std::vector<std::pair<real, real>> g = [] {
        const int n = 8;
        std::vector<std::pair<real, real>> r;
        for (int i = 1; i <= n; ++i) {
            real x = std::cos(pi * (static_cast<real>(i) - 0.25L) / (static_cast<real>(n) + 0.5L)),
                 dp = 1;
            for (int it = 0; it < 100; ++it) {
                real p0 = 1, p1 = x;
                for (int k = 2; k <= n; ++k) {
                    const real p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n * (x * p1 - p0) / (x * x - 1);
                const real dx = p1 / dp;
                x -= dx;
                if (std::abs(dx) < 4 * eps) break;
            }
            {
                real p0 = 1, p1 = x;
                for (int k = 2; k <= n; ++k) {
                    const real p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n * (x * p1 - p0) / (x * x - 1);
            }
            r.push_back({x, 2 / ((1 - x * x) * dp * dp)});
        }
        return r;
    }();
    return g;
}

// Solid of revolution about z between z0 and z1 with radius R(z): Gauss-Legendre in z and in
// rho (Jacobian rho), midpoint rule with 8 points in phi (exact for trigonometric degree < 8).
template <class Rf>
void integrate_revolution(moments& M, real z0, real z1, Rf R) {
    const auto& gl = gauss_legendre();
    const int nphi = 8;
    for (const auto& [xz, wz] : gl) {
        const real z = (z0 + z1) / 2 + (z1 - z0) / 2 * xz;
        const real Rz = R(z);
        if (!(Rz > 0)) continue;
        for (const auto& [xr, wr] : gl) {
            const real rho = Rz / 2 * (1 + xr);
            for (int k = 0; k < nphi; ++k) {
                const real phi = 2 * pi * (static_cast<real>(k) + 0.5L) / nphi;
                const real w = wz * (z1 - z0) / 2 * wr * Rz / 2 * rho * (2 * pi / nphi);
                M.add({rho * std::cos(phi), rho * std::sin(phi), z}, w);
            }
        }
    }
}

inline mass_result finish_mass(const moments& M, real density, const vec3& origin) {
    mass_result r{};
    r.mass = density * M.m0;
    if (!(M.m0 > 0)) {
        r.com = origin;
        return r;
    }
    const vec3 c = mul(1 / M.m0, M.m1);
    mat3 C;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) C[i][j] = M.m2[i][j] - M.m0 * c[i] * c[j];
    const real tr = C[0][0] + C[1][1] + C[2][2];
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            r.inertia_about_com[i][j] = density * ((i == j ? tr : 0) - C[i][j]);
    r.com = add(origin, c);
    return r;
}

}  // namespace detail

inline mass_result mass_properties(const sphere& s, real density) {
    detail::moments M;
    const real r = s.radius;
    detail::integrate_revolution(
        M, -r, r, [r](real z) { return std::sqrt(std::max<real>(0, r * r - z * z)); });
    return detail::finish_mass(M, density, {0, 0, 0});
}

inline mass_result mass_properties(const capsule& s, real density) {
    detail::moments M;
    const real r = s.radius, h = s.half_height;
    auto cap = [r](real zc) {
        return
            [r, zc](real z) { return std::sqrt(std::max<real>(0, r * r - (z - zc) * (z - zc))); };
    };
    detail::integrate_revolution(M, -h - r, -h, cap(-h));
    if (h > 0) detail::integrate_revolution(M, -h, h, [r](real) { return r; });
    detail::integrate_revolution(M, h, h + r, cap(h));
    return detail::finish_mass(M, density, {0, 0, 0});
}

inline mass_result mass_properties(const cylinder& s, real density) {
    detail::moments M;
    const real r = s.radius;
    detail::integrate_revolution(M, -s.half_height, s.half_height, [r](real) { return r; });
    return detail::finish_mass(M, density, {0, 0, 0});
}

inline mass_result mass_properties(const box& s, real density) {
    detail::moments M;
    const auto& gl = detail::gauss_legendre();
    const vec3& h = s.half;
    for (const auto& [x, wx] : gl)
        for (const auto& [y, wy] : gl)
            for (const auto& [z, wz] : gl)
                M.add({h[0] * x, h[1] * y, h[2] * z}, wx * wy * wz * h[0] * h[1] * h[2]);
    return detail::finish_mass(M, density, {0, 0, 0});
}

// Hull: tetrahedra from the mean of the points to each face triangle (fan of the face loop),
// signed volumes, each integrated with the 4-point rule (barycentric (a,b,b,b),
// a = (5+3 sqrt5)/20, b = (5-sqrt5)/20, weights V/4), exact for degree 2. A hull that spans no
// volume has mass 0 (com = mean of the points, inertia 0).
inline mass_result mass_properties(const hull& s, real density) {
    using namespace detail;
    vec3 c{0, 0, 0};
    for (const vec3& p : s.points) c = add(c, p);
    if (!s.points.empty()) c = mul(1 / static_cast<real>(s.points.size()), c);
    const auto faces = hull_faces(s.points);
    moments M;
    const real sq5 = std::sqrt(real(5));
    const real qa = (5 + 3 * sq5) / 20, qb = (5 - sq5) / 20;
    for (const auto& f : faces) {
        const vec3 p0 = sub(s.points[f.loop[0]], c);
        for (std::size_t k = 1; k + 1 < f.loop.size(); ++k) {
            const vec3 p1 = sub(s.points[f.loop[k]], c), p2 = sub(s.points[f.loop[k + 1]], c);
            const real V = dot(p0, cross(p1, p2)) / 6;
            const std::array<vec3, 4> v{vec3{0, 0, 0}, p0, p1, p2};
            for (std::size_t q = 0; q < 4; ++q) {
                vec3 x{0, 0, 0};
                for (std::size_t m = 0; m < 4; ++m) x = add(x, mul(m == q ? qa : qb, v[m]));
                M.add(x, V / 4);
            }
        }
    }
    return finish_mass(M, density, c);
}

}  // namespace collision_ref
