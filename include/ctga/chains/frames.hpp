// Frames of a kinematic tree: a body's own frame (chains::body<I>) or a named frame fixed to a
// body (tree.hpp's fixed_frame: a tool flange, a foot, a sensor, chains::frame<"tool0">), and
// where they are and how they move, from the bodies' kinematics (forward_kinematics.hpp).
//
// A frame F fixed to body b at placement P (motor map, P = 1 for the body's own frame) has the
// world pose W_F = W_b P. Being rigidly attached, it shares the body's motion: its velocity screw
// (§3) is the body's seen from another frame, and so is its spatial acceleration (the derivative
// of the velocity screw; for a frame fixed to a body, moving coordinates commute with d/dt).
// The three coordinate systems users know (Pinocchio's names):
//
//   reference::local                the frame's own: (ω, v) with v the velocity of the point at
//                                   its origin, in its axes          = P⁻¹ v_b
//   reference::world                the world's Plücker coordinates: v is the velocity of the
//                                   body's point at the world origin  = W_b v_b
//   reference::local_world_aligned  local's numbers in world axes: ω and the velocity of the
//                                   frame's origin, world axes       = R_F (local)
//
// The classical acceleration of the frame's origin (d²p/dt², what an accelerometer's proof mass
// needs minus gravity) is not the spatial acceleration's linear part: ä = a_v + ω × v (local).
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/inline.hpp"

