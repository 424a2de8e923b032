// EXPECT: ctga: set<Name>: this multivector type does not hold that blade
// A screw has no scalar component to set.
#include <ctga/ctga.hpp>

using screw = ctga::cl031::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
void f(screw& s) { s.set<"1">(1.0); }
