// Hand-written 6D spatial algorithms on kinematic trees: Featherstone's (Rigid Body Dynamics
// Algorithms, 2008) forward kinematics, RNEA (Table 5.1), CRBA (Table 6.2) and ABA (Table 7.1),
// written the way a competent engineer writes fast generic code without a library (Pinocchio-like):
// the tree's structure is run-time data (a capacity N as template parameter, no heap, no virtual
// calls, no Eigen), every joint type has its own code for its motion subspace (a revolute joint
// about z has S = (e_z, 0): Sᵀ f = f.n.z, S q̇ is one component, U = I^A S is one column of I^A,
// ...), placements are a 3×3 rotation and a translation, rigid inertias are (m, h = m c, I_o)
// about the body origin, articulated inertias are symmetric 6×6 matrices stored as three 3×3
// blocks [[A, B], [Bᵀ, C]] (A, C symmetric). The benchmarks' "spatial" competitor of ctga::chains;
// it uses only bench/spatial.hpp's plain structs.
//
// Conventions (the same as tests/support/featherstone.hpp):
//   * body i's joint frame in its parent's frame: x_parent = R x_joint + t. The body frame is the
//     joint frame moved by the joint: revolute about u by q: R_i = R Rot(u, q), t_i = t;
//     prismatic along u by q: R_i = R, t_i = t + q R u; fixed: R, t; floating (7 coordinates
//     q = (x, y, z, qw, qx, qy, qz), a unit quaternion, R_J its rotation, t_J = (x, y, z)):
//     R_i = R R_J, t_i = R t_J + t;
//   * motions (ω, v) and forces (n, f) in body coordinates about the body origin; S = (u, 0)
//     revolute, (0, u) prismatic, 1₆ floating (its 6 velocity coordinates are the body's twist
//     relative to the joint frame, body coordinates), none fixed;
//   * gravity by the base acceleration a_0 = (0, −g) (world coordinates) in rnea and aba; fk's
//     accelerations are without gravity;
//   * f_ext[i] (optional, nullptr = none) acts on body i in body i's coordinates and is
//     subtracted: f_i = I a_i + v_i ×* I v_i − f_ext_i (RNEA), p_i = v_i ×* I v_i − f_ext_i (ABA);
//   * q, q̇, q̈, τ are arrays of doubles, bodies in order, each with its joint's nq / nv numbers;
//     H is row-major nv × nv (leading dimension nv).
//
// Usage:
//   spatial::chains::model<8> m{};            // capacity 8
//   m.bodies[0] = {-1, joint_kind::revolute_z, {0, 0, 1}, identity, {0, 0, 0.3}, {m, c, I_c}};
//   ...; m.n = 7; m.gravity = {0, 0, -9.81};
//   finalize(m);                              // offsets, nq, nv, inertias about the origins, ...
//   rnea(m, q, qd, qdd, nullptr, tau); aba(m, q, qd, tau, nullptr, qdd); crba(m, q, H);
//   kinematics<8> k; fk(m, q, qd, qdd, k);
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "spatial.hpp"

// Everything on the hot paths is forced inline: GCC's size heuristics would otherwise keep the
// small helpers out of line once the joint types' cases have multiplied the algorithms' code.
#if defined(__GNUC__) || defined(__clang__)
#define SPATIAL_CHAINS_INLINE inline __attribute__((always_inline))
#else
#define SPATIAL_CHAINS_INLINE inline
#endif

