// The inverse of a tree's mass matrix, H⁻¹(q), directly in O(n²) by the articulated-body
// recursion (Featherstone (2008) §7.3) run on all unit joint forces at once (Carpentier's
// "Minverse", as in Pinocchio), never by inverting CRBA's H. In the world frame, where every
// body's articulated inertia, forces and accelerations add without transforms:
//
// ABA with q̇ = 0, no gravity and τ = e_j (one unit joint force) gives column j of H⁻¹. Backwards,
// with N^A_i the articulated inertia (rigid inertias in the world frame, plus each child's
// N^A − U D⁻¹ Uᵀ), U_i = N^A_i S_i (a co-screw per dof), D_i = S_iᵀ U_i, and F_i[j] the bias force
// the bodies below i pass on for column j:
//   H⁻¹(i, j) ← D_i⁻¹ (δ_ij − S_iᵀ F_i[j]),     F_λ[j] = F_i[j] + U_i H⁻¹(i, j)
// (only j on i's subtree has F_i[j] ≠ 0: one co-screw per column, carried up its branch). Then
// forwards, a_λ[j] the parent's acceleration for column j (0 at the world):
//   H⁻¹(i, j) −= D_i⁻¹ U_iᵀ a_λ[j],              a_i[j] = a_λ[j] + S_i H⁻¹(i, j)
// for the columns j from body i's own on (H⁻¹ is symmetric: the rest is mirrored). A column of
// another component of the tree (another body on the world) is a structural zero (tree_matrix.hpp,
// sparsity::components) and is never touched.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "ctga/chains/frame_jacobian.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/chains/tree_matrix.hpp"
#include "ctga/mechanics/articulated_inertia.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/inertia_transform.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/cholesky.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

namespace algorithm_detail {

// The dofs of the bodies body I carries (its subtree without I), in index order; and the dofs
// j ≥ First of the bodies in body I's component (those hanging from the world through the same
// root body), each with whether I carries it. Lists the columns are looped over at run time
// (each column's work is the same: compiled once per body, not once per pair).
template <class Tree>
constexpr std::size_t root_of(std::size_t i) noexcept {
    while (Tree::parent[i] >= 0) i = static_cast<std::size_t>(Tree::parent[i]);
    return i;
}
template <class Tree, std::size_t I>
inline constexpr auto carried_dofs = [] {
    constexpr auto carried = [](std::size_t j) { return Tree::supports(I, Tree::body_of_dof[j]) && Tree::body_of_dof[j] != I; };
    constexpr std::size_t count = [&] {
        std::size_t c = 0;
        for (std::size_t j = 0; j < Tree::nv; ++j) c += carried(j);
        return c;
    }();
    std::array<std::size_t, count> out{};
    std::size_t c = 0;
    for (std::size_t j = 0; j < Tree::nv; ++j)
        if (carried(j)) out[c++] = j;
    return out;
}();
struct component_dof {
    std::size_t j;
    bool carried;  // by the body the list is for
};
template <class Tree, std::size_t I, std::size_t First>
inline constexpr auto later_dofs_of_component = [] {
    constexpr auto in = [](std::size_t j) { return root_of<Tree>(Tree::body_of_dof[j]) == root_of<Tree>(I); };
    constexpr std::size_t count = [&] {
        std::size_t c = 0;
        for (std::size_t j = First; j < Tree::nv; ++j) c += in(j);
        return c;
    }();
    std::array<component_dof, count> out{};
    std::size_t c = 0;
    for (std::size_t j = First; j < Tree::nv; ++j)
        if (in(j)) out[c++] = {j, Tree::supports(I, Tree::body_of_dof[j])};
    return out;
}();

// D⁻¹ of a joint's D = Sᵀ N^A S (n × n, symmetric positive definite for a body with mass): 1/D
// for one dof, by Cholesky otherwise (NaN when it is not positive definite: never a number
// that looks fine).
template <std::size_t N, class T>
constexpr std::array<std::array<T, N>, N> joint_inverse(const std::array<std::array<T, N>, N>& D) noexcept {
    if constexpr (N == 1) {
        return {{{T(1) / D[0][0]}}};
    } else {
        std::array<std::array<T, N>, N> out{};
        const auto L = cholesky(D);
        for (std::size_t c = 0; c < N; ++c) {
            std::array<T, N> e{};
            e[c] = T(1);
            const std::array<T, N> x = L ? cholesky_solve(*L, e) : [] {
                std::array<T, N> nan;
                nan.fill(std::numeric_limits<T>::quiet_NaN());
                return nan;
            }();
            for (std::size_t r = 0; r < N; ++r) out[r][c] = x[r];
        }
        return out;
    }
}

}  // namespace algorithm_detail

