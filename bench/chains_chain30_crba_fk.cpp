// ctga_chains_bench's CRBA and forward-kinematics kernels of the chain30 tree (see chains_chain30.cpp).
#include "chains_kernels.hpp"
#include "chains_mujoco_case.hpp"

namespace bench::chains {
void add_chain30_crba_fk(std::vector<entry>& table) {
    static const auto f = make_fixture<chain30_tree>(chain<30>(), 72);
    add_tree<algorithm::crba, algorithm::fk>(table, "chain30", f);
    add_mujoco(table, make_mujoco_case<algorithm::crba>("chain30", f, chain<30>()));
}
}  // namespace bench::chains
