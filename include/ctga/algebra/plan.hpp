// Compile-time plans: for a rule of products.hpp and the layouts of the operands, the result's
// layout and the list of terms that make each result component. Only blade pairs whose product
// is structurally non-zero become terms; the evaluator (evaluate.hpp) emits exactly these.
//
// Plans are built in one pass into fixed-capacity arrays (constexpr std::vector is several
// times slower to interpret), then cut to their exact sizes: compile time is a budget.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "ctga/algebra/layout.hpp"

namespace ctga::detail {

// result[r] += sign · a[ia] · b[ib]
struct bilinear_term {
    std::uint16_t ia = 0, ib = 0, r = 0;
    signed char sign = 0;
};

// result[r] += sign · operand_k[i]
struct linear_term {
    std::uint8_t operand = 0;
    std::uint16_t i = 0, r = 0;
    signed char sign = 0;
};

// Terms before they are grouped by component: `mask` is the blade each one lands on.
template <class Term, std::size_t Cap>
struct raw_terms {
    std::array<Term, Cap> terms{};
    std::array<blade_mask, Cap> masks{};
    std::size_t count = 0;
    constexpr void add(const Term& t, blade_mask m) {
        terms[count] = t;
        masks[count] = m;
        ++count;
    }
};

// The distinct blades hit by a set of terms, in canonical order.
template <class Alg, class Raw>
struct distinct_blades {
    std::array<blade_mask, sizeof(Raw::masks) / sizeof(blade_mask)> masks{};
    std::size_t count = 0;
};

template <class Alg, class Raw>
constexpr auto canonical_blades_of(const Raw& raw) {
    distinct_blades<Alg, Raw> out;
    std::array<std::uint32_t, (Alg::blade_count + 31) / 32> seen{};
    for (std::size_t k = 0; k < raw.count; ++k) {
        const blade_mask m = raw.masks[k];
        if (seen[m / 32] >> (m % 32) & 1u) continue;
        seen[m / 32] |= 1u << (m % 32);
        out.masks[out.count++] = m;
    }
    std::sort(out.masks.begin(), out.masks.begin() + static_cast<std::ptrdiff_t>(out.count), canonical_less);
    return out;
}

// Position of `m` in a canonically sorted run.
template <std::size_t N>
constexpr std::uint16_t canonical_position(const std::array<blade_mask, N>& sorted, std::size_t n, blade_mask m) {
    return static_cast<std::uint16_t>(
        std::lower_bound(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(n), m, canonical_less) -
        sorted.begin());
}

template <std::size_t N, std::size_t Cap>
constexpr layout<N> canonical_layout_from(const std::array<blade_mask, Cap>& masks) {
    layout<N> l;
    for (std::size_t i = 0; i < N; ++i) {
        l.masks[i] = masks[i];
        l.signs[i] = 1;
    }
    return l;
}

// The terms grouped by result component (a stable counting sort); component[k] is term k's.
template <class Term, std::size_t N, std::size_t R, class Raw>
constexpr std::array<Term, N> group_by_component(const Raw& raw, const std::array<std::uint16_t, N>& component) {
    std::array<std::uint32_t, R + 1> next{};
    for (std::size_t k = 0; k < N; ++k) ++next[component[k] + 1u];
    for (std::size_t r = 0; r < R; ++r) next[r + 1] += next[r];
    std::array<Term, N> out{};
    for (std::size_t k = 0; k < N; ++k) {
        Term t = raw.terms[k];
        t.r = component[k];
        out[next[t.r]++] = t;
    }
    return out;
}

template <std::size_t R, class Term, std::size_t N>
constexpr std::array<std::uint32_t, R + 1> term_offsets(const std::array<Term, N>& terms) {
    std::array<std::uint32_t, R + 1> off{};
    for (const auto& t : terms) ++off[t.r + 1];
    for (std::size_t r = 0; r < R; ++r) off[r + 1] += off[r];
    return off;
}

// A plan whose result layout is canonical: the distinct blades its terms hit.
template <class Alg, class Term, auto Raw>
struct canonical_plan {
    static constexpr auto blades = canonical_blades_of<Alg>(Raw);
    static constexpr auto result = canonical_layout_from<blades.count>(blades.masks);
    static constexpr std::size_t term_count = Raw.count;
    static constexpr auto terms = [] {
        std::array<std::uint16_t, term_count> component{};
        for (std::size_t k = 0; k < term_count; ++k)
            component[k] = canonical_position(blades.masks, blades.count, Raw.masks[k]);
        return group_by_component<Term, term_count, result.size()>(Raw, component);
    }();
    static constexpr auto offsets = term_offsets<result.size()>(terms);
};

template <class Alg, class Rule, auto LA, auto LB>
constexpr auto bilinear_raw() {
    raw_terms<bilinear_term, (LA.size() * LB.size() > 0 ? LA.size() * LB.size() : 1)> raw;
    for (std::size_t i = 0; i < LA.size(); ++i)
        for (std::size_t j = 0; j < LB.size(); ++j)
            if (const auto p = Rule::apply(LA.masks[i], LB.masks[j]); p.sign != 0)
                raw.add({static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(j), 0,
                         static_cast<signed char>(p.sign * LA.signs[i] * LB.signs[j])},
                        p.mask);
    return raw;
}

// The plan of  a ∘ b  for a bilinear rule ∘ and operand layouts LA, LB.
template <class Alg, class Rule, auto LA, auto LB>
struct bilinear_plan : canonical_plan<Alg, bilinear_term, bilinear_raw<Alg, Rule, LA, LB>()> {};

template <class Alg, class Rule, auto L>
constexpr auto unary_raw() {
    raw_terms<linear_term, (L.size() > 0 ? L.size() : 1)> raw;
    for (std::size_t i = 0; i < L.size(); ++i)
        if (const auto p = Rule::apply(L.masks[i]); p.sign != 0)
            raw.add({0, static_cast<std::uint16_t>(i), 0, static_cast<signed char>(p.sign * L.signs[i])}, p.mask);
    return raw;
}

// A rule that only changes signs (reverse, involute, conj, negation) keeps the operand's
// layout: the reverse of a screw is a screw type.
template <class Rule, auto L>
constexpr bool sign_only() {
    for (std::size_t i = 0; i < L.size(); ++i)
        if (const auto p = Rule::apply(L.masks[i]); p.sign == 0 || p.mask != L.masks[i]) return false;
    return true;
}

template <class Rule, auto L>
struct layout_preserving_plan {
    static constexpr auto result = L;
    static constexpr std::size_t term_count = L.size();
    static constexpr auto terms = [] {
        std::array<linear_term, L.size()> t{};
        for (std::size_t i = 0; i < L.size(); ++i)
            t[i] = {0, static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(i),
                    static_cast<signed char>(Rule::apply(L.masks[i]).sign)};
        return t;
    }();
    static constexpr auto offsets = term_offsets<L.size()>(terms);
};

// The plan of a linear map given by a blade rule (involutions, projections, complements,
// automorphisms). Rules used here are injective on the blades they keep.
template <class Alg, class Rule, auto L>
struct unary_plan : std::conditional_t<sign_only<Rule, L>(), layout_preserving_plan<Rule, L>,
                                       canonical_plan<Alg, linear_term, unary_raw<Alg, Rule, L>()>> {};

// Re-expressing operands in a given target layout and adding them with signs Signs[k]:
// result = Σ_k Signs[k] · operand_k, component by component. Covers x + y, x − y, and
// conversion between layouts (one operand; blades the target lacks are dropped here and
// rejected earlier where dropping is not allowed).
template <class Alg, auto Target, std::array<signed char, 2> Signs, auto... Ls>
struct linear_plan {
    static constexpr auto result = Target;
    static constexpr auto raw = [] {
        raw_terms<linear_term, (Ls.size() + ... + 1)> raw;
        std::uint8_t k = 0;
        auto add = [&](const auto& l) {
            for (std::size_t i = 0; i < l.size(); ++i)
                if (const int r = Target.index_of(l.masks[i]); r >= 0)
                    raw.add({k, static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(r),
                             static_cast<signed char>(Signs[k] * l.signs[i] * Target.signs[r])},
                            l.masks[i]);
            ++k;
        };
        (add(Ls), ...);
        return raw;
    }();
    static constexpr std::size_t term_count = raw.count;
    static constexpr auto terms = [] {
        std::array<std::uint16_t, term_count> component{};
        for (std::size_t k = 0; k < term_count; ++k) component[k] = raw.terms[k].r;
        return group_by_component<linear_term, term_count, Target.size()>(raw, component);
    }();
    static constexpr auto offsets = term_offsets<Target.size()>(terms);
};

}  // namespace ctga::detail
