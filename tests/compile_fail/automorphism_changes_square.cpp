// EXPECT: ctga: the automorphism maps a generator to one with a different square
// Swapping e1 (square −1) with e (square 0) is no automorphism of Cl(0,3,1).
#include <ctga/ctga.hpp>

auto x = ctga::automorphism<3, 1, 2, 0>(ctga::cl031::blade<"e1e2">());
