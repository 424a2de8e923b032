// Centroidal momentum (Orin & Goswami, "Centroidal momentum matrix of a humanoid robot", 2008):
// the whole robot's momentum about its centre of mass c, in world axes, and the matrix A_G of
// h_G = A_G q̇, as co-screws (l, p) (coscrew.hpp: angular momentum about c, then linear momentum).
//
// Body i's momentum is N_i v_i (§5's momentum, body frame, about its origin); moved out by its
// pose, ḡ P ḡ* (§2), it is about the world origin in world axes, where momenta add; about c the
// angular part is l − c × p. Column k of A_G is the momentum of what joint k moves, the composite
// of its subtree (crba.hpp's N^c_j) moving with S_jk: N^c_j S_jk, moved out and about c. A
// mimic's column is added to its master's with its multiplier (joints.hpp).
#pragma once

#include <array>
#include <cstddef>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/center_of_mass.hpp"
#include "ctga/chains/frame_jacobian.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/inertia_transform.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
using centroidal_momentum_matrix_type = std::array<coscrew<T>, Tree::nv>;  // column k: a co-screw (l, p)

namespace centroidal_detail {
// A world co-screw about the world origin taken about point c: (l − c × p, p).
template <class T>
constexpr coscrew<T> about(const coscrew<T>& P, const vec3<T>& c) noexcept {
    const vec3<T> cp = linear3::cross(c, vec3<T>{P[3], P[4], P[5]});
    return coscrew<T>{P[0] - cp[0], P[1] - cp[1], P[2] - cp[2], P[3], P[4], P[5]};
}
}  // namespace centroidal_detail

struct centroidal_momentum_t {
    // h_G about the centre of mass (k: forward_kinematics(m, q, q̇)).
    template <class Tree, class T>
    [[nodiscard]] constexpr coscrew<T> operator()(const model<Tree, T>& m, const kinematics<Tree, T>& k) const noexcept {
        coscrew<T> h{};
        algorithm_detail::forward<Tree::size>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            h = h + transform(k.pose[i], coscrew<T>(momentum(m.template link<i>().inertia, k.v[i])));
        });
        return centroidal_detail::about(h, center_of_mass(m, k).position);
    }
};
inline constexpr algorithm<centroidal_momentum_t, "centroidal_momentum"> centroidal_momentum{};

struct centroidal_momentum_matrix_t {
    // A_G with h_G = A_G q̇ (k: forward_kinematics(m, q)).
    template <class Tree, class T>
    [[nodiscard]] constexpr centroidal_momentum_matrix_type<Tree, T> operator()(const model<Tree, T>& m,
                                                                              const kinematics<Tree, T>& k) const noexcept {
        std::array<body_inertia<T>, Tree::size> Nc = [&]<std::size_t... I>(std::index_sequence<I...>) {
            return std::array<body_inertia<T>, Tree::size>{m.template link<I>().inertia...};
        }(std::make_index_sequence<Tree::size>{});
        algorithm_detail::backward<Tree::size>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            constexpr int p = Tree::parent[i];
            if constexpr (p >= 0) Nc[p] = Nc[p] + transform(k.X[i], Nc[i]);
        });
        const vec3<T> c = center_of_mass(m, k).position;
        centroidal_momentum_matrix_type<Tree, T> A{};
        algorithm_detail::forward<Tree::size>([&](auto body) {
            constexpr std::size_t j = decltype(body)::value;
            using Jt = typename Tree::template joint_at<j>;
            if constexpr (moves<Jt>)
                [&]<std::size_t... K>(std::index_sequence<K...>) {
                    (frame_detail::put_column<j, K>(
                         m, A,
                         centroidal_detail::about(
                             transform(k.pose[j], coscrew<T>(momentum(Nc[j], Jt::template subspace<K, T>(m.template link<j>().joint)))), c)),
                     ...);
                }(std::make_index_sequence<is_mimic<Jt> ? 1 : Jt::nv>{});
        });
        return A;
    }
    // … from q.
    template <class Tree, class T>
    [[nodiscard]] constexpr centroidal_momentum_matrix_type<Tree, T> operator()(const model<Tree, T>& m,
                                                                              const configuration<Tree, T>& q) const noexcept {
        return (*this)(m, forward_kinematics(m, q));
    }
};
inline constexpr algorithm<centroidal_momentum_matrix_t, "centroidal_momentum_matrix"> centroidal_momentum_matrix{};

}  // namespace ctga::chains
