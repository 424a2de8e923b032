// Two bodies coupled by a spring–damper: a box and a rod tumbling in free space, joined between a
// corner of the box and an end of the rod. The printout follows the stretch of the spring, the
// total energy (kinetic + spring) that the damper removes, and the total linear momentum, which
// the internal spring force cannot change.
#include <cmath>
#include <cstdio>

#include <ctga/ctga.hpp>

int main() {
    namespace cg = ctga;
    using box = cg::body_motion<double, cg::subspace::full, cg::inertia_kind::diagonal>;
    using rod = cg::body_motion<double, cg::subspace::full, cg::inertia_kind::axisymmetric>;
    const double m_box = 2.0, m_rod = 0.5, k = 50.0, c = 0.4;
    const box b{{m_box, 0.05, 0.08, 0.1}};   // m, principal moments
    const rod r{{m_rod, 0.04, 0.001}};       // m, moment across the rod, moment along it (e3)
    const cg::vec3<double> corner{0.2, 0.15, 0.1}, tip{0, 0, -0.4};
    const auto world = cg::make_scene(cg::couple(cg::spring_damper<0, 1>{corner, tip, k, c}), b, r);

    using state = cg::motion_state<cg::motor<double>, cg::screw<double>>;
    const auto x0 = world.initial_state(
        state{cg::motor<double>(cg::make_translator(0.0, 0.0, 0.0)), cg::screw<double>{0.5, 2.0, 0.2, 0.0, 0.3, 0.0}},
        state{cg::rigid_motion(cg::make_translator(0.6, 0.4, 0.7), cg::make_rotor(0.5, 1.0, 0.0, 0.0)),
              cg::screw<double>{3.0, -1.0, 8.0, 0.0, 0.0, -0.5}});

    const auto report = [&](double t, const auto& x) {
        const cg::screw<double>& s0 = cg::part<0>(x.s);
        const cg::screw<double>& s1 = cg::part<1>(x.s);
        const cg::motor_map<double> G0 = cg::map_of(cg::part<0>(x.g)), G1 = cg::map_of(cg::part<1>(x.g));
        const auto p0 = cg::linear3::add(cg::linear3::apply(G0.R, corner), G0.t);
        const auto p1 = cg::linear3::add(cg::linear3::apply(G1.R, tip), G1.t);
        const double stretch = std::hypot(p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]);
        const double kinetic =
            0.5 * (0.05 * s0[0] * s0[0] + 0.08 * s0[1] * s0[1] + 0.1 * s0[2] * s0[2] +
                   m_box * (s0[3] * s0[3] + s0[4] * s0[4] + s0[5] * s0[5])) +
            0.5 * (0.04 * (s1[0] * s1[0] + s1[1] * s1[1]) + 0.001 * s1[2] * s1[2] + m_rod * (s1[3] * s1[3] + s1[4] * s1[4] + s1[5] * s1[5]));
        const auto q0 = cg::linear3::apply(G0.R, cg::vec3<double>{m_box * s0[3], m_box * s0[4], m_box * s0[5]});
        const auto q1 = cg::linear3::apply(G1.R, cg::vec3<double>{m_rod * s1[3], m_rod * s1[4], m_rod * s1[5]});
        std::printf("%5.1f  %8.4f  %10.5f   (%8.5f, %8.5f, %8.5f)\n", t, stretch, kinetic + 0.5 * k * stretch * stretch,
                    q0[0] + q1[0], q0[1] + q1[1], q0[2] + q1[2]);
    };
    std::printf("    t   stretch      energy    total linear momentum\n");
    auto x = x0;
    report(0, x);
    for (int n = 1; n <= 12; ++n) {
        const auto run = cg::integrate(cg::lie_rk4{}, world.model(), x, 1e-3, 500);
        if (!run) {
            std::printf("stopped: %s\n", cg::describe(run.error));
            return 1;
        }
        x = run.state;
        report(0.5 * n, x);
    }
    return 0;
}
