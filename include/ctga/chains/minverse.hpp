// The inverse of a tree's mass matrix, H⁻¹(q), never by inverting a dense H, by one of two
// routes, the cheaper for the tree's shape chosen at compile time (inverse_by_factor, below; issue
// 42 measured both):
//
// The tree factor. CRBA's H (in the bodies' frames, where turned and aligned joints cost least),
// then H = Lᵀ D L with L unit lower triangular and the tree's sparsity (Featherstone (2008) §6.5,
// LTDL: L(k, i) ≠ 0 only for dof i on the path from dof k to the root, so nothing fills in), then
// Z = H⁻¹ = L⁻¹ D⁻¹ L⁻ᵀ row by row from the root: L Z = D⁻¹ L⁻ᵀ is upper triangular with
// diagonal D⁻¹, so for j < i
//   Z(i, j) = −Σ_m L(i, m) Z(m, j),   Z(i, i) = D_i⁻¹ − Σ_m L(i, m) Z(i, m)
// over the dofs m on i's path: depth(i) contiguous rows of length i, so n³/3 multiply-adds on a
// chain and far fewer on a branched tree (UR5 542 → 244 ns, Solo 12 1598 → 1033 ns, the 44-dof
// humanoid's too).
//
// The articulated-body recursion (Featherstone (2008) §7.3) run on all unit joint forces at once
// (Carpentier's "Minverse", as in Pinocchio), O(n²), in the world frame, where every body's
// articulated inertia, forces and accelerations add without transforms: the route of long chains
// (the 30-body chain: 4.5 µs, the factor 7.3 µs). ABA with q̇ = 0, no gravity and τ = e_j gives
// column j of H⁻¹. Backwards, with N^A_i the articulated inertia (rigid inertias in the world
// frame, plus each child's N^A − U D⁻¹ Uᵀ), U_i = N^A_i S_i (a co-screw per dof), D_i = S_iᵀ U_i,
// and F_i[j] the bias force the bodies below i pass on for column j:
//   H⁻¹(i, j) ← D_i⁻¹ (δ_ij − S_iᵀ F_i[j]),     F_λ[j] = F_i[j] + U_i H⁻¹(i, j)
// (only j on i's subtree has F_i[j] ≠ 0: one co-screw per column, carried up its branch). Then
// forwards, a_λ[j] the parent's acceleration for column j (0 at the world):
//   H⁻¹(i, j) −= D_i⁻¹ U_iᵀ a_λ[j],              a_i[j] = a_λ[j] + S_i H⁻¹(i, j)
// for the columns j from body i's own on (H⁻¹ is symmetric: the rest is mirrored). A column of
// another component of the tree (another body on the world) is a structural zero (tree_matrix.hpp,
// sparsity::components) and is never touched.
//
// aba_derivatives takes the same route, with q̈ from the same factor or recursion. With mimic
// joints H is the reduced Gᵀ H G, whose pattern is not the tree's and for which the recursion does
// not hold: its dense Cholesky factor (inverse_of), as aba.hpp solves such trees.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/crba.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/chains/tree_matrix.hpp"
#include "ctga/chains/world_geometry.hpp"
#include "ctga/mechanics/articulated_inertia.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/cholesky.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/row_sum.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

namespace algorithm_detail {

// D⁻¹ of a joint's D = Sᵀ N^A S (n × n, symmetric positive definite for a body with mass): 1/D
// for one dof, from its Cholesky factor otherwise (all NaN when it is not positive definite:
// never a number that looks fine); inverse_of's dense H⁻¹ too.
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

// The dofs j ≥ the first of body b's own in b's component (its bodies hang from the world through
// the same root body), and whether b carries j's body: the columns of b's rows, forwards.
template <class Tree>
struct component_tables {
    struct entry {
        std::size_t j;
        bool carried;
    };
    static constexpr auto in = [](std::size_t b, std::size_t j) {
        return j >= Tree::v_offset[b] && root_of<Tree>(Tree::body_of_dof[j]) == root_of<Tree>(b);
    };
    static constexpr auto make = [](std::size_t b, std::size_t j) { return entry{j, Tree::supports(b, Tree::body_of_dof[j])}; };
    static constexpr auto later = make_dof_lists<Tree, entry, decltype(in), decltype(make)>();
};

// What the recursion keeps: per body its articulated inertia, per dof U, U D⁻¹ and the bias
// force F[j] passed up for column j.
template <class Tree, class T>
struct articulated_pass {
    std::array<articulated_inertia<T>, Tree::size> NA;
    std::array<coscrew<T>, Tree::nv> U, UD, F;

