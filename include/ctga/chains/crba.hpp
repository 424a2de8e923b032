// The joint-space mass matrix H(q) of a kinematic tree: the composite rigid body algorithm
// (Featherstone (2008) §6.2), with each body's N by its ten parameters (body_inertia). H(j, k) =
// F_k(S_j), F_k = N^c S_k the force of column k (dof k of body i, N^c_i the composite of body i
// and everything it carries), for every dof j of i and of its ancestors. Two formulations of
// these sums, the cheaper one for the tree's shape taken at compile time (crba_cost):
//
// - in each body's frame (local): N^c_i = N_i + Σ_children X_c N^c_c (transform(X, body_inertia),
//   54m 50a, 34m 33a across an aligned joint); F = N^c_i S_ik, then H(j, l) = F(S_jl) for body
//   i's own dofs and, moving F out through X_i, X_λ(i), … (24m 18a each, 14m 10a aligned), each
//   ancestor j. An axis joint's S is one blade, so
//   N S and F(S) cost almost nothing; the transforms, one per (dof, ancestor body), dominate.
//   Body by body as each_body visits them (runs.hpp); the walk up the ancestors unrolled from a
//   body of compile-time index, else a loop that visits each ancestor as its kind. With mimic
//   joints the entries are summed into H = Gᵀ H_all G.
// - in the world frame (world): with every body's S and N moved out once (world_geometry.hpp),
//   the composites are sums (10a per body) and each entry one pairing of world co-screw and
//   screw (6m 5a), so an entry costs no transform: cheaper for deep trees, whose (dof, ancestor)
//   pairs outnumber the bodies (a 30-body chain: 435 transforms against 30 world placements).
//   Loops over the bodies and the ancestors' dofs (tables), so its code does not grow with the
//   pairs. (Trees with mimic joints take the local form.)
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/runs.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/chains/world_geometry.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/inertia_transform.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/inline.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
using joint_matrix = std::array<std::array<T, Tree::nv>, Tree::nv>;  // H, row-major

