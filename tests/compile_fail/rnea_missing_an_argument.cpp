// EXPECT: no_overload_takes_these_arguments<ctga::chains::algorithm_named<'r', 'n', 'e', 'a'>
// FIRST-LINES: 8
// rnea(m, q, q̇) without q̈: no array to replace makes a call an overload takes, so the first
// lines name the algorithm and the arguments' types.
#include <ctga/chains/rnea.hpp>

#include "large_tree.hpp"

namespace ch = ctga::chains;
using large_tree_fixture::humanoid;

int main() {
    const ch::model<humanoid> m{};
    const ch::configuration<humanoid> q{};
    const ch::joint_vector<humanoid> qd{};
    const auto tau = ch::rnea(m, q, qd);
    return tau[0] > 0;
}
