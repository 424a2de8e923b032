// EXPECT: target_type_lacks_blade<'e', '0', 'e', '1'>
// ctga::pga::sandwich returns its argument's type: moving a line gives a line, and a point cannot
// hold a line's blades. The error names the first of them, e0e1.
#include <ctga/ctga.hpp>

namespace pga = ctga::pga;
pga::point<> wrong(const pga::motor<>& M, const pga::line<>& l) {
    pga::point<> q = pga::sandwich(M, l);
    return q;
}
