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

}  // namespace ctga::expr
