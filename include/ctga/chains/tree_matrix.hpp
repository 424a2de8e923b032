// An nv × nv matrix of a kinematic tree whose structurally non-zero entries are known from the
// tree's type: the derivatives of its dynamics (rnea_derivatives.hpp, aba_derivatives.hpp) and
// the inverse mass matrix (minverse.hpp).
//
//   sparsity::branches    (i, j) can be non-zero only when the bodies of dofs i and j (or of the
//                         mimic joints following them) lie on one branch, one supporting the
//                         other (Featherstone (2008) §6.2: the mass matrix's pattern; ∂τ/∂q and
//                         ∂τ/∂q̇ have it too, rnea_derivatives.hpp): a leg's torques do not
//                         depend on another leg's angles.
//   sparsity::components  (i, j) can be non-zero only when the two bodies hang from the world
//                         through the same root body (H is block diagonal by the tree's
//                         components, so are H⁻¹ and ∂q̈ = −H⁻¹ ∂τ); a floating base makes a
//                         tree one component, dense.
//
// The entries are stored row-major and dense (data(): an Eigen::Map<Matrix<T, nv, nv,
// RowMajor>> reads them in place); the algorithms write the pattern's entries only and the rest
// are zeros set once, never computed.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include "ctga/chains/tree.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

enum class sparsity { branches, components };

template <class Tree, class T, sparsity Pattern>
struct tree_matrix {
    static constexpr std::size_t n = Tree::nv;

    // pattern[i][j]: entry (i, j) can be non-zero. A dof moves its body and the mimic joints that
    // follow it (joints.hpp): any of those bodies on one branch (in one component) with any of j's.
    static constexpr std::array<std::array<bool, n>, n> pattern = [] {
        std::array<int, Tree::size> root{};
        for (std::size_t b = 0; b < Tree::size; ++b)
            root[b] = Tree::parent[b] < 0 ? static_cast<int>(b) : root[static_cast<std::size_t>(Tree::parent[b])];
        std::array<std::array<bool, Tree::size>, Tree::size> related{};  // on one branch / in one component
        for (std::size_t a = 0; a < Tree::size; ++a)
            for (std::size_t b = 0; b < Tree::size; ++b)
                related[a][b] = Pattern == sparsity::branches ? Tree::supports(a, b) || Tree::supports(b, a) : root[a] == root[b];
        std::array<std::array<std::size_t, Tree::size>, n> moved{};  // the bodies dof i moves
        std::array<std::size_t, n> count{};
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t b = 0; b < Tree::size; ++b)
                if (b == Tree::body_of_dof[i] || Tree::master[b] == static_cast<int>(Tree::body_of_dof[i])) moved[i][count[i]++] = b;
        std::array<std::array<bool, n>, n> p{};
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j)
                for (std::size_t x = 0; x < count[i]; ++x)
                    for (std::size_t y = 0; y < count[j]; ++y) p[i][j] = p[i][j] || related[moved[i][x]][moved[j][y]];
        return p;
    }();
    static constexpr std::size_t nonzeros = [] {
        std::size_t k = 0;
        for (const auto& row : pattern)
            for (bool x : row) k += x;
        return k;
    }();
    [[nodiscard]] static constexpr bool structural(std::size_t i, std::size_t j) noexcept { return pattern[i][j]; }
    // the places (i n + j) of the structural zeros
    static constexpr auto zeros = [] {
        std::array<std::size_t, n * n - nonzeros> z{};
        std::size_t k = 0;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j)
                if (!pattern[i][j]) z[k++] = i * n + j;
        return z;
    }();

    std::array<T, n * n> entries;  // row-major

    // Zero.
    constexpr tree_matrix() noexcept : entries{} {}
    // The entries outside the pattern zero, the pattern's left for the algorithm to write.
    constexpr explicit tree_matrix(uninitialized_t) noexcept {
        if (std::is_constant_evaluated()) entries = {};
        else
            for (std::size_t k : zeros) entries[k] = T(0);
    }

    [[nodiscard]] constexpr T& operator()(std::size_t i, std::size_t j) noexcept { return entries[i * n + j]; }
    [[nodiscard]] constexpr const T& operator()(std::size_t i, std::size_t j) const noexcept { return entries[i * n + j]; }
    [[nodiscard]] constexpr T* data() noexcept { return entries.data(); }
    [[nodiscard]] constexpr const T* data() const noexcept { return entries.data(); }
    // The plain matrix, row by row (crba's joint_matrix).
    [[nodiscard]] constexpr std::array<std::array<T, n>, n> dense() const noexcept {
        std::array<std::array<T, n>, n> out{};
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) out[i][j] = entries[i * n + j];
        return out;
    }
};

}  // namespace ctga::chains
