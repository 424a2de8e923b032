// Compile-time plans: for a rule of products.hpp and the layouts of the operands, the result's
// layout and the list of terms that make each result component. Only blade pairs whose product
// is structurally non-zero become terms; the evaluator (evaluate.hpp) emits exactly these.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

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

// Offsets of each result component's run of terms, the terms being sorted by component.
template <std::size_t R, class Term, std::size_t N>
constexpr std::array<std::uint32_t, R + 1> term_offsets(const std::array<Term, N>& terms) {
    std::array<std::uint32_t, R + 1> off{};
    for (const auto& t : terms) ++off[t.r + 1];
    for (std::size_t r = 0; r < R; ++r) off[r + 1] += off[r];
    return off;
}

// The terms made by `make`, grouped by result component (a stable counting sort: within a
// component, terms keep the order in which the operands' blades were visited).
template <class Term, std::size_t N, std::size_t R, class Make>
constexpr std::array<Term, N> sorted_terms(Make make) {
    const auto v = make();
    std::array<std::uint32_t, R + 1> next{};
    for (const auto& t : v) ++next[t.r + 1];
    for (std::size_t r = 0; r < R; ++r) next[r + 1] += next[r];
    std::array<Term, N> out{};
    for (const auto& t : v) out[next[t.r]++] = t;
    return out;
}

// Index of each blade of `l` in a table indexed by mask (−1: absent).
template <class Alg, auto L>
constexpr std::vector<int> index_by_mask() {
    std::vector<int> idx(Alg::blade_count, -1);
    for (std::size_t i = 0; i < L.size(); ++i) idx[L.masks[i]] = static_cast<int>(i);
    return idx;
}

// The plan of  a ∘ b  for a bilinear rule ∘ and operand layouts LA, LB.
template <class Alg, class Rule, auto LA, auto LB>
struct bilinear_plan {
    struct images {
        static constexpr std::vector<blade_mask> masks() {
            std::vector<blade_mask> v;
            for (std::size_t i = 0; i < LA.size(); ++i)
                for (std::size_t j = 0; j < LB.size(); ++j)
                    if (const auto p = Rule::apply(LA.masks[i], LB.masks[j]); p.sign != 0) v.push_back(p.mask);
            return v;
        }
    };
    static constexpr auto result = canonical_layout<images>();

    static constexpr std::vector<bilinear_term> make_terms() {
        const auto where = index_by_mask<Alg, result>();
        std::vector<bilinear_term> v;
        for (std::size_t i = 0; i < LA.size(); ++i)
            for (std::size_t j = 0; j < LB.size(); ++j)
                if (const auto p = Rule::apply(LA.masks[i], LB.masks[j]); p.sign != 0)
                    v.push_back({static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(j),
                                 static_cast<std::uint16_t>(where[p.mask]),
                                 static_cast<signed char>(p.sign * LA.signs[i] * LB.signs[j])});
        return v;
    }
    static constexpr std::size_t term_count = make_terms().size();
    static constexpr auto terms = sorted_terms<bilinear_term, term_count, result.size()>(make_terms);
    static constexpr auto offsets = term_offsets<result.size()>(terms);
};

// The plan of a linear map given by a blade rule (involutions, projections, complements,
// automorphisms). Rules used here are injective on the blades they keep. A rule that only
// changes signs (reverse, involute, conj) keeps the operand's layout: the reverse of a screw is
// a screw type.
template <class Alg, class Rule, auto L>
struct unary_plan {
    struct images {
        static constexpr std::vector<blade_mask> masks() {
            std::vector<blade_mask> v;
            for (std::size_t i = 0; i < L.size(); ++i)
                if (const auto p = Rule::apply(L.masks[i]); p.sign != 0) v.push_back(p.mask);
            return v;
        }
    };
    static constexpr bool sign_only = [] {
        for (std::size_t i = 0; i < L.size(); ++i)
            if (const auto p = Rule::apply(L.masks[i]); p.sign == 0 || p.mask != L.masks[i]) return false;
        return true;
    }();
    static constexpr auto result = [] {
        if constexpr (sign_only) return L; else return canonical_layout<images>();
    }();

    static constexpr std::vector<linear_term> make_terms() {
        const auto where = index_by_mask<Alg, result>();
        std::vector<linear_term> v;
        for (std::size_t i = 0; i < L.size(); ++i)
            if (const auto p = Rule::apply(L.masks[i]); p.sign != 0) {
                const int r = where[p.mask];
                v.push_back({0, static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(r),
                             static_cast<signed char>(p.sign * L.signs[i] * result.signs[r])});
            }
        return v;
    }
    static constexpr std::size_t term_count = make_terms().size();
    static constexpr auto terms = sorted_terms<linear_term, term_count, result.size()>(make_terms);
    static constexpr auto offsets = term_offsets<result.size()>(terms);
};

// Re-expressing operands in a target layout and adding them with signs Signs[k]:
// result = Σ_k Signs[k] · operand_k, component by component. Covers x + y, x − y, and
// conversion between layouts (one operand). Blades of an operand that the target lacks are
// reported by `first_missing`.
template <class Alg, auto Target, std::array<signed char, 2> Signs, auto... Ls>
struct linear_plan {
    static constexpr auto result = Target;

    static constexpr std::vector<linear_term> make_terms() {
        const auto where = index_by_mask<Alg, Target>();
        std::vector<linear_term> v;
        std::uint8_t k = 0;
        auto add = [&](const auto& l) {
            for (std::size_t i = 0; i < l.size(); ++i)
                if (where[l.masks[i]] >= 0)
                    v.push_back({k, static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(where[l.masks[i]]),
                                 static_cast<signed char>(Signs[k] * l.signs[i] * Target.signs[where[l.masks[i]]])});
            ++k;
        };
        (add(Ls), ...);
        return v;
    }
    static constexpr std::size_t term_count = make_terms().size();
    static constexpr auto terms = sorted_terms<linear_term, term_count, result.size()>(make_terms);
    static constexpr auto offsets = term_offsets<result.size()>(terms);
};

}  // namespace ctga::detail
