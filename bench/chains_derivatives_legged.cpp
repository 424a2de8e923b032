// ctga_chains_bench's derivative kernels of the legged trees (bench/chains_derivatives.hpp): the
// tree (random inertias) and the quadruped (Solo 12's numbers), one tree type, so one unit.
#include "chains_derivatives.hpp"

namespace bench::chains {
void add_derivatives_legged(std::vector<entry>& table) {
    static const derivative_fixture<legged_tree> tree{make_fixture<legged_tree>(legged(), 73)};
    static const derivative_fixture<legged_tree> quadruped{make_fixture<legged_tree>(solo12(), 74)};
    add_derivatives(table, "tree", tree);
    add_derivatives(table, "quadruped", quadruped);
}
}  // namespace bench::chains
