// The derivative of an expression with respect to one number of one leaf, as an expression.
//
// Every node of the engine is polynomial in its leaves' components: products are bilinear, maps
// and scalings linear, sums additive, constants constant (nodes.hpp; there is no division, root
// or transcendental node). So the partial derivative with respect to component j of leaf ℓ is
// again a node tree over the same leaves, built by the rules of a derivation:
//
//   ∂ leaf ℓ        = the blade component j stands on (signs[j] · masks[j]); any other leaf: 0
//   ∂ constant      = 0
//   ∂ (x ∘ y)       = (∂x) ∘ y + x ∘ (∂y)      for every bilinear product ∘ (Leibniz)
//   ∂ f(x)          = f(∂x)                    for a linear blade rule f (reversion, dual, lift…)
//   ∂ (x ± y)       = ∂x ± ∂y,   ∂ (q x) = q ∂x
//
// with zero pruned at the type level (a product with a zero factor is zero, x + 0 is x). The
// result is an ordinary node: its normal form, the structural zeros of its value (node_layout),
// its staging and its straight-line program are the engine's, exactly as for the expression it
// came from. ctga::jacobian (operations/jacobian.hpp) evaluates one such node per column.
//
// One rewriting makes the columns share work. For an associative product (geometric, exterior)
// whose left factor is itself a product x = a ∘ b with b free of the variable,
//   ∂(a ∘ b) ∘ y = (∂a ∘ b) ∘ y = ∂a ∘ (b ∘ y),
// and b ∘ y is then the same node in every column: ctga::jacobian computes it once (run.hpp,
// shared units) and each column multiplies only the sparse ∂a into it. The mirror image holds on
// the right: x ∘ ∂(a ∘ b) = (x ∘ a) ∘ ∂b when a is free of the variable. For (g ḡ) N (g ḡ)*,
// ∂[(G N) G*] = ∂G (N G*) + (G N) ∂G*: two products of the 15-blade ∂G per column, where
// (∂G N) G* multiplied a 64-blade ∂G N by the 64 blades of G*.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include "ctga/algebra/layout.hpp"
#include "ctga/algebra/rules.hpp"
#include "ctga/expr/looped.hpp"
#include "ctga/expr/nodes.hpp"
#include "ctga/expr/rational.hpp"

