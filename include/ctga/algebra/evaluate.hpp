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

template <class T, auto t, class A, class B>
constexpr T linear_value(const A& a, const B& b) noexcept {
    if constexpr (t.operand == 0) {
        if constexpr (t.sign > 0) return a[t.i]; else return -a[t.i];
    } else {
        if constexpr (t.sign > 0) return b[t.i]; else return -b[t.i];
    }
}

template <class T, auto t, class A, class B>
constexpr T bilinear_value(const A& a, const B& b) noexcept {
    if constexpr (t.sign > 0) return a[t.ia] * b[t.ib]; else return -(a[t.ia] * b[t.ib]);
}

template <class T, class Plan, bool Bilinear, std::size_t R, class A, class B>
constexpr T component(const A& a, const B& b) noexcept {
    constexpr std::size_t begin = Plan::offsets[R];
    constexpr std::size_t count = Plan::offsets[R + 1] - begin;
    if constexpr (count == 0) {
        return T{};
    } else {
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            if constexpr (Bilinear) return (bilinear_value<T, Plan::terms[begin + I]>(a, b) + ...);
            else return (linear_value<T, Plan::terms[begin + I]>(a, b) + ...);
        }(std::make_index_sequence<count>{});
    }
}

// Evaluate a plan whose operands are a and b (b is ignored by one-operand linear plans).
template <class Result, class Plan, bool Bilinear, class A, class B>
constexpr Result evaluate(const A& a, const B& b) noexcept {
    using T = typename Result::scalar_type;
    constexpr std::size_t n = Result::size();
    if constexpr (unrolled<Plan>()) {
        return [&]<std::size_t... R>(std::index_sequence<R...>) {
            return Result(from_components_t{}, std::array<T, n>{component<T, Plan, Bilinear, R>(a, b)...});
        }(std::make_index_sequence<n>{});
    } else {
        std::array<T, n> out{};
        for (const auto& t : Plan::terms) {
            if constexpr (Bilinear) {
                if (t.sign > 0) out[t.r] += a[t.ia] * b[t.ib]; else out[t.r] -= a[t.ia] * b[t.ib];
            } else {
                const T& v = t.operand == 0 ? a[t.i] : b[t.i];
                if (t.sign > 0) out[t.r] += v; else out[t.r] -= v;
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
        (void)sizeof(detail::target_type_lacks_blade<detail::blade_name_string<Alg, L2.masks[missing]>()>);
    } else {
        using plan = detail::linear_plan<Alg, Layout, std::array<signed char, 2>{1, 1}, L2>;
        *this = detail::evaluate<multivector, plan, false>(x, x);
    }
}

}  // namespace ctga
