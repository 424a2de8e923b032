// ctga_batch_bench's kernels of the 7-dof arm (bench/chain_trees.hpp): batch_{rnea,aba,crba}_arm7.
#include "chains_batch.hpp"

namespace bench::batch {
void add_arm7() {
    const auto m = chains::ctga_model<chains::arm7_tree>(chains::arm7());
    const auto states = chains::random_states<chains::arm7_tree>(71);
    add_widths<algorithm::rnea>("rnea_arm7", m, states, 7);
    add_widths<algorithm::aba>("aba_arm7", m, states, 7);
    add_widths<algorithm::crba>("crba_arm7", m, states, 7);
}
}  // namespace bench::batch
