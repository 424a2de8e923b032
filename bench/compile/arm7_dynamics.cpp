// Compile-time cost, case (b2): a translation unit with a 7-dof arm's inverse dynamics (RNEA),
// forward dynamics (ABA) and mass matrix (CRBA) (the arm: arm7_model.hpp). Measured by
// tools/compile-cost.sh; not part of any CMake target.
#include "arm7_model.hpp"

int main(int argc, char** argv) {
    // run-time inputs, so that nothing is folded away
    const double x = argc > 1 ? std::atof(argv[1]) : 0.3;
    const std::optional<ch::model<arm7>> m = arm7_model();
    if (!m) return 1;
    ch::configuration<arm7> q{};
    ch::joint_vector<arm7> qd{}, qdd{};
    for (std::size_t i = 0; i < 7; ++i) q[i] = x * static_cast<double>(i), qd[i] = x, qdd[i] = -x;
    const auto tau = ch::rnea(*m, q, qd, qdd);
    const auto qdd2 = ch::aba(*m, q, qd, tau);
    const auto H = ch::crba(*m, q);
    std::printf("%g %g %g\n", tau[3], qdd2[5], H[2][4]);
    return 0;
}
