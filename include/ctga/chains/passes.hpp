// What the algorithms of a kinematic tree (tree.hpp; algorithms.hpp lists them) share: the
// numbers they read and return (configuration, joint vectors, external wrenches: arguments.hpp), every body's
// frame, velocity and acceleration (kinematics), and the forward pass that computes them
// (Featherstone (2008) §4.1, §5.3). Screws for velocities and accelerations (§3), co-screws for
// forces (§5), motor maps for the frames (motor.hpp).
//
// Everything is in body coordinates: body i's velocity v_i and acceleration a_i are screws in
// its own frame, X_i is the motor map of body i in its parent's frame (placement ∘ joint motion).
// The forward pass, with × the Lie bracket of §3:
//
//   v_i = X_i⁻¹ v_λ + S_i q̇_i
//   a_i = X_i⁻¹ a_λ + S_i q̈_i + v_i × S_i q̇_i         (a of the world: −g, gravity's trick)
//
// A joint's S_i q̇_i and S_i are the joint's own sparse screws (joints.hpp): one blade for an
// axis joint, so the bracket, the momentum of the mass matrix and the pairing are evaluated by
// the engine on that blade only. The bodies are unrolled at compile time (a fold over their
// indices), each with its own joint type, parent and ancestors.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/joints.hpp"
#include "ctga/chains/runs.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
struct kinematics {
    std::array<motor_map<T>, Tree::size> X;     // body i in its parent's frame
    std::array<motor_map<T>, Tree::size> pose;  // body i in the world frame
    std::array<screw<T>, Tree::size> v;         // velocity, body frame
    std::array<screw<T>, Tree::size> a;         // acceleration (spatial, without gravity), body frame

    // Zero.
    constexpr kinematics() noexcept : X{}, pose{}, v{}, a{} {}
    // Not cleared: for a pass that writes every body's numbers it reads (support/uninitialized.hpp).
    constexpr explicit kinematics(uninitialized_t) noexcept
        : v(uninitialized_array<screw<T>, Tree::size>()), a(uninitialized_array<screw<T>, Tree::size>()) {}
};

