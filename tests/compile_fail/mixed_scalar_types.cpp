// EXPECT: ctga: the operands have different scalar types
// No silent promotion between float and double multivectors.
#include <ctga/ctga.hpp>

auto x = ctga::cl031::blade<"e1", float>() * ctga::cl031::blade<"e2", double>();
