// EXPECT: the tree has no frame of this name
// chains::frame<"tool9"> on a tree whose frames are "tool0" and "base": a name the tree does not
// have is a compile error (find_frame reports it at run time, error_code::unknown_frame).
#include <ctga/chains/forward_kinematics.hpp>
#include <ctga/chains/frames.hpp>

namespace ch = ctga::chains;
using arm = ch::tree<ch::link<-1, ch::revolute_z>,
                     ch::link<0, ch::revolute_y>,
                     ch::fixed_frame<"tool0", 1>,
                     ch::fixed_frame<"base", 0>>;
int main() {
    const ch::model<arm> m{};
    const auto k = ch::forward_kinematics(m, ch::configuration<arm>{});
    const auto W = ch::frame_pose(m, k, ch::frame<"tool9">);
    return W.t[0] > 0;
}
