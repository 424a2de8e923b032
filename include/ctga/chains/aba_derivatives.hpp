// The derivatives of forward dynamics, ∂q̈/∂q, ∂q̈/∂q̇ and ∂q̈/∂τ = H⁻¹, of a kinematic tree
// (Carpentier and Mansard, RSS 2018). Forward dynamics solves ID(q, q̇, q̈) = τ, so differentiating
// the identity ID(q, q̇, FD(q, q̇, τ)) = τ gives
//   ∂q̈/∂τ = H⁻¹,   ∂q̈/∂q = −H⁻¹ ∂τ/∂q,   ∂q̈/∂q̇ = −H⁻¹ ∂τ/∂q̇
// with ∂τ/∂(q, q̇) of inverse dynamics (rnea_derivatives.hpp) at q̈ = FD(q, q̇, τ). All from one
// world geometry and its velocities, H⁻¹ and q̈ by minverse.hpp's route for the tree: H and the
// bias forces b = τ(q, q̇, 0) (composite inertias and forces, backwards), H = Lᵀ D L with the
// tree's sparsity, q̈ by its two triangular solves and H⁻¹ from the factor; or, on long chains,
// the articulated-body recursion with τ − b as one more right-hand side. Then ∂τ at q̈.
// Configuration derivatives are in the tangent space, as rnea_derivatives'. H⁻¹ has the tree's
// components' pattern, ∂τ its branches', so ∂q̈ has the components' (tree_matrix.hpp).
// With mimic joints: q̈ by aba, ∂τ and H by rnea_derivatives, H⁻¹ from H's Cholesky factor.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/chains/aba.hpp"
#include "ctga/chains/arguments.hpp"
#include "ctga/chains/minverse.hpp"
#include "ctga/chains/rnea_derivatives.hpp"
#include "ctga/chains/tree_matrix.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/row_sum.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
struct aba_partials {
    joint_vector<Tree, T> qdd;                                 // q̈ = FD(q, q̇, τ), as aba
    tree_matrix<Tree, T, sparsity::components> dqdd_dq;        // ∂q̈/∂q (tangent space)
    tree_matrix<Tree, T, sparsity::components> dqdd_dv;        // ∂q̈/∂q̇
    tree_matrix<Tree, T, sparsity::components> Minv;           // ∂q̈/∂τ = H⁻¹
};

