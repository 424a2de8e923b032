// EXPECT: the_tree_has_no_frame_named<'f', 'o', 'o', 't', '_', 'l'>
// FIRST-LINES: 12
// A contact on a frame the tree does not have (a misspelt name) does not compile, and says the name.
#include <ctga/constrained/constraint_set.hpp>

namespace ch = ctga::chains;
using leg = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_y>, ch::fixed_frame<"foot_r", 1>>;
int main() {
    ch::model<leg> m;
    ctga::constrained::constraint_set<leg, double, 2> C;
    return static_cast<int>(C.touch(m, ch::configuration<leg>{}, ch::frame<"foot_l">, ctga::vec3<double>{0, 0, 1}, 0.5));
}
