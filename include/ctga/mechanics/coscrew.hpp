// Co-screws (paper §5–6): momenta and wrenches, the dual of screws, in Cl(0,6,2). The generators
// a1 a2 a3 a carry co-screws, e1 e2 e3 e carry screws; the bar involution swaps them (āi = ei,
// ā = e).
//
//   P = lx a1a + ly a2a + lz a3a + px a2a3 + py a3a1 + pz a1a2      (l, p), a wrench (τ, F)
//
// The invariants of §5–6 are exact constants: A = a1a2a3a, E = Ā = e1e2e3e, and Q0, the element
// pairing a co-screw with a screw, P(s) = P ∨ (Q0 ∧ s).
#pragma once

#include "ctga/mechanics/algebras.hpp"
#include "ctga/operations/formula.hpp"

namespace ctga {

// A co-screw: momentum (l, p) or wrench (τ, F), in the order of the paper's 6-vectors.
template <class T = double>
using coscrew = cl062::mv<T, "a1a", "a2a", "a3a", "a2a3", "a3a1", "a1a2">;
template <class T = double>
using wrench = coscrew<T>;

namespace invariants {
inline constexpr auto A = cl062::basis<"a1a2a3a">;
inline constexpr auto E = cl062::basis<"e1e2e3e">;
inline constexpr auto Q0 = cl062::basis<"a2a3e1e"> + cl062::basis<"a3a1e2e"> + cl062::basis<"a1a2e3e"> +
                           cl062::basis<"a1ae2e3"> + cl062::basis<"a2ae3e1"> + cl062::basis<"a3ae1e2">;
}  // namespace invariants

// §5: the pairing of a co-screw with a screw (the paper's "evaluation map"),
// P(s) = P ∨ (Q0 ∧ s) = ω·l + v·p, a number. s is a screw of Cl(0,3,1) or lifted.
inline constexpr operation pairing{formula([](auto P, auto s) { return P & (invariants::Q0 ^ lift(s)); }),
                                   scalar_over<1>};

// §6: the coadjoint action {s, P} = ½(s̄P − Ps̄) = (ω×l + v×p, ω×p), 18m 12a.
inline constexpr operation coadjoint{
    formula([](auto s, auto P) { return half * (bar(lift(s)) * P - P * bar(lift(s))); }), into<coscrew>};

}  // namespace ctga
