// EXPECT: use ctga::sandwich\(R, x\) or write it as a ctga::formula
// R * p * reverse(R) in Cl(3,0,1): R is two independent leaves, so the grade-1 terms that cancel
// between them are not seen and the product does not fit a point; the message says what to do.
#include <ctga/ctga.hpp>

using pga = ctga::algebra<"e0 e1 e2 e3", 0, 1, 1, 1>;
using point = pga::mv<double, "e0e3e2", "e0e1e3", "e0e2e1", "e1e2e3">;
using rotor = pga::mv<double, "1", "e1e2">;
point wrong(const rotor& R, const point& p) {
    point q = R * p * ctga::reverse(R);
    return q;
}
