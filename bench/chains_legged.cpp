// ctga_chains_bench's kernels of the tree tree (bench/chain_models.hpp).
#include "chains_kernels.hpp"

namespace bench::chains {
void add_legged(std::vector<entry>& table) {
    static const auto f = make_fixture<legged_tree>(legged(), 73);
    add_tree<algorithm::rnea, algorithm::aba, algorithm::crba, algorithm::fk, algorithm::jacobian>(table, "tree", f);
}
}  // namespace bench::chains
