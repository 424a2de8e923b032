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
// warm start), one sweep with the springs (soft_sweep, `relax` false), the displacements moved
// on by h_s s, one sweep without them (`relax` true: the velocities the positions moved with are
// not the ones the step ends with, so the springs' push is not kept as velocity). Nothing here
// measures convergence: there is no residual to report, only the gaps the scene ends with.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numbers>
#include <span>

#include "ctga/constraints/contact_problem.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/math.hpp"

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

// A contact on a soft surface (scenes/couplings.hpp) is its own spring: its row's compliance c
// and offset b, kept current by the caller, replace the step's.
template <class D>
[[nodiscard]] constexpr auto compliance_of(const D& W, std::size_t i) noexcept {
    if constexpr (requires { W.compliance(i); }) return W.compliance(i);
    else return decltype(W.block(i)[0][0]){0};
}

// One sweep over the rows of W (its velocities current: rows_delassus), r the impulses of this
// substep, gap(i) row i's gaps now (C = φ + J d: a contact's normal gap in [0], a joint's three).
template <class T, class D, class Gap>
void soft_sweep(D& W, std::span<const T> mu, std::span<T> r, Gap&& gap, const soft_sweep_settings<T>& s,
                const sweep_schedule<T>* schedule = nullptr) noexcept {
    const auto body = [&](std::size_t i) {
        const vec3<T> old{r[3 * i], r[3 * i + 1], r[3 * i + 2]};
        const vec3<T> u = W.velocity(i, std::span<const T>(r));
        vec3<T> next;
        if (is_bounded(W, i)) {
            next = bounded_step(W.block(i), u, bounds_of<T>(W, i), old);
        } else if (is_bilateral(W, i)) {
            const softness<T> k = s.relax ? softness<T>{} : s.joint;
            const vec3<T> C = gap(i);
            vec3<T> target;
            for (std::size_t a = 0; a < 3; ++a) target[a] = k.mass_scale * (u[a] + k.bias_rate * C[a]);
            const vec3<T> push = linear3::apply(inverse_block(W, i), target);
            for (std::size_t a = 0; a < 3; ++a) next[a] = old[a] - push[a] - k.impulse_scale * old[a];
        } else {
            const std::array<T, 2> length = step_lengths_of(W, i);
            const vec3<T> gaps = gap(i);
            const T C = gaps[0];
            T rn;
            if (compliance_of(W, i) > T(0)) rn = s.relax ? old[0] : old[0] - u[0] * length[0];  // its own spring, once a substep (u: c r_n + b)
            else if (C > T(0)) rn = old[0] - (u[0] + C / s.substep) * length[0];  // speculative
            else if (s.relax) rn = old[0] - u[0] * length[0];
            else {
                const T bias = std::max(s.contact.bias_rate * C, -s.push_speed);
                rn = old[0] - s.contact.mass_scale * (u[0] + bias) * length[0] - s.contact.impulse_scale * old[0];
            }
            // the friction disc at the new normal impulse, by one projected step (contact_problem.hpp)
            vec3<T> slip = u;
            if (!s.relax) slip[1] += s.contact.bias_rate * gaps[1], slip[2] += s.contact.bias_rate * gaps[2];
            next = friction_step(W.block(i), slip, mu[i], old, rn > T(0) ? rn : T(0), length);
        }
        const vec3<T> d = linear3::sub(next, old);
        for (std::size_t a = 0; a < 3; ++a) r[3 * i + a] = next[a];
        W.apply(i, d);
    };
    for_each_row(schedule, W.contacts(), body);
}

}  // namespace ctga::constraints
