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
//
// That table loop is the fallback. A product whose rule splits over the generators (below,
// "factorised over generators") runs as a block product instead: one unrolled, compile-time
// signed kernel over the four low generators, applied to each live pair of blocks of the high
// ones (the 256 × 256 geometric product: 6.7 µs against 31 µs for the table loop).
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "ctga/algebra/layout.hpp"
#include "ctga/algebra/rules.hpp"
#include "ctga/expr/nodes.hpp"
#include "ctga/expr/normal_form.hpp"
#include "ctga/expr/staging.hpp"
#include "ctga/support/inline.hpp"

// The loop threshold is one constant of the library, not a macro: a threshold set differently in
// two translation units would give one inline function (an operator, an operation) two bodies
// and two result types, an ODR violation no linker reports. One expression chooses for itself
// with ctga::loop_products(x) / ctga::unroll_products(x).
#ifdef CTGA_LOOP_THRESHOLD
#error "ctga: CTGA_LOOP_THRESHOLD is no longer read: a threshold that differs between translation units breaks the one-definition rule. Choose per expression with ctga::loop_products(x) or ctga::unroll_products(x)."
#endif

namespace ctga::expr {

// Above this many surviving blade pairs a product node loops over a table. Up to it the node
// is multiplied out symbolically (cancellations found, straight-line code, each pair one term
// of the program); past it the symbolic terms cost far more to compile than the loop costs to
// run (docs/engine.md, "Unrolled or looped").
inline constexpr std::size_t loop_threshold = 1024;
static_assert(loop_threshold <= term_budget, "ctga: expr::loop_threshold cannot exceed expr::term_budget");

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

// acc ± x ∘ y, acc indexed by output blade mask (Negate: subtract the product).
template <class T, class Rows, auto LY, bool Negate = false>
constexpr void run_rows_into(T* acc, const T* x, const T* y) noexcept {
    constexpr std::size_t W = Rows::column_words;
    const auto& d = Rows::value;
    for (std::size_t r = 0; r < Rows::rows; ++r) {
        constexpr bool identity = identity_layout<LY>;  // column j is blade j: no lookup
        run_set<T, W, Negate, identity>(d.add.data() + r * W, d.lead[r], LY.masks.data(), x[r], y, acc);
        run_set<T, W, !Negate, identity>(d.subtract.data() + r * W, d.lead[r], LY.masks.data(), x[r], y, acc);
    }
}

// The components of output layout OL (any blades, in any orientation: a target type's) from an
// accumulator over the Universe's blades.
template <class T, std::size_t Universe, auto OL>
constexpr std::array<T, OL.size()> gather(const T* acc) noexcept {
    std::array<T, OL.size()> out{};
    for (std::size_t k = 0; k < OL.size(); ++k)
        if (OL.masks[k] < Universe) out[k] = OL.signs[k] > 0 ? acc[OL.masks[k]] : T(-acc[OL.masks[k]]);
    return out;
}

// x ∘ y into output layout OL.
template <class T, class Rows, auto LY, auto OL>
constexpr std::array<T, OL.size()> run_rows(const T* x, const T* y) noexcept {
    std::array<T, Rows::universe> acc{};
    run_rows_into<T, Rows, LY>(acc.data(), x, y);
    return gather<T, Rows::universe, OL>(acc.data());
}

// ---- factorised over generators: a block product ---------------------------------------------
//
// Write a blade A = a | h, with a its low part (generators 0 … L−1, L = block_generators) and h
// its high part (the other generators, in place), and B = b | k alike. Take the row forms
// (rules.hpp) of the rows A, a (high part 0), h (low part 0) and 0. Suppose that for every live
// row A
//   care_A, want_A and flip_A agree with a's on the low generators and with h's on the high
//   ones, and parity_A ^ parity_a = T_h := parity_h ^ parity_0 on the low generators,
// and that a row A is dead only when row a or row h is. Then the pair (A, B) survives iff
// (b & care_a) = want_a on the low generators and (k & care_h) = want_h on the high ones, its
// output blade is (a ^ b ^ flip_a)_low | (h ^ k ^ flip_h)_high, and its sign splits:
//   sign_A (−1)^|B & parity_A| = K(a, b) · ψ_h(b) · χ_hk(a),  where
//   K(a, b)  = sign_a (−1)^|b & parity_a, low|    the low kernel, the same for every block pair,
//   ψ_h(b)   = (−1)^|b & T_h|                      a twist of the right operand's block,
//   χ_hk(a)  = sign_A sign_a (−1)^|k & parity_A|   the block sign (parity_A on the high
//                                                   generators, as k has no others).
// (The low parity gives K · ψ_h since parity_A = parity_a ^ T_h there; sign_A = sign_a · sign_A
// sign_a and the high parity make χ_hk.) So x ∘ y is a sum over the live block pairs (h, k) of
// one product K of 2^L × 2^L blades, fixed and signed at compile time, applied to the left
// block signed by χ_hk and the right block twisted by ψ_h, into output block h ^ k ^ flip_h.
//
// For the geometric product T_h is every low generator when |h| is odd (ψ_h is the grade
// involution of the right block: b moves past h at the cost (−1)^|h||b|) and χ_hk is the high
// product's sign s(h, k), the same for all a; for the shuffle product χ_hk also depends on the
// parity of a's complement. generator_split checks the conditions on all 2^n rows (no pair is
// visited); a rule or universe where they fail falls back to run_rows.
//
// K is unrolled straight-line code, about 0.5 cycles per pair against about 2 for the table
// loop, which reads a bit set, an index and a sign per pair. The operands are scattered first
// into zero-filled arrays over all 2^n blades, one copy per distinct χ (left) or ψ (right), so a
// block is 2^L consecutive values whose signs are set once, not once per block pair.

// Low generators per block: at most 16 × 16 blade pairs per kernel call.
inline constexpr std::size_t block_generators = 4;
// At most this many distinct kernels (by the low blades the operands' blocks hold; beyond it one
// kernel on all of them) and distinct χ and ψ (beyond it run_rows).
inline constexpr std::size_t max_block_kernels = 4;
inline constexpr std::size_t max_block_signs = 4;

constexpr bool dead(const rules::row_form& f) noexcept { return (f.want & ~f.care) != 0; }
constexpr bool odd_overlap(blade_mask p, blade_mask q) noexcept { return (std::popcount(p & q) & 1) != 0; }

// Whether Rule splits over the 2^Generators blades, with its twists T_h and block signs χ_hk.
// χ_hk as a set over a (bit a set: negative) is linear in k over GF(2):
//   χ_hk = sign_flips_h ^ (XOR over the high generators g of k of odd_with_{h,g}),
// sign_flips_h the a with sign_A ≠ sign_a, odd_with_{h,g} the a with g in parity_A.
template <class Rule, std::size_t Generators>
struct generator_split {
    static constexpr std::size_t low = Generators < block_generators ? Generators : block_generators;
    static constexpr std::size_t block = std::size_t{1} << low;
    static constexpr std::size_t high = Generators - low;
    static constexpr std::size_t blocks = std::size_t{1} << high;
    static constexpr blade_mask low_mask = static_cast<blade_mask>(block - 1);
    static constexpr blade_mask high_mask = ~low_mask;

