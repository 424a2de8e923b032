// ctga_chains_bench's derivative kernels of the arm7 tree (bench/chains_derivatives.hpp).
#include "chains_derivatives.hpp"

namespace bench::chains {
void add_derivatives_arm7(std::vector<entry>& table) {
    static const derivative_fixture<arm7_tree> d{make_fixture<arm7_tree>(arm7(), 71)};
    add_derivatives(table, "arm7", d);
}
}  // namespace bench::chains
