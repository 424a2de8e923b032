// Compile-time cost, case (b6): a translation unit with a 7-dof arm's derivatives of inverse
// dynamics (rnea_derivatives) and of forward dynamics (aba_derivatives, with minverse) (the arm:
// arm7_model.hpp). Measured by tools/compile-cost.sh; not part of any CMake target.
#include "arm7_model.hpp"

int main(int argc, char** argv) {
    // run-time inputs, so that nothing is folded away
    const arm7_state s(argc > 1 ? std::atof(argv[1]) : 0.3);
    const std::optional<ch::model<arm7>> m = arm7_model();
    if (!m) return 1;
    const auto id = ch::rnea_derivatives(*m, s.q, s.qd, s.qdd);
    const auto fd = ch::aba_derivatives(*m, s.q, s.qd, id.tau);
    std::printf("%g %g %g %g\n", id.dtau_dq(3, 2), id.dtau_dv(5, 1), fd.dqdd_dq(2, 4), fd.Minv(6, 0));
    return 0;
}