namespace algorithm_detail {

// f(std::integral_constant<std::size_t, I>) for I = 0 … N−1, or N−1 … 0.
template <std::size_t N, class F>
CTGA_ALWAYS_INLINE constexpr void forward(F&& f) {
    [&]<std::size_t... I>(std::index_sequence<I...>) { (f(std::integral_constant<std::size_t, I>{}), ...); }(
        std::make_index_sequence<N>{});
}
template <std::size_t N, class F>
CTGA_ALWAYS_INLINE constexpr void backward(F&& f) {
    [&]<std::size_t... I>(std::index_sequence<I...>) { (f(std::integral_constant<std::size_t, N - 1 - I>{}), ...); }(
        std::make_index_sequence<N>{});
}

// S q̇ of a joint: Σ_k S_k q̇_k, in the joint's own screw type (one blade for an axis joint); x
// points at the numbers the joint reads (a mimic joint: its master's, q̇ = r q̇_master).
template <class J, class P, class T>
CTGA_ALWAYS_INLINE constexpr auto joint_screw(const P& params, const T* x) noexcept {
    if constexpr (is_mimic<J>)
        return typename J::template subspace_type<T>{J::template subspace<0, T>(params) * (params.multiplier * x[0])};
    else if constexpr (J::nv == 1) return typename J::template subspace_type<T>{J::template subspace<0, T>(params) * x[0]};
    else if constexpr (J::nv == 6) return screw<T>{x[0], x[1], x[2], x[3], x[4], x[5]};
    else static_assert(J::nv == 1 || J::nv == 6, "ctga::chains: a joint has 1 or 6 degrees of freedom (or 0: fixed)");
}

// Body I's map in its parent's frame.
template <std::size_t I, class Tree, class T>
CTGA_ALWAYS_INLINE constexpr motor_map<T> joint_map(const model<Tree, T>& m, const configuration<Tree, T>& q) noexcept {
    using J = typename Tree::template joint_at<I>;
    const auto& L = m.template link<I>();
    return J::motion(L.placement, L.joint, q.data() + Tree::q_offset[Tree::reads_from[I]]);
}

// The world's acceleration in Featherstone's gravity trick (§5.3) is a pure translation, −g (or 0
// for the true accelerations of forward kinematics): seen from a body on the world with map X
// it is (0, Rᵀ(−g)) (X⁻¹ (0, a) = (Rᵀ 0, Rᵀ(a − t × 0))), 9m 6a instead of a screw's 24m 18a.
template <linear3::shape S = linear3::dense, class T>
CTGA_ALWAYS_INLINE constexpr screw<T> world_acceleration(const motor_map<T>& X, const vec3<T>& a) noexcept {
    const vec3<T> r = linear3::apply_transposed<S>(X.R, a);
    return screw<T>{T(0), T(0), T(0), r[0], r[1], r[2]};
}
template <class T>
constexpr vec3<T> minus(const vec3<T>& g) noexcept {
    return {-g[0], -g[1], -g[2]};
}

// Every body's map in its parent's frame, X_i = placement ∘ joint motion (a revolute joint's cos
// and sin): fill_joint_maps computes them once for several algorithms at one q (constrained/:
// CRBA and the world poses of a step), which take them as `maps`; maps_of_q (the default) has
// each algorithm evaluate the joints' motions itself.
template <class Tree, class T>
using joint_maps = std::array<motor_map<T>, Tree::size>;
struct maps_of_q {};
// Body b's map: from the maps given, or from q.
template <class B, class Tree, class T, class Maps>
CTGA_ALWAYS_INLINE constexpr motor_map<T> body_map(const B& b, const model<Tree, T>& m, const configuration<Tree, T>& q, const Maps& maps) noexcept {
    if constexpr (std::is_same_v<Maps, maps_of_q>) {
        const auto& L = b.link(m);
        return B::joint::motion(L.placement, L.joint, q.data() + b.q_src);
    } else {
        return maps[b.i];
    }
}
template <class Tree, class T>
constexpr void fill_joint_maps(joint_maps<Tree, T>& X, const model<Tree, T>& m, const configuration<Tree, T>& q) noexcept {
    each_body(m, [&](const auto& b) CTGA_INLINE_LAMBDA { X[b.i] = body_map(b, m, q, maps_of_q{}); });
}

enum class pass { poses, velocities, accelerations };

// The forward pass of §4.1/§5.3 into k, body by body (each_body: a run of repeated bodies is
// one loop, runs.hpp): maps, world poses (when Poses), velocities and accelerations (as asked),
// then then(body, k) while the body's numbers are at hand (RNEA's
// forces; the body's map k.X[i] is stored only after it). RNEA and ABA need no world poses:
// only each body's map in its parent. Every number asked for is written before it is read, so
// k may start uninitialized.
struct no_body_work {
    template <class B, class K>
    constexpr void operator()(B, const K&) const noexcept {}
};
template <pass What, bool Poses, class Tree, class T, class Then = no_body_work>
constexpr void forward_pass(kinematics<Tree, T>& k, const model<Tree, T>& m, const configuration<Tree, T>& q, const T* qd,
                            const T* qdd, const vec3<T>& a_world, Then&& then = {}) noexcept {
    each_body(m, [&](const auto& b) CTGA_INLINE_LAMBDA {
        using B = std::remove_cvref_t<decltype(b)>;
        using J = typename B::joint;
        const std::size_t i = b.i;
        const auto& L = b.link(m);
        const motor_map<T> X = J::motion(L.placement, L.joint, q.data() + b.q_src);  // stored in k.X after the body's work
        constexpr linear3::shape S = map_shape<J>;
        if constexpr (!Poses) {
        } else if constexpr (B::root) {
            k.pose[i] = X;
        } else {
            k.pose[i] = compose<S>(k.pose[b.p], X);
        }
        if constexpr (What != pass::poses) {
            const std::size_t o = b.v_src;
            if constexpr (!moves<J>) {
                if constexpr (B::root) {
                    k.v[i] = screw<T>{};
                    if constexpr (What == pass::accelerations) k.a[i] = world_acceleration<S>(X, a_world);
                } else {
                    k.v[i] = transform_inverse<S>(X, k.v[b.p]);
                    if constexpr (What == pass::accelerations) k.a[i] = transform_inverse<S>(X, k.a[b.p]);
                }
            } else {
                const auto vJ = joint_screw<J>(L.joint, qd + o);
                if constexpr (B::root) {
                    k.v[i] = vJ;  // the world does not move
                    if constexpr (What == pass::accelerations)
                        k.a[i] = world_acceleration<S>(X, a_world) + joint_screw<J>(L.joint, qdd + o);
                } else {
                    k.v[i] = transform_inverse<S>(X, k.v[b.p]) + vJ;
                    if constexpr (What == pass::accelerations)
                        k.a[i] = transform_inverse<S>(X, k.a[b.p]) + joint_screw<J>(L.joint, qdd + o) + bracket(k.v[i], vJ);
                }
            }
        }
        then(b, k);
        // last: a copy of X read while its parts still sit in the store buffer stalls store forwarding
        k.X[i] = X;
    });
}

}  // namespace algorithm_detail

}  // namespace ctga::chains
