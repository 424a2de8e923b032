// Property tests in Cl(3,0,1), projective geometric algebra: the sparse engine against the naive dense reference for every product
// and linear map, and the algebraic laws, on random inputs of several shapes.
// PARTS: 5
#include "support/properties.hpp"

TEST_CASE("Cl(3,0,1), projective geometric algebra: sparse products and maps equal the dense reference, laws hold" CTGA_TEST_PART_NAME, "[algebra][cl301]") {
    ctga::test::run_small_suite<ctga::algebra<"e0 e1 e2 e3", 0, 1, 1, 1>>(301);
}
