// Running a program (program.hpp) on the operands' storage. Every assignment is a sum of its
// constexpr terms; up to inline_terms terms a program is unrolled into the caller, so the
// compiler sees plain arithmetic on the operands' storage and on local temporaries; a larger one
// runs as one loop over its terms.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

#include "ctga/expr/derivative.hpp"
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
// Clang cannot fully unroll term_magnitude's loop where a program runs looped (run_looped: the
// degree is not a constant there) and says so with -Wpass-failed; the loop is correct either
// way, so the note is off from here to the end of this file.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wpass-failed"
#endif

// |c| in T: an integer, or a quotient (in T when T divides, else rounded from long double).
template <class T>
constexpr T coefficient(const rational& c) {
    const std::int64_t n = c.num < 0 ? -c.num : c.num;
    if (c.den == 1) return T(n);
    if constexpr (requires(const T& a) { a / a; }) return T(n) / T(c.den);
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
// equation of motion, and calls term_magnitude once per term). A larger program runs as one
// loop over its constexpr terms in a function of its own: unrolling thousands of terms into the
// caller made the property suites' build three times as long (measured on this project: a 256×256 product
// took 120 s unrolled against 11 s as a loop).
inline constexpr std::size_t inline_terms = 64;

template <class T, class P, std::size_t N>
[[gnu::noinline]] constexpr std::array<T, N> run_looped(const T* const* leaves) noexcept {
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
    if constexpr (P::terms.size() <= inline_terms) return run<U, P, N>(leaves);
    else return run_looped<U, P, N>(leaves);
}

// A looped product's operand: a leaf in place, anything else evaluated into its canonical layout.
template <class U, class X>
constexpr auto operand_values(const U* const* leaves) noexcept {
    if constexpr (read_in_place<X>) return leaves[leaf_index<X>];
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

// ---- values that share looped products: each computed once ----------------------------------
//
// Several trees over the same leaves (a Jacobian's columns, expr/derivative.hpp) can read the
// same looped products, and the same operands of them. Their units are every looped product the
// trees read, at any depth, and every operand of one that is not a leaf: each is computed once
// (identified by its structural hash), an operand before the products that read it, and every
// program then reads them as leaves.
template <class L>
struct looped_units;
template <class List>
struct units_of_list;
template <class... Ls>
struct units_of_list<type_list<Ls...>> {
    using type = decltype((type_list<>{} + ... + typename looped_units<Ls>::type{}));
};
// the units a tree's program reads
template <class Tree>
using tree_units = typename units_of_list<looped_nodes_t<Tree>>::type;

// An operand that is a product whose program would run as a loop over its terms anyway (past
// inline_terms) is computed as a looped product when that costs no more pairs than the program
// has terms: the table loop (or block product) runs about twice as fast per pair as the
// program's loop per term (G N of the moved inertia: 0.65 µs against 1.4 µs). Its factors are
// then units of their own, and its value is read into its own (symbolic) layout.
template <class X>
inline constexpr bool loop_as_unit = false;
template <class R, class A, class B>
inline constexpr bool loop_as_unit<product<R, A, B>> = [] {
    using P = program<product<R, A, B>, node_layout<product<R, A, B>>>;
    return P::terms.size() > inline_terms && rows_of<R, A, B>::pairs <= 2 * P::terms.size();
}();

template <class R, class A, class B>
constexpr auto factor_units(product<R, A, B>*);
template <class X>
constexpr auto operand_units() {
    if constexpr (read_in_place<X>) return type_list<>{};
    else if constexpr (is_looped_node<X>) return typename looped_units<X>::type{};
    else if constexpr (loop_as_unit<X>) return factor_units(static_cast<X*>(nullptr)) + type_list<X>{};
    else return tree_units<X>{} + type_list<X>{};
}
template <class R, class A, class B>
constexpr auto factor_units(product<R, A, B>*) {
    return operand_units<A>() + operand_units<B>();
}
template <class R, class X, class Y>
struct looped_units<looped<R, X, Y>> {
    using type = decltype(operand_units<X>() + operand_units<Y>() + type_list<looped<R, X, Y>>{});
};

template <class Units, class Node>
inline constexpr std::size_t unit_index = [] {
    constexpr auto& hashes = hash_list<Units>::value;
    for (std::size_t i = 0; i < hashes.size(); ++i)
        if (hashes[i] == traits<Node>::hash) return i;
    return hashes.size();
}();

template <class U, class Units>
struct unit_store;
template <class U, class... Us>
struct unit_store<U, type_list<Us...>> {
    using type = std::tuple<std::array<U, node_layout<Us>.size()>...>;
};

// An operand's values: a leaf in place, any other operand from its unit.
template <class U, class Units, class X, class Store>
CTGA_ALWAYS_INLINE constexpr const U* unit_operand(const U* const* leaves, const Store& store) noexcept {
    if constexpr (read_in_place<X>) return leaves[leaf_index<X>];
    else {
        static_assert(unit_index<Units, X> < std::tuple_size_v<Store>, "ctga: an operand missing from the shared units");
        return std::get<unit_index<Units, X>>(store).data();
    }
}

// Program P on the leaves, its looped products read from their units; unrolled up to Inline terms.
template <class U, class Units, class P, std::size_t N, std::size_t Inline, class Store, class... Ls>
constexpr std::array<U, N> run_with_units(const U* const* leaves, const Store& store, type_list<Ls...>) noexcept {
    std::array<const U*, P::leaf_base + sizeof...(Ls)> all{};
    for (std::size_t i = 0; i < P::leaf_base; ++i) all[i] = leaves[i];
    [[maybe_unused]] std::size_t k = P::leaf_base;
    ((all[k++] = unit_operand<U, Units, Ls>(leaves, store)), ...);
    if constexpr (P::terms.size() <= Inline) return run<U, P, N>(all.data());
    else return run_looped<U, P, N>(all.data());
}

// ---- a sum with looped products in it ------------------------------------------------------
//
// A Jacobian's column is a sum of products (expr/derivative.hpp), the large ones looped. Its
// looped products accumulate into one table over the blades, read once into the target layout,
// instead of each product's own table and a program adding their results; the rest of the sum
// (products with a constant factor, which are signed copies) is one program, added at the end.
template <int Sign, class L>
struct signed_looped {};
template <int S, class L>
auto negated_term(signed_looped<S, L>) -> signed_looped<-S, L>;
template <class... Ts>
auto negated(type_list<Ts...>) -> type_list<decltype(negated_term(Ts{}))...>;

// N = Σ ± looped products + rest (rest a node, or the zero node).
template <class N>
struct split_sum {
    using looped_terms = type_list<>;
    using rest = N;
};
template <class R, class X, class Y>
struct split_sum<looped<R, X, Y>> {
    using looped_terms = type_list<signed_looped<1, looped<R, X, Y>>>;
    using rest = zero_node;
};
template <class A, class B, int S>
struct split_sum<sum<A, B, S>> {
    using b_terms = typename split_sum<B>::looped_terms;
    using looped_terms =
        decltype(typename split_sum<A>::looped_terms{} + std::conditional_t<S == 1, b_terms, decltype(negated(b_terms{}))>{});
    using rest = derivative_detail::add_t<typename split_sum<A>::rest, typename split_sum<B>::rest, S>;
};
template <class X>
struct split_sum<scaled<rational{-1, 1}, X>> {
    using looped_terms = decltype(negated(typename split_sum<X>::looped_terms{}));
    using rest = derivative_detail::add_t<zero_node, typename split_sum<X>::rest, -1>;
};

// The accumulators' size: the largest universe of the products, as they run (swapped or not).
template <int S, class R, class X, class Y>
constexpr std::size_t term_universe(signed_looped<S, looped<R, X, Y>>) {
    constexpr auto LX = operand_layout<X>;
    constexpr auto LY = operand_layout<Y>;
    if constexpr (run_swapped<R, LX, LY>) return pair_rows<R, swapped_layout<R, LX>, swapped_layout<R, LY>>::universe;
    else return pair_rows<R, LX, LY>::universe;
}
template <int S, class R, class X, class Y>
constexpr bool term_swapped(signed_looped<S, looped<R, X, Y>>) {
    return run_swapped<R, operand_layout<X>, operand_layout<Y>>;
}
template <int S, class R, class X, class Y>
auto term_rule(signed_looped<S, looped<R, X, Y>>) -> R;
// the rule of the first term that runs swapped (the swap depends only on its algebra)
template <class T0, class... Ts>
auto swapped_rule(type_list<T0, Ts...>) {
    if constexpr (term_swapped(T0{}) || sizeof...(Ts) == 0) return decltype(term_rule(T0{})){};
    else return swapped_rule(type_list<Ts...>{});
}

// the units the sum reads: its looped products' operands, and the rest's
template <int... S, class... R, class... X, class... Y>
constexpr auto sum_operand_units(type_list<signed_looped<S, looped<R, X, Y>>...>) {
    return (type_list<>{} + ... + (operand_units<X>() + operand_units<Y>()));
}
template <class Root>
constexpr auto root_units() {
    using split = split_sum<Root>;
    if constexpr (is_zero_node<typename split::rest>) return sum_operand_units(typename split::looped_terms{});
    else return sum_operand_units(typename split::looped_terms{}) + tree_units<typename split::rest>{};
}

template <class U, class Units, class Store, int S, class R, class X, class Y>
CTGA_ALWAYS_INLINE constexpr void accumulate_looped(U* acc, U* swapped, const U* const* leaves, const Store& store,
                                                    signed_looped<S, looped<R, X, Y>>) noexcept {
    run_product_into<U, R, operand_layout<X>, operand_layout<Y>, (S < 0)>(acc, swapped, unit_operand<U, Units, X>(leaves, store),
                                                                        unit_operand<U, Units, Y>(leaves, store));
}
// (two accumulators: the products run as the blades lie, and those run with the halves
// swapped, looped.hpp; each is read back in its own labelling)
template <class U, class Units, auto TL, class Store, class... Ts>
constexpr std::array<U, TL.size()> looped_sum_from_units(const U* const* leaves, const Store& store, type_list<Ts...>) noexcept {
    constexpr std::size_t universe = std::max({term_universe(Ts{})...});
    constexpr bool any_plain = (!term_swapped(Ts{}) || ...);
    constexpr bool any_swapped = (term_swapped(Ts{}) || ...);
    std::array<U, any_plain ? universe : 1> acc{};
    std::array<U, any_swapped ? universe : 1> swapped{};
    (accumulate_looped<U, Units>(acc.data(), swapped.data(), leaves, store, Ts{}), ...);
    using R = decltype(swapped_rule(type_list<Ts...>{}));
    if constexpr (!any_swapped) return gather<U, universe, TL>(acc.data());
    else if constexpr (!any_plain) return gather<U, universe, swapped_layout<R, TL>>(swapped.data());
    else {
        auto out = gather<U, universe, TL>(acc.data());
        const auto more = gather<U, universe, swapped_layout<R, TL>>(swapped.data());
        for (std::size_t k = 0; k < TL.size(); ++k) out[k] += more[k];
        return out;
    }
}

template <class U, class Units, auto TL, class Store, class R, class X, class Y>
constexpr std::array<U, TL.size()> product_from_units(const U* const* leaves, const Store& store, product<R, X, Y>*) noexcept {
    return run_product<U, R, operand_layout<X>, operand_layout<Y>, TL>(unit_operand<U, Units, X>(leaves, store),
                                                                       unit_operand<U, Units, Y>(leaves, store));
}

// Node's components in layout TL, its units already computed: a product computed as a loop
// (loop_as_unit), the looped products of a sum accumulated together plus the program of the
// rest, or the program of the whole (unrolled up to Inline terms).
template <class U, class Units, class Node, auto TL, std::size_t Inline = inline_terms, class Store>
constexpr std::array<U, TL.size()> compute_from_units(const U* const* leaves, const Store& store) noexcept {
    using split = split_sum<Node>;
    using rest = typename split::rest;
    if constexpr (loop_as_unit<Node>) {
        return product_from_units<U, Units, TL>(leaves, store, static_cast<Node*>(nullptr));
    } else if constexpr (std::is_same_v<typename split::looped_terms, type_list<>>) {
        using P = program<Node, TL>;
        return run_with_units<U, Units, P, TL.size(), Inline>(leaves, store, typename P::looped_list{});
    } else {
        auto out = looped_sum_from_units<U, Units, TL>(leaves, store, typename split::looped_terms{});
        if constexpr (!is_zero_node<rest>) {
            using P = program<rest, TL>;
            const auto more = run_with_units<U, Units, P, TL.size(), Inline>(leaves, store, typename P::looped_list{});
            for (std::size_t k = 0; k < TL.size(); ++k) out[k] += more[k];
        }
        return out;
    }
}

template <std::size_t K, class... Us>
auto unit_type(type_list<Us...>) -> std::tuple_element_t<K, std::tuple<Us...>>;
template <std::size_t K, class Units>
using unit_t = decltype(unit_type<K>(Units{}));

// Every unit, in order (each reads only earlier ones).
template <class U, class Units, class Store, std::size_t... K>
constexpr void compute_units(const U* const* leaves, Store& store, std::index_sequence<K...>) noexcept {
    ((std::get<K>(store) = compute_from_units<U, Units, unit_t<K, Units>, node_layout<unit_t<K, Units>>>(leaves, store)), ...);
}

// What a root costs in layout TL once its units are computed: a loop a multiplication and an
// addition per pair, a program its assignments (the looped products it reads are units).
template <int... S, class... R, class... X, class... Y>
constexpr cost looped_terms_price(type_list<signed_looped<S, looped<R, X, Y>>...>) {
    return (cost{rows_of<R, X, Y>::pairs, rows_of<R, X, Y>::pairs} + ... + cost{});
}
template <class R, class A, class B>
constexpr cost product_pairs_price(product<R, A, B>*) {
    return cost{rows_of<R, A, B>::pairs, rows_of<R, A, B>::pairs};
}
template <class P>
constexpr cost program_assignments_price() {
    return assignments_price(P::terms.data(), P::offsets.data(), P::assignment_count);
}
template <class Node, auto TL>
constexpr cost root_price() {
    using split = split_sum<Node>;
    using rest = typename split::rest;
    if constexpr (loop_as_unit<Node>) return product_pairs_price(static_cast<Node*>(nullptr));
    else if constexpr (std::is_same_v<typename split::looped_terms, type_list<>>) return program_assignments_price<program<Node, TL>>();
    else if constexpr (is_zero_node<rest>) return looped_terms_price(typename split::looped_terms{});
    else return looped_terms_price(typename split::looped_terms{}) + program_assignments_price<program<rest, TL>>();
}
template <class... Us>
constexpr cost units_price(type_list<Us...>) {
    return (root_price<Us, node_layout<Us>>() + ... + cost{});
}

#if defined(__clang__)
#pragma clang diagnostic pop
#endif

}  // namespace ctga::expr
