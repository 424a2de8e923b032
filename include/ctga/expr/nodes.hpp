// Expression nodes as types. A lazy expression's type records its node tree; staging.hpp gives
// each node type its normal form (normal_form.hpp), computed once by the compiler.
//
//   arg<I, L>           argument I of a formula: the same I is the same leaf wherever it appears
//   leaf<I, L>          the I-th data leaf of a plain expression (a multivector or a scalar)
//   constant<L, C>      a compile-time constant (the paper's A, E, Q0), exact coefficients C
//   product<Rule, X, Y> a bilinear product        map<Rule, X>  a linear blade rule
//   sum<X, Y, S>        X + S·Y (S = ±1)          scaled<Q, X>  Q·X, Q an exact rational
//   looped<Rule, X, Y>  a bilinear product past the unrolling threshold: X and Y evaluated on
//                       their own, then one loop over a table of surviving blade pairs (looped.hpp)
//
// Each node kind is described once, by its node_shape below: what it is (node_kind), its
// children, and how it is rebuilt around other children. Every walker of a node tree (renaming
// leaves, re-forming products, finding looped products, differentiating, reading an operand in
// place) goes through node_shape, so a new node kind is added here, in one place, and a walker
// that meets a type without a shape stops with a compile error naming the walker and the type.
#pragma once

#include <cstddef>

#include "ctga/expr/rational.hpp"

namespace ctga::expr {

template <std::size_t I, auto L>
struct arg {};
template <std::size_t I, auto L>
struct leaf {};
template <auto L, auto C>
struct constant {};
template <class Rule, class X, class Y>
struct product {};
template <class Rule, class X, class Y>
struct looped {};
template <class Rule, class X>
struct map {};
template <class X, class Y, int S>
struct sum {};
template <rational Q, class X>
struct scaled {};

template <class... Ts>
struct type_list {};
template <class... A, class... B>
constexpr type_list<A..., B...> operator+(type_list<A...>, type_list<B...>) {
    return {};
}

// ---- the shape of each node kind ------------------------------------------------------------

// What a node is, as far as a walker needs to know: which operands it reads (children), and how
// its value depends on them. The derivative rules (derivative.hpp) are per kind: a bilinear
// product obeys Leibniz, a linear map and a scaling pass through, a sum adds.
enum class node_kind {
    unknown,   // not a node: a type without a node_shape
    argument,  // arg: a formula's argument (bound to a data leaf before anything runs)
    data_leaf, // leaf: a multivector's or a scalar's storage
    constant,  // constant: exact coefficients, no data
    product,   // product: bilinear, multiplied out symbolically
    looped,    // looped: bilinear, run as a loop over a table of blade pairs
    map,       // map: a linear blade rule
    sum,       // sum: X ± Y
    scaled,    // scaled: an exact rational times X
};

// The primary template describes nothing: a type without a specialisation is not a node.
template <class N>
struct node_shape {
    static constexpr bool known = false;
    static constexpr node_kind kind = node_kind::unknown;
    using children = type_list<>;
};
// arg and leaf: operand I, of layout L
template <node_kind Kind, std::size_t I, auto L>
struct leaf_shape {
    static constexpr bool known = true;
    static constexpr node_kind kind = Kind;
    static constexpr std::size_t index = I;
    static constexpr auto layout = L;
    using children = type_list<>;
};
template <std::size_t I, auto L>
struct node_shape<arg<I, L>> : leaf_shape<node_kind::argument, I, L> {};
template <std::size_t I, auto L>
struct node_shape<leaf<I, L>> : leaf_shape<node_kind::data_leaf, I, L> {};
template <auto L, auto C>
struct node_shape<constant<L, C>> {
    static constexpr bool known = true;
    static constexpr node_kind kind = node_kind::constant;
    using children = type_list<>;
};
// product and looped: a bilinear rule's two operands, P the node template of the kind
template <node_kind Kind, template <class, class, class> class P, class Rule, class X, class Y>
struct bilinear_shape {
    static constexpr bool known = true;
    static constexpr node_kind kind = Kind;
    using rule = Rule;
    using children = type_list<X, Y>;
    template <class A, class B>
    using with = P<Rule, A, B>;
};
template <class Rule, class X, class Y>
struct node_shape<product<Rule, X, Y>> : bilinear_shape<node_kind::product, product, Rule, X, Y> {};
template <class Rule, class X, class Y>
struct node_shape<looped<Rule, X, Y>> : bilinear_shape<node_kind::looped, looped, Rule, X, Y> {};
template <class Rule, class X>
struct node_shape<map<Rule, X>> {
    static constexpr bool known = true;
    static constexpr node_kind kind = node_kind::map;
    using rule = Rule;
    using children = type_list<X>;
    template <class A>
    using with = map<Rule, A>;
};
template <class X, class Y, int S>
struct node_shape<sum<X, Y, S>> {
    static constexpr bool known = true;
    static constexpr node_kind kind = node_kind::sum;
    static constexpr int sign = S;
    using children = type_list<X, Y>;
    template <class A, class B>
    using with = sum<A, B, S>;
};
template <rational Q, class X>
struct node_shape<scaled<Q, X>> {
    static constexpr bool known = true;
    static constexpr node_kind kind = node_kind::scaled;
    static constexpr rational factor = Q;
    using children = type_list<X>;
    template <class A>
    using with = scaled<Q, A>;
};

// A walker that meets a type that is not a node kind stops here: Walker is a tag type named after
// the walker, and the compiler's note names both (refuse_unknown<the walker, the type>).
template <class Walker, class N, bool Known = node_shape<N>::known>
struct refuse_unknown {};
template <class Walker, class N>
struct refuse_unknown<Walker, N, false> {
    static_assert(node_shape<N>::known,
                  "ctga::expr: a node-tree walker (the first argument of refuse_unknown) met a type that is not a "
                  "node kind (the second): describe the new kind by a node_shape in expr/nodes.hpp");
};

// Node N as the walker Walker sees it: its shape, a type that is not a node kind refused. The
// walkers that run on every node of every expression (relabel, looped_nodes) dispatch instead by
// partial specialisation on node_shape<N>::kind, their node_kind::unknown case refused the same way.
template <class Walker, class N>
struct shape_for : node_shape<N>, refuse_unknown<Walker, N> {};

// The walkers, as tags for shape_for and refuse_unknown.
namespace walker {
struct relabel {};
struct reform {};
struct looped_nodes {};
struct derive {};
struct read_operand {};
struct is_constant {};
struct normal_form {};
}  // namespace walker

// N with each child C replaced by F::template on<C> (N itself when it has no children).
template <class Walker, class N, class F, class Children = typename shape_for<Walker, N>::children>
struct rebuild;
template <class Walker, class N, class F>
struct rebuild<Walker, N, F, type_list<>> {
    using type = N;
};
template <class Walker, class N, class F, class... C>
    requires(sizeof...(C) > 0)
struct rebuild<Walker, N, F, type_list<C...>> {
    using type = typename node_shape<N>::template with<typename F::template on<C>...>;
};
template <class Walker, class N, class F>
using rebuild_t = typename rebuild<Walker, N, F>::type;

}  // namespace ctga::expr
