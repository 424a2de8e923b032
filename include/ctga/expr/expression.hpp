// Lazy expressions. Every operation of the core on multivectors builds an expression: a
// symbolic node type (nodes.hpp) and the data of its leaves, held in a Boost.Hana tuple
// (a reference to each lvalue operand, a copy of each temporary, runtime scalars by value).
// Nothing is computed until the expression is assigned to a multivector type, a component is
// asked for, or eval() is called; then the whole expression is one straight-line program
// (program.hpp) for exactly the components wanted.
//
// Leaves of a plain expression are numbered left to right: writing s twice gives two leaves, and
// the normal form cannot see that they are equal. A formula names its arguments, so the same
// argument is the same leaf wherever it appears and cancellations across the expression are
// found:
//
//   constexpr auto bracket = ctga::formula([](auto a, auto b) { return ctga::half * (a * b - b * a); });
//   screw r = bracket(s1, s2);      // 18 multiplications, the cross-product form
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <type_traits>
#include <utility>

#include <boost/hana/concat.hpp>
#include <boost/hana/length.hpp>
#include <boost/hana/tuple.hpp>
#include <boost/hana/unpack.hpp>

#include "ctga/algebra/multivector.hpp"
#include "ctga/expr/looped.hpp"
#include "ctga/expr/nodes.hpp"
#include "ctga/expr/program.hpp"
#include "ctga/expr/rational.hpp"
#include "ctga/expr/run.hpp"
#include "ctga/expr/staging.hpp"
#include "ctga/support/inline.hpp"

namespace ctga {

// ---- leaves ---------------------------------------------------------------------------------

namespace expr {

template <class X>
struct ref_leaf {  // an lvalue multivector, by address
    const X* p;
    constexpr const auto* data() const noexcept { return p->data(); }
};
template <class X>
struct value_leaf {  // a temporary multivector, by value
    X v;
    constexpr const auto* data() const noexcept { return v.data(); }
};
template <class T>
struct scalar_leaf {  // a runtime scalar
    T v;
    constexpr const T* data() const noexcept { return &v; }
};

// Renaming the leaves of a node tree: Map::on_leaf<I, L> and Map::on_arg<I, L> give each leaf's
// new node; every other node is rebuilt around its renamed children (nodes.hpp, node_shape). It
// runs on every node of every combination, so it dispatches by partial specialisation on the
// node's kind (one instantiation per node).
template <class N, class Map, node_kind K = node_shape<N>::kind, class Children = typename node_shape<N>::children>
struct relabel;
template <class N, class Map>
using relabel_t = typename relabel<N, Map>::type;
template <class N, class Map, node_kind K, class... C>
struct relabel<N, Map, K, type_list<C...>> {
    using type = typename node_shape<N>::template with<relabel_t<C, Map>...>;
};
template <class N, class Map>
struct relabel<N, Map, node_kind::data_leaf, type_list<>> {
    using type = typename Map::template on_leaf<node_shape<N>::index, node_shape<N>::layout>;
};
template <class N, class Map>
struct relabel<N, Map, node_kind::argument, type_list<>> {
    using type = typename Map::template on_arg<node_shape<N>::index, node_shape<N>::layout>;
};
template <class N, class Map>
struct relabel<N, Map, node_kind::constant, type_list<>> {
    using type = N;
};
template <class N, class Map>
struct relabel<N, Map, node_kind::unknown, type_list<>> : refuse_unknown<walker::relabel, N> {
    using type = N;
};

// Every product of a node tree formed again in mode M (looped or unrolled, as the user forces).
template <class N, product_mode M>
struct reform;
template <class N, product_mode M>
using reform_t = typename reform<N, M>::type;
template <product_mode M>
struct reform_children {
    template <class C>
    using on = reform_t<C, M>;
};
template <class Shape, product_mode M, class X, class Y>
auto reformed_product(type_list<X, Y>) -> product_node<typename Shape::rule, reform_t<X, M>, reform_t<Y, M>, M>;
template <class N, product_mode M>
struct reform {
    static constexpr auto pick() {
        using shape = shape_for<walker::reform, N>;
        if constexpr (shape::kind == node_kind::product || shape::kind == node_kind::looped)
            return decltype(reformed_product<shape, M>(typename shape::children{})){};
        else return rebuild_t<walker::reform, N, reform_children<M>>{};
    }
    using type = decltype(pick());
};

// The right operand of a combination: its data leaves numbered after the left operand's.
template <std::size_t Off>
struct shift_by {
    template <std::size_t I, auto L>
    using on_leaf = leaf<I + Off, L>;
    template <std::size_t I, auto L>
    using on_arg = arg<I, L>;
};
template <class N, std::size_t Off>
using shift_t = relabel_t<N, shift_by<Off>>;

// Binding a formula: argument I becomes leaf I, the formula's own data leaves follow them.
template <std::size_t Arity>
struct bind_arguments {
    template <std::size_t I, auto L>
    using on_leaf = leaf<I + Arity, L>;
    template <std::size_t I, auto L>
    using on_arg = leaf<I, L>;
};
template <class N, std::size_t Arity>
using bind_t = relabel_t<N, bind_arguments<Arity>>;

}  // namespace expr

// ---- the expression type --------------------------------------------------------------------

// T is void for compile-time constants until they meet a runtime value.
template <class Alg, class T, class Node, class Leaves>
class expression {
public:
    using algebra_type = Alg;
    using scalar_type = T;
    using node_type = Node;
    using leaves_type = Leaves;
    static constexpr std::size_t leaf_count = decltype(boost::hana::length(std::declval<Leaves>()))::value;
    // the blades the expression can make non-zero, canonical
    static constexpr auto layout = expr::node_layout<Node>;
    [[nodiscard]] static constexpr std::size_t size() noexcept { return layout.size(); }

