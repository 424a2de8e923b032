// EXPECT: ctga: unknown blade name
// A blade name with a factor that is not a generator of the algebra (Cl(0,3,1) has no e4).
#include <ctga/ctga.hpp>

using bad = ctga::cl031::mv<double, "e1e4">;
bad x{};
