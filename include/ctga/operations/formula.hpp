// Formulas (expressions with named arguments), operations (a formula with a typed call: the
// paper's operations are each written once as one), and what the engine can say about a formula
// at compile time: its cost (cost_of) and whether two formulas are equal for all inputs
// (identical).
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <boost/hana/concat.hpp>
#include <boost/hana/flatten.hpp>
#include <boost/hana/tuple.hpp>

#include "ctga/expr/expression.hpp"
#include "ctga/operations/evaluate.hpp"
#include "ctga/operations/operators.hpp"
#include "ctga/support/inline.hpp"

namespace ctga {

// A parametrised argument: one element of a formula given by a few multivectors and the
// expression they make. Its type provides parameters() (the multivectors, as a tuple of
// references) and element(p...) (the element as an expression of them). Inside a formula each
// parameter is one leaf: body_inertia passes a rigid body's N as its ten numbers.
template <class X>
concept parametrised_operand = requires(const X& x) {
    std::tuple_size<std::remove_cvref_t<decltype(x.parameters())>>::value;
    X::element;
};

// What a formula takes as an argument.
template <class X>
concept formula_argument = operand<X> || parametrised_operand<std::remove_cvref_t<X>>;

namespace expr {

template <class A>
struct argument_shape {  // a multivector: one leaf
    static constexpr std::size_t leaves = 1;
    static constexpr bool parametrised = false;
    using scalar_type = typename A::scalar_type;
};
template <parametrised_operand A>
struct argument_shape<A> {  // one leaf per parameter
    using parameters = std::remove_cvref_t<decltype(std::declval<const A&>().parameters())>;
    static constexpr std::size_t leaves = std::tuple_size_v<parameters>;
    static constexpr bool parametrised = true;
    using scalar_type = typename std::remove_cvref_t<std::tuple_element_t<0, parameters>>::scalar_type;
};
template <class A>
using shape_of = argument_shape<std::remove_cvref_t<A>>;

template <class... Args>
inline constexpr std::size_t leaf_total = (shape_of<Args>::leaves + ... + 0);

// Where each argument's leaves start: the multivector arguments first, in order, then the
// parameters of the parametrised ones.
template <class... Args>
inline constexpr std::array<std::size_t, sizeof...(Args)> first_leaf = [] {
    constexpr std::array<bool, sizeof...(Args)> parametrised{shape_of<Args>::parametrised...};
    constexpr std::array<std::size_t, sizeof...(Args)> leaves{shape_of<Args>::leaves...};
    std::array<std::size_t, sizeof...(Args)> first{};
    std::size_t next = 0;
    for (std::size_t i = 0; i < sizeof...(Args); ++i)
        if (!parametrised[i]) first[i] = next++;
    for (std::size_t i = 0; i < sizeof...(Args); ++i)
        if (parametrised[i]) first[i] = next, next += leaves[i];
    return first;
}();

// Leaf I of a formula, standing for an element of type A.
template <std::size_t I, class A>
constexpr auto placeholder() noexcept {
    using D = std::remove_cvref_t<A>;
    return make_expression<typename D::algebra_type, typename D::scalar_type, arg<I, D::layout>>(boost::hana::make_tuple());
}

// What the formula's body sees for an argument of type A whose leaves start at First.
template <std::size_t First, class A>
constexpr auto argument_placeholder() noexcept {
    using D = std::remove_cvref_t<A>;
    if constexpr (!shape_of<D>::parametrised) {
        return placeholder<First, D>();
    } else {
        using P = typename shape_of<D>::parameters;
        return [&]<std::size_t... J>(std::index_sequence<J...>) {
            return D::element(placeholder<First + J, std::tuple_element_t<J, P>>()...);
        }(std::make_index_sequence<shape_of<D>::leaves>{});
    }
}

template <class F, class... Args>
constexpr auto call_with_placeholders(const F& f) noexcept {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        // as an expression: a body may return a basis blade (the paper's E) or a leaf alone
        return as_expression(
            f(argument_placeholder<first_leaf<Args...>[I], std::tuple_element_t<I, std::tuple<Args...>>>()...));
    }(std::index_sequence_for<Args...>{});
}
template <class F, class... Args>
using formula_result = decltype(call_with_placeholders<F, Args...>(std::declval<const F&>()));

// The leaf of one multivector: by address when it outlives the expression's full-expression
// (an lvalue), by value otherwise.
template <bool ByValue, class X>
constexpr auto leaf_of(const X& x) noexcept {
    if constexpr (ByValue) return value_leaf<X>{x};
    else return ref_leaf<X>{&x};
}

// The leaves of the formula's arguments in the order first_leaf numbers them.
template <class... Args>
constexpr auto argument_leaves(Args&&... args) noexcept {
    auto plain = [&]<class A>(A&& a) {
        using D = std::remove_cvref_t<A>;
        if constexpr (shape_of<D>::parametrised) return boost::hana::make_tuple();
        else if constexpr (std::is_lvalue_reference_v<A>) return boost::hana::make_tuple(ref_leaf<D>{&a});
        else return boost::hana::make_tuple(value_leaf<D>{std::move(a)});
    };
    auto parameters = [&]<class A>(A&& a) {
        using D = std::remove_cvref_t<A>;
        if constexpr (!shape_of<D>::parametrised) {
            return boost::hana::make_tuple();
        } else {
            return std::apply([](const auto&... p) {
                return boost::hana::make_tuple(leaf_of<!std::is_lvalue_reference_v<A>>(p)...);
            }, a.parameters());
        }
    };
    return boost::hana::concat(boost::hana::flatten(boost::hana::make_tuple(plain(std::forward<Args>(args))...)),
                               boost::hana::flatten(boost::hana::make_tuple(parameters(std::forward<Args>(args))...)));
}

}  // namespace expr

