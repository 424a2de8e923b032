// Property tests in Cl(0,3,1), the paper's algebra of screws and motors (§3): the sparse engine against the naive dense reference for every product
// and linear map, and the algebraic laws, on random inputs of several shapes.
// PARTS: 5
#include "support/properties.hpp"

TEST_CASE("Cl(0,3,1), the paper's algebra of screws and motors (§3): sparse products and maps equal the dense reference, laws hold" CTGA_TEST_PART_NAME, "[algebra][cl031]") {
    ctga::test::run_small_suite<ctga::cl031>(31);
}
