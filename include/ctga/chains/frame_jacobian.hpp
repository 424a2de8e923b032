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
//   local                 S_jk moved out by X_{F←j}, body j seen from the frame, accumulated
//                         from the frame's body up: one composition per body (local_columns)
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

#include "ctga/chains/arguments.hpp"
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
        for (std::size_t i = 0; i < 3; ++i) w[i] = row_times<0, T, S>(G.R[i], s);
    if constexpr (translates)
        for (std::size_t i = 0; i < 3; ++i) v[i] = row_times<3, T, S>(G.R[i], s);
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
// The world poses of body B and its ancestors only (a Jacobian needs no other body's): the rest
// of the array is left unwritten.
template <int B, class Tree, class T>
CTGA_ALWAYS_INLINE constexpr void path_poses(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                             std::array<motor_map<T>, Tree::size>& pose) noexcept {
    if constexpr (B >= 0) {
        constexpr std::size_t j = static_cast<std::size_t>(B);
        constexpr int p = Tree::parent[j];
        if constexpr (p < 0) {
            pose[j] = algorithm_detail::joint_map<j>(m, q);
        } else {
            path_poses<p>(m, q, pose);
            pose[j] = compose(pose[static_cast<std::size_t>(p)], algorithm_detail::joint_map<j>(m, q));
        }
    }
}

// The local Jacobian without world poses: going up from the frame's body b, X = X_{F←j} (body j's
// frame seen from the frame's, starting from P⁻¹) gives column S_jk moved out by X, 6m for an
// axis joint, and then X_{F←λ(j)} = X_{F←j} X_j⁻¹ with X_j body j's map in its parent (Map(j):
// k.X[j], or computed from q). One composition per body, no rotation per column.
template <int B, class Tree, class T, class Map>
CTGA_ALWAYS_INLINE constexpr void local_columns(const model<Tree, T>& m, const motor_map<T>& X, const Map& map_of_body,
                                                jacobian_matrix<Tree, T>& out) noexcept {
    if constexpr (B >= 0) {
        constexpr std::size_t j = static_cast<std::size_t>(B);
        using Jt = typename Tree::template joint_at<j>;
        if constexpr (moves<Jt>)
            [&]<std::size_t... K>(std::index_sequence<K...>) {
                (put_column<j, K>(m, out, moved_out(X, Jt::template subspace<K, T>(m.template link<j>().joint))), ...);
            }(std::make_index_sequence<is_mimic<Jt> ? 1 : Jt::nv>{});
        if constexpr (Tree::parent[j] >= 0) {
            const motor_map<T> Xj = map_of_body(std::integral_constant<std::size_t, j>{});
            motor_map<T> up;  // X Xj⁻¹: R Rjᵀ, t − (R Rjᵀ) tj
            for (std::size_t r = 0; r < 3; ++r)
                for (std::size_t c = 0; c < 3; ++c) up.R[r][c] = X.R[r][0] * Xj.R[c][0] + X.R[r][1] * Xj.R[c][1] + X.R[r][2] * Xj.R[c][2];
            const vec3<T> u = linear3::apply(up.R, Xj.t);
            up.t = {X.t[0] - u[0], X.t[1] - u[1], X.t[2] - u[2]};
            local_columns<Tree::parent[j]>(m, up, map_of_body, out);
        }
    }
}
template <class Tree, class T, class F, class Map>
CTGA_ALWAYS_INLINE constexpr jacobian_matrix<Tree, T> local_jacobian(const model<Tree, T>& m, F f, const Map& map_of_body) noexcept {
    constexpr int b = frame_on<Tree, F>::body;
    jacobian_matrix<Tree, T> out{};
    if constexpr (b >= 0) local_columns<b>(m, inverse(placement(m, f)), map_of_body, out);
    return out;
}

// J from the poses of the frame's body and its ancestors (world, local_world_aligned).
template <class Tree, class T, class F>
CTGA_ALWAYS_INLINE constexpr jacobian_matrix<Tree, T> jacobian(const model<Tree, T>& m, const std::array<motor_map<T>, Tree::size>& pose,
                                                               F f, reference r) noexcept {
    constexpr int b = frame_on<Tree, F>::body;
    jacobian_matrix<Tree, T> out{};
    if constexpr (b >= 0) {
        const motor_map<T> W = frame_on<Tree, F>::placed ? compose(pose[b], placement(m, f)) : pose[b];
        for_each_column<b>(m, [&](auto j, auto K, const auto& S) {
            const motor_map<T>& G = pose[decltype(j)::value];
            screw<T> c;
            if (r == reference::world) c = moved_out(G, S);
            else c = moved_out(motor_map<T>{G.R, {G.t[0] - W.t[0], G.t[1] - W.t[1], G.t[2] - W.t[2]}}, S);
            put_column<decltype(j)::value, decltype(K)::value>(m, out, c);
        });
    }
    return out;
}
}  // namespace frame_detail

struct frame_jacobian_t {
    // J with v_F = J q̇ in reference r; k: forward_kinematics(m, q) (the world poses).
    template <class Tree, class T, class F>
    [[nodiscard]] constexpr jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m, const kinematics<Tree, T>& k, F f,
                                                                reference r) const noexcept {
        if (r == reference::local) return frame_detail::local_jacobian(m, f, [&](auto j) { return k.X[decltype(j)::value]; });
        return frame_detail::jacobian(m, k.pose, f, r);
    }
    // … from q: only the poses of the frame's body and its ancestors are computed (a foot's
    // Jacobian moves along its leg, not the other three).
    template <class Tree, class T, class F>
    [[nodiscard]] constexpr jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q, F f,
                                                                reference r) const noexcept {
        if (r == reference::local)
            return frame_detail::local_jacobian(m, f, [&](auto j) { return algorithm_detail::joint_map<decltype(j)::value>(m, q); });
        std::array<motor_map<T>, Tree::size> pose;  // written for the path only, read for it only
        frame_detail::path_poses<frame_detail::frame_on<Tree, F>::body>(m, q, pose);
        return frame_detail::jacobian(m, pose, f, r);
    }
};
inline constexpr algorithm<frame_jacobian_t, "frame_jacobian"> frame_jacobian{};

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
inline constexpr algorithm<frame_jacobian_time_variation_t, "frame_jacobian_time_variation"> frame_jacobian_time_variation{};

}  // namespace ctga::chains
