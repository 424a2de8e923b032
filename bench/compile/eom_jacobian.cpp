// Compile-time cost, case (b3): a translation unit with the exact Jacobian ∂ṡ/∂s of one body's
// equations of motion (ctga::jacobian of ctga::motion_rate, the mobility as its 36 blades), the
// Jacobian the implicit midpoint's Newton iteration uses. Measured by tools/compile-cost.sh; not
// part of any CMake target.
#include <cstdio>
#include <cstdlib>

#include <ctga/mechanics/dynamics.hpp>
#include <ctga/operations/jacobian.hpp>

int main(int argc, char** argv) {
    // run-time inputs, so that nothing is folded away
    const double x = argc > 1 ? std::atof(argv[1]) : 0.3;
    const auto b = ctga::make_mass_properties(2.0, ctga::vec3<double>{0.1, x, 0.0},
                                              ctga::mat3<double>{{{1.0, 0.1, 0.0}, {0.1, 1.5, 0.0}, {0.0, 0.0, 2.0}}});
    if (!b) return 1;
    const ctga::screw<double> s{x, 0.2, -0.3, 0.1, 0.4, x};
    const ctga::wrench<double> W{0.0, 0.1, x, 0.2, 0.0, -0.1};
    const auto J = ctga::jacobian<2, ctga::lifted_screw<double>>(ctga::motion_rate, ctga::body_inertia_of(*b),
                                                                 ctga::mobility_of(*b), s, W);
    std::printf("%g\n", J(0, 0) + J(5, 5));
    return 0;
}
