// Running a program (program.hpp) on the operands' storage. Every assignment is a sum of its
// constexpr terms; up to unroll_limit terms a program is unrolled into the caller, so the
// compiler sees plain arithmetic on the operands' storage and on local temporaries; a larger one
// is interpreted: one loop reads its constexpr terms (run_interpreted). Not to be confused with
// a looped product (looped.hpp): one product node run as a loop over a table of blade pairs.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

#include "ctga/expr/looped.hpp"
#include "ctga/expr/normal_form.hpp"
#include "ctga/expr/program.hpp"
#include "ctga/expr/rational.hpp"
#include "ctga/support/inline.hpp"

namespace ctga::expr {

#if defined(__clang__)
#define CTGA_UNROLL_TERMS _Pragma("clang loop unroll(full)")
#elif defined(__GNUC__)
#define CTGA_UNROLL_TERMS _Pragma("GCC unroll 1024")
#else
#define CTGA_UNROLL_TERMS
#endif

// GCC 12 at -O2 can report a bogus -Warray-bounds on these reads once whole expressions are
// inlined: every index is a compile-time constant of the program and within bounds (checked
// under AddressSanitizer in the tests), so the warning is off for these lines only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif
// Clang cannot fully unroll term_magnitude's loop where a program is interpreted (run_interpreted:
// the degree is not a constant there) and says so with -Wpass-failed; the loop is correct either
// way, so the note is off from here to the end of this file.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wpass-failed"
#endif

// |c| in T: an integer, or a quotient (in T when T divides, else rounded from long double).
template <class T>
constexpr T coefficient(const rational& c) {
    const std::int64_t n = c.num < 0 ? -c.num : c.num;
    // (a SIMD pack converts from a double, not from an integer whose value it might not keep)
    const auto as_T = [](std::int64_t k) {
        if constexpr (std::is_constructible_v<T, std::int64_t>) return T(k);
        else return T(static_cast<double>(k));
    };
    if (c.den == 1) return as_T(n);
    if constexpr (requires(const T& a) { a / a; }) return as_T(n) / as_T(c.den);
    else return T(static_cast<long double>(n) / static_cast<long double>(c.den));
}

template <class T>
CTGA_ALWAYS_INLINE constexpr T factor_value(std::uint32_t f, const T* const* leaves, const T* tmp) noexcept {
    return (f & tmp_flag) ? tmp[f & ~tmp_flag] : leaves[f >> leaf_shift][f & ((1u << leaf_shift) - 1)];
}

// |c| · Π factors, the sign left to the caller (a subtraction instead of a negation).
template <class T>
CTGA_ALWAYS_INLINE constexpr T term_magnitude(const op_term& o, const T* const* leaves, const T* tmp) noexcept {
    if (o.degree == 0) return coefficient<T>(o.c);
    T v = factor_value<T>(o.f[0], leaves, tmp);
    CTGA_UNROLL_TERMS
    for (std::uint32_t d = 1; d < o.degree; ++d) v = v * factor_value<T>(o.f[d], leaves, tmp);
    if (!is_unit(o.c)) v = v * coefficient<T>(o.c);
    return v;
}

// The straight-line form of a program: a list of steps, computed once per program at compile
// time and run by one fold (run_steps below): one small inline instance per step, with no
// recursion over terms or partial sums.
//
// Each assignment is the signed sum of its terms as a balanced tree: the compiler may not
// reassociate floating-point additions, and one left-to-right chain over the thirty terms of a
// kinetic energy is a chain of thirty dependent additions. Term i of an assignment of n terms
// is its term (i + r) mod n: the rotation r puts a positive term first when there is one, so
// that a − b is computed as a − b and not as −b + a. A half whose first term is negative is
// subtracted with its signs flipped, so no other negation is ever needed. A sum starts from a
// term, not from zero: x + 0.0 is not x for x = −0.0, so a zero start would cost an addition
// the compiler may not remove.
//
// Each step is a template instance, and an instance costs compile time (about a millisecond
// with g++ 12 at -O2), so a step does as much as one statement can: a half of a tree that is one
// term is computed by the combine that reads it, and the step at the root of an assignment's
// tree writes the assignment itself (store). An assignment of n ≥ 2 terms is n − 1 steps, one
// term is one. The arithmetic is the same either way.
enum class step_kind : std::uint8_t {
    term,     // value = ±|term reg|
    combine,  // value = left ± right: left ±|term reg| or r[reg], right |term other| or r[other]
    empty,    // value = 0 (an assignment with no terms; always stored)
};
struct step {
    step_kind kind{};
    bool subtract = false;     // term: negate; combine: subtract the right operand
    bool left_term = false;    // combine: the left operand is term `reg` (negated when left_negate)
    bool left_negate = false;
    bool right_term = false;   // combine: the right operand is +|term other|
    bool store = false;        // the value is assignment `target`; else it goes to r[reg]
    std::uint32_t reg = 0;     // a term's index in P::terms, and the register of its tree's value
    std::uint32_t other = 0;   // combine: the right operand's term (or its register, the same index)
    std::uint32_t target = 0;  // store: the assignment
};

template <class P>
struct straight_line {
    static constexpr std::size_t step_capacity = P::terms.size() + P::assignment_count;
    static constexpr std::size_t register_count = P::terms.size() > 0 ? P::terms.size() : 1;

