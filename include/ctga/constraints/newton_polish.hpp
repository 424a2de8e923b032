// The last digits of a contact problem (contact_problem.hpp) by semismooth Newton on Alart and
// Curnier's function, for a problem small enough to hold W densely (an island of a few dozen
// contacts). Sweeps of Gauss–Seidel shrink the residual by a factor that tends to 1 as W grows
// ill-conditioned (a heavy box on a light one: about 1,000 sweeps per decade at a mass ratio of
// 1:1000, measured); Newton from their result converges in a few steps.
//
// For u = W r + q and ρ > 0 (per contact), Alart and Curnier's function is, per contact,
//     ϕ_n = r_n − max(0, x_n),                          x_n = r_n − ρ u_n
//     ϕ_t = r_t − P_D(r_t − ρ u_t),                     D the disc of radius μ max(0, x_n),
// zero exactly at the solutions of the problem (Alart and Curnier 1991; Acary, Brémond and Huber
// 2018). It is piecewise smooth; each step solves G Δr = −ϕ with G an element of its generalized
// Jacobian, then halves the step until ‖ϕ‖² decreases enough (Armijo). Redundant contacts (a
// box's four corners on a face: W of rank 6 for 12 rows) make G singular on sticking contacts;
// G + δ·1 (δ = 1e-12 × the largest entry of ρ W) picks one of the equivalent impulses, and where
// its step does not descend a Levenberg–Marquardt step does. The impulses returned are the best
// (least natural-map residual) seen, so a polish never leaves a problem worse than it found it.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "ctga/constraints/contact_problem.hpp"
#include "ctga/constraints/friction_cone.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/math.hpp"

