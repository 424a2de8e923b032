// ctga_chains_bench's kernels of the tree tree and of the quadruped (Solo 12's numbers on the same
// shape: the same instantiations) (bench/chain_models.hpp).
#include "chains_kernels.hpp"
#include "chains_mujoco_case.hpp"

namespace bench::chains {
void add_legged(std::vector<entry>& table) {
    static const auto f = make_fixture<legged_tree>(legged(), 73);
    add_tree<algorithm::rnea, algorithm::aba, algorithm::crba, algorithm::fk, algorithm::jacobian>(table, "tree", f);
    add_mujoco(table, make_mujoco_case("tree", f, legged()));
    static const auto quadruped = make_fixture<legged_tree>(solo12(), 74);
    add_tree<algorithm::rnea, algorithm::aba, algorithm::crba>(table, "quadruped", quadruped);
    add_mujoco(table, make_mujoco_case("quadruped", quadruped, solo12()));
}
}  // namespace bench::chains
