// A rigid body with the paper's mechanics (§2–6): checked mass properties, the inertia element N
// of Cl(0,6,2), momentum, energy, a motion moving it, and the equations of motion solved for ṡ.
#include <cstdio>
#include <iostream>

#include <ctga/ctga.hpp>

int main() {
    namespace cg = ctga;
    // a 2 kg box, 0.3 × 0.2 × 0.1 m, centre of mass at the origin of its frame
    const double m = 2, Ixx = m * (0.2 * 0.2 + 0.1 * 0.1) / 12, Iyy = m * (0.3 * 0.3 + 0.1 * 0.1) / 12,
                 Izz = m * (0.3 * 0.3 + 0.2 * 0.2) / 12;
    const auto checked = cg::make_rigid_body(m, cg::vec3<double>{0, 0, 0},
                                             cg::mat3<double>{{{Ixx, 0, 0}, {0, Iyy, 0}, {0, 0, Izz}}});
    if (!checked) {
        std::puts(cg::describe(checked.error));  // e.g. a triangle-inequality violation
        return 1;
    }
    const cg::rigid_body<> body = *checked;

    const cg::motor<> g = cg::rigid_motion(cg::make_translator(1.0, 0.0, 0.5), cg::make_rotor(0.3, 0.0, 0.0, 1.0));
    const cg::screw<> s{0.1, 2.0, 0.1, 0.0, 0.0, 0.0};  // body-frame velocity (ω, v): tumbling about y

    const cg::coscrew<> P = cg::momentum(body.N, s);       // P = A ∨ (N ∧ s)
    const double E = cg::kinetic_energy(body.N, s);        // ½ s̄ ∨ (N ∧ s)
    const cg::motor_map<> G = cg::map_of(g);               // the sandwich by g, built once
    const cg::rigid_inertia<> N_space = cg::transform(G, body.N);  // (g ḡ) N (g ḡ)*
    const cg::screw<> s_space = cg::transform(G, s);               // g s g*

    const cg::wrench<> W{0, 0, 0, 0, 0, -9.81 * m};  // gravity in the body frame, for the example
    const cg::state_rate<> rate = cg::body_frame_rates(body, g, s, W);

    std::cout << "N (body)       = " << body.N << "\n"
              << "P = A v (N ^ s) = " << P << "\n"
              << "E_k            = " << E << "\n"
              << "N (space)      = " << N_space << "\n"
              << "s (space)      = " << s_space << "\n"
              << "ds/dt          = " << rate.s_dot << "\n"
              << "dg/dt = g s / 2 = " << rate.g_dot << "\n";
    return 0;
}
