// Closed-form reference for the inelastic frictional impact of a planar double pendulum's tip on
// the ground. Independent of the library under test: uses only <array> and <cmath>.
//
// Conventions:
//   * The pendulum moves in the x–y plane, gravity along −y (irrelevant for the impact).
//   * Joint 1 is a hinge about z at the origin, joint 2 a hinge about z at the end of link 1.
//     θ1 is link 1's absolute angle, θ2 is link 2's angle RELATIVE to link 1; the absolute link
//     angles are φ1 = θ1, φ2 = θ1 + θ2, positive counter-clockwise about +z.
//   * Link direction d(φ) = (sin φ, −cos φ), so θ = 0 hangs straight down along −y.
//     Its derivative is d'(φ) = (cos φ, sin φ).
//   * Link 1: length l1, mass m1, centre of mass at c1·d(φ1), inertia I1 about z through its COM.
//     Link 2: pivot at l1·d(φ1), mass m2, COM at l1·d(φ1) + c2·d(φ2), inertia I2 about z through
//     its COM, tip at l1·d(φ1) + l2·d(φ2).
//   * Matrices are row-major std::array<std::array<double,2>,2>.
//   * Contact frame at the tip: row/component 0 is the normal n = +y, row/component 1 the tangent
//     t = +x. So tip velocity u = (u_n, u_t) = (ẏ, ẋ) and impulse P = (P_n, P_t) = (P_y, P_x).
//
// Mass matrix (T = ½ θ̇ᵀ H θ̇):
//   v_c1 = c1 θ̇1 d'(φ1),           ω1 = θ̇1
//   v_c2 = l1 θ̇1 d'(φ1) + c2 (θ̇1+θ̇2) d'(φ2),   ω2 = θ̇1 + θ̇2
//   |v_c2|² = l1² θ̇1² + c2² (θ̇1+θ̇2)² + 2 l1 c2 cos θ2 θ̇1 (θ̇1+θ̇2)   (d'(φ1)·d'(φ2) = cos θ2)
//   T = ½ (m1 c1² + I1) θ̇1² + ½ m2 |v_c2|² + ½ I2 (θ̇1+θ̇2)²
//   ⇒ H11 = I1 + m1 c1² + I2 + m2 (l1² + c2² + 2 l1 c2 cos θ2)
//     H12 = H21 = I2 + m2 (c2² + l1 c2 cos θ2)
//     H22 = I2 + m2 c2²
//   H is symmetric positive definite for m_i > 0, I_i > 0 (T > 0 for θ̇ ≠ 0).
//
// Tip position and Jacobian:
//   x = l1 sin φ1 + l2 sin φ2,   y = −l1 cos φ1 − l2 cos φ2
//   ẏ = (l1 sin φ1 + l2 sin φ2) θ̇1 + l2 sin φ2 θ̇2
//   ẋ = (l1 cos φ1 + l2 cos φ2) θ̇1 + l2 cos φ2 θ̇2
//   J = [[l1 sin φ1 + l2 sin φ2, l2 sin φ2],     (row 0: normal, ẏ)
//        [l1 cos φ1 + l2 cos φ2, l2 cos φ2]]     (row 1: tangent, ẋ)
//   det J = −l1 l2 sin θ2 (singular when the pendulum is stretched or folded, θ2 ∈ {0, π}).
//
// Impact (Newton restitution 0, Coulomb friction μ ≥ 0, Moreau's law at velocity level):
//   generalized impulse Jᵀ P, θ̇⁺ = θ̇⁻ + H⁻¹ Jᵀ P, u⁺ = J θ̇⁺ = W P + u⁻, W = J H⁻¹ Jᵀ,
//   with  P_n ≥ 0, u⁺_n ≥ 0, P_n u⁺_n = 0, and either
//     sticking: u⁺_t = 0, |P_t| ≤ μ P_n,   or
//     sliding:  P_t = −μ P_n sgn(u⁺_t), u⁺_t ≠ 0.
//   Solution for an approaching tip (u⁻_n < 0):
//     1. sticking (μ > 0 and W invertible): P = −W⁻¹ u⁻; accept if P_n ≥ 0 and |P_t| ≤ μ P_n
//        (with a relative tolerance of 1e-12 on the cone, so a state exactly at the stick/slip
//        boundary is reported as sticking);
//     2. sliding, s = +1 then s = −1: P = P_n (1, −s μ); u⁺_n = 0 gives
//          P_n = −u⁻_n / (W_nn − s μ W_nt),
//        u⁺_t = u⁻_t + P_n (W_tn − s μ W_tt); accept if P_n ≥ 0 and sgn(u⁺_t) = s.
//     μ = 0 (frictionless): P = (−u⁻_n / W_nn, 0), sticks = false (whatever u⁺_t is).
//   If u⁻_n ≥ 0 (separating or grazing) the law is satisfied by P = 0: nothing changes,
//   sticks = false. If no case is consistent, every output is NaN (sticks = false).
#pragma once

#include <array>
#include <cmath>