namespace ctga::expr {

// The zero element: a constant with no blades.
inline constexpr layout<0> no_blades{};
using zero_node = constant<no_blades, std::array<rational, 0>{}>;

template <class N>
inline constexpr bool is_zero_node = std::is_same_v<N, zero_node>;

namespace derivative_detail {

// ∂(component j of a leaf with layout L) = signs[j] · blade(masks[j]): the unit constant on that
// component's blade, in the leaf's own orientation.
template <auto L, std::size_t J>
inline constexpr layout<1> component_blade{{L.masks[J]}, {L.signs[J]}};
template <auto L, std::size_t J>
using unit_component = constant<component_blade<L, J>, std::array<rational, 1>{{{1, 1}}}>;

// x + S·y with zeros pruned.
template <class X, class Y, int S>
struct add {
    using type = sum<X, Y, S>;
};
template <class Y, int S>
struct add<zero_node, Y, S> {
    using type = std::conditional_t<S == 1, Y, scaled<rational{-1, 1}, Y>>;
};
template <class X, int S>
struct add<X, zero_node, S> {
    using type = X;
};
template <int S>
struct add<zero_node, zero_node, S> {
    using type = zero_node;
};
template <class X, class Y, int S>
using add_t = typename add<X, Y, S>::type;

// Whether a node is a constant: a constant, or linear images and sums of constants (the
// derivative of a leaf, lifted or barred).
template <class N>
constexpr bool constant_node_of();
template <class... C>
constexpr bool all_constant(type_list<C...>) {
    return (constant_node_of<C>() && ...);
}
template <class N>
constexpr bool constant_node_of() {
    using shape = shape_for<walker::is_constant, N>;
    if constexpr (shape::kind == node_kind::constant) return true;
    else if constexpr (shape::kind == node_kind::map || shape::kind == node_kind::scaled || shape::kind == node_kind::sum)
        return all_constant(typename shape::children{});
    else return false;
}
template <class N>
inline constexpr bool constant_node = constant_node_of<N>();

// The product node P<R, X, Y> (product or looped), zero when a factor is. A product with a
// constant factor (a leaf's derivative: one blade, or a few) stays symbolic whatever P is: its
// terms are signed copies of the other factor's components, with no multiplication to loop over.
template <template <class, class, class> class P, class R, class X, class Y>
using times_t = std::conditional_t<is_zero_node<X> || is_zero_node<Y>, zero_node,
                                   std::conditional_t<constant_node<X> || constant_node<Y>, product<R, X, Y>, P<R, X, Y>>>;

}  // namespace derivative_detail

// ∂N/∂(component Comp of leaf Leaf): one rule per node kind (nodes.hpp), below.
template <class N, std::size_t Leaf, std::size_t Comp>
struct derive;
template <class N, std::size_t Leaf, std::size_t Comp>
using derive_t = typename derive<N, Leaf, Comp>::type;

namespace derivative_detail {

// (x ∘ y) ∘ z = x ∘ (y ∘ z) for every blade triple: the geometric and exterior products.
template <class Rule>
inline constexpr bool associative = false;
template <class Alg>
inline constexpr bool associative<rules::geometric<Alg>> = true;
template <class Alg>
inline constexpr bool associative<rules::exterior<Alg>> = true;

// A product that every column reads unchanged: looped (computed once, shared by the columns) past
// the size at which a program stops being unrolled anyway (run.hpp, unroll_limit), else left to
// the symbolic engine inside each column.
template <class R, class X, class Y>
using shared_product_t =
    std::conditional_t<(surviving_pairs<R, operand_layout<X>, operand_layout<Y>>(64) > 64), looped<R, X, Y>, product<R, X, Y>>;

// How a linear blade rule M meets the product R: M(a ∘ b) = M(a) ∘ M(b) (an automorphism) or
// M(b) ∘ M(a) (an anti-automorphism). Reversion and Clifford conjugation reverse the geometric
// and exterior products, the grade involution keeps them, and so does a permutation of the
// generators that keeps their squares (the paper's bar, §5).
enum class morphism { none, automorphism, anti };
template <class M, class R>
inline constexpr morphism morphism_of = morphism::none;
template <class Alg, template <class> class R>
    requires(associative<R<Alg>>)
inline constexpr morphism morphism_of<rules::reverse<Alg>, R<Alg>> = morphism::anti;
template <class Alg, template <class> class R>
    requires(associative<R<Alg>>)
inline constexpr morphism morphism_of<rules::conjugate<Alg>, R<Alg>> = morphism::anti;
template <class Alg, template <class> class R>
    requires(associative<R<Alg>>)
inline constexpr morphism morphism_of<rules::involute<Alg>, R<Alg>> = morphism::automorphism;
template <class Alg, std::array<int, Alg::dimension> Perm, template <class> class R>
    requires(associative<R<Alg>>)
inline constexpr morphism morphism_of<rules::permutation<Alg, Perm>, R<Alg>> = [] {
    for (std::size_t i = 0; i < Alg::dimension; ++i) {
        const blade_mask from = blade_mask{1} << i, to = blade_mask{1} << Perm[i];
        if (((Alg::null_mask & from) != 0) != ((Alg::null_mask & to) != 0) ||
            ((Alg::negative_mask & from) != 0) != ((Alg::negative_mask & to) != 0))
            return morphism::none;
    }
    return morphism::automorphism;
}();

// The two factors of X as a product of rule R, if it is one: a product or looped node, or the
// image of one under a linear rule that is a morphism of R (conj(a ∘ b) = conj(b) ∘ conj(a)).
// `node` builds a product of two factors of the same kind.
template <class R, class X>
struct factors_of {
    static constexpr bool is = false;
};
template <class A, class B, template <class, class, class> class P>
struct two_factors {
    static constexpr bool is = true;
    using left = A;
    using right = B;
    template <class R2, class L, class Q>
    using node = P<R2, L, Q>;
};
template <class R, class A, class B>
struct factors_of<R, product<R, A, B>> : two_factors<A, B, product> {};
template <class R, class A, class B>
struct factors_of<R, looped<R, A, B>> : two_factors<A, B, looped> {};
template <class R, class M, class X>
    requires(factors_of<R, X>::is && morphism_of<M, R> != morphism::none)
struct factors_of<R, map<M, X>> {
    static constexpr bool is = true;
    static constexpr bool anti = morphism_of<M, R> == morphism::anti;
    using left = map<M, std::conditional_t<anti, typename factors_of<R, X>::right, typename factors_of<R, X>::left>>;
    using right = map<M, std::conditional_t<anti, typename factors_of<R, X>::left, typename factors_of<R, X>::right>>;
    template <class R2, class L, class Q>
    using node = typename factors_of<R, X>::template node<R2, L, Q>;
};

template <class X, std::size_t Leaf, std::size_t Comp>
inline constexpr bool constant_in = is_zero_node<derive_t<X, Leaf, Comp>>;

template <template <class, class, class> class P, class R, class X, class Y, std::size_t Leaf, std::size_t Comp>
constexpr auto left_times();
template <template <class, class, class> class P, class R, class X, class Y, std::size_t Leaf, std::size_t Comp>
constexpr auto right_times();
// ∂a ∘ (b ∘ y), b ∘ y shared (not formed when a is constant)
template <template <class, class, class> class P, class R, class A, class B, class Y, std::size_t Leaf, std::size_t Comp>
constexpr auto left_times_shared() {
    if constexpr (constant_in<A, Leaf, Comp>) return zero_node{};
    else return left_times<P, R, A, shared_product_t<R, B, Y>, Leaf, Comp>();
}
// (x ∘ a) ∘ ∂b, x ∘ a shared (not formed when b is constant)
template <template <class, class, class> class P, class R, class X, class A, class B, std::size_t Leaf, std::size_t Comp>
constexpr auto right_times_shared() {
    if constexpr (constant_in<B, Leaf, Comp>) return zero_node{};
    else return right_times<P, R, shared_product_t<R, X, A>, B, Leaf, Comp>();
}

// ∂x ∘ y as the product node P of rule R. Where x = a ∘ b (R associative),
//   ∂(a ∘ b) ∘ y = ∂a ∘ (b ∘ y) + (a ∘ ∂b) ∘ y,
// b ∘ y the same node in every column; recursively into a.
template <template <class, class, class> class P, class R, class X, class Y, std::size_t Leaf, std::size_t Comp>
constexpr auto left_times() {
    using F = factors_of<R, X>;
    if constexpr (constant_in<X, Leaf, Comp>) {
        return zero_node{};
    } else if constexpr (associative<R> && F::is) {
        using A = typename F::left;
        using B = typename F::right;
        using first = decltype(left_times_shared<P, R, A, B, Y, Leaf, Comp>());
        using second = times_t<P, R, decltype(right_times<F::template node, R, A, B, Leaf, Comp>()), Y>;
        return add_t<first, second, 1>{};
    } else {
        return times_t<P, R, derive_t<X, Leaf, Comp>, Y>{};
    }
}
// x ∘ ∂y, the mirror image: where y = a ∘ b,
//   x ∘ ∂(a ∘ b) = x ∘ (∂a ∘ b) + (x ∘ a) ∘ ∂b,
// x ∘ a the same node in every column; recursively into b.
template <template <class, class, class> class P, class R, class X, class Y, std::size_t Leaf, std::size_t Comp>
constexpr auto right_times() {
    using F = factors_of<R, Y>;
    if constexpr (constant_in<Y, Leaf, Comp>) {
        return zero_node{};
    } else if constexpr (associative<R> && F::is) {
        using A = typename F::left;
        using B = typename F::right;
        using first = times_t<P, R, X, decltype(left_times<F::template node, R, A, B, Leaf, Comp>())>;
        using second = decltype(right_times_shared<P, R, X, A, B, Leaf, Comp>());
        return add_t<first, second, 1>{};
    } else {
        return times_t<P, R, X, derive_t<Y, Leaf, Comp>>{};
    }
}

template <template <class, class, class> class P, class R, class X, class Y, std::size_t Leaf, std::size_t Comp>
using leibniz_t = add_t<decltype(left_times<P, R, X, Y, Leaf, Comp>()), decltype(right_times<P, R, X, Y, Leaf, Comp>()), 1>;

template <template <class, class, class> class P, class R, std::size_t Leaf, std::size_t Comp, class X, class Y>
auto leibniz_of(type_list<X, Y>) -> leibniz_t<P, R, X, Y, Leaf, Comp>;
template <class Shape, std::size_t Leaf, std::size_t Comp, class X>
auto through_linear(type_list<X>) -> std::conditional_t<is_zero_node<derive_t<X, Leaf, Comp>>, zero_node,
                                                        typename Shape::template with<derive_t<X, Leaf, Comp>>>;
template <int S, std::size_t Leaf, std::size_t Comp, class X, class Y>
auto sum_derivative(type_list<X, Y>) -> add_t<derive_t<X, Leaf, Comp>, derive_t<Y, Leaf, Comp>, S>;

}  // namespace derivative_detail

template <class N, std::size_t Leaf, std::size_t Comp>
struct derive {
    static constexpr auto pick() {
        using shape = shape_for<walker::derive, N>;
        using children = typename shape::children;
        if constexpr (shape::kind == node_kind::data_leaf) {
            // ∂ leaf ℓ = the unit constant on component j's blade; any other leaf: 0
            if constexpr (shape::index == Leaf) {
                static_assert(Comp < shape::layout.size(), "ctga::derivative: the leaf has no such component");
                return derivative_detail::unit_component<shape::layout, Comp>{};
            } else {
                return zero_node{};
            }
        } else if constexpr (shape::kind == node_kind::argument) {
            static_assert(shape::kind != node_kind::argument,
                          "ctga::derivative: differentiate a bound formula (its arguments are leaves), not a formula's body");
            return zero_node{};
        } else if constexpr (shape::kind == node_kind::constant) {
            return zero_node{};
        } else if constexpr (shape::kind == node_kind::product) {
            return decltype(derivative_detail::leibniz_of<product, typename shape::rule, Leaf, Comp>(children{})){};
        } else if constexpr (shape::kind == node_kind::looped) {
            return decltype(derivative_detail::leibniz_of<looped, typename shape::rule, Leaf, Comp>(children{})){};
        } else if constexpr (shape::kind == node_kind::map || shape::kind == node_kind::scaled) {
            return decltype(derivative_detail::through_linear<shape, Leaf, Comp>(children{})){};
        } else if constexpr (shape::kind == node_kind::sum) {
            return decltype(derivative_detail::sum_derivative<shape::sign, Leaf, Comp>(children{})){};
        } else {
            static_assert(shape::kind != shape::kind, "ctga::expr::derive: no derivation rule for this node kind");
            return zero_node{};
        }
    }
    using type = decltype(pick());
};

}  // namespace ctga::expr
