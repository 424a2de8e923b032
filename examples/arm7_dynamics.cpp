// A 7-dof arm under gravity, from its URDF (tests/data/arm7.urdf, turned into the header arm7.hpp
// by tools/urdf_to_ctga.py when building): the joint torques of a trajectory by inverse dynamics
// (RNEA), the same accelerations back from those torques by forward dynamics (ABA), then the arm
// let go and simulated, its energy printed.
#include <array>
#include <cmath>
#include <cstdio>

#include <ctga/ctga.hpp>

#include "arm7.hpp"  // generated: namespace arm7 { using tree = …; make_model<T>(); }

namespace ch = ctga::chains;

int main() {
    const auto made = arm7::make_model<double>();
    if (!made) {
        std::printf("arm7: %s\n", ctga::describe(made.error));
        return 1;
    }
    const ch::model<arm7::tree>& arm = *made;
    constexpr std::size_t n = arm7::tree::nv;  // 7 (the tool is fixed)

    // 1. a trajectory q_k(t) = a_k sin(w_k t) + b_k, and the torques that make the arm follow it
    const auto reference = [](double t, ch::configuration<arm7::tree>& q, ch::joint_vector<arm7::tree>& qd,
                              ch::joint_vector<arm7::tree>& qdd) {
        for (std::size_t k = 0; k < n; ++k) {
            const double a = 0.4 + 0.05 * static_cast<double>(k), w = 1.0 + 0.3 * static_cast<double>(k), b = 0.1 * static_cast<double>(k);
            q[k] = a * std::sin(w * t) + b;
            qd[k] = a * w * std::cos(w * t);
            qdd[k] = -a * w * w * std::sin(w * t);
        }
    };
    std::printf("inverse dynamics of a 2 s trajectory (N m, every 0.25 s):\n  t    ");
    for (std::size_t k = 0; k < n; ++k) std::printf("  tau%zu   ", k + 1);
    std::printf("\n");
    double worst_roundtrip = 0, peak = 0;
    for (int step = 0; step <= 200; ++step) {
        const double t = 0.01 * step;
        ch::configuration<arm7::tree> q{};
        ch::joint_vector<arm7::tree> qd{}, qdd{};
        reference(t, q, qd, qdd);
        const auto tau = ch::checked_call(ch::rnea, arm, q, qd, qdd);  // τ = ID(q, q̇, q̈)
        const auto back = ch::checked_call(ch::aba, arm, q, qd, *tau); // q̈ = FD(q, q̇, τ)
        if (!tau || !back) return 1;
        for (std::size_t k = 0; k < n; ++k) {
            worst_roundtrip = std::fmax(worst_roundtrip, std::fabs(back.value[k] - qdd[k]));
            peak = std::fmax(peak, std::fabs(tau.value[k]));
        }
        if (step % 25 == 0) {
            std::printf("  %.2f ", t);
            for (double x : *tau) std::printf(" %8.3f", x);
            std::printf("\n");
        }
    }
    std::printf("peak |tau| %.2f N m; forward dynamics gives the trajectory's accelerations back to %.1e rad/s^2\n\n",
                peak, worst_roundtrip);

    // 2. the arm let go at the trajectory's start, no torques: lie_rk4, energy kept
    ch::configuration<arm7::tree> q0{};
    ch::joint_vector<arm7::tree> qd0{}, qdd0{};
    reference(0, q0, qd0, qdd0);
    const ch::tree_motion<arm7::tree> sim{arm};
    const ctga::motion_state<ch::coordinates<n>, ch::coordinates<n>> x0{{q0}, {qd0}};
    const double E0 = sim.energy(x0.g, x0.s);
    std::printf("the arm let go (gravity only), lie_rk4 with h = 1 ms:\n   t      E (J)       kinetic    potential   |E - E0|/|E0|\n");
    double worst = 0;
    const auto run = ctga::integrate(ctga::lie_rk4{}, sim, x0, 1e-3, 3000, [&](long long k, const auto& x) {
        const double E = sim.energy(x.g, x.s);
        worst = std::fmax(worst, std::fabs(E - E0) / std::fabs(E0));
        if (k % 500 == 0)
            std::printf("  %.1f  %10.6f  %10.6f  %10.6f   %.1e\n", 1e-3 * static_cast<double>(k), E,
                        ch::tree_kinetic_energy(arm, x.g.x, x.s.x), ch::tree_potential_energy(arm, x.g.x), std::fabs(E - E0) / std::fabs(E0));
    });
    if (!run) {
        std::printf("simulation stopped: %s\n", ctga::describe(run.error));
        return 1;
    }
    std::printf("worst relative energy error over 3 s: %.1e\n", worst);
    return worst_roundtrip < 1e-9 && worst < 1e-6 ? 0 : 1;
}
