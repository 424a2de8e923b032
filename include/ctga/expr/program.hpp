// From a root node and a target layout to a program: the list of assignments that run.hpp
// executes as straight-line code.
//
// Assembly (compile time): the intermediates the root's normal form refers to, repeats removed
// (the same subexpression is one intermediate), in dependency order. Output pruning: only the
// target's blades are computed, and of each intermediate only the components some needed term
// reads, transitively. The result is a program: a list of assignments, first the temporaries,
// then the target's components, each a sum of coefficient · monomial terms.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

#include "ctga/expr/looped.hpp"
#include "ctga/expr/normal_form.hpp"
#include "ctga/expr/staging.hpp"
#include "ctga/support/sort.hpp"

namespace ctga::expr {

// ---- intermediates: unique, in dependency order ----------------------------------------

template <class List>
struct unique_by_hash;

template <class... Ts>
struct unique_by_hash<type_list<Ts...>> {
    static constexpr std::size_t n = sizeof...(Ts);
    static constexpr std::array<std::uint64_t, n> hashes{traits<Ts>::hash...};
    static constexpr std::size_t count = [] {
        std::size_t c = 0;
        for (std::size_t i = 0; i < n; ++i) {
            bool seen = false;
            for (std::size_t j = 0; j < i; ++j) seen |= hashes[j] == hashes[i];
            c += !seen;
        }
        return c;
    }();
    static constexpr std::array<std::size_t, count> kept = [] {
        std::array<std::size_t, count> k{};
        std::size_t c = 0;
        for (std::size_t i = 0; i < n; ++i) {
            bool seen = false;
            for (std::size_t j = 0; j < i; ++j) seen |= hashes[j] == hashes[i];
            if (!seen) k[c++] = i;
        }
        return k;
    }();
    template <std::size_t... K>
    static auto pick(std::index_sequence<K...>) -> type_list<std::tuple_element_t<kept[K], std::tuple<Ts...>>...>;
    using type = decltype(pick(std::make_index_sequence<count>{}));
};

// All intermediates' terms in one array, with where each one's terms and components start.
template <class List>
struct flat_intermediates;

template <class... Cs>
struct flat_intermediates<type_list<Cs...>> {
    static constexpr std::size_t count = sizeof...(Cs);
    static constexpr std::size_t term_total = (traits<Cs>::terms.size() + ... + 0);
    static constexpr std::array<source_id, count> ids{intermediate_id(traits<Cs>::hash)...};
    static constexpr std::array<std::size_t, count + 1> term_begin = [] {
        std::array<std::size_t, count + 1> b{};
        [[maybe_unused]] std::size_t i = 0;
        ((b[i + 1] = b[i] + traits<Cs>::terms.size(), ++i), ...);
        return b;
    }();
    static constexpr std::array<term, (term_total > 0 ? term_total : 1)> terms = [] {
        std::array<term, (term_total > 0 ? term_total : 1)> a{};
        [[maybe_unused]] std::size_t k = 0;
        ((void)[&](const auto& from) {
             for (const term& t : from) a[k++] = t;
         }(traits<Cs>::terms),
         ...);
        return a;
    }();
};

// ---- the program ------------------------------------------------------------------------

// A factor of the program: a leaf component, or (tmp_flag) a temporary slot.
inline constexpr std::uint32_t tmp_flag = 1u << 31;
inline constexpr unsigned leaf_shift = component_bits;

struct op_term {
    std::uint32_t degree = 0;
    std::array<std::uint32_t, max_degree> f{};
    rational c{};
};

template <std::size_t Terms, std::size_t Assignments>
struct program_data {
    std::array<op_term, (Terms > 0 ? Terms : 1)> terms{};
    std::array<std::uint32_t, Assignments + 1> offsets{};
    std::size_t term_count = 0;
    std::size_t tmp_count = 0;
    std::size_t assignment_count = 0;
};

template <class List>
struct hash_list;
template <class... Ls>
struct hash_list<type_list<Ls...>> {
    static constexpr std::array<std::uint64_t, sizeof...(Ls)> value{traits<Ls>::hash...};
};

// What a looped node costs, its operands' programs included (specialised below).
template <class Node>
struct looped_price;

// What a program's assignments cost (assignment x is terms[offsets[x], offsets[x + 1])):
// additions per assignment; multiplications counting each distinct monomial prefix once (the
// same leaf product is computed once), plus coefficients other than ±1.
constexpr cost assignments_price(const op_term* terms, const std::uint32_t* offsets, std::size_t assignments) {
    cost c;
    std::size_t capacity = 1;
    for (std::size_t x = 0; x < assignments; ++x)
        for (std::uint32_t t = offsets[x]; t < offsets[x + 1]; ++t) capacity += terms[t].degree;
    std::uint64_t* prefixes = new std::uint64_t[capacity];
    std::size_t count = 0;
    for (std::size_t x = 0; x < assignments; ++x)
        for (std::uint32_t t = offsets[x]; t < offsets[x + 1]; ++t) {
            const op_term& o = terms[t];
            if (t > offsets[x]) ++c.add;
            if (o.degree >= 1 && !is_unit(o.c)) ++c.mul;
            std::uint64_t h = o.degree > 0 ? mix(0x7f, o.f[0]) : 0;
            for (std::uint32_t len = 2; len <= o.degree; ++len) prefixes[count++] = h = mix(h, o.f[len - 1]);
        }
    detail::merge_sort(prefixes, count, [](std::uint64_t a, std::uint64_t b) { return a < b; });
    for (std::size_t i = 0; i < count; ++i) c.mul += i == 0 || prefixes[i] != prefixes[i - 1];
    delete[] prefixes;
    return c;
}

// Assemble the program computing target layout TL from root node Root. The looped products
// in it (looped.hpp) are computed before it runs and read as further leaves, numbered from
// leaf_base on.
template <class Root, auto TL>
struct program {
    using looped_list = typename unique_by_hash<looped_nodes_t<Root>>::type;
    static constexpr auto& looped_hashes = hash_list<looped_list>::value;
    static constexpr std::size_t looped_count = looped_hashes.size();

