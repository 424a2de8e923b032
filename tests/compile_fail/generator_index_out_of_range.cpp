// EXPECT: ctga: generator index out of range
// Cl(0,3,1) has generators 0..3.
#include <ctga/ctga.hpp>

auto x = ctga::cl031::generator<4>();