struct minverse_t {
    template <class Tree, class T>
    [[nodiscard]] constexpr tree_matrix<Tree, T, sparsity::components> operator()(const model<Tree, T>& m,
                                                                                 const configuration<Tree, T>& q) const noexcept {
        static_assert(!Tree::has_mimic, "ctga::chains::minverse: trees with mimic joints are not supported yet");
        using namespace algorithm_detail;
        constexpr std::size_t n = Tree::size, nv = Tree::nv;
        tree_matrix<Tree, T, sparsity::components> Minv(uninitialized);
        std::array<motor_map<T>, n> pose;
        std::array<articulated_inertia<T>, n> NA;
        auto S = uninitialized_array<screw<T>, nv>();
        auto U = uninitialized_array<coscrew<T>, nv>(), UD = uninitialized_array<coscrew<T>, nv>();
        auto F = uninitialized_array<coscrew<T>, nv>();
        // world poses, S and each body's own inertia
        forward<n>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            constexpr int p = Tree::parent[i];
            using J = typename Tree::template joint_at<i>;
            const auto& L = m.template link<i>();
            const motor_map<T> X = joint_map<i>(m, q);
            if constexpr (p < 0) pose[i] = X;
            else pose[i] = compose(pose[p], X);
            [&]<std::size_t... K>(std::index_sequence<K...>) {
                ((S[Tree::v_offset[i] + K] = frame_detail::moved_out(pose[i], J::template subspace<K, T>(L.joint))), ...);
            }(std::make_index_sequence<J::nv>{});
            NA[i] = articulated_inertia_of(transform(pose[i], L.inertia));
        });
        // backwards: D⁻¹, the columns below each body, the articulated inertias
        backward<n>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            constexpr int p = Tree::parent[i];
            constexpr std::size_t o = Tree::v_offset[i], k = Tree::nv_of[i];
            if constexpr (k > 0) {
                std::array<std::array<T, k>, k> D;
                for (std::size_t c = 0; c < k; ++c) U[o + c] = momentum(NA[i], S[o + c]);
                for (std::size_t a = 0; a < k; ++a)
                    for (std::size_t b = 0; b < k; ++b) D[a][b] = pairing(U[o + b], S[o + a]);
                const std::array<std::array<T, k>, k> Dinv = joint_inverse(D);
                for (std::size_t c = 0; c < k; ++c) {
                    coscrew<T> x = U[o] * Dinv[0][c];
                    for (std::size_t b = 1; b < k; ++b) x = x + U[o + b] * Dinv[b][c];
                    UD[o + c] = x;
                }
                // the columns of the bodies below: H⁻¹(i, j) = −D⁻¹ Sᵀ F[j], then F[j] += U H⁻¹(i, j)
                for (const std::size_t j : carried_dofs<Tree, i>) {
                    std::array<T, k> g;
                    for (std::size_t b = 0; b < k; ++b) g[b] = pairing(F[j], S[o + b]);
                    for (std::size_t c = 0; c < k; ++c) {
                        T x = Dinv[c][0] * g[0];
                        for (std::size_t b = 1; b < k; ++b) x += Dinv[c][b] * g[b];
                        Minv(o + c, j) = -x;
                        F[j] = F[j] - U[o + c] * x;
                    }
                }
                // its own columns: H⁻¹ = D⁻¹ there, and F = U D⁻¹
                for (std::size_t c = 0; c < k; ++c) {
                    for (std::size_t b = 0; b < k; ++b) Minv(o + b, o + c) = Dinv[b][c];
                    F[o + c] = UD[o + c];
                }
                // the parent sees N^A − U D⁻¹ Uᵀ (zero for a 6-dof joint, up to rounding)
                if constexpr (p >= 0 && k == 1) {
                    NA[p] = NA[p] + minus_joint(NA[i], U[o], Dinv[0][0]);
                } else if constexpr (p >= 0) {
                    articulated_inertia<T> x = NA[i];
                    for (std::size_t e = 0; e < 21; ++e) {
                        const auto rc = articulated_detail::upper_entries[e];
                        T y = x.n[e][0];
                        for (std::size_t b = 0; b < k; ++b) y -= UD[o + b][rc.i] * U[o + b][rc.j];
                        x.n[e] = typename articulated_inertia<T>::scalar{y};
                    }
                    NA[p] = NA[p] + x;
                }
            }
            if constexpr (p >= 0 && k == 0) NA[p] = NA[p] + NA[i];
        });
        // forwards: the parent's acceleration of every later column of the component
        auto A = []<std::size_t... I>(std::index_sequence<I...>) {
            return std::array<std::array<screw<T>, nv>, n>{((void)I, uninitialized_array<screw<T>, nv>())...};
        }(std::make_index_sequence<n>{});
        forward<n>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            constexpr int p = Tree::parent[i];
            constexpr std::size_t o = Tree::v_offset[i], k = Tree::nv_of[i];
            if constexpr (o == nv) {
            } else if constexpr (k > 0)
                for (const component_dof jc : later_dofs_of_component<Tree, i, o>) {
                    const std::size_t j = jc.j;
                    screw<T> a;
                    if constexpr (p >= 0) a = A[p][j];
                    for (std::size_t c = 0; c < k; ++c) {
                        T x = jc.carried ? Minv(o + c, j) : T(0);  // set backwards
                        if constexpr (p >= 0) x -= pairing(UD[o + c], A[p][j]);
                        Minv(o + c, j) = x;
                        a = a + S[o + c] * x;
                    }
                    A[i][j] = a;
                }
            else  // a fixed joint: the parent's accelerations (the world's: zero)
                for (const component_dof jc : later_dofs_of_component<Tree, i, o>) {
                    if constexpr (p >= 0) A[i][jc.j] = A[p][jc.j];
                    else A[i][jc.j] = screw<T>{};
                }
        });
        // the lower triangle, mirrored
        for (std::size_t r = 0; r < nv; ++r)
            for (std::size_t c = 0; c < Tree::v_offset[Tree::body_of_dof[r]]; ++c)
                if (Minv.pattern[r][c]) Minv(r, c) = Minv(c, r);
        return Minv;
    }
};
// H⁻¹(q), the inverse of crba(m, q), with its components' pattern (tree_matrix.hpp).
inline constexpr minverse_t minverse{};

}  // namespace ctga::chains
