// Property tests in Cl(0,6,2), the paper's algebra of momenta and inertias (§5), on the
// paper's shapes (screws, co-screws, motors, a symmetric inertia-like grade-4 set) and random
// sparse sets: the sparse engine against the naive dense reference, and the algebraic laws.
// PARTS: 8
#include "support/properties.hpp"

namespace {

using G = ctga::cl062;
using screw = G::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
using coscrew = G::mv<double, "a2a3", "a3a1", "a1a2", "a1a", "a2a", "a3a">;
using motor = G::mv<double, "1", "e2e3", "e3e1", "e1e2", "ee1e2e3", "e1e", "e2e", "e3e">;
using inertia_like = G::mv<double, "a1ae1e", "a2ae2e", "a3ae3e", "a2a3e2e3", "a3a1e3e1", "a1a2e1e2", "a3ae3e1",
                           "a2ae1e2", "a3a1e3e", "a1a2e2e">;

TEST_CASE("Cl(0,6,2): sparse products and maps equal the dense reference, laws hold" CTGA_TEST_PART_NAME, "[algebra][cl062]") {
    using namespace ctga::test;
    run_suite<G, random_mv<G, 62, 24>, screw, coscrew, motor, inertia_like, grade_mv<G, 1>, random_mv<G, 63, 10>>(62);
}

}  // namespace
