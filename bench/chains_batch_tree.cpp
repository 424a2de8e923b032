// ctga_batch_bench's kernels of the legged tree (a floating base and four legs of three joints,
// bench/chain_trees.hpp): batch_{rnea,aba,crba}_tree.
#include "chains_batch.hpp"

namespace bench::batch {
void add_tree() {
    const auto m = chains::ctga_model<chains::legged_tree>(chains::legged());
    const auto states = chains::random_states<chains::legged_tree>(73);
    add_widths<algorithm::rnea>("rnea_tree", m, states, 0);
    add_widths<algorithm::aba>("aba_tree", m, states, 0);
    add_widths<algorithm::crba>("crba_tree", m, states, 0);
}
}  // namespace bench::batch
