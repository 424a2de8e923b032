// EXPECT: ctga: the automorphism.s images are not a permutation
// Two generators sent to the same image.
#include <ctga/ctga.hpp>

auto x = ctga::automorphism<0, 0, 2, 3>(ctga::cl031::blade<"e1e2">());
