// Compile-time cost, case (b2): a translation unit with a 7-dof arm's inverse dynamics (RNEA),
// forward dynamics (ABA) and mass matrix (CRBA) (the arm: arm7_model.hpp). Measured by
// tools/compile-cost.sh; not part of any CMake target.
#include "arm7_model.hpp"

int main(int argc, char** argv) {
    // run-time inputs, so that nothing is folded away
    const arm7_state s(argc > 1 ? std::atof(argv[1]) : 0.3);
    const std::optional<ch::model<arm7>> m = arm7_model();
    if (!m) return 1;
    const auto tau = ch::rnea(*m, s.q, s.qd, s.qdd);
    const auto qdd2 = ch::aba(*m, s.q, s.qd, tau);
    const auto H = ch::crba(*m, s.q);
    std::printf("%g %g %g\n", tau[3], qdd2[5], H[2][4]);
    return 0;
}
