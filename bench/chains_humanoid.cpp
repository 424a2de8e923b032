// ctga_chains_bench's kernels of the humanoid tree (bench/chain_models.hpp: 39 bodies, 44 dofs on
// a floating base).
#include "chains_kernels.hpp"
#include "chains_mujoco_case.hpp"

namespace bench::chains {
void add_humanoid(std::vector<entry>& table) {
    static const auto f = make_fixture<humanoid_tree>(humanoid(), 75);
    add_tree<algorithm::rnea, algorithm::aba, algorithm::crba, algorithm::fk>(table, "humanoid", f);
    add_mujoco(table, make_mujoco_case("humanoid", f, humanoid()));
}
}  // namespace bench::chains
