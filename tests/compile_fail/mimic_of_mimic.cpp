// EXPECT: master must be another body of the tree whose joint is independent
// Body 2 mimics body 1, itself a mimic of body 0: a mimic joint's master must be an independent
// joint of one degree of freedom (its coordinate is the one q the mimic reads).
#include <ctga/chains/tree.hpp>

namespace ch = ctga::chains;
using gripper = ch::tree<ch::link<-1, ch::prismatic_x>,
                         ch::link<-1, ch::mimic<ch::prismatic_x, 0>>,
                         ch::link<-1, ch::mimic<ch::prismatic_y, 1>>>;
int main() { return static_cast<int>(gripper::size); }
