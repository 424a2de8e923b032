// The Jacobian of a straight-line program, as one straight-line program (forward differentiation
// at compile time).
//
// A program (program.hpp) is a list of assignments a_k = Σ c · Π factors, each factor a leaf's
// component or an earlier temporary. Differentiating with respect to a leaf component x_j is the
// chain rule along the list, once per column j:
//
//   ∂a_k/∂x_j = Σ_terms c · Σ_i (Π_{l≠i} f_l) · ∂f_i/∂x_j,   ∂f_i/∂x_j = 1 (f_i = x_j), 0 (another
//               leaf), or the temporary ∂t/∂x_j (f_i = t, computed before it, when not zero)
//
// so every column of the Jacobian is one more list of assignments over the same leaves, and all
// of them go into one program: the value's temporaries (the staged subexpressions: P = A ∨ (N ∧ s)
// in the equations of motion) are computed once and shared by every column, and a column only
// adds the derivatives of the temporaries it depends on. Equal monomials merge and zeros vanish
// as in the normal form (x·x gives 2x), so an entry with no terms is a structural zero: the
// pattern of the Jacobian is read off the program. No normal form is built per column: the
// compile-time work is one pass over the value's program.
//
// (Looped products, whose values a program reads as further leaves, are not in the list; their
// derivatives come from the expression tree, expr/derivative.hpp.)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "ctga/expr/program.hpp"
#include "ctga/support/sort.hpp"

namespace ctga::expr {

namespace differentiate_detail {

inline constexpr std::uint32_t none = ~std::uint32_t{0};

constexpr bool factors_less(const op_term& a, const op_term& b) {
    if (a.degree != b.degree) return a.degree < b.degree;
    for (std::uint32_t k = 0; k < a.degree; ++k)
        if (a.f[k] != b.f[k]) return a.f[k] < b.f[k];
    return false;
}
constexpr bool same_factors(const op_term& a, const op_term& b) {
    return a.degree == b.degree && !factors_less(a, b) && !factors_less(b, a);
}
// factors in ascending order, so that equal monomials compare equal
constexpr void sort_factors(op_term& o) {
    for (std::uint32_t i = 1; i < o.degree; ++i)
        for (std::uint32_t j = i; j > 0 && o.f[j] < o.f[j - 1]; --j) {
            const std::uint32_t x = o.f[j];
            o.f[j] = o.f[j - 1];
            o.f[j - 1] = x;
        }
}

// Sort terms [b, n), merge equal monomials, drop zeros; the new end.
constexpr std::size_t merge_terms(op_term* t, std::size_t b, std::size_t n) {
    detail::merge_sort(t + b, n - b, factors_less);
    std::size_t w = b;
    for (std::size_t r = b; r < n;) {
        op_term acc = t[r++];
        while (r < n && same_factors(acc, t[r])) acc.c = acc.c + t[r++].c;
        if (!is_zero(acc.c)) t[w++] = acc;
    }
    return w;
}

}  // namespace differentiate_detail

// The Jacobian of program P (no looped products) with respect to the leaf components Columns
// (each a factor code, leaf << leaf_shift | component). Its outputs are the structurally
// non-zero entries, column by column, rows in the order of P's outputs: `rows_of[k]`,
// `column_begin[c]`. A program itself (terms, offsets, tmp_count, assignment_count), run by
// run.hpp like any other.
template <class P, auto Columns>
struct program_jacobian {
    static_assert(P::looped_count == 0, "ctga: program_jacobian differentiates programs without looped products");
    static constexpr std::size_t cols = Columns.size();
    static constexpr std::size_t value_tmps = P::tmp_count;
    static constexpr std::size_t rows = P::assignment_count - P::tmp_count;

    // bounds: each term of degree d gives at most d terms per column
    static constexpr std::size_t degree_total = [] {
        std::size_t n = 0;
        for (const op_term& o : P::terms) n += o.degree;
        return n;
    }();
    static constexpr std::size_t capacity_terms = P::terms.size() + degree_total * cols + 1;
    static constexpr std::size_t capacity_assign = value_tmps * (cols + 1) + rows * cols;