namespace algorithm_detail {
// The weight of body b's joint in G (joints.hpp): a mimic's multiplier, 1 for any other joint.
template <class B, class Tree, class T>
CTGA_ALWAYS_INLINE constexpr T dof_weight(const B& b, const model<Tree, T>& m) noexcept {
    if constexpr (is_mimic<typename B::joint>) return b.link(m).joint.multiplier;
    else return T(1);
}
// H(j, c) = F(S_j) for body b's dofs j, F from column c. In a tree with mimic joints the entries
// of H_all are added into H = Gᵀ H_all G with their weights: an ancestor's entry both ways round
// (H_all is symmetric and only its lower part is computed), the column's own body's (Own) once,
// since its columns give its whole block.
// (The weight is passed in a tree with mimic joints only: the others' code has no trace of it.)
template <bool Own, class B, class Tree, class T, class... Weight>
CTGA_ALWAYS_INLINE constexpr void fill_rows(const B& b, const model<Tree, T>& m, joint_matrix<Tree, T>& H, std::size_t col,
                                            const coscrew<T>& F, const Weight&... w_col) noexcept {
    using Jt = typename B::joint;
    constexpr std::size_t n = is_mimic<Jt> ? 1 : Jt::nv;
    const auto& L = b.link(m);
    if constexpr (!Tree::has_mimic) {
        [&]<std::size_t... K>(std::index_sequence<K...>) CTGA_INLINE_LAMBDA {
            ((H[b.v_own + K][col] = H[col][b.v_own + K] = pairing(F, Jt::template subspace<K, T>(L.joint))), ...);
        }(std::make_index_sequence<n>{});
    } else {
        const T w = (w_col * ...) * dof_weight(b, m);
        const auto add = [&](std::size_t row, const T& x) {
            H[row][col] += x;
            if constexpr (!Own) H[col][row] += x;
        };
        [&]<std::size_t... K>(std::index_sequence<K...>) {
            (add(b.v_src + K, w * pairing(F, Jt::template subspace<K, T>(L.joint))), ...);
        }(std::make_index_sequence<n>{});
    }
}
// F moved out of body b into its parent's frame, and the parent's entries filled; then on up:
// for a body of compile-time index by recursion (unrolled), else by a loop over the ancestors,
// each visited as its kind (runs.hpp).
template <class B, class Tree, class T, class Links, class... Weight>
CTGA_ALWAYS_INLINE constexpr void fill_ancestors(const B& b, const model<Tree, T>& m, const Links& links,
                                                 const std::array<motor_map<T>, Tree::size>& X, joint_matrix<Tree, T>& H,
                                                 std::size_t col, const coscrew<T>& F, const Weight&... w_col) noexcept {
    const auto fill = [&](const auto& a, const coscrew<T>& Fa) CTGA_INLINE_LAMBDA {
        if constexpr (moves<typename std::remove_cvref_t<decltype(a)>::joint>) fill_rows<false>(a, m, H, col, Fa, w_col...);
    };
    if constexpr (B::constant) {
        if constexpr (!B::root) {
            using parent = run_detail::single_body<Tree, B::p>;
            const coscrew<T> Fp = transform<map_shape<typename B::joint>>(X[B::i], F);
            fill(parent{}, Fp);
            fill_ancestors(parent{}, m, links, X, H, col, Fp, w_col...);
        }
    } else {
        // each ancestor, visited as its kind, fills its rows and moves F on by its own map
        if constexpr (!B::root) {
            coscrew<T> Fa = transform<map_shape<typename B::joint>>(X[b.i], F);
            for (std::size_t a = b.p;; a = static_cast<std::size_t>(Tree::parent[a])) {
                bool top = false;
                visit_body<Tree, T>(links, a, [&](const auto& ancestor) CTGA_INLINE_LAMBDA {
                    using A = std::remove_cvref_t<decltype(ancestor)>;
                    fill(ancestor, Fa);
                    if constexpr (A::root) top = true;
                    else Fa = transform<map_shape<typename A::joint>>(X[a], Fa);
                });
                if (top) break;
            }
        }
    }
}

// H's structural zeros, the entries of dofs on different branches (neither body supports the
// other), set to 0: both forms write every other entry (add to it, with mimic joints: then all
// of H is cleared). One store per zero when that is fewer stores than clearing all of H 64 bytes
// at a time: a serial chain has none, the legged tree 108 of 324 (in 8 lanes 108 stores for 324;
// in doubles, 41 stores clear H).
template <class Tree>
inline constexpr auto structural_zeros = [] {
    constexpr auto apart = [](std::size_t j, std::size_t k) {
        return !Tree::supports(Tree::body_of_dof[j], Tree::body_of_dof[k]) && !Tree::supports(Tree::body_of_dof[k], Tree::body_of_dof[j]);
    };
    constexpr std::size_t count = [&] {
        std::size_t c = 0;
        for (std::size_t j = 0; j < Tree::nv; ++j)
            for (std::size_t k = 0; k < Tree::nv; ++k) c += apart(j, k);
        return c;
    }();
    std::array<std::array<std::size_t, 2>, count> list{};
    std::size_t c = 0;
    for (std::size_t j = 0; j < Tree::nv; ++j)
        for (std::size_t k = 0; k < Tree::nv; ++k)
            if (apart(j, k)) list[c++] = {j, k};
    return list;
}();
template <class Tree, class T>
CTGA_ALWAYS_INLINE constexpr void clear_for_fill(joint_matrix<Tree, T>& H) noexcept {
    constexpr auto& zeros = structural_zeros<Tree>;
    if constexpr (!Tree::has_mimic && zeros.size() * 64 < Tree::nv * Tree::nv * sizeof(T)) {
        [&]<std::size_t... Z>(std::index_sequence<Z...>) CTGA_INLINE_LAMBDA {
            ((H[zeros[Z][0]][zeros[Z][1]] = T(0)), ...);
        }(std::make_index_sequence<zeros.size()>{});
    } else {
        H = {};
    }
}

// H_kk + a_k for a joint with an armature (with_armature: its rotor).
template <class Tree, class T>
CTGA_ALWAYS_INLINE constexpr void add_armature(const model<Tree, T>& m, joint_matrix<Tree, T>& H) noexcept {
    each_armature(m, [&](std::size_t k, const T& a) { H[k][k] += a; });
}

// The local form (the header's first).
template <class Tree, class T, class Maps = maps_of_q>
constexpr joint_matrix<Tree, T> crba_local(const model<Tree, T>& m, const configuration<Tree, T>& q, const Maps& maps = {}) noexcept {
    if constexpr (std::is_same_v<Maps, maps_of_q>) {
        joint_maps<Tree, T> X;
        fill_joint_maps(X, m, q);
        return crba_local(m, q, X);
    } else {
        const joint_maps<Tree, T>& X = maps;
        // (parameter by parameter: a whole body_inertia of packs, 640 bytes in 8 lanes, GCC copies
        // with a call to memcpy, 11 % of the legged tree's CRBA in 8 lanes)
        std::array<body_inertia<T>, Tree::size> Nc = [&]<std::size_t... I>(std::index_sequence<I...>) {
            return std::array<body_inertia<T>, Tree::size>{parameters_cast<T>(m.template link<I>().inertia)...};
        }(std::make_index_sequence<Tree::size>{});
        each_body_backward(m, [&](const auto& b) CTGA_INLINE_LAMBDA {
            using B = std::remove_cvref_t<decltype(b)>;
            if constexpr (!B::root) Nc[b.p] = Nc[b.p] + transform<map_shape<typename B::joint>>(X[b.i], Nc[b.i]);
        });
        const auto links = body_links(m);
        joint_matrix<Tree, T> H;
        clear_for_fill<Tree>(H);
        each_body(m, [&](const auto& b) CTGA_INLINE_LAMBDA {
            using J = typename std::remove_cvref_t<decltype(b)>::joint;
            if constexpr (moves<J>)
                [&]<std::size_t... K>(std::index_sequence<K...>) CTGA_INLINE_LAMBDA {
                    ([&] {  // column K of body b's dofs, from F = N^c_b S_bK
                        const coscrew<T> F = momentum(Nc[b.i], J::template subspace<K, T>(b.link(m).joint));
                        const std::size_t col = b.v_src + K;
                        if constexpr (Tree::has_mimic) {
                            const T w = dof_weight(b, m);
                            fill_rows<true>(b, m, H, col, F, w);
                            fill_ancestors(b, m, links, X, H, col, F, w);
                        } else {
                            fill_rows<false>(b, m, H, col, F);  // (Own matters to the mimic sums only)
                            fill_ancestors(b, m, links, X, H, col, F);
                        }
                    }(), ...);
                }(std::make_index_sequence<is_mimic<J> ? 1 : J::nv>{});
        });
        add_armature(m, H);
        return H;
    }
}

// The world form (the header's second).
template <class Tree, class T, class Maps = maps_of_q>
constexpr joint_matrix<Tree, T> crba_world(const model<Tree, T>& m, const configuration<Tree, T>& q, const Maps& maps = {}) noexcept {
    world_geometry<Tree, T> g{uninitialized};
    fill_world_geometry(g, m, q, maps);
    for (std::size_t i = Tree::size; i-- > 0;)  // the composites: children come after their parent
        if (const int p = Tree::parent[i]; p >= 0) g.N[static_cast<std::size_t>(p)] = g.N[static_cast<std::size_t>(p)] + g.N[i];
    using ancestors = branch_tables<Tree>;
    joint_matrix<Tree, T> H;
    clear_for_fill<Tree>(H);  // (the world form is taken only without mimic joints)
    for (std::size_t i = 0; i < Tree::size; ++i)
        for (std::size_t k = Tree::v_offset[i]; k < Tree::v_offset[i + 1]; ++k) {
            const coscrew<T> F = momentum(g.N[i], g.S[k]);
            for (std::size_t c = ancestors::supporting.first[i]; c < ancestors::supporting.first[i + 1]; ++c) {
                const std::size_t j = ancestors::supporting.list[c];
                H[j][k] = H[k][j] = pairing(F, g.S[j]);
            }
            for (std::size_t j = Tree::v_offset[i]; j <= k; ++j) H[j][k] = H[k][j] = pairing(F, g.S[j]);
        }
    add_armature(m, H);
    return H;
}

// The flops of each form for Tree's shape (axis joints' S one blade), in terms of c_b, the cost of
// applying body b's rotation (linear3::apply_cost of its map_shape: 15 dense, 6 for an aligned
// joint's turn about an axis): local 34 + 6 c_b per body and 14 + 2 c_b per (dof, ancestor body
// b) (a force transform, 12 + 2 c_b, and a pairing); world 173 + 4.5 c_b per body (the pose, the
// inertia moved out, the composite, N S) and 12 per (dof, ancestor's or own dof) entry. Fitted to
// the operations counted on serial chains of 10 and 20 bodies, dense and aligned
// (bench/counting_scalar.hpp), within 1 % of them.
template <class Tree>
struct crba_cost {
    static constexpr std::array<std::size_t, Tree::size> rotation = []<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<std::size_t, Tree::size>{linear3::apply_cost(map_shape<typename Tree::template joint_at<I>>)...};
    }(std::make_index_sequence<Tree::size>{});
    static constexpr std::size_t local = [] {
        std::size_t c = 0;
        for (std::size_t b = 0; b < Tree::size; ++b) c += 34 + 6 * rotation[b];
        for (std::size_t k = 0; k < Tree::nv; ++k)
            for (int b = Tree::parent[Tree::body_of_dof[k]]; b >= 0; b = Tree::parent[static_cast<std::size_t>(b)])
                c += 14 + 2 * rotation[static_cast<std::size_t>(b)];
        return c;
    }();
    static constexpr std::size_t world = [] {
        std::size_t c = 0;
        for (std::size_t b = 0; b < Tree::size; ++b) c += 173 + 9 * rotation[b] / 2;
        for (std::size_t k = 0; k < Tree::nv; ++k)
            for (std::size_t j = 0; j <= k; ++j) c += Tree::supports(Tree::body_of_dof[j], Tree::body_of_dof[k]) ? std::size_t{12} : 0;
        return c;
    }();
    // the world form's loops do less per second than the unrolled transforms (the 30-body aligned
    // chain: local 2.14 µs for 13,410 flops, world 2.34 µs for 11,580; the 64-body one: 7.98 µs
    // for 56,896 against 6.62 µs for 37,760), so it is taken below 0.8 × the local count
    static constexpr bool in_world = !Tree::has_mimic && 5 * world < 4 * local;
};
// H in the cheaper form, from q or the maps given (passes.hpp).
template <class Tree, class T, class Maps = maps_of_q>
constexpr joint_matrix<Tree, T> mass_matrix(const model<Tree, T>& m, const configuration<Tree, T>& q, const Maps& maps = {}) noexcept {
    if constexpr (crba_cost<Tree>::in_world) return crba_world(m, q, maps);
    else return crba_local(m, q, maps);
}
}  // namespace algorithm_detail

struct crba_t {
    template <class Tree, class T>
    [[nodiscard]] constexpr joint_matrix<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q) const noexcept {
        return algorithm_detail::mass_matrix(m, q);
    }
};
inline constexpr algorithm<crba_t, "crba"> crba{};

}  // namespace ctga::chains
