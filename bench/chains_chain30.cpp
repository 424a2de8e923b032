// ctga_chains_bench's kernels of the chain30 tree (bench/chain_models.hpp): RNEA and ABA here,
// CRBA and forward kinematics in chains_chain30_crba_fk.cpp (30 unrolled bodies per algorithm:
// one unit with all four took 50 s to compile).
#include "chains_kernels.hpp"
#include "chains_mujoco_case.hpp"

namespace bench::chains {
void add_chain30(std::vector<entry>& table) {
    static const auto f = make_fixture<chain30_tree>(chain<30>(), 72);
    add_tree<algorithm::rnea, algorithm::aba>(table, "chain30", f);
    add_mujoco(table, make_mujoco_case<algorithm::rnea, algorithm::aba>("chain30", f, chain<30>()));
}
}  // namespace bench::chains
