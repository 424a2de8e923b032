// Property tests in the small algebras: Euclidean 3-space, the paper's Cl(0,3,1) (screws and
// motors, §3) and projective Cl(3,0,1), on random inputs of several shapes.
#include "support/properties.hpp"

namespace {

using namespace ctga;
using namespace ctga::test;

template <class G>
void run_small_suite(std::uint64_t seed) {
    run_suite<G, random_mv<G, 1, G::blade_count>,  // every blade
              grade_mv<G, 1>, grade_mv<G, 2>, random_mv<G, 2, 3>, random_mv<G, 3, 5>>(seed);
}

TEST_CASE("Cl(3,0,0): sparse products and maps equal the dense reference; laws hold", "[algebra][cl300]") {
    run_small_suite<algebra<"e1 e2 e3", 1, 1, 1>>(300);
}

TEST_CASE("Cl(0,3,1): sparse products and maps equal the dense reference; laws hold", "[algebra][cl031]") {
    run_small_suite<cl031>(31);
}

TEST_CASE("Cl(3,0,1): sparse products and maps equal the dense reference; laws hold", "[algebra][cl301]") {
    run_small_suite<algebra<"e0 e1 e2 e3", 0, 1, 1, 1>>(301);
}

}  // namespace
