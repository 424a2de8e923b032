// EXPECT: two frames have the same name
// Two named frames called "tool0" (on different bodies): a frame's name must say which it is.
#include <ctga/chains/tree.hpp>

namespace ch = ctga::chains;
using arm = ch::tree<ch::link<-1, ch::revolute_z>,
                     ch::link<0, ch::revolute_y>,
                     ch::fixed_frame<"tool0", 1>,
                     ch::fixed_frame<"tool0", 0>>;
int main() { return static_cast<int>(arm::frame_count); }
