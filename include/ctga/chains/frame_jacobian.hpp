// The geometric Jacobian of a frame of a kinematic tree (frames.hpp: a body's own frame or a
// named frame) in the three references, and its time derivative J̇, from the bodies' world poses
// (and velocities) of forward_kinematics.
//
// v_F = J q̇: column k of joint j is the velocity the frame has when only q̇_k moves. For j on the
// path from the frame's body to the root it is S_jk moved out of body j, g_j S_jk g_j* (§3),
// seen from the reference; for any other joint it is zero. Moved out, the screw keeps its
// sparsity: an axis joint's S is one blade, so its world column is (R e, t × R e), 6m 3a
// (moved_out). From the world column (ω, v):
//   world                 (ω, v)
//   local_world_aligned   (ω, v + ω × p) = S_jk moved out by (R_j, t_j − p), p the frame's origin
//   local                 R_Fᵀ (local_world_aligned column)
// A mimic joint's column is added to its master's with its multiplier (J = J_all G, joints.hpp).
//
// J̇ along the motion (k with velocities): a joint's S is constant in its body, so its world
// column moves with the body's world velocity V_j: d/dt (g_j S g_j*) = [V_j, S_world] (the
// bracket of §3). Then, with p' the frame origin's velocity and Ω the frame's angular velocity
// (world):  local_world_aligned  (ω', v' + ω' × p + ω × p'),  local  R_Fᵀ(J̇_lwa − Ω × J_lwa),
// each part. So a_F = J q̈ + J̇ q̇ in local and world (the spatial acceleration, frames.hpp), and in
// local_world_aligned J q̈ + J̇ q̇ = (ω', classical acceleration of the frame's origin).
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/chains/forward_kinematics.hpp"
#include "ctga/chains/frames.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/inline.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
using jacobian_matrix = std::array<screw<T>, Tree::nv>;  // column k: a screw

namespace frame_detail {
// Whether a screw type S (a joint's sparse subspace) holds screw component C (screw.hpp's order:
// e2e3, e3e1, e1e2, e1e, e2e, e3e).
template <std::size_t C>
inline constexpr auto component_blade = [] {
    if constexpr (C == 0) return cl031::mv<double, "e2e3">::layout.masks[0];
    else if constexpr (C == 1) return cl031::mv<double, "e3e1">::layout.masks[0];
    else if constexpr (C == 2) return cl031::mv<double, "e1e2">::layout.masks[0];
    else if constexpr (C == 3) return cl031::mv<double, "e1e">::layout.masks[0];
    else if constexpr (C == 4) return cl031::mv<double, "e2e">::layout.masks[0];
    else return cl031::mv<double, "e3e">::layout.masks[0];
}();
template <std::size_t C, class S>
inline constexpr bool has_component = S::layout.contains(component_blade<C>);
// Σ_k row[k] s_(Off+k) over the components S has (no product with a structural zero).
template <std::size_t Off, class T, class S>
CTGA_ALWAYS_INLINE constexpr T row_times(const vec3<T>& row, const screw<T>& s) noexcept {
    T acc{};
    bool any = false;
    [&]<std::size_t... K>(std::index_sequence<K...>) {
        (((has_component<Off + K, S>) ? (acc = any ? T(acc + row[K] * s[Off + K]) : T(row[K] * s[Off + K]), any = true) : false),
         ...);
    }(std::make_index_sequence<3>{});
    return acc;
}
// g s g* for g's map G and s of sparse type S, over S's blades only: ω = R ω_S, v = R v_S + t × ω.
template <class T, class S>
CTGA_ALWAYS_INLINE constexpr screw<T> moved_out(const motor_map<T>& G, const S& sparse) noexcept {
    constexpr bool rotates = has_component<0, S> || has_component<1, S> || has_component<2, S>;
    constexpr bool translates = has_component<3, S> || has_component<4, S> || has_component<5, S>;
    const screw<T> s(sparse);
    vec3<T> w{}, v{};
    if constexpr (rotates)
        for (int i = 0; i < 3; ++i) w[i] = row_times<0, T, S>(G.R[i], s);
    if constexpr (translates)
        for (int i = 0; i < 3; ++i) v[i] = row_times<3, T, S>(G.R[i], s);
    if constexpr (rotates) {
        const vec3<T> tw = linear3::cross(G.t, w);
        if constexpr (translates) v = linear3::add(v, tw);
        else v = tw;
    }
    return screw<T>{w[0], w[1], w[2], v[0], v[1], v[2]};
}

template <class T>
CTGA_ALWAYS_INLINE constexpr screw<T> rotate_transposed(const mat3<T>& R, const screw<T>& s) noexcept {
    const vec3<T> w = linear3::apply_transposed(R, angular(s)), v = linear3::apply_transposed(R, linear(s));
    return screw<T>{w[0], w[1], w[2], v[0], v[1], v[2]};
}

// out[column of body J's dof K] (+)= column: assigned in a tree without mimic joints; summed with
// the weights of G in one with them (a mimic and its master may both lie on the path).
template <std::size_t J, std::size_t K, class Tree, class T, class Columns, class Column>
CTGA_ALWAYS_INLINE constexpr void put_column(const model<Tree, T>& m, Columns& out, const Column& c) noexcept {
    using Jt = typename Tree::template joint_at<J>;
    if constexpr (!Tree::has_mimic) out[Tree::v_offset[J] + K] = c;
    else if constexpr (is_mimic<Jt>) out[Tree::v_offset[Jt::master]] = out[Tree::v_offset[Jt::master]] + c * m.template link<J>().joint.multiplier;
    else out[Tree::v_offset[J] + K] = out[Tree::v_offset[J] + K] + c;
}

// column(J, K, S_JK) for body J = B and each of its ancestors with a moving joint, S_JK its joint's
// sparse free direction.
template <int B, class Tree, class T, class Column>
CTGA_ALWAYS_INLINE constexpr void for_each_column(const model<Tree, T>& m, Column&& column) noexcept {
    if constexpr (B >= 0) {
        constexpr std::size_t j = static_cast<std::size_t>(B);
        using Jt = typename Tree::template joint_at<j>;
        if constexpr (moves<Jt>)
            [&]<std::size_t... K>(std::index_sequence<K...>) {
                (column(std::integral_constant<std::size_t, j>{}, std::integral_constant<std::size_t, K>{},
                        Jt::template subspace<K, T>(m.template link<j>().joint)),
                 ...);
            }(std::make_index_sequence<is_mimic<Jt> ? 1 : Jt::nv>{});
        for_each_column<Tree::parent[j]>(m, column);
    }
}
}  // namespace frame_detail

