// What the world-frame algorithms of a tree share (rnea_derivatives.hpp, minverse.hpp,
// aba_derivatives.hpp): every body's pose in the world and its joint's free directions S moved
// out into the world frame, computed body by body where the joint types matter (unrolled: an
// axis joint's S is one blade, moved out at 6m 3a), and its own inertia moved into the world
// (§5: (g ḡ) N (g ḡ)*, the same for every joint: a loop); and the tree's shape as tables, so that the rest of those
// algorithms, the same for every joint in the world frame, runs as loops over the bodies and
// compiles once for any tree.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "ctga/chains/frame_jacobian.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/runs.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

namespace algorithm_detail {

// Every body's pose in the world and every dof's free direction there: what a constraint's rows
// read too (constrained/: a row pairs a force line with these screws).
template <class Tree, class T>
struct world_poses {
    std::array<motor_map<T>, Tree::size> pose;  // body i in the world
    std::array<screw<T>, Tree::nv> S;           // dof k's free direction, world frame

    explicit constexpr world_poses(uninitialized_t) : S(uninitialized_array<screw<T>, Tree::nv>()) {}
};
template <class Tree, class T>
struct world_geometry : world_poses<Tree, T> {
    std::array<body_inertia<T>, Tree::size> N;  // body i's own inertia, world frame
    std::array<T, Tree::nv> armature;           // dof k's armature (tree.hpp; 0 where a joint has none)

    explicit constexpr world_geometry(uninitialized_t) : world_poses<Tree, T>(uninitialized) {}
};

template <class Tree, class T, class Maps = maps_of_q>
constexpr void fill_world_poses(world_poses<Tree, T>& g, const model<Tree, T>& m, const configuration<Tree, T>& q, const Maps& maps = {}) noexcept {
    each_body(m, [&](const auto& b) CTGA_INLINE_LAMBDA {
        using B = std::remove_cvref_t<decltype(b)>;
        using J = typename B::joint;
        const std::size_t i = b.i;
        const auto& L = b.link(m);
        const motor_map<T> X = body_map(b, m, q, maps);
        if constexpr (B::root) g.pose[i] = X;
        else g.pose[i] = compose<map_shape<J>>(g.pose[b.p], X);
        [&]<std::size_t... K>(std::index_sequence<K...>) CTGA_INLINE_LAMBDA {
            ((g.S[b.v_own + K] = frame_detail::moved_out(g.pose[i], J::template subspace<K, T>(L.joint))), ...);
        }(std::make_index_sequence<J::nv>{});
    });
}
template <class Tree, class T, class Maps = maps_of_q>
constexpr void fill_world_geometry(world_geometry<Tree, T>& g, const model<Tree, T>& m, const configuration<Tree, T>& q, const Maps& maps = {}) noexcept {
    fill_world_poses<Tree, T>(g, m, q, maps);
    [&]<std::size_t... I>(std::index_sequence<I...>) { ((g.N[I] = m.template link<I>().inertia), ...); }(std::make_index_sequence<Tree::size>{});
    g.armature = armature_by_dof(m);
    for (std::size_t i = 0; i < Tree::size; ++i) g.N[i] = transform(g.pose[i], g.N[i]);
}

// Lists of dofs by body, flattened: for body b, list[first[b] … first[b + 1]).
template <std::size_t Bodies, std::size_t Total, class Entry = std::size_t>
struct dof_lists {
    std::array<std::size_t, Bodies + 1> first{};
    std::array<Entry, Total> list{};
};
// Built from a predicate: the dofs j (ascending) with In{}(b, j), each entry Make{}(b, j)
// (stateless lambdas, as types).
template <class Tree, class Entry, class In, class Make>
constexpr auto make_dof_lists() {
    constexpr std::size_t total = [] {
        std::size_t c = 0;
        for (std::size_t b = 0; b < Tree::size; ++b)
            for (std::size_t j = 0; j < Tree::nv; ++j) c += In{}(b, j);
        return c;
    }();
    dof_lists<Tree::size, total, Entry> out;
    std::size_t c = 0;
    for (std::size_t b = 0; b < Tree::size; ++b) {
        out.first[b] = c;
        for (std::size_t j = 0; j < Tree::nv; ++j)
            if (In{}(b, j)) out.list[c++] = Make{}(b, j);
    }
    out.first[Tree::size] = c;
    return out;
}

template <class Tree>
constexpr std::size_t root_of(std::size_t i) noexcept {
    while (Tree::parent[i] >= 0) i = static_cast<std::size_t>(Tree::parent[i]);
    return i;
}

template <class Tree>
struct branch_tables {
    static constexpr auto dof = [](std::size_t, std::size_t j) { return j; };
    static constexpr auto below = [](std::size_t b, std::size_t j) {  // body b supports dof j's body, another
        return Tree::supports(b, Tree::body_of_dof[j]) && Tree::body_of_dof[j] != b;
    };
    static constexpr auto above = [](std::size_t b, std::size_t j) {  // dof j's body supports body b, another
        return Tree::supports(Tree::body_of_dof[j], b) && Tree::body_of_dof[j] != b;
    };
    // the dofs of body b's ancestors, and of the bodies b carries (b's own excluded)
    static constexpr auto supporting = make_dof_lists<Tree, std::size_t, decltype(above), decltype(dof)>();
    static constexpr auto carried = make_dof_lists<Tree, std::size_t, decltype(below), decltype(dof)>();
    // dof k's body hangs from the world
    static constexpr auto on_world = [] {
        std::array<bool, Tree::nv> w{};
        for (std::size_t k = 0; k < Tree::nv; ++k) w[k] = Tree::parent[Tree::body_of_dof[k]] < 0;
        return w;
    }();
    // whether any joint has several dofs (a floating one)
    static constexpr bool multi_dof = [] {
        for (std::size_t b = 0; b < Tree::size; ++b)
            if (Tree::nv_of[b] > 1) return true;
        return false;
    }();
};

}  // namespace algorithm_detail

}  // namespace ctga::chains
