// ctga_chains_bench's CRBA and forward-kinematics kernels of the chain30 tree (see chains_chain30.cpp).
#include "chains_kernels.hpp"

namespace bench::chains {
void add_chain30_crba_fk(std::vector<entry>& table) {
    static const auto f = make_fixture<chain30_tree>(chain<30>(), 72);
    add_tree<algorithm::crba, algorithm::fk>(table, "chain30", f);
}
}  // namespace bench::chains
