// Property tests in Cl(4,1,0), conformal geometric algebra: the sparse engine against the naive dense reference for every product
// and linear map, and the algebraic laws, on random inputs of several shapes.
// PARTS: 6
#include "support/properties.hpp"

TEST_CASE("Cl(4,1,0), conformal geometric algebra: sparse products and maps equal the dense reference, laws hold" CTGA_TEST_PART_NAME, "[algebra][cl410]") {
    ctga::test::run_small_suite<ctga::algebra<"e1 e2 e3 e4 e5", 1, 1, 1, 1, -1>>(410);
}
