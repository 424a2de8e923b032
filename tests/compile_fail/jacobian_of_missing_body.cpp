// EXPECT: the tree has no body I
// The Jacobian of body 3 of a tree with bodies 0, 1 and 2.
#include <ctga/chains/frame_jacobian.hpp>

using arm = ctga::chains::tree<ctga::chains::link<-1, ctga::chains::revolute_z>,
                               ctga::chains::link<0, ctga::chains::revolute_y>,
                               ctga::chains::link<1, ctga::chains::revolute_y>>;
int main() {
    const ctga::chains::model<arm> m{};
    const auto J = ctga::chains::frame_jacobian(m, ctga::chains::configuration<arm>{}, ctga::chains::body<3>,
                                                ctga::chains::reference::local);
    return J[0][0] > 0;
}
