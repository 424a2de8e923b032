// Screws (paper §3): velocities (twists) and the elements of the Lie algebra of rigid motions,
// the bivectors of Cl(0,3,1) with the blade orientations of the shared conventions,
//
//   s = ωx e2e3 + ωy e3e1 + ωz e1e2 + vx e1e + vy e2e + vz e3e      (ω, v)
//
// The same six blades on the e's of Cl(0,6,2) are lifted_screw (§5); lift(s) views a screw there
// without copying (algebras.hpp).
#pragma once

#include "ctga/mechanics/algebras.hpp"
#include "ctga/operations/formula.hpp"

namespace ctga {

template <class T = double>
using screw = cl031::mv<T, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;

// A screw of §3 placed on the e's of Cl(0,6,2): the same coefficients, (ω, v).
template <class T = double>
using lifted_screw = cl062::mv<T, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;

// §3: the Lie bracket [s1, s2] = ½(s1 s2 − s2 s1) = (ω1×ω2, ω1×v2 − ω2×v1), 18m 12a.
inline constexpr operation bracket{formula([](auto s1, auto s2) { return half * (s1 * s2 - s2 * s1); }), into<screw>};

}  // namespace ctga
