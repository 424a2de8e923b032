// EXPECT: joint_vector_has_the_wrong_length<ctga::chains::argument<3>, ctga::chains::expected<30>, ctga::chains::given<32>
// FIRST-LINES: 8
// aba(m, q, q̇, τ) with q̇ of the configuration's length (32) where a velocity has nv = 30
// numbers (a floating base moves by 6): the first lines name the argument and both lengths.
#include <ctga/chains/aba.hpp>

#include "large_tree.hpp"

namespace ch = ctga::chains;
using large_tree_fixture::humanoid;

int main() {
    const ch::model<humanoid> m{};
    const ch::configuration<humanoid> q{}, qd{};
    const ch::joint_vector<humanoid> tau{};
    const auto qdd = ch::aba(m, q, qd, tau);
    return qdd[0] > 0;
}
