// Compile-time cost, case (b): a translation unit using the mechanics of <ctga/ctga.hpp>:
// a checked rigid body, momentum and kinetic energy, a motor_map transforming a screw, a
// co-screw and the rigid inertia, and the body-frame rates of the equations of motion
// (acceleration inside). Measured by tools/compile-cost.sh; not part of any CMake target.
#include <cstdio>
#include <cstdlib>

#include <ctga/ctga.hpp>

int main(int argc, char** argv) {
    namespace cg = ctga;
    // run-time inputs, so that nothing is folded away
    const double x = argc > 1 ? std::atof(argv[1]) : 0.3;
    const double m = 2, Ixx = 0.0083, Iyy = 0.0167, Izz = 0.0217;
    const auto checked = cg::make_rigid_body(m, cg::vec3<double>{0.01, 0, x / 10},
                                             cg::mat3<double>{{{Ixx, 0, 0}, {0, Iyy, 0}, {0, 0, Izz}}});
    if (!checked) {
        std::puts(cg::describe(checked.error));
        return 1;
    }
    const cg::rigid_body<> body = *checked;
    const cg::motor<> g = cg::rigid_motion(cg::make_translator(1.0, x, 0.5), cg::make_rotor(x, 0.0, 0.0, 1.0));
    const cg::screw<> s{0.1, 2.0, x, 0.0, 0.5, 0.0};
    const cg::wrench<> W{0, 0, 0, 0, 0, -9.81 * m};

    const cg::coscrew<> P = cg::momentum(body.N, s);                 // A ∨ (N ∧ s)
    const double E = cg::kinetic_energy(body.N, s);                  // ½ s̄ ∨ (N ∧ s)
    const cg::motor_map<> G = cg::map_of(g);                         // the sandwich by g
    const cg::screw<> s1 = cg::transform(G, s);                      // g s g*
    const cg::coscrew<> P1 = cg::transform(G, P);                    // ḡ P ḡ*
    const cg::rigid_inertia<> N1 = cg::transform(G, body.N);         // (g ḡ) N (g ḡ)*
    const cg::screw<> a = cg::acceleration(body.N, body.M, s, W);    // ṡ in the body frame
    const cg::state_rate<> r = cg::body_frame_rates(body, g, s, W);  // (ġ, ṡ)

    double sum = E;
    for (std::size_t i = 0; i < 6; ++i) sum += P[i] + s1[i] + P1[i] + a[i] + r.s_dot[i];
    for (std::size_t i = 0; i < cg::rigid_inertia<>::size(); ++i) sum += N1[i];
    for (std::size_t i = 0; i < cg::motor<>::size(); ++i) sum += r.g_dot[i];
    std::printf("%g\n", sum);
    return 0;
}
