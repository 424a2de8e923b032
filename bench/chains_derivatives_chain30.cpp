// ctga_chains_bench's derivative kernels of the chain30 tree (bench/chains_derivatives.hpp).
#include "chains_derivatives.hpp"

namespace bench::chains {
void add_derivatives_chain30(std::vector<entry>& table) {
    static const derivative_fixture<chain30_tree> d{make_fixture<chain30_tree>(chain<30>(), 72)};
    add_derivatives(table, "chain30", d);
}
}  // namespace bench::chains