// An expression with named arguments: f(args...) is a lazy expression in which each argument
// is one leaf wherever the formula uses it, so the normal form sees repeated arguments cancel.
template <class F>
struct formula_t {
    F f;

    template <formula_argument... Args>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr auto operator()(Args&&... args) const noexcept {
        auto body = expr::call_with_placeholders<F, Args...>(f);
        using B = decltype(body);
        using first = expr::shape_of<std::tuple_element_t<0, std::tuple<Args...>>>;
        using node = expr::bind_t<typename B::node_type, expr::leaf_total<Args...>>;
        // the body's algebra: arguments may come from a subalgebra it embeds (ctga::lift)
        return expr::make_expression<typename B::algebra_type, typename first::scalar_type, node>(
            boost::hana::concat(expr::argument_leaves(std::forward<Args>(args)...), std::move(body.leaves)));
    }
};

template <class F>
[[nodiscard]] constexpr formula_t<F> formula(F f) noexcept {
    return {f};
}

// The sandwich R x R̃: a rotor, translator or motor R (R R̃ = 1) of any algebra acting on x, as
// klein's R(x). One formula, so R is one argument and what cancels between its two appearances
// is found: in Cl(3,0,1) a rotor sandwiching a point gives a point (the grade-1 terms of
// R p R̃ cancel), where R * p * reverse(R), with R as two independent leaves, cannot show it.
//   point q = ctga::sandwich(R, p);
inline constexpr auto sandwich = formula([](auto r, auto x) { return r * x * ~r; });

// An operation: a formula with a typed call, so that each of the paper's operations is written
// once and is both the composable formula and the function that returns a value.
//
//   inline constexpr operation momentum{formula([](auto N, auto s) { return A & (N ^ lift(s)); }),
//                                       into<coscrew>};
//   coscrew<double> P = momentum(N, s);      // evaluated, in the type the operation names
//   auto p = momentum.formula(N, s);         // the lazy formula, to compose further
//
// Finish takes the formula's expression and returns the value (into<Result>: Result<T>).
template <class F, class Finish>
struct operation {
    formula_t<F> formula;
    Finish finish;

    template <formula_argument... Args>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr auto operator()(const Args&... args) const noexcept {
        return finish(formula(args...));
    }
};
template <class F, class Finish>
operation(formula_t<F>, Finish) -> operation<F, Finish>;

// Finishing an operation in the multivector type Result<T>, T the arguments' scalar type.
template <template <class> class Result>
struct into_t {
    template <class E>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr Result<typename E::scalar_type> operator()(const E& e) const noexcept {
        return e;
    }
};
template <template <class> class Result>
inline constexpr into_t<Result> into{};

// Finishing an operation with its scalar part divided by Divisor (a pairing: Divisor 1; an energy
// from twice its value: 2).
template <int Divisor>
struct scalar_over_t {
    template <class E>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr auto operator()(const E& e) const noexcept {
        using T = typename E::scalar_type;
        if constexpr (Divisor == 1) return scalar_part(e);
        else return scalar_part(e) / T(Divisor);
    }
};
template <int Divisor>
inline constexpr scalar_over_t<Divisor> scalar_over{};

// Multiplications and additions of the code an expression type runs when evaluated into
// Target's blades (its own canonical blades by default), intermediates included. For a computed
// value that carries its price (a sparse_jacobian, operations/jacobian.hpp): that price.
template <class E, class Target = void>
inline constexpr expr::cost cost_of = [] {
    using D = std::remove_cvref_t<E>;
    if constexpr (requires { D::price; }) return D::price;
    else if constexpr (std::is_void_v<Target>) return expr::program<typename D::node_type, D::layout>::price;
    else return expr::program<typename D::node_type, Target::layout>::price;
}();

// True when f and g agree for all values of arguments of types Args: their fully expanded
// normal forms are equal term by term. A compile-time proof:
//   static_assert(ctga::identical<screw, screw>(lhs, rhs));
template <class... Args, class F, class G>
[[nodiscard]] consteval bool identical(F, G) {
    using nf = expr::traits<expr::bind_t<typename expr::formula_result<F, Args...>::node_type, expr::leaf_total<Args...>>,
                            expr::staging::proof>;
    using ng = expr::traits<expr::bind_t<typename expr::formula_result<G, Args...>::node_type, expr::leaf_total<Args...>>,
                            expr::staging::proof>;
    static_assert(nf::complete && ng::complete,
                  "ctga: identical<>: an expression is too large to expand (maximum degree or expansion budget)");
    constexpr auto& a = nf::terms;
    constexpr auto& b = ng::terms;
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!expr::same_monomial(a[i], b[i]) || !(a[i].c == b[i].c)) return false;
    return true;
}

}  // namespace ctga
