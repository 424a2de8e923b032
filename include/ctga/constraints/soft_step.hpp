// The soft step: a cheaper, approximate way through the rows of a step, for scenes that trade
// accuracy for time (Catto's "soft step", Box2D v3 and Box3D; the exact way is
// contact_problem.hpp's, to a tolerance).
//
// The step h is cut into n substeps of h_s = h / n, the rows (lines, blocks) built once. Each
// body keeps its displacement d over the step so far, a screw summed from its velocities,
// d = Σ h_s s; a row's gap is then its gap at the step's start plus the pairing of its lines
// with the displacements (§5: L(d), the distance along e the point has moved), C = φ + J d: the
// rows are not rebuilt, their gaps are kept current. A gap is a spring of frequency f and
// damping ratio ζ (ω = 2π f) taken implicitly over h_s: the impulse that brings the velocity u
// towards −ω C / (2ζ + h_s ω) is
//     Δr = −m_eff σ (u + β C) − τ r,   β = ω / (2ζ + h_s ω),  σ = a / (1 + a),  τ = 1 / (1 + a),
//     a = h_s ω (2ζ + h_s ω),
// m_eff = 1 / W_nn (Catto 2011, "Soft constraints"; the implicit Euler step of the spring and
// damper). A contact's normal row does so while it penetrates (C < 0, the push limited to a
// speed), is speculative while open (u ≥ −C / h_s: the gap may close, not be crossed, no spring),
// and its impulse stays ≥ 0 (on a soft surface, §7's K and D are the spring instead); its friction is Coulomb's disc, ‖r_t‖ ≤ μ r_n, by one projected
// step (contact_problem.hpp). A joint's block holds u + β C = 0 the same way (A⁻¹ for m_eff); a
// bounded block (limits, motor) takes the exact way's bounded step.
//
// Each substep: the free velocity's share, the impulses of the last substep applied again (the
// warm start), one sweep with the springs (`relax` false), the displacements moved on by h_s s,
// one sweep without them (`relax` true: the velocities the positions moved with are not the
// ones the step ends with, so the springs' push is not kept as velocity). A sweep goes colour by
// colour through groups of rows that share no body (row_colours.hpp), a group's rows at once in
// the lanes of a pack (soft_group). Nothing here measures convergence: there is no residual to
// report, only the gaps the scene ends with.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numbers>
#include <span>

#include "ctga/constraints/contact_problem.hpp"
#include "ctga/constraints/row_colours.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/pack.hpp"

namespace ctga::constraints {

// β, σ and τ of a spring of `hertz` and damping ratio `zeta` over a substep h_s (above).
template <class T>
struct softness {
    T bias_rate = T(0), mass_scale = T(1), impulse_scale = T(0);
};
template <class T>
[[nodiscard]] constexpr softness<T> make_soft(const T& hertz, const T& zeta, const T& h) noexcept {
    const T omega = T(2) * std::numbers::pi_v<T> * hertz;
    const T a1 = T(2) * zeta + h * omega, a2 = h * omega * a1, a3 = T(1) / (T(1) + a2);
    return {omega / a1, a2 * a3, a3};
}

// How one soft sweep treats its rows: the contacts' and the joints' springs, the largest speed a
// contact's spring pushes at, the substep, and whether this is the relaxing sweep.
template <class T>
struct soft_sweep_settings {
    softness<T> contact, joint;
    T push_speed = T(3);
    T substep = T(0);
    bool relax = false;
};

// One group of rows (row_colours.hpp: no two lanes share a body) with the sides' screws in
// lanes: each lane's new impulses from its velocity and its gaps C (g.gap), applied. A contact on
// a soft surface (scenes/couplings.hpp) is its own spring: its normal row is u_n + c r_n + b with
// b = k C / (h_s k + d) (g.spring_rate: k / (h_s k + d)), solved once a substep.
template <class T, std::size_t L>
CTGA_ALWAYS_INLINE void soft_group(row_group<T, L>& g, bool bilateral, lane_screws<T, L>& sa, lane_screws<T, L>& sb,
                                   const soft_sweep_settings<T>& s) noexcept {
    using P = pack<T, L>;
    vec3<P> u = group_velocity(g, sa, sb);
    for (std::size_t k = 0; k < 3; ++k) u[k] += g.surface[k];
    const vec3<P>& C = g.gap;
    const vec3<P> r = g.r;
    vec3<P> next;
    if (bilateral) {
        const softness<T> k = s.relax ? softness<T>{} : s.joint;
        vec3<P> target;
        for (std::size_t a = 0; a < 3; ++a) target[a] = P(k.mass_scale) * (u[a] + P(k.bias_rate) * C[a]);
        const std::array<P, 6>& A = g.inverse;  // W⁻¹, upper triangle
        const vec3<P> push{A[0] * target[0] + A[1] * target[1] + A[2] * target[2], A[1] * target[0] + A[3] * target[1] + A[4] * target[2],
                           A[2] * target[0] + A[4] * target[1] + A[5] * target[2]};
        for (std::size_t a = 0; a < 3; ++a) next[a] = r[a] - push[a] - P(k.impulse_scale) * r[a];
    } else {
        const P zero(T(0)), length = g.step_length[0];
        const P un = u[0] + g.compliance * r[0] + g.spring_rate * C[0];
        // rigid: speculative while open; else the spring (the relaxing sweep: none)
        const P spring = P(s.contact.bias_rate) * C[0], fastest(-s.push_speed);
        P rn = s.relax ? r[0] - un * length
                       : r[0] - P(s.contact.mass_scale) * (un + select(spring > fastest, spring, fastest)) * length -
                             P(s.contact.impulse_scale) * r[0];
        rn = select(C[0] > zero, r[0] - (un + C[0] / P(s.substep)) * length, rn);
        rn = select(g.compliance > zero, s.relax ? r[0] : r[0] - un * length, rn);
        rn = select(rn > zero, rn, zero);
        // the friction disc at the new normal impulse, by one projected step (contact_problem.hpp);
        // the tangential gaps as springs too, so that a sticking contact returns to where it held
        vec3<P> slip = u;
        if (!s.relax) slip[1] += P(s.contact.bias_rate) * C[1], slip[2] += P(s.contact.bias_rate) * C[2];
        next = friction_step(g.coupling_1, g.coupling_2, slip, g.mu, r, rn, g.step_length[1]);
    }
    const vec3<P> d{next[0] - r[0], next[1] - r[1], next[2] - r[2]};
    g.r = next;
    group_apply(g, d, sa, sb);
}

// The group's gaps now, C = C₀ + J d + t k: at the step's start, plus its lines paired with the
// sides' displacements d (§5: the distance the points have moved along e), plus a kinematic
// surface's speed k times the time t elapsed.
template <class T, std::size_t L>
CTGA_ALWAYS_INLINE void measure_gaps(row_group<T, L>& g, const lane_screws<T, L>& da, const lane_screws<T, L>& db, const T& elapsed) noexcept {
    const vec3<pack<T, L>> moved = group_velocity(g, da, db);
    for (std::size_t k = 0; k < 3; ++k) g.gap[k] = g.start[k] + moved[k] + pack<T, L>(elapsed) * g.surface[k];
}

}  // namespace ctga::constraints
