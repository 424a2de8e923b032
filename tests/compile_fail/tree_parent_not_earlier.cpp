// EXPECT: every body's parent must be an earlier body
// A kinematic tree whose body 1 names body 2 as its parent: the bodies must be listed parents first.
#include <ctga/chains/tree.hpp>

using bad = ctga::chains::tree<ctga::chains::link<-1, ctga::chains::revolute_z>,
                               ctga::chains::link<2, ctga::chains::revolute_y>,
                               ctga::chains::link<0, ctga::chains::revolute_y>>;
int main() { return static_cast<int>(bad::size); }
