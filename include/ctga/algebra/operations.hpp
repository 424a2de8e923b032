// The operations of the algebra. Each builds a lazy expression (expr/expression.hpp) whose
// node is a rule of products.hpp; the whole expression is compiled into one straight-line
// program when it is assigned, evaluated or read.
//
// Operators follow the common geometric-algebra convention:
//   x * y   geometric product          x ^ y   exterior product ∧
//   x & y   shuffle/regressive ∨ (§4)  x | y   left contraction ⌋
//   ~x      reverse                    -x, x + y, x - y, s * x, x * s, x / s, half * x
// C++ gives ^, & and | lower precedence than + and ==: write the paper's A ∨ (N ∧ s) as
// A & (N ^ s), with the parentheses the paper has anyway.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "ctga/algebra/multivector.hpp"
#include "ctga/algebra/products.hpp"
#include "ctga/expr/expression.hpp"
#include "ctga/expr/nodes.hpp"
#include "ctga/expr/program.hpp"

namespace ctga {

// ---- bilinear products -------------------------------------------------------------------

// A bilinear product by a rule of products.hpp, as a function object: gp(x, y), wedge(x, y), …
template <template <class> class Rule>
struct bilinear_product {
    template <operand X, operand Y>
    [[nodiscard]] constexpr auto operator()(X&& x, Y&& y) const noexcept {
        return expr::combine<expr::bilinear<Rule>>(std::forward<X>(x), std::forward<Y>(y));
    }
};
inline constexpr bilinear_product<rules::geometric> gp{};
inline constexpr bilinear_product<rules::exterior> wedge{};
inline constexpr bilinear_product<rules::regressive> vee{};
inline constexpr bilinear_product<rules::left_contraction> left_contraction{};
inline constexpr bilinear_product<rules::right_contraction> right_contraction{};
inline constexpr bilinear_product<rules::scalar> scalar_product{};

template <operand X, operand Y>
[[nodiscard]] constexpr auto operator*(X&& x, Y&& y) noexcept { return gp(std::forward<X>(x), std::forward<Y>(y)); }
template <operand X, operand Y>
[[nodiscard]] constexpr auto operator^(X&& x, Y&& y) noexcept { return wedge(std::forward<X>(x), std::forward<Y>(y)); }
template <operand X, operand Y>
[[nodiscard]] constexpr auto operator&(X&& x, Y&& y) noexcept { return vee(std::forward<X>(x), std::forward<Y>(y)); }
template <operand X, operand Y>
[[nodiscard]] constexpr auto operator|(X&& x, Y&& y) noexcept {
    return left_contraction(std::forward<X>(x), std::forward<Y>(y));
}

template <operand X, operand Y>
[[nodiscard]] constexpr auto operator+(X&& x, Y&& y) noexcept {
    return expr::combine<expr::additive<1>>(std::forward<X>(x), std::forward<Y>(y));
}
template <operand X, operand Y>
[[nodiscard]] constexpr auto operator-(X&& x, Y&& y) noexcept {
    return expr::combine<expr::additive<-1>>(std::forward<X>(x), std::forward<Y>(y));
}

// ---- linear maps -------------------------------------------------------------------------

// A linear blade rule of products.hpp, as a function object: reverse(x), conj(x), …
template <template <class> class Rule>
struct linear_map {
    template <operand X>
    [[nodiscard]] constexpr auto operator()(X&& x) const noexcept {
        return expr::apply_map<Rule>(std::forward<X>(x));
    }
};
inline constexpr linear_map<rules::reverse> reverse{};
inline constexpr linear_map<rules::involute> involute{};
inline constexpr linear_map<rules::conjugate> conj{};  // Clifford conjugation, the paper's x*: g g* = 1 (§3)
inline constexpr linear_map<rules::right_complement> right_complement{};
inline constexpr linear_map<rules::left_complement> left_complement{};

template <operand X>
[[nodiscard]] constexpr auto operator~(X&& x) noexcept { return reverse(std::forward<X>(x)); }
template <int K, operand X>
[[nodiscard]] constexpr auto grade(X&& x) noexcept {
    return expr::apply_map<rules::grade_projection_of<K>::template rule>(std::forward<X>(x));
}
template <operand X>
[[nodiscard]] constexpr auto operator-(X&& x) noexcept {
    return expr::apply_scale<expr::rational{-1, 1}>(std::forward<X>(x));
}

// The algebra automorphism sending generator i to generator Images...[i]. It is one only when
// each generator goes to a generator with the same square; anything else is rejected.
template <int... Images, operand X>
[[nodiscard]] constexpr auto automorphism(X&& x) noexcept {
    using alg = typename std::remove_cvref_t<X>::algebra_type;
    static_assert(sizeof...(Images) == alg::dimension, "ctga: an automorphism needs exactly one image per generator");
    if constexpr (sizeof...(Images) == alg::dimension) {
        constexpr std::array<int, alg::dimension> perm{Images...};
        constexpr bool permutation = [&] {
            std::array<bool, alg::dimension> hit{};
            for (int p : perm) {
                if (p < 0 || p >= static_cast<int>(alg::dimension) || hit[p]) return false;
                hit[p] = true;
            }
            return true;
        }();
        static_assert(permutation, "ctga: the automorphism's images are not a permutation of the generators");
        constexpr bool squares_kept = [&] {
            if (!permutation) return true;
            for (std::size_t i = 0; i < alg::dimension; ++i)
                if (alg::squares[i] != alg::squares[perm[i]]) return false;
            return true;
        }();
        static_assert(squares_kept, "ctga: the automorphism maps a generator to one with a different square");
        if constexpr (permutation && squares_kept)
            return expr::apply_map<rules::permutation_of<perm>::template rule>(std::forward<X>(x));
    }
}

// The paper's bar involution (§5) on a doubled algebra: generator i ↔ generator i + n/2
// (in Cl(0,6,2): ai ↔ ei, a ↔ e).
template <operand X>
[[nodiscard]] constexpr auto bar(X&& x) noexcept {
    constexpr std::size_t n = std::remove_cvref_t<X>::algebra_type::dimension;
    static_assert(n % 2 == 0, "ctga: bar needs a doubled algebra (an even number of generators)");
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return automorphism<static_cast<int>((I + n / 2) % n)...>(std::forward<X>(x));
    }(std::make_index_sequence<n>{});
}

