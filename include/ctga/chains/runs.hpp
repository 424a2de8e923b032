// Runs of repeated bodies: the legs of a quadruped, the cycles of a long chain. The passes of
// the algorithms visit a tree's bodies in index order, each body's step compiled with its own
// joint type; a run of R repeats of the same L joint types, hanging the same way, is compiled
// once and executed R times with the body's index, its parent's and its offsets at run time.
// The step's code is the same (the joint type decides it), so what the engine drops for an axis
// joint stays dropped; the tree's code, and its compile time, grow with the number of distinct
// patterns instead of the number of bodies.
//
// Repeat r of a pattern of bodies [s, s + L) is [s + rL, s + (r+1)L): body s + rL + k has the
// joint type of body s + k and hangs from the same body (absolute: the trunk of the legs) or
// from the body at the same distance (relative: the previous body of a chain). No mimic joint is
// in a run (its master is a compile-time index). Runs are formed only in trees of at least
// run_threshold bodies: a small tree is fastest unrolled.
//
// A pass's step receives a body handle: B::joint, B::root (compile time), b.i, b.p (its parent,
// unless root), b.q_src, b.v_src (where the numbers its joint reads start), b.v_own (where its
// own start) and b.link(m) (its link_parameters), constants for a body visited alone.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "ctga/chains/tree.hpp"
#include "ctga/support/inline.hpp"

