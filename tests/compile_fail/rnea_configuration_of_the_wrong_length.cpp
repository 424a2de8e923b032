// EXPECT: configuration_has_the_wrong_length<ctga::chains::argument<2>, ctga::chains::expected<32>, ctga::chains::given<31>
// FIRST-LINES: 8
// rnea(m, q, q̇, q̈) with q of 31 numbers on a humanoid whose configuration has 32 (a floating
// base's 8, 24 joints): the first lines name the argument, the length expected and the one given.
#include <array>

#include <ctga/chains/rnea.hpp>

#include "large_tree.hpp"

namespace ch = ctga::chains;
using large_tree_fixture::humanoid;

int main() {
    const ch::model<humanoid> m{};
    const std::array<double, 31> q{};
    const ch::joint_vector<humanoid> qd{}, qdd{};
    const auto tau = ch::rnea(m, q, qd, qdd);
    return tau[0] > 0;
}
