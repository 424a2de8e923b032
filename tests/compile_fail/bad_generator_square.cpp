// EXPECT: ctga::algebra: every generator square must be
// Generators square to +1, −1 or 0.
#include <ctga/ctga.hpp>

ctga::algebra<"e1 e2", 1, 2>::mv<double, "e1"> x{};
