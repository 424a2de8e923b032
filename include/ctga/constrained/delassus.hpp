// The Delassus operator of a tree's constraints, W = J H⁻¹ Jᵀ (how the rows' rates answer forces
// along them), without forming H⁻¹: with the tree factor H = Lᵀ D L (minverse.hpp, Featherstone
// §6.5: L(k, i) ≠ 0 only for dof i on dof k's path, nothing fills in),
//     W = Y D⁻¹ Yᵀ,   Y = J L⁻¹   (Yᵀ = L⁻ᵀ Jᵀ by the leaves-first sweep of tree_solve),
// J's rows are non-zero on their bodies' paths only (constraint_rows.hpp, from the tree's type),
// and the sweep keeps them there (L(k, i) ≠ 0 only for i on k's path). It runs on all the rows at
// once, by dof: a step y_i −= L(k, i) y_k over the rows of the blocks that reach dof k, and W a sum
// of rank-one terms D_k⁻¹ y_k y_kᵀ on the 3 × 3 blocks of the pairs of blocks reaching k: a foot's
// leg costs its own block, the base every pair, a limb no block reaches nothing. The same factor gives J H⁻¹ (τ − C) = Y D⁻¹ L⁻ᵀ (τ − C) and, after
// the solve, q̈ = L⁻¹ D⁻¹ (L⁻ᵀ (τ − C) + Yᵀ λ) (constrained_dynamics.hpp). (Measured, Solo 12's
// four feet: the sums row by row, 1.5 µs; rank-one terms over all rows, 2.2 µs.) The sweeps of
// the frictional solver need W only as W r = Y (D⁻¹ Yᵀ r) (constrained_dynamics.hpp's
// tree_delassus): Y is filled alone (fill_sweep), W (fill_w) where a direct solve or Newton needs it.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "ctga/chains/crba.hpp"
#include "ctga/chains/minverse.hpp"
#include "ctga/constrained/constraint_rows.hpp"
#include "ctga/constrained/constraint_set.hpp"
#include "ctga/support/checked.hpp"

namespace ctga::constrained {

template <class Tree, class T, std::size_t Capacity>
struct delassus_parts {
    static constexpr std::size_t max_rows = 3 * Capacity;
    std::array<std::array<T, max_rows>, Tree::nv> Y;   // by dof: Y[k][r] = (J L⁻¹)(r, k), r < the rows' count
    std::array<std::array<T, max_rows>, max_rows> W;   // Y D⁻¹ Yᵀ on the rows in use (the rest unset)
};

// Y_k is zero on the rows of the blocks dof k does not reach, so both the sweep's steps and W's
// terms run over one contiguous span of rows, from k's first block to its last (any block
// between that k does not reach adds zeros): no loop over the blocks, vectorised. (Measured,
// a grasp's 24 rows: 1,356 ns by blocks of three rows, 653 ns by spans.)
template <class Tree, class T, std::size_t Capacity>
constexpr void fill_sweep(delassus_parts<Tree, T, Capacity>& out, const chains::algorithm_detail::tree_factor<Tree, T>& f,
                          const constraint_rows<Tree, T, Capacity>& R) noexcept {
    const std::size_t n = R.count;  // (the rows in use: the rest of Y and W is left as it was)
    for (std::size_t k = 0; k < Tree::nv; ++k)
        for (std::size_t r = 0; r < n; ++r) out.Y[k][r] = R.columns[k][r];
    // the sweep: dof k's blocks reach every dof on k's path too
    chains::algorithm_detail::transposed_sweep(f, [&](std::size_t k, std::size_t i, const T& l) {
        const auto [first, last] = row_span(R.reach[k]);
        for (std::size_t r = first; r < last; ++r) out.Y[i][r] -= l * out.Y[k][r];
    });
}
// W from Y (fill_sweep's): D_k⁻¹ y_k y_kᵀ on the span of dof k's rows, a body's dofs together
// (they reach the same blocks): each row of W loaded and stored once a body, not once a dof
// (measured, a grasp's 24 rows, its cube's six dofs on all: 535 → 400 ns; Solo 12's 780 → 560 ns).
template <class Tree, class T, std::size_t Capacity>
constexpr void fill_w(delassus_parts<Tree, T, Capacity>& out, const chains::algorithm_detail::tree_factor<Tree, T>& f,
                      const constraint_rows<Tree, T, Capacity>& R) noexcept {
    for (std::size_t r = 0; r < R.count; ++r) out.W[r].fill(T(0));  // (whole rows: stores of a known length, no call per row)
    [&]<std::size_t... B>(std::index_sequence<B...>) {
        const auto body = [&]<std::size_t b>() {
            constexpr std::size_t o = Tree::v_offset[b], dofs = Tree::nv_of[b];
            if constexpr (dofs > 0) {
                const auto [first, last] = row_span(R.reach[o]);
                for (std::size_t r = first; r < last; ++r) {
                    std::array<T, dofs> a;
                    for (std::size_t j = 0; j < dofs; ++j) a[j] = f.inv_D[o + j] * out.Y[o + j][r];
                    for (std::size_t c = first; c < last; ++c) {
                        T w = out.W[r][c];
                        for (std::size_t j = 0; j < dofs; ++j) w += a[j] * out.Y[o + j][c];
                        out.W[r][c] = w;
                    }
                }
            }
        };
        (body.template operator()<B>(), ...);
    }(std::make_index_sequence<Tree::size>{});
}
template <class Tree, class T, std::size_t Capacity>
constexpr void fill_delassus(delassus_parts<Tree, T, Capacity>& out, const chains::algorithm_detail::tree_factor<Tree, T>& f,
                             const constraint_rows<Tree, T, Capacity>& R) noexcept {
    fill_sweep(out, f, R);
    fill_w(out, f, R);
}

template <class T, std::size_t Capacity>
struct delassus_matrix {
    error_code error = error_code::none;  // massless_subtree: H is not positive definite
    std::size_t rows = 0;
    std::array<std::array<T, 3 * Capacity>, 3 * Capacity> W{};
};

// W(q) for the set's blocks (3 rows each, in block order; rows in B's constraint axes).
template <class Tree, class T, std::size_t Capacity>
[[nodiscard]] constexpr delassus_matrix<T, Capacity> delassus(const chains::model<Tree, T>& m, const chains::configuration<Tree, T>& q,
                                                              const constraint_set<Tree, T, Capacity>& C) noexcept {
    static_assert(!Tree::has_mimic, "ctga::constrained: trees with mimic joints are not supported yet (their H is not the tree factor's)");
    delassus_matrix<T, Capacity> out;
    const auto f = chains::algorithm_detail::factor_tree<Tree>(chains::crba(m, q));
    if (!f.positive_definite) return out.error = error_code::massless_subtree, out;
    tree_motion<Tree, T> g(uninitialized);
    const chains::joint_vector<Tree, T> rest{};
    fill_tree_motion(g, m, q, rest);
    constraint_rows<Tree, T, Capacity> R;
    fill_rows(R, g, C, q, rest);
    delassus_parts<Tree, T, Capacity> parts;
    fill_delassus(parts, f, R);
    out.rows = R.count;
    for (std::size_t r = 0; r < R.count; ++r)
        for (std::size_t c = 0; c < R.count; ++c) out.W[r][c] = parts.W[r][c];
    return out;
}

}  // namespace ctga::constrained
