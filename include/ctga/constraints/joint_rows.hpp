// The rows of joints between two bodies, in blocks of three bilateral rows (contact_rows.hpp's
// contact_row with bilateral = true: each row holds u = 0). A joint is one or two blocks:
//
//   point     body a's anchor held at body b's: the world's axes e_k as lines through each
//             side's own anchor (a spherical joint; with hinge a revolute, with weld a fixed one)
//   line      b's anchor kept on the line through a's anchor along a's axis w: the two
//             directions t1, t2 normal to w, both sides' lines through b's anchor (with weld, a
//             prismatic joint)
//   distance  the anchors kept `length` apart: one line along d = p_b − p_a through each anchor
//   hinge     a's axis kept along b's: two couples, t1 and t2 normal to a's axis w (lines at
//             infinity, co-screws (t, 0): their pairing with a screw is t·ω)
//   weld      the relative rotation kept: three couples along the world's axes
//   twist     a revolute joint's limits and motor, about a's axis w: the couples (w, w, −w),
//             rows lower limit, motor, upper limit (a bounded block, below)
//   slide     a prismatic joint's, along a's axis w: the lines (w, w, −w) through b's anchor
//
// A block's gap g is what its rows hold at zero, with dg/dt = u = J s to first order (the position
// correction asks for g + h u_p = 0):
//   point     g = p_b − p_a
//   line      g_k = t_k · (p_b − p_a)
//   distance  g = |p_b − p_a| − length
//   hinge     g_k = t_k · (w_a × w_b): for w_a ≈ w_b, d/dt (w_a × w_b) = ((ω_b − ω_a) normal to w)
//   weld      g = vee(E), E = R_b (R_a R₀)ᵀ the rotation left from the reference R₀ = R_aᵀ R_b
//             (vee(E) = sin θ times E's axis; dE/dt = [ω_b − ω_a]× at E = 1)
//   twist     g = (θ − lower, 0, upper − θ), θ = atan2(w · (x_a × x_b), x_a · x_b) the angle from
//             a's reference x_a (normal to w) to b's x_b (the same vector when the joint was added)
//   slide     g = (s − lower, 0, upper − s), s = w · (p_b − p_a)
// Limits and motor are a bounded block: a limit row's impulse in [0, ∞) (its offset speculative,
// as a contact's: u⁺ ≥ −u⁻ − 2g/h, or u⁺ ≥ 0 when the free motion would reach it within the step),
// the motor row's in [−h F, h F] for the effort F (torque or force), its offset −speed, so that it
// drives u to the speed while it can; an infinite limit or a zero effort is a row held at zero.
// A block's unused rows (distance: two, line and hinge: one) have no lines: their velocity and
// impulse are zero, and a 1 on the block's diagonal keeps it invertible.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "ctga/constraints/contact_rows.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/math.hpp"

