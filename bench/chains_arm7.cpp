// ctga_chains_bench's kernels of the arm7 tree (bench/chain_models.hpp).
#include "chains_kernels.hpp"
#include "chains_mujoco_case.hpp"

namespace bench::chains {
void add_arm7(std::vector<entry>& table) {
    static const auto f = make_fixture<arm7_tree>(arm7(), 71);
    add_tree<algorithm::rnea, algorithm::aba, algorithm::crba, algorithm::fk, algorithm::jacobian>(table, "arm7", f);
    add_mujoco(table, make_mujoco_case("arm7", f, arm7()));
}
}  // namespace bench::chains