namespace ctga::chains {

// A body's own frame: chains::body<I>; named frame K of the tree, by number: chains::frame_at<K>
// (chains::frame<"name"> by name, tree.hpp).
template <std::size_t I>
inline constexpr std::integral_constant<std::size_t, I> body{};
template <std::size_t K>
struct frame_number {};
template <std::size_t K>
inline constexpr frame_number<K> frame_at{};

enum class reference { local, world, local_world_aligned };

namespace frame_detail {
// Which body frame F is fixed to (−1: the world), and whether it has a placement of its own
// (model::frames[index]) or is the body's frame.
template <class Tree, class F>
struct frame_on {
    static_assert(!std::is_same_v<F, F>, "ctga::chains: a frame is chains::body<I> or chains::frame<\"name\">");
};
template <class Tree, std::size_t I>
struct frame_on<Tree, std::integral_constant<std::size_t, I>> {
    static_assert(I < Tree::size, "ctga::chains::body<I>: the tree has no body I");
    static constexpr int body = static_cast<int>(I);
    static constexpr bool placed = false;
    static constexpr std::size_t index = 0;
};
template <class Tree, fixed_string Name>
struct frame_on<Tree, frame_name<Name>> {
    static constexpr std::size_t index = Tree::frame_index_of(Name.view());
    static constexpr int body = index < Tree::frame_count ? Tree::frame_body[index] : -1;  // (no second error)
    static_assert(sizeof(tree_detail::frame_named<Tree, Name>));  // the name checked apart from the index (why: tree.hpp)
    static constexpr bool placed = true;
};
template <class Tree, std::size_t K>
struct frame_on<Tree, frame_number<K>> {
    static_assert(K < Tree::frame_count, "ctga::chains::frame_at<K>: the tree has no frame K");
    static constexpr std::size_t index = K;
    static constexpr int body = Tree::frame_body[K];
    static constexpr bool placed = true;
};

template <class Tree, class T, class F>
CTGA_ALWAYS_INLINE constexpr motor_map<T> placement(const model<Tree, T>& m, F) noexcept {
    using on = frame_on<Tree, F>;
    if constexpr (on::placed) return m.frames[on::index];
    else return tree_detail::identity_map<T>();
}

// (ω, v) with both parts rotated by R.
template <class T>
CTGA_ALWAYS_INLINE constexpr screw<T> rotate(const mat3<T>& R, const vec3<T>& w, const vec3<T>& v) noexcept {
    const vec3<T> w2 = linear3::apply(R, w), v2 = linear3::apply(R, v);
    return screw<T>{w2[0], w2[1], w2[2], v2[0], v2[1], v2[2]};
}
template <class T>
CTGA_ALWAYS_INLINE constexpr vec3<T> angular(const screw<T>& s) noexcept {
    return {s[0], s[1], s[2]};
}
template <class T>
CTGA_ALWAYS_INLINE constexpr vec3<T> linear(const screw<T>& s) noexcept {
    return {s[3], s[4], s[5]};
}

// A screw s of body b's (body coordinates: velocity or spatial acceleration) seen from frame F.
template <class Tree, class T, class F>
CTGA_ALWAYS_INLINE constexpr screw<T> seen_from(const model<Tree, T>& m, const kinematics<Tree, T>& k, F f, const screw<T>& s,
                                                reference r) noexcept {
    constexpr int b = frame_on<Tree, F>::body;
    if constexpr (b < 0) {
        return screw<T>{};  // fixed to the world: it does not move
    } else {
        const motor_map<T> P = placement(m, f);
        switch (r) {
            case reference::local: return transform_inverse(P, s);
            case reference::world: return transform(k.pose[b], s);
            case reference::local_world_aligned: {
                // ω and the velocity of the frame's origin t_P: v + ω × t_P, in world axes
                const vec3<T> w = angular(s);
                return rotate(k.pose[b].R, w, linear3::add(linear(s), linear3::cross(w, P.t)));
            }
        }
        return screw<T>{};
    }
}
}  // namespace frame_detail

// The frame's pose in the world, W_b P (a motor map: its axes R and its origin t).
struct frame_pose_t {
    template <class Tree, class T, class F>
    [[nodiscard]] constexpr motor_map<T> operator()(const model<Tree, T>& m, const kinematics<Tree, T>& k, F f) const noexcept {
        using on = frame_detail::frame_on<Tree, F>;
        if constexpr (on::body < 0) return frame_detail::placement(m, f);
        else if constexpr (!on::placed) return k.pose[on::body];
        else return compose(k.pose[on::body], m.frames[on::index]);
    }
};
inline constexpr algorithm<frame_pose_t, "frame_pose"> frame_pose{};

// The frame's velocity screw (k: forward_kinematics(m, q, q̇)), or its spatial acceleration: the
// time derivative of the velocity screw's numbers in the same coordinates (k:
// forward_kinematics(m, q, q̇, q̈); gravity not included). Moving a body's screw into a frame fixed
// to it commutes with d/dt, so both are seen_from the same way; in local_world_aligned the
// acceleration is local's in world axes, as Pinocchio's.
template <bool Acceleration>
struct frame_motion_t {
    template <class Tree, class T, class F>
    [[nodiscard]] constexpr screw<T> operator()(const model<Tree, T>& m, const kinematics<Tree, T>& k, F f,
                                                reference r) const noexcept {
        constexpr int b = frame_detail::frame_on<Tree, F>::body;
        if constexpr (b < 0) return screw<T>{};
        else return frame_detail::seen_from(m, k, f, Acceleration ? k.a[b] : k.v[b], r);
    }
};
inline constexpr algorithm<frame_motion_t<false>, "frame_velocity"> frame_velocity{};
inline constexpr algorithm<frame_motion_t<true>, "frame_acceleration"> frame_acceleration{};

// The classical acceleration of the frame's origin, d²p/dt² = a_v + ω × v from the local (or
// local_world_aligned) velocity and acceleration: in the frame's axes (local) or the world's
// (world, local_world_aligned). k: forward_kinematics(m, q, q̇, q̈).
struct frame_classical_acceleration_t {
    template <class Tree, class T, class F>
    [[nodiscard]] constexpr vec3<T> operator()(const model<Tree, T>& m, const kinematics<Tree, T>& k, F f,
                                               reference r) const noexcept {
        constexpr int b = frame_detail::frame_on<Tree, F>::body;
        if constexpr (b < 0) {
            return vec3<T>{};
        } else {
            const reference axes = r == reference::local ? reference::local : reference::local_world_aligned;
            const screw<T> v = frame_detail::seen_from(m, k, f, k.v[b], axes);
            const screw<T> a = frame_detail::seen_from(m, k, f, k.a[b], axes);
            return linear3::add(frame_detail::linear(a), linear3::cross(frame_detail::angular(v), frame_detail::linear(v)));
        }
    }
};
inline constexpr algorithm<frame_classical_acceleration_t, "frame_classical_acceleration"> frame_classical_acceleration{};

// For tools: f(chains::frame_at<K>) for the frame of run-time index k (tree::find_frame), the
// same code as with the frame named in the source; f's result for every frame has one type. An
// index out of range calls nothing (and returns a value-initialised result).
template <class Tree, class Fn>
constexpr auto visit_frame(std::size_t k, Fn&& f) -> decltype(f(frame_at<0>)) {
    static_assert(Tree::frame_count > 0, "ctga::chains::visit_frame: the tree has no named frames");
    using R = decltype(f(frame_at<0>));
    if constexpr (std::is_void_v<R>) {
        [&]<std::size_t... K>(std::index_sequence<K...>) { (void)((k == K ? (f(frame_at<K>), true) : false) || ...); }(
            std::make_index_sequence<Tree::frame_count>{});
    } else {
        R out{};
        [&]<std::size_t... K>(std::index_sequence<K...>) { (void)((k == K ? (out = f(frame_at<K>), true) : false) || ...); }(
            std::make_index_sequence<Tree::frame_count>{});
        return out;
    }
}

}  // namespace ctga::chains