    struct plan {
        std::array<step, (step_capacity > 0 ? step_capacity : 1)> steps{};
        std::size_t count = 0;
    };
    // The tree over terms [b, e) (e − b ≥ 2) of the assignment whose terms start at `begin`: its
    // value ends in the register of its first term (each term has its own register: its index).
    // A one-term half is computed inline by the combine that reads it: the left one as ±|term|,
    // the right one as +|term| (its sign is in `subtract`).
    static constexpr void sum(plan& p, std::uint32_t begin, std::uint32_t n, std::uint32_t rotation, std::uint32_t b,
                              std::uint32_t e, bool negate) {
        auto at = [&](std::uint32_t i) { return begin + (i + rotation) % n; };
        const std::uint32_t m = b + (e - b) / 2;
        const bool subtract = (P::terms[at(m)].c.num < 0) != negate;
        step c{step_kind::combine, subtract};
        c.left_term = m - b == 1;
        c.left_negate = (P::terms[at(b)].c.num < 0) != negate;
        c.right_term = e - m == 1;
        c.reg = at(b);
        c.other = at(m);
        if (!c.left_term) sum(p, begin, n, rotation, b, m, negate);
        if (!c.right_term) sum(p, begin, n, rotation, m, e, subtract ? !negate : negate);
        p.steps[p.count++] = c;
    }
    static constexpr plan steps_of = [] {
        plan p;
        for (std::uint32_t a = 0; a < P::assignment_count; ++a) {
            const std::uint32_t begin = P::offsets[a], n = P::offsets[a + 1] - begin;
            std::uint32_t rotation = 0;
            while (rotation < n && P::terms[begin + rotation].c.num <= 0) ++rotation;
            if (rotation == n) rotation = 0;
            if (n >= 2) {
                sum(p, begin, n, rotation, 0, n, false);
            } else {
                step t{n == 1 ? step_kind::term : step_kind::empty};
                t.subtract = n == 1 && P::terms[begin].c.num < 0;
                t.reg = begin;
                p.steps[p.count++] = t;
            }
            // the last step is the tree's root
            p.steps[p.count - 1].store = true;
            p.steps[p.count - 1].target = a;
        }
        return p;
    }();
    static constexpr std::size_t count = steps_of.count;
};

// A step is run with its contents as constants (if constexpr on the step, factor indices as
// template arguments), so each step is a few statements on the operands' storage from the
// start: the optimiser has no switch over step kinds and no reads of the step table to fold
// away (measured: bench/compile/mechanics.cpp 3.49 s → 3.04 s at -O2, the same assembly).
template <std::uint32_t F, class T>
CTGA_ALWAYS_INLINE constexpr T factor_at(const T* const* leaves, const T* tmp) noexcept {
    if constexpr ((F & tmp_flag) != 0) return tmp[F & ~tmp_flag];
    else return leaves[F >> leaf_shift][F & ((1u << leaf_shift) - 1)];
}
template <class T, class P, std::uint32_t Term, std::size_t... D>
CTGA_ALWAYS_INLINE constexpr T term_at(const T* const* leaves, const T* tmp, std::index_sequence<D...>) noexcept {
    constexpr op_term o = P::terms[Term];
    if constexpr (sizeof...(D) == 0) return coefficient<T>(o.c);
    else if constexpr (is_unit(o.c)) return (... * factor_at<o.f[D]>(leaves, tmp));
    else return (... * factor_at<o.f[D]>(leaves, tmp)) * coefficient<T>(o.c);
}
template <class T, class P, std::size_t N, std::size_t K>
CTGA_ALWAYS_INLINE constexpr void run_step(T* r, T* tmp, std::array<T, N>& out, const T* const* leaves) noexcept {
    constexpr step s = straight_line<P>::steps_of.steps[K];
    T v{};
    if constexpr (s.kind == step_kind::term) {
        const T x = term_at<T, P, s.reg>(leaves, tmp, std::make_index_sequence<P::terms[s.reg].degree>{});
        if constexpr (s.subtract) v = -x; else v = x;
    } else if constexpr (s.kind == step_kind::combine) {
        T left{}, right{};
        if constexpr (s.left_term) {
            const T x = term_at<T, P, s.reg>(leaves, tmp, std::make_index_sequence<P::terms[s.reg].degree>{});
            if constexpr (s.left_negate) left = -x; else left = x;
        } else {
            left = r[s.reg];
        }
        if constexpr (s.right_term) right = term_at<T, P, s.other>(leaves, tmp, std::make_index_sequence<P::terms[s.other].degree>{});
        else right = r[s.other];
        if constexpr (s.subtract) v = left - right; else v = left + right;
    }
    if constexpr (!s.store) r[s.reg] = v;
    else if constexpr (s.target < P::tmp_count) tmp[s.target] = v;
    else out[s.target - P::tmp_count] = v;
}
template <class T, class P, std::size_t N, std::size_t... K>
CTGA_ALWAYS_INLINE constexpr std::array<T, N> run_steps([[maybe_unused]] const T* const* leaves, std::index_sequence<K...>) noexcept {
    using line = straight_line<P>;
    [[maybe_unused]] std::array<T, line::register_count> r{};
    [[maybe_unused]] std::array<T, (P::tmp_count > 0 ? P::tmp_count : 1)> tmp{};
    std::array<T, N> out{};
    (run_step<T, P, N, K>(r.data(), tmp.data(), out, leaves), ...);
    return out;
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#undef CTGA_UNROLL_TERMS

// The same sums in constant evaluation, where the compiler interprets the program instead of
// compiling it: the tree of each assignment walked directly (the same operations in the same
// order as the steps, so the same bits), without the step list's register writes, which cost an
// integration inside a constant expression (examples/compile_time_trajectory.cpp) half its
// evaluation budget.
template <class T>
constexpr T tree_sum(const op_term* terms, std::uint32_t begin, std::uint32_t n, std::uint32_t rotation, std::uint32_t b,
                     std::uint32_t e, bool negate, const T* const* leaves, const T* tmp) noexcept {
    const op_term& first = terms[begin + (b + rotation) % n];
    if (e - b == 1) {
        const T v = term_magnitude<T>(first, leaves, tmp);
        return (first.c.num < 0) != negate ? T(-v) : v;
    }
    const std::uint32_t m = b + (e - b) / 2;
    const bool subtract = (terms[begin + (m + rotation) % n].c.num < 0) != negate;
    const T left = tree_sum<T>(terms, begin, n, rotation, b, m, negate, leaves, tmp);
    const T right = tree_sum<T>(terms, begin, n, rotation, m, e, subtract ? !negate : negate, leaves, tmp);
    return subtract ? left - right : left + right;
}

template <class T, class P, std::size_t N>
constexpr std::array<T, N> run_in_constant_evaluation(const T* const* leaves) noexcept {
    std::array<T, (P::tmp_count > 0 ? P::tmp_count : 1)> tmp{};
    std::array<T, N> out{};
    for (std::uint32_t a = 0; a < P::assignment_count; ++a) {
        const std::uint32_t begin = P::offsets[a], n = P::offsets[a + 1] - begin;
        std::uint32_t rotation = 0;
        while (rotation < n && P::terms[begin + rotation].c.num <= 0) ++rotation;
        if (rotation == n) rotation = 0;
        const T v = n == 0 ? T{} : tree_sum<T>(P::terms.data(), begin, n, rotation, 0, n, false, leaves, tmp.data());
        if (a < P::tmp_count) tmp[a] = v;
        else out[a - P::tmp_count] = v;
    }
    return out;
}

// Run program P on the leaves' storage: the temporaries in order, then the N outputs.
template <class T, class P, std::size_t N>
CTGA_ALWAYS_INLINE constexpr std::array<T, N> run(const T* const* leaves) noexcept {
    if (std::is_constant_evaluated()) return run_in_constant_evaluation<T, P, N>(leaves);
    return run_steps<T, P, N>(leaves, std::make_index_sequence<straight_line<P>::count>{});
}

// Up to this many terms a program runs as the unrolled straight-line code above, inlined into
// the caller (always: left to its heuristics GCC stops inlining inside a large caller, a whole
// equation of motion, and calls term_magnitude once per term). A larger program is interpreted:
// one loop over its constexpr terms in a function of its own: unrolling thousands of terms into the
// caller made the property suites' build three times as long (measured on this project: a 256×256 product
// took 120 s unrolled against 11 s as a loop).
inline constexpr std::size_t unroll_limit = 64;

template <class T, class P, std::size_t N>
[[gnu::noinline]] constexpr std::array<T, N> run_interpreted(const T* const* leaves) noexcept {
    std::array<T, (P::tmp_count > 0 ? P::tmp_count : 1)> tmp{};
    std::array<T, N> out{};
    for (std::size_t a = 0; a < P::tmp_count + N; ++a) {
        T acc{};
        for (std::uint32_t t = P::offsets[a]; t < P::offsets[a + 1]; ++t) {
            const op_term& o = P::terms[t];
            const T v = term_magnitude<T>(o, leaves, tmp.data());
            if (t == P::offsets[a]) acc = o.c.num < 0 ? T(-v) : v;  // from the first term, as above
            else acc = o.c.num < 0 ? acc - v : acc + v;
        }
        (a < P::tmp_count ? tmp[a] : out[a - P::tmp_count]) = acc;
    }
    return out;
}

// ---- from a node to its values: unrolled, looped program, or looped product ------------------

template <class U, class Node, auto TL>
constexpr std::array<U, TL.size()> compute(const U* const* leaves) noexcept;

template <class U, class P, std::size_t N>
CTGA_ALWAYS_INLINE constexpr std::array<U, N> run_program(const U* const* leaves) noexcept {
    if constexpr (P::terms.size() <= unroll_limit) return run<U, P, N>(leaves);
    else return run_interpreted<U, P, N>(leaves);
}

// A looped product's operand: a leaf in place, anything else evaluated into its canonical layout.
template <class U, class X>
constexpr auto operand_values(const U* const* leaves) noexcept {
    if constexpr (read_in_place<X>) return leaves[leaf_index<X>()];
    else return compute<U, X, node_layout<X>>(leaves);
}
template <class U>
constexpr const U* data_of(const U* p) noexcept { return p; }
template <class U, std::size_t N>
constexpr const U* data_of(const std::array<U, N>& a) noexcept { return a.data(); }

template <class U, auto TL, class Rule, class X, class Y>
constexpr std::array<U, TL.size()> compute_looped(const U* const* leaves, looped<Rule, X, Y>*) noexcept {
    const auto x = operand_values<U, X>(leaves);
    const auto y = operand_values<U, Y>(leaves);
    return run_product<U, Rule, operand_layout<X>, operand_layout<Y>, TL>(data_of(x), data_of(y));
}

// The program of P, after its looped products: each computed once, then read as leaves
// leaf_base, leaf_base + 1, …
template <class U, class P, std::size_t N, class... Ls>
constexpr std::array<U, N> run_after_looped(const U* const* leaves, type_list<Ls...>) noexcept {
    const std::tuple<std::array<U, node_layout<Ls>.size()>...> values{compute<U, Ls, node_layout<Ls>>(leaves)...};
    std::array<const U*, P::leaf_base + sizeof...(Ls)> all{};
    for (std::size_t i = 0; i < P::leaf_base; ++i) all[i] = leaves[i];
    std::apply([&](const auto&... v) {
        std::size_t k = P::leaf_base;
        ((all[k++] = v.data()), ...);
    }, values);
    return run_program<U, P, N>(all.data());
}

// The components of layout TL of Node's value, from the leaves' storage.
template <class U, class Node, auto TL>
CTGA_ALWAYS_INLINE constexpr std::array<U, TL.size()> compute(const U* const* leaves) noexcept {
    if constexpr (is_looped_node<Node>) {
        return compute_looped<U, TL>(leaves, static_cast<Node*>(nullptr));
    } else {
        using P = program<Node, TL>;
        if constexpr (P::looped_count == 0) return run_program<U, P, TL.size()>(leaves);
        else return run_after_looped<U, P, TL.size()>(leaves, typename P::looped_list{});
    }
}

#if defined(__clang__)
#pragma clang diagnostic pop
#endif

}  // namespace ctga::expr
