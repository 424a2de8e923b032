// The normal form of every node type (normal_form.hpp), computed once by the compiler and
// memoised as a static member of traits<Node>, and the cost model that decides, node by node,
// what is expanded and what is computed once as an intermediate.
//
// Staging (the cost-driven choice per node): a product node either multiplies its children's
// normal forms out (full expansion: cancellations across the whole expression become visible),
// or materialises a child as an intermediate, computed once at run time and entering the
// product as a degree-1 source. It takes whichever needs fewer multiplications, counting the
// intermediates' own cost, and stages whenever expansion would pass the term budget or the
// maximum degree. Full expansion of s̄ ∨ (N ∧ s) costs 57 multiplications, staging N ∧ s 42.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "ctga/algebra/layout.hpp"
#include "ctga/expr/nodes.hpp"
#include "ctga/expr/normal_form.hpp"
#include "ctga/expr/rational.hpp"

namespace ctga::expr {

// Expansion past this many term pairs in one product node is not attempted: it stages.
inline constexpr std::size_t term_budget = 4096;
// Full expansion is attempted up to this many term pairs per node: for a result's blades, and
// (larger) for a proof.
inline constexpr std::size_t expansion_budget = 2048;
inline constexpr std::size_t proof_budget = 65536;

constexpr std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 0xbf58476d1ce4e5b9ull;
    return h ^ (h >> 31);
}

template <auto L>
constexpr std::uint64_t layout_hash() {
    std::uint64_t h = L.size();
    for (std::size_t i = 0; i < L.size(); ++i) h = mix(h, L.masks[i] * 2u + (L.signs[i] > 0));
    return h;
}

// True when a normal form costs nothing to inline: each output blade one term of degree ≤ 1
// with coefficient ±1 (a leaf, a constant, a relabelling by a linear rule).
template <std::size_t N>
constexpr bool trivial(const std::array<term, N>& t) {
    for (std::size_t i = 0; i < N; ++i) {
        if (t[i].degree > 1 || !is_unit(t[i].c)) return false;
        if (i > 0 && t[i].out == t[i - 1].out) return false;
    }
    return true;
}

// Staging policy: cost-driven (evaluation), or none: full expansion, for the blades of a result
// (within expansion_budget) and for proofs (within proof_budget: two expressions are equal for
// all inputs iff their fully expanded normal forms are equal).
enum class staging { by_cost, never, proof };

// Each node kind's normal form is a specialisation below (looped.hpp has the looped node's). A
// type that is not a node kind, or a kind without one, is refused by name.
template <class Node, staging P = staging::by_cost>
struct traits : refuse_unknown<walker::normal_form, Node> {
    static_assert(!node_shape<Node>::known, "ctga::expr::traits: this node kind has no normal form (expr/staging.hpp)");
};

// A leaf (a formula's argument or a data leaf): its components, each one source factor. Data
// leaves are numbered after the formula's arguments; traits see the final numbering.
template <std::size_t I, auto L, std::uint64_t Salt>
struct leaf_traits {
    static constexpr bool complete = true;
    static constexpr std::uint64_t hash = mix(mix(Salt, I), layout_hash<L>());
    static constexpr auto list = leaf_terms<L>(I);
    static constexpr auto terms = exact<list.n>(list);
    static constexpr cost hidden{};
    using staged = type_list<>;
};
template <std::size_t I, auto L, staging P>
struct traits<arg<I, L>, P> : leaf_traits<I, L, 0xa5> {};
template <std::size_t I, auto L, staging P>
struct traits<leaf<I, L>, P> : leaf_traits<I, L, 0x1e> {};

template <auto L, auto C, staging P>
struct traits<constant<L, C>, P> {
    static constexpr bool complete = true;
    static constexpr std::uint64_t hash = [] {
        std::uint64_t h = mix(0xc0, layout_hash<L>());
        for (const rational& q : C) h = mix(mix(h, static_cast<std::uint64_t>(q.num)), static_cast<std::uint64_t>(q.den));
        return h;
    }();
    static constexpr auto list = [] {
        term_list<(L.size() > 0 ? L.size() : 1)> l;
        for (std::size_t i = 0; i < L.size(); ++i) {
            term x;
            x.out = L.masks[i];
            x.c = C[i] * rational{L.signs[i], 1};
            l.push(x);
        }
        normalize(l);
        return l;
    }();
    static constexpr auto terms = exact<list.n>(list);
    static constexpr cost hidden{};
    using staged = type_list<>;
};

// A staged node as a source: one degree-1 term per output blade of its normal form.
template <class Node>
constexpr auto intermediate_terms() {
    constexpr auto& t = traits<Node>::terms;  // staging happens under the by_cost policy only
    constexpr std::size_t n = distinct_outputs(t);
    std::array<term, n> out{};
    std::size_t k = 0;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (i == 0 || t[i].out != t[i - 1].out) {
            out[k].out = t[i].out;
            out[k].degree = 1;
            out[k].f[0] = make_factor(intermediate_id(traits<Node>::hash), static_cast<std::uint32_t>(k));
            out[k].c = {1, 1};
            ++k;
        }
    return out;
}

