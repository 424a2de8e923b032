// EXPECT: ctga: lower\(\) takes an element of the e-half of Cl\(0,6,2\)
// A co-screw lives on the a's of Cl(0,6,2) (§5): it has no image in Cl(0,3,1). Its screw is the
// bar, lower(eval(bar(P))).
#include <ctga/ctga.hpp>

auto wrong(const ctga::coscrew<double>& P) { return ctga::lower(P); }