namespace algorithm_detail {
// −A B₁ and −A B₂ for A = H⁻¹ (symmetric, the components' pattern) and B₁, B₂ of the branches'
// pattern (∂τ/∂q, ∂τ/∂q̇; B₁'s columns of translates_tree zero): column j of a product is
// −Σ_k B(k, j) A(·, k) = −Σ_k B(k, j) A(k, ·)ᵀ, over the k on j's branch only (B's pattern, a
// compile-time list per column), each a multiply-add over A's whole row (contiguous, of constant
// length; A's stored zeros make the entries outside j's component exact zeros), the column's sum
// in registers (row_sum.hpp) and written once. Measured, the legged tree's aba_derivatives: 7.45 µs
// by columns summed in memory, 8.2 over B's full rows, 10.0 by runs of B's structural columns.
template <class Tree>
struct branch_columns {
    // the rows k of column j in the branches' pattern: list[first[j] … first[j + 1])
    static constexpr auto rows = [] {
        using B = tree_matrix<Tree, double, sparsity::branches>;
        constexpr std::size_t n = Tree::nv;
        dof_lists<n, B::nonzeros> out;
        std::size_t c = 0;
        for (std::size_t j = 0; j < n; ++j) {
            out.first[j] = c;
            for (std::size_t k = 0; k < n; ++k)
                if (B::pattern[k][j]) out.list[c++] = k;
        }
        out.first[n] = c;
        return out;
    }();
};
// The dofs whose column of ∂τ/∂q is zero: a body on the world moved along a translation (a
// prismatic root, a floating base's v): the whole tree translates rigidly and uniform gravity does
// not see it (Ψ̇ = 0, Ψ̈ = (−g) × S = 0 for two translations), so its entries are exact zeros
// and the product skips them (a quarter of ∂q̈/∂q's work on a legged robot).
template <class J, std::size_t K>
constexpr bool translation_dof() {  // S_K's blades all hold the null generator e (mask bit 3: e1e, e2e, e3e)
    using S = std::remove_cvref_t<decltype(J::template subspace<K, double>(std::declval<const typename J::template parameters<double>&>()))>;
    for (std::size_t i = 0; i < S::layout.size(); ++i)
        if (!(S::layout.masks[i] & 8u)) return false;
    return true;
}
template <class Tree, std::size_t B, std::size_t... K>
constexpr void mark_translations(std::array<bool, Tree::nv>& out, std::index_sequence<K...>) {
    ((out[Tree::v_offset[B] + K] = translation_dof<typename Tree::template joint_at<B>, K>()), ...);
}
template <class Tree, std::size_t... B>
constexpr std::array<bool, Tree::nv> translations_on_world(std::index_sequence<B...>) {
    std::array<bool, Tree::nv> out{};
    ((Tree::parent[B] < 0 ? mark_translations<Tree, B>(out, std::make_index_sequence<Tree::template joint_at<B>::nv>{}) : void()), ...);
    return out;
}
template <class Tree>
inline constexpr std::array<bool, Tree::nv> translates_tree = translations_on_world<Tree>(std::make_index_sequence<Tree::size>{});

// Column j of −A B, rows [First, n) in passes of at most 12 registers (row_sum.hpp).
template <class Tree, std::size_t L, std::size_t First = 0, class T>
CTGA_ALWAYS_INLINE constexpr void minus_column(const T* A, const T* B, std::size_t j, T* out) noexcept {
    constexpr std::size_t n = Tree::nv, pass = 12 * L, count = n - First < pass ? n - First : pass;
    constexpr const auto& rows = branch_columns<Tree>::rows;
    row_sum<T, count, L> s;
    for (std::size_t e = rows.first[j]; e < rows.first[j + 1]; ++e) {
        const std::size_t k = rows.list[e];
        s.subtract(B[k * n + j], A + k * n + First);
    }
    s.each([&](std::size_t i, const T& v) CTGA_INLINE_LAMBDA { out[(First + i) * n + j] = v; });
    if constexpr (First + count < n) minus_column<Tree, L, First + count>(A, B, j, out);
}
template <class Tree, std::size_t L, class T>
constexpr void minus_products_by(const T* A, const T* B1, const T* B2, T* out1, T* out2) noexcept {
    for (std::size_t j = 0; j < Tree::nv; ++j) {
        if (translates_tree<Tree>[j])  // B1's column j is zero
            for (std::size_t i = 0; i < Tree::nv; ++i) out1[i * Tree::nv + j] = T(0);
        else minus_column<Tree, L>(A, B1, j, out1);
        minus_column<Tree, L>(A, B2, j, out2);
    }
}
template <class Tree, class T, class B>
constexpr void minus_products(const tree_matrix<Tree, T, sparsity::components>& A, const B& B1, const B& B2,
                              tree_matrix<Tree, T, sparsity::components>& out1, tree_matrix<Tree, T, sparsity::components>& out2) noexcept {
    if (std::is_constant_evaluated()) minus_products_by<Tree, 1>(A.data(), B1.data(), B2.data(), out1.data(), out2.data());
    else minus_products_by<Tree, row_lanes<T>>(A.data(), B1.data(), B2.data(), out1.data(), out2.data());
}

// H and b = τ(q, q̇, 0) from the world geometry and velocities (derivative_velocities: c = v_λ × v
// and F = v ×* N v − f_ext): with q̈ = 0 the accelerations are a_i = a_λ + c_i from −g at the
// world; backwards, with each subtree's composite inertia N^c and force F^c (F_i = N_i a_i + F),
// b_k = F^c_j(S_k) and H(k, l) = (N^c_j S_l)(S_k) for l a dof of body j and k one of j or an
// ancestor (plus the armature on the diagonal). H's other entries are left as they are.
template <class Tree, class T>
constexpr void mass_and_bias(const derivative_pass<Tree, T>& d, const screw<T>& a_world, joint_matrix<Tree, T>& H,
                             std::array<T, Tree::nv>& b) noexcept {
    using tables = branch_tables<Tree>;
    std::array<body_inertia<T>, Tree::size> Nc = d.N;
    std::array<coscrew<T>, Tree::size> F = uninitialized_array<coscrew<T>, Tree::size>();
    std::array<screw<T>, Tree::size> a = uninitialized_array<screw<T>, Tree::size>();
    for (std::size_t i = 0; i < Tree::size; ++i) {
        const int p = Tree::parent[i];
        a[i] = (p < 0 ? a_world : a[static_cast<std::size_t>(p)]) + d.c[i];
        F[i] = d.Fc[i] + momentum(d.N[i], a[i]);
    }
    for (std::size_t j = Tree::size; j-- > 0;) {
        const std::size_t o = Tree::v_offset[j], nv = Tree::nv_of[j];
        for (std::size_t c = o; c < o + nv; ++c) {
            const coscrew<T> U = momentum(Nc[j], d.S[c]);
            b[c] = pairing(F[j], d.S[c]);
            for (std::size_t k = o; k < o + nv; ++k) H[k][c] = pairing(U, d.S[k]);
            H[c][c] += d.armature[c];
            for (std::size_t e = tables::supporting.first[j]; e < tables::supporting.first[j + 1]; ++e) {
                const std::size_t k = tables::supporting.list[e];
                H[k][c] = H[c][k] = pairing(U, d.S[k]);
            }
        }
        if (const int p = Tree::parent[j]; p >= 0) {
            const std::size_t q = static_cast<std::size_t>(p);
            Nc[q] = Nc[q] + Nc[j];
            F[q] = F[q] + F[j];
        }
    }
}

// ∂τ/∂q and ∂τ/∂q̇ without τ and M (derivative_backward writes what its output has): only their
// pattern's entries are written and read (minus_products), the rest left unset.
template <class Tree, class T>
struct pattern_entries {
    std::array<T, Tree::nv * Tree::nv> entries;
    [[nodiscard]] constexpr T& operator()(std::size_t i, std::size_t j) noexcept { return entries[i * Tree::nv + j]; }
    [[nodiscard]] constexpr const T* data() const noexcept { return entries.data(); }
};
template <class Tree, class T>
struct inverse_partials {
    pattern_entries<Tree, T> dtau_dq, dtau_dv;
};
}  // namespace algorithm_detail

