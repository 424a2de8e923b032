// Hand-written 6D spatial algebra in the style of Featherstone (Rigid Body Dynamics Algorithms,
// 2008) and Pinocchio (include/pinocchio/spatial/): what a user would write without ctga.
// Motions (ω, v), forces (n, f), a rigid inertia as (m, c, I_c) with I_c symmetric about the
// centre of mass, a rigid motion as (R, t), and unit dual quaternions for motor products.
// Plain structs and cross-product formulas; the benchmarks' "spatial" implementation.
#pragma once

#include <array>

namespace spatial {

struct vec3 {
    double x, y, z;
};
inline vec3 operator+(vec3 a, vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline vec3 operator-(vec3 a, vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline vec3 operator*(double s, vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline vec3 cross(vec3 a, vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// Symmetric 3×3: xx, xy, yy, xz, yz, zz (Pinocchio's Symmetric3 order).
struct sym3 {
    double xx, xy, yy, xz, yz, zz;
};
inline vec3 operator*(const sym3& S, vec3 v) {
    return {S.xx * v.x + S.xy * v.y + S.xz * v.z, S.xy * v.x + S.yy * v.y + S.yz * v.z,
            S.xz * v.x + S.yz * v.y + S.zz * v.z};
}

struct mat3 {
    vec3 r0, r1, r2;  // rows
};
inline vec3 operator*(const mat3& R, vec3 v) { return {dot(R.r0, v), dot(R.r1, v), dot(R.r2, v)}; }

struct motion {
    vec3 w, v;
};
struct force {
    vec3 n, f;
};
struct inertia {
    double m;
    vec3 c;
    sym3 I;  // about the centre of mass
};
struct se3 {
    mat3 R;
    vec3 t;
};

// inertia × motion: f = m (v − c × ω), n = I_c ω + c × f (Pinocchio Inertia::__mult__)
inline force operator*(const inertia& Y, const motion& s) {
    const vec3 f = Y.m * (s.v - cross(Y.c, s.w));
    return {Y.I * s.w + cross(Y.c, f), f};
}
inline double kinetic_energy(const inertia& Y, const motion& s) {
    const force h = Y * s;
    return 0.5 * (dot(s.w, h.n) + dot(s.v, h.f));
}
// motion × motion (the Lie bracket): (ω1 × ω2, ω1 × v2 + v1 × ω2)
inline motion cross(const motion& a, const motion& b) { return {cross(a.w, b.w), cross(a.w, b.v) + cross(a.v, b.w)}; }
// motion ×* force (the coadjoint action): (ω × n + v × f, ω × f)
inline force cross(const motion& a, const force& b) { return {cross(a.w, b.n) + cross(a.v, b.f), cross(a.w, b.f)}; }

// SE3 acting on motions and forces (Pinocchio SE3::act): 24m 18a each.
inline motion act(const se3& X, const motion& s) {
    const vec3 w = X.R * s.w;
    return {w, X.R * s.v + cross(X.t, w)};
}
inline force act(const se3& X, const force& F) {
    const vec3 f = X.R * F.f;
    return {X.R * F.n + cross(X.t, f), f};
}
// SE3 acting on an inertia: c' = R c + t, I' = R I Rᵀ (symmetric: the upper triangle).
inline inertia act(const se3& X, const inertia& Y) {
    const mat3& R = X.R;
    // rows of R I (I symmetric)
    const vec3 a0 = Y.I * R.r0, a1 = Y.I * R.r1, a2 = Y.I * R.r2;
    return {Y.m, R * Y.c + X.t, {dot(a0, R.r0), dot(a0, R.r1), dot(a1, R.r1), dot(a0, R.r2), dot(a1, R.r2), dot(a2, R.r2)}};
}

// The acceleration of a free body: Y ṡ = F − s ×* (Y s), solved with the inverse rotational
// inertia J = I_c⁻¹ precomputed: ω̇ = J (n − c × f), v̇ = f/m + c × ω̇ (Featherstone §2.13).
struct inverse_inertia {
    double inv_m;
    vec3 c;
    sym3 J;
};
inline motion solve(const inverse_inertia& Z, const force& F) {
    const vec3 wd = Z.J * (F.n - cross(Z.c, F.f));
    return {wd, Z.inv_m * F.f + cross(Z.c, wd)};
}
inline motion acceleration(const inertia& Y, const inverse_inertia& Z, const motion& s, const force& F) {
    const force h = Y * s;
    const force c = cross(s, h);
    return solve(Z, {F.n - c.n, F.f - c.f});
}

// Unit dual quaternions q = r + ε d (r = (w, x, y, z)): the motor product, 48m 40a.
struct dual_quaternion {
    double r[4], d[4];
};
inline void quat_mul(const double* a, const double* b, double* out) {
    out[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    out[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    out[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    out[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}
// a ⊗ (0, v): a quaternion times a pure one, 12m 8a
inline void quat_mul_pure(const double* a, vec3 v, double* out) {
    out[0] = -a[1] * v.x - a[2] * v.y - a[3] * v.z;
    out[1] = a[0] * v.x + a[2] * v.z - a[3] * v.y;
    out[2] = a[0] * v.y - a[1] * v.z + a[3] * v.x;
    out[3] = a[0] * v.z + a[1] * v.y - a[2] * v.x;
}
inline dual_quaternion operator*(const dual_quaternion& a, const dual_quaternion& b) {
    dual_quaternion out;
    double u[4], v[4];
    quat_mul(a.r, b.r, out.r);
    quat_mul(a.r, b.d, u);
    quat_mul(a.d, b.r, v);
    for (int i = 0; i < 4; ++i) out.d[i] = u[i] + v[i];
    return out;
}

// dg/dt = ½ g s for a body-frame velocity s = ω + ε v (pure dual quaternion): 36m 28a + 8m
inline dual_quaternion pose_rate(const dual_quaternion& g, const motion& s) {
    dual_quaternion out;
    double u[4], v[4];
    quat_mul_pure(g.r, s.w, out.r);
    quat_mul_pure(g.r, s.v, u);
    quat_mul_pure(g.d, s.w, v);
    for (int i = 0; i < 4; ++i) {
        out.r[i] *= 0.5;
        out.d[i] = 0.5 * (u[i] + v[i]);
    }
    return out;
}

}  // namespace spatial
