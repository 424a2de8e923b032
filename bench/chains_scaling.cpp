// ctga_chains_scaling_*'s kernels: serial chains of the sizes in CTGA_CHAINS_SCALING (1 … 64
// bodies), RNEA, ABA and CRBA in ctga and in the hand-written spatial code.
#include <string>

#include "chains_kernels.hpp"

namespace bench::chains {
namespace {
template <std::size_t... N>
void add_sizes(std::vector<entry>& table) {
    (
        [&] {
            static const auto f = make_fixture<chain_tree<N>>(chain<N>(), 100 + N);
            add_tree<algorithm::rnea, algorithm::aba, algorithm::crba>(table, "chain/" + std::to_string(N), f);
        }(),
        ...);
}
}  // namespace
void add_scaling(std::vector<entry>& table) { add_sizes<CTGA_CHAINS_SCALING>(table); }
}  // namespace bench::chains
