// Several values over the same leaves that read the same looped products: a Jacobian's columns
// (expr/derivative.hpp builds each column as a differentiated tree; operations/jacobian.hpp runs
// them). Each looped product the trees read, at any depth, and each operand of one that is not a
// leaf, is a *unit*: computed once (identified by its structural hash), an operand before the
// products that read it, and every column's program then reads the units as leaves. A column that
// is a sum of looped products accumulates them into one table over the blades (looped.hpp).
//
// Only the Jacobian machinery includes this header: evaluating an expression (run.hpp) does not
// parse the derivative rules.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "ctga/expr/derivative.hpp"
#include "ctga/expr/looped.hpp"
#include "ctga/expr/program.hpp"
#include "ctga/expr/run.hpp"
#include "ctga/support/inline.hpp"

namespace ctga::expr {

template <class L>
struct looped_units;
template <class List>
struct units_of_list;
template <class... Ls>
struct units_of_list<type_list<Ls...>> {
    using type = decltype((type_list<>{} + ... + typename looped_units<Ls>::type{}));
};
// the units a tree's program reads
template <class Tree>
using tree_units = typename units_of_list<looped_nodes_t<Tree>>::type;

// An operand that is a product whose program would run as a loop over its terms anyway (past
// unroll_limit) is computed as a looped product when that costs no more pairs than the program
// has terms: the table loop (or block product) runs about twice as fast per pair as the
// program's loop per term (G N of the moved inertia: 0.65 µs against 1.4 µs). Its factors are
// then units of their own, and its value is read into its own (symbolic) layout.
template <class X>
inline constexpr bool loop_as_unit = false;
template <class R, class A, class B>
inline constexpr bool loop_as_unit<product<R, A, B>> = [] {
    using P = program<product<R, A, B>, node_layout<product<R, A, B>>>;
    return P::terms.size() > unroll_limit && rows_of<R, A, B>::pairs <= 2 * P::terms.size();
}();

template <class R, class A, class B>
constexpr auto factor_units(product<R, A, B>*);
template <class X>
constexpr auto operand_units() {
    if constexpr (read_in_place<X>) return type_list<>{};
    else if constexpr (is_looped_node<X>) return typename looped_units<X>::type{};
    else if constexpr (loop_as_unit<X>) return factor_units(static_cast<X*>(nullptr)) + type_list<X>{};
    else return tree_units<X>{} + type_list<X>{};
}
template <class R, class A, class B>
constexpr auto factor_units(product<R, A, B>*) {
    return operand_units<A>() + operand_units<B>();
}
template <class R, class X, class Y>
struct looped_units<looped<R, X, Y>> {
    using type = decltype(operand_units<X>() + operand_units<Y>() + type_list<looped<R, X, Y>>{});
};

template <class Units, class Node>
inline constexpr std::size_t unit_index = [] {
    constexpr auto& hashes = hash_list<Units>::value;
    for (std::size_t i = 0; i < hashes.size(); ++i)
        if (hashes[i] == traits<Node>::hash) return i;
    return hashes.size();
}();

template <class U, class Units>
struct unit_store;
template <class U, class... Us>
struct unit_store<U, type_list<Us...>> {
    using type = std::tuple<std::array<U, node_layout<Us>.size()>...>;
};

// An operand's values: a leaf in place, any other operand from its unit.
template <class U, class Units, class X, class Store>
CTGA_ALWAYS_INLINE constexpr const U* unit_operand(const U* const* leaves, const Store& store) noexcept {
    if constexpr (read_in_place<X>) return leaves[leaf_index<X>()];
    else {
        static_assert(unit_index<Units, X> < std::tuple_size_v<Store>, "ctga: an operand missing from the shared units");
        return std::get<unit_index<Units, X>>(store).data();
    }
}

// Program P on the leaves, its looped products read from their units; unrolled up to Inline terms.
template <class U, class Units, class P, std::size_t N, std::size_t Inline, class Store, class... Ls>
constexpr std::array<U, N> run_with_units(const U* const* leaves, const Store& store, type_list<Ls...>) noexcept {
    std::array<const U*, P::leaf_base + sizeof...(Ls)> all{};
    for (std::size_t i = 0; i < P::leaf_base; ++i) all[i] = leaves[i];
    [[maybe_unused]] std::size_t k = P::leaf_base;
    ((all[k++] = unit_operand<U, Units, Ls>(leaves, store)), ...);
    if constexpr (P::terms.size() <= Inline) return run<U, P, N>(all.data());
    else return run_interpreted<U, P, N>(all.data());
}

// ---- a sum with looped products in it ------------------------------------------------------
//
// A Jacobian's column is a sum of products (expr/derivative.hpp), the large ones looped. Its
// looped products accumulate into one table over the blades, read once into the target layout,
// instead of each product's own table and a program adding their results; the rest of the sum
// (products with a constant factor, which are signed copies) is one program, added at the end.
template <int Sign, class L>
struct signed_looped {};
template <int S, class L>
auto negated_term(signed_looped<S, L>) -> signed_looped<-S, L>;
template <class... Ts>
auto negated(type_list<Ts...>) -> type_list<decltype(negated_term(Ts{}))...>;

// N = Σ ± looped products + rest (rest a node, or the zero node).
template <class N>
struct split_sum {
    using looped_terms = type_list<>;
    using rest = N;
};
template <class R, class X, class Y>
struct split_sum<looped<R, X, Y>> {
    using looped_terms = type_list<signed_looped<1, looped<R, X, Y>>>;
    using rest = zero_node;
};
template <class A, class B, int S>
struct split_sum<sum<A, B, S>> {
    using b_terms = typename split_sum<B>::looped_terms;
    using looped_terms =
        decltype(typename split_sum<A>::looped_terms{} + std::conditional_t<S == 1, b_terms, decltype(negated(b_terms{}))>{});
    using rest = derivative_detail::add_t<typename split_sum<A>::rest, typename split_sum<B>::rest, S>;
};
template <class X>
struct split_sum<scaled<rational{-1, 1}, X>> {
    using looped_terms = decltype(negated(typename split_sum<X>::looped_terms{}));
    using rest = derivative_detail::add_t<zero_node, typename split_sum<X>::rest, -1>;
};

// The accumulators' size: the largest universe of the products, as they run (swapped or not).
template <int S, class R, class X, class Y>
constexpr std::size_t term_universe(signed_looped<S, looped<R, X, Y>>) {
    constexpr auto LX = operand_layout<X>;
    constexpr auto LY = operand_layout<Y>;
    if constexpr (run_swapped<R, LX, LY>) return pair_rows<R, swapped_layout<R, LX>, swapped_layout<R, LY>>::universe;
    else return pair_rows<R, LX, LY>::universe;
}
template <int S, class R, class X, class Y>
constexpr bool term_swapped(signed_looped<S, looped<R, X, Y>>) {
    return run_swapped<R, operand_layout<X>, operand_layout<Y>>;
}
template <int S, class R, class X, class Y>
auto term_rule(signed_looped<S, looped<R, X, Y>>) -> R;
// the rule of the first term that runs swapped (the swap depends only on its algebra)
template <class T0, class... Ts>
auto swapped_rule(type_list<T0, Ts...>) {
    if constexpr (term_swapped(T0{}) || sizeof...(Ts) == 0) return decltype(term_rule(T0{})){};
    else return swapped_rule(type_list<Ts...>{});
}

// the units the sum reads: its looped products' operands, and the rest's
template <int... S, class... R, class... X, class... Y>
constexpr auto sum_operand_units(type_list<signed_looped<S, looped<R, X, Y>>...>) {
    return (type_list<>{} + ... + (operand_units<X>() + operand_units<Y>()));
}
template <class Root>
constexpr auto root_units() {
    using split = split_sum<Root>;
    if constexpr (is_zero_node<typename split::rest>) return sum_operand_units(typename split::looped_terms{});
    else return sum_operand_units(typename split::looped_terms{}) + tree_units<typename split::rest>{};
}

template <class U, class Units, class Store, int S, class R, class X, class Y>
CTGA_ALWAYS_INLINE constexpr void accumulate_looped(U* acc, U* swapped, const U* const* leaves, const Store& store,
                                                    signed_looped<S, looped<R, X, Y>>) noexcept {
    run_product_into<U, R, operand_layout<X>, operand_layout<Y>, (S < 0)>(acc, swapped, unit_operand<U, Units, X>(leaves, store),
                                                                        unit_operand<U, Units, Y>(leaves, store));
}
// (two accumulators: the products run as the blades lie, and those run with the halves
// swapped, looped.hpp; each is read back in its own labelling)
template <class U, class Units, auto TL, class Store, class... Ts>
constexpr std::array<U, TL.size()> looped_sum_from_units(const U* const* leaves, const Store& store, type_list<Ts...>) noexcept {
    constexpr std::size_t universe = std::max({term_universe(Ts{})...});
    constexpr bool any_plain = (!term_swapped(Ts{}) || ...);
    constexpr bool any_swapped = (term_swapped(Ts{}) || ...);
    std::array<U, any_plain ? universe : 1> acc{};
    std::array<U, any_swapped ? universe : 1> swapped{};
    (accumulate_looped<U, Units>(acc.data(), swapped.data(), leaves, store, Ts{}), ...);
    using R = decltype(swapped_rule(type_list<Ts...>{}));
    if constexpr (!any_swapped) return gather<U, universe, TL>(acc.data());
    else if constexpr (!any_plain) return gather<U, universe, swapped_layout<R, TL>>(swapped.data());
    else {
        auto out = gather<U, universe, TL>(acc.data());
        const auto more = gather<U, universe, swapped_layout<R, TL>>(swapped.data());
        for (std::size_t k = 0; k < TL.size(); ++k) out[k] += more[k];
        return out;
    }
}

template <class U, class Units, auto TL, class Store, class R, class X, class Y>
constexpr std::array<U, TL.size()> product_from_units(const U* const* leaves, const Store& store, product<R, X, Y>*) noexcept {
    return run_product<U, R, operand_layout<X>, operand_layout<Y>, TL>(unit_operand<U, Units, X>(leaves, store),
                                                                       unit_operand<U, Units, Y>(leaves, store));
}

// Node's components in layout TL, its units already computed: a product computed as a loop
// (loop_as_unit), the looped products of a sum accumulated together plus the program of the
// rest, or the program of the whole (unrolled up to Inline terms).
template <class U, class Units, class Node, auto TL, std::size_t Inline = unroll_limit, class Store>
constexpr std::array<U, TL.size()> compute_from_units(const U* const* leaves, const Store& store) noexcept {
    using split = split_sum<Node>;
    using rest = typename split::rest;
    if constexpr (loop_as_unit<Node>) {
        return product_from_units<U, Units, TL>(leaves, store, static_cast<Node*>(nullptr));
    } else if constexpr (std::is_same_v<typename split::looped_terms, type_list<>>) {
        using P = program<Node, TL>;
        return run_with_units<U, Units, P, TL.size(), Inline>(leaves, store, typename P::looped_list{});
    } else {
        auto out = looped_sum_from_units<U, Units, TL>(leaves, store, typename split::looped_terms{});
        if constexpr (!is_zero_node<rest>) {
            using P = program<rest, TL>;
            const auto more = run_with_units<U, Units, P, TL.size(), Inline>(leaves, store, typename P::looped_list{});
            for (std::size_t k = 0; k < TL.size(); ++k) out[k] += more[k];
        }
        return out;
    }
}

template <std::size_t K, class... Us>
auto unit_type(type_list<Us...>) -> std::tuple_element_t<K, std::tuple<Us...>>;
template <std::size_t K, class Units>
using unit_t = decltype(unit_type<K>(Units{}));

// Every unit, in order (each reads only earlier ones).
template <class U, class Units, class Store, std::size_t... K>
constexpr void compute_units(const U* const* leaves, Store& store, std::index_sequence<K...>) noexcept {
    ((std::get<K>(store) = compute_from_units<U, Units, unit_t<K, Units>, node_layout<unit_t<K, Units>>>(leaves, store)), ...);
}

// What a root costs in layout TL once its units are computed: a loop a multiplication and an
// addition per pair, a program its assignments (the looped products it reads are units).
template <int... S, class... R, class... X, class... Y>
constexpr cost looped_terms_price(type_list<signed_looped<S, looped<R, X, Y>>...>) {
    return (cost{rows_of<R, X, Y>::pairs, rows_of<R, X, Y>::pairs} + ... + cost{});
}
template <class R, class A, class B>
constexpr cost product_pairs_price(product<R, A, B>*) {
    return cost{rows_of<R, A, B>::pairs, rows_of<R, A, B>::pairs};
}
template <class P>
constexpr cost program_assignments_price() {
    return assignments_price(P::terms.data(), P::offsets.data(), P::assignment_count);
}
template <class Node, auto TL>
constexpr cost root_price() {
    using split = split_sum<Node>;
    using rest = typename split::rest;
    if constexpr (loop_as_unit<Node>) return product_pairs_price(static_cast<Node*>(nullptr));
    else if constexpr (std::is_same_v<typename split::looped_terms, type_list<>>) return program_assignments_price<program<Node, TL>>();
    else if constexpr (is_zero_node<rest>) return looped_terms_price(typename split::looped_terms{});
    else return looped_terms_price(typename split::looped_terms{}) + program_assignments_price<program<rest, TL>>();
}
template <class... Us>
constexpr cost units_price(type_list<Us...>) {
    return (root_price<Us, node_layout<Us>>() + ... + cost{});
}

}  // namespace ctga::expr
