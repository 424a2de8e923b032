// Compile-time cost, case (e): one translation unit with a tree's inverse dynamics (RNEA), forward
// dynamics (ABA) and mass matrix (CRBA), the tree chosen by -DCTGA_BODIES=N (a serial chain of N
// revolute joints cycling z, y, x) or -DCTGA_HUMANOID (39 bodies, 44 dofs on a floating base),
// the trees of bench/chain_trees.hpp, or by -DCTGA_ROBOT=name with -include <header>: a header
// tools/urdf_to_ctga.py wrote from a real robot's URDF (its tree name::tree). Measured by
// tools/compile-cost.sh (compile seconds against bodies; --robots DIR); not part of any CMake target.
#include <cstdio>

#include <ctga/chains/algorithms.hpp>

#ifdef CTGA_ROBOT
using tree_type = CTGA_ROBOT::tree;  // (the header by -include)
#else
#include "../chain_trees.hpp"
#ifdef CTGA_HUMANOID
using tree_type = bench::chains::humanoid_tree;
#else
using tree_type = bench::chains::chain_tree<CTGA_BODIES>;
#endif
#endif
namespace ch = ctga::chains;

ch::model<tree_type> model_in;  // (external: its numbers are not known here, nothing folds)

int main(int argc, char**) {
    ch::configuration<tree_type> q{};
    ch::joint_vector<tree_type> qd{}, qdd{};
    for (std::size_t i = 0; i < tree_type::nv; ++i) qd[i] = qdd[i] = 0.1 * argc * static_cast<double>(i);
    for (std::size_t i = 0; i < tree_type::nq; ++i) q[i] = 0.2 * argc;
    const auto tau = ch::rnea(model_in, q, qd, qdd);
    const auto qdd2 = ch::aba(model_in, q, qd, tau);
    const auto H = ch::crba(model_in, q);
    std::printf("%g %g %g\n", tau[0], qdd2[tree_type::nv - 1], H[0][tree_type::nv - 1]);
    return 0;
}
