// Looped products (expr/looped.hpp) in Cl(3,0,1), forced, against unrolled evaluation and the
// dense reference, and in a 10-generator algebra: 512 x 512 even and 1024 x 1024 general
// products against the dense reference. (Split from looped_products_test.cpp to keep each
// translation unit's compile time in budget.)
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>

#include "support/looped.hpp"

namespace {

using namespace ctga::test;
using namespace ctga::test::looped;
namespace dense = ctga::dense;
namespace hana = boost::hana;
using ctga::blade_mask;

// ---- looped products against the dense reference ----------------------------------------------

TEST_CASE("Cl(3,0,1): forcing looped or unrolled gives the same products", "[looped][cl301]") {
    std::mt19937_64 rng(301);
    using full = general<cl301>;
    static_assert(!is_looped<decltype(full{} * full{})>, "192 pairs: unrolled by default");
    const auto a = random_fill<full>(rng);
    const auto b = random_fill<random_mv<cl301, 7, 11>>(rng);
    static_assert(is_looped<decltype(ctga::loop_products(a * b))>);
    check_all_products<full, random_mv<cl301, 7, 11>>("Cl(3,0,1)", rng);
    check_close("Cl(3,0,1) looped against unrolled", ctga::loop_products(a * b), ctga::unroll_products(a * b));
    check_close("Cl(3,0,1) looped against unrolled, ∨", ctga::loop_products(a & b), ctga::unroll_products(a & b));
    // four generators: one block, the block product is the low kernel alone
    check_both_loops<full, random_mv<cl301, 7, 11>>("Cl(3,0,1)", rng);
}

TEST_CASE("10 generators: 512 x 512 even and 1024 x 1024 general products equal the dense reference",
          "[looped][ten]") {
    std::mt19937_64 rng(10);
    const auto a = random_fill<even<ten>>(rng);
    const auto b = random_fill<even<ten>>(rng);
    static_assert(is_looped<decltype(a * b)> && decltype(a * b)::size() == 512);
    static_assert(by_blocks<decltype(a * b)> && by_blocks<decltype(a ^ b)>, "even blocks: four kernels");
    check_close("even * even", a * b, dense::gp(as_dense(a), as_dense(b)));
    check_close("even ∧ even", a ^ b, dense::wedge(as_dense(a), as_dense(b)));
    const auto x = random_fill<general<ten>>(rng);
    const auto y = random_fill<general<ten>>(rng);
    static_assert(by_blocks<decltype(x * y)> && by_blocks<decltype(x & y)> && by_blocks<decltype(x | y)>);
    check_close("general * general", x * y, dense::gp(as_dense(x), as_dense(y)));
    check_close("general ∨ general", x & y, dense::shuffle(as_dense(x), as_dense(y)));
    check_close("general ⌋ general", x | y, dense::lcont(as_dense(x), as_dense(y)));
}

}  // namespace
