// Products past the unrolling threshold. A bilinear product whose operands' blades form more
// surviving pairs than loop_threshold is not multiplied out symbolically: its operands are
// evaluated on their own (each by its own program, or read in place when it is a leaf), then
// one loop runs over a table, built at compile time, of the blade pairs the rule does not kill
// (in Cl(0,6,2) the squares e0² = e² = 0 remove 7 of every 16 pairs of the geometric product).
// The result type is still exact: an output blade is in the layout iff some pair makes it, and
// for two distinct operands the pairs of one output are distinct monomials x_i y_j, which
// cannot cancel. What is given up is the cancellation across the product's boundary that a
// formula with a repeated argument could show (a ∧ a = 0); below the threshold the symbolic
// engine still finds it.
//
// The table lists, per output blade, the pairs that add and then those that subtract, each
// pair packed as x index << 16 | y index. Building it costs two passes over the blade pairs
// at compile time (a census per output blade, then the placement), no sort and no term lists:
// the full 256 × 256 geometric product of Cl(0,6,2) is 65,536 rule applications and a table of
// 36,864 pairs.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "ctga/algebra/layout.hpp"
#include "ctga/algebra/rules.hpp"
#include "ctga/expr/nodes.hpp"
#include "ctga/expr/normal_form.hpp"
#include "ctga/expr/staging.hpp"
#include "ctga/support/inline.hpp"

// The number of surviving blade pairs above which a product is looped instead of unrolled
// (see expr::loop_threshold). Define it before including ctga to move the threshold for a
// whole program; ctga::looped(x) and ctga::unrolled(x) choose for one expression.
#ifndef CTGA_LOOP_THRESHOLD
#define CTGA_LOOP_THRESHOLD 1024
#endif

namespace ctga::expr {

// Above this many surviving blade pairs a product node loops over a table. Up to it the node
// is multiplied out symbolically (cancellations found, straight-line code, each pair one term
// of the program); past it the symbolic terms cost far more to compile than the loop costs to
// run (docs/engine.md, "Unrolled or looped").
inline constexpr std::size_t loop_threshold = CTGA_LOOP_THRESHOLD;
static_assert(loop_threshold <= term_budget, "ctga: CTGA_LOOP_THRESHOLD cannot exceed expr::term_budget");

// Whether a product node is formed by the engine's choice, or forced either way.
enum class product_mode { by_threshold, unrolled, looped };

template <auto L>
constexpr blade_mask all_bits() {
    blade_mask u = 0;
    for (blade_mask m : L.masks) u |= m;
    return u;
}

// Surviving blade pairs of two layouts under a bilinear rule, stopping once past `limit`.
template <class Rule, auto LX, auto LY>
constexpr std::size_t surviving_pairs(std::size_t limit) {
    std::size_t n = 0;
    for (blade_mask a : LX.masks)
        for (blade_mask b : LY.masks)
            if (Rule::apply(a, b).sign != 0 && ++n > limit) return n;
    return n;
}

// Looped when more than loop_threshold pairs survive, or when the operands' blades make more
// pairs than the symbolic engine multiplies out at all (expr::term_budget; the scalar product
// of two general multivectors keeps few of them).
// (The operands' normal forms, which the product needs anyway, bound their blades: the common
// case is decided without computing their layouts, which can take a full expansion.)
template <class Rule, class X, class Y>
constexpr bool worth_looping() {
    if constexpr (traits<X>::terms.size() * traits<Y>::terms.size() <= loop_threshold) {
        return false;
    } else {
        constexpr auto& lx = node_layout<X>;
        constexpr auto& ly = node_layout<Y>;
        if constexpr (lx.size() * ly.size() <= loop_threshold) return false;
        else if constexpr (lx.size() * ly.size() > term_budget) return true;
        else return surviving_pairs<Rule, lx, ly>(loop_threshold) > loop_threshold;
    }
}

// The node a bilinear product of X and Y becomes.
template <class Rule, class X, class Y, product_mode M = product_mode::by_threshold>
using product_node =
    std::conditional_t<M == product_mode::looped || (M == product_mode::by_threshold && worth_looping<Rule, X, Y>()),
                       looped<Rule, X, Y>, product<Rule, X, Y>>;

// ---- the table: per row of the left operand, the surviving columns as bit sets -----------------

// A set of positions as 64-bit words.
template <std::size_t Words>
using bitset_words = std::array<std::uint64_t, Words>;

// The set {p ^ t : p in s} of a set of blade masks: for each generator g of t, positions p and
// p ^ 2^g trade places (within a word for g < 6, whole words for g ≥ 6).
template <std::size_t W>
constexpr void xor_translate(std::uint64_t* s, blade_mask t) noexcept {
    constexpr std::uint64_t low[6] = {0x5555555555555555u, 0x3333333333333333u, 0x0f0f0f0f0f0f0f0fu,
                                      0x00ff00ff00ff00ffu, 0x0000ffff0000ffffu, 0x00000000ffffffffu};
    for (int g = 0; t >> g; ++g) {
        if (!((t >> g) & 1u)) continue;
        if (g < 6) {
            const unsigned shift = 1u << g;
            for (std::size_t w = 0; w < W; ++w) s[w] = ((s[w] & low[g]) << shift) | ((s[w] >> shift) & low[g]);
        } else {
            const std::size_t block = std::size_t{1} << (g - 6);
            for (std::size_t w = 0; w < W; ++w)
                if (!(w & block)) {
                    const std::uint64_t keep = s[w];
                    s[w] = s[w | block];
                    s[w | block] = keep;
                }
        }
    }
}

// LX, LY are the operands' storage layouts (a leaf's own, with its orientations, or the
// canonical layout of an evaluated operand). Row i of the table holds two sets of columns j of
// LY: the pairs (i, j) that add to output blade lead[i] ^ LY.masks[j] and those that subtract
// from it. Built from the rule's row form (rules.hpp) with word-wide operations on sets: for
// each generator, the columns whose blade holds it; no rule application per pair. (Raw pointers
// and few calls in the loops: std::array::operator[] is a function call, and each call costs
// GCC's constant evaluator more than the loop body does.)
template <class Rule, auto LX, auto LY>
struct pair_rows {
    static constexpr std::size_t generators = std::bit_width(all_bits<LX>() | all_bits<LY>());
    static constexpr std::size_t universe = std::size_t{1} << generators;
    static constexpr std::size_t universe_words = (universe + 63) / 64;
    static constexpr std::size_t rows = LX.size();
    static constexpr std::size_t columns = LY.size();
    static constexpr std::size_t column_words = columns > 0 ? (columns + 63) / 64 : 1;