namespace ctga::test {

struct double_pendulum {
    double l1, m1, c1, I1, l2, m2, c2, I2;
};

struct impact_result {
    std::array<double, 2> impulse;             // (P_n, P_t) on the tip, n = +y, t = +x
    std::array<double, 2> velocity_after;      // (θ̇1, θ̇2) just after the impact
    std::array<double, 2> tip_velocity_after;  // (u_n, u_t) = (ẏ, ẋ) of the tip after
    bool sticks;
};

namespace double_pendulum_detail {

using mat2 = std::array<std::array<double, 2>, 2>;
using vec2 = std::array<double, 2>;

inline vec2 mul(const mat2& a, const vec2& v) {
    return {a[0][0] * v[0] + a[0][1] * v[1], a[1][0] * v[0] + a[1][1] * v[1]};
}

inline mat2 mul(const mat2& a, const mat2& b) {
    mat2 r{};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j];
    return r;
}

inline mat2 transpose(const mat2& a) { return {{{a[0][0], a[1][0]}, {a[0][1], a[1][1]}}}; }

inline double det(const mat2& a) { return a[0][0] * a[1][1] - a[0][1] * a[1][0]; }

// Inverse by the adjugate; the caller checks det ≠ 0.
inline mat2 inverse(const mat2& a) {
    const double d = det(a);
    return {{{a[1][1] / d, -a[0][1] / d}, {-a[1][0] / d, a[0][0] / d}}};
}

}  // namespace double_pendulum_detail

// H(θ) with T = ½ θ̇ᵀ H θ̇ (see the derivation above). Depends on θ2 only.
inline std::array<std::array<double, 2>, 2> mass_matrix(const double_pendulum& p, double th1,
                                                        double th2) {
    (void)th1;
    const double c = std::cos(th2);
    const double h22 = p.I2 + p.m2 * p.c2 * p.c2;
    const double h12 = h22 + p.m2 * p.l1 * p.c2 * c;
    const double h11 = p.I1 + p.m1 * p.c1 * p.c1 + p.I2 +
                       p.m2 * (p.l1 * p.l1 + p.c2 * p.c2 + 2.0 * p.l1 * p.c2 * c);
    return {{{h11, h12}, {h12, h22}}};
}

// Tip position (x, y) = l1·d(θ1) + l2·d(θ1+θ2), d(φ) = (sin φ, −cos φ).
inline std::array<double, 2> tip_position(const double_pendulum& p, double th1, double th2) {
    const double f2 = th1 + th2;
    return {p.l1 * std::sin(th1) + p.l2 * std::sin(f2), -p.l1 * std::cos(th1) - p.l2 * std::cos(f2)};
}

// (ẏ, ẋ) = J θ̇: row 0 the normal (y), row 1 the tangent (x).
inline std::array<std::array<double, 2>, 2> tip_jacobian(const double_pendulum& p, double th1,
                                                         double th2) {
    const double f2 = th1 + th2;
    const double s1 = std::sin(th1), c1 = std::cos(th1);
    const double s2 = std::sin(f2), c2 = std::cos(f2);
    return {{{p.l1 * s1 + p.l2 * s2, p.l2 * s2}, {p.l1 * c1 + p.l2 * c2, p.l2 * c2}}};
}

// Inelastic impact of the tip on the plane y = const with normal +y, Coulomb friction μ ≥ 0,
// Moreau's velocity-level law (see the header comment for the case analysis).
inline impact_result impact(const double_pendulum& p, double th1, double th2,
                            std::array<double, 2> thd_before, double mu) {
    using namespace double_pendulum_detail;
    const mat2 H = mass_matrix(p, th1, th2);
    const mat2 J = tip_jacobian(p, th1, th2);
    const mat2 Hinv = inverse(H);
    const mat2 HinvJt = mul(Hinv, transpose(J));  // H⁻¹ Jᵀ
    const mat2 W = mul(J, HinvJt);                 // J H⁻¹ Jᵀ, indices (n, t)
    const vec2 u0 = mul(J, thd_before);            // u⁻ = (u_n, u_t)

    auto finish = [&](const vec2& P, bool sticks) {
        const vec2 dq = mul(HinvJt, P);
        const vec2 qd{thd_before[0] + dq[0], thd_before[1] + dq[1]};
        // u⁺ = J θ̇⁺ (evaluated directly; equals W P + u⁻ up to rounding).
        return impact_result{P, qd, mul(J, qd), sticks};
    };

    // Separating or grazing: P = 0 satisfies the law.
    if (u0[0] >= 0.0) return finish({0.0, 0.0}, false);

    if (mu == 0.0) {
        // Frictionless: u⁺_n = W_nn P_n + u⁻_n = 0.
        const double Pn = -u0[0] / W[0][0];
        if (Pn >= 0.0) return finish({Pn, 0.0}, false);
    } else if (mu > 0.0) {
        // 1. Sticking: u⁺ = 0 ⇒ P = −W⁻¹ u⁻.
        const double dW = det(W);
        const double scale = W[0][0] * W[1][1];
        if (std::abs(dW) > 1e-14 * scale) {
            const mat2 Winv = inverse(W);
            const vec2 Pw = mul(Winv, u0);
            const vec2 P{-Pw[0], -Pw[1]};
            if (P[0] >= 0.0 && std::abs(P[1]) <= mu * P[0] * (1.0 + 1e-12)) return finish(P, true);
        }
        // 2. Sliding with sgn(u⁺_t) = s: P = P_n (1, −s μ), u⁺_n = 0.
        for (const double s : std::array<double, 2>{1.0, -1.0}) {
            const double denom = W[0][0] - s * mu * W[0][1];
            const double Pn = -u0[0] / denom;
            if (!(denom > 0.0) || !(Pn >= 0.0)) continue;
            const double ut = u0[1] + Pn * (W[1][0] - s * mu * W[1][1]);
            if (s * ut > 0.0) return finish({Pn, -s * mu * Pn}, false);
        }
    }

    const double nan = std::nan("");
    return impact_result{{nan, nan}, {nan, nan}, {nan, nan}, false};
}

}  // namespace ctga::test
