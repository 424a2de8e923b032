// A tree with mimic joints (joints.hpp) seen as its expanded tree, where every mimic joint is
// independent (its followed joint, a coordinate of its own), with the constant map G between
// their velocities: q̇_all = G q̇, one non-zero per row (1 for an independent joint; the
// multiplier r for a mimic, in its master's column), and q_all = G q + o. The derivatives of the
// dynamics run on the expanded tree and reduce by G (G constant):
//   τ = Gᵀ τ_all,   ∂τ/∂x = Gᵀ (∂τ_all/∂x_all) G  (x: q, q̇, q̈),   H = Gᵀ H_all G,   J = J_all G
// (rnea_derivatives.hpp, aba_derivatives.hpp, frame_derivatives.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "ctga/chains/frame_jacobian.hpp"
#include "ctga/chains/joints.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/chains/tree_matrix.hpp"

namespace ctga::chains {

namespace mimic_detail {
template <class E>
struct independent {
    using type = E;
};
template <int P, class J, std::size_t M>
struct independent<link<P, mimic<J, M>>> {
    using type = link<P, J>;
};
template <class Tree>
struct expanded;
template <class... E>
struct expanded<tree<E...>> {
    using type = tree<typename independent<E>::type...>;
};
}  // namespace mimic_detail

// The tree with its mimic joints made independent (the same bodies, frames and order).
template <class Tree>
using expanded_tree = typename mimic_detail::expanded<Tree>::type;

template <class Tree, class T>
struct expansion {
    using all = expanded_tree<Tree>;
    // the dof of Tree that each dof of the expanded tree moves with (G's non-zero column)
    static constexpr std::array<std::size_t, all::nv> column = [] {
        std::array<std::size_t, all::nv> c{};
        for (std::size_t b = 0; b < Tree::size; ++b)
            for (std::size_t k = 0; k < all::nv_of[b]; ++k)
                c[all::v_offset[b] + k] = Tree::v_offset[Tree::reads_from[b]] + (Tree::master[b] >= 0 ? 0 : k);
        return c;
    }();

    model<all, T> m;
    std::array<T, all::nv> g{};  // G's non-zero in each row
    std::array<T, all::nv> o{};  // the offsets (q_all = G q + o for the one-coordinate joints)

    constexpr explicit expansion(const model<Tree, T>& reduced) noexcept {
        m.gravity = reduced.gravity;
        m.frames = reduced.frames;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ([&] {
                const auto& from = reduced.template link<I>();
                auto& to = m.template link<I>();
                to.placement = from.placement;
                to.inertia = from.inertia;
                for (std::size_t k = all::v_offset[I]; k < all::v_offset[I + 1]; ++k) g[k] = T(1), o[k] = T(0);
                if constexpr (is_mimic<typename Tree::template joint_at<I>>) {
                    to.joint = from.joint.joint;
                    g[all::v_offset[I]] = from.joint.multiplier;
                    o[all::v_offset[I]] = from.joint.offset;
                } else {
                    to.joint = from.joint;
                    to.armature = from.armature;  // (a mimic has none: its expanded joint's is 0)
                }
            }(), ...);
        }(std::make_index_sequence<Tree::size>{});
    }

    // q_all: an independent joint's own numbers; a mimic's r q_master + o
    [[nodiscard]] constexpr configuration<all, T> configuration_of(const configuration<Tree, T>& q) const noexcept {
        configuration<all, T> out{};
        for (std::size_t b = 0; b < Tree::size; ++b) {
            if (Tree::master[b] >= 0) {
                const std::size_t e = all::v_offset[b];
                out[all::q_offset[b]] = g[e] * q[Tree::q_offset[Tree::reads_from[b]]] + o[e];
            } else {
                for (std::size_t k = 0; k < Tree::nq_of[b]; ++k) out[all::q_offset[b] + k] = q[Tree::q_offset[b] + k];
            }
        }
        return out;
    }
    // G x (velocities, accelerations)
    [[nodiscard]] constexpr joint_vector<all, T> velocities_of(const joint_vector<Tree, T>& x) const noexcept {
        joint_vector<all, T> out{};
        for (std::size_t e = 0; e < all::nv; ++e) out[e] = g[e] * x[column[e]];
        return out;
    }
    // Gᵀ y
    [[nodiscard]] constexpr joint_vector<Tree, T> reduce(const joint_vector<all, T>& y) const noexcept {
        joint_vector<Tree, T> out{};
        for (std::size_t e = 0; e < all::nv; ++e) out[column[e]] += g[e] * y[e];
        return out;
    }
    // Gᵀ A G, in Tree's pattern (tree_matrix.hpp: a mimic joint's body counts as its master's)
    template <sparsity P>
    [[nodiscard]] constexpr tree_matrix<Tree, T, P> reduce(const tree_matrix<all, T, P>& A) const noexcept {
        tree_matrix<Tree, T, P> out;
        for (std::size_t e = 0; e < all::nv; ++e)
            for (std::size_t f = 0; f < all::nv; ++f) out(column[e], column[f]) += g[e] * g[f] * A(e, f);
        return out;
    }
    // J_all G (a Jacobian's columns)
    [[nodiscard]] constexpr jacobian_matrix<Tree, T> reduce(const jacobian_matrix<all, T>& J) const noexcept {
        jacobian_matrix<Tree, T> out{};
        for (std::size_t e = 0; e < all::nv; ++e) out[column[e]] = out[column[e]] + J[e] * g[e];
        return out;
    }
};

}  // namespace ctga::chains