namespace ctga::chains {

// The number of bodies from which a tree's repeated bodies are executed as runs.
inline constexpr std::size_t run_threshold = 10;

namespace run_detail {

struct segment {
    std::size_t first = 0, length = 1, repeats = 1;  // a body alone: length 1, repeats 1
};

template <class Tree, std::size_t A, std::size_t... B>
constexpr void same_row(std::array<std::array<bool, Tree::size>, Tree::size>& s, std::index_sequence<B...>) {
    ((s[A][B] = std::is_same_v<typename Tree::template joint_at<A>, typename Tree::template joint_at<B>>), ...);
}
template <class Tree, std::size_t... A>
constexpr auto same_table(std::index_sequence<A...>) {
    std::array<std::array<bool, Tree::size>, Tree::size> s{};
    (same_row<Tree, A>(s, std::make_index_sequence<Tree::size>{}), ...);
    return s;
}

template <class Tree>
struct plan {
    static constexpr std::size_t N = Tree::size;
    // same[a][b]: bodies a and b have the same joint type
    static constexpr auto same = same_table<Tree>(std::make_index_sequence<N>{});
    // whether body s + k of a pattern [s, s + L) hangs from the same body in every repeat (else: from
    // the body at the same distance), as repeat 1 shows
    static constexpr bool absolute(std::size_t s, std::size_t L, std::size_t k) {
        return s + L + k < N && Tree::parent[s + L + k] == Tree::parent[s + k];
    }
    // how many repeats of pattern [s, s + L) follow one another from s
    static constexpr std::size_t repeats(std::size_t s, std::size_t L) {
        for (std::size_t k = 0; k < L; ++k)
            if (s + k >= N || Tree::master[s + k] >= 0) return 0;
        std::size_t r = 1;
        for (;; ++r) {
            for (std::size_t k = 0; k < L; ++k) {
                const std::size_t a = s + k, b = s + r * L + k;
                if (b >= N || !same[a][b] || Tree::master[b] >= 0) return r;
                const int pa = Tree::parent[a], pb = Tree::parent[b];
                const bool ok = absolute(s, L, k) ? pb == pa
                                               : pa >= 0 && pb - static_cast<int>(s + r * L) == pa - static_cast<int>(s);
                if (!ok) return r;
            }
        }
    }
    static constexpr auto segments = [] {
        std::array<segment, N> out{};
        std::size_t n = 0;
        for (std::size_t s = 0; s < N;) {
            segment best{s, 1, 1};
            if (N >= run_threshold)
                for (std::size_t L = 1; L <= 6 && 2 * L <= N - s; ++L) {
                    const std::size_t R = repeats(s, L);
                    if (R >= 2 && R * L > best.length * best.repeats) best = {s, L, R};
                }
            out[n++] = best;
            s += best.length * best.repeats;
        }
        return std::pair{out, n};
    }();
    static constexpr std::size_t count = segments.second;
    static constexpr segment at(std::size_t g) { return segments.first[g]; }
};

// A body visited alone: everything is a constant.
template <class Tree, std::size_t I>
struct single_body {
    using joint = typename Tree::template joint_at<I>;
    static constexpr bool root = Tree::parent[I] < 0;
    static constexpr std::size_t i = I;
    static constexpr std::size_t p = root ? 0 : static_cast<std::size_t>(Tree::parent[I]);
    static constexpr std::size_t q_src = Tree::q_offset[Tree::reads_from[I]];
    static constexpr std::size_t v_src = Tree::v_offset[Tree::reads_from[I]];
    static constexpr std::size_t v_own = Tree::v_offset[I];
    template <class M>
    CTGA_ALWAYS_INLINE static constexpr const auto& link(const M& m) noexcept {
        return m.template link<I>();
    }
};

// Body P of a run's pattern in repeat r: its numbers at run time.
template <class Tree, std::size_t P, class Link>
struct run_body {
    using joint = typename Tree::template joint_at<P>;
    static constexpr bool root = Tree::parent[P] < 0;
    std::size_t i, p, q_src, v_src, v_own;
    const Link* L;
    template <class M>
    CTGA_ALWAYS_INLINE constexpr const Link& link(const M&) const noexcept {
        return *L;
    }
};

// &m.link<First + K + r L>() for r < R, and that for each K < L.
template <std::size_t First, std::size_t K, std::size_t L, class M, std::size_t... Rr>
constexpr auto link_pointers(const M& m, std::index_sequence<Rr...>) noexcept {
    return std::array{&m.template link<First + K + Rr * L>()...};
}
template <std::size_t First, std::size_t L, std::size_t R, class M, std::size_t... K>
constexpr auto link_table(const M& m, std::index_sequence<K...>) noexcept {
    return std::tuple{link_pointers<First, K, L>(m, std::make_index_sequence<R>{})...};
}

// f(body) for every body of segment G, in index order (Forward) or backwards.
template <bool Forward, std::size_t G, class Tree, class T, class F>
CTGA_ALWAYS_INLINE constexpr void visit_segment(const model<Tree, T>& m, F& f) {
    constexpr segment S = plan<Tree>::at(G);
    if constexpr (S.repeats == 1) {
        f(single_body<Tree, S.first>{});
    } else {
        constexpr std::size_t L = S.length, R = S.repeats;
        constexpr std::size_t dq = Tree::q_offset[S.first + L] - Tree::q_offset[S.first];
        constexpr std::size_t dv = Tree::v_offset[S.first + L] - Tree::v_offset[S.first];
        // each pattern body's parameters in every repeat (the model keeps them in a tuple)
        const auto links = link_table<S.first, L, R>(m, std::make_index_sequence<L>{});
        const auto body = [&]<std::size_t K>(std::integral_constant<std::size_t, K>, std::size_t r) CTGA_INLINE_LAMBDA {
            constexpr std::size_t P = S.first + K;
            using link_type = std::remove_cvref_t<decltype(m.template link<P>())>;
            constexpr bool abs_parent = plan<Tree>::absolute(S.first, L, K);
            constexpr int p0 = Tree::parent[P];
            const std::size_t p = p0 < 0 ? 0 : abs_parent ? static_cast<std::size_t>(p0) : static_cast<std::size_t>(p0) + r * L;
            f(run_body<Tree, P, link_type>{P + r * L, p, Tree::q_offset[P] + r * dq, Tree::v_offset[P] + r * dv,
                                            Tree::v_offset[P] + r * dv, std::get<K>(links)[r]});
        };
        if constexpr (Forward) {
            for (std::size_t r = 0; r < R; ++r)
                [&]<std::size_t... K>(std::index_sequence<K...>) CTGA_INLINE_LAMBDA {
                    (body(std::integral_constant<std::size_t, K>{}, r), ...);
                }(std::make_index_sequence<L>{});
        } else {
            for (std::size_t r = R; r-- > 0;)
                [&]<std::size_t... K>(std::index_sequence<K...>) CTGA_INLINE_LAMBDA {
                    (body(std::integral_constant<std::size_t, L - 1 - K>{}, r), ...);
                }(std::make_index_sequence<L>{});
        }
    }
}
}  // namespace run_detail

// f(body handle) for every body in index order: parents before children.
template <class Tree, class T, class F>
CTGA_ALWAYS_INLINE constexpr void each_body(const model<Tree, T>& m, F&& f) {
    [&]<std::size_t... G>(std::index_sequence<G...>) CTGA_INLINE_LAMBDA { (run_detail::visit_segment<true, G>(m, f), ...); }(
        std::make_index_sequence<run_detail::plan<Tree>::count>{});
}
// … in reverse index order: children before parents.
template <class Tree, class T, class F>
CTGA_ALWAYS_INLINE constexpr void each_body_backward(const model<Tree, T>& m, F&& f) {
    constexpr std::size_t n = run_detail::plan<Tree>::count;
    [&]<std::size_t... G>(std::index_sequence<G...>) CTGA_INLINE_LAMBDA { (run_detail::visit_segment<false, n - 1 - G>(m, f), ...); }(
        std::make_index_sequence<n>{});
}

}  // namespace ctga::chains
