// The Delassus operator of a tree's constraints, W = J H⁻¹ Jᵀ (how the rows' rates answer forces
// along them), without forming H⁻¹: with the tree factor H = Lᵀ D L (minverse.hpp, Featherstone
// §6.5: L(k, i) ≠ 0 only for dof i on dof k's path, nothing fills in),
//     W = Y D⁻¹ Yᵀ,   Y = J L⁻¹   (each row's Yᵀ = L⁻ᵀ Jᵀ by the leaves-first sweep),
// and a row of J is non-zero on its two bodies' paths only, which the sweep keeps: a foot's row
// costs its leg and the base, W(r, s) sums over the dofs the two rows share. The pattern comes from
// the tree's type (constraint_rows.hpp's path tables); what is per call is which bodies a row
// joins. The same factor gives J H⁻¹ (τ − C) = Y D⁻¹ L⁻ᵀ (τ − C) and, after the solve,
// q̈ = L⁻¹ D⁻¹ (L⁻ᵀ (τ − C) + Yᵀ λ) (constrained_dynamics.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "ctga/chains/crba.hpp"
#include "ctga/chains/minverse.hpp"
#include "ctga/constrained/constraint_rows.hpp"
#include "ctga/constrained/constraint_set.hpp"
#include "ctga/support/checked.hpp"

namespace ctga::constrained {

// The dofs on either of two bodies' paths (−1: none), descending: a row's pattern.
template <class Tree>
struct row_pattern {
    std::array<std::size_t, Tree::nv> dofs;
    std::size_t count = 0;

    constexpr row_pattern() noexcept : dofs{} {}
    constexpr row_pattern(int a, int b) noexcept : dofs{} {
        using P = rows_detail::paths<Tree>;
        const auto range = [](int body) -> std::array<std::size_t, 2> {
            if (body < 0) return {0, 0};
            return {P::lists.first[static_cast<std::size_t>(body)], P::lists.first[static_cast<std::size_t>(body) + 1]};
        };
        auto [i, i_end] = range(a);
        auto [j, j_end] = range(b);
        // merge, from the largest down
        while (i_end > i || j_end > j) {
            const std::size_t x = i_end > i ? P::lists.list[i_end - 1] : 0, y = j_end > j ? P::lists.list[j_end - 1] : 0;
            const bool take_x = i_end > i && (j_end == j || x >= y);
            const bool take_y = j_end > j && (i_end == i || y >= x);
            dofs[count++] = take_x ? x : y;
            if (take_x) --i_end;
            if (take_y) --j_end;
        }
    }
    [[nodiscard]] constexpr std::span<const std::size_t> span() const noexcept { return {dofs.data(), count}; }
};

template <class Tree, class T, std::size_t Capacity>
constexpr std::array<row_pattern<Tree>, Capacity> make_patterns(const constraint_set<Tree, T, Capacity>& C) noexcept {
    std::array<row_pattern<Tree>, Capacity> out{};
    for (std::size_t i = 0; i < C.size(); ++i) out[i] = row_pattern<Tree>(C.blocks()[i].a, C.blocks()[i].b);
    return out;
}

template <class Tree, class T, std::size_t Capacity>
struct delassus_parts {
    static constexpr std::size_t max_rows = 3 * Capacity;
    std::array<std::array<T, Tree::nv>, max_rows> Y;      // J L⁻¹
    std::array<std::array<T, max_rows>, max_rows> W;      // Y D⁻¹ Yᵀ, symmetric, rows × rows used
};

// Y and W from the factor and the rows; pattern[r / 3] is block r / 3's row_pattern.
template <class Tree, class T, std::size_t Capacity>
constexpr void fill_delassus(delassus_parts<Tree, T, Capacity>& out, const chains::algorithm_detail::tree_factor<Tree, T>& f,
                             const constraint_rows<Tree, T, Capacity>& R, std::span<const row_pattern<Tree>> pattern) noexcept {
    for (std::size_t r = 0; r < R.count; ++r) {
        out.Y[r] = R.J[r];
        chains::algorithm_detail::transposed_sweep(f, out.Y[r].data(), pattern[r / 3].span());
    }
    for (std::size_t r = 0; r < R.count; ++r)
        for (std::size_t s = 0; s <= r; ++s) {
            T w = T(0);
            for (const std::size_t k : pattern[r / 3].span()) w += out.Y[r][k] * f.inv_D[k] * out.Y[s][k];
            out.W[r][s] = out.W[s][r] = w;
        }
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
    fill_rows(R, g, C, rest);
    const std::array<row_pattern<Tree>, Capacity> pattern = make_patterns(C);
    delassus_parts<Tree, T, Capacity> parts;
    fill_delassus(parts, f, R, std::span<const row_pattern<Tree>>(pattern.data(), C.size()));
    out.rows = R.count;
    for (std::size_t r = 0; r < R.count; ++r)
        for (std::size_t s = 0; s < R.count; ++s) out.W[r][s] = parts.W[r][s];
    return out;
}

}  // namespace ctga::constrained
