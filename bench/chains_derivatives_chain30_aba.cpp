// ctga_chains_bench's derivative kernels of the chain30 tree, the forward dynamics'
// (chains_derivatives_chain30.cpp has the rest; the same fixture, seed 72).
#include "chains_derivatives.hpp"

namespace bench::chains {
void add_derivatives_chain30_aba(std::vector<entry>& table) {
    static const derivative_fixture<chain30_tree> d{make_fixture<chain30_tree>(chain<30>(), 72)};
    add_derivatives<dynamics::forward>(table, "chain30", d);
}
}  // namespace bench::chains
