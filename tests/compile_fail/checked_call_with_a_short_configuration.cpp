// EXPECT: configuration_has_the_wrong_length<ctga::chains::argument<2>, ctga::chains::expected<32>, ctga::chains::given<30>
// FIRST-LINES: 8
// checked_call(aba, m, q, q̇, τ) with a joint vector passed as q: checked_call hands q to the
// algorithm as given, whose first lines name it (argument<2> of aba, the model being the first).
#include <ctga/chains/aba.hpp>
#include <ctga/chains/checked_call.hpp>

#include "large_tree.hpp"

namespace ch = ctga::chains;
using large_tree_fixture::humanoid;

int main() {
    const ch::model<humanoid> m{};
    const ch::joint_vector<humanoid> q{}, qd{}, tau{};
    const auto qdd = ch::checked_call(ch::aba, m, q, qd, tau);
    return qdd.value[0] > 0;
}
