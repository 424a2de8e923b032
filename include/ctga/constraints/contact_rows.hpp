// The rows of the contact problem in the paper's terms (§5): a contact's normal and friction
// forces are lines, co-screws L = (x × e, e) for a direction e through the contact point x; a
// row of the constraint Jacobian is the pairing L(s) = ω·(x × e) + v·e of a body's screw s with
// such a line (the speed along e of the body's point at x); a body's response to an impulse r
// along L is its mobility applied to the line, r N⁻¹ L.
//
// Every moving body's screw is taken in the frame at its centre of mass with the world's axes:
// there N = diag(I_w, m 1) with I_w = R I_b Rᵀ, and the mobility is N⁻¹ (l, p) = (I_w⁻¹ l, p / m),
// I_w⁻¹ = R I_b⁻¹ Rᵀ: the body-frame mobility moved by the body's rotation as N is (§7: the same
// transformation for every symmetric 6 × 6 element). The body kinds' mobilities (body_kinds.hpp)
// keep their structure: a sphere's I⁻¹ is one scalar and needs no rotation.
//
// A contact point between bodies A and B (normal n from A to B, tangents t1, t2) has three
// directions e_k; B feels +r_k e_k, A feels −r_k e_k. Its velocity u_k = L_k^B(s_B) − L_k^A(s_A)
// and its block of the Delassus operator W_jk = L_j^A(N_A⁻¹ L_k^A) + L_j^B(N_B⁻¹ L_k^B). A static
// body has no screw and no response: its side of a row is absent (not a zero).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/screw.hpp"

namespace ctga::constraints {

inline constexpr std::uint32_t no_body = ~std::uint32_t{0};  // the static side of a row

// A moving body's mobility in the frame at its centre of mass with the world's axes.
template <class T>
struct mobility {
    T inverse_mass;
    mat3<T> inverse_inertia;  // I_w⁻¹ = R I_b⁻¹ Rᵀ
};

// N⁻¹ L for a line L = (l, p): the screw (I_w⁻¹ l, p / m).
template <class T>
[[nodiscard]] constexpr screw<T> respond(const mobility<T>& M, const coscrew<T>& L) noexcept {
    const vec3<T> w = linear3::apply(M.inverse_inertia, vec3<T>{L[0], L[1], L[2]});
    return screw<T>{w[0], w[1], w[2], M.inverse_mass * L[3], M.inverse_mass * L[4], M.inverse_mass * L[5]};
}

// The evaluation map L(s) = l·ω + p·v (§5).
template <class T>
[[nodiscard]] constexpr T pair(const coscrew<T>& L, const screw<T>& s) noexcept {
    return L[0] * s[0] + L[1] * s[1] + L[2] * s[2] + L[3] * s[3] + L[4] * s[4] + L[5] * s[5];
}

// A unit vector's two tangents, t1 × t2 = n (Duff et al. 2017: continuous in n but at n_z = −1,
// so a resting contact keeps its tangents, and its friction impulses stay comparable, from one
// step to the next).
template <class T>
[[nodiscard]] constexpr std::array<vec3<T>, 2> tangents(const vec3<T>& n) noexcept {
    const T sign = n[2] >= T(0) ? T(1) : T(-1);
    const T a = T(-1) / (sign + n[2]);
    const T b = n[0] * n[1] * a;
    return {vec3<T>{T(1) + sign * n[0] * n[0] * a, sign * b, -sign * n[0]}, vec3<T>{b, sign + n[1] * n[1] * a, -n[1]}};
}

// One side of a contact point: the body and the moments x × e_k of its three lines about its
// centre of mass (the lines' force parts are the row's directions, shared by both sides).
template <class T>
struct row_side {
    std::uint32_t body = no_body;
    std::array<vec3<T>, 3> moment;
};

// A contact point's three rows: its frame's directions (n, t1, t2), the two sides, its Delassus
// block, the velocity offsets added to its rows (a contact's normal row: speculative gap,
// restitution, the caller's law) and the friction coefficient. A bilateral block (a spherical joint: the world's axes as
// directions, each side at its own anchor) has no cone: its rows hold u = 0. A bounded block (a
// joint's limits and motor) has an interval for each row's impulse, lower_k ≤ r_k ≤ upper_k, and
// u_k ≥ 0 where r_k = lower_k, u_k ≤ 0 where r_k = upper_k, u_k = 0 between.
template <class T>
struct contact_row {
    std::array<vec3<T>, 3> direction;
    row_side<T> a, b;
    mat3<T> block;
    std::array<T, 2> step_length{};  // a contact's projected step: 1/W_nn, 2/(W_t1t1 + W_t2t2) (contact_problem.hpp)
    mat3<T> inverse;  // block⁻¹, kept for a bilateral block (its sweeps solve with it)
    vec3<T> bias;
    T compliance = T(0);  // a soft contact's c (scenes/couplings.hpp): its normal velocity is u_n + c r_n
    T mu;
    bool bilateral = false;
    bool bounded = false;
    vec3<T> lower{}, upper{};  // a bounded block's intervals
};

// Line k of a side: (x × e_k, e_k).
template <class T>
[[nodiscard]] constexpr coscrew<T> line(const contact_row<T>& row, const row_side<T>& side, std::size_t k) noexcept {
    const vec3<T>& m = side.moment[k];
    const vec3<T>& e = row.direction[k];
    return coscrew<T>{m[0], m[1], m[2], e[0], e[1], e[2]};
}

// The side of a body with centre of mass c at the point x, for the directions e.
template <class T>
[[nodiscard]] constexpr row_side<T> make_side(std::uint32_t body, const vec3<T>& c, const vec3<T>& x, const std::array<vec3<T>, 3>& e) noexcept {
    row_side<T> out;
    out.body = body;
    const vec3<T> arm = linear3::sub(x, c);
    for (std::size_t k = 0; k < 3; ++k) out.moment[k] = linear3::cross(arm, e[k]);
    return out;
}

// L_j(N⁻¹ L_k) for lines j of row x's side sx and k of row y's side sy on the same body.
template <class T>
[[nodiscard]] constexpr T coupling(const mobility<T>& M, const contact_row<T>& x, const row_side<T>& sx, std::size_t j,
                                   const contact_row<T>& y, const row_side<T>& sy, std::size_t k) noexcept {
    return pair(line(x, sx, j), respond(M, line(y, sy, k)));
}

// The row's block W_jk = Σ_sides L_j(N⁻¹ L_k) (symmetric: L_jᵀ N⁻¹ L_k).
template <class T>
[[nodiscard]] constexpr mat3<T> delassus_block(const contact_row<T>& row, std::span<const mobility<T>> M) noexcept {
    mat3<T> W{};
    for (const row_side<T>* side : {&row.a, &row.b}) {
        if (side->body == no_body) continue;
        for (std::size_t k = 0; k < 3; ++k) {
            const screw<T> response = respond(M[side->body], line(row, *side, k));  // N⁻¹ L_k, once for its column
            for (std::size_t j = 0; j <= k; ++j) W[j][k] += pair(line(row, *side, j), response);
        }
    }
    for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t k = 0; k < j; ++k) W[j][k] = W[k][j];
    return W;
}

