// EXPECT: ctga: a blade is listed twice in a multivector type
// e3e1 and e1e3 are the same blade.
#include <ctga/ctga.hpp>

ctga::cl031::mv<double, "e3e1", "e1e3"> x{};
