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
// A tree that runs do not make small, one whose runs and bodies alone would still compile more
// than by_kind_threshold steps (a humanoid: its legs repeat, its torso, arms and hands do not),
// is one loop over all its bodies instead: each body's step is the step compiled for its kind
// (its joint type and whether it hangs from the world; a mimic's body is a kind of its own),
// chosen by a branch on the body's kind number. Its code then grows with its kinds of bodies,
// not their number (a 39-body humanoid: 4 kinds). Runs stay where they apply: consecutive
// bodies in one straight line keep each other's numbers in registers (a 30-body chain's RNEA:
// 1.48 µs as a run, 1.59 µs by kind; a 39-body humanoid's: 2.47 µs by runs, 1.93 µs by kind).
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

// The number of bodies from which a tree's repeated bodies are executed as runs, and the number
// of compiled steps from which the tree is one loop by kind instead.
inline constexpr std::size_t run_threshold = 10;
inline constexpr std::size_t by_kind_threshold = 16;

namespace run_detail {

struct segment {
    std::size_t first = 0, length = 1, repeats = 1;  // a body alone: length 1, repeats 1
    bool by_kind = false;                            // all the tree's bodies: one loop by kind
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
    // the longest run from s (repeats 1: body s alone)
    static constexpr segment best_from(std::size_t s) {
        segment best{s, 1, 1};
        if (N >= run_threshold)
            for (std::size_t L = 1; L <= 6 && 2 * L <= N - s; ++L) {
                const std::size_t R = repeats(s, L);
                if (R >= 2 && R * L > best.length * best.repeats) best = {s, L, R};
            }
        return best;
    }
    static constexpr auto runs = [] {
        std::array<segment, N> out{};
        std::size_t n = 0;
        for (std::size_t s = 0; s < N;) {
            out[n++] = best_from(s);
            s += out[n - 1].length * out[n - 1].repeats;
        }
        return std::pair{out, n};
    }();
    // the steps the runs and the bodies alone compile
    static constexpr std::size_t steps = [] {
        std::size_t c = 0;
        for (std::size_t g = 0; g < runs.second; ++g) c += runs.first[g].length;
        return c;
    }();
    static constexpr auto segments = N >= run_threshold && steps > by_kind_threshold
                                         ? std::pair{std::array<segment, N>{segment{0, N, 1, true}}, std::size_t{1}}
                                         : runs;
    static constexpr std::size_t count = segments.second;
    static constexpr segment at(std::size_t g) { return segments.first[g]; }
};

// A body visited alone: everything is a constant.
template <class Tree, std::size_t I>
struct single_body {
    using joint = typename Tree::template joint_at<I>;
    static constexpr bool root = Tree::parent[I] < 0;
    static constexpr bool constant = true;  // i and the offsets are compile-time constants
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
    static constexpr bool constant = false;
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

// The kinds of a tree's bodies: body i's kind is the first body with its joint type and
// rootness (a mimic's body: itself), numbered in body order.
template <class Tree>
struct kinds {
    static constexpr std::size_t N = Tree::size;
    static constexpr std::array<std::size_t, N> first_of_kind = [] {
        std::array<std::size_t, N> r{};
        for (std::size_t i = 0; i < N; ++i) {
            r[i] = i;
            for (std::size_t j = 0; j < i && Tree::master[i] < 0; ++j)
                if (Tree::master[j] < 0 && plan<Tree>::same[i][j] && (Tree::parent[i] < 0) == (Tree::parent[j] < 0)) {
                    r[i] = j;
                    break;
                }
        }
        return r;
    }();
    static constexpr std::size_t count = [] {
        std::size_t c = 0;
        for (std::size_t i = 0; i < N; ++i) c += first_of_kind[i] == i;
        return c;
    }();
    static constexpr std::array<std::size_t, count> first = [] {  // the first body of each kind
        std::array<std::size_t, count> l{};
        std::size_t c = 0;
        for (std::size_t i = 0; i < N; ++i)
            if (first_of_kind[i] == i) l[c++] = i;
        return l;
    }();
    static constexpr std::array<std::size_t, N> kind = [] {
        std::array<std::size_t, N> k{};
        for (std::size_t i = 0; i < N; ++i)
            for (std::size_t c = 0; c < count; ++c)
                if (first[c] == first_of_kind[i]) k[i] = c;
        return k;
    }();
    // the bodies of kind C, ascending, and body i's place among those of its kind
    template <std::size_t C>
    static constexpr auto members = [] {
        constexpr std::size_t n = [] {
            std::size_t c = 0;
            for (std::size_t i = 0; i < N; ++i) c += kind[i] == C;
            return c;
        }();
        std::array<std::size_t, n> l{};
        for (std::size_t i = 0, c = 0; i < N; ++i)
            if (kind[i] == C) l[c++] = i;
        return l;
    }();
    static constexpr std::array<std::size_t, N> slot = [] {
        std::array<std::size_t, N> r{};
        std::array<std::size_t, N> used{};
        for (std::size_t i = 0; i < N; ++i) r[i] = used[kind[i]]++;
        return r;
    }();
};
template <class Tree, class T, std::size_t C>
using kind_link = std::remove_cvref_t<decltype(std::declval<const model<Tree, T>&>().template link<kinds<Tree>::first[C]>())>;

// f(body i) with i's numbers at run time, compiled as the first body of kind C
template <class Tree, std::size_t C, class T, class F>
CTGA_ALWAYS_INLINE constexpr void visit_as_kind(F& f, std::size_t i, const kind_link<Tree, T, C>* link) {
    const int p = Tree::parent[i];
    f(run_body<Tree, kinds<Tree>::first[C], kind_link<Tree, T, C>>{i, p < 0 ? 0 : static_cast<std::size_t>(p),
                                                                 Tree::q_offset[Tree::reads_from[i]],
                                                                 Tree::v_offset[Tree::reads_from[i]], Tree::v_offset[i], link});
}
template <class Tree, class T, std::size_t C>
CTGA_ALWAYS_INLINE constexpr auto kind_links(const model<Tree, T>& m) noexcept {
    return [&]<std::size_t... B>(std::index_sequence<B...>) {
        return std::array<const kind_link<Tree, T, C>*, sizeof...(B)>{&m.template link<kinds<Tree>::template members<C>[B]>()...};
    }(std::make_index_sequence<kinds<Tree>::template members<C>.size()>{});
}

}  // namespace run_detail

// Every body's link parameters, for visit_body: for each kind, its bodies' (typed pointers, so
// that the algorithms stay constant expressions).
template <class Tree, class T>
CTGA_ALWAYS_INLINE constexpr auto body_links(const model<Tree, T>& m) noexcept {
    return [&]<std::size_t... C>(std::index_sequence<C...>) {
        return std::tuple{run_detail::kind_links<Tree, T, C>(m)...};
    }(std::make_index_sequence<run_detail::kinds<Tree>::count>{});
}
// f(body handle) for body i given at run time, compiled for its kind (links: body_links(m) of a
// model<Tree, T>).
template <class Tree, class T, class Links, class F>
CTGA_ALWAYS_INLINE constexpr void visit_body(const Links& links, std::size_t i, F&& f) {
    using K = run_detail::kinds<Tree>;
    [&]<std::size_t... C>(std::index_sequence<C...>) CTGA_INLINE_LAMBDA {
        (void)((K::kind[i] == C ? (run_detail::visit_as_kind<Tree, C, T>(f, i, std::get<C>(links)[K::slot[i]]), true) : false) || ...);
    }(std::make_index_sequence<K::count>{});
}

namespace run_detail {

// f(body) for every body of segment G, in index order (Forward) or backwards.
template <bool Forward, std::size_t G, class Tree, class T, class F>
CTGA_ALWAYS_INLINE constexpr void visit_segment(const model<Tree, T>& m, F& f) {
    constexpr segment S = plan<Tree>::at(G);
    if constexpr (S.by_kind) {
        // each body's parameters (the model keeps them in a tuple, one type per kind)
        const auto links = body_links(m);
        if constexpr (Forward)
            for (std::size_t i = 0; i < Tree::size; ++i) visit_body<Tree, T>(links, i, f);
        else
            for (std::size_t i = Tree::size; i-- > 0;) visit_body<Tree, T>(links, i, f);
    } else if constexpr (S.repeats == 1) {
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