// Multiplications of multiplying two normal forms out, counted without building the terms
// (an upper bound: no merging). Prices the staged options; full expansion, where cancellations
// matter, is priced on its actual terms.
template <class Rule, std::size_t NX, std::size_t NY>
constexpr cost product_cost_bound(const std::array<term, NX>& x, const std::array<term, NY>& y) {
    cost c;
    for (const term& a : x)
        for (const term& b : y)
            if (Rule::apply(a.out, b.out).sign != 0) {
                c.mul += a.degree + b.degree - 1 + ((is_unit(a.c) && is_unit(b.c)) ? 0 : 1);
                ++c.add;
            }
    return c;
}

template <std::size_t N>
constexpr std::uint32_t max_term_degree(const std::array<term, N>& t) {
    std::uint32_t d = 0;
    for (const term& x : t) d = x.degree > d ? x.degree : d;
    return d;
}

// One way of evaluating a product node: child X staged or not (SX), child Y staged or not (SY).
template <class Rule, class X, class Y, bool SX, bool SY>
struct product_option {
    static constexpr auto x_terms = [] {
        if constexpr (SX) return intermediate_terms<X>(); else return traits<X>::terms;
    }();
    static constexpr auto y_terms = [] {
        if constexpr (SY) return intermediate_terms<Y>(); else return traits<Y>::terms;
    }();
    // within the term budget and the maximum degree (staging both is the last resort)
    static constexpr bool valid = (x_terms.size() * y_terms.size() <= term_budget &&
                                   max_term_degree(x_terms) + max_term_degree(y_terms) <= max_degree) ||
                                  (SX && SY);
    // the terms: built for full expansion (to price it) and for the option chosen, not otherwise
    static constexpr auto list = [] {
        if constexpr (valid) return product_terms<Rule>(x_terms, y_terms);
        else return term_list<1>{{}, 0, true};
    }();
    static constexpr auto terms = exact<list.n>(list);
    // what this option costs in all: its own terms, the intermediates it stages, and those its
    // children's normal forms already refer to (an intermediate used by both children once)
    static constexpr cost hidden = [] {
        cost c = traits<X>::hidden;
        if (!(SX && SY && traits<X>::hash == traits<Y>::hash)) c = c + traits<Y>::hidden;
        if constexpr (SX) c = c + terms_cost(traits<X>::terms);
        if constexpr (SY) if (!(SX && traits<X>::hash == traits<Y>::hash)) c = c + terms_cost(traits<Y>::terms);
        return c;
    }();
    static constexpr cost own = [] {
        if constexpr (!valid) return cost{~std::size_t{0} / 4, 0};
        else if constexpr (!SX && !SY) return terms_cost(terms);
        else return product_cost_bound<Rule>(x_terms, y_terms);
    }();
    static constexpr cost total = own + hidden;
};

template <class A, class B>
constexpr bool cheaper(bool a_valid, bool b_valid) {
    if (a_valid != b_valid) return a_valid;
    if (A::total.mul != B::total.mul) return A::total.mul < B::total.mul;
    return A::total.add < B::total.add;
}

// Full expansion: the children's expanded normal forms multiplied out. Where the cost-driven
// normal form staged nothing below this node it is already the full expansion, and is reused.
template <class Rule, class X, class Y, staging P>
    requires(P != staging::by_cost)
struct traits<product<Rule, X, Y>, P> {
    using x = traits<X, P>;
    using y = traits<Y, P>;
    static constexpr std::size_t budget = P == staging::proof ? proof_budget : expansion_budget;
    using by_cost = traits<product<Rule, X, Y>>;
    static constexpr std::uint64_t hash = by_cost::hash;
    // nothing staged at or below this node: the cost-driven form is the full expansion
    static constexpr bool reuse = std::is_same_v<typename by_cost::staged, type_list<>>;
    // staged only here: full expansion is the cost-driven 'expand' option, if it was valid
    using expand_option = product_option<Rule, X, Y, false, false>;
    static constexpr bool reuse_expand =
        !reuse && std::is_same_v<decltype(typename traits<X>::staged{} + typename traits<Y>::staged{}), type_list<>> &&
        expand_option::valid;
    static constexpr bool attempted = reuse || reuse_expand ||
                                      (x::complete && y::complete && x::terms.size() * y::terms.size() <= budget);
    static constexpr auto list = [] {
        if constexpr (reuse || reuse_expand || !attempted) return term_list<1>{{}, 0, !attempted};
        else return product_terms<Rule>(x::terms, y::terms);
    }();
    // false when the expansion was too large to attempt or passed the maximum degree
    static constexpr bool complete = attempted && !list.degree_overflow &&
                                     !(reuse_expand && expand_option::list.degree_overflow);
    static constexpr auto terms = [] {
        if constexpr (reuse) return by_cost::terms;
        else if constexpr (reuse_expand) return expand_option::terms;
        else return exact<list.n>(list);
    }();
    static constexpr cost hidden{};
    using staged = type_list<>;
};

