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
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include "ctga/algebra/layout.hpp"
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

// The product node P<R, X, Y> (product or looped), zero when a factor is.
template <template <class, class, class> class P, class R, class X, class Y>
using times_t = std::conditional_t<is_zero_node<X> || is_zero_node<Y>, zero_node, P<R, X, Y>>;

}  // namespace derivative_detail

// ∂N/∂(component Comp of leaf Leaf).
template <class N, std::size_t Leaf, std::size_t Comp>
struct derive {
    using type = zero_node;  // constants (and the zero element)
};
template <class N, std::size_t Leaf, std::size_t Comp>
using derive_t = typename derive<N, Leaf, Comp>::type;

template <std::size_t I, auto L, std::size_t Leaf, std::size_t Comp>
struct derive<leaf<I, L>, Leaf, Comp> {
    static constexpr auto pick() {
        if constexpr (I == Leaf) {
            static_assert(Comp < L.size(), "ctga::derivative: the leaf has no such component");
            return derivative_detail::unit_component<L, Comp>{};
        } else {
            return zero_node{};
        }
    }
    using type = decltype(pick());
};
template <std::size_t I, auto L, std::size_t Leaf, std::size_t Comp>
struct derive<arg<I, L>, Leaf, Comp> {
    static_assert(I != I, "ctga::derivative: differentiate a bound formula (its arguments are leaves), not a formula's body");
    using type = zero_node;
};
template <class R, class X, class Y, std::size_t Leaf, std::size_t Comp>
struct derive<product<R, X, Y>, Leaf, Comp> {
    using type = derivative_detail::add_t<derivative_detail::times_t<product, R, derive_t<X, Leaf, Comp>, Y>,
                                          derivative_detail::times_t<product, R, X, derive_t<Y, Leaf, Comp>>, 1>;
};
template <class R, class X, class Y, std::size_t Leaf, std::size_t Comp>
struct derive<looped<R, X, Y>, Leaf, Comp> {
    using type = derivative_detail::add_t<derivative_detail::times_t<looped, R, derive_t<X, Leaf, Comp>, Y>,
                                          derivative_detail::times_t<looped, R, X, derive_t<Y, Leaf, Comp>>, 1>;
};
template <class R, class X, std::size_t Leaf, std::size_t Comp>
struct derive<map<R, X>, Leaf, Comp> {
    using dx = derive_t<X, Leaf, Comp>;
    using type = std::conditional_t<is_zero_node<dx>, zero_node, map<R, dx>>;
};
template <class X, class Y, int S, std::size_t Leaf, std::size_t Comp>
struct derive<sum<X, Y, S>, Leaf, Comp> {
    using type = derivative_detail::add_t<derive_t<X, Leaf, Comp>, derive_t<Y, Leaf, Comp>, S>;
};
template <rational Q, class X, std::size_t Leaf, std::size_t Comp>
struct derive<scaled<Q, X>, Leaf, Comp> {
    using dx = derive_t<X, Leaf, Comp>;
    using type = std::conditional_t<is_zero_node<dx>, zero_node, scaled<Q, dx>>;
};

}  // namespace ctga::expr