struct aba_derivatives_t {
    template <class Tree, class T>
    [[nodiscard]] constexpr aba_partials<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                             const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& tau) const noexcept {
        return run(m, q, qd, tau, static_cast<const body_wrenches<Tree, T>*>(nullptr));
    }
    // … with an external wrench on each body (body frame, about the body's origin), as aba.
    template <class Tree, class T>
    [[nodiscard]] constexpr aba_partials<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                             const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& tau,
                                                             const body_wrenches<Tree, T>& f_ext) const noexcept {
        return run(m, q, qd, tau, &f_ext);
    }

private:
    // One world geometry for all: H and b, H's tree factor, q̈ and H⁻¹ from it (minverse.hpp), then
    // ∂τ at q̈ (rnea_derivatives.hpp) from the same velocities.
    template <class Tree, class T>
    static constexpr aba_partials<Tree, T> run(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                               const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& tau,
                                               const body_wrenches<Tree, T>* f_ext) noexcept {
        using namespace algorithm_detail;
        using C = tree_matrix<Tree, T, sparsity::components>;
        if constexpr (Tree::has_mimic) {
            // the articulated-body recursion does not hold with couplings: q̈ by aba (a Cholesky
            // solve), ∂τ and H by rnea_derivatives (reduced), H⁻¹ from H's Cholesky factor
            const joint_vector<Tree, T> qdd = f_ext ? chains::aba(m, q, qd, tau, *f_ext) : chains::aba(m, q, qd, tau);
            const rnea_partials<Tree, T> id = f_ext ? rnea_derivatives(m, q, qd, qdd, *f_ext) : rnea_derivatives(m, q, qd, qdd);
            aba_partials<Tree, T> out{qdd, C(uninitialized), C(uninitialized), inverse_of<Tree>(id.M.dense())};
            minus_products(out.Minv, id.dtau_dq, id.dtau_dv, out.dqdd_dq, out.dqdd_dv);
            return out;
        } else {
            derivative_pass<Tree, T> d{uninitialized};
            fill_world_geometry(d, m, q);
            for (std::size_t i = 0; i < Tree::size; ++i) derivative_velocities(d, i, qd.data(), f_ext);
            const screw<T> a_world{T(0), T(0), T(0), -m.gravity[0], -m.gravity[1], -m.gravity[2]};
            aba_partials<Tree, T> out{{}, C(uninitialized), C(uninitialized), C(uninitialized)};
            if constexpr (inverse_by_factor<Tree>) {
                tree_factor<Tree, T> f;  // H's pattern only is written and read
                std::array<T, Tree::nv> b;
                mass_and_bias(d, a_world, f.LD, b);
                factor_tree(f);
                for (std::size_t k = 0; k < Tree::nv; ++k) b[k] = tau[k] - b[k];
                out.qdd = tree_solve(f, b);
                out.Minv = tree_inverse(f);
            } else {  // the articulated-body recursion with τ − the bias forces as one more right-hand side
                articulated_bias<Tree, T> bias{tau.data(), d.Fc, d.c, a_world,
                                               out.qdd.data(), {}, uninitialized_array<screw<T>, Tree::size>()};
                articulated_recursion(d, out.Minv, bias);
            }
            for (std::size_t i = 0; i < Tree::size; ++i) derivative_accelerations(d, i, a_world, out.qdd.data());
            inverse_partials<Tree, T> id;
            derivative_backward(d, id);
            minus_products(out.Minv, id.dtau_dq, id.dtau_dv, out.dqdd_dq, out.dqdd_dv);
            return out;
        }
    }
};
// The derivatives of q̈ = aba(m, q, q̇, τ[, f_ext]) with q̈ itself: aba_partials.
inline constexpr algorithm<aba_derivatives_t, "aba_derivatives"> aba_derivatives{};

}  // namespace ctga::chains