    struct draft_t {
        program_data<capacity_terms, capacity_assign> p;
        std::array<std::uint16_t, rows * cols + 1> row{};
        std::array<std::uint32_t, cols + 1> column_begin{};
        std::size_t non_zeros = 0;
    };

    static constexpr draft_t draft = [] {
        using namespace differentiate_detail;
        constexpr std::size_t A = P::assignment_count;
        // 1. every assignment's derivative per column, as term lists in one buffer; a derivative
        //    temporary (value temporary k, column c) gets an index when it is not zero
        op_term* buf = new op_term[capacity_terms];
        std::uint32_t* begin = new std::uint32_t[A * cols + 1];   // list of (a, c): [begin, end)
        std::uint32_t* end = new std::uint32_t[A * cols + 1];
        std::uint32_t* dtmp = new std::uint32_t[value_tmps * cols + 1];  // derivative temporary (k, c), or none
        // a derivative of one term of degree ≤ 1 (±x_i, a constant, c · another temporary) is
        // not stored: it is substituted where it is read
        op_term* alias = new op_term[value_tmps * cols + 1];
        bool* aliased = new bool[value_tmps * cols + 1]{};
        std::uint32_t dcount = 0;
        std::size_t n = 0;
        for (std::size_t a = 0; a < A; ++a)
            for (std::size_t c = 0; c < cols; ++c) {
                const std::size_t b = n;
                for (std::uint32_t t = P::offsets[a]; t < P::offsets[a + 1]; ++t) {
                    const op_term& o = P::terms[t];
                    for (std::uint32_t i = 0; i < o.degree; ++i) {
                        op_term d = o;
                        if (o.f[i] & tmp_flag) {
                            const std::uint32_t k = o.f[i] & ~tmp_flag;
                            if (aliased[k * cols + c]) {
                                const op_term& x = alias[k * cols + c];
                                d.c = d.c * x.c;
                                if (x.degree == 1) {
                                    d.f[i] = x.f[0];
                                } else {
                                    for (std::uint32_t l = i; l + 1 < o.degree; ++l) d.f[l] = o.f[l + 1];
                                    d.f[o.degree - 1] = 0;
                                    --d.degree;
                                }
                            } else if (dtmp[k * cols + c] != none) {
                                d.f[i] = tmp_flag | static_cast<std::uint32_t>(value_tmps + dtmp[k * cols + c]);
                            } else {
                                continue;
                            }
                        } else if (o.f[i] == Columns[c]) {
                            for (std::uint32_t l = i; l + 1 < o.degree; ++l) d.f[l] = o.f[l + 1];
                            d.f[o.degree - 1] = 0;
                            --d.degree;
                        } else {
                            continue;
                        }
                        sort_factors(d);
                        buf[n++] = d;
                    }
                }
                n = merge_terms(buf, b, n);
                begin[a * cols + c] = static_cast<std::uint32_t>(b);
                end[a * cols + c] = static_cast<std::uint32_t>(n);
                if (a < value_tmps) {
                    dtmp[a * cols + c] = none;
                    if (n == b + 1 && buf[b].degree <= 1) {
                        alias[a * cols + c] = buf[b];
                        aliased[a * cols + c] = true;
                        n = b;
                    } else if (n > b) {
                        dtmp[a * cols + c] = dcount++;
                    }
                }
            }

        // 2. which temporaries the entries need: value temporaries 0…, then derivative ones
        const std::size_t tmps = value_tmps + dcount;
        bool* needed = new bool[tmps + 1]{};
        auto mark = [&](const op_term& o) {
            for (std::uint32_t i = 0; i < o.degree; ++i)
                if (o.f[i] & tmp_flag) needed[o.f[i] & ~tmp_flag] = true;
        };
        for (std::size_t r = 0; r < rows; ++r)
            for (std::size_t c = 0; c < cols; ++c)
                for (std::uint32_t t = begin[(value_tmps + r) * cols + c]; t < end[(value_tmps + r) * cols + c]; ++t) mark(buf[t]);
        // a temporary's own terms: a derivative temporary (k, c) is listed after every temporary it
        // reads, so one backward sweep over (derivative temporaries, then value temporaries) marks all
        for (std::size_t k = value_tmps; k-- > 0;)
            for (std::size_t c = cols; c-- > 0;)
                if (dtmp[k * cols + c] != none && needed[value_tmps + dtmp[k * cols + c]])
                    for (std::uint32_t t = begin[k * cols + c]; t < end[k * cols + c]; ++t) mark(buf[t]);
        for (std::size_t k = value_tmps; k-- > 0;)
            if (needed[k])
                for (std::uint32_t t = P::offsets[k]; t < P::offsets[k + 1]; ++t) mark(P::terms[t]);

        // 3. slots for the needed temporaries, in an order that computes each after what it
        //    reads: the value temporaries, then the derivative temporaries
        std::uint32_t* slot = new std::uint32_t[tmps + 1];
        std::uint32_t slots = 0;
        for (std::size_t k = 0; k < tmps; ++k) slot[k] = needed[k] ? slots++ : none;
        auto rewrite = [&](op_term o) {
            for (std::uint32_t i = 0; i < o.degree; ++i)
                if (o.f[i] & tmp_flag) o.f[i] = tmp_flag | slot[o.f[i] & ~tmp_flag];
            return o;
        };

        draft_t out;
        program_data<capacity_terms, capacity_assign>& p = out.p;
        std::size_t x = 0;
        auto emit = [&](std::uint32_t b, std::uint32_t e, const op_term* from) {
            for (std::uint32_t t = b; t < e; ++t) p.terms[p.term_count++] = rewrite(from[t]);
            p.offsets[++x] = static_cast<std::uint32_t>(p.term_count);
        };
        for (std::size_t k = 0; k < value_tmps; ++k)
            if (needed[k]) emit(P::offsets[k], P::offsets[k + 1], P::terms.data());
        for (std::size_t k = 0; k < value_tmps; ++k)
            for (std::size_t c = 0; c < cols; ++c)
                if (dtmp[k * cols + c] != none && needed[value_tmps + dtmp[k * cols + c]])
                    emit(begin[k * cols + c], end[k * cols + c], buf);
        p.tmp_count = x;
        // 4. the entries, column by column
        for (std::size_t c = 0; c < cols; ++c) {
            out.column_begin[c] = static_cast<std::uint32_t>(out.non_zeros);
            for (std::size_t r = 0; r < rows; ++r) {
                const std::size_t a = (value_tmps + r) * cols + c;
                if (end[a] == begin[a]) continue;
                out.row[out.non_zeros++] = static_cast<std::uint16_t>(r);
                emit(begin[a], end[a], buf);
            }
        }
        out.column_begin[cols] = static_cast<std::uint32_t>(out.non_zeros);
        p.assignment_count = x;

        delete[] buf;
        delete[] begin;
        delete[] end;
        delete[] dtmp;
        delete[] alias;
        delete[] aliased;
        delete[] needed;
        delete[] slot;
        return out;
    }();

    static constexpr std::size_t non_zeros = draft.non_zeros;
    static constexpr std::size_t tmp_count = draft.p.tmp_count;
    static constexpr std::size_t assignment_count = draft.p.assignment_count;
    static constexpr auto terms = [] {
        std::array<op_term, (draft.p.term_count > 0 ? draft.p.term_count : 1)> t{};
        for (std::size_t i = 0; i < draft.p.term_count; ++i) t[i] = draft.p.terms[i];
        return t;
    }();
    static constexpr auto offsets = [] {
        std::array<std::uint32_t, assignment_count + 1> o{};
        for (std::size_t i = 0; i <= assignment_count; ++i) o[i] = draft.p.offsets[i];
        return o;
    }();
    static constexpr cost price = [] { return assignments_price(terms.data(), offsets.data(), assignment_count); }();
};

}  // namespace ctga::expr