    explicit constexpr articulated_pass(uninitialized_t)
        : U(uninitialized_array<coscrew<T>, Tree::nv>()), UD(uninitialized_array<coscrew<T>, Tree::nv>()),
          F(uninitialized_array<coscrew<T>, Tree::nv>()) {}
};

// One more right-hand side, τ − the bias forces, gives ABA's q̈ in the same passes (aba_derivatives):
// with p_i = v_i ×* N_i v_i − f_ext,i and c_i = v_λ × v_i (the acceleration of the joint's motion,
// Σ Ψ̇ q̇: rnea_derivatives.hpp), backwards u = τ − Sᵀ p^A, w = D⁻¹ u and the parent's
// p^A += p^A + N^a c + U w (N^a = N^A − U D⁻¹ Uᵀ, Featherstone eq. 7.43 in the world frame, where
// nothing is transformed); forwards a' = a_λ + c, q̈ = w − (U D⁻¹)ᵀ a', a = a' + S q̈, from
// a = −g at the world.
template <class Tree, class T>
struct articulated_bias {
    const T* tau;
    std::array<coscrew<T>, Tree::size> p;          // v ×* N v − f_ext in; p^A as the bodies below add
    const std::array<screw<T>, Tree::size>& c;     // v_λ × v
    screw<T> a_world;                              // −g
    T* qdd;                                        // out
    std::array<T, Tree::nv> w;
    std::array<screw<T>, Tree::size> a;
};
struct no_bias {};

// Body j's step backwards, for a joint of K dofs (K = 1, or 6 for a floating joint): U, D⁻¹, the
// columns of the bodies below, its own columns, and what its parent sees.
template <std::size_t K, class Tree, class T, class Bias>
constexpr void minverse_backward_step(std::size_t j, const world_geometry<Tree, T>& g, articulated_pass<Tree, T>& P,
                                      tree_matrix<Tree, T, sparsity::components>& Minv, Bias& bias) noexcept {
    using tables = branch_tables<Tree>;
    auto& NA = P.NA;  // (references, not a structured binding: clang 14's lambdas cannot capture one)
    auto& U = P.U;
    auto& UD = P.UD;
    auto& F = P.F;
    const std::size_t o = Tree::v_offset[j];
    const int p = Tree::parent[j];
    constexpr bool biased = !std::is_same_v<Bias, no_bias>;
    std::array<std::array<T, K>, K> D;  // symmetric
    for (std::size_t c = 0; c < K; ++c) U[o + c] = momentum(NA[j], g.S[o + c]);
    for (std::size_t a = 0; a < K; ++a)
        for (std::size_t b = a; b < K; ++b) D[a][b] = D[b][a] = pairing(U[o + b], g.S[o + a]);
    for (std::size_t a = 0; a < K; ++a) D[a][a] += g.armature[o + a];  // D = Sᵀ N^A S + the joint's armature
    const std::array<std::array<T, K>, K> Dinv = joint_inverse(D);
    // S D⁻¹, so that a row D⁻¹ Sᵀ F is K pairings
    std::array<screw<T>, K> SD;
    for (std::size_t c = 0; c < K; ++c) {
        screw<T> x = g.S[o] * Dinv[0][c];
        for (std::size_t b = 1; b < K; ++b) x = x + g.S[o + b] * Dinv[b][c];
        SD[c] = x;
    }
    // U D⁻¹, for the parent and the rows forwards (of a body on the world, only q̈ needs it)
    if (p >= 0 || biased)
        for (std::size_t c = 0; c < K; ++c) {
            coscrew<T> x = U[o] * Dinv[0][c];
            for (std::size_t b = 1; b < K; ++b) x = x + U[o + b] * Dinv[b][c];
            UD[o + c] = x;
        }
    // the columns of the bodies below: H⁻¹(j, i) = −D⁻¹ Sᵀ F[i], then F[i] += U H⁻¹(j, i) for
    // the parent (a body on the world has none)
    for (std::size_t e = tables::carried.first[j]; e < tables::carried.first[j + 1]; ++e) {
        const std::size_t i = tables::carried.list[e];
        std::array<T, K> x;
        for (std::size_t c = 0; c < K; ++c) {
            x[c] = pairing(F[i], SD[c]);
            Minv(o + c, i) = -x[c];
        }
        if (p >= 0)
            for (std::size_t c = 0; c < K; ++c) F[i] = F[i] - U[o + c] * x[c];
    }
    // its own columns: H⁻¹ = D⁻¹ there, and F = U D⁻¹
    for (std::size_t c = 0; c < K; ++c) {
        for (std::size_t b = 0; b < K; ++b) Minv(o + b, o + c) = Dinv[b][c];
        if (p >= 0) F[o + c] = UD[o + c];
    }
    if constexpr (biased) {
        std::array<T, K> u;
        for (std::size_t b = 0; b < K; ++b) u[b] = bias.tau[o + b] - pairing(bias.p[j], g.S[o + b]);
        for (std::size_t c = 0; c < K; ++c) {
            T x = Dinv[c][0] * u[0];
            for (std::size_t b = 1; b < K; ++b) x += Dinv[c][b] * u[b];
            bias.w[o + c] = x;
        }
    }
    // the parent sees N^A − U D⁻¹ Uᵀ (zero for a 6-dof joint, up to rounding)
    if (p < 0) return;
    const std::size_t q = static_cast<std::size_t>(p);
    const articulated_inertia<T> Na = [&] {
        if constexpr (K == 1) {
            return minus_joint(NA[j], U[o], Dinv[0][0]);
        } else {
            articulated_inertia<T> x = NA[j];
            for (std::size_t e = 0; e < 21; ++e) {
                const auto rc = articulated_detail::upper_entries[e];
                T y = x.n[e][0];
                for (std::size_t b = 0; b < K; ++b) y -= UD[o + b][rc.i] * U[o + b][rc.j];
                x.n[e] = typename articulated_inertia<T>::scalar{y};
            }
            return x;
        }
    }();
    NA[q] = NA[q] + Na;
    if constexpr (biased) {
        coscrew<T> x = bias.p[j] + momentum(Na, bias.c[j]);
        for (std::size_t c = 0; c < K; ++c) x = x + U[o + c] * bias.w[o + c];
        bias.p[q] = bias.p[q] + x;
    }
}

// H⁻¹ from the world geometry (and, with a bias, q̈): backwards, then each body's rows forwards,
// then the lower triangle mirrored.
template <class Tree, class T, class Bias>
constexpr void articulated_recursion(const world_geometry<Tree, T>& g, tree_matrix<Tree, T, sparsity::components>& Minv,
                                     Bias& bias) noexcept {
    constexpr std::size_t n = Tree::size, nv = Tree::nv;
    constexpr bool biased = !std::is_same_v<Bias, no_bias>;
    articulated_pass<Tree, T> P{uninitialized};
    for (std::size_t i = 0; i < n; ++i) P.NA[i] = articulated_inertia_of(g.N[i]);
    // backwards: D⁻¹, the columns below each body, the articulated inertias
    for (std::size_t j = n; j-- > 0;) {
        const std::size_t k = Tree::nv_of[j];
        if (k == 1) minverse_backward_step<1>(j, g, P, Minv, bias);
        else if constexpr (branch_tables<Tree>::multi_dof) {
            if (k == 6) minverse_backward_step<6>(j, g, P, Minv, bias);
        }
        if (k == 0 && Tree::parent[j] >= 0) {
            const std::size_t q = static_cast<std::size_t>(Tree::parent[j]);
            P.NA[q] = P.NA[q] + P.NA[j];
            if constexpr (biased) bias.p[q] = bias.p[q] + bias.p[j];  // (c = 0: the body moves with its parent)
        }
    }
    // forwards: each body's rows over the later columns of its component, with its parent's
    // accelerations for them (the world's: zero)
    auto A = []<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<std::array<screw<T>, nv>, n>{((void)I, uninitialized_array<screw<T>, nv>())...};
    }(std::make_index_sequence<n>{});
    using later = component_tables<Tree>;
    for (std::size_t i = 0; i < n; ++i) {
        const int p = Tree::parent[i];
        const std::size_t o = Tree::v_offset[i], k = Tree::nv_of[i];
        for (std::size_t e = later::later.first[i]; e < later::later.first[i + 1]; ++e) {
            const auto [j, carried] = later::later.list[e];
            screw<T> a = p < 0 ? screw<T>{} : A[static_cast<std::size_t>(p)][j];
            for (std::size_t c = o; c < o + k; ++c) {
                T x = carried ? Minv(c, j) : T(0);  // (set backwards)
                if (p >= 0) x -= pairing(P.UD[c], A[static_cast<std::size_t>(p)][j]);
                Minv(c, j) = x;
                a = a + g.S[c] * x;
            }
            A[i][j] = a;
        }
        if constexpr (biased) {
            const screw<T> a_c = (p < 0 ? bias.a_world : bias.a[static_cast<std::size_t>(p)]) + bias.c[i];
            screw<T> a = a_c;
            for (std::size_t c = o; c < o + k; ++c) {
                bias.qdd[c] = bias.w[c] - pairing(P.UD[c], a_c);
                a = a + g.S[c] * bias.qdd[c];
            }
            bias.a[i] = a;
        }
    }
    // the lower triangle, mirrored
    for (std::size_t r = 0; r < nv; ++r)
        for (std::size_t c = 0; c < Tree::v_offset[Tree::body_of_dof[r]]; ++c)
            if (Minv.pattern[r][c]) Minv(r, c) = Minv(c, r);
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
// The dofs on dof i's path to the root, nearest first (λ(i), λ(λ(i)), …): list[first[i] … first[i + 1]).
template <class Tree>
inline constexpr auto dof_paths = [] {
    constexpr auto path = [](std::size_t i, auto&& f) {
        for (int m = dof_parent<Tree>[i]; m >= 0; m = dof_parent<Tree>[static_cast<std::size_t>(m)]) f(static_cast<std::size_t>(m));
    };
    constexpr std::size_t total = [&] {
        std::size_t c = 0;
        for (std::size_t i = 0; i < Tree::nv; ++i) path(i, [&](std::size_t) { ++c; });
        return c;
    }();
    dof_lists<Tree::nv, total> out;
    std::size_t c = 0;
    for (std::size_t i = 0; i < Tree::nv; ++i) {
        out.first[i] = c;
        path(i, [&](std::size_t m) { out.list[c++] = m; });
    }
    out.first[Tree::nv] = c;
    return out;
}();

// H = Lᵀ D L (a tree without mimic joints) in place (Featherstone Table 6.3): H(k, k) becomes
// D_k, H(k, i) for i on k's path L(k, i); the rest of H is neither read nor written (so H may be
// written into LD where it is built: factor_tree(f)). A pivot
// D_k ≤ 0 (H not positive definite: a massless subtree) leaves positive_definite false (for
// robots in lanes: NaN in that lane).
template <class Tree, class T>
struct tree_factor {
    joint_matrix<Tree, T> LD;
    std::array<T, Tree::nv> inv_D;
    bool positive_definite;
};
template <class Tree, class T>
constexpr void factor_tree(tree_factor<Tree, T>& f) noexcept {
    constexpr const std::array<int, Tree::nv>& lambda = dof_parent<Tree>;
    f.positive_definite = true;
    auto& A = f.LD;
    for (std::size_t k = Tree::nv; k-- > 0;) {
        const T d = A[k][k];
        if constexpr (lane_wise<T>) {
            // robots in lanes (pack.hpp): a lane whose pivot is not positive gets NaN from here on
            f.inv_D[k] = select(d > T(0), T(1) / d, T(std::numeric_limits<typename T::value_type>::quiet_NaN()));
        } else {
            if (!(d > T(0))) {
                f.positive_definite = false;
                return;
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
}
template <class Tree, class T>
constexpr tree_factor<Tree, T> factor_tree(const joint_matrix<Tree, T>& H) noexcept {
    tree_factor<Tree, T> f{H, {}, true};
    factor_tree(f);
    return f;
}
// Z = H⁻¹ from the factor (above; all NaN when H is not positive definite): L Z = D⁻¹ L⁻ᵀ, whose
// part below the diagonal is zero, gives row i from its path's rows, Z(i, j) = −Σ_m L(i, m) Z(m, j)
// for j < i (m < i on i's path: rows done, their entries m < j < i mirrored from row j), then
// Z(i, i) = D_i⁻¹ − Σ_m L(i, m) Z(i, m), and row i's entries j < i mirrored into column i.
// Row i's sums in registers (row_sum.hpp), in chunks of 4 registers, then of one, then single
// numbers: a chunk may run past i (Z is zero at first, so those sums are finite; the entries it
// writes past i are rewritten by the mirror of a later row or the diagonal). Measured, Solo 12:
// 461 ns summed in memory over j < i, 302 ns so.
template <class Tree, std::size_t L, class T>
constexpr void inverse_rows(const tree_factor<Tree, T>& f, T* Z) noexcept {
    constexpr std::size_t n = Tree::nv, chunk = 4 * L;
    constexpr const auto& paths = dof_paths<Tree>;
    const auto row_part = [&]<std::size_t Count, std::size_t Lanes>(std::size_t i, std::size_t j0) CTGA_INLINE_LAMBDA {
        row_sum<T, Count, Lanes> s;
        for (std::size_t e = paths.first[i]; e < paths.first[i + 1]; ++e) {
            const std::size_t m = paths.list[e];
            s.subtract(f.LD[i][m], Z + m * n + j0);
        }
        s.store(Z + i * n + j0);
    };
    for (std::size_t i = 0; i < n; ++i) {
        T* row = Z + i * n;
        std::size_t j = 0;
        for (; j < i && j + chunk <= n; j += chunk) row_part.template operator()<chunk, L>(i, j);
        for (; j < i && j + L <= n; j += L) row_part.template operator()<L, L>(i, j);
        for (; j < i; ++j) row_part.template operator()<1, 1>(i, j);
        T d = f.inv_D[i];
        for (std::size_t e = paths.first[i]; e < paths.first[i + 1]; ++e) d -= f.LD[i][paths.list[e]] * row[paths.list[e]];
        row[i] = d;
        for (std::size_t k = 0; k < i; ++k) Z[k * n + i] = row[k];
    }
}
template <class Tree, class T>
constexpr tree_matrix<Tree, T, sparsity::components> tree_inverse(const tree_factor<Tree, T>& f) noexcept {
    tree_matrix<Tree, T, sparsity::components> Z;  // zero
    if (!f.positive_definite) Z.entries.fill(std::numeric_limits<T>::quiet_NaN());
    else if (std::is_constant_evaluated()) inverse_rows<Tree, 1>(f, Z.data());
    else inverse_rows<Tree, row_lanes<T>>(f, Z.data());
    return Z;
}
// H⁻¹ r from the factor (Featherstone Table 6.4) in its two halves: Lᵀ y = r from the leaves
// (transposed_sweep), then L x = D⁻¹ y from the root (lower_sweep); NaN when H is not positive
// definite. The first half as its steps y_i −= L(k, i) y_k, k from the last dof down and i on k's
// path, handed to `step(k, i, L(k, i))`: for one vector (tree_solve), or for the columns of
// several at once (constrained/delassus.hpp: J's rows, a vector register at a time).
template <class Tree, class T, class Step>
constexpr void transposed_sweep(const tree_factor<Tree, T>& f, Step&& step) noexcept {
    constexpr const std::array<int, Tree::nv>& lambda = dof_parent<Tree>;
    for (std::size_t k = Tree::nv; k-- > 0;)
        for (int i = lambda[k]; i >= 0; i = lambda[static_cast<std::size_t>(i)]) step(k, static_cast<std::size_t>(i), f.LD[k][static_cast<std::size_t>(i)]);
}
template <class Tree, class T>
constexpr void lower_sweep(const tree_factor<Tree, T>& f, T* r) noexcept {
    constexpr const std::array<int, Tree::nv>& lambda = dof_parent<Tree>;
    for (std::size_t k = 0; k < Tree::nv; ++k) {
        T x = r[k] * f.inv_D[k];
        for (int i = lambda[k]; i >= 0; i = lambda[static_cast<std::size_t>(i)]) x -= f.LD[k][static_cast<std::size_t>(i)] * r[static_cast<std::size_t>(i)];
        r[k] = x;
    }
}
template <class Tree, class T>
constexpr std::array<T, Tree::nv> tree_solve(const tree_factor<Tree, T>& f, std::array<T, Tree::nv> r) noexcept {
    if (!f.positive_definite) {
        r.fill(std::numeric_limits<T>::quiet_NaN());
        return r;
    }
    transposed_sweep(f, [&](std::size_t k, std::size_t i, const T& l) { r[i] -= l * r[k]; });
    lower_sweep(f, r.data());
    return r;
}

// The route (above): the tree factor unless the dofs' paths are long, Σ_i depth(i)·i (the
// factor's multiply-adds for Z) above 12 per pair of dofs in one component (the recursion's two
// co-screw operations per pair): measured, the factor is faster on the arms, the quadrupeds and
// the 44-dof humanoid, the recursion on the 30-body chain.
template <class Tree>
inline constexpr bool inverse_by_factor = [] {
    std::size_t factor = 0, pairs = 0;
    for (std::size_t i = 0; i < Tree::nv; ++i) {
        std::size_t depth = 0;
        for (int m = dof_parent<Tree>[i]; m >= 0; m = dof_parent<Tree>[static_cast<std::size_t>(m)]) ++depth;
        factor += depth * i;
        for (std::size_t j = i; j < Tree::nv; ++j) pairs += tree_matrix<Tree, double, sparsity::components>::pattern[i][j];
    }
    return factor <= 12 * pairs;
}();

}  // namespace algorithm_detail

struct minverse_t {
    template <class Tree, class T>
    [[nodiscard]] constexpr tree_matrix<Tree, T, sparsity::components> operator()(const model<Tree, T>& m,
                                                                                 const configuration<Tree, T>& q) const noexcept {
        using namespace algorithm_detail;
        if constexpr (Tree::has_mimic) return inverse_of<Tree>(crba(m, q));  // (inverse_of: why)
        else if constexpr (inverse_by_factor<Tree>) return tree_inverse(factor_tree<Tree>(crba(m, q)));
        else {
            tree_matrix<Tree, T, sparsity::components> Minv(uninitialized);
            world_geometry<Tree, T> g{uninitialized};
            fill_world_geometry(g, m, q);
            no_bias none;
            articulated_recursion(g, Minv, none);
            return Minv;
        }
    }
};
// H⁻¹(q), the inverse of crba(m, q), with its components' pattern (tree_matrix.hpp).
inline constexpr algorithm<minverse_t, "minverse"> minverse{};

}  // namespace ctga::chains
