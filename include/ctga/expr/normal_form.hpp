// The compile-time normal form of an expression: every output blade's coefficient as a sum of
// monomials over the components of the expression's sources, with exact rational
// coefficients. A source is a leaf (an operand of the expression) or an intermediate (a
// subexpression the evaluator materialises, see nodes.hpp).
//
// Terms are kept sorted by (output blade, monomial); equal monomials merge and zero
// coefficients vanish, so cancellations are gone before any code is emitted:
// ½(s1 s2 − s2 s1) keeps 18 monomials of the 54 that the two products make.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "ctga/algebra/blade.hpp"
#include "ctga/algebra/layout.hpp"
#include "ctga/expr/rational.hpp"
#include "ctga/support/sort.hpp"

namespace ctga::expr {

// Monomials of degree above this are not formed: the evaluator stages instead. (Identity 7 of
// the conventions, (g ḡ) N (g ḡ)* seen through A ∨ (· ∧ s), has degree 7.)
inline constexpr std::size_t max_degree = 8;

// A factor is one component of one source, packed in 64 bits: source << 20 | component.
// Leaves are numbered 0, 1, …; an intermediate is named by 43 bits of its subexpression's
// structural hash with bit 43 set, so equal subexpressions are one intermediate.
using factor = std::uint64_t;
using source_id = std::uint64_t;
inline constexpr unsigned component_bits = 20;
inline constexpr source_id intermediate_bit = source_id{1} << 43;

constexpr factor make_factor(source_id source, std::uint32_t comp) { return source << component_bits | comp; }
constexpr source_id source_of(factor f) { return f >> component_bits; }
constexpr std::uint32_t component_of(factor f) { return static_cast<std::uint32_t>(f & ((1u << component_bits) - 1)); }
constexpr source_id intermediate_id(std::uint64_t hash) { return intermediate_bit | (hash & (intermediate_bit - 1)); }

// c · Π f[0..degree) contributing to canonical blade `out`.
struct term {
    blade_mask out = 0;
    std::uint32_t degree = 0;
    std::array<factor, max_degree> f{};
    rational c{};
};

constexpr bool same_monomial(const term& a, const term& b) {
    if (a.out != b.out || a.degree != b.degree) return false;
    for (std::uint32_t k = 0; k < a.degree; ++k)
        if (a.f[k] != b.f[k]) return false;
    return true;
}

constexpr bool term_less(const term& a, const term& b) {
    if (a.out != b.out) return canonical_less(a.out, b.out);
    if (a.degree != b.degree) return a.degree < b.degree;
    for (std::uint32_t k = 0; k < a.degree; ++k)
        if (a.f[k] != b.f[k]) return a.f[k] < b.f[k];
    return false;
}

// A bounded list of terms, as built inside one constant evaluation.
template <std::size_t Cap>
struct term_list {
    std::array<term, Cap> t{};
    std::size_t n = 0;
    bool degree_overflow = false;  // a monomial would exceed max_degree
    constexpr void push(const term& x) { t[n++] = x; }
};

// Sort, merge equal monomials, drop zero coefficients.
template <std::size_t Cap>
constexpr void normalize(term_list<Cap>& l) {
    detail::merge_sort(l.t.data(), l.n, term_less);
    std::size_t w = 0;
    for (std::size_t r = 0; r < l.n;) {
        term acc = l.t[r++];
        while (r < l.n && same_monomial(acc, l.t[r])) acc.c = acc.c + l.t[r++].c;
        if (!is_zero(acc.c)) l.t[w++] = acc;
    }
    l.n = w;
}

template <std::size_t N, std::size_t Cap>
constexpr std::array<term, N> exact(const term_list<Cap>& l) {
    std::array<term, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = l.t[i];
    return out;
}

// ---- the operations -------------------------------------------------------------------

// Leaf `id` with layout L: component i is the coefficient of signs[i] · blade(masks[i]).
template <auto L>
constexpr term_list<(L.size() > 0 ? L.size() : 1)> leaf_terms(source_id id) {
    term_list<(L.size() > 0 ? L.size() : 1)> l;
    for (std::size_t i = 0; i < L.size(); ++i) {
        term x;
        x.out = L.masks[i];
        x.degree = 1;
        x.f[0] = make_factor(id, static_cast<std::uint32_t>(i));
        x.c = {L.signs[i], 1};
        l.push(x);
    }
    normalize(l);
    return l;
}

// The product of two normal forms under a blade rule: every pair of terms whose blades the
// rule does not kill; monomials multiply (factor lists merge), coefficients multiply.
template <class Rule, std::size_t NX, std::size_t NY>
constexpr term_list<(NX * NY > 0 ? NX * NY : 1)> product_terms(const std::array<term, NX>& x,
                                                              const std::array<term, NY>& y) {
    term_list<(NX * NY > 0 ? NX * NY : 1)> l;
    for (const term& a : x)
        for (const term& b : y) {
            const auto p = Rule::apply(a.out, b.out);
            if (p.sign == 0) continue;
            if (a.degree + b.degree > max_degree) { l.degree_overflow = true; continue; }
            term m;
            m.out = p.mask;
            m.degree = a.degree + b.degree;
            // the monomial's factors stay sorted: merge the two sorted factor lists
            for (std::uint32_t i = 0, j = 0, k = 0; k < m.degree; ++k)
                m.f[k] = j == b.degree || (i < a.degree && !(b.f[j] < a.f[i])) ? a.f[i++] : b.f[j++];
            m.c = a.c * b.c * rational{p.sign, 1};
            l.push(m);
        }
    normalize(l);
    return l;
}

// A linear blade rule applied term by term.
template <class Rule, std::size_t NX>
constexpr term_list<(NX > 0 ? NX : 1)> map_terms(const std::array<term, NX>& x) {
    term_list<(NX > 0 ? NX : 1)> l;
    for (term a : x) {
        const auto p = Rule::apply(a.out);
        if (p.sign == 0) continue;
        a.out = p.mask;
        a.c = a.c * rational{p.sign, 1};
        l.push(a);
    }
    normalize(l);
    return l;
}

// x + sign_y · y.
template <std::size_t NX, std::size_t NY>
constexpr term_list<(NX + NY > 0 ? NX + NY : 1)> sum_terms(const std::array<term, NX>& x,
                                                          const std::array<term, NY>& y, int sign_y) {
    term_list<(NX + NY > 0 ? NX + NY : 1)> l;
    for (const term& a : x) l.push(a);
    for (term b : y) {
        b.c = b.c * rational{sign_y, 1};
        l.push(b);
    }
    normalize(l);
    return l;
}

template <std::size_t NX>
constexpr term_list<(NX > 0 ? NX : 1)> scaled_terms(const std::array<term, NX>& x, rational q) {
    term_list<(NX > 0 ? NX : 1)> l;
    for (term a : x) {
        a.c = a.c * q;
        l.push(a);
    }
    normalize(l);
    return l;
}

// ---- what a normal form costs ----------------------------------------------------------

struct cost {
    std::size_t mul = 0;
    std::size_t add = 0;
    friend constexpr bool operator==(const cost&, const cost&) = default;
};

constexpr cost operator+(cost a, cost b) { return {a.mul + b.mul, a.add + b.add}; }

// Multiplications: degree − 1 per monomial, one more for a coefficient other than ±1.
// Additions: one fewer than the terms of each output blade. (Shared prefixes of monomials are
// counted once where a whole program is assembled, program.hpp.)
template <std::size_t N>
constexpr cost terms_cost(const std::array<term, N>& t) {
    cost c;
    for (std::size_t i = 0; i < N; ++i) {
        if (t[i].degree > 0) c.mul += t[i].degree - 1 + (is_unit(t[i].c) ? 0 : 1);
        if (i > 0 && t[i].out == t[i - 1].out) ++c.add;
    }
    return c;
}

// The distinct output blades of sorted terms, as a canonical layout.
template <std::size_t N>
constexpr std::size_t distinct_outputs(const std::array<term, N>& t) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < N; ++i) n += (i == 0 || t[i].out != t[i - 1].out);
    return n;
}

template <std::size_t R, std::size_t N>
constexpr layout<R> output_layout(const std::array<term, N>& t) {
    layout<R> l;
    std::size_t k = 0;
    for (std::size_t i = 0; i < N; ++i)
        if (i == 0 || t[i].out != t[i - 1].out) {
            l.masks[k] = t[i].out;
            l.signs[k] = 1;
            ++k;
        }
    return l;
}

}  // namespace ctga::expr
