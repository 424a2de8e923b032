// EXPECT: the_tree_has_no_frame_named<'l', '_', 's', 'o', 'l'>
// FIRST-LINES: 8
// A frame function from q (frame_jacobian computes the poses of the frame's path, so the frame
// is looked up deep in its body): the first lines name the frame the humanoid lacks ("l_sole").
#include <ctga/chains/frame_jacobian.hpp>

#include "large_tree.hpp"

namespace ch = ctga::chains;
using large_tree_fixture::humanoid;

int main() {
    const ch::model<humanoid> m{};
    const auto J = ch::frame_jacobian(m, ch::configuration<humanoid>{}, ch::frame<"l_sol">, ch::reference::world);
    return J(0, 0) > 0;
}
