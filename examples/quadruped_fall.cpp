// A floating-base robot with four legs, from its URDF (tests/data/quadruped.urdf with
// --floating-base: the trunk's configuration is a motor, its velocity a body-frame screw). With
// no contact, it falls: its centre of mass follows −½ g t² exactly whatever the legs do, while
// the legs, driven by PD torques towards a crouch, swing the trunk around. Integrated by lie_rk4,
// which moves the trunk's motor on the group (it stays a unit motor), with h = 0.25 ms (the PD
// transient of the legs is stiff: at h = 1 ms the centre of mass is 1e-4 m off after 0.5 s).
#include <array>
#include <cmath>
#include <cstdio>

#include <ctga/ctga.hpp>

#include "quadruped.hpp"  // generated: namespace quadruped { using tree = …; make_model<T>(); }

namespace ch = ctga::chains;
using robot = quadruped::tree;

// PD torques on the twelve leg joints towards a crouch; none on the trunk's six.
struct crouch {
    std::array<double, robot::nv> target{};
    template <std::size_t NQ, std::size_t NV>
    std::array<double, NV> operator()(const std::array<double, NQ>& q, const std::array<double, NV>& qd) const {
        std::array<double, NV> tau{};
        for (std::size_t k = 6; k < NV; ++k) tau[k] = 40.0 * (target[k] - q[k + 2]) - 1.0 * qd[k];  // q: 8 motor numbers first
        return tau;
    }
};

// the centre of mass of the whole robot, world frame
ctga::vec3<double> centre_of_mass(const ch::model<robot>& m, const ch::configuration<robot>& q, double& mass) {
    const auto k = ch::forward_kinematics(m, q);
    ctga::vec3<double> c{};
    mass = 0;
    ch::algorithm_detail::forward<robot::size>([&](auto body) {
        constexpr std::size_t i = decltype(body)::value;
        const auto& N = m.link<i>().inertia;
        const auto Rh = ctga::linear3::apply(k.pose[i].R, N.first_moment());  // m_i c_i = R h + m t
        for (std::size_t r = 0; r < 3; ++r) c[r] += Rh[r] + N.mass() * k.pose[i].t[r];
        mass += N.mass();
    });
    for (double& x : c) x /= mass;
    return c;
}

int main() {
    const auto made = quadruped::make_model<double>();
    if (!made) {
        std::printf("quadruped: %s\n", ctga::describe(made.error));
        return 1;
    }
    ch::tree_motion<robot, double, crouch> sim{*made, {}};
    for (std::size_t leg = 0; leg < 4; ++leg) {  // thigh +0.6 rad, calf −1.2 rad
        sim.actuation.target[6 + 3 * leg + 1] = 0.6;
        sim.actuation.target[6 + 3 * leg + 2] = -1.2;
    }
    // start: trunk 0.5 m up, level, turning slowly; legs straight
    ch::configuration<robot> q0{};
    const ctga::motor<double> trunk = ctga::rigid_motion(ctga::make_translator(0.0, 0.0, 0.5), ctga::make_rotor(0.0, 0.0, 0.0, 1.0));
    for (std::size_t k = 0; k < 8; ++k) q0[k] = trunk[k];
    ch::joint_vector<robot> qd0{};
    qd0[2] = 0.5;  // yaw rate of the trunk (body frame)
    double mass = 0;
    const ctga::vec3<double> c0 = centre_of_mass(sim.m, q0, mass);
    std::printf("quadruped: %zu bodies, %zu velocity numbers, mass %.2f kg; centre of mass at z = %.4f m\n", robot::size,
                robot::nv, mass, c0[2]);
    std::printf("  t      com z      -g t^2/2 + z0   trunk |g g* - 1|   calf joint (rad)\n");
    const double h = 2.5e-4, g = 9.81;
    double worst = 0;
    const auto run = ctga::integrate(ctga::lie_rk4{}, sim, {{q0}, {qd0}}, h, 2000, [&](long long k, const auto& x) {
        const double t = h * static_cast<double>(k);
        double m = 0;
        const ctga::vec3<double> c = centre_of_mass(sim.m, x.g.x, m);
        const double expected = c0[2] - 0.5 * g * t * t;
        worst = std::fmax(worst, std::fabs(c[2] - expected));
        if (k % 400 == 0) {
            const ctga::motor<double> gb{x.g[0], x.g[1], x.g[2], x.g[3], x.g[4], x.g[5], x.g[6], x.g[7]};
            std::printf("  %.1f   %9.6f   %9.6f         %.1e            %7.4f\n", t, c[2], expected,
                        std::fabs(ctga::unit_defect(gb).alpha_norm), x.g[8 + 2]);
        }
    });
    if (!run) {
        std::printf("simulation stopped: %s\n", ctga::describe(run.error));
        return 1;
    }
    std::printf("centre of mass against free fall: worst difference %.1e m over 0.5 s\n", worst);
    return worst < 1e-6 ? 0 : 1;
}
