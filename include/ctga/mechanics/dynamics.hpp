// The equations of motion of a single rigid body (§6) and their solution for the acceleration.
//
// Newton's law dP/dt = W with P = A ∨ (N ∧ s) and dN/dt from the group action gives (§6)
//
//   N ∧ ṡ + ½((s̄N − Ns̄) ∧ s) = W E,   i.e.   A ∨ (N ∧ ṡ) = W − {s, P},   {s, P} = ½(s̄P − Ps̄),
//
// since ½ A ∨ ((s̄N − Ns̄) ∧ s) = {s, A ∨ (N ∧ s)} and AE ∨ c = c. The mobility M = N⁻¹ solves it:
//
//   ṡ = E ∨ (M ∧ (W − {s, A ∨ (N ∧ s)})).
//
// The same equation holds with every quantity in the fixed frame (the paper's choice: N moves
// with the body) or every quantity in the body frame (N constant). The pose follows
// dg/dt = ½ s g for the fixed-frame velocity s (§3), and dg/dt = ½ g s_b for the body-frame
// velocity s_b = g* s g.
#pragma once

#include <type_traits>

#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/inertia_transform.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/rigid_body.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/operations/formula.hpp"
#include "ctga/support/inline.hpp"

namespace ctga {

// §6: the left-hand side of N ∧ ṡ + ½((s̄N − Ns̄) ∧ s) = W E, as a formula (N in one frame with
// s and ṡ); the tests check it against W E for the ṡ that acceleration() returns.
inline constexpr auto motion_lhs = formula([](auto N, auto s, auto sdot) {
    const auto x = lift(s);
    return (N ^ lift(sdot)) + half * ((bar(x) * N - N * bar(x)) ^ x);
});

// The same equation solved, as one formula of N, M, s and W (its value a lifted screw):
//   ṡ = E ∨ (M ∧ (W − {s, A ∨ (N ∧ s)}))
// acceleration() below evaluates it in two typed steps; this form is what ctga::jacobian
// differentiates (∂ṡ/∂s, ∂ṡ/∂W, ∂ṡ/∂N: operations/jacobian.hpp).
inline constexpr auto motion_rate = formula([](auto N, auto M, auto s, auto W) {
    const auto P = invariants::A & (N ^ lift(s));
    const auto x = bar(lift(s));
    return invariants::E & (M ^ (W - half * (x * P - P * x)));
});

// ṡ from N ∧ ṡ + ½((s̄N − Ns̄) ∧ s) = W E, all four quantities in one frame. M is any mobility
// (36 blades: a general 6×6 inverse inertia) or a rigid body's body_mobility, solved about the
// centre of mass (body_inertia.hpp: E ∨ (M ∧ P) = t (E ∨ (M_c ∧ (t̄* P t̄))) t*, 24m 18a instead of 36m 30a).
template <class T, class Inertia, class Mobility>
    requires(formula_argument<Inertia> &&
             (std::is_same_v<Mobility, mobility<T>> || std::is_same_v<Mobility, body_mobility<T>>))
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr screw<T> acceleration(const Inertia& N, const Mobility& M, const screw<T>& s,
                                                                 const wrench<T>& W) noexcept {
    const coscrew<T> P = momentum(N, s);
    const coscrew<T> rhs = W - coadjoint(s, P);
    return velocity_from(M, rhs);
}

// A rigid body's acceleration, from N and M by their ten parameters each (body.Nb, body.Mb): the
// momentum at 24m 18a, the solve about the centre of mass at 24m 18a.
template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr screw<T> acceleration(const rigid_body<T>& body, const screw<T>& s,
                                                                 const wrench<T>& W) noexcept {
    return acceleration(body.Nb, body.Mb, s, W);
}

template <class T = double>
struct state_rate {
    motor<T> g_dot;  // dg/dt
    screw<T> s_dot;  // ds/dt
};

// The paper's form (§6): pose g, velocity s and wrench W in the fixed frame, the body's inertia in
// its own frame. The inertia and mobility are moved to the fixed frame, (g ḡ) N (g ḡ)*.
template <class T>
[[nodiscard]] constexpr state_rate<T> fixed_frame_rates(const rigid_body<T>& body, const motor<T>& g, const screw<T>& s,
                                                        const wrench<T>& W) noexcept {
    const mass_properties<T> in_space = transform(map_of(g), body.properties);
    const screw<T> s_dot = acceleration(inertia_of(in_space), mobility_of(in_space), s, W);
    return {half * s * g, s_dot};
}

// The same fixed-frame rates, evaluated about the body's own frame and moved out: the remedy for
// a body far from the origin. There the fixed-frame N has entries m|t|² next to entries of
// order m and I_c, and solving through it loses about |t|² of relative accuracy; the body-frame
// N and M stay as given. With s = g s_b g* and dg/dt = ½ s g,
//   ds/dt = ½ s g s_b g* + g ṡ_b g* + g s_b ½ (s g)* = ½ s s + g ṡ_b g* − ½ s s = g ṡ_b g*,
// so ṡ is the body-frame acceleration moved by H (s_b = H⁻¹ s and W_b = Hᵀ W in, H ṡ_b out).
template <class T>
[[nodiscard]] constexpr state_rate<T> fixed_frame_rates_about_body(const rigid_body<T>& body, const motor<T>& g,
                                                                   const screw<T>& s, const wrench<T>& W) noexcept {
    const motor_map<T> G = map_of(g), G_inverse = inverse(G);
    const screw<T> s_dot_b = acceleration(body, transform(G_inverse, s), transform(G_inverse, W));
    return {half * s * g, transform(G, s_dot_b)};
}

// The body-frame form: velocity s_b and wrench W_b in the body frame; N and M are constant.
template <class T>
[[nodiscard]] constexpr state_rate<T> body_frame_rates(const rigid_body<T>& body, const motor<T>& g, const screw<T>& s_b,
                                                       const wrench<T>& W_b) noexcept {
    return {half * g * s_b, acceleration(body, s_b, W_b)};
}

}  // namespace ctga