    struct data {
        bool holds = true;
        std::array<blade_mask, blocks> twist{};                                  // T_h
        std::array<std::uint32_t, blocks> sign_flips{};                          // over a
        std::array<std::uint32_t, blocks * (high > 0 ? high : 1)> odd_with{};  // over a, at h · high + g
    };
    // (Raw pointers into the arrays, as in pair_rows.)
    static constexpr data value = [] {
        data d;
        std::array<rules::row_form, block> low_rows{};
        const rules::row_form* rows_a = low_rows.data();
        for (std::size_t a = 0; a < block; ++a) low_rows[a] = Rule::row(static_cast<blade_mask>(a));
        blade_mask* twist = d.twist.data();
        std::uint32_t* sign_flips = d.sign_flips.data();
        std::uint32_t* odd_with = d.odd_with.data();
        for (std::size_t hb = 0; hb < blocks; ++hb) {
            const blade_mask h = static_cast<blade_mask>(hb << low);
            const rules::row_form fh = Rule::row(h);
            twist[hb] = (fh.parity ^ rows_a[0].parity) & low_mask;
            for (std::size_t a = 0; a < block; ++a) {
                const rules::row_form& fa = rows_a[a];
                const rules::row_form f = Rule::row(h | static_cast<blade_mask>(a));
                if (dead(f)) {
                    d.holds = d.holds && (dead(fa) || dead(fh));
                    continue;
                }
                // where row A differs from row a (must be high) and from row h (must be low)
                const blade_mask from_a = (f.care ^ fa.care) | (f.want ^ fa.want) | (f.flip ^ fa.flip);
                const blade_mask from_h = (f.care ^ fh.care) | (f.want ^ fh.want) | (f.flip ^ fh.flip);
                d.holds = d.holds && !dead(fa) && !dead(fh) && (from_a & low_mask) == 0 && (from_h & high_mask) == 0 &&
                          ((f.parity ^ fa.parity) & low_mask) == twist[hb];
                if (f.sign != fa.sign) sign_flips[hb] |= std::uint32_t{1} << a;
                for (std::size_t g = 0; g < high; ++g)
                    if ((f.parity >> (low + g)) & 1u) odd_with[hb * high + g] |= std::uint32_t{1} << a;
            }
        }
        return d;
    }();
};

// The low kernel K between the low blades XP of a left block and YP of a right block (bit
// sets): per surviving pair its blades, output and sign, from the rows a of the low generators.
struct kernel_term {
    std::uint8_t x = 0, y = 0, out = 0;
    bool negative = false;
};
template <class Rule, std::size_t Low, std::uint32_t XP, std::uint32_t YP>
struct block_kernel {
    static constexpr std::size_t block = std::size_t{1} << Low;
    static constexpr blade_mask low_mask = static_cast<blade_mask>(block - 1);
    template <class Visit>
    static constexpr void each_pair_in(std::uint32_t xp, std::uint32_t yp, Visit visit) {
        for (std::size_t a = 0; a < block; ++a) {
            const rules::row_form f = Rule::row(static_cast<blade_mask>(a));
            if (!((xp >> a) & 1u) || dead(f)) continue;
            for (std::size_t b = 0; b < block; ++b)
                if (((yp >> b) & 1u) && (b & f.care & low_mask) == (f.want & low_mask))
                    visit(kernel_term{static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(b),
                                      static_cast<std::uint8_t>((a ^ b ^ f.flip) & low_mask),
                                      (f.sign < 0) != odd_overlap(static_cast<blade_mask>(b), f.parity & low_mask)});
        }
    }
    template <class Visit>
    static constexpr void each_pair(Visit visit) { each_pair_in(XP, YP, visit); }
    template <class Visit>
    static constexpr void each_pair_of_all(Visit visit) {
        constexpr std::uint32_t all = static_cast<std::uint32_t>((std::uint64_t{1} << block) - 1);  // every low blade
        each_pair_in(all, all, visit);
    }
    static constexpr std::size_t size = [] {
        std::size_t n = 0;
        each_pair([&](kernel_term) { ++n; });
        return n;
    }();
    static constexpr std::array<kernel_term, size> terms = [] {
        std::array<kernel_term, size> t{};
        kernel_term* p = t.data();
        each_pair([&](kernel_term k) { *p++ = k; });
        return t;
    }();
};

// A small set of distinct values, in order of arrival.
template <std::size_t N>
struct distinct_values {
    std::array<std::uint32_t, N> values{};
    std::size_t count = 0;
    bool overflow = false;
    constexpr std::size_t index(std::uint32_t v) noexcept {
        for (std::size_t i = 0; i < count; ++i)
            if (values[i] == v) return i;
        if (count == N) {
            overflow = true;
            return 0;
        }
        values[count] = v;
        return count++;
    }
};

// One block pair: offsets of its left block (in the copy for its χ), its right block (in the
// copy for its ψ) and its output block.
struct block_pair {
    std::uint32_t x = 0, y = 0, out = 0;
};
// A kernel: the low blades present in the left and right blocks it multiplies.
struct kernel_shape {
    std::uint32_t x = 0, y = 0;
    friend constexpr bool operator==(kernel_shape, kernel_shape) = default;
};

// The block product of operand layouts LX, LY: the live pairs of non-empty blocks, grouped by
// kernel, and whether it is used (the rule splits, and the kernels' work, structural zeros
// included, is below the table loop's; operands with scattered blades fill blocks sparsely).
template <class Rule, auto LX, auto LY>
struct block_plan {
    using rows = pair_rows<Rule, LX, LY>;
    using split = generator_split<Rule, rows::generators>;
    static constexpr std::size_t low = split::low, high = split::high, block = split::block, blocks = split::blocks;
    static constexpr std::size_t universe = rows::universe;

