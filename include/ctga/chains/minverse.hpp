// The inverse of a tree's mass matrix, H⁻¹(q), in O(n²) on a chain and less on a branched tree
// (issue 42, measured against the articulated-body recursion of Carpentier's "Minverse" in the
// world frame that ctga used before, as Pinocchio does: UR5 542 → 244 ns, Solo 12 1598 → 1033 ns):
// CRBA's H (in the bodies' frames, where turned and aligned joints cost least), then H = Lᵀ D L
// with L unit lower triangular and the tree's sparsity (Featherstone (2008) §6.5, LTDL: L(k, i)
// ≠ 0 only for dof i on the path from dof k to the root, so nothing fills in), then
// Z = H⁻¹ = L⁻¹ D⁻¹ L⁻ᵀ row by row from the root: L Z = D⁻¹ L⁻ᵀ is upper triangular with
// diagonal D⁻¹, so for j < i
//   Z(i, j) = −Σ_m L(i, m) Z(m, j),   Z(i, i) = D_i⁻¹ − Σ_m L(i, m) Z(i, m)
// over the dofs m on i's path (depth(i) rows of length i: n³/3 multiply-adds for a chain, far
// fewer on a branched tree), each row a contiguous multiply-add that vectorises. Entries of two
// components (bodies on the world apart) come out zero. aba_derivatives factors its own H so.
// With mimic joints H is the reduced Gᵀ H G, whose pattern is not the tree's: its dense Cholesky
// factor (inverse_of), as aba.hpp solves such trees.
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/crba.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/chains/tree_matrix.hpp"
#include "ctga/support/cholesky.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

