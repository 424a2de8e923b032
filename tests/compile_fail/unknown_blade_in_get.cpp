// EXPECT: ctga: unknown blade name
// Reading a component under a misspelt blade name.
#include <ctga/ctga.hpp>

using screw = ctga::cl031::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
double read(const screw& s) { return ctga::get<"e2f">(s); }
