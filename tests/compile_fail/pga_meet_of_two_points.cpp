// EXPECT: this join or meet is zero for every input
// The meet (∧) of two points has grade 6 in a 4-dimensional algebra: zero for every input. The
// error says so (the join, ∨, is the line through them).
#include <ctga/ctga.hpp>

namespace pga = ctga::pga;
void wrong(const pga::point<>& p, const pga::point<>& q) {
    (void)pga::meet(p, q);
}
