// ctga_chains_bench's derivative kernels of the tree tree (bench/chains_derivatives.hpp).
#include "chains_derivatives.hpp"

namespace bench::chains {
void add_derivatives_legged(std::vector<entry>& table) {
    static const derivative_fixture<legged_tree> d{make_fixture<legged_tree>(legged(), 73)};
    add_derivatives(table, "tree", d);
}
}  // namespace bench::chains
