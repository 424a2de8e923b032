// Running a program (program.hpp) on the operands' storage. Every assignment is a sum of its
// constexpr terms; up to inline_terms terms a program is unrolled into the caller, so the
// compiler sees plain arithmetic on the operands' storage and on local temporaries; a larger one
// runs as one loop over its terms.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
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

// The signed sum of terms I ∈ [B, E) of assignment A of program P (negated when Negate), as a
// balanced tree: the compiler may not reassociate floating-point additions, and one left-to-right
// chain over the thirty terms of a kinetic energy is a chain of thirty dependent additions. Term
// I is the assignment's term (I + R) mod n: the rotation R puts a positive term first when there
// is one, so that a − b is computed as a − b and not as −b + a. A half whose first term is
// negative is subtracted with its signs flipped, so no other negation is ever needed.
template <class P, std::size_t A>
struct assignment_terms {
    static constexpr std::uint32_t begin = P::offsets[A];
    static constexpr std::uint32_t n = P::offsets[A + 1] - begin;
    static constexpr std::uint32_t rotation = [] {
        for (std::uint32_t i = 0; i < n; ++i)
            if (P::terms[begin + i].c.num > 0) return i;
        return std::uint32_t{0};
    }();
    static constexpr const op_term& at(std::uint32_t i) noexcept { return P::terms[begin + (i + rotation) % n]; }
};

template <class T, class P, std::size_t A, std::uint32_t B, std::uint32_t E, bool Negate>
CTGA_ALWAYS_INLINE constexpr T range_sum(const T* const* leaves, const T* tmp) noexcept {
    using terms = assignment_terms<P, A>;
    if constexpr (E - B == 1) {
        const T v = term_magnitude<T>(terms::at(B), leaves, tmp);
        if constexpr ((terms::at(B).c.num < 0) != Negate) return T(-v);
        else return v;
    } else {
        constexpr std::uint32_t M = B + (E - B) / 2;
        const T left = range_sum<T, P, A, B, M, Negate>(leaves, tmp);
        if constexpr ((terms::at(M).c.num < 0) != Negate) return left - range_sum<T, P, A, M, E, !Negate>(leaves, tmp);
        else return left + range_sum<T, P, A, M, E, Negate>(leaves, tmp);
    }
}

// Assignment A of program P: its terms summed (from a term, not from zero: x + 0.0 is not x for
// x = −0.0, so a zero start would cost an addition the compiler may not remove).
template <class T, class P, std::size_t A>
CTGA_ALWAYS_INLINE constexpr T assignment(const T* const* leaves, const T* tmp) noexcept {
    constexpr std::uint32_t n = assignment_terms<P, A>::n;
    if constexpr (n == 0) return T{};
    else return range_sum<T, P, A, 0, n, false>(leaves, tmp);
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#undef CTGA_UNROLL_TERMS

// Run program P on the leaves' storage: the temporaries in order, then the N outputs.
template <class T, class P, std::size_t... A>
CTGA_ALWAYS_INLINE constexpr void run_temporaries([[maybe_unused]] T* tmp, [[maybe_unused]] const T* const* leaves,
                                                     std::index_sequence<A...>) noexcept {
    ((tmp[A] = assignment<T, P, A>(leaves, tmp)), ...);
}

template <class T, class P, std::size_t N, std::size_t... R>
CTGA_ALWAYS_INLINE constexpr std::array<T, N> run_outputs([[maybe_unused]] const T* tmp, [[maybe_unused]] const T* const* leaves,
                                                              std::index_sequence<R...>) noexcept {
    return std::array<T, N>{assignment<T, P, P::tmp_count + R>(leaves, tmp)...};
}

template <class T, class P, std::size_t N>
CTGA_ALWAYS_INLINE constexpr std::array<T, N> run(const T* const* leaves) noexcept {
    std::array<T, (P::tmp_count > 0 ? P::tmp_count : 1)> tmp{};
    run_temporaries<T, P>(tmp.data(), leaves, std::make_index_sequence<P::tmp_count>{});
    return run_outputs<T, P, N>(tmp.data(), leaves, std::make_index_sequence<N>{});
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
    return run_rows<U, pair_rows<Rule, operand_layout<X>, operand_layout<Y>>, operand_layout<Y>, TL>(data_of(x), data_of(y));
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