namespace ctga::constraints {

enum class joint_block_kind : std::uint8_t { point, line, distance, hinge, weld, twist, slide };

// A block as the world keeps it: moving body a, moving body b or no_body (the ground: b's frame
// is the world's), anchors and axes in their bodies' frames (unit axes), the weld's reference
// rotation R₀ = R_aᵀ R_b, the distance's length.
template <class T>
struct joint_block {
    joint_block_kind kind = joint_block_kind::point;
    std::uint32_t a = no_body, b = no_body;
    vec3<T> anchor_a{}, anchor_b{}, axis_a{}, axis_b{};
    mat3<T> reference{};
    T length = T(0);
    vec3<T> reference_a{}, reference_b{};  // a twist's x_a and x_b, in their bodies' frames
    T lower = T(0), upper = T(0), speed = T(0), effort = T(0);  // a twist's or slide's limits and motor
};

// The rows a block uses (the others have no lines).
[[nodiscard]] constexpr std::size_t used_rows(joint_block_kind kind) noexcept {
    switch (kind) {
        case joint_block_kind::distance: return 1;
        case joint_block_kind::line:
        case joint_block_kind::hinge: return 2;
        default: return 3;
    }
}

namespace joint_detail {
template <class T>
[[nodiscard]] constexpr vec3<T> at(const motor_map<T>& G, const vec3<T>& x) noexcept {
    return linear3::add(linear3::apply(G.R, x), G.t);
}
// A side whose lines are couples along the given directions.
template <class T>
[[nodiscard]] constexpr row_side<T> couple_side(std::uint32_t body, const std::array<vec3<T>, 3>& axes) noexcept {
    return row_side<T>{body, axes};
}
// vee(B Cᵀ) for rotations B and C: the axial part of their relative rotation.
template <class T>
[[nodiscard]] constexpr vec3<T> relative_vee(const mat3<T>& B, const mat3<T>& C) noexcept {
    const auto e = [&](std::size_t i, std::size_t j) { return B[i][0] * C[j][0] + B[i][1] * C[j][1] + B[i][2] * C[j][2]; };
    return {(e(2, 1) - e(1, 2)) / T(2), (e(0, 2) - e(2, 0)) / T(2), (e(1, 0) - e(0, 1)) / T(2)};
}
template <class T>
[[nodiscard]] constexpr mat3<T> product(const mat3<T>& A, const mat3<T>& B) noexcept {
    mat3<T> out{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) out[i][j] = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
    return out;
}
}  // namespace joint_detail

// The reference rotation of a weld between bodies at rotations R_a and R_b: R₀ = R_aᵀ R_b.
template <class T>
[[nodiscard]] constexpr mat3<T> weld_reference(const mat3<T>& Ra, const mat3<T>& Rb) noexcept {
    mat3<T> out{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) out[i][j] = Ra[0][i] * Rb[0][j] + Ra[1][i] * Rb[1][j] + Ra[2][i] * Rb[2][j];
    return out;
}

// The block's row (lines, Delassus block and its inverse; no offsets) for bodies at the maps A
// and B (B the identity for the ground), and its gap.
template <class T>
constexpr vec3<T> joint_row(const joint_block<T>& J, const motor_map<T>& A, const motor_map<T>& B, std::span<const mobility<T>> M,
                            contact_row<T>& row) noexcept {
    using joint_detail::at;
    const vec3<T> zero{};
    const vec3<T> pa = at(A, J.anchor_a), pb = at(B, J.anchor_b), d = linear3::sub(pb, pa);
    const bool fixed = J.b == no_body;
    const auto sides_at = [&](const vec3<T>& xa, const vec3<T>& xb) {
        row.a = make_side(J.a, A.t, xa, row.direction);
        row.b = fixed ? row_side<T>{} : make_side(J.b, B.t, xb, row.direction);
    };
    const auto couples = [&](const std::array<vec3<T>, 3>& axes) {
        row.direction = {zero, zero, zero};
        row.a = joint_detail::couple_side(J.a, axes);
        row.b = fixed ? row_side<T>{} : joint_detail::couple_side(J.b, axes);
    };
    vec3<T> gap{};
    switch (J.kind) {
        case joint_block_kind::point:
            row.direction = {vec3<T>{T(1), T(0), T(0)}, vec3<T>{T(0), T(1), T(0)}, vec3<T>{T(0), T(0), T(1)}};
            sides_at(pa, pb);
            gap = d;
            break;
        case joint_block_kind::line: {
            const std::array<vec3<T>, 2> t = tangents(linear3::apply(A.R, J.axis_a));
            row.direction = {t[0], t[1], zero};
            sides_at(pb, pb);
            gap = {linear3::dot(t[0], d), linear3::dot(t[1], d), T(0)};
            break;
        }
        case joint_block_kind::distance: {
            const T length = math::sqrt(linear3::dot(d, d));
            // (anchors on top of each other: a's axis as the direction)
            const vec3<T> n = length > T(0) ? linear3::scale(T(1) / length, d) : linear3::apply(A.R, J.axis_a);
            row.direction = {n, zero, zero};
            sides_at(pa, pb);
            gap = {length - J.length, T(0), T(0)};
            break;
        }
        case joint_block_kind::hinge: {
            const vec3<T> wa = linear3::apply(A.R, J.axis_a), wb = linear3::apply(B.R, J.axis_b);
            const std::array<vec3<T>, 2> t = tangents(wa);
            couples({t[0], t[1], zero});
            const vec3<T> turn = linear3::cross(wa, wb);
            gap = {linear3::dot(t[0], turn), linear3::dot(t[1], turn), T(0)};
            break;
        }
        case joint_block_kind::weld:
            couples({vec3<T>{T(1), T(0), T(0)}, vec3<T>{T(0), T(1), T(0)}, vec3<T>{T(0), T(0), T(1)}});
            gap = joint_detail::relative_vee(B.R, joint_detail::product(A.R, J.reference));
            break;
        case joint_block_kind::twist:
        case joint_block_kind::slide: {
            const vec3<T> w = linear3::apply(A.R, J.axis_a), back = linear3::scale(T(-1), w);
            T at = linear3::dot(w, d);
            if (J.kind == joint_block_kind::twist) {
                const vec3<T> xa = linear3::apply(A.R, J.reference_a), xb = linear3::apply(B.R, J.reference_b);
                using std::atan2;
                at = atan2(linear3::dot(w, linear3::cross(xa, xb)), linear3::dot(xa, xb));
                couples({w, w, back});
            } else {
                row.direction = {w, w, back};
                sides_at(pb, pb);
            }
            gap = {at - J.lower, T(0), J.upper - at};
            break;
        }
    }
    row.block = delassus_block<T>(row, M);
    for (std::size_t k = used_rows(J.kind); k < 3; ++k) row.block[k][k] = T(1);
    row.inverse = linear3::inverse_symmetric(row.block);
    row.bias = {}, row.mu = T(0), row.compliance = T(0);
    row.bounded = J.kind == joint_block_kind::twist || J.kind == joint_block_kind::slide;
    row.bilateral = !row.bounded;
    return gap;
}

// A twist's or slide's offsets and intervals for a step of h (above), from its gaps g and its rows'
// velocities before the step (u⁻) and free (u_free: the step's forces, no impulse).
template <class T>
constexpr void limit_and_motor(const joint_block<T>& J, const vec3<T>& g, const vec3<T>& before, const vec3<T>& free, const T& h,
                               contact_row<T>& row) noexcept {
    constexpr T unbounded = std::numeric_limits<T>::infinity();
    for (const std::size_t k : {std::size_t{0}, std::size_t{2}}) {
        const bool limited = is_finite(k == 0 ? J.lower : J.upper);
        const bool closing = g[k] + h * (before[k] + free[k]) / T(2) <= T(0);
        row.bias[k] = !limited || closing ? T(0) : before[k] + T(2) * g[k] / h;
        row.lower[k] = T(0), row.upper[k] = limited ? unbounded : T(0);
    }
    row.bias[1] = -J.speed;
    row.lower[1] = -h * J.effort, row.upper[1] = h * J.effort;
}

}  // namespace ctga::constraints
