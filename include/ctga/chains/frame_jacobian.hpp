// The geometric Jacobian of a body's frame in a kinematic tree, in the body's own frame
// (body_jacobian) or in the world's (world_jacobian), from the bodies' world poses
// (forward_kinematics.hpp).
//
// v_I = J q̇: column k of joint j is the velocity body I has when only q̇_k moves, S_jk seen from
// body I's frame (world: from the world's). For j on the path from I to the root it is S_jk moved
// out of body j, g_j S_jk g_j* = transform(pose_j, S_jk) (§3), then into body I; for any other
// joint it is zero. The body is a compile-time index: chains::body<I>.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/chains/forward_kinematics.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/inline.hpp"

namespace ctga::chains {

template <std::size_t I>
inline constexpr std::integral_constant<std::size_t, I> body{};

template <class Tree, class T = double>
using jacobian_matrix = std::array<screw<T>, Tree::nv>;  // column k: a screw

namespace algorithm_detail {
template <std::size_t J, class Tree, class T>
CTGA_ALWAYS_INLINE constexpr void world_columns(const model<Tree, T>& m, const kinematics<Tree, T>& k,
                                                jacobian_matrix<Tree, T>& out) noexcept {
    using Jt = typename Tree::template joint_at<J>;
    [&]<std::size_t... K>(std::index_sequence<K...>) {
        ((out[Tree::v_offset[J] + K] = transform(k.pose[J], screw<T>(Jt::template subspace<K, T>(m.template link<J>().joint)))),
         ...);
    }(std::make_index_sequence<Jt::nv>{});
    if constexpr (Tree::parent[J] >= 0) world_columns<static_cast<std::size_t>(Tree::parent[J])>(m, k, out);
}
}  // namespace algorithm_detail

struct world_jacobian_t {
    // Velocity of body I in world coordinates (ω, v of the point at the world origin) = J q̇.
    template <class Tree, class T, std::size_t I>
    [[nodiscard]] constexpr jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                                std::integral_constant<std::size_t, I>) const noexcept {
        static_assert(I < Tree::size, "ctga::chains::world_jacobian: no such body in the tree");
        jacobian_matrix<Tree, T> out{};
        algorithm_detail::world_columns<I>(m, forward_kinematics(m, q), out);
        return out;
    }
};
inline constexpr world_jacobian_t world_jacobian{};

struct body_jacobian_t {
    // Velocity of body I in its own frame (the v of forward_kinematics) = J q̇.
    template <class Tree, class T, std::size_t I>
    [[nodiscard]] constexpr jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                                std::integral_constant<std::size_t, I>) const noexcept {
        static_assert(I < Tree::size, "ctga::chains::body_jacobian: no such body in the tree");
        const kinematics<Tree, T> k = forward_kinematics(m, q);
        jacobian_matrix<Tree, T> out{};
        algorithm_detail::world_columns<I>(m, k, out);
        for (std::size_t c = 0; c < Tree::nv; ++c)
            if (Tree::supports(Tree::body_of_dof[c], I)) out[c] = transform_inverse(k.pose[I], out[c]);
        return out;
    }
};
inline constexpr body_jacobian_t body_jacobian{};

}  // namespace ctga::chains
