// EXPECT: target_type_lacks_blade<'e', '1', 'e', '2', 'e', '3', 'e'>
// s1 ∧ s2 of two screws is a multiple of e1e2e3e, which a screw type cannot hold: the error
// names that blade. (ctga::project would drop it on purpose.)
#include <ctga/ctga.hpp>

using screw = ctga::cl031::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
screw wrong(const screw& a, const screw& b) {
    screw r = a ^ b;
    return r;
}