    // the low blades of each block of an operand
    template <auto L>
    static constexpr std::array<std::uint32_t, blocks> block_contents() {
        std::array<std::uint32_t, blocks> c{};
        for (blade_mask m : L.masks) c[m >> low] |= std::uint32_t{1} << (m & split::low_mask);
        return c;
    }
    static constexpr auto x_blocks = block_contents<LX>();
    static constexpr auto y_blocks = block_contents<LY>();

    // per block pair (h, k): whether it is live and both blocks non-empty, its kernel, χ, ψ
    // and output block (in Cl(0,6,2) the high null generator e kills 64 of the 256 block pairs)
    struct visit {
        bool live = false;
        std::uint8_t kernel = 0, chi = 0, psi = 0;
        std::uint32_t out = 0;
    };
    struct data {
        bool splits = split::value.holds;
        distinct_values<max_block_signs> chi, psi;
        std::array<kernel_shape, max_block_kernels> kernels{};
        std::size_t kernel_count = 0;
        bool one_kernel = false;  // too many shapes: one kernel on the union of the blocks' blades
        std::size_t entries = 0;
        std::array<visit, blocks * blocks> pairs{};  // at h · blocks + k
    };
    static constexpr data census = [] {
        data d;
        if (!d.splits) return d;
        const std::uint32_t* xb = x_blocks.data();
        const std::uint32_t* yb = y_blocks.data();
        const std::uint32_t* odd_with = split::value.odd_with.data();
        visit* pairs = d.pairs.data();
        kernel_shape* kernels = d.kernels.data();
        kernel_shape all{};
        std::array<std::uint32_t, blocks> chi_of_k{};
        std::uint32_t* chi_of = chi_of_k.data();
        for (std::size_t hb = 0; hb < blocks; ++hb) {
            const rules::row_form fh = Rule::row(static_cast<blade_mask>(hb << low));
            if (xb[hb] == 0 || dead(fh)) continue;
            const std::size_t psi = d.psi.index(split::value.twist[hb]);
            // χ_hk, linear in k: from k without its lowest generator
            chi_of[0] = split::value.sign_flips[hb];
            for (std::size_t kb = 1; kb < blocks; ++kb)
                chi_of[kb] = chi_of[kb & (kb - 1)] ^ odd_with[hb * high + static_cast<std::size_t>(std::countr_zero(kb))];
            for (std::size_t kb = 0; kb < blocks; ++kb) {
                const blade_mask k = static_cast<blade_mask>(kb << low);
                if (yb[kb] == 0 || (((k & fh.care) ^ fh.want) & split::high_mask) != 0) continue;
                const std::size_t out = hb ^ kb ^ (fh.flip >> low);
                const kernel_shape s{xb[hb], yb[kb]};
                std::size_t kernel = 0;
                while (kernel < d.kernel_count && !(kernels[kernel] == s)) ++kernel;
                if (kernel == d.kernel_count) {
                    if (kernel < max_block_kernels) kernels[d.kernel_count++] = s;
                    else d.one_kernel = true;
                }
                all.x |= s.x;
                all.y |= s.y;
                d.splits = d.splits && out < blocks;
                pairs[hb * blocks + kb] = visit{true, static_cast<std::uint8_t>(kernel), static_cast<std::uint8_t>(d.chi.index(chi_of[kb])),
                                                static_cast<std::uint8_t>(psi), static_cast<std::uint32_t>(out)};
                ++d.entries;
            }
        }
        if (d.one_kernel) {
            d.kernels = {};
            d.kernels[0] = all;
            d.kernel_count = 1;
            for (std::size_t i = 0; i < blocks * blocks; ++i) pairs[i].kernel = 0;
        }
        d.splits = d.splits && !d.chi.overflow && !d.psi.overflow;
        return d;
    }();
    static constexpr std::size_t kernel_count = census.kernel_count;
    template <std::size_t V>
    using kernel = block_kernel<Rule, low, census.kernels[V].x, census.kernels[V].y>;

