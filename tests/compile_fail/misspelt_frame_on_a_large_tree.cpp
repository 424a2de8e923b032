// EXPECT: the_tree_has_no_frame_named<'t', 'o', 'l', '0'>
// FIRST-LINES: 8
// frame_pose(m, k, chains::frame<"tol0">) on a humanoid whose frames include "tool0": the first
// lines of the compiler's output name the frame asked for, not only kilobytes further down in
// an instantiation trace that prints the 75-entry tree type on every line. (The umbrella header:
// the longest include chain a user has.)
#include <ctga/ctga.hpp>

#include "large_tree.hpp"

namespace ch = ctga::chains;
using large_tree_fixture::humanoid;

int main() {
    const ch::model<humanoid> m{};
    const auto k = ch::forward_kinematics(m, ch::configuration<humanoid>{});
    const auto W = ch::frame_pose(m, k, ch::frame<"tol0">);
    return W.t[0] > 0;
}
