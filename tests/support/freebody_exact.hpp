// Exact reference solution of the torque-free rigid body, and independent numerical references.
//
// Conventions (everything below uses them):
//   * body frame = principal axes, principal moments I = (I_0, I_1, I_2): positive, finite, pairwise
//     distinct, in ANY order (internally sorted by a signed permutation of determinant +1);
//   * m = body-frame angular momentum, ω = I⁻¹ m, Euler's equations ṁ = m × ω;
//   * R maps body coordinates to fixed coordinates (x_fixed = R x_body), Ṙ = R ω̂, R(0) = 1, so
//     the fixed-frame momentum R(t) m(t) = m0 is constant;
//   * matrices are row-major std::array<std::array<T,3>,3>, quaternions (w, x, y, z) with w ≥ 0.
// Supported motions: the two regular families G² > 2E·I_mid and G² < 2E·I_mid, and steady rotation
// (m0 along a principal axis, or m0 = 0). The separatrix G² = 2E·I_mid off the middle axis (k = 1)
// is rejected with std::domain_error, as are non-distinct, non-positive or non-finite moments.
// Near the separatrix all elliptic quantities are computed from k'² = 1 − k², which is formed
// without cancellation beyond the distance G² − 2E·I_mid itself (see jacobi_kp).
//
// Sources: Landau & Lifshitz, Mechanics §37 (Jacobi solution
// and the Euler-angle attitude); DLMF 19.25.5/19.25.14 (Legendre integrals as Carlson R_F, R_J);
// DLMF 22.4 (half-period shifts of sn, cn, dn). Signs are not trusted from the sources: the tests
// check everything against an RK4 integration in long double.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