    // the block pairs, grouped by kernel: those of kernel V are [first[V], first[V + 1])
    struct table {
        std::array<block_pair, (census.entries > 0 ? census.entries : 1)> pairs{};
        std::array<std::size_t, max_block_kernels + 1> first{};
    };
    static constexpr table value = [] {
        table t;
        const visit* visits = census.pairs.data();
        std::size_t* first = t.first.data();
        for (std::size_t i = 0; i < blocks * blocks; ++i)
            if (visits[i].live) ++first[visits[i].kernel + 1];
        for (std::size_t v = 0; v < max_block_kernels; ++v) first[v + 1] += first[v];
        std::array<std::size_t, max_block_kernels + 1> next_of = t.first;
        std::size_t* next = next_of.data();
        block_pair* pairs = t.pairs.data();
        for (std::size_t i = 0; i < blocks * blocks; ++i) {
            const visit& p = visits[i];
            if (!p.live) continue;
            pairs[next[p.kernel]++] = block_pair{static_cast<std::uint32_t>(p.chi * universe + (i / blocks) * block),
                                                 static_cast<std::uint32_t>(p.psi * universe + (i % blocks) * block),
                                                 static_cast<std::uint32_t>(p.out * block)};
        }
        return t;
    }();

    // the kernels' multiplications, structural zeros included
    static constexpr std::size_t work = []<std::size_t... V>(std::index_sequence<V...>) {
        return ((kernel<V>::size * (value.first[V + 1] - value.first[V])) + ... + std::size_t{0});
    }(std::make_index_sequence<kernel_count>{});
    // the surviving pairs: the work itself when each kernel is made for its blocks' blades, else
    // counted per block pair from the low kernel's rows (not rows::pairs: counting the table's
    // bit sets costs the compiler more than this whole plan)
    static constexpr std::size_t pairs = [] {
        if (!census.one_kernel) return work;
        std::array<std::uint32_t, block> survivors{};  // per a: the b the low kernel keeps
        kernel<0>::each_pair_of_all([&](kernel_term t) { survivors[t.x] |= std::uint32_t{1} << t.y; });
        std::size_t n = 0;
        for (std::size_t i = 0; i < blocks * blocks; ++i) {
            if (!census.pairs[i].live) continue;
            const std::uint32_t xs = x_blocks[i / blocks], ys = y_blocks[i % blocks];
            for (std::size_t a = 0; a < block; ++a)
                if ((xs >> a) & 1u) n += static_cast<std::size_t>(std::popcount(survivors[a] & ys));
        }
        return n;
    }();
    // A kernel pair costs about a quarter of a table pair, a block pair (its three blocks loaded
    // and stored) about eight table pairs.
    static constexpr bool used = census.splits && census.entries > 0 && work + 32 * census.entries <= 4 * pairs;
};

// One kernel pair into the accumulators o of its output block.
template <class T, kernel_term K>
CTGA_ALWAYS_INLINE constexpr void accumulate(const T* x, const T* y, T* o) noexcept {
    if constexpr (K.negative) o[K.out] -= x[K.x] * y[K.y];
    else o[K.out] += x[K.x] * y[K.y];
}

// out += K(x, y) on one block pair: the output block held in locals (they alias nothing, so
// the compiler keeps them in registers across the kernel).
template <class T, class Kernel, std::size_t... I>
CTGA_ALWAYS_INLINE constexpr void run_kernel([[maybe_unused]] const T* x, [[maybe_unused]] const T* y, T* out,
                                             std::index_sequence<I...>) noexcept {
    std::array<T, Kernel::block> o{};
    for (std::size_t i = 0; i < Kernel::block; ++i) o[i] = out[i];
    (accumulate<T, Kernel::terms[I]>(x, y, o.data()), ...);
    for (std::size_t i = 0; i < Kernel::block; ++i) out[i] = o[i];
}

template <class T, class Plan, std::size_t V>
CTGA_ALWAYS_INLINE constexpr void run_block_pairs(const T* xs, const T* ys, T* acc) noexcept {
    using K = typename Plan::template kernel<V>;
    for (std::size_t e = Plan::value.first[V]; e < Plan::value.first[V + 1]; ++e) {
        const block_pair p = Plan::value.pairs[e];
        run_kernel<T, K>(xs + p.x, ys + p.y, acc + p.out, std::make_index_sequence<K::size>{});
    }
}

// acc ± x ∘ y by blocks: scatter (each copy of x signed by its χ, of y twisted by its ψ, with
// the stored orientations, x negated for Negate), then every kernel over its block pairs.
template <class T, class Plan, auto LX, auto LY, bool Negate = false>
constexpr void run_blocks_into(T* acc, const T* x, const T* y) noexcept {
    constexpr std::size_t U = Plan::universe;
    constexpr auto& c = Plan::census;
    constexpr blade_mask low_mask = Plan::split::low_mask;
    // only the blocks an operand fills are read (whole): only they are cleared
    std::array<T, c.chi.count * U> xs;
    std::array<T, c.psi.count * U> ys;
    for (std::size_t b = 0; b < Plan::blocks; ++b) {
        if (Plan::x_blocks[b] != 0)
            for (std::size_t v = 0; v < c.chi.count; ++v)
                for (std::size_t i = 0; i < Plan::block; ++i) xs[v * U + b * Plan::block + i] = T(0);
        if (Plan::y_blocks[b] != 0)
            for (std::size_t t = 0; t < c.psi.count; ++t)
                for (std::size_t i = 0; i < Plan::block; ++i) ys[t * U + b * Plan::block + i] = T(0);
    }
    for (std::size_t j = 0; j < LX.size(); ++j) {
        const blade_mask m = LX.masks[j];
        for (std::size_t v = 0; v < c.chi.count; ++v)
            xs[v * U + m] = ((LX.signs[j] < 0) != (((c.chi.values[v] >> (m & low_mask)) & 1u) != 0)) != Negate ? T(-x[j]) : x[j];
    }
    for (std::size_t j = 0; j < LY.size(); ++j) {
        const blade_mask m = LY.masks[j];
        for (std::size_t t = 0; t < c.psi.count; ++t)
            ys[t * U + m] = (LY.signs[j] < 0) != odd_overlap(m & low_mask, c.psi.values[t]) ? T(-y[j]) : y[j];
    }
    [&]<std::size_t... V>(std::index_sequence<V...>) {
        (run_block_pairs<T, Plan, V>(xs.data(), ys.data(), acc), ...);
    }(std::make_index_sequence<Plan::kernel_count>{});
}

// x ∘ y into OL by blocks.
template <class T, class Plan, auto LX, auto LY, auto OL>
constexpr std::array<T, OL.size()> run_blocks(const T* x, const T* y) noexcept {
    std::array<T, Plan::universe> acc{};
    run_blocks_into<T, Plan, LX, LY>(acc.data(), x, y);
    return gather<T, Plan::universe, OL>(acc.data());
}

// acc ± x ∘ y: by blocks when the plan is used, else the table loop. The accumulator spans the
// universe of the operands' generators (pair_rows::universe).
template <class T, class Rule, auto LX, auto LY, bool Negate = false>
constexpr void run_product_into(T* acc, const T* x, const T* y) noexcept {
    using plan = block_plan<Rule, LX, LY>;
    if constexpr (plan::used) run_blocks_into<T, plan, LX, LY, Negate>(acc, x, y);
    else run_rows_into<T, pair_rows<Rule, LX, LY>, LY, Negate>(acc, x, y);
}

// ---- the other half as the low generators ---------------------------------------------------
//
// A block product reads its operands in blocks of the four low generators. In a doubled algebra
// such as Cl(0,6,2) an operand can fill the blocks of the high half densely and those of the low
// half sparsely: x ē, x a motor of one half and ē a blade of the other, is 8 blocks of one blade
// each, where the table loop is faster than the kernel. The swap of the halves, generator
// i ↔ i + n/2, is an automorphism φ of the algebra when the halves have the same squares (the
// paper's bar, §5; the geometric and exterior products commute with it):
//   φ(e_m) = σ(m) e_s(m),  s(m) the mask with its halves exchanged, σ(m) = (−1)^(|low m| |high m|)
// the sign that re-sorts the word. φ is an involution, so x ∘ y = φ(φ(x) ∘ φ(y)): the same rule
// on the swapped operands, whose blocks are dense, accumulated over the swapped blades and read
// back through φ. Swapping a layout moves its masks and folds σ into its stored orientations.
template <class Rule>
struct rule_algebra {
    using type = void;
};
template <class Alg>
struct rule_algebra<rules::geometric<Alg>> {
    using type = Alg;
};
template <class Alg>
struct rule_algebra<rules::exterior<Alg>> {
    using type = Alg;
};
template <class Rule>
inline constexpr bool halves_swap = [] {
    using Alg = typename rule_algebra<Rule>::type;
    if constexpr (std::is_void_v<Alg>) {
        return false;
    } else {
        if (Alg::dimension % 2 != 0 || Alg::dimension < 2 * block_generators) return false;
        for (std::size_t i = 0; i < Alg::dimension / 2; ++i)
            if (Alg::squares[i] != Alg::squares[i + Alg::dimension / 2]) return false;
        return true;
    }
}();

template <class Rule, auto L>
inline constexpr auto swapped_layout = [] {
    constexpr std::size_t h = rule_algebra<Rule>::type::dimension / 2;
    constexpr blade_mask low = static_cast<blade_mask>((blade_mask{1} << h) - 1);
    auto copy = L;
    for (std::size_t j = 0; j < L.size(); ++j) {
        const blade_mask m = L.masks[j];
        copy.masks[j] = static_cast<blade_mask>(((m & low) << h) | (m >> h));
        if ((std::popcount(m & low) * std::popcount(static_cast<blade_mask>(m >> h))) % 2 != 0)
            copy.signs[j] = static_cast<signed char>(-copy.signs[j]);
    }
    return copy;
}();

// Whether x ∘ y runs swapped: the block product is not used as the operands lie, and is once
// they are swapped.
template <class Rule, auto LX, auto LY>
inline constexpr bool run_swapped = [] {
    if constexpr (!halves_swap<Rule>) return false;
    else if constexpr (block_plan<Rule, LX, LY>::used) return false;
    else return block_plan<Rule, swapped_layout<Rule, LX>, swapped_layout<Rule, LY>>::used;
}();

// acc ± x ∘ y into the accumulator of its labelling: acc for the blades as they are, swapped for
// the swapped blades (when run_swapped).
template <class T, class Rule, auto LX, auto LY, bool Negate = false>
constexpr void run_product_into(T* acc, T* swapped, const T* x, const T* y) noexcept {
    if constexpr (run_swapped<Rule, LX, LY>)
        run_product_into<T, Rule, swapped_layout<Rule, LX>, swapped_layout<Rule, LY>, Negate>(swapped, x, y);
    else run_product_into<T, Rule, LX, LY, Negate>(acc, x, y);
}

// x ∘ y into OL.
template <class T, class Rule, auto LX, auto LY, auto OL>
constexpr std::array<T, OL.size()> run_product(const T* x, const T* y) noexcept {
    constexpr std::size_t U = pair_rows<Rule, LX, LY>::universe;
    std::array<T, U> acc{};
    if constexpr (run_swapped<Rule, LX, LY>) {
        run_product_into<T, Rule, swapped_layout<Rule, LX>, swapped_layout<Rule, LY>>(acc.data(), x, y);
        return gather<T, U, swapped_layout<Rule, OL>>(acc.data());
    } else {
        run_product_into<T, Rule, LX, LY>(acc.data(), x, y);
        return gather<T, U, OL>(acc.data());
    }
}

// ---- the looped node in the engine ----------------------------------------------------------

// A looped product's value enters the expressions around it as a source of its own, like a
// leaf: one degree-1 term per output blade.
inline constexpr source_id looped_bit = source_id{1} << 42;
constexpr source_id looped_id(std::uint64_t hash) { return looped_bit | (hash & (looped_bit - 1)); }
constexpr bool is_looped_source(source_id s) { return (s & intermediate_bit) == 0 && (s & looped_bit) != 0; }

// An operand's storage: a data leaf is read in place, anything else is evaluated into the
// canonical layout of its blades. A formula's argument has the layout of the leaf it will be
// bound to (for the compile-time decisions on a formula's body); it has no storage to read.
template <class X>
inline constexpr bool read_in_place = [] {
    constexpr node_kind kind = shape_for<walker::read_operand, X>::kind;
    return kind == node_kind::data_leaf || kind == node_kind::argument;
}();
template <class X>
consteval std::size_t leaf_index() {
    using shape = shape_for<walker::read_operand, X>;
    static_assert(shape::kind != node_kind::argument,
                  "ctga::expr: a formula's argument reached evaluation unbound: bind the formula (call it) first");
    static_assert(shape::kind == node_kind::data_leaf, "ctga::expr: only a data leaf is read in place");
    return shape::index;
}

template <class N>
inline constexpr bool is_looped_node = node_shape<N>::kind == node_kind::looped;

template <class X>
constexpr auto operand_layout_of() {
    if constexpr (read_in_place<X>) return node_shape<X>::layout;
    else return node_layout<X>;
}
template <class X>
inline constexpr auto operand_layout = operand_layout_of<X>();

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
// Every program walks its root's tree for them: by partial specialisation on the node's kind, as
// relabel (expression.hpp).
template <class N, node_kind K = node_shape<N>::kind, class Children = typename node_shape<N>::children>
struct looped_nodes;
template <class N>
using looped_nodes_t = typename looped_nodes<N>::type;
template <class N, node_kind K, class... C>
struct looped_nodes<N, K, type_list<C...>> {
    using type = decltype((type_list<>{} + ... + looped_nodes_t<C>{}));
};
template <class N, class... C>
struct looped_nodes<N, node_kind::looped, type_list<C...>> {
    using type = type_list<N>;
};
template <class N>
struct looped_nodes<N, node_kind::unknown, type_list<>> : refuse_unknown<walker::looped_nodes, N> {
    using type = type_list<>;
};

}  // namespace ctga::expr
