// ctga_chains_bench: forward kinematics, RNEA, CRBA and ABA of kinematic trees in ctga::chains and
// in hand-written spatial code (bench/spatial_chains.hpp), as Google Benchmarks named
// <algorithm>_<tree>/<implementation>: rnea_arm7/ctga, rnea_arm7/spatial, aba_chain30/…, fk_tree/…
// (trees in bench/chain_models.hpp; kernels in chains_kernels.hpp, one translation unit per tree).
// With MuJoCo found by CMake (CTGA_BENCH_MUJOCO), rnea, crba and aba also as <algorithm>_<tree>/mujoco
// (chains_mujoco.cpp: the same trees in MuJoCo 2.2.2, checked against ctga before they are timed).
// With CTGA_CHAINS_SCALING it is ctga_chains_scaling_* instead: rnea_chain/<N>/<implementation>,
// aba_chain/<N>/…, crba_chain/<N>/… for the N listed (chains_scaling.cpp). With the development
// robots found (CMake: CTGA_BENCH_ROBOTS_DIR), their rows too: rnea_<robot>/ctga, … (chains_robot.cpp).
// The quadruped with its feet held: constrained_fd_quadruped/ctga, delassus_quadruped/ctga
// (chains_constrained.cpp).
//
// Each kernel is one non-inlined call (chain_kernel) on one of 64 random states in memory,
// cycling, so nothing folds and callgrind can count the instructions of a call alone:
//   ctga_chains_bench --repeat NAME N        call one kernel N times and exit
#include <vector>

#include "chains_kernels.hpp"

int main(int argc, char** argv) {
    using namespace bench::chains;
    std::vector<entry> table;
#ifdef CTGA_CHAINS_SCALING
    add_scaling(table);
#else
    add_arm7(table);
    add_chain30(table);
    add_chain30_crba_fk(table);
    add_legged(table);
    add_constrained(table);
    add_humanoid_contact(table);
    add_grasp_contact(table);
    add_humanoid(table);
    add_derivatives_arm7(table);
    add_derivatives_chain30(table);
    add_derivatives_chain30_aba(table);
    add_derivatives_legged(table);
    for (auto* add_robot : robot_tables()) add_robot(table);  // CTGA_BENCH_ROBOTS_DIR's robots, if built
#endif
    return bench::run(table, argc, argv);
}
