// The frictional contact problem of one step, and its solver.
//
// m contacts, each in its frame (n, t1, t2). The impulses r = (r_1 … r_m), r_i ∈ R³, and the
// velocities after the step
//     u = W r + q,
// W = J M⁻¹ Jᵀ the Delassus operator (J's rows: each contact's normal and tangent lines, co-screws,
// paired with the bodies' screws; M⁻¹ the bodies' mobility) and q the contact velocities the step
// gives without contact (Acary, Brémond and Huber 2018; Siconos' and FCLIB's "fc3d"). Find r with,
// for every contact,
//     K_μi ∋ r_i ⊥ ũ_i ∈ K*_μi          (friction_cone.hpp: ũ = u + μ ‖u_t‖ e_n)
// that is, each contact takes off (r_i = 0, u_n ≥ 0), sticks (u_i = 0, r_i ∈ K_μi) or slides
// (r_i on the cone's boundary, u_n = 0, r_t = −μ r_n u_t / ‖u_t‖).
//
// The solver is nonsmooth Gauss–Seidel (Jean and Moreau's NSGS): a sweep solves each contact's own
// problem exactly with the others' impulses held (one_contact); sweeps go on until the natural-map
// residual ‖F(r)‖₂ (F_i = r_i − P_K(r_i − ũ_i)) is at most the tolerance the caller picks, or the
// sweep budget is spent. The report says which: the residual reached, the sweeps, converged.
// r is the caller's storage, its contents the warm start (zeros, or the previous step's impulses by
// contact id); no allocation. With scratch of 6m numbers the sweeps are accelerated by conjugate
// directions (Silcowitz, Niebe and Erleben's nonsmooth nonlinear conjugate gradient: each sweep's
// change plus β times the last direction, restarted when β > 1; the same fixed points). Measured
// from rest on pyramids of cubes (tolerance 1e-6): 30 % fewer sweeps (base 20: 82,899 → 56,364).
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <numbers>
#include <span>
#include <cstdint>

#include "ctga/constraints/friction_cone.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/team.hpp"

namespace ctga::constraints {

// What the solver needs of W and q: the contact count, W's diagonal block W_ii (symmetric positive
// definite), contact i's velocity (W r + q)_i at the impulses r, and `apply(i, dr)` after r_i
// changed by dr (an operator that keeps the bodies' velocities updates them; a dense one has
// nothing to do).
template <class D, class T>
concept delassus_operator = requires(const D& c, D& d, std::size_t i, std::span<const T> r, const vec3<T>& dr) {
    { c.contacts() } -> std::convertible_to<std::size_t>;
    { c.block(i) } -> std::convertible_to<mat3<T>>;
    { c.velocity(i, r) } -> std::convertible_to<vec3<T>>;
    d.apply(i, dr);
};

// A block may instead be bilateral (a spherical joint's three rows: r free, u = 0): an operator
// says so by `bilateral(i)`; one without that member has contacts only. A bilateral block's cone is
// all of R³, its dual {0}: its natural map is F = u, and a sweep solves it exactly, r ← r − A⁻¹ u.
template <class D>
[[nodiscard]] constexpr bool is_bilateral(const D& W, std::size_t i) noexcept {
    if constexpr (requires { W.bilateral(i); }) return W.bilateral(i);
    else return false;
}
// A block may be bounded (a joint's limits and motor: each row's impulse in an interval), which
// an operator says by `bounded(i)` and `bounds(i)` (lower, upper). Its natural map is
// F_k = r_k − clamp(r_k − u_k, lower_k, upper_k), and a sweep solves its rows one by one,
// r_k ← clamp(r_k − u_k / A_kk, lower_k, upper_k), u updated by A's column k.
template <class D>
[[nodiscard]] constexpr bool is_bounded(const D& W, std::size_t i) noexcept {
    if constexpr (requires { W.bounded(i); }) return W.bounded(i);
    else return false;
}
template <class T, class D>
[[nodiscard]] constexpr std::array<vec3<T>, 2> bounds_of(const D& W, std::size_t i) noexcept {
    if constexpr (requires { W.bounds(i); }) return W.bounds(i);
    else return {};
}
template <class T>
[[nodiscard]] constexpr T clamp_to(const T& x, const T& lower, const T& upper) noexcept {
    return x < lower ? lower : (x > upper ? upper : x);
}
template <class T>
[[nodiscard]] constexpr vec3<T> box_map(const vec3<T>& r, const vec3<T>& u, const std::array<vec3<T>, 2>& b) noexcept {
    vec3<T> F;
    for (std::size_t k = 0; k < 3; ++k) F[k] = r[k] - clamp_to(r[k] - u[k], b[0][k], b[1][k]);
    return F;
}
template <class T>
[[nodiscard]] constexpr vec3<T> bounded_step(const mat3<T>& A, vec3<T> u, const std::array<vec3<T>, 2>& b, vec3<T> r) noexcept {
    for (std::size_t k = 0; k < 3; ++k) {
        const T next = A[k][k] > T(0) ? clamp_to(r[k] - u[k] / A[k][k], b[0][k], b[1][k]) : clamp_to(r[k], b[0][k], b[1][k]);
        const T d = next - r[k];
        r[k] = next;
        for (std::size_t j = 0; j < 3; ++j) u[j] += A[j][k] * d;
    }
    return r;
}
// W_ii⁻¹ for a bilateral block: the operator's own when it keeps one (inverse_block), else by cofactors.
template <class D>
[[nodiscard]] constexpr auto inverse_block(const D& W, std::size_t i) noexcept {
    if constexpr (requires { W.inverse_block(i); }) return W.inverse_block(i);
    else return linear3::inverse_symmetric(W.block(i));
}

// W (3m × 3m, row-major) and q (3m) given densely: a problem as Siconos and FCLIB store it.
template <class T>
struct dense_delassus {
    std::span<const T> W, q;

