// The contact scenarios of ctga_chains_bench (contact_scenario, chains_mujoco.hpp): a robot on
// spheres on the ground, or holding a free body, under a PD controller, stepped by ctga's
// contact_stepper; its figures measured after settling (stderr), its row contact_step_<label>/ctga
// registered beside MuJoCo's (add_mujoco_contact). Used by chains_constrained.cpp (the quadruped),
// chains_humanoid_contact.cpp (the humanoid) and chains_grasp_contact.cpp (the grasp), one robot
// per unit (compile time).
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
namespace contact_detail {
namespace cn = ctga::constrained;
namespace co = ctga::collision;

using ground_kinds = co::shape<co::half_space<double>>;

// A free joint's start as MuJoCo's qpos and as ctga's motor (make_mujoco_case's conversion: the
// map's translation, the rotor's four numbers are the quaternion).
inline std::array<double, 7> free_qpos(const std::array<double, 3>& at, double angle_about_y) {
    const ctga::motor<double> g = ctga::rigid_motion(ctga::make_translator(at[0], at[1], at[2]), ctga::make_rotor(angle_about_y, 0.0, 1.0, 0.0));
    const auto G = ctga::map_of(g);
    return {G.t[0], G.t[1], G.t[2], g[0], g[1], g[2], g[3]};
}
inline ctga::motor<double> free_motor(const std::array<double, 7>& p) {
    return ctga::rigid_motion(ctga::make_translator(p[0], p[1], p[2]), ctga::rotor<double>{p[3], p[4], p[5], p[6]});
}

template <class Tree, class Kinds, std::size_t Shapes, std::size_t Capacity>
struct contact_robot {
    using tree = Tree;
    ch::model<Tree> m;
    cn::robot_geometry<Tree, Kinds, double, Shapes> shapes;
    std::array<cn::static_shape<ground_kinds>, 1> ground{};
    cn::contact_stepper<Tree, double, Capacity> stepper;
    cn::step_settings<double> settings;
    ch::configuration<Tree> q{};
    ch::joint_vector<Tree> qd{};
    std::array<double, Tree::nv> target{};  // on the actuated (one-dof) joints' velocity numbers
    std::array<bool, Tree::nv> actuated{};
    double kp = 0;
    cn::step_report<double> last;

    contact_robot(const contact_scenario& s, const ch::model<Tree>& model) : m(model) {
        for (const body_shape& f : s.shapes) {
            ctga::motor_map<double> at = ch::tree_detail::identity_map<double>();
            at.t = {f.at[0], f.at[1], f.at[2]};
            Kinds shape = co::sphere<double>{f.radius};
            bool boxed = false;  // (a box where the kinds have boxes)
            if constexpr (std::is_constructible_v<Kinds, co::box<double>>)
                if (f.half[0] > 0) shape = co::box<double>{{f.half[0], f.half[1], f.half[2]}}, boxed = true;
            if ((f.half[0] > 0) != boxed || shapes.attach(static_cast<int>(f.body), shape, at) != ctga::error_code::none)
                throw std::logic_error("contact_step_" + s.label + ": a shape refused");
        }
        settings.step = s.h, settings.mu = s.mu;
        kp = s.kp;
        std::size_t next_free = 0, next_actuated = 0;
        for (std::size_t i = 0; i < Tree::size; ++i) {
            const std::size_t o = Tree::q_offset[i], k = Tree::v_offset[i];
            if (Tree::nv_of[i] == 6) {
                const ctga::motor<double> g = free_motor(s.free_start.at(next_free++));
                for (std::size_t j = 0; j < 8; ++j) q[o + j] = g[j];
            } else if (Tree::nv_of[i] == 1) {
                actuated[k] = true;
                stepper.limits.damping[k] = s.damping;
                q[o] = target[k] = s.target.at(next_actuated++);
            }
        }
    }
};
template <class Robot>
[[gnu::noinline]] void ctga_contact_kernel_step(Robot& x) {
    ch::joint_vector<typename Robot::tree> tau{};
    for (std::size_t i = 0; i < Robot::tree::size; ++i)
        if (Robot::tree::nv_of[i] == 1) {
            const std::size_t k = Robot::tree::v_offset[i];
            tau[k] = x.kp * (x.target[k] - x.q[Robot::tree::q_offset[i]]);
        }
    x.last = x.stepper.step(x.m, x.q, x.qd, tau, x.shapes, std::span<const cn::static_shape<ground_kinds>>(x.ground), x.settings);
}

// The scenario's figures (chains_mujoco.hpp), ctga's row and MuJoCo's.
template <class Robot>
inline void add_contact_step(std::vector<entry>& table, const contact_scenario& s, std::shared_ptr<Robot> x) {
    contact_figures fig;
    std::size_t sweeps = 0, unconverged = 0;
    for (std::size_t n = 0; n < s.settle + s.measure; ++n) {
        ctga_contact_kernel_step(*x);
        if (x->last.error != ctga::error_code::none) throw std::logic_error("contact_step_" + s.label + ": " + ctga::describe(x->last.error));
        sweeps += x->last.solver.sweeps;
        unconverged += !x->last.solver.converged;
        if (n < s.settle) continue;
        const auto k = ch::forward_kinematics(x->m, x->q, x->qd);
        if (s.held >= 0) {  // its origin's speed: (ω, v) in body axes, v the origin's
            const ctga::screw<double>& V = k.v[static_cast<std::size_t>(s.held)];
            fig.slip = std::max(fig.slip, std::sqrt(V[3] * V[3] + V[4] * V[4] + V[5] * V[5]));
            fig.sinking = std::max(fig.sinking, x->last.penetration);
            continue;
        }
        for (const body_shape& f : s.shapes) {
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
                 "ctga_chains_bench: ctga contact_step_%s (h %g s, tolerance %.0e N s): after %zu steps, over %zu: %s %.1e m/s, %s %.1e m; "
                 "%.1f sweeps a step, %zu steps unconverged\n",
                 s.label.c_str(), s.h, x->settings.solve.rows.solver.tolerance, s.settle, s.measure, s.held >= 0 ? "the held body's speed" : "slip",
                 fig.slip, s.held >= 0 ? "deepest overlap" : "sinking", fig.sinking,
                 static_cast<double>(sweeps) / static_cast<double>(s.settle + s.measure), unconverged);
    table.push_back({"contact_step_" + s.label + "/ctga",
                     [x](benchmark::State& st) {
                         for (auto _ : st) ctga_contact_kernel_step(*x);
                     },
                     [x](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) ctga_contact_kernel_step(*x);
                     }});
    add_mujoco_contact(table, s);
}
}  // namespace contact_detail
}  // namespace bench::chains
