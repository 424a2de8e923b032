// The derivatives of forward dynamics, ∂q̈/∂q, ∂q̈/∂q̇ and ∂q̈/∂τ = H⁻¹, of a kinematic tree
// (Carpentier and Mansard, RSS 2018). Forward dynamics solves ID(q, q̇, q̈) = τ, so differentiating
// the identity ID(q, q̇, FD(q, q̇, τ)) = τ gives
//   ∂q̈/∂τ = H⁻¹,   ∂q̈/∂q = −H⁻¹ ∂τ/∂q,   ∂q̈/∂q̇ = −H⁻¹ ∂τ/∂q̇
// with ∂τ/∂(q, q̇) of inverse dynamics (rnea_derivatives.hpp) at q̈ = FD(q, q̇, τ) (aba.hpp) and H⁻¹
// by its own recursion (minverse.hpp). Configuration derivatives are in the tangent space, as
// rnea_derivatives'. The products run over the structural entries only: H⁻¹ has the tree's
// components' pattern, ∂τ its branches', so ∂q̈ has the components' (tree_matrix.hpp).
#pragma once

#include <cstddef>
#include <utility>

#include "ctga/chains/aba.hpp"
#include "ctga/chains/minverse.hpp"
#include "ctga/chains/rnea_derivatives.hpp"
#include "ctga/chains/tree_matrix.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
struct aba_partials {
    joint_vector<Tree, T> qdd;                                 // q̈ = FD(q, q̇, τ), as aba
    tree_matrix<Tree, T, sparsity::components> dqdd_dq;        // ∂q̈/∂q (tangent space)
    tree_matrix<Tree, T, sparsity::components> dqdd_dv;        // ∂q̈/∂q̇
    tree_matrix<Tree, T, sparsity::components> Minv;           // ∂q̈/∂τ = H⁻¹
};

namespace algorithm_detail {
// −A B for A of the components' pattern and B of the branches': Σ_k over the k where both have
// structural entries (compile-time lists).
template <class Tree, class T>
constexpr tree_matrix<Tree, T, sparsity::components> minus_product(const tree_matrix<Tree, T, sparsity::components>& A,
                                                                   const tree_matrix<Tree, T, sparsity::branches>& B) noexcept {
    using C = tree_matrix<Tree, T, sparsity::components>;
    using Br = tree_matrix<Tree, T, sparsity::branches>;
    constexpr std::size_t n = Tree::nv;
    C out(uninitialized);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            if (!C::pattern[i][j]) continue;
            T x(0);
            for (std::size_t k = 0; k < n; ++k)
                if (C::pattern[i][k] && Br::pattern[k][j]) x -= A(i, k) * B(k, j);
            out(i, j) = x;
        }
    return out;
}
}  // namespace algorithm_detail

struct aba_derivatives_t {
    template <class Tree, class T>
    [[nodiscard]] constexpr aba_partials<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                             const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& tau) const noexcept {
        const joint_vector<Tree, T> qdd = aba(m, q, qd, tau);
        return from(m, q, qdd, minverse(m, q), rnea_derivatives(m, q, qd, qdd));
    }
    // … with an external wrench on each body (body frame, about the body's origin), as aba.
    template <class Tree, class T>
    [[nodiscard]] constexpr aba_partials<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                             const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& tau,
                                                             const body_wrenches<Tree, T>& f_ext) const noexcept {
        const joint_vector<Tree, T> qdd = aba(m, q, qd, tau, f_ext);
        return from(m, q, qdd, minverse(m, q), rnea_derivatives(m, q, qd, qdd, f_ext));
    }

private:
    template <class Tree, class T>
    static constexpr aba_partials<Tree, T> from(const model<Tree, T>&, const configuration<Tree, T>&,
                                                const joint_vector<Tree, T>& qdd,
                                                const tree_matrix<Tree, T, sparsity::components>& Minv,
                                                const rnea_partials<Tree, T>& id) noexcept {
        return {qdd, algorithm_detail::minus_product(Minv, id.dtau_dq), algorithm_detail::minus_product(Minv, id.dtau_dv), Minv};
    }
};
// The derivatives of q̈ = aba(m, q, q̇, τ[, f_ext]) with q̈ itself: aba_partials.
inline constexpr aba_derivatives_t aba_derivatives{};

}  // namespace ctga::chains
