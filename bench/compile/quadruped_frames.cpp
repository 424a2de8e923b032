// Compile-time cost, case (b4): a quadruped as the URDF tool makes it (tests/data/legged.urdf,
// --floating-base: fixed links merged, 26 named frames) with, in one translation unit, its
// RNEA, ABA and CRBA and the four feet's frame Jacobians (local and local_world_aligned). With -DCTGA_MORE also their time variation, the centre of mass and the
// centroidal momentum matrix. Measured at -O2 by tools/compile-cost.sh (which generates
// legged.hpp first); not part of any CMake target.
#include <cstdio>
#include <cstdlib>

#include "legged.hpp"

namespace ch = ctga::chains;
using tree = legged::tree;

int main(int argc, char** argv) {
    const double x = argc > 1 ? std::atof(argv[1]) : 0.3;  // run-time inputs: nothing folds away
    const auto built = legged::make_model<double>();
    if (!built) return 1;
    const ch::model<tree>& m = *built;
    ch::configuration<tree> q{};
    const auto base = ch::floating_base_configuration(ch::base_pose<double>{{0.0, 0.0, x}, {0.0, 0.0, 0.0, 1.0}});
    if (!base) return 1;
    for (std::size_t i = 0; i < 8; ++i) q[i] = (*base)[i];
    ch::joint_vector<tree> qd{}, qdd{};
    for (std::size_t i = 8; i < tree::nq; ++i) q[i] = x * static_cast<double>(i);
    for (std::size_t i = 0; i < tree::nv; ++i) qd[i] = x, qdd[i] = -x;
    const auto tau = ch::rnea(m, q, qd, qdd);
    const auto qdd2 = ch::aba(m, q, qd, tau);
    const auto H = ch::crba(m, q);
    double s = 0;
    const auto foot = [&](auto frame) {
        const auto J = ch::frame_jacobian(m, q, frame, ch::reference::local);
        const auto Jw = ch::frame_jacobian(m, q, frame, ch::reference::local_world_aligned);
        s += J[7][3] + Jw[8][4];
#ifdef CTGA_MORE
        const auto Jd = ch::frame_jacobian_time_variation(m, ch::forward_kinematics(m, q, qd), frame,
                                                          ch::reference::local_world_aligned);
        s += Jd[9][5];
#endif
    };
    foot(ch::frame<"LF_FOOT">);
    foot(ch::frame<"RF_FOOT">);
    foot(ch::frame<"LH_FOOT">);
    foot(ch::frame<"RH_FOOT">);
#ifdef CTGA_MORE
    const auto k = ch::forward_kinematics(m, q, qd);
    const auto A = ch::centroidal_momentum_matrix(m, k);
    const auto c = ch::center_of_mass(m, k);
    s += A[6][3] + c.position[2];
#endif
    std::printf("%g %g %g %g\n", tau[3], qdd2[5], H[2][4], s);
    return 0;
}
