// The two algebras of the paper, with the generator order and orientations of
// shared conventions (every formula of the paper holds exactly under them).
#pragma once

#include "ctga/algebra/signature.hpp"

namespace ctga {

// Cl(0,3,1), §3: screws, rotors, translators, motors.  e1² = e2² = e3² = −1, e² = 0.
using cl031 = algebra<"e1 e2 e3 e", -1, -1, -1, 0>;

// Cl(0,6,2), §5: momenta (co-screws), wrenches, inertias. ai² = ei² = −1, a² = e² = 0, in this
// order: the shuffle product's determinant uses it as the basis order, det(a1,…,e) = +1.
using cl062 = algebra<"a1 a2 a3 a e1 e2 e3 e", -1, -1, -1, 0, -1, -1, -1, 0>;

}  // namespace ctga