namespace freebody {

template <class T>
using vec3 = std::array<T, 3>;
template <class T>
using mat3 = std::array<std::array<T, 3>, 3>;

// --- small 3-vector / 3×3 helpers ----------------------------------------------------------------
template <class T>
vec3<T> cross(const vec3<T>& a, const vec3<T>& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
T dot(const vec3<T>& a, const vec3<T>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
T norm(const vec3<T>& a) {
    return std::sqrt(dot(a, a));
}
template <class T>
mat3<T> identity() {
    return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
}
template <class T>
mat3<T> transpose(const mat3<T>& a) {
    mat3<T> r{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) r[i][j] = a[j][i];
    return r;
}
template <class T>
mat3<T> mul(const mat3<T>& a, const mat3<T>& b) {
    mat3<T> r{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return r;
}
template <class T>
vec3<T> mul(const mat3<T>& a, const vec3<T>& x) {
    return {dot(a[0], x), dot(a[1], x), dot(a[2], x)};
}
template <class T>
T det(const mat3<T>& a) {
    return dot(a[0], cross(a[1], a[2]));
}
// Rotation angle of a (near-)rotation matrix, = ‖log A‖: atan2(|vee(A − Aᵀ)|/2, (tr A − 1)/2),
// accurate for small and for large angles.
template <class T>
T rotation_angle(const mat3<T>& a) {
    const vec3<T> v{a[2][1] - a[1][2], a[0][2] - a[2][0], a[1][0] - a[0][1]};
    return std::atan2(norm(v) / 2, (a[0][0] + a[1][1] + a[2][2] - 1) / 2);
}
// ‖log(Aᵀ B)‖: the angle of the rotation taking A to B.
template <class T>
T rotation_distance(const mat3<T>& a, const mat3<T>& b) {
    return rotation_angle(mul(transpose(a), b));
}
// Unit quaternion (w, x, y, z), w ≥ 0, of a rotation matrix (Shepperd: divide by the largest of
// 4w², 4x², 4y², 4z²).
template <class T>
std::array<T, 4> quaternion_of(const mat3<T>& r) {
    const T tr = r[0][0] + r[1][1] + r[2][2];
    std::array<T, 4> q{};
    if (tr >= r[0][0] && tr >= r[1][1] && tr >= r[2][2]) {
        const T s = 2 * std::sqrt(1 + tr);  // 4w
        q = {s / 4, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
    } else if (r[0][0] >= r[1][1] && r[0][0] >= r[2][2]) {
        const T s = 2 * std::sqrt(1 + r[0][0] - r[1][1] - r[2][2]);  // 4x
        q = {(r[2][1] - r[1][2]) / s, s / 4, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
    } else if (r[1][1] >= r[2][2]) {
        const T s = 2 * std::sqrt(1 - r[0][0] + r[1][1] - r[2][2]);  // 4y
        q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, s / 4, (r[1][2] + r[2][1]) / s};
    } else {
        const T s = 2 * std::sqrt(1 - r[0][0] - r[1][1] + r[2][2]);  // 4z
        q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, s / 4};
    }
    if (q[0] < 0)
        for (T& c : q) c = -c;
    return q;
}

// --- Jacobi elliptic functions driven by the complementary parameter k'² = 1 − k² ------------------
// Near the separatrix k → 1 everything depends on k' (K ≈ ln(4/k')); a modulus k rounded to T loses
// about eps/k'² of k'² (Boost's ellint_1(k), jacobi_elliptic(k, ·) take k). So K, Π(n) and F are
// evaluated as Carlson integrals of k'² (DLMF 19.25.1, 19.25.2, 19.25.5, 19.25.14), and sn, cn, dn
// by the descending Landen/AGM scheme (A&S 16.4, as in Boost's jacobi_elliptic) started from b0 = k':
//   a_n = (a_{n−1} + b_{n−1})/2, b_n = √(a_{n−1} b_{n−1}), c_n = c_{n−1}²/(4a_n) (= (a_{n−1} − b_{n−1})/2),
//   φ_N = 2^N a_N u, and back down to am u = φ_0 through tan(φ_n − φ_{n−1}) = κ tan φ_{n−1},
//   κ = b_{n−1}/a_{n−1}. A&S's equivalent sin(2φ_{n−1} − φ_n) = (c_n/a_n) sin φ_n loses ~eps·a_n/b_n
//   in asin when k' → 0; the quadratic for tan φ_{n−1} solved without cancellation does not:
//     tan φ_{n−1} = 2 sin φ_n / ((1+κ) cos φ_n + √Q)               (cos φ_n ≥ 0)
//                 = (√Q + (1+κ)|cos φ_n|) / (2κ sin φ_n)          (cos φ_n < 0),
//     Q = (1+κ)² cos² φ_n + 4κ sin² φ_n,
//   taking the branch with |φ_{n−1} − φ_n/2| ≤ π/4 (the asin form bounds 2φ_{n−1} − φ_n).
// dn = √(cn² + k'² sn²) (no cancellation, dn ≥ k' > 0).
template <class T>
struct jacobi_triple {
    T sn, cn, dn;
};
template <class T>
jacobi_triple<T> jacobi_kp(T u, T kp2) {
    const T eps = std::numeric_limits<T>::epsilon(), pi = std::acos(T(-1));
    std::array<T, 32> a{}, b{}, c{};
    a[0] = 1;
    b[0] = std::sqrt(kp2);
    c[0] = std::sqrt(1 - kp2);
    std::size_t n = 0;
    while (c[n] > eps * a[n] && n + 1 < a.size()) {
        ++n;
        a[n] = (a[n - 1] + b[n - 1]) / 2;
        b[n] = std::sqrt(a[n - 1] * b[n - 1]);
        c[n] = n == 1 ? (1 - b[0]) / 2 : c[n - 1] * c[n - 1] / (4 * a[n]);
    }
    T phi = std::ldexp(a[n] * u, static_cast<int>(n));
    T x = std::cos(phi), y = std::sin(phi);  // cos φ_n, sin φ_n (up to a common positive factor)
    for (; n > 0; --n) {
        const T kappa = b[n - 1] / a[n - 1], s = std::sin(phi), co = std::cos(phi);
        const T rootQ = std::sqrt((1 + kappa) * (1 + kappa) * co * co + 4 * kappa * s * s);
        if (co >= 0) {
            x = (1 + kappa) * co + rootQ;
            y = 2 * s;
        } else {
            x = 2 * kappa * std::abs(s);
            y = std::copysign(rootQ - (1 + kappa) * co, s);
        }
        const T principal = std::atan2(y, x);  // ∈ [−π/2, π/2], x ≥ 0
        const T shift = std::round((phi / 2 - principal) / pi);
        phi = principal + shift * pi;
        if (std::fmod(shift, T(2)) != 0) {  // odd multiple of π: (x, y) → (−x, −y)
            x = -x;
            y = -y;
        }
    }
    const T r = std::hypot(x, y), sn = y / r, cn = x / r;
    return {sn, cn, std::sqrt(cn * cn + kp2 * sn * sn)};
}
// K(k) = R_F(0, k'², 1) (DLMF 19.25.1).
template <class T>
T complete_K(T kp2) {
    return boost::math::ellint_rf(T(0), kp2, T(1));
}

// sn, cn, dn of u = r + 2Kj, |r| ≤ K: sn(r + 2K) = −sn r, cn(r + 2K) = −cn r, dn(r + 2K) = dn r
// (DLMF 22.4.3); the AGM is evaluated at r only.
template <class T>
struct jacobi_reduced {
    T r;                 // u − 2Kj ∈ [−K, K]
    long long j;         // the number of half periods removed
    T sn_r, cn_r, dn_r;  // at r
    T sn, cn, dn;        // at u
};
template <class T>
jacobi_reduced<T> jacobi_reduce(T u, T kp2, T K) {
    jacobi_reduced<T> out{};
    out.j = std::llround(u / (2 * K));
    out.r = u - 2 * K * static_cast<T>(out.j);
    const jacobi_triple<T> f = jacobi_kp(out.r, kp2);
    out.sn_r = f.sn;
    out.cn_r = f.cn;
    out.dn_r = f.dn;
    const T sign = (out.j % 2 == 0) ? T(1) : T(-1);
    out.sn = sign * f.sn;
    out.cn = sign * f.cn;
    out.dn = f.dn;
    return out;
}

// --- the exact torque-free body -------------------------------------------------------------------
enum class regime {
    steady,             // m0 along a principal axis (or zero): m constant, R = exp(t ω̂)
    major_axis_family,  // G² > 2E·I_mid: m circulates around the axis of largest inertia
    minor_axis_family,  // G² < 2E·I_mid: m circulates around the axis of smallest inertia
};

template <class T>
struct torque_free_body {
    static_assert(std::is_floating_point_v<T>, "freebody::torque_free_body<T>: T must be a floating type");

    using regime = freebody::regime;

    torque_free_body(const vec3<T>& I, const vec3<T>& m0) : I_(I), m0_(m0) {
        for (std::size_t i = 0; i < 3; ++i) {
            if (!(std::isfinite(I[i]) && I[i] > 0))
                throw std::domain_error("freebody: principal moments must be finite and positive");
            if (!std::isfinite(m0[i])) throw std::domain_error("freebody: m0 must be finite");
        }
        if (I[0] == I[1] || I[1] == I[2] || I[0] == I[2])
            throw std::domain_error("freebody: principal moments must be pairwise distinct");

        G_ = norm(m0);
        E_ = (m0[0] * m0[0] / I[0] + m0[1] * m0[1] / I[1] + m0[2] * m0[2] / I[2]) / 2;

        // Sort: working axis a is user axis p_[a] with sign s_[a], w_a = s_a m_{p_a}, and
        // J_0 < J_1 < J_2. The signed permutation must be a proper rotation (so that it maps
        // ṁ = m × ω to ẇ = w × J⁻¹w): flip the sign of the last axis for an odd permutation.
        std::array<std::size_t, 3> p{0, 1, 2};
        std::sort(p.begin(), p.end(), [&](std::size_t a, std::size_t b) { return I[a] < I[b]; });
        const bool odd = (p[0] > p[1]) != ((p[0] > p[2]) != (p[1] > p[2]));
        std::array<T, 3> s{1, 1, odd ? T(-1) : T(1)};
        mid_axis_ = p[1];

        const auto zeros = static_cast<int>(m0[0] == 0) + static_cast<int>(m0[1] == 0) + static_cast<int>(m0[2] == 0);
        if (zeros >= 2) {  // steady rotation about a principal axis: ω = I⁻¹m0 ∥ m0, constant
            kind_ = regime::steady;
            return;
        }

        vec3<T> w{}, J{};
        for (std::size_t a = 0; a < 3; ++a) {
            w[a] = s[a] * m0[p[a]];
            J[a] = I[p[a]];
        }
        // 2E·J_a − G² = Σ_i w_i² (J_a − J_i)/J_i: sums of same-signed terms for the outer axes,
        // so B_i, λ, k² keep full relative accuracy; the middle one carries the separatrix
        // distance and its (unavoidable) cancellation.
        const T Dmid = D(w, J, 1);
        if (Dmid == 0)
            throw std::domain_error("freebody: separatrix G^2 = 2E*I_mid (k = 1) is not supported");
        if (Dmid < 0) {
            kind_ = regime::major_axis_family;
        } else {
            // Relabel with the proper rotation (w0, w1, w2) → (w2, −w1, w0), inertias
            // (J2, J1, J0); the same formulas then hold with λ = sign(J2' − J1')·√… < 0.
            kind_ = regime::minor_axis_family;
            p = {p[2], p[1], p[0]};
            s = {s[2], -s[1], s[0]};
            w = {w[2], -w[1], w[0]};
            J = {J[2], J[1], J[0]};
        }
        p_ = p;
        s_ = s;
        J_ = J;

        // Landau §37 (their B1, B2, B3 are B0, B1, B2 here), with D_a = 2E·J_a − G²
        // (signs valid in both families):
        //   B0² = J0·D2/(J2 − J0), B1² = J1·D2/(J2 − J1), B2² = J2·(−D0)/(J2 − J0),
        //   λ = sign(J2 − J1)·√((J2 − J1)(−D0)/(J0 J1 J2)),
        //   k² = (J1 − J0)·D2 / ((J2 − J1)(−D0)),  k'² = 1 − k² = (J2 − J0)(−D1) / ((J2 − J1)(−D0)),
        //   w0 = B0 cn u, w1 = σ B1 sn u, w2 = σ B2 dn u, u = λt + u0, σ = sign w2(0).
        const T D0 = D(w, J, 0), D1 = D(w, J, 1), D2 = D(w, J, 2);
        B_ = {std::sqrt(J[0] * D2 / (J[2] - J[0])), std::sqrt(J[1] * D2 / (J[2] - J[1])),
              std::sqrt(J[2] * -D0 / (J[2] - J[0]))};
        lambda_ = std::sqrt((J[2] - J[1]) * -D0 / (J[0] * J[1] * J[2]));
        if (J[2] < J[1]) lambda_ = -lambda_;
        const T k2 = (J[1] - J[0]) * D2 / ((J[2] - J[1]) * -D0);
        kp2_ = (J[2] - J[0]) * -D1 / ((J[2] - J[1]) * -D0);
        if (!(kp2_ > 0)) throw std::domain_error("freebody: separatrix (k'^2 = 0) is not supported");
        k_ = std::sqrt(k2);
        sigma_ = w[2] < 0 ? T(-1) : T(1);
        K_ = complete_K(kp2_);

        // u0 = F(am u0, k) with sn u0 = σ w1/B1, cn u0 = w0/B0 (normalised), dn² = cn² + k'² sn².
        // F(φ) = sn·R_F(cn², dn², 1) for |φ| ≤ π/2 (DLMF 19.25.5 scaled by sin²φ), and
        // F(±π ∓ φ') = ±2K ∓ F(φ') beyond; this avoids losing cos φ near φ = ±π/2.
        T sn0 = sigma_ * w[1] / B_[1], cn0 = w[0] / B_[0];
        const T h = std::hypot(sn0, cn0);
        sn0 /= h;
        cn0 /= h;
        const T dn0 = std::sqrt(cn0 * cn0 + kp2_ * sn0 * sn0);
        const T F = sn0 * boost::math::ellint_rf(cn0 * cn0, dn0 * dn0, T(1));
        u0_ = cn0 >= 0 ? F : (sn0 < 0 ? T(-2) : T(2)) * K_ - F;

        // Attitude (Landau §37): Euler angles of the working body frame in a frame whose z axis is
        // the spatial momentum, x_F = Rz(φ) Rx(θ) Rz(ψ) x_work, with
        //   w = G (sin θ sin ψ, sin θ cos ψ, cos θ),
        //   φ̇ = G (w0²/J0 + w1²/J1)/(w0² + w1²) = G/J2 + G(2E − G²/J2)/(G² − w2²).
        // G² − w2² = c (1 − n sn² u) with c = G² − B2² = B0² and n = −B2² k²/B0² ≤ 0, and
        // ∫ du/(1 − n sn² u) = Π(n, am u, k), so
        //   φ(t) = G t/J2 + coef·[Π(n, am u, k) − Π(n, am u0, k)],
        //   coef = G(2E − G²/J2)/(c λ) = G (J2 − J0)/(J0 J2 λ)   (using B0² = J0 D2/(J2 − J0)).
        n_ = -(B_[2] * B_[2]) * k2 / (B_[0] * B_[0]);
        coef_ = G_ * (J[2] - J[0]) / (J[0] * J[2] * lambda_);
        // Π(n, k) = R_F(0, k'², 1) + (n/3) R_J(0, k'², 1, 1 − n) (DLMF 19.25.2)
        Pi_complete_ = K_ + n_ / 3 * boost::math::ellint_rj(T(0), kp2_, T(1), 1 - n_);
        Pi_u0_ = unwrapped_Pi(jacobi_reduce(u0_, kp2_, K_));
        // R(t) = Sᵀ · B(w0)ᵀ Rz(φ(t)) B(w(t)) · S, B(w) = Rx(θ) Rz(ψ), so that R(0) = 1 (φ(0) = 0).
        B0t_ = transpose(euler_tail(w));
    }

    regime kind() const { return kind_; }
    const vec3<T>& inertia() const { return I_; }
    const vec3<T>& initial_momentum() const { return m0_; }
    // E = ½ Σ m_i²/I_i and G = |m|, both constant.
    T energy() const { return E_; }
    T momentum_norm() const { return G_; }
    // Elliptic modulus k, k'² = 1 − k², signed rate λ (u = λt + u0), u0, K(k). Zero in steady rotation.
    T modulus() const { return k_; }
    T complementary_modulus_squared() const { return kp2_; }
    T rate() const { return lambda_; }
    T phase0() const { return u0_; }
    T quarter_period() const { return K_; }
    // Period of m(t): 4K/|λ|; 0 in steady rotation (m constant).
    T period() const { return kind_ == regime::steady ? T(0) : 4 * K_ / std::abs(lambda_); }
    // The user index of the axis of intermediate inertia.
    std::size_t intermediate_axis() const { return mid_axis_; }

    // Body-frame angular momentum m(t).
    vec3<T> momentum(T t) const {
        if (kind_ == regime::steady) return m0_;
        return to_user(working_momentum(jacobi_reduce(lambda_ * t + u0_, kp2_, K_)));
    }
    // Body angular velocity ω(t) = I⁻¹ m(t).
    vec3<T> omega(T t) const {
        const vec3<T> m = momentum(t);
        return {m[0] / I_[0], m[1] / I_[1], m[2] / I_[2]};
    }

    // R(t), x_fixed = R x_body, R(0) = 1.
    mat3<T> attitude(T t) const {
        if (kind_ == regime::steady) {  // Rodrigues: rotation by |ω| t about ω
            const vec3<T> om{m0_[0] / I_[0], m0_[1] / I_[1], m0_[2] / I_[2]};
            const T speed = norm(om);
            if (speed == 0) return identity<T>();
            const vec3<T> a{om[0] / speed, om[1] / speed, om[2] / speed};
            const T c = std::cos(speed * t), s = std::sin(speed * t), v = 1 - c;
            return {{{c + v * a[0] * a[0], v * a[0] * a[1] - s * a[2], v * a[0] * a[2] + s * a[1]},
                     {v * a[1] * a[0] + s * a[2], c + v * a[1] * a[1], v * a[1] * a[2] - s * a[0]},
                     {v * a[2] * a[0] - s * a[1], v * a[2] * a[1] + s * a[0], c + v * a[2] * a[2]}}};
        }
        const jacobi_reduced<T> jr = jacobi_reduce(lambda_ * t + u0_, kp2_, K_);
        const vec3<T> w = working_momentum(jr);
        const T phi = G_ * t / J_[2] + coef_ * (unwrapped_Pi(jr) - Pi_u0_);
        const T c = std::cos(phi), s = std::sin(phi);
        const mat3<T> rz{{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
        const mat3<T> work = mul(B0t_, mul(rz, euler_tail(w)));
        // back to user axes: R_user = Sᵀ R_work S, (Sᵀ M S)_{p_a p_b} = s_a s_b M_ab
        mat3<T> r{};
        for (std::size_t a = 0; a < 3; ++a)
            for (std::size_t b = 0; b < 3; ++b) r[p_[a]][p_[b]] = s_[a] * s_[b] * work[a][b];
        return r;
    }
    std::array<T, 4> quaternion(T t) const { return quaternion_of(attitude(t)); }

    // Number of zeros (= sign changes, all zeros are simple) of m_i(t) for t ∈ (0, t_end], t_end ≥ 0,
    // from the phase alone: w0 ∝ cn u vanishes at u = K + 2Kj, w1 ∝ sn u at u = 2Kj, w2 ∝ dn u never.
    long long sign_changes(std::size_t i, T t_end) const {
        if (i > 2) throw std::out_of_range("freebody: component index must be 0, 1 or 2");
        if (kind_ == regime::steady || t_end <= 0) return 0;
        std::size_t a = 0;
        while (p_[a] != i) ++a;
        if (a == 2) return 0;
        const T offset = a == 0 ? K_ : T(0);
        const T x0 = (u0_ - offset) / (2 * K_), x1 = (lambda_ * t_end + u0_ - offset) / (2 * K_);
        // integers in (x0, x1] when λ > 0, in [x1, x0) when λ < 0
        const T count = lambda_ > 0 ? std::floor(x1) - std::floor(x0) : std::ceil(x0) - std::ceil(x1);
        return static_cast<long long>(count);
    }
    // Flips of the intermediate axis (the Dzhanibekov effect): sign changes of m_mid on (0, t_end].
    long long flips(T t_end) const { return sign_changes(mid_axis_, t_end); }

private:
    static T D(const vec3<T>& w, const vec3<T>& J, std::size_t a) {
        return w[0] * w[0] * ((J[a] - J[0]) / J[0]) + w[1] * w[1] * ((J[a] - J[1]) / J[1]) +
               w[2] * w[2] * ((J[a] - J[2]) / J[2]);
    }
    vec3<T> working_momentum(const jacobi_reduced<T>& jr) const {
        return {B_[0] * jr.cn, sigma_ * B_[1] * jr.sn, sigma_ * B_[2] * jr.dn};
    }
    vec3<T> to_user(const vec3<T>& w) const {
        vec3<T> m{};
        for (std::size_t a = 0; a < 3; ++a) m[p_[a]] = s_[a] * w[a];
        return m;
    }
    // Π(n, am u, k), continuous in u: with u = r + 2Kj, am u = am r + jπ and
    // Π(n, φ + jπ) = Π(n, φ) + 2j Π(n) (DLMF 19.7.9 with 19.2.8); for |r| ≤ K (DLMF 19.25.14 scaled by sin²φ)
    //   Π(n, am r) = sn·R_F(cn², dn², 1) + (n/3) sn³ R_J(cn², dn², 1, 1 − n sn²),
    // evaluated from sn, cn, dn directly (no loss of cos φ near φ = ±π/2).
    T unwrapped_Pi(const jacobi_reduced<T>& jr) const {
        const T s = jr.sn_r, c2 = jr.cn_r * jr.cn_r, d2 = jr.dn_r * jr.dn_r;
        const T local = s * boost::math::ellint_rf(c2, d2, T(1)) +
                        n_ / 3 * s * s * s * boost::math::ellint_rj(c2, d2, T(1), 1 - n_ * s * s);
        return local + 2 * static_cast<T>(jr.j) * Pi_complete_;
    }
    // B(w) = Rx(θ) Rz(ψ) with cos θ = w2/|w|, sin θ = ρ/|w|, sin ψ = w0/ρ, cos ψ = w1/ρ,
    // ρ = √(w0² + w1²) > 0 off steady rotation. Its last row is w/|w|, so B(w) w = |w| e_z exactly
    // up to rounding, whatever φ is.
    static mat3<T> euler_tail(const vec3<T>& w) {
        const T rho = std::hypot(w[0], w[1]), g = norm(w);
        const T ct = w[2] / g, st = rho / g, sp = w[0] / rho, cp = w[1] / rho;
        return {{{cp, -sp, 0}, {ct * sp, ct * cp, -st}, {st * sp, st * cp, ct}}};
    }

    vec3<T> I_{}, m0_{};
    T G_{}, E_{};
    regime kind_{regime::steady};
    std::size_t mid_axis_{1};
    std::array<std::size_t, 3> p_{0, 1, 2};
    vec3<T> s_{1, 1, 1}, J_{}, B_{};
    T lambda_{}, k_{}, kp2_{}, sigma_{1}, K_{}, u0_{}, n_{}, coef_{}, Pi_complete_{}, Pi_u0_{};
    mat3<T> B0t_{};
};

// --- numerical reference: classical RK4 on (m, R) --------------------------------------------------
//   ṁ = m × ω, Ṙ = R ω̂, ω = I⁻¹ m   (body frame; ω̂ x = ω × x).
// Global error O(h⁴); R is not re-orthonormalised (its drift is itself O(h⁴)).
template <class T>
struct rigid_state {
    vec3<T> m;
    mat3<T> R;
};

template <class T>
class reference_integrator {
public:
    reference_integrator(const vec3<T>& I, const vec3<T>& m0, T h) : I_(I), h_(h), x_{m0, identity<T>()} {}

    T time() const { return t_; }
    const rigid_state<T>& state() const { return x_; }
    // Steps of equal size ≤ h from the current time to exactly t_end.
    const rigid_state<T>& advance_to(T t_end) {
        const T span = t_end - t_;
        if (span <= 0) return x_;
        const auto n = static_cast<long long>(std::ceil(span / h_));
        const T dt = span / static_cast<T>(n);
        for (long long i = 0; i < n; ++i) step(dt);
        t_ = t_end;
        return x_;
    }

private:
    rigid_state<T> rhs(const rigid_state<T>& x) const {
        const vec3<T> w{x.m[0] / I_[0], x.m[1] / I_[1], x.m[2] / I_[2]};
        rigid_state<T> d{cross(x.m, w), {}};
        for (std::size_t i = 0; i < 3; ++i) d.R[i] = cross(x.R[i], w);  // row i of R ω̂ is R_i × ω
        return d;
    }
    static rigid_state<T> axpy(T a, const rigid_state<T>& d, const rigid_state<T>& x) {
        rigid_state<T> y = x;
        for (std::size_t i = 0; i < 3; ++i) {
            y.m[i] += a * d.m[i];
            for (std::size_t j = 0; j < 3; ++j) y.R[i][j] += a * d.R[i][j];
        }
        return y;
    }
    void step(T dt) {
        const rigid_state<T> k1 = rhs(x_);
        const rigid_state<T> k2 = rhs(axpy(dt / 2, k1, x_));
        const rigid_state<T> k3 = rhs(axpy(dt / 2, k2, x_));
        const rigid_state<T> k4 = rhs(axpy(dt, k3, x_));
        for (std::size_t i = 0; i < 3; ++i) {
            x_.m[i] += dt / 6 * (k1.m[i] + 2 * k2.m[i] + 2 * k3.m[i] + k4.m[i]);
            for (std::size_t j = 0; j < 3; ++j)
                x_.R[i][j] += dt / 6 * (k1.R[i][j] + 2 * k2.R[i][j] + 2 * k3.R[i][j] + k4.R[i][j]);
        }
    }

    vec3<T> I_;
    T h_;
    T t_{0};
    rigid_state<T> x_;
};

// m(t_end), R(t_end) from m(0) = m0, R(0) = 1 by RK4 with steps ≤ h.
template <class T>
rigid_state<T> integrate_reference(const vec3<T>& I, const vec3<T>& m0, T t_end, T h) {
    reference_integrator<T> integ(I, m0, h);
    return integ.advance_to(t_end);
}

// --- DETEST problem B5 (Hull, Enright, Fellen, Sedgwick 1972) -------------------------------------
//   y' = (y1 y2, −y0 y2, −0.51 y0 y1), y(0) = (0, 1, 1); exact y = (sn, cn, dn)(t, k² = 0.51):
// sn' = cn dn, cn' = −sn dn, dn' = −k² sn cn.
template <class T>
T detest_b5_k2() {
    return T(51) / T(100);
}
template <class T>
vec3<T> detest_b5_y0() {
    return {0, 1, 1};
}
template <class T>
vec3<T> detest_b5_rhs(const vec3<T>& y) {
    return {y[1] * y[2], -y[0] * y[2], -detest_b5_k2<T>() * y[0] * y[1]};
}
// Straight from Boost (its own AGM; an independent check of jacobi_kp above).
template <class T>
vec3<T> detest_b5_exact(T t) {
    T cn{}, dn{};
    const T sn = boost::math::jacobi_elliptic(std::sqrt(detest_b5_k2<T>()), t, &cn, &dn);
    return {sn, cn, dn};
}

}  // namespace freebody
