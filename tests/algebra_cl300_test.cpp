// Property tests in Cl(3,0,0), Euclidean 3-space: the sparse engine against the naive dense reference for every product
// and linear map, and the algebraic laws, on random inputs of several shapes.
// PARTS: 5
#include "support/properties.hpp"

TEST_CASE("Cl(3,0,0), Euclidean 3-space: sparse products and maps equal the dense reference, laws hold" CTGA_TEST_PART_NAME, "[algebra][cl300]") {
    ctga::test::run_small_suite<ctga::algebra<"e1 e2 e3", 1, 1, 1>>(300);
}
