// Compile-time cost, case (a): a minimal user translation unit of the algebra core and the
// expression engine only (no mechanics): the product of two motors of Cl(0,3,1), 48m 40a.
// Measured by tools/compile-cost.sh; not part of any CMake target.
#include <cstdio>
#include <cstdlib>

#include <ctga/operations/formula.hpp>
#include <ctga/operations/operators.hpp>
#include <ctga/mechanics/algebras.hpp>

using G = ctga::cl031;
using motor = G::mv<double, "1", "e2e3", "e3e1", "e1e2", "ee1e2e3", "e1e", "e2e", "e3e">;

int main(int argc, char** argv) {
    // run-time operands, so that the product is not folded away
    const double x = argc > 1 ? std::atof(argv[1]) : 0.5;
    const motor g1{x, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
    const motor g2{0.7, x, 0.5, 0.4, 0.3, 0.2, 0.1, 0.0};
    const motor g = g1 * g2;
    double sum = 0;
    for (std::size_t i = 0; i < motor::size(); ++i) sum += g[i];
    std::printf("%g\n", sum);
    return 0;
}