    [[nodiscard]] constexpr std::size_t contacts() const noexcept { return q.size() / 3; }
    [[nodiscard]] constexpr mat3<T> block(std::size_t i) const noexcept {
        const std::size_t n = q.size();
        mat3<T> out{};
        for (std::size_t a = 0; a < 3; ++a)
            for (std::size_t b = 0; b < 3; ++b) out[a][b] = W[(3 * i + a) * n + 3 * i + b];
        return out;
    }
    [[nodiscard]] constexpr vec3<T> velocity(std::size_t i, std::span<const T> r) const noexcept {
        const std::size_t n = q.size();
        vec3<T> u{q[3 * i], q[3 * i + 1], q[3 * i + 2]};
        for (std::size_t a = 0; a < 3; ++a)
            for (std::size_t k = 0; k < n; ++k) u[a] += W[(3 * i + a) * n + k] * r[k];
        return u;
    }
    constexpr void apply(std::size_t, const vec3<T>&) noexcept {}
};

// How a sweep treats one contact: `exact` solves its own problem (one_contact); `projected` takes
// one projected step, the normal impulse then the tangential one (below): cheaper, and with the
// same fixed points, so the same solutions when the sweeps converge.
enum class local_solve : unsigned char { exact, projected };

template <class T>
struct contact_settings {
    T tolerance = T(1e-10);        // on ‖F(r)‖₂, in the impulses' units
    std::size_t max_sweeps = 1000;
    local_solve local = local_solve::exact;
    std::size_t check_every = 1;   // sweeps between two evaluations of the residual (a pass as costly as a sweep)
};

template <class T>
struct contact_report {
    error_code error = error_code::none;
    T residual = T(0);  // ‖F(r)‖₂ at the impulses returned
    std::size_t sweeps = 0;
    std::size_t polish_steps = 0;  // Newton steps after the sweeps (newton_polish.hpp)
    bool converged = false;
};

namespace contact_detail {
template <class T>
[[nodiscard]] constexpr T absolute(const T& x) noexcept {
    return x < T(0) ? -x : x;
}
// For the slip direction d = (cos θ, sin θ): r = r_n (1, −μ d) with u_n = 0, that is r_n = −b_n /
// (A g)_n, g = (1, −μ d); and w = (A g)_n u_t = (A g)_n b_t − b_n (A g)_t, which points as u_t
// where (A g)_n > 0 but has no pole where (A g)_n = 0 (r_n unbounded): its cross and dot products
// with d are smooth in θ. Taken at d itself (a unit vector), so no angle is ever turned into one.
template <class T>
struct slide_at {
    vec3<T> r;
    T cross, along;  // w × d, w · d
    bool valid;      // (A g)_n > 0: r_n > 0 (b_n < 0)
};
template <class T>
[[nodiscard]] constexpr slide_at<T> slide(const mat3<T>& A, const vec3<T>& b, const T& mu, const std::array<T, 2>& d) noexcept {
    const vec3<T> g{T(1), -mu * d[0], -mu * d[1]};
    const vec3<T> Ag = linear3::apply(A, g);
    const T w1 = Ag[0] * b[1] - b[0] * Ag[1], w2 = Ag[0] * b[2] - b[0] * Ag[2];
    const bool valid = Ag[0] > T(0);
    return {linear3::scale(valid ? -b[0] / Ag[0] : T(0), g), w1 * d[1] - w2 * d[0], w1 * d[0] + w2 * d[1], valid};
}
// The 64 sample directions (cos, sin of 2πk/64), two more to wrap around; constant-evaluated.
inline constexpr std::size_t circle_samples = 64;
template <class T>
inline constexpr std::array<std::array<T, 2>, circle_samples + 2> circle = [] {
    std::array<std::array<T, 2>, circle_samples + 2> out{};
    for (std::size_t k = 0; k < out.size(); ++k) {
        const math::cos_sin_pair<T> cs = math::cos_sin(T(2) * std::numbers::pi_v<T> * T(k % circle_samples) / T(circle_samples));
        out[k] = {cs.cos, cs.sin};
    }
    return out;
}();
// The direction a fraction t ∈ [0, 1] of the way from p to q (less than π apart): p + t (q − p)
// normalised, which turns monotonically from p to q as t grows (a search over t is one over the
// angle between them).
template <class T>
[[nodiscard]] constexpr std::array<T, 2> between(const std::array<T, 2>& p, const std::array<T, 2>& q, const T& t) noexcept {
    const T x = p[0] + t * (q[0] - p[0]), y = p[1] + t * (q[1] - p[1]);
    const T scale = T(1) / math::sqrt(x * x + y * y);
    return {x * scale, y * scale};
}
}  // namespace contact_detail

// One contact's problem with the others' impulses held: u = A r + b (A = W_ii, symmetric positive
// definite; b the velocity at r = 0), solved exactly:
//   take-off when b_n ≥ 0: r = 0 (then ũ_n = b_n + μ ‖b_t‖ ≥ μ ‖b_t‖, in K*);
//   stick when r = −A⁻¹ b lies in K_μ (u = 0);
//   else it slides: r = r_n (1, −μ d), d the unit slip direction; u_n = 0 fixes r_n for each d,
//   and d = (cos θ, sin θ) must make u_t a positive multiple of d: θ is a root of w × d (below),
//   a trigonometric polynomial of degree 2 (at most four roots), found as the sampling below says.
// μ = 0 slides along n only: r = (−b_n / A_nn, 0, 0).
template <class T>
[[nodiscard]] constexpr vec3<T> one_contact(const mat3<T>& A, const vec3<T>& b, const T& mu) noexcept {
    if (b[0] >= T(0)) return {T(0), T(0), T(0)};
    if (mu == T(0)) return {-b[0] / A[0][0], T(0), T(0)};
    const vec3<T> stick = linear3::scale(T(-1), linear3::apply(linear3::inverse_symmetric(A), b));
    if (tangential_norm(stick) <= mu * stick[0]) return stick;
    // h = w × d sampled at 64 directions; a root is found by regula falsi (Illinois: the end that
    // stays has its value halved, superlinear, the bracket kept) where h changes sign, and |h| is
    // minimised by golden section where it has a local minimum without a change of sign on either
    // side (a double root: h touches zero, where sliding meets sticking), both over the fraction t
    // between two sample directions (contact_detail::between). Each candidate is scored by the
    // natural map, the least kept.
    using contact_detail::between, contact_detail::slide;
    constexpr std::size_t samples = contact_detail::circle_samples;
    constexpr const auto& circle = contact_detail::circle<T>;
    std::array<T, samples + 2> h{};
    for (std::size_t k = 0; k < samples + 2; ++k) h[k] = slide(A, b, mu, circle[k]).cross;
    vec3<T> best{T(0), T(0), T(0)};
    T best_residual = T(-1);
    const auto consider = [&](const std::array<T, 2>& d) {
        const contact_detail::slide_at<T> at = slide(A, b, mu, d);
        const vec3<T> F = natural_map(at.r, linear3::add(linear3::apply(A, at.r), b), mu);
        const T res = linear3::dot(F, F);
        if (at.valid && (best_residual < T(0) || res < best_residual)) best = at.r, best_residual = res;
    };
    for (std::size_t k = 1; k <= samples; ++k) {
        const bool falls = (h[k - 1] <= T(0)) != (h[k] <= T(0)), rises = (h[k] <= T(0)) != (h[k + 1] <= T(0));
        if (falls) {
            const auto& p = circle[k - 1];
            const auto& q = circle[k];
            T lo = T(0), hi = T(1), f_lo = h[k - 1], f_hi = h[k], t = T(0);
            int kept = 0;  // which end stayed last time (−1 lo, +1 hi)
            for (int it = 0; it < 100; ++it) {
                T next = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
                if (!(next > lo && next < hi)) next = (lo + hi) / T(2);
                if (next <= lo || next >= hi || next == t) break;
                t = next;
                const T f = slide(A, b, mu, between(p, q, t)).cross;
                if (f == T(0)) break;
                if ((f <= T(0)) == (f_lo <= T(0))) {
                    lo = t, f_lo = f;
                    if (kept == 1) f_hi /= T(2);
                    kept = 1;
                } else {
                    hi = t, f_hi = f;
                    if (kept == -1) f_lo /= T(2);
                    kept = -1;
                }
            }
            consider(between(p, q, t));
        }
        if (!falls && !rises && contact_detail::absolute(h[k]) <= contact_detail::absolute(h[k - 1]) &&
            contact_detail::absolute(h[k]) <= contact_detail::absolute(h[k + 1])) {
            const auto& p = circle[k - 1];
            const auto& q = circle[k + 1];
            const auto size = [&](const T& t) { return contact_detail::absolute(slide(A, b, mu, between(p, q, t)).cross); };
            constexpr T golden = T(0.6180339887498948482);
            T lo = T(0), hi = T(1);
            T x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo), f1 = size(x1), f2 = size(x2);
            for (int it = 0; it < 100 && hi - lo > T(0); ++it) {
                if (f1 <= f2) hi = x2, x2 = x1, f2 = f1, x1 = hi - golden * (hi - lo), f1 = size(x1);
                else lo = x1, x1 = x2, f1 = f2, x2 = lo + golden * (hi - lo), f2 = size(x2);
            }
            consider(between(p, q, (lo + hi) / T(2)));
        }
    }
    return best;
}

