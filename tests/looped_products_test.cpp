// Products past the unrolling threshold (expr/looped.hpp): every bilinear rule's row form
// against the rule itself for every pair of blades; looped products of general multivectors in
// Cl(0,6,2), Cl(3,0,1) and a 10-generator algebra against the naive dense reference; forced
// unrolled and looped evaluation of the same expression; looped products inside larger
// expressions, projected, and in formulas.
// PARTS: 2
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>

#include "support/looped.hpp"
#include "support/parts.hpp"

namespace {

using namespace ctga::test;
using namespace ctga::test::looped;
namespace dense = ctga::dense;
namespace hana = boost::hana;
using ctga::blade_mask;

// ---- the row forms ----------------------------------------------------------------------------

template <class Rule, class Alg>
int row_form_mismatches() {
    int bad = 0;
    for (blade_mask a = 0; a < Alg::blade_count; ++a) {
        const ctga::rules::row_form f = Rule::row(a);
        for (blade_mask b = 0; b < Alg::blade_count; ++b) {
            const ctga::signed_blade p = Rule::apply(a, b);
            const bool alive = (b & f.care) == f.want;
            if (alive != (p.sign != 0)) { ++bad; continue; }
            if (!alive) continue;
            const int sign = f.sign * ((std::popcount(b & f.parity) & 1) ? -1 : 1);
            bad += sign != p.sign || (a ^ b ^ f.flip) != p.mask;
        }
    }
    return bad;
}

template <class Alg>
void check_row_forms() {
    using namespace ctga::rules;
    CHECK(row_form_mismatches<geometric<Alg>, Alg>() == 0);
    CHECK(row_form_mismatches<exterior<Alg>, Alg>() == 0);
    CHECK(row_form_mismatches<shuffle<Alg>, Alg>() == 0);
    CHECK(row_form_mismatches<left_contraction<Alg>, Alg>() == 0);
    CHECK(row_form_mismatches<right_contraction<Alg>, Alg>() == 0);
    CHECK(row_form_mismatches<scalar<Alg>, Alg>() == 0);
}

#if CTGA_TEST_PART_HOLDS(0)
TEST_CASE("every rule's row form equals the rule for every pair of blades", "[looped]") {
    check_row_forms<ctga::cl062>();
    check_row_forms<cl301>();
    check_row_forms<ctga::algebra<"e1 e2 e3 e4", -1, 1, 1, 1>>();
    check_row_forms<ten>();
}

// ---- looped products against the dense reference ----------------------------------------------

TEST_CASE("Cl(0,6,2): the full 256 x 256 products are looped and equal the dense reference", "[looped][cl062]") {
    std::mt19937_64 rng(62);
    using full = general<ctga::cl062>;
    static_assert(is_looped<decltype(full{} * full{})>, "past the threshold the engine loops");
    static_assert(decltype(full{} * full{})::size() == 256);
    // 7 pairs in 16 die to e0² = e² = 0: 256 · 256 · 9/16 multiplications
    static_assert(ctga::cost_of<decltype(full{} * full{})>.mul == 36864);
    check_all_products<full, full>("Cl(0,6,2) general", rng);
    // random blade orders and orientations on both sides
    check_all_products<random_mv<ctga::cl062, 3, 256>, random_mv<ctga::cl062, 4, 256>>("Cl(0,6,2) shuffled", rng);
    check_all_products<even<ctga::cl062>, random_mv<ctga::cl062, 5, 40>>("Cl(0,6,2) even x 40 blades", rng);
}

#endif

#if CTGA_TEST_PART_HOLDS(1)
TEST_CASE("Cl(0,6,2): block products and the table loop, both for every rule, equal the dense reference",
          "[looped][cl062][blocks]") {
    std::mt19937_64 rng(2062);
    using full = general<ctga::cl062>;
    // the engine's choice: blocks for the full products, the table loop for sparse operands and
    // for the scalar product (8 surviving pairs per block pair)
    static_assert(by_blocks<decltype(full{} * full{})> && by_blocks<decltype(full{} ^ full{})>);
    static_assert(by_blocks<decltype(ctga::loop_products(full{} & full{}))> && by_blocks<decltype(ctga::loop_products(full{} | full{}))>);
    static_assert(!by_blocks<decltype(ctga::loop_products(ctga::scalar_product(full{}, full{})))>);
    static_assert(!by_blocks<decltype(ctga::loop_products(even<ctga::cl062>{} * random_mv<ctga::cl062, 5, 40>{}))>);
    check_both_loops<full, full>("Cl(0,6,2) general", rng);
    check_both_loops<random_mv<ctga::cl062, 3, 256>, random_mv<ctga::cl062, 4, 256>>("Cl(0,6,2) shuffled", rng);
    check_both_loops<even<ctga::cl062>, random_mv<ctga::cl062, 5, 40>>("Cl(0,6,2) even x 40 blades", rng);
    check_both_loops<random_mv<ctga::cl062, 6, 100>, grade_mv<ctga::cl062, 3>>("Cl(0,6,2) 100 blades x trivectors", rng);
}

#endif

// ---- looped products inside expressions -----------------------------------------------------------

#if CTGA_TEST_PART_HOLDS(0)
TEST_CASE("Cl(0,6,2): a product whose operand fills the high half's blocks runs with the halves swapped",
          "[looped][cl062][blocks]") {
    using motor_blade = ctga::multivector<ctga::cl062, double, motor_times_blade>;
    using geometric = ctga::rules::geometric<ctga::cl062>;
    // as the blades lie the block product is refused (8 block pairs of one blade); swapped, used
    static_assert(!ctga::expr::block_plan<geometric, motor_blade::layout, even<ctga::cl062>::layout>::used);
    static_assert(ctga::expr::run_swapped<geometric, motor_blade::layout, even<ctga::cl062>::layout>);
    static_assert(ctga::expr::run_swapped<geometric, even<ctga::cl062>::layout, motor_blade::layout>);
    std::mt19937_64 rng(24);
    check_all_products<motor_blade, even<ctga::cl062>>("Cl(0,6,2) motor-blade x even", rng);
    check_all_products<even<ctga::cl062>, motor_blade>("Cl(0,6,2) even x motor-blade", rng);
    check_both_loops<motor_blade, even<ctga::cl062>>("Cl(0,6,2) motor-blade x even", rng);
}

#endif

#if CTGA_TEST_PART_HOLDS(1)
TEST_CASE("looped products compose: operands that are expressions, sums, projections, formulas",
          "[looped][engine]") {
    std::mt19937_64 rng(7);
    using full = general<ctga::cl062>;
    const auto a = random_fill<full>(rng);
    const auto b = random_fill<full>(rng);
    const auto c = random_fill<random_mv<ctga::cl062, 9, 100>>(rng);
    const auto s = random_fill<grade_mv<ctga::cl062, 2>>(rng);
    const auto da = as_dense(a), db = as_dense(b), dc = as_dense(c), ds = as_dense(s);

    // a looped product of looped products, and of sums
    check_close("(a b)(b a)", (a * b) * (b * a), dense::gp(dense::gp(da, db), dense::gp(db, da)));
    check_close("(a + c)(b - c)", (a + c) * (b - c), dense::gp(da + dc, db - dc));
    // a looped product inside an unrolled expression
    check_close("½ (a b) + s", ctga::half * (a * b) + s, dense::gp(da, db) * 0.5 + ds);
    check_close("s ∧ (a b)", s ^ (a * b), dense::wedge(ds, dense::gp(da, db)));
    // fewer blades, in other orientations, than the product makes
    using target = random_mv<ctga::cl062, 11, 30>;
    const target p = ctga::project<target>(a * b);
    check_close("project(a b)", p, keep_only<ctga::cl062, target::layout>(dense::gp(da, db)));
    constexpr auto e3e1 = ctga::cl062::parse_blade("e3e1");  // orientation −1 against e1e3
    const double expected = e3e1.sign * dense::gp(da, db)[e3e1.mask];
    CHECK(std::abs(ctga::get<"e3e1">(a * b) - expected) <= tolerance * dense::max_abs(dense::gp(da, db)));
    // in a formula, with a repeated argument
    constexpr auto square = ctga::formula([](auto x) { return x * x; });
    check_close("formula x x", square(a), dense::gp(da, da));
}
#endif

}  // namespace
