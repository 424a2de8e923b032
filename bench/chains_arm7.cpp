// ctga_chains_bench's kernels of the arm7 tree (bench/chain_models.hpp).
#include "chains_kernels.hpp"

namespace bench::chains {
void add_arm7(std::vector<entry>& table) {
    static const auto f = make_fixture<arm7_tree>(arm7(), 71);
    add_tree<algorithm::rnea, algorithm::aba, algorithm::crba, algorithm::fk, algorithm::jacobian>(table, "arm7", f);
}
}  // namespace bench::chains
