// Compile-time cost, case (b6): a translation unit with a 7-dof arm's derivatives of inverse
// dynamics (rnea_derivatives) and of forward dynamics (aba_derivatives, with minverse): revolute
// joints about z, y, z, y, z, y, z, each frame 0.3 m along the last (the arm of
// arm7_dynamics.cpp). Measured by tools/compile-cost.sh; not part of any CMake target.
#include <cstdio>
#include <cstdlib>

#include <ctga/ctga.hpp>

namespace ch = ctga::chains;
using arm7 = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_y>, ch::link<1, ch::revolute_z>,
                      ch::link<2, ch::revolute_y>, ch::link<3, ch::revolute_z>, ch::link<4, ch::revolute_y>,
                      ch::link<5, ch::revolute_z>>;

int main(int argc, char** argv) {
    // run-time inputs, so that nothing is folded away
    const double x = argc > 1 ? std::atof(argv[1]) : 0.3;
    ch::model<arm7> m;
    bool ok = true;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            const auto link = ch::make_link<arm7::joint_at<I>>(
                ctga::rigid_motion(ctga::make_translator(0.0, 0.0, I == 0 ? 0.0 : 0.3), ctga::make_rotor(0.0, 0.0, 0.0, 1.0)),
                ctga::make_mass_properties(2.0 - 0.2 * I, ctga::vec3<double>{0.01, 0.0, 0.15},
                                           ctga::mat3<double>{{{0.02, 0.001, 0.0}, {0.001, 0.02, 0.0}, {0.0, 0.0, 0.005}}}));
            ok = ok && link;
            if (link) m.link<I>() = *link;
        }(), ...);
    }(std::make_index_sequence<arm7::size>{});
    if (!ok) return 1;
    ch::configuration<arm7> q{};
    ch::joint_vector<arm7> qd{}, qdd{};
    for (std::size_t i = 0; i < 7; ++i) q[i] = x * static_cast<double>(i), qd[i] = x, qdd[i] = -x;
    const auto id = ch::rnea_derivatives(m, q, qd, qdd);
    const auto fd = ch::aba_derivatives(m, q, qd, id.tau);
    std::printf("%g %g %g %g\n", id.dtau_dq(3, 2), id.dtau_dv(5, 1), fd.dqdd_dq(2, 4), fd.Minv(6, 0));
    return 0;
}
