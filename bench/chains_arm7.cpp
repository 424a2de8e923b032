// ctga_chains_bench's kernels of the arm7 tree (bench/chain_models.hpp).
#include "chains_kernels.hpp"
#include "chains_mujoco_case.hpp"

namespace bench::chains {
void add_arm7(std::vector<entry>& table) {
    static const auto f = make_fixture<arm7_tree>(arm7(), 71);
    add_tree<algorithm::rnea, algorithm::aba, algorithm::crba, algorithm::fk, algorithm::jacobian>(table, "arm7", f);
    add_mujoco(table, make_mujoco_case("arm7", f, arm7()));
    // the same arm and states with its joints not declared aligned: <algorithm>_arm7/ctga_general
    static const auto g = make_fixture<arm7_general_tree>(arm7(), 71);
    add<algorithm::rnea, implementation::ctga>(table, "rnea_arm7/ctga_general", g);
    add<algorithm::aba, implementation::ctga>(table, "aba_arm7/ctga_general", g);
    add<algorithm::crba, implementation::ctga>(table, "crba_arm7/ctga_general", g);
}
}  // namespace bench::chains