    Leaves leaves;

    // The components of target layout TL (blades of the expression outside TL are not computed).
    template <class U, auto TL>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr std::array<U, TL.size()> evaluate() const noexcept {
        return expr::compute<U, Node, TL>(leaf_data<U>().data());
    }
    // Where each leaf's components are (the leaves of programs over this expression's leaves).
    template <class U>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr std::array<const U*, leaf_count> leaf_data() const noexcept {
        return boost::hana::unpack(leaves, [](const auto&... l) { return std::array<const U*, leaf_count>{l.data()...}; });
    }

    // The coefficient of a blade named as written; only that component is computed.
    template <fixed_string Name>
    [[nodiscard]] constexpr auto get() const noexcept {
        using b = detail::blade_of<Alg, Name>;
        constexpr ctga::layout<1> one{{b::mask}, {static_cast<signed char>(b::sign)}};
        using U = std::conditional_t<std::is_void_v<T>, double, T>;
        return evaluate<U, one>()[0];
    }
};

template <class X>
inline constexpr bool is_expression_v = false;
template <class Alg, class T, class N, class L>
inline constexpr bool is_expression_v<expression<Alg, T, N, L>> = true;

template <class X>
concept expression_type = is_expression_v<std::remove_cvref_t<X>>;

template <class X>
concept basis_blade_type = is_basis_blade_v<std::remove_cvref_t<X>>;

// Anything an operator takes as a multivector operand.
template <class X>
concept operand = multivector_type<X> || expression_type<X> || basis_blade_type<X>;

// An exact rational constant: q<1, 2> is the paper's ½.
template <std::int64_t N, std::int64_t D = 1>
struct q {
    static constexpr expr::rational value = expr::make_rational(N, D);
};
inline constexpr q<1, 2> half{};

template <class X>
inline constexpr bool is_rational_v = false;
template <std::int64_t N, std::int64_t D>
inline constexpr bool is_rational_v<q<N, D>> = true;

namespace expr {

template <class Alg, class T, class Node, class Leaves>
constexpr auto make_expression(Leaves leaves) {
    return expression<Alg, T, Node, Leaves>{std::move(leaves)};
}

// An operand as an expression: multivectors become one-leaf expressions, a basis blade an exact
// constant.
template <class X>
constexpr auto as_expression(X&& x) noexcept {
    using D = std::remove_cvref_t<X>;
    if constexpr (expression_type<D>) {
        return D(std::forward<X>(x));
    } else if constexpr (basis_blade_type<D>) {
        return make_expression<typename D::algebra_type, void, constant<D::layout, std::array<rational, 1>{{{1, 1}}}>>(
            boost::hana::make_tuple());
    } else if constexpr (std::is_lvalue_reference_v<X>) {
        return make_expression<typename D::algebra_type, typename D::scalar_type, leaf<0, D::layout>>(
            boost::hana::make_tuple(ref_leaf<D>{&x}));
    } else {
        return make_expression<typename D::algebra_type, typename D::scalar_type, leaf<0, D::layout>>(
            boost::hana::make_tuple(value_leaf<D>{std::move(x)}));
    }
}

template <class TX, class TY>
using common_scalar = std::conditional_t<std::is_void_v<TX>, TY, TX>;

template <class EX, class EY>
constexpr void check_operands() {
    static_assert(std::is_same_v<typename EX::algebra_type, typename EY::algebra_type>,
                  "ctga: the operands belong to different algebras");
    static_assert(std::is_void_v<typename EX::scalar_type> || std::is_void_v<typename EY::scalar_type> ||
                      std::is_same_v<typename EX::scalar_type, typename EY::scalar_type>,
                  "ctga: the operands have different scalar types; convert one explicitly");
}

// Node formers: what x ∘ y becomes, given the algebra and the operands' nodes. A product is
// unrolled or looped by the number of its blade pairs (looped.hpp), unless forced.
template <template <class> class Rule, product_mode Mode = product_mode::by_threshold>
struct bilinear {
    template <class Alg, class NX, class NY>
    using node = product_node<Rule<Alg>, NX, NY, Mode>;
};
template <int S>
struct additive {
    template <class Alg, class NX, class NY>
    using node = sum<NX, NY, S>;
};

// x ∘ y: the right operand's leaves are renumbered after the left's.
template <class Former, class X, class Y>
constexpr auto combine(X&& x, Y&& y) noexcept {
    auto ex = as_expression(std::forward<X>(x));
    auto ey = as_expression(std::forward<Y>(y));
    using EX = decltype(ex);
    using EY = decltype(ey);
    check_operands<EX, EY>();
    using alg = typename EX::algebra_type;
    using node = typename Former::template node<alg, typename EX::node_type, shift_t<typename EY::node_type, EX::leaf_count>>;
    return make_expression<alg, common_scalar<typename EX::scalar_type, typename EY::scalar_type>, node>(
        boost::hana::concat(std::move(ex.leaves), std::move(ey.leaves)));
}

// A linear blade rule (Rule<Alg>) on x; the result lives in Target (x's own algebra by
// default; another one for an embedding of x's algebra into a larger one).
template <template <class> class Rule, class Target = void, class X>
constexpr auto apply_map(X&& x) noexcept {
    auto ex = as_expression(std::forward<X>(x));
    using EX = decltype(ex);
    using alg = typename EX::algebra_type;
    using target = std::conditional_t<std::is_void_v<Target>, alg, Target>;
    return make_expression<target, typename EX::scalar_type, map<Rule<alg>, typename EX::node_type>>(std::move(ex.leaves));
}

// x with every product formed in mode M.
template <product_mode M, class X>
constexpr auto in_mode(X&& x) noexcept {
    auto ex = as_expression(std::forward<X>(x));
    using EX = decltype(ex);
    return make_expression<typename EX::algebra_type, typename EX::scalar_type, reform_t<typename EX::node_type, M>>(
        std::move(ex.leaves));
}

template <rational Q, class X>
constexpr auto apply_scale(X&& x) noexcept {
    auto ex = as_expression(std::forward<X>(x));
    using EX = decltype(ex);
    return make_expression<typename EX::algebra_type, typename EX::scalar_type, scaled<Q, typename EX::node_type>>(
        std::move(ex.leaves));
}

// A runtime scalar as a one-leaf expression of the scalar blade.
inline constexpr layout<1> scalar_blade{{0}, {1}};

template <class Alg, class T>
constexpr auto scalar_expression(const T& value) noexcept {
    return make_expression<Alg, T, leaf<0, scalar_blade>>(boost::hana::make_tuple(scalar_leaf<T>{value}));
}

}  // namespace expr

}  // namespace ctga
