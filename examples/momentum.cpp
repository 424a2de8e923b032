// The README's example: the paper's momentum and kinetic energy (§5), as written there.
#include <iostream>

#include <ctga/ctga.hpp>

using G = ctga::cl062;  // generators a1 a2 a3 a e1 e2 e3 e, squares −1 −1 −1 0 −1 −1 −1 0

using velocity = G::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;   // the screw s = (ω, v)
using inertia  = G::mv<double, "a1ae1e", "a2ae2e", "a3ae3e", "a2a3e2e3", "a3a1e3e1", "a1a2e1e2">;
using Q0_type  = G::mv<double, "a2a3e1e", "a3a1e2e", "a1a2e3e", "a1ae2e3", "a2ae3e1", "a3ae1e2">;

constexpr velocity s{0, 0, 1, 0.5, 0, 0};
constexpr inertia  N{0.1, 0.2, 0.3, 2, 2, 2};        // dx, dy, dz, m, m, m
constexpr Q0_type  Q0{1, 1, 1, 1, 1, 1};
constexpr auto     A = G::basis<"a1a2a3a">;           // the paper's invariant A, an exact constant

constexpr auto P = A & (N ^ s);                       // P = A ∨ (N ∧ s), a lazy expression: 6 products, no more
static_assert(ctga::scalar_part(P & (Q0 ^ s)) == 0.8); // P ∨ (Q0 ∧ s) = 2 E_k = dz ωz² + m vx², at compile time
static_assert((A & (Q0 ^ s)) == ctga::bar(s));        // A ∨ (Q0 ∧ s) = s̄

int main() { std::cout << P << "\n"; }                // a2a3 + 0.3*a3a
