// EXPECT: state_array_is_not_a_std_array<ctga::chains::argument<2>, ctga::chains::expected_type<std::array<double, 32> ?>, ctga::chains::given_type<std::vector<double
// FIRST-LINES: 8
// q as a std::vector: the algorithms read std::arrays whose length is the tree's; the first
// lines name the argument, the std::array expected and the type given.
#include <vector>

#include <ctga/chains/rnea.hpp>

#include "large_tree.hpp"

namespace ch = ctga::chains;
using large_tree_fixture::humanoid;

int main() {
    const ch::model<humanoid> m{};
    const std::vector<double> q(humanoid::nq);
    const ch::joint_vector<humanoid> qd{}, qdd{};
    const auto tau = ch::rnea(m, q, qd, qdd);
    return tau[0] > 0;
}