// One projected step for a contact of block A at its impulse r and velocity u: the normal impulse
// r_n ← max(0, r_n − u_n / A_nn), then, with u updated, the tangential one
// r_t ← P(r_t − u_t / ρ) on the disc ‖r_t‖ ≤ μ r_n, ρ = (A_t1t1 + A_t2t2) / 2. Its fixed points
// are Coulomb's law: 0 ≤ r_n ⊥ u_n ≥ 0, and r_t inside the disc with u_t = 0 or on its rim
// opposite to u_t (maximal dissipation), that is K_μ ∋ r ⊥ ũ ∈ K*_μ. The step lengths 1/A_nn and
// 1/ρ are the block's (step_lengths), which an operator may keep with its rows: a sweep then
// divides only where the disc clips.
template <class T>
[[nodiscard]] constexpr std::array<T, 2> step_lengths(const mat3<T>& A) noexcept {
    return {T(1) / A[0][0], T(2) / (A[1][1] + A[2][2])};
}
// The tangential half, at the new normal impulse rn: W_t1n and W_t2n couple it to the normal
// change, `length` is 1/ρ. In scalars or in the lanes of a pack (the soft step's: soft_step.hpp).
template <class S>
[[nodiscard]] constexpr vec3<S> friction_step(const S& coupling_1, const S& coupling_2, const vec3<S>& u, const S& mu, const vec3<S>& r,
                                              const S& rn, const S& length) noexcept {
    const S dn = rn - r[0];
    S t1 = r[1] - (u[1] + coupling_1 * dn) * length, t2 = r[2] - (u[2] + coupling_2 * dn) * length;
    const S squared = t1 * t1 + t2 * t2, limit = mu * rn;
    if constexpr (lane_wise<S>) {
        const auto over = squared > limit * limit;
        const S s = select(over, limit / math::sqrt(select(over, squared, S(1))), S(1));
        t1 *= s, t2 *= s;
    } else if (squared > limit * limit) {
        const S s = limit / math::sqrt(squared);
        t1 *= s, t2 *= s;
    }
    return {rn, t1, t2};
}
template <class T>
[[nodiscard]] constexpr vec3<T> projected_step(const mat3<T>& A, const vec3<T>& u, const T& mu, const vec3<T>& r,
                                               const std::array<T, 2>& length) noexcept {
    const T rn = r[0] - u[0] * length[0];
    return friction_step(A[1][0], A[2][0], u, mu, r, rn > T(0) ? rn : T(0), length[1]);
}
template <class D>
[[nodiscard]] constexpr auto step_lengths_of(const D& W, std::size_t i) noexcept {
    if constexpr (requires { W.step_lengths(i); }) return W.step_lengths(i);
    else return step_lengths(W.block(i));
}

