// ctga_chains_bench's derivative kernels of the chain30 tree (bench/chains_derivatives.hpp): the
// inverse dynamics' and M⁻¹'s here, the forward dynamics' in chains_derivatives_chain30_aba.cpp
// (as one unit the tree's kernels took 91 s to compile under -j2).
#include "chains_derivatives.hpp"

namespace bench::chains {
void add_derivatives_chain30(std::vector<entry>& table) {
    static const derivative_fixture<chain30_tree> d{make_fixture<chain30_tree>(chain<30>(), 72)};
    add_derivatives<dynamics::inverse, dynamics::inverse_mass>(table, "chain30", d);
}
}  // namespace bench::chains
