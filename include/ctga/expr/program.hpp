// From a root node and a target layout to straight-line code.
//
// Assembly (compile time): the intermediates the root's normal form refers to, repeats removed
// (the same subexpression is one intermediate), in dependency order. Output pruning: only the
// target's blades are computed, and of each intermediate only the components some needed term
// reads, transitively. The result is a program: a list of assignments, first the temporaries,
// then the target's components, each a sum of coefficient · monomial terms.
//
// Execution (run time): every assignment is one loop over its constexpr terms, fully unrolled,
// so the compiler sees plain arithmetic on the operands' storage and on local temporaries.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "ctga/expr/inline.hpp"
#include "ctga/expr/nodes.hpp"
#include "ctga/expr/normal_form.hpp"

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
        ((std::copy(traits<Cs>::terms.begin(), traits<Cs>::terms.end(), a.begin() + static_cast<std::ptrdiff_t>(k)),
          k += traits<Cs>::terms.size()),
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

// Assemble the program computing target layout TL from root node Root.
template <class Root, auto TL>
struct program {
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

    // What the program costs (computed only when asked for, by cost_of).
    static constexpr cost price = [] {
        cost c;
        // 4. the price: additions per assignment; multiplications counting each distinct
        //    monomial prefix once (the same leaf product is computed once), plus coefficients
        std::vector<std::uint64_t> prefixes;
        for (std::size_t x = 0; x < assignment_count; ++x)
            for (std::uint32_t t = offsets[x]; t < offsets[x + 1]; ++t) {
                const op_term& o = terms[t];
                if (t > offsets[x]) ++c.add;
                if (o.degree >= 1 && !is_unit(o.c)) ++c.mul;
                std::uint64_t h = o.degree > 0 ? mix(0x7f, o.f[0]) : 0;
                for (std::uint32_t len = 2; len <= o.degree; ++len) prefixes.push_back(h = mix(h, o.f[len - 1]));
            }
        std::sort(prefixes.begin(), prefixes.end());
        c.mul += static_cast<std::size_t>(std::unique(prefixes.begin(), prefixes.end()) - prefixes.begin());
        return c;
    }();
};

// ---- execution ---------------------------------------------------------------------------

#if defined(__clang__)
#define CTGA_UNROLL_TERMS _Pragma("clang loop unroll(full)")
#elif defined(__GNUC__)
#define CTGA_UNROLL_TERMS _Pragma("GCC unroll 1024")
#else
#define CTGA_UNROLL_TERMS
#endif

// GCC 12 at -O2 can report a bogus -Warray-bounds on these reads once whole expressions are
// inlined: every index is a compile-time constant of the program and within bounds (checked
// under AddressSanitizer in the tests), so the warning is off for these lines only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
#endif

// |c| in T: an integer, or a quotient (in T when T divides, else rounded from long double).
template <class T>
constexpr T coefficient(const rational& c) {
    const std::int64_t n = c.num < 0 ? -c.num : c.num;
    if (c.den == 1) return T(n);
    if constexpr (requires(const T& a) { a / a; }) return T(n) / T(c.den);
    else return T(static_cast<long double>(n) / static_cast<long double>(c.den));
}

template <class T>
CTGA_ALWAYS_INLINE constexpr T factor_value(std::uint32_t f, const T* const* leaves, const T* tmp) noexcept {
    return (f & tmp_flag) ? tmp[f & ~tmp_flag] : leaves[f >> leaf_shift][f & ((1u << leaf_shift) - 1)];
}

// |c| · Π factors, the sign left to the caller (a subtraction instead of a negation).
template <class T>
CTGA_ALWAYS_INLINE constexpr T term_magnitude(const op_term& o, const T* const* leaves, const T* tmp) noexcept {
    if (o.degree == 0) return coefficient<T>(o.c);
    T v = factor_value<T>(o.f[0], leaves, tmp);
    CTGA_UNROLL_TERMS
    for (std::uint32_t d = 1; d < o.degree; ++d) v = v * factor_value<T>(o.f[d], leaves, tmp);
    if (!is_unit(o.c)) v = v * coefficient<T>(o.c);
    return v;
}

// The signed sum of terms I ∈ [B, E) of assignment A of program P (negated when Negate), as a
// balanced tree: the compiler may not reassociate floating-point additions, and one left-to-right
// chain over the thirty terms of a kinetic energy is a chain of thirty dependent additions. Term
// I is the assignment's term (I + R) mod n: the rotation R puts a positive term first when there
// is one, so that a − b is computed as a − b and not as −b + a. A half whose first term is
// negative is subtracted with its signs flipped, so no other negation is ever needed.
template <class P, std::size_t A>
struct assignment_terms {
    static constexpr std::uint32_t begin = P::offsets[A];
    static constexpr std::uint32_t n = P::offsets[A + 1] - begin;
    static constexpr std::uint32_t rotation = [] {
        for (std::uint32_t i = 0; i < n; ++i)
            if (P::terms[begin + i].c.num > 0) return i;
        return std::uint32_t{0};
    }();
    static constexpr const op_term& at(std::uint32_t i) noexcept { return P::terms[begin + (i + rotation) % n]; }
};

template <class T, class P, std::size_t A, std::uint32_t B, std::uint32_t E, bool Negate>
CTGA_ALWAYS_INLINE constexpr T range_sum(const T* const* leaves, const T* tmp) noexcept {
    using terms = assignment_terms<P, A>;
    if constexpr (E - B == 1) {
        const T v = term_magnitude<T>(terms::at(B), leaves, tmp);
        if constexpr ((terms::at(B).c.num < 0) != Negate) return T(-v);
        else return v;
    } else {
        constexpr std::uint32_t M = B + (E - B) / 2;
        const T left = range_sum<T, P, A, B, M, Negate>(leaves, tmp);
        if constexpr ((terms::at(M).c.num < 0) != Negate) return left - range_sum<T, P, A, M, E, !Negate>(leaves, tmp);
        else return left + range_sum<T, P, A, M, E, Negate>(leaves, tmp);
    }
}

// Assignment A of program P: its terms summed (from a term, not from zero: x + 0.0 is not x for
// x = −0.0, so a zero start would cost an addition the compiler may not remove).
template <class T, class P, std::size_t A>
CTGA_ALWAYS_INLINE constexpr T assignment(const T* const* leaves, const T* tmp) noexcept {
    constexpr std::uint32_t n = assignment_terms<P, A>::n;
    if constexpr (n == 0) return T{};
    else return range_sum<T, P, A, 0, n, false>(leaves, tmp);
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#undef CTGA_UNROLL_TERMS

// Run program P on the leaves' storage: the temporaries in order, then the N outputs.
template <class T, class P, std::size_t... A>
CTGA_ALWAYS_INLINE constexpr void run_temporaries([[maybe_unused]] T* tmp, [[maybe_unused]] const T* const* leaves,
                                                     std::index_sequence<A...>) noexcept {
    ((tmp[A] = assignment<T, P, A>(leaves, tmp)), ...);
}

template <class T, class P, std::size_t N, std::size_t... R>
CTGA_ALWAYS_INLINE constexpr std::array<T, N> run_outputs([[maybe_unused]] const T* tmp, [[maybe_unused]] const T* const* leaves,
                                                              std::index_sequence<R...>) noexcept {
    return std::array<T, N>{assignment<T, P, P::tmp_count + R>(leaves, tmp)...};
}

template <class T, class P, std::size_t N>
CTGA_ALWAYS_INLINE constexpr std::array<T, N> run(const T* const* leaves) noexcept {
    std::array<T, (P::tmp_count > 0 ? P::tmp_count : 1)> tmp{};
    run_temporaries<T, P>(tmp.data(), leaves, std::make_index_sequence<P::tmp_count>{});
    return run_outputs<T, P, N>(tmp.data(), leaves, std::make_index_sequence<N>{});
}

// Up to this many terms a program runs as the unrolled straight-line code above, inlined into
// the caller (always: left to its heuristics GCC stops inlining inside a large caller, a whole
// equation of motion, and calls term_magnitude once per term). A larger program runs as one
// loop over its constexpr terms in a function of its own: unrolling thousands of terms into the
// caller made the property suites' build three times as long (toolchain.md: a 256×256 product
// took 120 s unrolled against 11 s as a loop).
inline constexpr std::size_t inline_terms = 64;

template <class T, class P, std::size_t N>
[[gnu::noinline]] constexpr std::array<T, N> run_looped(const T* const* leaves) noexcept {
    std::array<T, (P::tmp_count > 0 ? P::tmp_count : 1)> tmp{};
    std::array<T, N> out{};
    for (std::size_t a = 0; a < P::tmp_count + N; ++a) {
        T acc{};
        for (std::uint32_t t = P::offsets[a]; t < P::offsets[a + 1]; ++t) {
            const op_term& o = P::terms[t];
            const T v = term_magnitude<T>(o, leaves, tmp.data());
            if (t == P::offsets[a]) acc = o.c.num < 0 ? T(-v) : v;  // from the first term, as above
            else acc = o.c.num < 0 ? acc - v : acc + v;
        }
        (a < P::tmp_count ? tmp[a] : out[a - P::tmp_count]) = acc;
    }
    return out;
}

}  // namespace ctga::expr