namespace spatial::chains {

// ---------------------------------------------------------------------------------------------
// The model.

enum class joint_kind {
    revolute_x,
    revolute_y,
    revolute_z,
    prismatic_x,
    prismatic_y,
    prismatic_z,
    revolute_axis,
    prismatic_axis,
    fixed,
    floating
};

constexpr int joint_nq(joint_kind k) {
    return k == joint_kind::fixed ? 0 : k == joint_kind::floating ? 7 : 1;
}
constexpr int joint_nv(joint_kind k) {
    return k == joint_kind::fixed ? 0 : k == joint_kind::floating ? 6 : 1;
}

struct body {
    int parent;        // parent body, −1 = the world; parent < own index
    joint_kind kind;
    vec3 axis;         // unit, joint-frame coordinates (revolute_axis, prismatic_axis)
    mat3 R;            // joint frame in the parent frame: x_parent = R x_joint + t
    vec3 t;
    inertia I;         // m, c, I_c in the body frame
};

// A rigid inertia about the body origin: mass, first moment h = m c, rotational inertia I_o about
// the origin (I_o = I_c + m (|c|² 1 − c cᵀ)). n = I_o ω + h × v, f = m v − h × ω.
struct rigid {
    double m;
    vec3 h;
    sym3 I;
};

// What finalize() precomputes for a body.
struct body_cache {
    rigid Y;    // the body's inertia about its origin, body frame
    mat3 P1;    // revolute_axis: R [u]×
    mat3 P2;    // revolute_axis: R [u]×²   (R Rot(u, q) = R + sin q P1 + (1 − cos q) P2)
    vec3 Ru;    // prismatic: R u (the joint's direction in the parent frame)
    int iq, iv; // where the body's coordinates start in q and in v
};

template <std::size_t N>
struct model {
    std::array<body, N> bodies;
    std::size_t n;   // bodies used; parents precede children
    vec3 gravity;    // world frame
    // filled by finalize()
    std::array<body_cache, N> cache;
    std::size_t nq, nv;
};

// ---------------------------------------------------------------------------------------------
// Small helpers on bench/spatial.hpp's types.

SPATIAL_CHAINS_INLINE vec3 operator-(vec3 a) { return {-a.x, -a.y, -a.z}; }
SPATIAL_CHAINS_INLINE motion operator+(const motion& a, const motion& b) { return {a.w + b.w, a.v + b.v}; }
// Y s: n = I_o ω + h × v, f = m v − h × ω: 24m
SPATIAL_CHAINS_INLINE force operator*(const rigid& Y, const motion& s) {
    return {Y.I * s.w + cross(Y.h, s.v), Y.m * s.v - cross(Y.h, s.w)};
}

namespace detail {

SPATIAL_CHAINS_INLINE vec3 col(const mat3& R, int j) {
    return j == 0 ? vec3{R.r0.x, R.r1.x, R.r2.x} : j == 1 ? vec3{R.r0.y, R.r1.y, R.r2.y} : vec3{R.r0.z, R.r1.z, R.r2.z};
}
// Rᵀ v
SPATIAL_CHAINS_INLINE vec3 tmul(const mat3& R, vec3 v) {
    return {R.r0.x * v.x + R.r1.x * v.y + R.r2.x * v.z, R.r0.y * v.x + R.r1.y * v.y + R.r2.y * v.z,
            R.r0.z * v.x + R.r1.z * v.y + R.r2.z * v.z};
}
// row vector times matrix: vᵀ B
SPATIAL_CHAINS_INLINE vec3 rmul(vec3 v, const mat3& B) {
    return {v.x * B.r0.x + v.y * B.r1.x + v.z * B.r2.x, v.x * B.r0.y + v.y * B.r1.y + v.z * B.r2.y,
            v.x * B.r0.z + v.y * B.r1.z + v.z * B.r2.z};
}
SPATIAL_CHAINS_INLINE mat3 mul(const mat3& A, const mat3& B) { return {rmul(A.r0, B), rmul(A.r1, B), rmul(A.r2, B)}; }
SPATIAL_CHAINS_INLINE mat3 skew(vec3 u) { return {{0, -u.z, u.y}, {u.z, 0, -u.x}, {-u.y, u.x, 0}}; }
SPATIAL_CHAINS_INLINE void add_to(sym3& a, const sym3& b) {
    a.xx += b.xx; a.xy += b.xy; a.yy += b.yy; a.xz += b.xz; a.yz += b.yz; a.zz += b.zz;
}
SPATIAL_CHAINS_INLINE void add_to(vec3& a, vec3 b) { a.x += b.x; a.y += b.y; a.z += b.z; }
SPATIAL_CHAINS_INLINE void add_to(mat3& a, const mat3& b) { add_to(a.r0, b.r0); add_to(a.r1, b.r1); add_to(a.r2, b.r2); }
SPATIAL_CHAINS_INLINE void add_to(force& a, const force& b) { add_to(a.n, b.n); add_to(a.f, b.f); }
SPATIAL_CHAINS_INLINE void sub_to(force& a, const force& b) { a.n = a.n - b.n; a.f = a.f - b.f; }

// R S Rᵀ for symmetric S (the upper triangle): 45m
SPATIAL_CHAINS_INLINE sym3 rotate(const mat3& R, const sym3& S) {
    const vec3 a0 = S * R.r0, a1 = S * R.r1, a2 = S * R.r2;   // rows of R S
    return {dot(a0, R.r0), dot(a0, R.r1), dot(a1, R.r1), dot(a0, R.r2), dot(a1, R.r2), dot(a2, R.r2)};
}
// R B Rᵀ for general B: 54m
SPATIAL_CHAINS_INLINE mat3 rotate(const mat3& R, const mat3& B) {
    const vec3 a0 = rmul(R.r0, B), a1 = rmul(R.r1, B), a2 = rmul(R.r2, B);   // rows of R B
    return {{dot(a0, R.r0), dot(a0, R.r1), dot(a0, R.r2)},
            {dot(a1, R.r0), dot(a1, R.r1), dot(a1, R.r2)},
            {dot(a2, R.r0), dot(a2, R.r1), dot(a2, R.r2)}};
}

// ---- transforms by a body's placement X = (R, t) in its parent ------------------------------

// parent → body for motions: ω = Rᵀ ω_p, v = Rᵀ (v_p − t × ω_p): 24m
SPATIAL_CHAINS_INLINE motion inv_act(const se3& X, const motion& m) {
    return {tmul(X.R, m.w), tmul(X.R, m.v + cross(m.w, X.t))};
}
// body → parent for forces: f_p = R f, n_p = R n + t × f_p (as spatial::act): 24m
SPATIAL_CHAINS_INLINE force act_force(const se3& X, const force& F) {
    const vec3 f = X.R * F.f;
    return {X.R * F.n + cross(X.t, f), f};
}
// v ×* f = (ω × n + v × f, ω × f) and v × m = (ω × ω_m, ω × v_m + v × ω_m) (as spatial::cross)
SPATIAL_CHAINS_INLINE force crf(const motion& a, const force& b) { return {cross(a.w, b.n) + cross(a.v, b.f), cross(a.w, b.f)}; }
SPATIAL_CHAINS_INLINE motion crm(const motion& a, const motion& b) { return {cross(a.w, b.w), cross(a.w, b.v) + cross(a.v, b.w)}; }

// world → body for the gravity base acceleration (0, a): ω = 0, v = Rᵀ a
SPATIAL_CHAINS_INLINE motion inv_act_linear(const se3& X, vec3 a) { return {{0, 0, 0}, tmul(X.R, a)}; }

// composition: (Xa Xb) x = Ra (Rb x + tb) + ta
SPATIAL_CHAINS_INLINE se3 compose(const se3& a, const se3& b) { return {mul(a.R, b.R), a.R * b.t + a.t}; }

// ---- rigid inertias about the origin ---------------------------------------------------------

SPATIAL_CHAINS_INLINE rigid about_origin(const inertia& Y) {
    const vec3 c = Y.c;
    const double m = Y.m;
    return {m, m * c,
            {Y.I.xx + m * (c.y * c.y + c.z * c.z), Y.I.xy - m * c.x * c.y, Y.I.yy + m * (c.x * c.x + c.z * c.z),
             Y.I.xz - m * c.x * c.z, Y.I.yz - m * c.y * c.z, Y.I.zz + m * (c.x * c.x + c.y * c.y)}};
}
// P += X Y (Y expressed in the parent frame): h_r = R h, I_r = R I Rᵀ,
// I_p = I_r + 2 (g · t) 1 − (t gᵀ + g tᵀ) with g = h_r + (m/2) t; h_p = h_r + m t.
SPATIAL_CHAINS_INLINE void add_transformed(rigid& P, const se3& X, const rigid& Y) {
    const vec3 hr = X.R * Y.h;
    const sym3 Ir = rotate(X.R, Y.I);
    const vec3 t = X.t;
    const vec3 g = hr + (0.5 * Y.m) * t;
    const double k = 2 * dot(g, t);
    P.m += Y.m;
    add_to(P.h, hr + Y.m * t);
    P.I.xx += Ir.xx + k - 2 * t.x * g.x;
    P.I.yy += Ir.yy + k - 2 * t.y * g.y;
    P.I.zz += Ir.zz + k - 2 * t.z * g.z;
    P.I.xy += Ir.xy - (t.x * g.y + g.x * t.y);
    P.I.xz += Ir.xz - (t.x * g.z + g.x * t.z);
    P.I.yz += Ir.yz - (t.y * g.z + g.y * t.z);
}

// ---- articulated inertias: [[A, B], [Bᵀ, C]], n = A ω + B v, f = Bᵀ ω + C v -------------------

struct abi {
    sym3 A;
    mat3 B;
    sym3 C;
};
SPATIAL_CHAINS_INLINE abi to_abi(const rigid& Y) {
    return {Y.I, skew(Y.h), {Y.m, 0, Y.m, 0, 0, Y.m}};
}
SPATIAL_CHAINS_INLINE force operator*(const abi& I, const motion& s) {
    return {I.A * s.w + I.B * s.v, tmul(I.B, s.w) + I.C * s.v};
}
// P += the articulated inertia [[A, B], [Bᵀ, C]] (already rotated into the parent's axes) moved
// by t (the body origin in the parent): with T = [t]×, K = T C,
//   C_p = C, B_p = B + K, A_p = A − (B T + (B T)ᵀ) − K T   (48m)
SPATIAL_CHAINS_INLINE void translate_add(abi& P, vec3 t, const sym3& A, const mat3& B, const sym3& C) {
    // K = T C: column j = t × C col j (C symmetric: col j = row j)
    const vec3 k0 = cross(t, vec3{C.xx, C.xy, C.xz});
    const vec3 k1 = cross(t, vec3{C.xy, C.yy, C.yz});
    const vec3 k2 = cross(t, vec3{C.xz, C.yz, C.zz});
    add_to(P.C, C);
    P.B.r0.x += B.r0.x + k0.x; P.B.r0.y += B.r0.y + k1.x; P.B.r0.z += B.r0.z + k2.x;
    P.B.r1.x += B.r1.x + k0.y; P.B.r1.y += B.r1.y + k1.y; P.B.r1.z += B.r1.z + k2.y;
    P.B.r2.x += B.r2.x + k0.z; P.B.r2.y += B.r2.y + k1.z; P.B.r2.z += B.r2.z + k2.z;
    // rows of B T (row_i(B) × t) and the upper triangle of K T (row_i(K) × t)
    const vec3 bt0 = cross(B.r0, t), bt1 = cross(B.r1, t), bt2 = cross(B.r2, t);
    const vec3 kr0{k0.x, k1.x, k2.x}, kr1{k0.y, k1.y, k2.y}, kr2{k0.z, k1.z, k2.z};
    P.A.xx += A.xx - 2 * bt0.x - (kr0.y * t.z - kr0.z * t.y);
    P.A.xy += A.xy - (bt0.y + bt1.x) - (kr0.z * t.x - kr0.x * t.z);
    P.A.xz += A.xz - (bt0.z + bt2.x) - (kr0.x * t.y - kr0.y * t.x);
    P.A.yy += A.yy - 2 * bt1.y - (kr1.z * t.x - kr1.x * t.z);
    P.A.yz += A.yz - (bt1.z + bt2.y) - (kr1.x * t.y - kr1.y * t.x);
    P.A.zz += A.zz - 2 * bt2.z - (kr2.x * t.y - kr2.y * t.x);
}

// P += Xᵀ I X (the articulated inertia of a body's subtree carried to its parent, X = ^iX_λ):
// rotate the blocks (A' = R A Rᵀ, ...: 144m), then translate_add.
SPATIAL_CHAINS_INLINE void add_transformed(abi& P, const se3& X, const abi& I) {
    translate_add(P, X.t, rotate(X.R, I.A), rotate(X.R, I.B), rotate(X.R, I.C));
}

// Component a (a compile-time constant after inlining) of a vector.
SPATIAL_CHAINS_INLINE double get(vec3 v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }

// R S Rᵀ for a symmetric S whose row and column k are zero: S = the 2×2 block (s_ii, s_ij, s_jj)
// on the other two indices i, j; ri, rj = columns i, j of R. R S Rᵀ = p riᵀ + q rjᵀ with
// p = s_ii ri + s_ij rj, q = s_ij ri + s_jj rj (24m).
SPATIAL_CHAINS_INLINE sym3 rotate2(vec3 ri, vec3 rj, double sii, double sij, double sjj) {
    const vec3 p = sii * ri + sij * rj, q = sij * ri + sjj * rj;
    return {p.x * ri.x + q.x * rj.x, p.x * ri.y + q.x * rj.y, p.y * ri.y + q.y * rj.y,
            p.x * ri.z + q.x * rj.z, p.y * ri.z + q.y * rj.z, p.z * ri.z + q.z * rj.z};
}
// entry (a, b) of a symmetric matrix, row a of a matrix (a, b compile-time after inlining)
SPATIAL_CHAINS_INLINE double sget(const sym3& S, int a, int b) {
    if (a > b) { const int t = a; a = b; b = t; }
    return a == b ? (a == 0 ? S.xx : a == 1 ? S.yy : S.zz) : a == 0 ? (b == 1 ? S.xy : S.xz) : S.yz;
}
SPATIAL_CHAINS_INLINE vec3 row(const mat3& M, int a) { return a == 0 ? M.r0 : a == 1 ? M.r1 : M.r2; }
// v_a += x
SPATIAL_CHAINS_INLINE void add_at(vec3& v, int a, double x) {
    if (a == 0) v.x += x;
    else if (a == 1) v.y += x;
    else v.z += x;
}
// x yᵀ + z wᵀ
SPATIAL_CHAINS_INLINE mat3 outer2(vec3 x, vec3 y, vec3 z, vec3 w) {
    return {x.x * y + z.x * w, x.y * y + z.y * w, x.z * y + z.z * w};
}

// I −= U Uᵀ / D (U = (n, f) a force; Uᵀ's motion components pair f with v): with W = U / D
SPATIAL_CHAINS_INLINE void rank1_sub(abi& I, const force& U, const force& W) {
    const vec3 a = U.n, b = U.f, wa = W.n, wb = W.f;
    I.A.xx -= wa.x * a.x; I.A.xy -= wa.x * a.y; I.A.yy -= wa.y * a.y;
    I.A.xz -= wa.x * a.z; I.A.yz -= wa.y * a.z; I.A.zz -= wa.z * a.z;
    I.B.r0 = I.B.r0 - wa.x * b; I.B.r1 = I.B.r1 - wa.y * b; I.B.r2 = I.B.r2 - wa.z * b;
    I.C.xx -= wb.x * b.x; I.C.xy -= wb.x * b.y; I.C.yy -= wb.y * b.y;
    I.C.xz -= wb.x * b.z; I.C.yz -= wb.y * b.z; I.C.zz -= wb.z * b.z;
}

// Solve [[A, B], [Bᵀ, C]] x = rhs (symmetric positive definite 6×6) by LDLᵀ.
SPATIAL_CHAINS_INLINE motion solve6(const abi& I, const force& rhs) {
    double M[6][6];
    M[0][0] = I.A.xx; M[1][0] = I.A.xy; M[1][1] = I.A.yy; M[2][0] = I.A.xz; M[2][1] = I.A.yz; M[2][2] = I.A.zz;
    M[3][0] = I.B.r0.x; M[3][1] = I.B.r1.x; M[3][2] = I.B.r2.x;
    M[4][0] = I.B.r0.y; M[4][1] = I.B.r1.y; M[4][2] = I.B.r2.y;
    M[5][0] = I.B.r0.z; M[5][1] = I.B.r1.z; M[5][2] = I.B.r2.z;
    M[3][3] = I.C.xx; M[4][3] = I.C.xy; M[4][4] = I.C.yy; M[5][3] = I.C.xz; M[5][4] = I.C.yz; M[5][5] = I.C.zz;
    // LDLᵀ in place (lower triangle: L below the diagonal, D on it), with 1/D kept
    double inv_d[6];
    for (int j = 0; j < 6; ++j) {
        double d = M[j][j];
        for (int k = 0; k < j; ++k) d -= M[j][k] * M[j][k] * M[k][k];
        M[j][j] = d;
        inv_d[j] = 1.0 / d;
        for (int i = j + 1; i < 6; ++i) {
            double x = M[i][j];
            for (int k = 0; k < j; ++k) x -= M[i][k] * M[j][k] * M[k][k];
            M[i][j] = x * inv_d[j];
        }
    }
    double y[6] = {rhs.n.x, rhs.n.y, rhs.n.z, rhs.f.x, rhs.f.y, rhs.f.z};
    for (int i = 1; i < 6; ++i)
        for (int k = 0; k < i; ++k) y[i] -= M[i][k] * y[k];
    for (int i = 0; i < 6; ++i) y[i] *= inv_d[i];
    for (int i = 4; i >= 0; --i)
        for (int k = i + 1; k < 6; ++k) y[i] -= M[k][i] * y[k];
    return {{y[0], y[1], y[2]}, {y[3], y[4], y[5]}};
}

// ---- joints ----------------------------------------------------------------------------------

template <joint_kind K>
using kind_t = std::integral_constant<joint_kind, K>;

// Calls f(kind_t<k>{}): one specialised instance per joint type.
template <class F>
SPATIAL_CHAINS_INLINE void dispatch(joint_kind k, F&& f) {
    switch (k) {
    case joint_kind::revolute_x: f(kind_t<joint_kind::revolute_x>{}); return;
    case joint_kind::revolute_y: f(kind_t<joint_kind::revolute_y>{}); return;
    case joint_kind::revolute_z: f(kind_t<joint_kind::revolute_z>{}); return;
    case joint_kind::prismatic_x: f(kind_t<joint_kind::prismatic_x>{}); return;
    case joint_kind::prismatic_y: f(kind_t<joint_kind::prismatic_y>{}); return;
    case joint_kind::prismatic_z: f(kind_t<joint_kind::prismatic_z>{}); return;
    case joint_kind::revolute_axis: f(kind_t<joint_kind::revolute_axis>{}); return;
    case joint_kind::prismatic_axis: f(kind_t<joint_kind::prismatic_axis>{}); return;
    case joint_kind::fixed: f(kind_t<joint_kind::fixed>{}); return;
    case joint_kind::floating: f(kind_t<joint_kind::floating>{}); return;
    }
}

template <joint_kind K>
inline constexpr bool is_one_dof = K != joint_kind::fixed && K != joint_kind::floating;
template <joint_kind K>
inline constexpr bool is_revolute =
    K == joint_kind::revolute_x || K == joint_kind::revolute_y || K == joint_kind::revolute_z || K == joint_kind::revolute_axis;

template <joint_kind K>
inline constexpr bool is_coordinate_axis = K == joint_kind::revolute_x || K == joint_kind::revolute_y ||
                                           K == joint_kind::revolute_z || K == joint_kind::prismatic_x ||
                                           K == joint_kind::prismatic_y || K == joint_kind::prismatic_z;
template <joint_kind K>
inline constexpr int axis_index = (K == joint_kind::revolute_x || K == joint_kind::prismatic_x)   ? 0
                                  : (K == joint_kind::revolute_y || K == joint_kind::prismatic_y) ? 1
                                                                                                  : 2;

// ABA pass 2 for a one-dof joint about a coordinate axis e_k with a parent: I^a = I^A − U D⁻¹ Uᵀ
// has S in its kernel, so (revolute) row and column k of A and row k of B are zero, or
// (prismatic) column k of B and row and column k of C are; only the other entries are formed,
// rotated (with the two columns i, j of R that meet them) and translated into the parent's I^A.
// p^a = p^A + I^a c + U D⁻¹ u (c = v × S q̇ has no k components) goes to the parent's p^A.
template <joint_kind K>
SPATIAL_CHAINS_INLINE void aba_project_add(abi& P, force& pP, const se3& X, const abi& I, const force& U, double dinv, double u,
                            const motion& c, const force& p) {
    constexpr int k = axis_index<K>, i = (k + 1) % 3, j = (k + 2) % 3;
    const force W{dinv * U.n, dinv * U.f};
    const vec3 ri = col(X.R, i), rj = col(X.R, j);
    force pa{p.n + u * W.n, p.f + u * W.f};
    if constexpr (is_revolute<K>) {
        const double wi = get(W.n, i), wj = get(W.n, j), ui = get(U.n, i), uj = get(U.n, j);
        const double aii = sget(I.A, i, i) - wi * ui, aij = sget(I.A, i, j) - wi * uj, ajj = sget(I.A, j, j) - wj * uj;
        const vec3 bi = row(I.B, i) - wi * U.f, bj = row(I.B, j) - wj * U.f;
        const sym3 C{I.C.xx - W.f.x * U.f.x, I.C.xy - W.f.x * U.f.y, I.C.yy - W.f.y * U.f.y,
                     I.C.xz - W.f.x * U.f.z, I.C.yz - W.f.y * U.f.z, I.C.zz - W.f.z * U.f.z};
        // I^a c: n = A cω + B cv (rows i, j), f = Bᵀ cω + C cv
        const double cwi = get(c.w, i), cwj = get(c.w, j), cvi = get(c.v, i), cvj = get(c.v, j);
        add_at(pa.n, i, aii * cwi + aij * cwj + get(bi, i) * cvi + get(bi, j) * cvj);
        add_at(pa.n, j, aij * cwi + ajj * cwj + get(bj, i) * cvi + get(bj, j) * cvj);
        const vec3 Ci{sget(C, 0, i), sget(C, 1, i), sget(C, 2, i)}, Cj{sget(C, 0, j), sget(C, 1, j), sget(C, 2, j)};
        pa.f = pa.f + (cwi * bi + cwj * bj) + (cvi * Ci + cvj * Cj);
        // R B Rᵀ with B = e_i biᵀ + e_j bjᵀ: ri (R bi)ᵀ + rj (R bj)ᵀ
        translate_add(P, X.t, rotate2(ri, rj, aii, aij, ajj), outer2(ri, X.R * bi, rj, X.R * bj), rotate(X.R, C));
    } else {
        const double wi = get(W.f, i), wj = get(W.f, j), ui = get(U.f, i), uj = get(U.f, j);
        const double cii = sget(I.C, i, i) - wi * ui, cij = sget(I.C, i, j) - wi * uj, cjj = sget(I.C, j, j) - wj * uj;
        const vec3 bi = col(I.B, i) - ui * W.n, bj = col(I.B, j) - uj * W.n;   // columns i, j of B
        const sym3 A{I.A.xx - W.n.x * U.n.x, I.A.xy - W.n.x * U.n.y, I.A.yy - W.n.y * U.n.y,
                     I.A.xz - W.n.x * U.n.z, I.A.yz - W.n.y * U.n.z, I.A.zz - W.n.z * U.n.z};
        // I^a c (cω = 0): n = B cv, f = C cv (rows i, j)
        const double cvi = get(c.v, i), cvj = get(c.v, j);
        pa.n = pa.n + (cvi * bi + cvj * bj);
        add_at(pa.f, i, cii * cvi + cij * cvj);
        add_at(pa.f, j, cij * cvi + cjj * cvj);
        // R B Rᵀ with B = bi e_iᵀ + bj e_jᵀ: (R bi) riᵀ + (R bj) rjᵀ
        translate_add(P, X.t, rotate(X.R, A), outer2(X.R * bi, ri, X.R * bj, rj), rotate2(ri, rj, cii, cij, cjj));
    }
    add_to(pP, act_force(X, pa));
}

// The body's placement in its parent for the joint coordinates q (q points at the body's first).
template <joint_kind K>
SPATIAL_CHAINS_INLINE se3 placement(const body& b, const body_cache& c, const double* q) {
    const mat3& R = b.R;
    if constexpr (K == joint_kind::revolute_x || K == joint_kind::revolute_y || K == joint_kind::revolute_z) {
        const double s = std::sin(q[0]), co = std::cos(q[0]);
        auto row = [&](vec3 r) -> vec3 {
            if constexpr (K == joint_kind::revolute_x) return {r.x, co * r.y + s * r.z, co * r.z - s * r.y};
            else if constexpr (K == joint_kind::revolute_y) return {co * r.x - s * r.z, r.y, s * r.x + co * r.z};
            else return {co * r.x + s * r.y, co * r.y - s * r.x, r.z};
        };
        return {{row(R.r0), row(R.r1), row(R.r2)}, b.t};
    } else if constexpr (K == joint_kind::revolute_axis) {
        const double s = std::sin(q[0]), v = 1 - std::cos(q[0]);
        return {{R.r0 + s * c.P1.r0 + v * c.P2.r0, R.r1 + s * c.P1.r1 + v * c.P2.r1, R.r2 + s * c.P1.r2 + v * c.P2.r2},
                b.t};
    } else if constexpr (K == joint_kind::prismatic_x || K == joint_kind::prismatic_y || K == joint_kind::prismatic_z ||
                         K == joint_kind::prismatic_axis) {
        return {R, b.t + q[0] * c.Ru};
    } else if constexpr (K == joint_kind::fixed) {
        return {R, b.t};
    } else {   // floating
        const double w = q[3], x = q[4], y = q[5], z = q[6];
        const double x2 = 2 * x, y2 = 2 * y, z2 = 2 * z;
        const double xx = x * x2, yy = y * y2, zz = z * z2, xy = x * y2, xz = x * z2, yz = y * z2;
        const double wx = w * x2, wy = w * y2, wz = w * z2;
        const mat3 RJ{{1 - (yy + zz), xy - wz, xz + wy}, {xy + wz, 1 - (xx + zz), yz - wx}, {xz - wy, yz + wx, 1 - (xx + yy)}};
        return {mul(R, RJ), R * vec3{q[0], q[1], q[2]} + b.t};
    }
}

// The one-dof joints' motion subspace s (6 × 1), by component.
template <joint_kind K>
struct one_dof {
    // S x
    SPATIAL_CHAINS_INLINE static motion S(const body_cache& c, const body& b, double x) {
        (void)c;
        if constexpr (K == joint_kind::revolute_x) return {{x, 0, 0}, {0, 0, 0}};
        else if constexpr (K == joint_kind::revolute_y) return {{0, x, 0}, {0, 0, 0}};
        else if constexpr (K == joint_kind::revolute_z) return {{0, 0, x}, {0, 0, 0}};
        else if constexpr (K == joint_kind::prismatic_x) return {{0, 0, 0}, {x, 0, 0}};
        else if constexpr (K == joint_kind::prismatic_y) return {{0, 0, 0}, {0, x, 0}};
        else if constexpr (K == joint_kind::prismatic_z) return {{0, 0, 0}, {0, 0, x}};
        else if constexpr (K == joint_kind::revolute_axis) return {x * b.axis, {0, 0, 0}};
        else return {{0, 0, 0}, x * b.axis};
    }
    // m += S x
    SPATIAL_CHAINS_INLINE static void add_S(motion& m, const body& b, double x) {
        if constexpr (K == joint_kind::revolute_x) m.w.x += x;
        else if constexpr (K == joint_kind::revolute_y) m.w.y += x;
        else if constexpr (K == joint_kind::revolute_z) m.w.z += x;
        else if constexpr (K == joint_kind::prismatic_x) m.v.x += x;
        else if constexpr (K == joint_kind::prismatic_y) m.v.y += x;
        else if constexpr (K == joint_kind::prismatic_z) m.v.z += x;
        else if constexpr (K == joint_kind::revolute_axis) add_to(m.w, x * b.axis);
        else add_to(m.v, x * b.axis);
    }
    // Sᵀ f
    SPATIAL_CHAINS_INLINE static double St(const body& b, const force& f) {
        if constexpr (K == joint_kind::revolute_x) return f.n.x;
        else if constexpr (K == joint_kind::revolute_y) return f.n.y;
        else if constexpr (K == joint_kind::revolute_z) return f.n.z;
        else if constexpr (K == joint_kind::prismatic_x) return f.f.x;
        else if constexpr (K == joint_kind::prismatic_y) return f.f.y;
        else if constexpr (K == joint_kind::prismatic_z) return f.f.z;
        else if constexpr (K == joint_kind::revolute_axis) return dot(b.axis, f.n);
        else return dot(b.axis, f.f);
    }
    // v × (S x)  (c_i = v_i × v_J, Featherstone's velocity-product acceleration; c_J = 0)
    SPATIAL_CHAINS_INLINE static motion cross_S(const motion& v, const body& b, double x) {
        if constexpr (K == joint_kind::revolute_x) return {{0, x * v.w.z, -x * v.w.y}, {0, x * v.v.z, -x * v.v.y}};
        else if constexpr (K == joint_kind::revolute_y) return {{-x * v.w.z, 0, x * v.w.x}, {-x * v.v.z, 0, x * v.v.x}};
        else if constexpr (K == joint_kind::revolute_z) return {{x * v.w.y, -x * v.w.x, 0}, {x * v.v.y, -x * v.v.x, 0}};
        else if constexpr (K == joint_kind::prismatic_x) return {{0, 0, 0}, {0, x * v.w.z, -x * v.w.y}};
        else if constexpr (K == joint_kind::prismatic_y) return {{0, 0, 0}, {-x * v.w.z, 0, x * v.w.x}};
        else if constexpr (K == joint_kind::prismatic_z) return {{0, 0, 0}, {x * v.w.y, -x * v.w.x, 0}};
        else if constexpr (K == joint_kind::revolute_axis) {
            const vec3 u = x * b.axis;
            return {cross(v.w, u), cross(v.v, u)};
        } else {
            return {{0, 0, 0}, cross(v.w, x * b.axis)};
        }
    }
    // U = I S for an articulated inertia (a column of the 6×6 matrix)
    SPATIAL_CHAINS_INLINE static force column(const abi& I, const body& b) {
        if constexpr (K == joint_kind::revolute_x) return {{I.A.xx, I.A.xy, I.A.xz}, I.B.r0};
        else if constexpr (K == joint_kind::revolute_y) return {{I.A.xy, I.A.yy, I.A.yz}, I.B.r1};
        else if constexpr (K == joint_kind::revolute_z) return {{I.A.xz, I.A.yz, I.A.zz}, I.B.r2};
        else if constexpr (K == joint_kind::prismatic_x) return {col(I.B, 0), {I.C.xx, I.C.xy, I.C.xz}};
        else if constexpr (K == joint_kind::prismatic_y) return {col(I.B, 1), {I.C.xy, I.C.yy, I.C.yz}};
        else if constexpr (K == joint_kind::prismatic_z) return {col(I.B, 2), {I.C.xz, I.C.yz, I.C.zz}};
        else if constexpr (K == joint_kind::revolute_axis) return {I.A * b.axis, tmul(I.B, b.axis)};
        else return {I.B * b.axis, I.C * b.axis};
    }
    // F = Y S for a rigid inertia about the origin
    SPATIAL_CHAINS_INLINE static force column(const rigid& Y, const body& b) {
        const sym3& I = Y.I;
        const vec3 h = Y.h;
        if constexpr (K == joint_kind::revolute_x) return {{I.xx, I.xy, I.xz}, {0, -h.z, h.y}};
        else if constexpr (K == joint_kind::revolute_y) return {{I.xy, I.yy, I.yz}, {h.z, 0, -h.x}};
        else if constexpr (K == joint_kind::revolute_z) return {{I.xz, I.yz, I.zz}, {-h.y, h.x, 0}};
        else if constexpr (K == joint_kind::prismatic_x) return {{0, h.z, -h.y}, {Y.m, 0, 0}};
        else if constexpr (K == joint_kind::prismatic_y) return {{-h.z, 0, h.x}, {0, Y.m, 0}};
        else if constexpr (K == joint_kind::prismatic_z) return {{h.y, -h.x, 0}, {0, 0, Y.m}};
        else if constexpr (K == joint_kind::revolute_axis) return {I * b.axis, cross(b.axis, h)};
        else return {cross(h, b.axis), Y.m * b.axis};
    }
};

SPATIAL_CHAINS_INLINE double St6(const force& f, int k) {
    return k == 0 ? f.n.x : k == 1 ? f.n.y : k == 2 ? f.n.z : k == 3 ? f.f.x : k == 4 ? f.f.y : f.f.z;
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// finalize: coordinates' offsets, nq, nv, the inertias about the body origins, the joints' constants.

template <std::size_t N>
void finalize(model<N>& m) {
    std::size_t iq = 0, iv = 0;
    for (std::size_t i = 0; i < m.n; ++i) {
        const body& b = m.bodies[i];
        body_cache& c = m.cache[i];
        c.iq = static_cast<int>(iq);
        c.iv = static_cast<int>(iv);
        iq += static_cast<std::size_t>(joint_nq(b.kind));
        iv += static_cast<std::size_t>(joint_nv(b.kind));
        c.Y = detail::about_origin(b.I);
        vec3 u = b.axis;
        switch (b.kind) {
        case joint_kind::revolute_x:
        case joint_kind::prismatic_x: u = {1, 0, 0}; break;
        case joint_kind::revolute_y:
        case joint_kind::prismatic_y: u = {0, 1, 0}; break;
        case joint_kind::revolute_z:
        case joint_kind::prismatic_z: u = {0, 0, 1}; break;
        default: break;
        }
        const mat3 U = detail::skew(u);
        c.P1 = detail::mul(b.R, U);
        c.P2 = detail::mul(c.P1, U);
        c.Ru = b.R * u;
    }
    m.nq = iq;
    m.nv = iv;
}

// ---------------------------------------------------------------------------------------------
// Forward kinematics.

template <std::size_t N>
struct kinematics {
    std::array<se3, N> pose;       // world pose: x_world = R x_body + t
    std::array<motion, N> v;       // body velocity, body frame
    std::array<motion, N> a;       // body spatial acceleration (no gravity), body frame
};

// World poses only.
template <std::size_t N>
void fk(const model<N>& m, const double* q, std::array<se3, N>& pose) {
    for (std::size_t i = 0; i < m.n; ++i) {
        const body& b = m.bodies[i];
        const body_cache& c = m.cache[i];
        detail::dispatch(b.kind, [&](auto kind) {
            constexpr joint_kind K = decltype(kind)::value;
            const se3 X = detail::placement<K>(b, c, q + c.iq);
            pose[i] = b.parent < 0 ? X : detail::compose(pose[static_cast<std::size_t>(b.parent)], X);
        });
    }
}

template <std::size_t N>
void fk(const model<N>& m, const double* q, const double* qd, const double* qdd, kinematics<N>& out) {
    for (std::size_t i = 0; i < m.n; ++i) {
        const body& b = m.bodies[i];
        const body_cache& c = m.cache[i];
        detail::dispatch(b.kind, [&](auto kind) {
            constexpr joint_kind K = decltype(kind)::value;
            const se3 X = detail::placement<K>(b, c, q + c.iq);
            motion v, a;
            if (b.parent < 0) {
                out.pose[i] = X;
                v = {{0, 0, 0}, {0, 0, 0}};
                a = v;
            } else {
                const auto p = static_cast<std::size_t>(b.parent);
                out.pose[i] = detail::compose(out.pose[p], X);
                v = detail::inv_act(X, out.v[p]);
                a = detail::inv_act(X, out.a[p]);
            }
            if constexpr (detail::is_one_dof<K>) {
                using J = detail::one_dof<K>;
                const double x = qd[c.iv];
                J::add_S(v, b, x);
                a = a + J::cross_S(v, b, x);
                J::add_S(a, b, qdd[c.iv]);
            } else if constexpr (K == joint_kind::floating) {
                const motion vJ{{qd[c.iv], qd[c.iv + 1], qd[c.iv + 2]}, {qd[c.iv + 3], qd[c.iv + 4], qd[c.iv + 5]}};
                v = v + vJ;
                a = a + detail::crm(v, vJ);
                a = a + motion{{qdd[c.iv], qdd[c.iv + 1], qdd[c.iv + 2]}, {qdd[c.iv + 3], qdd[c.iv + 4], qdd[c.iv + 5]}};
            }
            out.v[i] = v;
            out.a[i] = a;
        });
    }
}

// ---------------------------------------------------------------------------------------------
// The geometric Jacobian of a frame F fixed to body b (placement F in b), as Pinocchio's
// computeFrameJacobian: the world poses, then for each joint on the path to the root its motion
// subspace moved out, taken about the frame's origin p in world axes (local_world_aligned:
// ω = R_j u, v = (t_j − p) × ω for a revolute joint, (0, R_j u) for a prismatic one) and, for
// local, rotated into the frame's axes (R_Fᵀ). J is 6 × nv, column-major (column k at J + 6k).

template <std::size_t N>
void frame_jacobian(const model<N>& m, const double* q, std::size_t b, const se3& F, bool local, double* J) {
    std::array<se3, N> pose;
    fk(m, q, pose);
    const se3 W = detail::compose(pose[b], F);
    for (std::size_t k = 0; k < 6 * m.nv; ++k) J[k] = 0;
    const auto put = [&](std::size_t col, vec3 w, vec3 v) {
        if (local) w = detail::tmul(W.R, w), v = detail::tmul(W.R, v);
        double* c = J + 6 * col;
        c[0] = w.x, c[1] = w.y, c[2] = w.z, c[3] = v.x, c[4] = v.y, c[5] = v.z;
    };
    for (int i = static_cast<int>(b); i >= 0; i = m.bodies[static_cast<std::size_t>(i)].parent) {
        const auto u = static_cast<std::size_t>(i);
        const body& bd = m.bodies[u];
        const se3& X = pose[u];
        const vec3 r = X.t - W.t;
        const std::size_t iv = static_cast<std::size_t>(m.cache[u].iv);
        detail::dispatch(bd.kind, [&](auto kind) {
            constexpr joint_kind K = decltype(kind)::value;
            if constexpr (K == joint_kind::revolute_x || K == joint_kind::revolute_y || K == joint_kind::revolute_z) {
                const vec3 w = detail::col(X.R, detail::axis_index<K>);
                put(iv, w, cross(r, w));
            } else if constexpr (K == joint_kind::revolute_axis) {
                const vec3 w = X.R * bd.axis;
                put(iv, w, cross(r, w));
            } else if constexpr (K == joint_kind::prismatic_x || K == joint_kind::prismatic_y || K == joint_kind::prismatic_z) {
                put(iv, {0, 0, 0}, detail::col(X.R, detail::axis_index<K>));
            } else if constexpr (K == joint_kind::prismatic_axis) {
                put(iv, {0, 0, 0}, X.R * bd.axis);
            } else if constexpr (K == joint_kind::floating) {
                for (int a = 0; a < 3; ++a) {
                    const vec3 w = detail::col(X.R, a);
                    put(iv + static_cast<std::size_t>(a), w, cross(r, w));
                    put(iv + 3 + static_cast<std::size_t>(a), {0, 0, 0}, w);
                }
            }
        });
    }
}

// ---------------------------------------------------------------------------------------------
// Inverse dynamics: RNEA (Featherstone Table 5.1).

template <std::size_t N>
void rnea(const model<N>& m, const double* q, const double* qd, const double* qdd, const force* f_ext, double* tau) {
    std::array<se3, N> X;
    std::array<motion, N> v, a;
    std::array<force, N> f;
    const vec3 ng = -m.gravity;
    for (std::size_t i = 0; i < m.n; ++i) {
        const body& b = m.bodies[i];
        const body_cache& c = m.cache[i];
        detail::dispatch(b.kind, [&](auto kind) {
            constexpr joint_kind K = decltype(kind)::value;
            X[i] = detail::placement<K>(b, c, q + c.iq);
            motion vi, ai;
            if (b.parent < 0) {
                vi = {{0, 0, 0}, {0, 0, 0}};
                ai = detail::inv_act_linear(X[i], ng);
            } else {
                const auto p = static_cast<std::size_t>(b.parent);
                vi = detail::inv_act(X[i], v[p]);
                ai = detail::inv_act(X[i], a[p]);
            }
            if constexpr (detail::is_one_dof<K>) {
                using J = detail::one_dof<K>;
                const double x = qd[c.iv];
                J::add_S(vi, b, x);
                ai = ai + J::cross_S(vi, b, x);
                J::add_S(ai, b, qdd[c.iv]);
            } else if constexpr (K == joint_kind::floating) {
                const motion vJ{{qd[c.iv], qd[c.iv + 1], qd[c.iv + 2]}, {qd[c.iv + 3], qd[c.iv + 4], qd[c.iv + 5]}};
                vi = vi + vJ;
                ai = ai + detail::crm(vi, vJ);
                ai = ai + motion{{qdd[c.iv], qdd[c.iv + 1], qdd[c.iv + 2]}, {qdd[c.iv + 3], qdd[c.iv + 4], qdd[c.iv + 5]}};
            }
            v[i] = vi;
            a[i] = ai;
            const force h = c.Y * vi;
            const force fa = c.Y * ai;
            const force fv = detail::crf(vi, h);
            force fi{fa.n + fv.n, fa.f + fv.f};
            if (f_ext) detail::sub_to(fi, f_ext[i]);
            f[i] = fi;
        });
    }
    for (std::size_t i = m.n; i-- > 0;) {
        const body& b = m.bodies[i];
        const body_cache& c = m.cache[i];
        detail::dispatch(b.kind, [&](auto kind) {
            constexpr joint_kind K = decltype(kind)::value;
            if constexpr (detail::is_one_dof<K>) {
                tau[c.iv] = detail::one_dof<K>::St(b, f[i]);
            } else if constexpr (K == joint_kind::floating) {
                double* t = tau + c.iv;
                t[0] = f[i].n.x; t[1] = f[i].n.y; t[2] = f[i].n.z;
                t[3] = f[i].f.x; t[4] = f[i].f.y; t[5] = f[i].f.z;
            }
        });
        if (b.parent >= 0) detail::add_to(f[static_cast<std::size_t>(b.parent)], detail::act_force(X[i], f[i]));
    }
}

// ---------------------------------------------------------------------------------------------
// The joint-space inertia matrix: CRBA (Featherstone Table 6.2). H: nv × nv, row-major, both
// triangles filled.

template <std::size_t N>
void crba(const model<N>& m, const double* q, double* H) {
    std::array<se3, N> X;
    std::array<rigid, N> Ic;
    const std::size_t nv = m.nv;
    for (std::size_t k = 0; k < nv * nv; ++k) H[k] = 0;
    for (std::size_t i = 0; i < m.n; ++i) {
        const body& b = m.bodies[i];
        const body_cache& c = m.cache[i];
        detail::dispatch(b.kind, [&](auto kind) {
            constexpr joint_kind K = decltype(kind)::value;
            X[i] = detail::placement<K>(b, c, q + c.iq);
        });
        Ic[i] = c.Y;
    }
    for (std::size_t i = m.n; i-- > 0;) {
        const body& b = m.bodies[i];
        const body_cache& c = m.cache[i];
        // Ic_i is complete (its children come after it)
        detail::dispatch(b.kind, [&](auto kind) {
            constexpr joint_kind K = decltype(kind)::value;
            if constexpr (detail::is_one_dof<K>) {
                using J = detail::one_dof<K>;
                const std::size_t vi = static_cast<std::size_t>(c.iv);
                force F = J::column(Ic[i], b);
                H[vi * nv + vi] = J::St(b, F);
                std::size_t j = i;
                while (m.bodies[j].parent >= 0) {
                    F = detail::act_force(X[j], F);
                    j = static_cast<std::size_t>(m.bodies[j].parent);
                    const body& bj = m.bodies[j];
                    const std::size_t vj = static_cast<std::size_t>(m.cache[j].iv);
                    detail::dispatch(bj.kind, [&](auto kind_j) {
                        constexpr joint_kind Kj = decltype(kind_j)::value;
                        if constexpr (detail::is_one_dof<Kj>) {
                            const double x = detail::one_dof<Kj>::St(bj, F);
                            H[vi * nv + vj] = x;
                            H[vj * nv + vi] = x;
                        } else if constexpr (Kj == joint_kind::floating) {
                            for (std::size_t k = 0; k < 6; ++k) {
                                const double x = detail::St6(F, static_cast<int>(k));
                                H[vi * nv + vj + k] = x;
                                H[(vj + k) * nv + vi] = x;
                            }
                        }
                    });
                }
            } else if constexpr (K == joint_kind::floating) {
                const std::size_t vi = static_cast<std::size_t>(c.iv);
                const rigid& Y = Ic[i];
                // the six columns of Y: ω = e_k, then v = e_k
                // (f = −h × ω for ω = e_k; n = h × v for v = e_k)
                force F[6] = {{{Y.I.xx, Y.I.xy, Y.I.xz}, {0, -Y.h.z, Y.h.y}}, {{Y.I.xy, Y.I.yy, Y.I.yz}, {Y.h.z, 0, -Y.h.x}},
                              {{Y.I.xz, Y.I.yz, Y.I.zz}, {-Y.h.y, Y.h.x, 0}},   {{0, Y.h.z, -Y.h.y}, {Y.m, 0, 0}},
                              {{-Y.h.z, 0, Y.h.x}, {0, Y.m, 0}},                {{Y.h.y, -Y.h.x, 0}, {0, 0, Y.m}}};
                for (std::size_t k = 0; k < 6; ++k)
                    for (std::size_t l = 0; l < 6; ++l) H[(vi + k) * nv + vi + l] = detail::St6(F[k], static_cast<int>(l));
                std::size_t j = i;
                while (m.bodies[j].parent >= 0) {
                    for (force& Fk : F) Fk = detail::act_force(X[j], Fk);
                    j = static_cast<std::size_t>(m.bodies[j].parent);
                    const body& bj = m.bodies[j];
                    const std::size_t vj = static_cast<std::size_t>(m.cache[j].iv);
                    detail::dispatch(bj.kind, [&](auto kind_j) {
                        constexpr joint_kind Kj = decltype(kind_j)::value;
                        if constexpr (detail::is_one_dof<Kj>) {
                            for (std::size_t k = 0; k < 6; ++k) {
                                const double x = detail::one_dof<Kj>::St(bj, F[k]);
                                H[(vi + k) * nv + vj] = x;
                                H[vj * nv + vi + k] = x;
                            }
                        } else if constexpr (Kj == joint_kind::floating) {
                            for (std::size_t k = 0; k < 6; ++k)
                                for (std::size_t l = 0; l < 6; ++l) {
                                    const double x = detail::St6(F[k], static_cast<int>(l));
                                    H[(vi + k) * nv + vj + l] = x;
                                    H[(vj + l) * nv + vi + k] = x;
                                }
                        }
                    });
                }
            }
        });
        if (b.parent >= 0) detail::add_transformed(Ic[static_cast<std::size_t>(b.parent)], X[i], Ic[i]);
    }
}

// ---------------------------------------------------------------------------------------------
// Forward dynamics: the articulated-body algorithm (Featherstone Table 7.1).

template <std::size_t N>
void aba(const model<N>& m, const double* q, const double* qd, const double* tau, const force* f_ext, double* qdd) {
    std::array<se3, N> X;
    std::array<motion, N> v, c, a;
    std::array<detail::abi, N> IA;
    std::array<force, N> pA;
    std::array<force, N> U;           // one-dof: U_i = I^A_i S_i
    std::array<double, N> Dinv, u;    // one-dof: 1 / D_i, u_i = τ_i − S_iᵀ p^A_i
    // (floating: a[i] holds the body's acceleration (I^A)⁻¹ (τ − p^A) from pass 2)

    // pass 1 (outwards): placements, velocities, velocity products, isolated-body quantities
    for (std::size_t i = 0; i < m.n; ++i) {
        const body& b = m.bodies[i];
        const body_cache& cc = m.cache[i];
        detail::dispatch(b.kind, [&](auto kind) {
            constexpr joint_kind K = decltype(kind)::value;
            X[i] = detail::placement<K>(b, cc, q + cc.iq);
            motion vi;
            if (b.parent < 0) vi = {{0, 0, 0}, {0, 0, 0}};
            else vi = detail::inv_act(X[i], v[static_cast<std::size_t>(b.parent)]);
            if constexpr (detail::is_one_dof<K>) {
                using J = detail::one_dof<K>;
                const double x = qd[cc.iv];
                J::add_S(vi, b, x);
                c[i] = J::cross_S(vi, b, x);
            } else if constexpr (K == joint_kind::floating) {
                const motion vJ{{qd[cc.iv], qd[cc.iv + 1], qd[cc.iv + 2]}, {qd[cc.iv + 3], qd[cc.iv + 4], qd[cc.iv + 5]}};
                vi = vi + vJ;
                c[i] = detail::crm(vi, vJ);
            } else {
                c[i] = {{0, 0, 0}, {0, 0, 0}};
            }
            v[i] = vi;
            force p = detail::crf(vi, cc.Y * vi);
            if (f_ext) detail::sub_to(p, f_ext[i]);
            pA[i] = p;
            IA[i] = detail::to_abi(cc.Y);
        });
    }
    // pass 2 (inwards): articulated inertias and bias forces
    for (std::size_t i = m.n; i-- > 0;) {
        const body& b = m.bodies[i];
        const body_cache& cc = m.cache[i];
        const bool has_parent = b.parent >= 0;
        const auto p = static_cast<std::size_t>(has_parent ? b.parent : 0);
        detail::dispatch(b.kind, [&](auto kind) {
            constexpr joint_kind K = decltype(kind)::value;
            if constexpr (detail::is_one_dof<K>) {
                using J = detail::one_dof<K>;
                detail::abi& Ia = IA[i];
                const force Ui = J::column(Ia, b);
                const double dinv = 1.0 / J::St(b, Ui);
                const double ui = tau[cc.iv] - J::St(b, pA[i]);
                U[i] = Ui;
                Dinv[i] = dinv;
                u[i] = ui;
                if constexpr (detail::is_coordinate_axis<K>) {
                    if (has_parent) detail::aba_project_add<K>(IA[p], pA[p], X[i], Ia, Ui, dinv, ui, c[i], pA[i]);
                } else if (has_parent) {
                    // I^a = I^A − U D⁻¹ Uᵀ, p^a = p^A + I^a c + U D⁻¹ u
                    const force W{dinv * Ui.n, dinv * Ui.f};
                    detail::rank1_sub(Ia, Ui, W);
                    const force Ic = Ia * c[i];
                    const force pa{pA[i].n + Ic.n + ui * W.n, pA[i].f + Ic.f + ui * W.f};
                    detail::add_transformed(IA[p], X[i], Ia);
                    detail::add_to(pA[p], detail::act_force(X[i], pa));
                }
            } else if constexpr (K == joint_kind::floating) {
                // D = U = I^A: I^a = 0, p^a = τ; the body's acceleration (I^A)⁻¹ (τ − p^A) does not
                // depend on the parent's
                const double* t = tau + cc.iv;
                const force r{{t[0] - pA[i].n.x, t[1] - pA[i].n.y, t[2] - pA[i].n.z},
                              {t[3] - pA[i].f.x, t[4] - pA[i].f.y, t[5] - pA[i].f.z}};
                a[i] = detail::solve6(IA[i], r);
                if (has_parent) detail::add_to(pA[p], detail::act_force(X[i], force{{t[0], t[1], t[2]}, {t[3], t[4], t[5]}}));
            } else {   // fixed: I^a = I^A, p^a = p^A (c = 0)
                if (has_parent) {
                    detail::add_transformed(IA[p], X[i], IA[i]);
                    detail::add_to(pA[p], detail::act_force(X[i], pA[i]));
                }
            }
        });
    }
    // pass 3 (outwards): accelerations
    const vec3 ng = -m.gravity;
    for (std::size_t i = 0; i < m.n; ++i) {
        const body& b = m.bodies[i];
        const body_cache& cc = m.cache[i];
        detail::dispatch(b.kind, [&](auto kind) {
            constexpr joint_kind K = decltype(kind)::value;
            motion ai = b.parent < 0 ? detail::inv_act_linear(X[i], ng)
                                     : detail::inv_act(X[i], a[static_cast<std::size_t>(b.parent)]);
            if constexpr (detail::is_one_dof<K>) {
                ai = ai + c[i];
                const double x = Dinv[i] * (u[i] - (dot(U[i].n, ai.w) + dot(U[i].f, ai.v)));
                qdd[cc.iv] = x;
                detail::one_dof<K>::add_S(ai, b, x);
                a[i] = ai;
            } else if constexpr (K == joint_kind::floating) {
                ai = ai + c[i];
                double* x = qdd + cc.iv;
                const motion& ab = a[i];
                x[0] = ab.w.x - ai.w.x; x[1] = ab.w.y - ai.w.y; x[2] = ab.w.z - ai.w.z;
                x[3] = ab.v.x - ai.v.x; x[4] = ab.v.y - ai.v.y; x[5] = ab.v.z - ai.v.z;
            } else {
                a[i] = ai;
            }
        });
    }
}

}  // namespace spatial::chains