// The row's velocities J s from the bodies' screws s (no offsets): u_k = L_k^B(s_B) − L_k^A(s_A).
template <class T>
[[nodiscard]] constexpr vec3<T> row_velocity(const contact_row<T>& c, std::span<const screw<T>> s) noexcept {
    vec3<T> u{};
    const auto add = [&](const row_side<T>& side, const T& sign) {
        if (side.body == no_body) return;
        const screw<T>& sb = s[side.body];
        const vec3<T> w{sb[0], sb[1], sb[2]}, v{sb[3], sb[4], sb[5]};
        for (std::size_t k = 0; k < 3; ++k) u[k] += sign * (linear3::dot(side.moment[k], w) + linear3::dot(c.direction[k], v));
    };
    add(c.b, T(1));
    add(c.a, T(-1));
    return u;
}

// The rows of a step as the solver's Delassus operator (contact_problem.hpp): the velocities are
// the moving bodies' screws, kept current as impulses change (u = J s + c r_n, s = s_free + N⁻¹ Jᵀ r),
// so a contact's velocity costs its sides' pairings and a change of impulse dr one mobility
// applied per side, to the impulse's co-screw ±Σ dr_k L_k.
template <class T>
struct rows_delassus {
    std::span<const contact_row<T>> rows;
    std::span<const mobility<T>> mobility_of_body;
    std::span<screw<T>> velocity_of_body;

    [[nodiscard]] constexpr std::size_t contacts() const noexcept { return rows.size(); }
    [[nodiscard]] constexpr mat3<T> block(std::size_t i) const noexcept { return rows[i].block; }
    [[nodiscard]] constexpr bool bilateral(std::size_t i) const noexcept { return rows[i].bilateral; }
    [[nodiscard]] constexpr const mat3<T>& inverse_block(std::size_t i) const noexcept { return rows[i].inverse; }
    [[nodiscard]] constexpr const std::array<T, 2>& step_lengths(std::size_t i) const noexcept { return rows[i].step_length; }
    [[nodiscard]] constexpr bool bounded(std::size_t i) const noexcept { return rows[i].bounded; }
    [[nodiscard]] constexpr std::array<vec3<T>, 2> bounds(std::size_t i) const noexcept { return {rows[i].lower, rows[i].upper}; }
    [[nodiscard]] constexpr vec3<T> velocity(std::size_t i, std::span<const T> r = {}) const noexcept {
        vec3<T> u = linear3::add(rows[i].bias, row_velocity(rows[i], std::span<const screw<T>>(velocity_of_body)));
        if (!r.empty()) u[0] += rows[i].compliance * r[3 * i];
        return u;
    }
    constexpr void apply(std::size_t i, const vec3<T>& dr) const noexcept {
        const contact_row<T>& c = rows[i];
        const auto push = [&](const row_side<T>& side, const T& sign) {
            if (side.body == no_body) return;
            coscrew<T> P{};
            for (std::size_t k = 0; k < 3; ++k)
                for (std::size_t a = 0; a < 3; ++a) P[a] += sign * dr[k] * side.moment[k][a], P[3 + a] += sign * dr[k] * c.direction[k][a];
            screw<T>& s = velocity_of_body[side.body];
            s = screw<T>(s + respond(mobility_of_body[side.body], P));
        };
        push(c.b, T(1));
        push(c.a, T(-1));
    }
};

}  // namespace ctga::constraints