// An order of the rows in parts, and the parts in phases: part p is order[part_start[p] ..
// part_start[p + 1]), phase f the parts [phase_start[f], phase_start[f + 1]). The parts of a phase
// share no moving body, so the team's threads sweep them at once, each part in its order; the
// phases follow one another. With m numbers for the residual's terms.
template <class T>
struct sweep_schedule {
    std::span<const std::uint32_t> order;
    std::span<const std::uint32_t> part_start;
    std::span<const std::uint32_t> phase_start;
    team* crew = nullptr;
    std::span<T> partial;
};

// f(i) for the m rows: in order, or phase by phase of the schedule, the parts of a phase at once
// (f may change the bodies of its row: no two parts of a phase share one).
template <class T, class F>
void for_each_row(const sweep_schedule<T>* schedule, std::size_t m, F&& f) {
    if (schedule == nullptr || schedule->phase_start.empty()) {
        for (std::size_t i = 0; i < m; ++i) f(i);
        return;
    }
    for (std::size_t phase = 0; phase + 1 < schedule->phase_start.size(); ++phase) {
        const std::size_t first = schedule->phase_start[phase], parts = schedule->phase_start[phase + 1] - first;
        const auto sweep_parts = [&](std::size_t begin, std::size_t end) {
            for (std::size_t p = first + begin; p < first + end; ++p)
                for (std::size_t k = schedule->part_start[p]; k < schedule->part_start[p + 1]; ++k) f(std::size_t{schedule->order[k]});
        };
        if (schedule->crew != nullptr && parts > 1) schedule->crew->run_parts(parts, sweep_parts);
        else sweep_parts(0, parts);
    }
}

