// EXPECT: the two frames are on one body
// FIRST-LINES: 12
// A loop closure between two frames fixed to one body constrains nothing: refused at compile time.
#include <ctga/constrained/constraint_set.hpp>

namespace ch = ctga::chains;
using arm = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_y>, ch::fixed_frame<"a", 1>, ch::fixed_frame<"b", 1>>;
int main() {
    ch::model<arm> m;
    ctga::constrained::constraint_set<arm, double, 2> C;
    return static_cast<int>(C.close_loop(m, ch::frame<"a">, ch::frame<"b">));
}