template <class Rule, class X, class Y>
struct traits<product<Rule, X, Y>, staging::by_cost> {
    static constexpr std::uint64_t hash = mix(mix(mix(0x9d, Rule::id), traits<X>::hash), traits<Y>::hash);
    // a child that costs nothing inlined (a leaf, a constant) is never staged
    static constexpr bool may_stage_x = !trivial(traits<X>::terms);
    static constexpr bool may_stage_y = !trivial(traits<Y>::terms);

    using none = product_option<Rule, X, Y, false, false>;
    using only_x = product_option<Rule, X, Y, true, false>;
    using only_y = product_option<Rule, X, Y, false, true>;
    using both = product_option<Rule, X, Y, true, true>;

    // 0: expand, 1: stage X, 2: stage Y, 3: stage both. Ties go to fewer intermediates.
    static constexpr int choice = [] {
        int best = 0;
        bool best_valid = none::valid;
        auto consider = [&]<class O>(int id, bool allowed) {
            if (!allowed) return;
            const bool better = [&] {
                if (best == 0) return cheaper<O, none>(O::valid, best_valid);
                if (best == 1) return cheaper<O, only_x>(O::valid, best_valid);
                if (best == 2) return cheaper<O, only_y>(O::valid, best_valid);
                return cheaper<O, both>(O::valid, best_valid);
            }();
            if (better) { best = id; best_valid = O::valid; }
        };
        if constexpr (may_stage_x) consider.template operator()<only_x>(1, true);
        if constexpr (may_stage_y) consider.template operator()<only_y>(2, true);
        if constexpr (may_stage_x || may_stage_y) consider.template operator()<both>(3, may_stage_x && may_stage_y);
        return best;
    }();
    static constexpr bool stage_x = choice == 1 || choice == 3;
    static constexpr bool stage_y = choice == 2 || choice == 3;
    using chosen = product_option<Rule, X, Y, stage_x, stage_y>;
    static_assert(chosen::valid || (stage_x && stage_y),
                  "ctga: an expression node is too large to unroll even when staged: more blade pairs than "
                  "expr::term_budget or monomials beyond expr::max_degree; evaluate it looped (ctga::loop_products(x)) "
                  "instead of ctga::unroll_products(x)");

    static constexpr bool complete = true;
    static constexpr auto terms = chosen::terms;
    static constexpr cost hidden = chosen::hidden;
    // intermediates in dependency order (repeats removed when a program is assembled)
    using staged = decltype(typename traits<X>::staged{} + typename traits<Y>::staged{} +
                            std::conditional_t<stage_x, type_list<X>, type_list<>>{} +
                            std::conditional_t<stage_y, type_list<Y>, type_list<>>{});
};

template <class Rule, class X, staging P>
struct traits<map<Rule, X>, P> {
    static constexpr std::uint64_t hash = mix(mix(0x3a, Rule::id), traits<X>::hash);
    static constexpr bool complete = traits<X, P>::complete;
    static constexpr auto list = map_terms<Rule>(traits<X, P>::terms);
    static constexpr auto terms = exact<list.n>(list);
    static constexpr cost hidden = traits<X, P>::hidden;
    using staged = typename traits<X, P>::staged;
};

template <class X, class Y, int S, staging P>
struct traits<sum<X, Y, S>, P> {
    static constexpr std::uint64_t hash = mix(mix(mix(0x5e, static_cast<std::uint64_t>(S + 2)), traits<X>::hash), traits<Y>::hash);
    static constexpr bool complete = traits<X, P>::complete && traits<Y, P>::complete;
    static constexpr auto list = sum_terms(traits<X, P>::terms, traits<Y, P>::terms, S);
    static constexpr auto terms = exact<list.n>(list);
    static constexpr cost hidden = traits<X, P>::hidden + traits<Y, P>::hidden;
    using staged = decltype(typename traits<X, P>::staged{} + typename traits<Y, P>::staged{});
};

template <rational Q, class X, staging P>
struct traits<scaled<Q, X>, P> {
    static constexpr std::uint64_t hash =
        mix(mix(mix(0x5c, static_cast<std::uint64_t>(Q.num)), static_cast<std::uint64_t>(Q.den)), traits<X>::hash);
    static constexpr bool complete = traits<X, P>::complete;
    static constexpr auto list = scaled_terms(traits<X, P>::terms, Q);
    static constexpr auto terms = exact<list.n>(list);
    static constexpr cost hidden = traits<X, P>::hidden;
    using staged = typename traits<X, P>::staged;
};

// The canonical layout of a node's value: the blades it can make non-zero. Taken from the full
// expansion where that is affordable, since staging can hide cancellations: g s g* of a screw
// has no scalar part for any g, but (g s) g* over the intermediate g s cannot show it. The
// staged program is then evaluated for these blades only.
template <class Node>
constexpr auto value_terms() -> const auto& {
    if constexpr (std::is_same_v<typename traits<Node>::staged, type_list<>>) return traits<Node>::terms;  // nothing staged
    else if constexpr (traits<Node, staging::never>::complete) return traits<Node, staging::never>::terms;
    else return traits<Node>::terms;
}
template <class Node>
inline constexpr auto node_layout = output_layout<distinct_outputs(value_terms<Node>())>(value_terms<Node>());

}  // namespace ctga::expr