namespace ctga::constraints {

// Scratch for a problem of up to `contacts` contacts: 2 (3m)² + 5·3m numbers.
[[nodiscard]] constexpr std::size_t newton_scratch_size(std::size_t contacts) noexcept {
    return 18 * contacts * contacts + 16 * contacts;
}

// A block's kind for newton_polish: a contact's cone, a bilateral block, a bounded one.
inline constexpr unsigned char contact_block = 0, bilateral_block = 1, bounded_block = 2;

namespace newton_detail {
template <class T>
[[nodiscard]] constexpr T absolute(const T& x) noexcept {
    return x < T(0) ? -x : x;
}

// ϕ at r (and, when G is not empty, a generalized Jacobian of it, row-major n × n).
// With the proximal term: u = W r + q + ε (r − c), c the centre.
// A bilateral block (kind[i] = bilateral_block) is on the pressed, sticking piece everywhere:
// ϕ = ρ u. A bounded one's rows each ϕ_a = r_a − clamp(r_a − ρ u_a, lower_a, upper_a).
template <class T>
constexpr void alart_curnier(std::span<const T> W, std::span<const T> q, std::span<const T> mu, std::span<const T> rho,
                             const T& eps, std::span<const T> c, std::span<const T> r, std::span<T> phi, std::span<T> G,
                             std::span<const unsigned char> kind, std::span<const std::array<vec3<T>, 2>> bounds) noexcept {
    const std::size_t n = q.size(), m = n / 3;
    for (std::size_t i = 0; i < m; ++i) {
        vec3<T> u{q[3 * i], q[3 * i + 1], q[3 * i + 2]};
        for (std::size_t a = 0; a < 3; ++a) {
            for (std::size_t k = 0; k < n; ++k) u[a] += W[(3 * i + a) * n + k] * r[k];
            u[a] += eps * (r[3 * i + a] - c[3 * i + a]);
        }
        const T p = rho[i];
        const vec3<T> ri{r[3 * i], r[3 * i + 1], r[3 * i + 2]};
        const T xn = ri[0] - p * u[0];
        const T x1 = ri[1] - p * u[1], x2 = ri[2] - p * u[2];
        const T radius = mu[i] * (xn > T(0) ? xn : T(0));
        const T length = math::sqrt(x1 * x1 + x2 * x2);
        if (!kind.empty() && kind[i] == bounded_block) {
            for (std::size_t a = 0; a < 3; ++a) {
                const T x = ri[a] - p * u[a], lo = bounds[i][0][a], hi = bounds[i][1][a];
                const bool free = lo < x && x < hi;
                phi[3 * i + a] = ri[a] - clamp_to(x, lo, hi);
                if (G.empty()) continue;
                for (std::size_t k = 0; k < n; ++k)
                    G[(3 * i + a) * n + k] = (k == 3 * i + a ? T(1) : T(0)) - (free ? (k == 3 * i + a ? T(1) - p * eps : T(0)) - p * W[(3 * i + a) * n + k] : T(0));
            }
            continue;
        }
        const bool both = !kind.empty() && kind[i] == bilateral_block;
        const bool pressed = both || xn >= T(0), inside = both || length <= radius;  // at a tie, the active piece
        phi[3 * i] = ri[0] - (pressed ? xn : T(0));
        if (inside) phi[3 * i + 1] = ri[1] - x1, phi[3 * i + 2] = ri[2] - x2;
        else {
            const T s = length > T(0) ? radius / length : T(0);
            phi[3 * i + 1] = ri[1] - s * x1, phi[3 * i + 2] = ri[2] - s * x2;
        }
        if (G.empty()) continue;
        // rows of ∂x/∂r: e_a − ρ W_a
        const auto dx = [&](std::size_t a, std::size_t k) {
            return (k == 3 * i + a ? T(1) - p * eps : T(0)) - p * W[(3 * i + a) * n + k];
        };
        for (std::size_t k = 0; k < n; ++k) {
            const T e0 = k == 3 * i ? T(1) : T(0), e1 = k == 3 * i + 1 ? T(1) : T(0), e2 = k == 3 * i + 2 ? T(1) : T(0);
            G[(3 * i) * n + k] = e0 - (pressed ? dx(0, k) : T(0));
            if (inside) {
                G[(3 * i + 1) * n + k] = e1 - dx(1, k);
                G[(3 * i + 2) * n + k] = e2 - dx(2, k);
            } else if (length > T(0)) {
                // P = μ x_n⁺ x_t / ‖x_t‖: ∂P = μ x̂ ∂x_n⁺ + (μ x_n⁺ / ‖x_t‖)(1 − x̂ x̂ᵀ) ∂x_t
                const T h1 = x1 / length, h2 = x2 / length, c = radius / length;
                const T dn = pressed ? mu[i] * dx(0, k) : T(0);
                const T d1 = dx(1, k), d2 = dx(2, k), along = h1 * d1 + h2 * d2;
                G[(3 * i + 1) * n + k] = e1 - (h1 * dn + c * (d1 - h1 * along));
                G[(3 * i + 2) * n + k] = e2 - (h2 * dn + c * (d2 - h2 * along));
            } else {
                G[(3 * i + 1) * n + k] = e1;
                G[(3 * i + 2) * n + k] = e2;
            }
        }
    }
}

template <class T>
[[nodiscard]] constexpr T squared(std::span<const T> x) noexcept {
    T s = T(0);
    for (const T& v : x) s += v * v;
    return s;
}

// G x = b in place (x returned in b) by Gaussian elimination with partial pivoting.
template <class T>
constexpr void solve_dense(std::span<T> G, std::span<T> b) noexcept {
    const std::size_t n = b.size();
    for (std::size_t c = 0; c < n; ++c) {
        std::size_t best = c;
        for (std::size_t r = c + 1; r < n; ++r)
            if (absolute(G[r * n + c]) > absolute(G[best * n + c])) best = r;
        if (best != c) {
            for (std::size_t k = 0; k < n; ++k) {
                const T t = G[c * n + k];
                G[c * n + k] = G[best * n + k], G[best * n + k] = t;
            }
            const T t = b[c];
            b[c] = b[best], b[best] = t;
        }
        const T pivot = G[c * n + c];
        if (pivot == T(0)) continue;
        for (std::size_t r = c + 1; r < n; ++r) {
            const T f = G[r * n + c] / pivot;
            if (f == T(0)) continue;
            for (std::size_t k = c; k < n; ++k) G[r * n + k] -= f * G[c * n + k];
            b[r] -= f * b[c];
        }
    }
    for (std::size_t c = n; c-- > 0;) {
        T s = b[c];
        for (std::size_t k = c + 1; k < n; ++k) s -= G[c * n + k] * b[k];
        b[c] = G[c * n + c] != T(0) ? s / G[c * n + c] : T(0);
    }
}
}  // namespace newton_detail

// Newton steps from the impulses in r until the natural-map residual (contact_problem.hpp's
// measure) is at most the tolerance, or max_steps steps. W (3m × 3m, row-major) and q as
// dense_delassus's; scratch of newton_scratch_size(m) numbers. The report counts Newton steps in
// `sweeps`.
// kind (empty: contacts only) gives each block's kind, bounds a bounded block's intervals.
template <class T>
constexpr contact_report<T> newton_polish(std::span<const T> W, std::span<const T> q, std::span<const T> mu, std::span<T> r,
                                          std::span<T> scratch, const T& tolerance, std::size_t max_steps = 30,
                                          std::span<const unsigned char> kind = {},
                                          std::span<const std::array<vec3<T>, 2>> bounds = {}) noexcept {
    const std::size_t n = q.size(), m = n / 3;
    contact_report<T> report;
    if (mu.size() != m || r.size() != n || scratch.size() < newton_scratch_size(m) || (!kind.empty() && kind.size() != m))
        return report.error = error_code::size_mismatch, report;
    for (std::size_t i = 0; i < kind.size(); ++i)
        if (kind[i] == bounded_block && bounds.size() != m) return report.error = error_code::size_mismatch, report;
    std::span<T> G = scratch.subspan(0, n * n), phi = scratch.subspan(n * n, n), step = scratch.subspan(n * n + n, n),
                 trial = scratch.subspan(n * n + 2 * n, n), best = scratch.subspan(n * n + 3 * n, n),
                 centre = scratch.subspan(n * n + 4 * n, n), rho = scratch.subspan(n * n + 5 * n, m);
    T largest = T(0);
    for (std::size_t i = 0; i < m; ++i) {
        const T trace = W[(3 * i) * n + 3 * i] + W[(3 * i + 1) * n + 3 * i + 1] + W[(3 * i + 2) * n + 3 * i + 2];
        rho[i] = T(3) / trace;
        largest = trace > largest ? trace : largest;
    }
    const T eps = T(1e-9) * largest;
    const dense_delassus<T> D{W, q};
    const auto residual = [&](std::span<const T> x) {
        T sum = T(0);
        for (std::size_t i = 0; i < m; ++i) {
            const vec3<T> u = D.velocity(i, x);
            const vec3<T> xi{x[3 * i], x[3 * i + 1], x[3 * i + 2]};
            const unsigned char k = kind.empty() ? contact_block : kind[i];
            const vec3<T> F = k == bounded_block ? box_map(xi, u, bounds[i]) : k == bilateral_block ? u : natural_map(xi, u, mu[i]);
            sum += linear3::dot(F, F);
        }
        return math::sqrt(sum);
    };
    T best_residual = residual(r);
    for (std::size_t i = 0; i < n; ++i) best[i] = r[i], centre[i] = r[i];
    report.residual = best_residual;
    while (report.residual > tolerance && report.sweeps < max_steps) {
        ++report.sweeps;
        newton_detail::alart_curnier<T>(W, q, mu, rho, eps, centre, r, phi, G, kind, bounds);
        const T merit = newton_detail::squared<T>(phi);
        for (std::size_t i = 0; i < n; ++i) step[i] = -phi[i];
        newton_detail::solve_dense<T>(G, step);
        T t = T(1);
        bool descended = false;
        for (int halving = 0; halving < 20 && !descended; ++halving, t /= T(2)) {
            for (std::size_t i = 0; i < n; ++i) trial[i] = r[i] + t * step[i];
            newton_detail::alart_curnier<T>(W, q, mu, rho, eps, centre, trial, phi, {}, kind, bounds);
            descended = newton_detail::squared<T>(phi) <= (T(1) - T(1e-4) * t) * merit;
        }
        for (std::size_t i = 0; i < n; ++i) r[i] = trial[i];
        // the proximal problem solved (or stuck): move its centre to the point reached
        newton_detail::alart_curnier<T>(W, q, mu, rho, eps, centre, r, phi, {}, kind, bounds);
        if (!descended || newton_detail::squared<T>(phi) <= T(1e-4) * merit)
            for (std::size_t i = 0; i < n; ++i) centre[i] = r[i];
        report.residual = residual(r);
        if (report.residual < best_residual) {
            best_residual = report.residual;
            for (std::size_t i = 0; i < n; ++i) best[i] = r[i];
        }
    }
    // never worse than it started: the best point seen
    for (std::size_t i = 0; i < n; ++i) r[i] = best[i];
    report.residual = best_residual;
    report.converged = report.residual <= tolerance;
    if (!is_finite(report.residual)) report.error = error_code::non_finite;
    return report;
}

}  // namespace ctga::constraints
