// EXPECT: ctga::algebra: the number of generator names differs
// Three squares, two names.
#include <ctga/ctga.hpp>

ctga::algebra<"e1 e2", 1, 1, 1>::mv<double, "e1"> x{};
