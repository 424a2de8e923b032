// The paper's formulas as code (Selig & Bayro-Corrochano, "Rigid Body Dynamics Using Clifford
// Algebra", 2010), printed with blade names. Every type below carries its blade set, and every
// product evaluates only the blade pairs that can be non-zero.
#include <cmath>
#include <iostream>

#include <ctga/ctga.hpp>

int main() {
    using namespace ctga;

    // §3, Cl(0,3,1): a screw s = ω·(e2e3, e3e1, e1e2) + v·(e1e, e2e, e3e), a rotor r, a translator t
    using screw = cl031::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
    const screw s{0.0, 0.0, 1.0, 0.5, 0.0, 0.0};  // spinning about z, moving along x
    const double theta = std::acos(-1.0) / 2;     // a quarter turn about z
    const auto r = std::cos(theta / 2) + cl031::blade<"e1e2">(std::sin(theta / 2));
    const auto t = 1.0 + 0.5 * cl031::blade<"e1e">(2.0);  // translate by 2 along x
    const auto g = t * r;
    std::cout << "Cl(0,3,1)\n"
              << "  s        = " << s << "\n"
              << "  g = t r  = " << g << "\n"
              << "  g g*     = " << g * conj(g) << "\n"
              << "  g s g*   = " << grade<2>(g * s * conj(g)) << "\n"
              << "  e1e2 ∨ e3e = " << (cl031::blade<"e1e2">() & cl031::blade<"e3e">()) << "   (§4)\n";

    // §5, Cl(0,6,2): the screw on the e's, a co-screw on the a's, the invariants Q0, A, E
    using G = cl062;
    using screw6 = G::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
    using inertia = G::mv<double, "a1ae1e", "a2ae2e", "a3ae3e", "a2a3e2e3", "a3a1e3e1", "a1a2e1e2">;
    const screw6 s6{0.0, 0.0, 1.0, 0.5, 0.0, 0.0};
    const G::mv<double, "a2a3e1e", "a3a1e2e", "a1a2e3e", "a1ae2e3", "a2ae3e1", "a3ae1e2"> Q0{1, 1, 1, 1, 1, 1};
    const auto A = G::blade<"a1a2a3a">();
    const double m = 2.0, dx = 0.1, dy = 0.2, dz = 0.3;
    const inertia N{dx, dy, dz, m, m, m};  // diagonal inertia: N = dx a1ae1e + … + m a1a2e1e2

    const auto P = A & (N ^ s6);            // momentum  P = A ∨ (N ∧ s)
    const auto twice_Ek = P & (Q0 ^ s6);    // evaluation P ∨ (Q0 ∧ s) = ω·l + v·p = 2 E_k
    std::cout << "Cl(0,6,2)\n"
              << "  N            = " << N << "\n"
              << "  A ∨ (N ∧ s)  = " << P << "\n"
              << "  P ∨ (Q0 ∧ s) = " << twice_Ek << "   (2 E_k = dz ωz² + m vx²)\n"
              << "  A ∨ (Q0 ∧ s) = " << (A & (Q0 ^ s6)) << "   (= s̄)\n"
              << "  a1a2a3a ∨ a3a1e1e2e3e = " << (A & G::blade<"a3a1e1e2e3e">()) << "   (§4: −a1a3 = a3a1)\n";
    return 0;
}