    struct data {
        std::array<std::uint64_t, (rows > 0 ? rows : 1) * column_words> add{}, subtract{};
        std::array<blade_mask, (rows > 0 ? rows : 1)> lead{};  // a ^ flip of the row's rule form
        bitset_words<universe_words> made{};                   // the output blades some pair makes
    };
    static constexpr data value = [] {
        data d;
        constexpr std::size_t G = generators > 0 ? generators : 1;
        constexpr std::size_t CW = column_words, UW = universe_words;
        const blade_mask* ym = LY.masks.data();
        // the columns: all of them, those stored negated, and for each generator g (at g · CW)
        // those whose blade holds g
        std::array<std::uint64_t, CW> all_columns{}, negated_columns{};
        std::array<std::uint64_t, G * CW> holds_columns{};
        std::uint64_t* all = all_columns.data();
        std::uint64_t* negated = negated_columns.data();
        std::uint64_t* holds = holds_columns.data();
        for (std::size_t j = 0; j < columns; ++j) {
            const std::uint64_t bit = std::uint64_t{1} << (j % 64);
            all[j / 64] |= bit;
            if (LY.signs[j] < 0) negated[j / 64] |= bit;
            for (std::size_t g = 0; g < generators; ++g)
                if ((ym[j] >> g) & 1u) holds[g * CW + j / 64] |= bit;
        }
        // the blades of LY as a set of masks, and for each generator the masks holding it
        std::array<std::uint64_t, UW> in_y_masks{};
        std::array<std::uint64_t, G * UW> holds_masks{};
        std::uint64_t* in_y = in_y_masks.data();
        std::uint64_t* mask_holds = holds_masks.data();
        for (std::size_t j = 0; j < columns; ++j) in_y[ym[j] / 64] |= std::uint64_t{1} << (ym[j] % 64);
        for (std::size_t m = 0; m < universe; ++m)
            for (std::size_t g = 0; g < generators; ++g)
                if ((m >> g) & 1u) mask_holds[g * UW + m / 64] |= std::uint64_t{1} << (m % 64);

        std::array<std::uint64_t, CW> alive_words{}, odd_words{};
        std::array<std::uint64_t, UW> out_words{};
        std::uint64_t* alive = alive_words.data();
        std::uint64_t* odd = odd_words.data();
        std::uint64_t* out = out_words.data();
        std::uint64_t* made = d.made.data();
        for (std::size_t r = 0; r < rows; ++r) {
            const rules::row_form f = Rule::row(LX.masks[r]);
            const blade_mask lead = LX.masks[r] ^ f.flip;
            d.lead[r] = lead;
            if (f.want & ~f.care) continue;  // a dead row
            // surviving columns: (b & care) == want; signs: parity of b & f.parity, the stored
            // orientations of both operands, and the row's constant sign
            for (std::size_t w = 0; w < CW; ++w) {
                alive[w] = all[w];
                odd[w] = negated[w];
            }
            for (std::size_t w = 0; w < UW; ++w) out[w] = in_y[w];
            for (std::size_t g = 0; g < generators; ++g) {
                if ((f.care >> g) & 1u) {
                    const std::uint64_t* h = holds + g * CW;
                    const std::uint64_t* hm = mask_holds + g * UW;
                    if ((f.want >> g) & 1u) {
                        for (std::size_t w = 0; w < CW; ++w) alive[w] &= h[w];
                        for (std::size_t w = 0; w < UW; ++w) out[w] &= hm[w];
                    } else {
                        for (std::size_t w = 0; w < CW; ++w) alive[w] &= ~h[w];
                        for (std::size_t w = 0; w < UW; ++w) out[w] &= ~hm[w];
                    }
                }
                if ((f.parity >> g) & 1u) {
                    const std::uint64_t* h = holds + g * CW;
                    for (std::size_t w = 0; w < CW; ++w) odd[w] ^= h[w];
                }
            }
            const std::uint64_t flip_all = f.sign * LX.signs[r] < 0 ? ~std::uint64_t{0} : 0;
            std::uint64_t* add = d.add.data() + r * CW;
            std::uint64_t* subtract = d.subtract.data() + r * CW;
            for (std::size_t w = 0; w < CW; ++w) {
                const std::uint64_t negative = odd[w] ^ flip_all;
                add[w] = alive[w] & ~negative;
                subtract[w] = alive[w] & negative;
            }
            // the output blades of this row: LY's blades with (b & care) == want, moved by lead
            xor_translate<UW>(out, lead);
            for (std::size_t w = 0; w < UW; ++w) made[w] |= out[w];
        }
        return d;
    }();
    // the surviving pairs (for the cost model only)
    static constexpr std::size_t pairs = [] {
        std::size_t n = 0;
        for (std::uint64_t w : value.add) n += static_cast<std::size_t>(std::popcount(w));
        for (std::uint64_t w : value.subtract) n += static_cast<std::size_t>(std::popcount(w));
        return n;
    }();