// Sweeps of nonsmooth Gauss–Seidel from the impulses in r (the warm start) until ‖F(r)‖₂ ≤ the
// tolerance. Refused before any sweep: a non-finite μ, W block, velocity or impulse (non_finite),
// μ < 0 (negative_friction), a block whose normal entry is not positive (not_positive_definite),
// r of the wrong size (size_mismatch); r is then left as given.
template <class T, class D>
    requires delassus_operator<D, T>
constexpr contact_report<T> solve_contacts(D& W, std::span<const T> mu, std::span<T> r, const contact_settings<T>& settings = {},
                                           std::span<T> scratch = {}, const sweep_schedule<T>* schedule = nullptr) noexcept {
    const std::size_t m = W.contacts();
    contact_report<T> report;
    if (mu.size() != m || r.size() != 3 * m) return report.error = error_code::size_mismatch, report;
    for (std::size_t i = 0; i < m; ++i) {  // (the velocities: by the first residual, below)
        const mat3<T> A = W.block(i);
        if (!all_finite(mu[i], A[0][0], A[0][1], A[0][2], A[1][1], A[1][2], A[2][2], r[3 * i], r[3 * i + 1], r[3 * i + 2]))
            return report.error = error_code::non_finite, report;
        if (mu[i] < T(0) && !is_bilateral(W, i) && !is_bounded(W, i)) return report.error = error_code::negative_friction, report;
        if (!(A[0][0] > T(0))) return report.error = error_code::not_positive_definite, report;
    }
    // Row by row, or phase by phase of the schedule (the parts of a phase at once, by the team's
    // threads); sums over rows are made in row order, so that the result does not depend on the
    // number of threads.
    const bool coloured = schedule != nullptr && !schedule->phase_start.empty();
    const auto each_row = [&](auto&& f) { for_each_row(schedule, m, f); };
    const auto term = [&](std::size_t i) {  // ‖F_i‖²
        const vec3<T> u = W.velocity(i, std::span<const T>(r));
        const vec3<T> ri{r[3 * i], r[3 * i + 1], r[3 * i + 2]};
        const vec3<T> F = is_bounded(W, i) ? box_map(ri, u, bounds_of<T>(W, i)) : is_bilateral(W, i) ? u : natural_map(ri, u, mu[i]);
        return linear3::dot(F, F);
    };
    const auto residual = [&] {
        T sum = T(0);
        if (!coloured) {
            for (std::size_t i = 0; i < m; ++i) sum += term(i);
            return math::sqrt(sum);
        }
        const auto rows = [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) schedule->partial[i] = term(i);
        };
        if (schedule->crew != nullptr) schedule->crew->run(m, rows);
        else rows(0, m);
        for (std::size_t i = 0; i < m; ++i) sum += schedule->partial[i];
        return math::sqrt(sum);
    };
    report.residual = residual();
    if (!is_finite(report.residual)) return report.error = error_code::non_finite, report;  // a velocity is not finite
    const std::size_t every = settings.check_every > 0 ? settings.check_every : 1;
    // the conjugate directions of the nonsmooth nonlinear CG (with scratch of 6m numbers)
    const bool conjugate = scratch.size() >= 6 * m;
    std::span<T> direction = conjugate ? scratch.subspan(0, 3 * m) : scratch, change = conjugate ? scratch.subspan(3 * m, 3 * m) : scratch;
    for (T& x : direction) x = T(0);
    T previous = T(0);
    while (report.residual > settings.tolerance && report.sweeps < settings.max_sweeps) {
        each_row([&](std::size_t i) {
            const vec3<T> old{r[3 * i], r[3 * i + 1], r[3 * i + 2]};
            const vec3<T> u = W.velocity(i, std::span<const T>(r));
            vec3<T> next;
            if (is_bounded(W, i)) next = bounded_step(W.block(i), u, bounds_of<T>(W, i), old);
            else if (is_bilateral(W, i)) next = linear3::sub(old, linear3::apply(inverse_block(W, i), u));
            else if (settings.local == local_solve::projected) next = projected_step(W.block(i), u, mu[i], old, step_lengths_of(W, i));
            else {
                const mat3<T> A = W.block(i);
                next = one_contact(A, linear3::sub(u, linear3::apply(A, old)), mu[i]);
            }
            const vec3<T> d = linear3::sub(next, old);
            for (std::size_t a = 0; a < 3; ++a) r[3 * i + a] = next[a];
            W.apply(i, d);
            if (conjugate)
                for (std::size_t a = 0; a < 3; ++a) change[3 * i + a] = d[a];
        });
        ++report.sweeps;
        if (conjugate && report.sweeps < settings.max_sweeps) {
            // Silcowitz, Niebe and Erleben 2010: the sweep's change g_k; β = ‖g_k‖² / ‖g_{k−1}‖², a
            // restart when β > 1; else the step β p_{k−1} is taken as well and p_k = β p_{k−1} + g_k
            T moved = T(0);
            for (std::size_t i = 0; i < 3 * m; ++i) moved += change[i] * change[i];
            const T beta = previous > T(0) ? moved / previous : T(2);
            previous = moved;
            each_row([&](std::size_t i) {
                vec3<T> step{};
                if (beta <= T(1)) {
                    for (std::size_t a = 0; a < 3; ++a) step[a] = beta * direction[3 * i + a], r[3 * i + a] += step[a];
                    W.apply(i, step);
                }
                for (std::size_t a = 0; a < 3; ++a) direction[3 * i + a] = step[a] + change[3 * i + a];
            });
        }
        if (report.sweeps % every == 0 || report.sweeps == settings.max_sweeps) report.residual = residual();
    }
    // the conjugate step can leave an impulse just outside its cone or bounds (a contact lifting
    // off: r_n = −4e-16): each such impulse is returned projected on its set, and the residual is
    // that of the impulses returned
    if (conjugate && is_finite(report.residual)) {
        bool moved = false;
        for (std::size_t i = 0; i < m; ++i) {
            if (is_bilateral(W, i)) continue;
            const vec3<T> ri{r[3 * i], r[3 * i + 1], r[3 * i + 2]};
            vec3<T> in = ri;
            if (is_bounded(W, i)) {
                const std::array<vec3<T>, 2> b = bounds_of<T>(W, i);
                for (std::size_t a = 0; a < 3; ++a) in[a] = clamp_to(ri[a], b[0][a], b[1][a]);
            } else {
                in = project_on_cone(ri, mu[i]);
            }
            if (in == ri) continue;
            moved = true;
            for (std::size_t a = 0; a < 3; ++a) r[3 * i + a] = in[a];
            W.apply(i, linear3::sub(in, ri));
        }
        if (moved) report.residual = residual();
    }
    report.converged = report.residual <= settings.tolerance;
    if (!is_finite(report.residual)) report.error = error_code::non_finite;
    return report;
}

}  // namespace ctga::constraints
