// Forward kinematics of a kinematic tree (Featherstone (2008) §4.1): every body's frame, its map
// in the parent's frame and in the world, and as asked its velocity screw and acceleration, in
// body coordinates: the forward pass of passes.hpp with the world poses.
#pragma once

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

struct forward_kinematics_t {
    // Every body's frame: its map in the parent's frame (X) and in the world (pose).
    template <class Tree, class T>
    [[nodiscard]] constexpr kinematics<Tree, T> operator()(const model<Tree, T>& m,
                                                                   const configuration<Tree, T>& q) const noexcept {
        kinematics<Tree, T> k;  // v, a: zero
        algorithm_detail::forward_pass<algorithm_detail::pass::poses, true>(k, m, q, static_cast<const T*>(nullptr), static_cast<const T*>(nullptr), vec3<T>{});
        return k;
    }
    // … and every body's velocity screw, body frame.
    template <class Tree, class T>
    [[nodiscard]] constexpr kinematics<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                                   const joint_vector<Tree, T>& qd) const noexcept {
        kinematics<Tree, T> k;  // a: zero
        algorithm_detail::forward_pass<algorithm_detail::pass::velocities, true>(k, m, q, qd.data(), static_cast<const T*>(nullptr), vec3<T>{});
        return k;
    }
    // … and every body's acceleration (the true spatial acceleration, gravity not included).
    template <class Tree, class T>
    [[nodiscard]] constexpr kinematics<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                                   const joint_vector<Tree, T>& qd,
                                                                   const joint_vector<Tree, T>& qdd) const noexcept {
        kinematics<Tree, T> k{uninitialized};  // every member written
        algorithm_detail::forward_pass<algorithm_detail::pass::accelerations, true>(k, m, q, qd.data(), qdd.data(), vec3<T>{});
        return k;
    }
};
inline constexpr algorithm<forward_kinematics_t, "forward_kinematics"> forward_kinematics{};

}  // namespace ctga::chains
