// EXPECT: this joint's axis is fixed by its type
// revolute_x turns about x whatever axis is passed: make_link refuses the axis instead of
// ignoring it (revolute_about takes a run-time axis).
#include <ctga/ctga.hpp>

int main() {
    const auto link = ctga::chains::make_link<ctga::chains::revolute_x>(
        ctga::motor<double>(ctga::make_rotor(0.0, 0.0, 0.0, 1.0)), ctga::make_principal_mass_properties(1.0, 0.1, 0.1, 0.1),
        ctga::vec3<double>{0.0, 1.0, 0.0});
    return link ? 0 : 1;
}
