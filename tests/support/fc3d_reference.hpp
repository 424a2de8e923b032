// fc3d_reference.hpp: an independent, long-double reference solver for the 3-D frictional
// contact problem ("fc3d": Acary, Brémond, Huber 2018; Siconos/FCLIB), for the contact-solver
// tests.
//
// Nothing here is taken from ctga's contact code. The problem: m contacts; W (3m x 3m,
// symmetric positive definite, dense, row-major), q (3m), mu (m values >= 0). Contact i owns
// rows 3i (normal n), 3i+1, 3i+2 (tangents t); u = W r + q. Find r such that for every i
//     K_i  contains r_i  _|_  u~_i in K*_i,      u~_i = u_i + (mu_i |u_t,i|, 0, 0),
// K = {|r_t| <= mu r_n}, K* = {mu |v_t| <= v_n} (mu = 0: K = {r_t = 0, r_n >= 0}, K* = {v_n >= 0}).
// This is Signorini + Coulomb with maximal dissipation: take-off (r = 0, u_n >= 0), stick
// (u = 0, r in K), slide (u_n = 0, r_t = -mu r_n u_t / |u_t|, u_t != 0).
// natural_map_residual returns |F(r)|_2, F(r)_i = r_i - P_K(r_i - u~_i), zero exactly at the
// solutions; P_K is the closed-form projection on the cone (project_cone).
//
// Method (solve), chosen for accuracy rather than speed:
//  1. Block projected Gauss-Seidel (PGS): contact by contact, the one-contact problem with the
//     others frozen (A = W_ii, b = q_i + sum_{j != i} W_ij r_j) is solved exactly by
//     enumerating its cases: take-off r = 0 (a solution iff b_n >= 0), stick r = -A^-1 b (iff
//     it lies in K), slide r = r_n (1, -mu cos a, -mu sin a). For the slide, u_n = 0 gives
//     r_n = -b_n / D(a) with D = (A e(a))_n, and u_t = v(a) / D with v = D b_t - b_n (A e)_t;
//     u_t parallel to (cos a, sin a) is h(a) = v x (cos a, sin a) = 0, a trigonometric
//     polynomial of degree 2 (at most 4 roots). Its roots are bracketed on 256 samples of a and
//     bisected to rounding; local minima of |h| (double roots) are refined by golden section.
//     Every candidate is scored by its one-contact natural-map residual and the smallest wins,
//     so no threshold decides the case.
//  2. Semismooth Newton on the Alart-Curnier function (rho_i > 0 per contact):
//        Phi_n = r_n - max(0, x_n),                       x_n = r_n - rho u_n,
//        Phi_t = r_t - P_{disk of radius mu max(0, x_n)}(r_t - rho u_t).
//     Phi(r) = 0 iff r solves the problem, for every rho > 0 (Phi_n = 0 is Signorini; given it,
//     the radius is mu r_n and Phi_t = 0 says -u_t is normal to the disk at r_t, i.e. Coulomb
//     with maximal dissipation). Phi is piecewise smooth, hence semismooth: Newton with one
//     element of the generalised Jacobian, G = D_r Phi + D_u Phi W, converges locally
//     quadratically at regular solutions. G is factorised by LU with partial pivoting; when it
//     is singular or its step fails, Levenberg-Marquardt steps (G^T G + lambda I) d = -G^T Phi
//     are tried. Every step is globalised by Armijo backtracking on |Phi|^2.
//  3. Restarts: PGS (30 sweeps) from r = 0, then Newton; while not converged, more PGS sweeps
//     (200, 1000, 3000, 10000, 10000) from the best point so far, then Newton with another rho
//     (factors 1, 0.1, 10, 0.01, 100, 1 of rho_i = 3 / trace W_ii).
// The returned r is the iterate with the smallest natural-map residual seen; converged is
// residual <= tolerance * max(1, |q|_2), computed from that r by natural_map_residual itself;
// iterations counts PGS sweeps plus Newton steps. Newton continues for up to two steps past
// convergence, to reach the rounding floor.
//
// The attainable residual is set by rounding in u = W r + q, about eps_ld |W| |r| (eps_ld =
// 1.1e-19), so a very ill-conditioned W (|r| >> |q|) may end honestly unconverged.
//
// Accuracy, measured (g++ 12 and clang 14, x86-64, -O2): 5,500 random problems, m = 1..10,
// mu in [0, 1] (10% exactly 0, 5% exactly 1), W = J J^T / k + eps I, J 3m x k Gaussian, k in
// [3m, 6m] or k = 3m, eps from 1e-1 down to 1e-8: all converged, |F|_2 <= 3.6e-18 max(1, |q|_2)
// (one problem of another draw, |r| = 2.5e3, reached only 1.0e-16, its rounding floor), in at
// most 44 iterations; 300 problems with planted solutions (take-off, stick, slide and the
// degenerate r = u = 0, grazing slide r = 0 with u_n = 0, stick on the cone's boundary): all
// converged, |F|_2 <= 2.2e-19 max(1, |q|_2), r within 3.5e-18 of the planted r (or, in 2 of
// 300, another solution: fc3d solutions need not be unique). Either part alone also works:
// Newton from r = 0 reached 1e-14 on 198-200 of 200 problems, PGS alone on all 200 (20 sweeps
// on average). The hand cases (W = I, mu = 0.5: stick, slide, take-off) come out exact.
// Cost: 3.2 ms per problem on average, at most ~24 ms (m = 10, -O2).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <vector>