struct frame_jacobian_t {
    // J with v_F = J q̇ in reference r; k: forward_kinematics(m, q) (the world poses).
    template <class Tree, class T, class F>
    [[nodiscard]] constexpr jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m, const kinematics<Tree, T>& k, F f,
                                                                reference r) const noexcept {
        using namespace frame_detail;
        constexpr int b = frame_on<Tree, F>::body;
        jacobian_matrix<Tree, T> out{};
        if constexpr (b >= 0) {
            const motor_map<T> W = frame_pose(m, k, f);
            for_each_column<b>(m, [&](auto j, auto K, const auto& S) {
                const motor_map<T>& G = k.pose[decltype(j)::value];
                screw<T> c;
                if (r == reference::world) c = moved_out(G, S);
                else {
                    c = moved_out(motor_map<T>{G.R, {G.t[0] - W.t[0], G.t[1] - W.t[1], G.t[2] - W.t[2]}}, S);
                    if (r == reference::local) c = rotate_transposed(W.R, c);
                }
                put_column<decltype(j)::value, decltype(K)::value>(m, out, c);
            });
        }
        return out;
    }
    // … from q.
    template <class Tree, class T, class F>
    [[nodiscard]] constexpr jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q, F f,
                                                                reference r) const noexcept {
        return (*this)(m, forward_kinematics(m, q), f, r);
    }
};
inline constexpr frame_jacobian_t frame_jacobian{};

struct frame_jacobian_time_variation_t {
    // J̇ along the motion; k: forward_kinematics(m, q, q̇) (world poses and body velocities).
    template <class Tree, class T, class F>
    [[nodiscard]] constexpr jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m, const kinematics<Tree, T>& k, F f,
                                                                reference r) const noexcept {
        using namespace frame_detail;
        constexpr int b = frame_on<Tree, F>::body;
        jacobian_matrix<Tree, T> out{};
        if constexpr (b >= 0) {
            const motor_map<T> W = frame_pose(m, k, f);
            const screw<T> V = frame_velocity(m, k, f, reference::local_world_aligned);  // (Ω, p')
            const vec3<T> Omega = angular(V), p_dot = linear(V);
            for_each_column<b>(m, [&](auto j, auto K, const auto& S) {
                constexpr std::size_t jj = decltype(j)::value;
                const motor_map<T>& G = k.pose[jj];
                const screw<T> c = moved_out(G, S);                                  // (ω, v), world
                const screw<T> c_dot = bracket(transform(G, k.v[jj]), c);           // [V_j, c]
                screw<T> d = c_dot;
                if (r != reference::world) {
                    const vec3<T> w = angular(c), w_dot = angular(c_dot);
                    // local_world_aligned: (ω', v' + ω' × p + ω × p')
                    const vec3<T> v_dot = linear3::add(linear(c_dot), linear3::add(linear3::cross(w_dot, W.t), linear3::cross(w, p_dot)));
                    d = screw<T>{w_dot[0], w_dot[1], w_dot[2], v_dot[0], v_dot[1], v_dot[2]};
                    if (r == reference::local) {
                        // R_Fᵀ (J̇_lwa − Ω × J_lwa), J_lwa = (ω, v + ω × p)
                        const vec3<T> v_lwa = linear3::add(linear(c), linear3::cross(w, W.t));
                        const vec3<T> a = linear3::cross(Omega, w), l = linear3::cross(Omega, v_lwa);
                        d = rotate_transposed(W.R, screw<T>{d[0] - a[0], d[1] - a[1], d[2] - a[2], d[3] - l[0], d[4] - l[1], d[5] - l[2]});
                    }
                }
                put_column<jj, decltype(K)::value>(m, out, d);
            });
        }
        return out;
    }
};
inline constexpr frame_jacobian_time_variation_t frame_jacobian_time_variation{};

}  // namespace ctga::chains