// The coefficient of one blade (named as written) as a scalar expression.
template <fixed_string Name, operand X>
[[nodiscard]] constexpr auto coeff(X&& x) noexcept {
    using alg = typename std::remove_cvref_t<X>::algebra_type;
    using b = detail::blade_of<alg, Name>;
    return expr::apply_map<rules::coefficient_of<b::mask, b::sign>::template rule>(std::forward<X>(x));
}

// ---- scalars -----------------------------------------------------------------------------

namespace detail {
template <class S, class X>
concept runtime_scalar_for =
    !operand<S> && !is_rational_v<std::remove_cvref_t<S>> &&
    (std::is_void_v<typename std::remove_cvref_t<X>::scalar_type> ||
     std::convertible_to<S, typename std::remove_cvref_t<X>::scalar_type>);

template <class S, class X>
using scalar_of = std::conditional_t<std::is_void_v<typename std::remove_cvref_t<X>::scalar_type>, std::remove_cvref_t<S>,
                                     typename std::remove_cvref_t<X>::scalar_type>;

template <class X, class S>
constexpr auto scalar_operand(const S& s) noexcept {
    using T = scalar_of<S, X>;
    return expr::scalar_expression<typename std::remove_cvref_t<X>::algebra_type, T>(static_cast<T>(s));
}
}  // namespace detail

template <class S, operand X>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator*(const S& s, X&& x) noexcept {
    return detail::scalar_operand<X>(s) * std::forward<X>(x);
}
template <operand X, class S>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator*(X&& x, const S& s) noexcept {
    return std::forward<X>(x) * detail::scalar_operand<X>(s);
}
template <operand X, class S>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator/(X&& x, const S& s) noexcept {
    using T = detail::scalar_of<S, X>;
    return std::forward<X>(x) * detail::scalar_operand<X>(T(1) / static_cast<T>(s));
}
template <operand X, class S>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator+(X&& x, const S& s) noexcept {
    return std::forward<X>(x) + detail::scalar_operand<X>(s);
}
template <class S, operand X>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator+(const S& s, X&& x) noexcept {
    return detail::scalar_operand<X>(s) + std::forward<X>(x);
}
template <operand X, class S>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator-(X&& x, const S& s) noexcept {
    return std::forward<X>(x) - detail::scalar_operand<X>(s);
}
template <class S, operand X>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator-(const S& s, X&& x) noexcept {
    return detail::scalar_operand<X>(s) - std::forward<X>(x);
}

// Exact rational factors: half * (s1 * s2 − s2 * s1).
template <std::int64_t N, std::int64_t D, operand X>
[[nodiscard]] constexpr auto operator*(q<N, D>, X&& x) noexcept {
    return expr::apply_scale<q<N, D>::value>(std::forward<X>(x));
}
template <operand X, std::int64_t N, std::int64_t D>
[[nodiscard]] constexpr auto operator*(X&& x, q<N, D>) noexcept {
    return expr::apply_scale<q<N, D>::value>(std::forward<X>(x));
}

// ---- evaluation --------------------------------------------------------------------------

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
        return result(detail::from_components_t{}, x.template evaluate<U, D::layout>());
    }
}

// Keep only the blades of Target (a multivector type), dropping the rest on purpose; only the
// kept components are computed.
template <multivector_type Target, operand X>
[[nodiscard]] constexpr Target project(const X& x) noexcept {
    const auto e = expr::as_expression(x);
    return Target(detail::from_components_t{}, e.template evaluate<typename Target::scalar_type, Target::layout>());
}

