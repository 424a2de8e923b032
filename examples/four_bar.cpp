// A four-bar linkage driven by its crank (issue 45): three bars on hinges as a kinematic tree (the
// crank and the coupler on one branch, the rocker on another), the loop closed by a constraint
// that holds the coupler's end on the rocker's, and a motor on the crank. Each step takes
// constrained forward dynamics (constrained/constrained_dynamics.hpp: q̈ and the closing force)
// and RK4; the printout shows the crank and rocker angles, the force in the closing pin, and how
// well the motion keeps Freudenstein's equation (K1 cos φ − K2 cos θ + K3 = cos(θ − φ)).
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <ctga/chains/algorithms.hpp>
#include <ctga/constrained/constrained_dynamics.hpp>

namespace ch = ctga::chains;
namespace cn = ctga::constrained;

// crank a about the origin, coupler b on its end, rocker c about (d, 0, 0); planar, gravity −y
using four_bar = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_z>, ch::link<-1, ch::revolute_z>,
                          ch::fixed_frame<"coupler_end", 1>, ch::fixed_frame<"rocker_end", 2>>;
constexpr double a = 1.0, b = 3.0, c = 2.5, d = 3.0;

int main() {
    ch::model<four_bar> m;
    m.gravity = {0, -9.81, 0};
    const auto bar = [](double length, double mass) {  // a rod along x from its hinge
        const double I = mass * length * length / 12;
        return ctga::make_mass_properties(mass, ctga::vec3<double>{length / 2, 0, 0}, ctga::mat3<double>{{{1e-3, 0, 0}, {0, I, 0}, {0, 0, I}}});
    };
    const auto at = [](double x) { return ctga::motor<double>(ctga::make_translator(x, 0.0, 0.0)); };
    m.link<0>() = *ch::make_link<ch::revolute_z>(at(0), bar(a, 1.0));
    m.link<1>() = *ch::make_link<ch::revolute_z>(at(a), bar(b, 2.0));
    m.link<2>() = *ch::make_link<ch::revolute_z>(at(d), bar(c, 1.5));
    m.frames[0] = *ch::make_frame(at(b));
    m.frames[1] = *ch::make_frame(at(c));

    // the loop: the coupler's end held on the rocker's (3 rows; the one along z is redundant)
    cn::constraint_set<four_bar, double, 1> closure;
    if (closure.close_loop(m, ch::frame<"coupler_end">, ch::frame<"rocker_end">) != ctga::error_code::none) return 1;
    cn::constrained_settings<double> settings;
    settings.stabilization = 20;  // Baumgarte, 1/s

    // a closed start: θ = 0.3, the coupler's end where the two circles meet
    const double theta = 0.3, ax = a * std::cos(theta), ay = a * std::sin(theta), dx = d - ax, dy = -ay, L = std::hypot(dx, dy);
    const double along = (b * b - c * c + L * L) / (2 * L), h = std::sqrt(b * b - along * along);
    const double bx = ax + (along * dx - h * dy) / L, by = ay + (along * dy + h * dx) / L;
    ch::configuration<four_bar> q{theta, std::atan2(by - ay, bx - ax) - theta, std::atan2(by, bx - d)};
    ch::joint_vector<four_bar> v{};

    const auto dynamics = [&](const ch::configuration<four_bar>& x, const ch::joint_vector<four_bar>& xd) {
        const ch::joint_vector<four_bar> tau{20.0 - xd[0], 0, 0};  // the crank's motor, 20 N m less its back-EMF
        const auto r = cn::constrained_forward_dynamics(m, x, xd, tau, closure, settings);
        if (r.error != ctga::error_code::none) {
            std::puts(ctga::describe(r.error));
            std::exit(1);
        }
        return r;
    };
    const auto acceleration = [&](const auto& x, const auto& xd) { return dynamics(x, xd).qdd; };
    const double K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2 * a * c);
    const double dt = 2.5e-4;
    std::printf("   t      crank θ   rocker φ   pin force (N)   Freudenstein residual\n");
    for (int step = 0; step <= 8000; ++step) {
        const auto now = dynamics(q, v);
        const auto& a1 = now.qdd;
        const auto& force = now.force;  // on the coupler's end, in the rocker's axes
        if (step % 1000 == 0)
            std::printf("%5.2f  %9.4f  %9.4f  %14.3f  %10.1e\n", step * dt, q[0], q[2], std::hypot(force[0], force[1]),
                        K1 * std::cos(q[2]) - K2 * std::cos(q[0]) + K3 - std::cos(q[0] - q[2]));
        const auto add = [](auto x, const auto& dx, double t) {
            for (std::size_t i = 0; i < x.size(); ++i) x[i] += t * dx[i];
            return x;
        };
        const auto q2 = add(q, v, dt / 2), v2 = add(v, a1, dt / 2);
        const auto a2 = acceleration(q2, v2);
        const auto q3 = add(q, v2, dt / 2), v3 = add(v, a2, dt / 2);
        const auto a3 = acceleration(q3, v3);
        const auto q4 = add(q, v3, dt), v4 = add(v, a3, dt);
        const auto a4 = acceleration(q4, v4);
        for (std::size_t i = 0; i < 3; ++i) {
            q[i] += dt / 6 * (v[i] + 2 * v2[i] + 2 * v3[i] + v4[i]);
            v[i] += dt / 6 * (a1[i] + 2 * a2[i] + 2 * a3[i] + a4[i]);
        }
    }
    return 0;
}
