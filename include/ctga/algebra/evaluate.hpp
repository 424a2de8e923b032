// Turning a plan into code. Each result component is one fold expression over its terms,
// written on the operands' own storage, so the compiler sees straight-line arithmetic:
// no tables, no loops, no copies. Signs are compile-time: a term with sign −1 is a negation,
// which the compiler fuses into a subtraction. Components with no term are T{} (zero).
//
// Plans past a size threshold are evaluated by a loop over the constexpr term array instead
// (toolchain.md: unrolling tens of thousands of terms costs minutes of compile time, and clang
// caps a fold at 256 operands).
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "ctga/algebra/multivector.hpp"
#include "ctga/algebra/plan.hpp"

namespace ctga::detail {

inline constexpr std::size_t unroll_term_limit = 4096;   // whole plan
inline constexpr std::size_t unroll_fold_limit = 200;    // one component

template <class Plan>
constexpr bool unrolled() {
    if (Plan::term_count > unroll_term_limit) return false;
    for (std::size_t r = 0; r + 1 < Plan::offsets.size(); ++r)
        if (Plan::offsets[r + 1] - Plan::offsets[r] > unroll_fold_limit) return false;
    return true;
}

// GCC 12 at -O2 can report a bogus -Warray-bounds on these reads once whole expressions are
// inlined: every index is a compile-time constant of the plan and within bounds (checked under
// AddressSanitizer in the tests), so the warning is switched off for these few lines only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif

// One term's value. The term is a compile-time constant of the plan, so once inlined its sign
// test folds away and a negative term becomes a subtraction; one instantiation per operand
// types, not one per term, keeps compile time linear in the number of products.
template <class T, class A, class B>
constexpr T term_value(const linear_term& t, const A& a, const B& b) noexcept {
    // operands reached through one table: a constant operand index folds to a direct load
    const T* const operands[2] = {a.data(), b.data()};
    const T& v = operands[t.operand][t.i];
    return t.sign > 0 ? v : T(-v);
}

template <class T, class A, class B>
constexpr T term_value(const bilinear_term& t, const A& a, const B& b) noexcept {
    return t.sign > 0 ? T(a[t.ia] * b[t.ib]) : T(-(a[t.ia] * b[t.ib]));
}

#if defined(__clang__)
#define CTGA_UNROLL _Pragma("clang loop unroll(full)")
#elif defined(__GNUC__)
#define CTGA_UNROLL _Pragma("GCC unroll 1024")
#else
#define CTGA_UNROLL
#endif

// Result component R: its run of terms, summed from the first term (not from zero: x + 0.0 is
// not x for x = −0.0, so a zero start would cost an addition the compiler may not remove).
// The loop has a compile-time trip count over a constexpr array and is fully unrolled.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

template <class T, class Plan, std::size_t R, class A, class B>
constexpr T component(const A& a, const B& b) noexcept {
    constexpr std::size_t begin = Plan::offsets[R];
    constexpr std::size_t end = Plan::offsets[R + 1];
    if constexpr (begin == end) {
        return T{};
    } else {
        T acc = term_value<T>(Plan::terms[begin], a, b);
        CTGA_UNROLL
        for (std::size_t k = begin + 1; k < end; ++k) acc = acc + term_value<T>(Plan::terms[k], a, b);
        return acc;
    }
}

// Evaluate a plan whose operands are a and b (b is ignored by one-operand linear plans).
template <class Result, class Plan, bool Bilinear, class A, class B>
constexpr Result evaluate(const A& a, const B& b) noexcept {
    using T = typename Result::scalar_type;
    constexpr std::size_t n = Result::size();
    if constexpr (unrolled<Plan>()) {
        return [&]<std::size_t... R>(std::index_sequence<R...>) {
            return Result(from_components_t{}, std::array<T, n>{component<T, Plan, R>(a, b)...});
        }(std::make_index_sequence<n>{});
    } else {
        std::array<T, n> out{};
        for (const auto& t : Plan::terms) {
            if constexpr (Bilinear) {
                out[t.r] = t.sign > 0 ? out[t.r] + a[t.ia] * b[t.ib] : out[t.r] - a[t.ia] * b[t.ib];
            } else {
                const T* const operands[2] = {a.data(), b.data()};
                const T& v = operands[t.operand][t.i];
                out[t.r] = t.sign > 0 ? out[t.r] + v : out[t.r] - v;
            }
        }
        return Result(from_components_t{}, out);
    }
}

}  // namespace ctga::detail

namespace ctga {

template <class Alg, class T, auto Layout>
template <auto L2>
constexpr multivector<Alg, T, Layout>::multivector(const multivector<Alg, T, L2>& x) noexcept {
    constexpr int missing = detail::first_missing<L2, Layout>();
    if constexpr (missing >= 0) {
        (void)sizeof(detail::target_lacks<Alg, L2.masks[missing]>);
    } else {
        using plan = detail::linear_plan<Alg, Layout, std::array<signed char, 2>{1, 1}, L2>;
        *this = detail::evaluate<multivector, plan, false>(x, x);
    }
}

}  // namespace ctga
