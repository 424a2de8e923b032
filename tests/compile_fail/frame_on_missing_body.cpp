// EXPECT: a fixed_frame's body must be a body of the tree or -1
// A named frame on body 3 of a tree with bodies 0, 1 and 2.
#include <ctga/chains/tree.hpp>

namespace ch = ctga::chains;
using arm = ch::tree<ch::link<-1, ch::revolute_z>,
                     ch::link<0, ch::revolute_y>,
                     ch::link<1, ch::revolute_y>,
                     ch::fixed_frame<"tool0", 3>>;
int main() { return static_cast<int>(arm::frame_count); }
