// The Coulomb friction cone of one contact (the complementarity formulation of Trinkle, Pang et
// al. the paper cites in §1), in the contact's frame (n, t1, t2): a vector x = (x_n, x_t), x_t the
// two tangential components.
//   K_μ  = {r : ‖r_t‖ ≤ μ r_n}   the impulses Coulomb's law allows
//   K*_μ = {v : μ ‖v_t‖ ≤ v_n}   its dual cone (v·r ≥ 0 for every r in K_μ)
// De Saxcé's modified velocity ũ = u + μ ‖u_t‖ e_n makes Signorini's condition and Coulomb's law
// with maximal dissipation one cone complementarity, K_μ ∋ r ⊥ ũ ∈ K*_μ (Acary, Brémond and
// Huber 2018), whose natural map F(r) = r − P_K(r − ũ) is zero exactly at its solutions: its size
// is the residual a solve reports, whatever the solver.
#pragma once

#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/math.hpp"

namespace ctga::constraints {

// ‖x_t‖: the tangential part's length.
template <class T>
[[nodiscard]] constexpr T tangential_norm(const vec3<T>& x) noexcept {
    return math::sqrt(x[1] * x[1] + x[2] * x[2]);
}

// The Euclidean projection on K_μ: x itself inside; 0 in the polar cone (μ ‖x_t‖ ≤ −x_n); else the
// nearest point of the boundary, r_n = (x_n + μ ‖x_t‖) / (1 + μ²), r_t = μ r_n x_t / ‖x_t‖ (there
// ‖x_t‖ > 0: x_t = 0 is inside for x_n ≥ 0 and polar for x_n < 0). μ = 0: (max(x_n, 0), 0, 0).
template <class T>
[[nodiscard]] constexpr vec3<T> project_on_cone(const vec3<T>& x, const T& mu) noexcept {
    const T t = tangential_norm(x);
    if (t <= mu * x[0]) return x;
    if (mu * t <= -x[0]) return {T(0), T(0), T(0)};
    const T normal = (x[0] + mu * t) / (T(1) + mu * mu);
    const T s = mu * normal / t;
    return {normal, s * x[1], s * x[2]};
}

// ũ = u + μ ‖u_t‖ e_n.
template <class T>
[[nodiscard]] constexpr vec3<T> de_saxce(const vec3<T>& u, const T& mu) noexcept {
    return {u[0] + mu * tangential_norm(u), u[1], u[2]};
}

// F(r) = r − P_K(r − ũ) for the contact's impulse r and velocity u.
template <class T>
[[nodiscard]] constexpr vec3<T> natural_map(const vec3<T>& r, const vec3<T>& u, const T& mu) noexcept {
    return linear3::sub(r, project_on_cone(linear3::sub(r, de_saxce(u, mu)), mu));
}

}  // namespace ctga::constraints