namespace fc3d_reference {

using real = long double;

struct result {
    std::vector<real> r;
    real residual;
    int iterations;
    bool converged;
};

namespace detail {

using vec3 = std::array<real, 3>;
using mat3 = std::array<std::array<real, 3>, 3>;

inline constexpr real pi = std::numbers::pi_v<real>;

inline real norm(const std::vector<real>& v) {
    real s = 0;
    for (real x : v) s += x * x;
    return std::sqrt(s);
}

// u = W r + q (n = q.size())
inline std::vector<real> velocity(const std::vector<real>& W, const std::vector<real>& q,
                                  const std::vector<real>& r) {
    const std::size_t n = q.size();
    std::vector<real> u(n);
    for (std::size_t i = 0; i < n; ++i) {
        real s = q[i];
        for (std::size_t j = 0; j < n; ++j) s += W[i * n + j] * r[j];
        u[i] = s;
    }
    return u;
}

// Euclidean projection on K_mu = {|x_t| <= mu x_n}.
inline vec3 project_cone(real mu, const vec3& x) {
    const real nt = std::hypot(x[1], x[2]);
    if (x[0] >= 0 && nt <= mu * x[0]) return x;  // in K
    if (mu * nt <= -x[0]) return {0, 0, 0};      // in the polar cone -K*; nt > 0 below
    const real rn = (x[0] + mu * nt) / (1 + mu * mu);
    const real f = mu * rn / nt;
    return {rn, f * x[1], f * x[2]};
}

// One contact's natural map r - P_K(r - u~).
inline vec3 natural_map(real mu, const vec3& r, const vec3& u) {
    const real ut = std::hypot(u[1], u[2]);
    const vec3 p = project_cone(mu, {r[0] - (u[0] + mu * ut), r[1] - u[1], r[2] - u[2]});
    return {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
}

inline vec3 block(const std::vector<real>& v, std::size_t i) {
    return {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
}

inline real residual(const std::vector<real>& W, const std::vector<real>& q,
                     const std::vector<real>& mu, const std::vector<real>& r) {
    const std::vector<real> u = velocity(W, q, r);
    real s = 0;
    for (std::size_t i = 0; i < mu.size(); ++i) {
        const vec3 f = natural_map(mu[i], block(r, i), block(u, i));
        s += f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
    }
    return std::sqrt(s);
}

// ---- one-contact exact solve (PGS) -----------------------------------------------------------

inline real local_residual(real mu, const mat3& A, const vec3& b, const vec3& r) {
    vec3 u;
    for (std::size_t a = 0; a < 3; ++a) u[a] = A[a][0] * r[0] + A[a][1] * r[1] + A[a][2] * r[2] + b[a];
    const vec3 f = natural_map(mu, r, u);
    return std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
}

// x = A^-1 y by Cramer's rule (A SPD, 3 x 3); false when the determinant vanishes.
inline bool solve3(const mat3& A, const vec3& y, vec3& x) {
    const real c00 = A[1][1] * A[2][2] - A[1][2] * A[2][1];
    const real c01 = A[1][2] * A[2][0] - A[1][0] * A[2][2];
    const real c02 = A[1][0] * A[2][1] - A[1][1] * A[2][0];
    const real det = A[0][0] * c00 + A[0][1] * c01 + A[0][2] * c02;
    if (!(det != 0) || !std::isfinite(det)) return false;
    const real c10 = A[0][2] * A[2][1] - A[0][1] * A[2][2];
    const real c11 = A[0][0] * A[2][2] - A[0][2] * A[2][0];
    const real c12 = A[0][1] * A[2][0] - A[0][0] * A[2][1];
    const real c20 = A[0][1] * A[1][2] - A[0][2] * A[1][1];
    const real c21 = A[0][2] * A[1][0] - A[0][0] * A[1][2];
    const real c22 = A[0][0] * A[1][1] - A[0][1] * A[1][0];
    // inverse = adjugate / det, adjugate = cofactor matrix transposed
    x[0] = (c00 * y[0] + c10 * y[1] + c20 * y[2]) / det;
    x[1] = (c01 * y[0] + c11 * y[1] + c21 * y[2]) / det;
    x[2] = (c02 * y[0] + c12 * y[1] + c22 * y[2]) / det;
    return true;
}

inline constexpr int angle_samples = 256;

inline vec3 solve_one_contact(real mu, const mat3& A, const vec3& b) {
    vec3 best{0, 0, 0};  // take-off
    real best_res = local_residual(mu, A, b, best);
    const auto consider = [&](const vec3& r) {
        if (!(std::isfinite(r[0]) && std::isfinite(r[1]) && std::isfinite(r[2]))) return;
        const real res = local_residual(mu, A, b, r);
        if (res < best_res) {
            best_res = res;
            best = r;
        }
    };
    if (b[0] >= 0 && best_res == 0) return best;
    if (mu == 0) {
        if (A[0][0] > 0) consider({-b[0] / A[0][0], 0, 0});
        return best;
    }
    vec3 stick;
    if (solve3(A, {-b[0], -b[1], -b[2]}, stick)) consider(stick);
    // slide: r = r_n (1, -mu c, -mu s)
    const auto h = [&](real a) {
        const real c = std::cos(a), s = std::sin(a);
        const real D = A[0][0] - mu * (A[0][1] * c + A[0][2] * s);
        const real a1 = A[1][0] - mu * (A[1][1] * c + A[1][2] * s);
        const real a2 = A[2][0] - mu * (A[2][1] * c + A[2][2] * s);
        const real v1 = D * b[1] - b[0] * a1, v2 = D * b[2] - b[0] * a2;
        return v1 * s - v2 * c;
    };
    const auto slide = [&](real a) {
        const real c = std::cos(a), s = std::sin(a);
        const real D = A[0][0] - mu * (A[0][1] * c + A[0][2] * s);
        if (!(D > 0)) return;
        const real rn = -b[0] / D;
        if (!(rn > 0)) return;
        consider({rn, -mu * rn * c, -mu * rn * s});
    };
    constexpr int N = angle_samples;
    const real step = 2 * pi / N;
    std::array<real, N> hv;
    for (int k = 0; k < N; ++k) hv[static_cast<std::size_t>(k)] = h(step * k);
    for (int k = 0; k < N; ++k) {
        const real a0 = step * k, a1 = step * (k + 1);
        const real h0 = hv[static_cast<std::size_t>(k)];
        const real h1 = hv[static_cast<std::size_t>((k + 1) % N)];
        const real hm = hv[static_cast<std::size_t>((k + N - 1) % N)];
        if (h0 == 0) slide(a0);
        if ((h0 < 0 && h1 > 0) || (h0 > 0 && h1 < 0)) {  // bisection on [a0, a1]
            real lo = a0, hi = a1, hlo = h0;
            for (int it = 0; it < 80; ++it) {
                const real mid = (lo + hi) / 2;
                if (mid <= lo || mid >= hi) break;
                const real hmid = h(mid);
                if (hmid == 0) {
                    lo = hi = mid;
                    break;
                }
                if ((hmid < 0) == (hlo < 0)) {
                    lo = mid;
                    hlo = hmid;
                } else {
                    hi = mid;
                }
            }
            slide(std::abs(h(lo)) <= std::abs(h(hi)) ? lo : hi);
        }
        // local minimum of |h| without a sign change: a possible double root
        if (std::abs(h0) <= std::abs(hm) && std::abs(h0) <= std::abs(h1) &&
            !((h0 < 0 && h1 > 0) || (h0 > 0 && h1 < 0)) &&
            !((h0 < 0 && hm > 0) || (h0 > 0 && hm < 0))) {
            const real g = (std::sqrt(real(5)) - 1) / 2;
            real lo = a0 - step, hi = a1;
            real x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
            real f1 = std::abs(h(x1)), f2 = std::abs(h(x2));
            for (int it = 0; it < 100 && hi - lo > 1e-18L; ++it) {
                if (f1 <= f2) {
                    hi = x2;
                    x2 = x1;
                    f2 = f1;
                    x1 = hi - g * (hi - lo);
                    f1 = std::abs(h(x1));
                } else {
                    lo = x1;
                    x1 = x2;
                    f1 = f2;
                    x2 = lo + g * (hi - lo);
                    f2 = std::abs(h(x2));
                }
            }
            slide(f1 <= f2 ? x1 : x2);
        }
    }
    return best;
}

// Sweeps of block projected Gauss-Seidel; stops early at residual <= stop. Returns the sweeps done.
inline int pgs(const std::vector<real>& W, const std::vector<real>& q, const std::vector<real>& mu,
               std::vector<real>& r, int sweeps, real stop) {
    const std::size_t m = mu.size(), n = 3 * m;
    for (int sweep = 1; sweep <= sweeps; ++sweep) {
        for (std::size_t i = 0; i < m; ++i) {
            mat3 A;
            vec3 b;
            for (std::size_t a = 0; a < 3; ++a) {
                const std::size_t row = 3 * i + a;
                real s = q[row];
                for (std::size_t j = 0; j < n; ++j)
                    if (j / 3 != i) s += W[row * n + j] * r[j];
                b[a] = s;
                for (std::size_t c = 0; c < 3; ++c) A[a][c] = W[row * n + 3 * i + c];
            }
            const vec3 ri = solve_one_contact(mu[i], A, b);
            for (std::size_t a = 0; a < 3; ++a) r[3 * i + a] = ri[a];
        }
        if (residual(W, q, mu, r) <= stop) return sweep;
    }
    return sweeps;
}

// ---- Alart-Curnier function and its generalised Jacobian -------------------------------------

// Phi (3m) and, when G is non-null, G = D_r Phi + D_u Phi W (row-major 3m x 3m).
inline void alart_curnier(const std::vector<real>& W, const std::vector<real>& q,
                          const std::vector<real>& mu, const std::vector<real>& rho,
                          const std::vector<real>& r, std::vector<real>& phi,
                          std::vector<real>* G) {
    const std::size_t m = mu.size(), n = 3 * m;
    const std::vector<real> u = velocity(W, q, r);
    phi.assign(n, 0);
    if (G) G->assign(n * n, 0);
    for (std::size_t i = 0; i < m; ++i) {
        const real p = rho[i], f = mu[i];
        const std::size_t o = 3 * i;
        mat3 dr{}, du{};
        const real xn = r[o] - p * u[o];
        if (xn > 0) {
            phi[o] = p * u[o];
            du[0][0] = p;
        } else {
            phi[o] = r[o];
            dr[0][0] = 1;
        }
        const real s = f * std::max<real>(xn, 0);
        const real y1 = r[o + 1] - p * u[o + 1], y2 = r[o + 2] - p * u[o + 2];
        const real ny = std::hypot(y1, y2);
        if (s > 0 && ny <= s) {  // stick: Phi_t = rho u_t
            phi[o + 1] = p * u[o + 1];
            phi[o + 2] = p * u[o + 2];
            du[1][1] = du[2][2] = p;
        } else if (s > 0) {  // slide: Phi_t = r_t - s y / |y|
            const real e1 = y1 / ny, e2 = y2 / ny, k = s / ny;
            phi[o + 1] = r[o + 1] - s * e1;
            phi[o + 2] = r[o + 2] - s * e2;
            const real P11 = k * (1 - e1 * e1), P12 = -k * e1 * e2, P22 = k * (1 - e2 * e2);
            dr[1][1] = 1 - P11;
            dr[1][2] = -P12;
            dr[2][1] = -P12;
            dr[2][2] = 1 - P22;
            du[1][1] = p * P11;
            du[1][2] = p * P12;
            du[2][1] = p * P12;
            du[2][2] = p * P22;
            dr[1][0] = -f * e1;  // through x_n
            dr[2][0] = -f * e2;
            du[1][0] = f * p * e1;
            du[2][0] = f * p * e2;
        } else {  // zero radius: Phi_t = r_t
            phi[o + 1] = r[o + 1];
            phi[o + 2] = r[o + 2];
            dr[1][1] = dr[2][2] = 1;
        }
        if (!G) continue;
        for (std::size_t a = 0; a < 3; ++a) {
            real* row = G->data() + (o + a) * n;
            for (std::size_t c = 0; c < 3; ++c) row[o + c] += dr[a][c];
            for (std::size_t c = 0; c < 3; ++c) {
                const real d = du[a][c];
                if (d == 0) continue;
                const real* w = W.data() + (o + c) * n;
                for (std::size_t j = 0; j < n; ++j) row[j] += d * w[j];
            }
        }
    }
}

// Solves A x = y (A n x n row-major, copied) by LU with partial pivoting; false if singular.
inline bool solve_linear(std::vector<real> A, std::vector<real> y, std::vector<real>& x) {
    const std::size_t n = y.size();
    real amax = 0;
    for (real v : A) amax = std::max(amax, std::abs(v));
    if (!(amax > 0) || !std::isfinite(amax)) return false;
    const real tiny = amax * std::numeric_limits<real>::epsilon() * 1e-3L;
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t piv = k;
        for (std::size_t i = k + 1; i < n; ++i)
            if (std::abs(A[i * n + k]) > std::abs(A[piv * n + k])) piv = i;
        if (!(std::abs(A[piv * n + k]) > tiny)) return false;
        if (piv != k) {
            for (std::size_t j = 0; j < n; ++j) std::swap(A[k * n + j], A[piv * n + j]);
            std::swap(y[k], y[piv]);
        }
        for (std::size_t i = k + 1; i < n; ++i) {
            const real l = A[i * n + k] / A[k * n + k];
            if (l == 0) continue;
            for (std::size_t j = k; j < n; ++j) A[i * n + j] -= l * A[k * n + j];
            y[i] -= l * y[k];
        }
    }
    x.assign(n, 0);
    for (std::size_t k = n; k-- > 0;) {
        real s = y[k];
        for (std::size_t j = k + 1; j < n; ++j) s -= A[k * n + j] * x[j];
        x[k] = s / A[k * n + k];
    }
    for (real v : x)
        if (!std::isfinite(v)) return false;
    return true;
}

inline real squared(const std::vector<real>& v) {
    real s = 0;
    for (real x : v) s += x * x;
    return s;
}

// Semismooth Newton from r; updates best / best_res (natural-map residual). Returns the steps.
inline int newton(const std::vector<real>& W, const std::vector<real>& q,
                  const std::vector<real>& mu, const std::vector<real>& rho, std::vector<real> r,
                  std::vector<real>& best, real& best_res, real target, int max_steps) {
    const std::size_t n = q.size();
    std::vector<real> phi, G, d, trial, phi_trial;
    alart_curnier(W, q, mu, rho, r, phi, &G);
    real merit = squared(phi);
    int steps = 0, past = 0;
    constexpr real sigma = 1e-4L;
    while (steps < max_steps) {
        const real res = residual(W, q, mu, r);
        if (res < best_res) {
            best_res = res;
            best = r;
        }
        if (res <= target && ++past > 2) break;
        if (merit == 0) break;
        ++steps;
        // try the Newton direction, then Levenberg-Marquardt directions
        bool moved = false;
        for (int attempt = 0; attempt < 4 && !moved; ++attempt) {
            bool ok;
            if (attempt == 0) {
                std::vector<real> rhs(n);
                for (std::size_t i = 0; i < n; ++i) rhs[i] = -phi[i];
                ok = solve_linear(G, rhs, d);
            } else {
                std::vector<real> M(n * n, 0), g(n, 0);
                real tr = 0;
                for (std::size_t i = 0; i < n; ++i)
                    for (std::size_t j = 0; j < n; ++j) {
                        real s = 0;
                        for (std::size_t k = 0; k < n; ++k) s += G[k * n + i] * G[k * n + j];
                        M[i * n + j] = s;
                    }
                for (std::size_t i = 0; i < n; ++i) tr += M[i * n + i];
                const real lambda = (tr / n) * (attempt == 1 ? 1e-8L : attempt == 2 ? 1e-4L : 1);
                for (std::size_t i = 0; i < n; ++i) {
                    M[i * n + i] += lambda;
                    real s = 0;
                    for (std::size_t k = 0; k < n; ++k) s += G[k * n + i] * phi[k];
                    g[i] = -s;
                }
                ok = solve_linear(M, g, d);
            }
            if (!ok) continue;
            real t = 1;
            for (int ls = 0; ls < 50; ++ls, t /= 2) {
                trial = r;
                for (std::size_t i = 0; i < n; ++i) trial[i] += t * d[i];
                alart_curnier(W, q, mu, rho, trial, phi_trial, nullptr);
                const real mt = squared(phi_trial);
                if (mt <= (1 - 2 * sigma * t) * merit) {
                    moved = true;
                    break;
                }
            }
        }
        if (!moved) break;  // stalled (or at the rounding floor)
        r = trial;
        alart_curnier(W, q, mu, rho, r, phi, &G);
        merit = squared(phi);
    }
    const real res = residual(W, q, mu, r);
    if (res < best_res) {
        best_res = res;
        best = r;
    }
    return steps;
}

}  // namespace detail

// |F(r)|_2, F(r)_i = r_i - P_K(r_i - u~_i), u = W r + q, u~_i = u_i + (mu_i |u_t,i|, 0, 0).
inline long double natural_map_residual(const std::vector<long double>& W,
                                        const std::vector<long double>& q,
                                        const std::vector<long double>& mu,
                                        const std::vector<long double>& r) {
    return detail::residual(W, q, mu, r);
}

inline result solve(const std::vector<long double>& W, const std::vector<long double>& q,
                    const std::vector<long double>& mu, long double tolerance = 1e-15L) {
    const std::size_t m = mu.size(), n = 3 * m;
    const real target = tolerance * std::max<real>(1, detail::norm(q));
    std::vector<real> best(n, 0);
    real best_res = detail::residual(W, q, mu, best);
    int iterations = 0;
    std::vector<real> rho0(m);
    for (std::size_t i = 0; i < m; ++i) {
        const std::size_t o = 3 * i;
        const real tr = W[o * n + o] + W[(o + 1) * n + o + 1] + W[(o + 2) * n + o + 2];
        rho0[i] = tr > 0 ? 3 / tr : 1;
    }
    constexpr std::array<int, 6> sweeps{30, 200, 1000, 3000, 10000, 10000};
    constexpr std::array<real, 6> factors{1, 0.1L, 10, 0.01L, 100, 1};
    for (std::size_t round = 0; round < sweeps.size() && best_res > target; ++round) {
        std::vector<real> r = best;
        const real pgs_stop = std::max(target, 1e-10L * std::max<real>(1, detail::norm(q)));
        iterations += detail::pgs(W, q, mu, r, sweeps[round], pgs_stop);
        const real res = detail::residual(W, q, mu, r);
        if (res < best_res) {
            best_res = res;
            best = r;
        }
        std::vector<real> rho(m);
        for (std::size_t i = 0; i < m; ++i) rho[i] = rho0[i] * factors[round];
        iterations += detail::newton(W, q, mu, rho, r, best, best_res, target, 200);
    }
    return {best, best_res, iterations, best_res <= target};
}

}  // namespace fc3d_reference