    static constexpr bool makes(std::size_t m) { return (value.made[m / 64] >> (m % 64)) & 1u; }
    // the blades some pair makes, canonical (by grade, then mask)
    static constexpr std::size_t output_count = [] {
        std::size_t n = 0;
        for (std::uint64_t w : value.made) n += static_cast<std::size_t>(std::popcount(w));
        return n;
    }();
    static constexpr layout<output_count> outputs = [] {
        layout<output_count> l;
        std::size_t k = 0;
        for (std::size_t g = 0; g <= generators; ++g)
            for (std::size_t m = 0; m < universe; ++m)
                if (static_cast<std::size_t>(blade_grade(static_cast<blade_mask>(m))) == g && makes(m)) {
                    l.masks[k] = static_cast<blade_mask>(m);
                    l.signs[k++] = 1;
                }
        return l;
    }();
};

// ---- the loop ----------------------------------------------------------------------------------

// Row by row: x_i once, then each surviving y_j times it added to (or subtracted from) its
// output blade's accumulator. Within a row every pair has its own output blade (a ^ b is one to
// one in b), so the additions of a row do not wait on each other.
template <class T, std::size_t Words, bool Subtract, bool Identity>
CTGA_ALWAYS_INLINE constexpr void run_set(const std::uint64_t* set, blade_mask lead, const blade_mask* ym, T xi,
                                          const T* y, T* acc) noexcept {
    for (std::size_t w = 0; w < Words; ++w)
        for (std::uint64_t bits = set[w]; bits != 0; bits &= bits - 1) {
            const std::size_t j = w * 64 + static_cast<std::size_t>(std::countr_zero(bits));
            T& a = acc[lead ^ (Identity ? static_cast<blade_mask>(j) : ym[j])];
            if constexpr (Subtract) a -= xi * y[j];
            else a += xi * y[j];
        }
}

template <auto L>
inline constexpr bool identity_layout = [] {
    for (std::size_t j = 0; j < L.size(); ++j)
        if (L.masks[j] != j) return false;
    return true;
}();

// x ∘ y into output layout OL (any blades, in any orientation: a target type's).
template <class T, class Rows, auto LY, auto OL>
constexpr std::array<T, OL.size()> run_rows(const T* x, const T* y) noexcept {
    std::array<T, Rows::universe> acc{};
    constexpr std::size_t W = Rows::column_words;
    const auto& d = Rows::value;
    for (std::size_t r = 0; r < Rows::rows; ++r) {
        constexpr bool identity = identity_layout<LY>;  // column j is blade j: no lookup
        run_set<T, W, false, identity>(d.add.data() + r * W, d.lead[r], LY.masks.data(), x[r], y, acc.data());
        run_set<T, W, true, identity>(d.subtract.data() + r * W, d.lead[r], LY.masks.data(), x[r], y, acc.data());
    }
    std::array<T, OL.size()> out{};
    for (std::size_t k = 0; k < OL.size(); ++k)
        if (OL.masks[k] < Rows::universe) out[k] = OL.signs[k] > 0 ? acc[OL.masks[k]] : T(-acc[OL.masks[k]]);
    return out;
}

// ---- the looped node in the engine ----------------------------------------------------------

// A looped product's value enters the expressions around it as a source of its own, like a
// leaf: one degree-1 term per output blade.
inline constexpr source_id looped_bit = source_id{1} << 42;
constexpr source_id looped_id(std::uint64_t hash) { return looped_bit | (hash & (looped_bit - 1)); }
constexpr bool is_looped_source(source_id s) { return (s & intermediate_bit) == 0 && (s & looped_bit) != 0; }

// An operand's storage layout: a leaf is read in place, anything else is evaluated into the
// canonical layout of its blades.
template <class X>
inline constexpr bool read_in_place = false;
template <std::size_t I, auto L>
inline constexpr bool read_in_place<leaf<I, L>> = true;
template <std::size_t I, auto L>
inline constexpr bool read_in_place<arg<I, L>> = true;
template <class X>
inline constexpr std::size_t leaf_index = 0;
template <std::size_t I, auto L>
inline constexpr std::size_t leaf_index<leaf<I, L>> = I;

template <class N>
inline constexpr bool is_looped_node = false;
template <class R, class X, class Y>
inline constexpr bool is_looped_node<looped<R, X, Y>> = true;

template <class X>
inline constexpr auto operand_layout = node_layout<X>;
template <std::size_t I, auto L>
inline constexpr auto operand_layout<leaf<I, L>> = L;
template <std::size_t I, auto L>
inline constexpr auto operand_layout<arg<I, L>> = L;

template <class Rule, class X, class Y>
using rows_of = pair_rows<Rule, operand_layout<X>, operand_layout<Y>>;

template <class Rule, class X, class Y, staging P>
struct traits<looped<Rule, X, Y>, P> {
    static constexpr std::uint64_t hash = mix(mix(mix(0xb1, Rule::id), traits<X>::hash), traits<Y>::hash);
    static constexpr bool complete = true;
    static constexpr auto list = leaf_terms<rows_of<Rule, X, Y>::outputs>(looped_id(hash));
    static constexpr auto terms = exact<list.n>(list);
    // for the staging decisions around it: the loop's multiplications and additions, and the
    // operands' (their normal forms' cost; cost_of counts their programs exactly)
    static constexpr cost hidden = [] {
        using rows = rows_of<Rule, X, Y>;
        return cost{rows::pairs, rows::pairs} + traits<X>::hidden + terms_cost(traits<X>::terms) +
               traits<Y>::hidden + terms_cost(traits<Y>::terms);
    }();
    using staged = type_list<>;
};

// The outermost looped nodes of a tree (those inside a looped node are its operands' business).
template <class N>
struct looped_nodes { using type = type_list<>; };
template <class N>
using looped_nodes_t = typename looped_nodes<N>::type;
template <class R, class X, class Y>
struct looped_nodes<looped<R, X, Y>> { using type = type_list<looped<R, X, Y>>; };
template <class R, class X, class Y>
struct looped_nodes<product<R, X, Y>> { using type = decltype(looped_nodes_t<X>{} + looped_nodes_t<Y>{}); };
template <class X, class Y, int S>
struct looped_nodes<sum<X, Y, S>> { using type = decltype(looped_nodes_t<X>{} + looped_nodes_t<Y>{}); };
template <class R, class X>
struct looped_nodes<map<R, X>> { using type = looped_nodes_t<X>; };
template <rational Q, class X>
struct looped_nodes<scaled<Q, X>> { using type = looped_nodes_t<X>; };

}  // namespace ctga::expr