// A multivector from an expression: every blade the expression can make non-zero must be in
// the type (a compile error names the first that is not). Only the type's components are
// computed.
template <class Alg, class T, auto Layout>
template <class T2, class Node, class Leaves>
CTGA_ALWAYS_INLINE constexpr multivector<Alg, T, Layout>::multivector(const expression<Alg, T2, Node, Leaves>& e) noexcept {
    static_assert(std::is_void_v<T2> || std::is_same_v<T, T2>,
                  "ctga: the expression's scalar type differs from the multivector's");
    constexpr int missing = detail::first_missing<expression<Alg, T2, Node, Leaves>::layout, Layout>();
    if constexpr (missing >= 0) {
        (void)sizeof(detail::target_lacks<Alg, expression<Alg, T2, Node, Leaves>::layout.masks[missing]>);
    } else {
        c_ = e.template evaluate<T, Layout>();
    }
}

template <class Alg, class T, auto Layout>
template <auto L2>
constexpr multivector<Alg, T, Layout>::multivector(const multivector<Alg, T, L2>& x) noexcept
    : multivector(expr::as_expression(x)) {}

// The coefficient of a blade named as written, computing that component only.
template <fixed_string Name, class Alg, class T, class Node, class Leaves>
[[nodiscard]] constexpr auto get(const expression<Alg, T, Node, Leaves>& e) noexcept {
    return e.template get<Name>();
}

// The scalar (grade-0) coefficient.
template <operand X>
[[nodiscard]] constexpr auto scalar_part(const X& x) noexcept { return x.template get<"1">(); }

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

// ---- formulas, costs, proofs ---------------------------------------------------------------

namespace expr {
// Argument I of a formula whose I-th argument has type A.
template <std::size_t I, class A>
constexpr auto placeholder() noexcept {
    using D = std::remove_cvref_t<A>;
    return make_expression<typename D::algebra_type, typename D::scalar_type, arg<I, D::layout>>(boost::hana::make_tuple());
}

template <class F, class... Args>
constexpr auto call_with_placeholders(const F& f) noexcept {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return f(placeholder<I, std::tuple_element_t<I, std::tuple<Args...>>>()...);
    }(std::index_sequence_for<Args...>{});
}
template <class F, class... Args>
using formula_result = decltype(call_with_placeholders<F, Args...>(std::declval<const F&>()));
}  // namespace expr

// An expression with named arguments: f(args...) is a lazy expression in which each argument
// is one leaf wherever the formula uses it, so the normal form sees repeated arguments cancel.
template <class F>
struct formula_t {
    F f;

    template <operand... Args>
    [[nodiscard]] constexpr auto operator()(Args&&... args) const noexcept {
        auto body = expr::call_with_placeholders<F, Args...>(f);
        using B = decltype(body);
        using first = std::remove_cvref_t<std::tuple_element_t<0, std::tuple<Args...>>>;
        using node = expr::bind_t<typename B::node_type, sizeof...(Args)>;
        auto arg_leaves = boost::hana::make_tuple([&]<class A>(A&& a) {
            using D = std::remove_cvref_t<A>;
            if constexpr (std::is_lvalue_reference_v<A>) return expr::ref_leaf<D>{&a};
            else return expr::value_leaf<D>{std::move(a)};
        }(std::forward<Args>(args))...);
        // the body's algebra: arguments may come from a subalgebra it embeds (ctga::lift)
        return expr::make_expression<typename B::algebra_type, typename first::scalar_type, node>(
            boost::hana::concat(std::move(arg_leaves), std::move(body.leaves)));
    }
};

template <class F>
[[nodiscard]] constexpr formula_t<F> formula(F f) noexcept {
    return {f};
}

// Multiplications and additions of the code an expression type runs when evaluated into
// Target's blades (its own canonical blades by default), intermediates included.
template <class E, class Target = void>
inline constexpr expr::cost cost_of = [] {
    using D = std::remove_cvref_t<E>;
    if constexpr (std::is_void_v<Target>) return expr::program<typename D::node_type, D::layout>::price;
    else return expr::program<typename D::node_type, Target::layout>::price;
}();

// True when f and g agree for all values of arguments of types Args: their fully expanded
// normal forms are equal term by term. A compile-time proof:
//   static_assert(ctga::identical<screw, screw>(lhs, rhs));
template <class... Args, class F, class G>
[[nodiscard]] consteval bool identical(F, G) {
    using nf = expr::traits<expr::bind_t<typename expr::formula_result<F, Args...>::node_type, sizeof...(Args)>,
                            expr::staging::proof>;
    using ng = expr::traits<expr::bind_t<typename expr::formula_result<G, Args...>::node_type, sizeof...(Args)>,
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
