// EXPECT: state_array_has_another_scalar<ctga::chains::argument<2>, ctga::chains::expected_type<double>, ctga::chains::given_type<float>
// FIRST-LINES: 8
// float arrays given to a double model (no silent conversion of a robot's state): the first
// lines name the first such argument, the model's scalar and the one given.
#include <array>

#include <ctga/chains/rnea.hpp>

#include "large_tree.hpp"

namespace ch = ctga::chains;
using large_tree_fixture::humanoid;

int main() {
    const ch::model<humanoid, double> m{};
    const ch::configuration<humanoid, float> q{};
    const ch::joint_vector<humanoid, float> qd{}, qdd{};
    const auto tau = ch::rnea(m, q, qd, qdd);
    return tau[0] > 0;
}
