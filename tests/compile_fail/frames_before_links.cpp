// EXPECT: list the bodies \(link entries\) first, then the frames
// A fixed_frame listed before a link: the bodies are numbered by the links, which come first.
#include <ctga/chains/tree.hpp>

namespace ch = ctga::chains;
using arm = ch::tree<ch::link<-1, ch::revolute_z>,
                     ch::fixed_frame<"tool0", 0>,
                     ch::link<0, ch::revolute_y>>;
int main() { return static_cast<int>(arm::size); }