namespace algorithm_detail {

// The inverse of a symmetric positive definite N × N matrix from its Cholesky factor (all NaN
// when it is not positive definite: never a number that looks fine).
template <std::size_t N, class T>
constexpr std::array<std::array<T, N>, N> joint_inverse(const std::array<std::array<T, N>, N>& D) noexcept {
    if constexpr (N == 1) {
        return {{{T(1) / D[0][0]}}};
    } else {
        const auto L = cholesky(D);
        if (L) return cholesky_inverse(*L);
        std::array<std::array<T, N>, N> nan;
        for (auto& row : nan) row.fill(std::numeric_limits<T>::quiet_NaN());
        return nan;
    }
}

// H⁻¹ from H (dense) by its Cholesky factor, in the components' pattern: for a tree with mimic
// joints, where the articulated-body recursion does not hold (aba.hpp solves by Cholesky too).
template <class Tree, class T>
constexpr tree_matrix<Tree, T, sparsity::components> inverse_of(const std::array<std::array<T, Tree::nv>, Tree::nv>& H) noexcept {
    const std::array<std::array<T, Tree::nv>, Tree::nv> X = joint_inverse(H);
    tree_matrix<Tree, T, sparsity::components> out(uninitialized);
    for (std::size_t i = 0; i < Tree::nv; ++i)
        for (std::size_t j = 0; j < Tree::nv; ++j)
            if (out.pattern[i][j]) out(i, j) = X[i][j];
    return out;
}

// λ(k): the dof before dof k on its path to the root: k − 1 within a joint of several dofs, else
// the last dof of the nearest ancestor body with dofs (−1: none). λ(k) < k.
template <class Tree>
inline constexpr std::array<int, Tree::nv> dof_parent = [] {
    std::array<int, Tree::nv> out{};
    for (std::size_t k = 0; k < Tree::nv; ++k) {
        const std::size_t b = Tree::body_of_dof[k];
        int a = Tree::parent[b];
        while (a >= 0 && Tree::nv_of[static_cast<std::size_t>(a)] == 0) a = Tree::parent[static_cast<std::size_t>(a)];
        out[k] = k > Tree::v_offset[b] ? static_cast<int>(k) - 1
                 : a < 0               ? -1
                                       : static_cast<int>(Tree::v_offset[static_cast<std::size_t>(a)] + Tree::nv_of[static_cast<std::size_t>(a)]) - 1;
    }
    return out;
}();

// H = Lᵀ D L (a tree without mimic joints) in place (Featherstone Table 6.3): H(k, k) becomes
// D_k, H(k, i) for i on k's path L(k, i); the rest of H is neither read nor written. A pivot
// D_k ≤ 0 (H not positive definite: a massless subtree) leaves positive_definite false (for
// robots in lanes: NaN in that lane).
template <class Tree, class T>
struct tree_factor {
    joint_matrix<Tree, T> LD;
    std::array<T, Tree::nv> inv_D;
    bool positive_definite;
};
template <class Tree, class T>
constexpr tree_factor<Tree, T> factor_tree(const joint_matrix<Tree, T>& H) noexcept {
    constexpr const std::array<int, Tree::nv>& lambda = dof_parent<Tree>;
    tree_factor<Tree, T> f{H, {}, true};
    auto& A = f.LD;
    for (std::size_t k = Tree::nv; k-- > 0;) {
        const T d = A[k][k];
        if constexpr (lane_wise<T>) {
            // robots in lanes (pack.hpp): a lane whose pivot is not positive gets NaN from here on
            f.inv_D[k] = select(d > T(0), T(1) / d, T(std::numeric_limits<typename T::value_type>::quiet_NaN()));
        } else {
            if (!(d > T(0))) {
                f.positive_definite = false;
                return f;
            }
            f.inv_D[k] = T(1) / d;
        }
        for (int i = lambda[k]; i >= 0; i = lambda[static_cast<std::size_t>(i)]) {
            const std::size_t u = static_cast<std::size_t>(i);
            const T a = A[k][u] * f.inv_D[k];
            for (int j = i; j >= 0; j = lambda[static_cast<std::size_t>(j)]) A[u][static_cast<std::size_t>(j)] -= a * A[k][static_cast<std::size_t>(j)];
            A[k][u] = a;
        }
    }
    return f;
}
// Z = H⁻¹ from the factor (above; all NaN when H is not positive definite); each row's entries
// j < i are mirrored into column i for the later rows.
template <class Tree, class T>
constexpr tree_matrix<Tree, T, sparsity::components> tree_inverse(const tree_factor<Tree, T>& f) noexcept {
    constexpr std::size_t n = Tree::nv;
    constexpr const std::array<int, n>& lambda = dof_parent<Tree>;
    tree_matrix<Tree, T, sparsity::components> Z(uninitialized);
    if (!f.positive_definite) {
        Z.entries.fill(std::numeric_limits<T>::quiet_NaN());
        return Z;
    }
    for (std::size_t i = 0; i < n; ++i) {
        T* row = Z.data() + i * n;
        for (std::size_t j = 0; j < i; ++j) row[j] = T(0);
        for (int m = lambda[i]; m >= 0; m = lambda[static_cast<std::size_t>(m)]) {
            const T l = f.LD[i][static_cast<std::size_t>(m)];
            const T* zm = Z.data() + static_cast<std::size_t>(m) * n;
            for (std::size_t j = 0; j < i; ++j) row[j] -= l * zm[j];
        }
        T d = f.inv_D[i];
        for (int m = lambda[i]; m >= 0; m = lambda[static_cast<std::size_t>(m)]) d -= f.LD[i][static_cast<std::size_t>(m)] * row[static_cast<std::size_t>(m)];
        row[i] = d;
        for (std::size_t j = 0; j < i; ++j) Z(j, i) = row[j];
    }
    return Z;
}
// H⁻¹ r from the factor (Featherstone Table 6.4): Lᵀ y = r from the leaves, z = D⁻¹ y, L x = z
// from the root (NaN when H is not positive definite).
template <class Tree, class T>
constexpr std::array<T, Tree::nv> tree_solve(const tree_factor<Tree, T>& f, std::array<T, Tree::nv> r) noexcept {
    constexpr const std::array<int, Tree::nv>& lambda = dof_parent<Tree>;
    if (!f.positive_definite) {
        r.fill(std::numeric_limits<T>::quiet_NaN());
        return r;
    }
    for (std::size_t k = Tree::nv; k-- > 0;)
        for (int i = lambda[k]; i >= 0; i = lambda[static_cast<std::size_t>(i)])
            r[static_cast<std::size_t>(i)] -= f.LD[k][static_cast<std::size_t>(i)] * r[k];
    for (std::size_t k = 0; k < Tree::nv; ++k) {
        T x = r[k] * f.inv_D[k];
        for (int i = lambda[k]; i >= 0; i = lambda[static_cast<std::size_t>(i)]) x -= f.LD[k][static_cast<std::size_t>(i)] * r[static_cast<std::size_t>(i)];
        r[k] = x;
    }
    return r;
}

}  // namespace algorithm_detail

struct minverse_t {
    template <class Tree, class T>
    [[nodiscard]] constexpr tree_matrix<Tree, T, sparsity::components> operator()(const model<Tree, T>& m,
                                                                                 const configuration<Tree, T>& q) const noexcept {
        using namespace algorithm_detail;
        if constexpr (Tree::has_mimic) return inverse_of<Tree>(crba(m, q));  // (inverse_of: why)
        else return tree_inverse(factor_tree<Tree>(crba(m, q)));
    }
};
// H⁻¹(q), the inverse of crba(m, q), with its components' pattern (tree_matrix.hpp).
inline constexpr algorithm<minverse_t, "minverse"> minverse{};

}  // namespace ctga::chains
