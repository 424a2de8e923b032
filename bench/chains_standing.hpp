// The standing scenarios of ctga_chains_bench (standing_scenario, chains_mujoco.hpp): a robot on
// spheres on the ground under a PD controller, stepped by ctga's contact_stepper, its slip and
// sinking measured after settling (stderr), its row contact_step_<label>/ctga registered beside
// MuJoCo's (add_mujoco_standing). Used by chains_constrained.cpp (the quadruped) and
// chains_humanoid_contact.cpp (the humanoid), one robot per unit (compile time).
#pragma once

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include <ctga/constrained/contact_step.hpp>

#include "chains_kernels.hpp"
#include "chains_mujoco_case.hpp"

namespace bench::chains {
namespace standing_detail {
namespace cn = ctga::constrained;

using sphere_kinds = ctga::collision::shape<ctga::collision::sphere<double>>;
using ground_kinds = ctga::collision::shape<ctga::collision::half_space<double>>;

// The base's start as ctga's motor and as MuJoCo's free joint's qpos (make_mujoco_case's
// conversion: the map's translation, the rotor's four numbers).
inline ctga::motor<double> base_motor(double height, double angle_about_y) {
    return ctga::rigid_motion(ctga::make_translator(0.0, 0.0, height), ctga::make_rotor(angle_about_y, 0.0, 1.0, 0.0));
}
inline std::array<double, 7> base_qpos(const ctga::motor<double>& g) {
    const auto G = ctga::map_of(g);
    return {G.t[0], G.t[1], G.t[2], g[0], g[1], g[2], g[3]};
}

template <class Tree, std::size_t Spheres, std::size_t Capacity>
struct standing_robot {
    static constexpr std::size_t hinges = Tree::nv - 6;
    ch::model<Tree> m;
    cn::robot_geometry<Tree, sphere_kinds, double, Spheres> spheres;
    std::array<cn::static_shape<ground_kinds>, 1> ground{};
    cn::contact_stepper<Tree, double, Capacity> stepper;
    cn::step_settings<double> settings;
    ch::configuration<Tree> q{};
    ch::joint_vector<Tree> qd{};
    std::array<double, hinges> target{};
    double kp = 0;
    cn::step_report<double> last;

    standing_robot(const standing_scenario& s, const ch::model<Tree>& model, const ctga::motor<double>& base) : m(model) {
        for (const foot_sphere& f : s.feet) {
            ctga::motor_map<double> at = ch::tree_detail::identity_map<double>();
            at.t = {f.at[0], f.at[1], f.at[2]};
            if (spheres.attach(static_cast<int>(f.body), ctga::collision::sphere<double>{f.radius}, at) != ctga::error_code::none)
                throw std::logic_error("contact_step_" + s.label + ": a sphere refused");
        }
        settings.step = s.h, settings.mu = s.mu;
        kp = s.kp;
        for (std::size_t k = 6; k < Tree::nv; ++k) stepper.limits.damping[k] = s.damping;
        for (std::size_t k = 0; k < 8; ++k) q[k] = base[k];
        for (std::size_t j = 0; j < hinges; ++j) q[8 + j] = target[j] = s.target[j];
    }
};
template <class Robot>
[[gnu::noinline]] void ctga_contact_kernel_step(Robot& x) {
    ch::joint_vector<typename std::remove_cvref_t<decltype(x.m)>::tree_type> tau{};
    for (std::size_t j = 0; j < Robot::hinges; ++j) tau[6 + j] = x.kp * (x.target[j] - x.q[8 + j]);
    x.last = x.stepper.step(x.m, x.q, x.qd, tau, x.spheres, std::span<const cn::static_shape<ground_kinds>>(x.ground), x.settings);
}

template <class Robot>
inline void add_standing(std::vector<entry>& table, const standing_scenario& s, std::shared_ptr<Robot> x) {
    standing_figures fig;
    std::size_t sweeps = 0, unconverged = 0;
    for (std::size_t n = 0; n < s.settle + s.measure; ++n) {
        ctga_contact_kernel_step(*x);
        if (x->last.error != ctga::error_code::none) throw std::logic_error("contact_step_" + s.label + ": " + ctga::describe(x->last.error));
        sweeps += x->last.solver.sweeps;
        unconverged += !x->last.solver.converged;
        if (n < s.settle) continue;
        const auto k = ch::forward_kinematics(x->m, x->q, x->qd);
        for (const foot_sphere& f : s.feet) {
            const ctga::motor_map<double>& W = k.pose[f.body];
            const ctga::screw<double>& V = k.v[f.body];  // body axes: (ω, v at the body's origin)
            // the sphere's bottom in body axes, and its material velocity there, in world axes
            const ctga::vec3<double> p{f.at[0] - f.radius * W.R[2][0], f.at[1] - f.radius * W.R[2][1], f.at[2] - f.radius * W.R[2][2]};
            const ctga::vec3<double> w{V[0], V[1], V[2]};
            const ctga::vec3<double> v = ctga::linear3::apply(W.R, ctga::linear3::add(ctga::vec3<double>{V[3], V[4], V[5]}, ctga::linear3::cross(w, p)));
            fig.slip = std::max(fig.slip, std::hypot(v[0], v[1]));
            const ctga::vec3<double> centre = ctga::linear3::add(ctga::linear3::apply(W.R, ctga::vec3<double>{f.at[0], f.at[1], f.at[2]}), W.t);
            fig.sinking = std::max(fig.sinking, f.radius - centre[2]);
        }
    }
    std::fprintf(stderr,
                 "ctga_chains_bench: ctga contact_step_%s (h %g s, tolerance %.0e N s): after %zu steps, over %zu: slip %.1e m/s, sinking %.1e m; "
                 "%.1f sweeps a step, %zu steps unconverged\n",
                 s.label.c_str(), s.h, x->settings.solve.rows.solver.tolerance, s.settle, s.measure, fig.slip, fig.sinking,
                 static_cast<double>(sweeps) / static_cast<double>(s.settle + s.measure), unconverged);
    table.push_back({"contact_step_" + s.label + "/ctga",
                     [x](benchmark::State& st) {
                         for (auto _ : st) ctga_contact_kernel_step(*x);
                     },
                     [x](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) ctga_contact_kernel_step(*x);
                     }});
    add_mujoco_standing(table, s);
}
}  // namespace standing_detail
}  // namespace bench::chains
