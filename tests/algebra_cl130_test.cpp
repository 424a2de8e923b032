// Property tests in Cl(1,3,0), spacetime algebra: the sparse engine against the naive dense reference for every product
// and linear map, and the algebraic laws, on random inputs of several shapes.
// PARTS: 5
#include "support/properties.hpp"

TEST_CASE("Cl(1,3,0), spacetime algebra: sparse products and maps equal the dense reference, laws hold" CTGA_TEST_PART_NAME, "[algebra][cl130]") {
    ctga::test::run_small_suite<ctga::algebra<"t x y z", 1, -1, -1, -1>>(130);
}
