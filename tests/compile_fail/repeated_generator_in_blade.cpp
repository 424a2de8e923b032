// EXPECT: ctga: a generator appears twice in a blade name
// A blade is a product of distinct generators: "e1e1" is not a blade name.
#include <ctga/ctga.hpp>

auto x = ctga::cl031::blade<"e1e1">();