    using intermediates = typename unique_by_hash<typename traits<Root>::staged>::type;
    using flat = flat_intermediates<intermediates>;
    static constexpr auto& root_terms = traits<Root>::terms;
    static constexpr auto root_outs = [] {
        std::array<blade_mask, root_terms.size()> o{};
        for (std::size_t i = 0; i < root_terms.size(); ++i) o[i] = root_terms[i].out;
        return o;
    }();
    static constexpr std::size_t k = flat::count;

    static constexpr std::size_t which(source_id s) {
        for (std::size_t i = 0; i < k; ++i)
            if (flat::ids[i] == s) return i;
        return k;
    }

    static constexpr std::size_t nt = flat::term_total;
    static constexpr std::size_t capacity_terms = nt + root_terms.size();
    static constexpr std::size_t capacity_assign = nt + TL.size();

    // The intermediates' components, numbered globally: component c of intermediate i is
    // comp_base[i] + c, and its terms are [first_term[g], first_term[g + 1]).
    struct components {
        std::array<std::size_t, k + 1> comp_base{};
        std::array<std::size_t, nt + 1> first_term{};  // indexed by global component (≤ nt of them)
        std::size_t count = 0;
    };
    static constexpr components comps = [] {
        components c;
        for (std::size_t i = 0; i < k; ++i) {
            c.comp_base[i] = c.count;
            for (std::size_t u = flat::term_begin[i]; u < flat::term_begin[i + 1]; ++u)
                if (u == flat::term_begin[i] || flat::terms[u].out != flat::terms[u - 1].out) c.first_term[c.count++] = u;
        }
        c.comp_base[k] = c.count;
        c.first_term[c.count] = nt;
        return c;
    }();
    static constexpr std::size_t global_component(factor f) {
        return comps.comp_base[which(source_of(f))] + component_of(f);
    }

    // One past the highest leaf any term reads: the first of the looped products' slots.
    static constexpr std::uint32_t leaf_base = [] {
        std::uint32_t b = 0;
        auto scan = [&](const term& t) {
            for (std::uint32_t d = 0; d < t.degree; ++d) {
                const source_id s = source_of(t.f[d]);
                if (!(s & intermediate_bit) && !is_looped_source(s) && s + 1 > b) b = static_cast<std::uint32_t>(s + 1);
            }
        };
        for (const term& t : root_terms) scan(t);
        for (std::size_t u = 0; u < nt; ++u) scan(flat::terms[u]);
        return b;
    }();
    static constexpr std::uint32_t looped_slot(source_id s) {
        for (std::size_t i = 0; i < looped_count; ++i)
            if (looped_id(looped_hashes[i]) == s) return leaf_base + static_cast<std::uint32_t>(i);
        return ~std::uint32_t{0};
    }

