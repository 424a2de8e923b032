// Reading a value: an expression (or any operand) evaluated into a multivector type, one
// component of it, a projection onto fewer blades, equality. Each runs the expression's program
// (expr/program.hpp, expr/run.hpp) for exactly the components asked for.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/algebra/multivector.hpp"
#include "ctga/expr/expression.hpp"

namespace ctga {

// The value of an operand as a multivector of the blades it can make non-zero.
template <class T = void, operand X>
[[nodiscard]] constexpr auto eval(const X& x) noexcept {
    using D = std::remove_cvref_t<X>;
    if constexpr (multivector_type<D>) {
        return x;
    } else {
        using U = std::conditional_t<std::is_void_v<typename D::scalar_type>, std::conditional_t<std::is_void_v<T>, double, T>,
                                     typename D::scalar_type>;
        using result = multivector<typename D::algebra_type, U, D::layout>;
        return result(detail::from_components_t{}, expr::as_expression(x).template evaluate<U, D::layout>());
    }
}

// Keep only the blades of Target (a multivector type), dropping the rest on purpose; only the
// kept components are computed.
template <multivector_type Target, operand X>
[[nodiscard]] constexpr Target project(const X& x) noexcept {
    const auto e = expr::as_expression(x);
    return Target(detail::from_components_t{}, e.template evaluate<typename Target::scalar_type, Target::layout>());
}

// Unrolled or looped, by choice. The engine unrolls a product into straight-line code up to
// expr::loop_threshold surviving blade pairs and loops over a table of them past it
// (expr/looped.hpp); these force either for every product of x:
//   auto p = ctga::loop_products(a * b);     // one loop, cheap to compile, for a large product
//   auto q = ctga::unroll_products(a * b);   // straight-line code (up to expr::term_budget pairs)
template <operand X>
[[nodiscard]] constexpr auto loop_products(X&& x) noexcept {
    return expr::in_mode<expr::product_mode::looped>(std::forward<X>(x));
}
template <operand X>
[[nodiscard]] constexpr auto unroll_products(X&& x) noexcept {
    return expr::in_mode<expr::product_mode::unrolled>(std::forward<X>(x));
}

// The coefficient of a blade named as written, computing that component only.
template <fixed_string Name, class Alg, class T, class Node, class Leaves>
[[nodiscard]] constexpr auto get(const expression<Alg, T, Node, Leaves>& e) noexcept {
    return e.template get<Name>();
}

// The scalar (grade-0) coefficient.
template <operand X>
[[nodiscard]] constexpr auto scalar_part(const X& x) noexcept {
    if constexpr (multivector_type<X>) return x.template get<"1">();
    else return expr::as_expression(x).template get<"1">();
}

// Equal when every blade has the same coefficient (absent blades count as zero).
template <operand X, operand Y>
[[nodiscard]] constexpr bool operator==(const X& x, const Y& y) noexcept {
    const auto a = eval(x);
    const auto b = eval(y);
    using A = decltype(a);
    using B = decltype(b);
    static_assert(std::is_same_v<typename A::algebra_type, typename B::algebra_type>,
                  "ctga: the operands belong to different algebras");
    using T = typename A::scalar_type;
    auto coefficient = [](const auto& m, blade_mask blade) -> T {
        const int i = m.layout.index_of(blade);
        if (i < 0) return T{};
        return m.layout.signs[i] > 0 ? T(m[i]) : T(-m[i]);
    };
    constexpr auto all = layout_union<A::layout, B::layout>;
    for (blade_mask blade : all.masks)
        if (!(coefficient(a, blade) == coefficient(b, blade))) return false;
    return true;
}

}  // namespace ctga
