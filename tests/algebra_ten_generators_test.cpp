// Property tests in a 10-generator algebra (1,024 blades), of signature (6,2,2) with the
// second half of the generators repeating the first half's squares, so the paper's bar
// involution applies: the sparse engine against the naive dense reference, and the laws.
// PARTS: 4
#include "support/properties.hpp"

namespace {

using G = ctga::algebra<"e1 e2 e3 e4 e5 e6 e7 e8 e9 e10", 1, 1, 1, -1, 0, 1, 1, 1, -1, 0>;

TEST_CASE("10 generators: sparse products and maps equal the dense reference, laws hold" CTGA_TEST_PART_NAME, "[algebra][ten]") {
    using namespace ctga::test;
    static_assert(G::blade_count == 1024);
    static_assert(permutation_sign(bar_permutation<G>()) == -1.0, "swapping two halves of 5 is odd");
    static_assert(permutation_sign(bar_permutation<ctga::cl062>()) == 1.0, "swapping two halves of 4 is even");
    run_suite<G, random_mv<G, 10, 28>, grade_mv<G, 1>, random_mv<G, 11, 6>, random_mv<G, 12, 16>>(10);
}

}  // namespace