    static constexpr auto draft = [] {
        // 1. which intermediate components are needed: the target's terms, then backwards
        //    (an intermediate depends only on earlier ones)
        std::array<bool, nt + 1> needed{};
        auto mark = [&](const term& t) {
            for (std::uint32_t d = 0; d < t.degree; ++d)
                if (source_of(t.f[d]) & intermediate_bit) needed[global_component(t.f[d])] = true;
        };
        if constexpr (k > 0)
            for (const term& t : root_terms)
                if (TL.contains(t.out)) mark(t);
        for (std::size_t g = comps.count; g-- > 0;)
            if (needed[g])
                for (std::size_t u = comps.first_term[g]; u < comps.first_term[g + 1]; ++u) mark(flat::terms[u]);

        // 2. one temporary slot per needed component
        std::array<std::uint32_t, nt + 1> slot{};
        std::uint32_t slots = 0;
        for (std::size_t g = 0; g < comps.count; ++g)
            if (needed[g]) slot[g] = slots++;

        auto rewrite = [&](const term& t, int sign) {
            op_term o;
            o.degree = t.degree;
            o.c = t.c * rational{sign, 1};
            for (std::uint32_t d = 0; d < t.degree; ++d) {
                if (source_of(t.f[d]) & intermediate_bit) o.f[d] = tmp_flag | slot[global_component(t.f[d])];
                else if (is_looped_source(source_of(t.f[d]))) o.f[d] = looped_slot(source_of(t.f[d])) << leaf_shift | component_of(t.f[d]);
                else o.f[d] = static_cast<std::uint32_t>(source_of(t.f[d])) << leaf_shift | component_of(t.f[d]);
            }
            return o;
        };

        // 3. the assignments: temporaries in order, then the target's components
        program_data<capacity_terms, capacity_assign> p;
        std::size_t a = 0;
        for (std::size_t g = 0; g < comps.count; ++g) {
            if (!needed[g]) continue;
            for (std::size_t u = comps.first_term[g]; u < comps.first_term[g + 1]; ++u)
                p.terms[p.term_count++] = rewrite(flat::terms[u], 1);
            p.offsets[++a] = static_cast<std::uint32_t>(p.term_count);
        }
        p.tmp_count = a;
        for (std::size_t r = 0; r < TL.size(); ++r) {
            // root terms are sorted canonically by output blade: find this blade's run
            const blade_mask m = TL.masks[r];
            std::size_t lo = 0, hi = root_outs.size();
            while (lo < hi) {
                const std::size_t mid = (lo + hi) / 2;
                if (canonical_less(root_outs[mid], m)) lo = mid + 1; else hi = mid;
            }
            for (std::size_t q = lo; q < root_outs.size() && root_outs[q] == m; ++q)
                p.terms[p.term_count++] = rewrite(root_terms[q], TL.signs[r]);
            p.offsets[++a] = static_cast<std::uint32_t>(p.term_count);
        }
        p.assignment_count = a;

        return p;
    }();

    static constexpr std::size_t tmp_count = draft.tmp_count;
    static constexpr std::size_t assignment_count = draft.assignment_count;

    static constexpr auto terms = [] {
        std::array<op_term, (draft.term_count > 0 ? draft.term_count : 1)> t{};
        for (std::size_t i = 0; i < draft.term_count; ++i) t[i] = draft.terms[i];
        return t;
    }();
    static constexpr auto offsets = [] {
        std::array<std::uint32_t, assignment_count + 1> o{};
        for (std::size_t i = 0; i <= assignment_count; ++i) o[i] = draft.offsets[i];
        return o;
    }();

    template <class... Ls>
    static constexpr cost looped_prices(type_list<Ls...>) {
        return (looped_price<Ls>::value + ... + cost{});
    }

    // What the program costs (computed only when asked for, by cost_of), the looped products it
    // reads included.
    static constexpr cost price = [] {
        return looped_prices(looped_list{}) + assignments_price(terms.data(), offsets.data(), assignment_count);
    }();
};

// A looped product: one multiplication and one addition per pair; its operands' own programs
// (a leaf is read in place, for nothing).
template <class X>
constexpr cost operand_price() {
    if constexpr (read_in_place<X>) return cost{};
    else return program<X, node_layout<X>>::price;
}
template <class Rule, class X, class Y>
struct looped_price<looped<Rule, X, Y>> {
    using rows = rows_of<Rule, X, Y>;
    static constexpr cost value = [] {
        return cost{rows::pairs, rows::pairs} + operand_price<X>() + operand_price<Y>();
    }();
};

}  // namespace ctga::expr
