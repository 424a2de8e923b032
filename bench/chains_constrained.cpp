// ctga_chains_bench's constrained dynamics of the quadruped (Solo 12's numbers on the legged tree,
// chains_legged.cpp's fixture): its four feet (the lower legs' points at (0, ±0.008, −0.16), where
// the URDF's feet are) held where they are in each state, four 3-D contacts (constrained/):
//   constrained_fd_quadruped/ctga   q̈ and the 12 contact forces (constrained_forward_dynamics)
//   delassus_quadruped/ctga         the 12 × 12 Delassus operator J H⁻¹ Jᵀ (delassus)
// beside the same run's aba_quadruped/ctga (the target: constrained forward dynamics ≤ 2× ABA);
// and a step of the quadruped standing on the ground on four sphere feet under a PD controller
// (standing_scenario, chains_mujoco.hpp: the same numbers for MuJoCo's row):
//   contact_step_quadruped/ctga     contact_stepper::step (collision, limits, one solve, Euler)
//   contact_step_quadruped/mujoco   mj_step (chains_mujoco.cpp)
// each with its foot slip and sinking printed (stderr) after the same settling.
#include <cmath>
#include <cstdio>
#include <memory>

#include <ctga/constrained/constrained_dynamics.hpp>
#include <ctga/constrained/contact_step.hpp>

#include "chains_kernels.hpp"
#include "chains_mujoco_case.hpp"

namespace bench::chains {
namespace {
namespace cn = ctga::constrained;
using feet = cn::constraint_set<legged_tree, double, 4>;

struct quadruped_case {
    fixture<legged_tree> f = make_fixture<legged_tree>(solo12(), 74);
    std::array<feet, 64> held{};

    quadruped_case() {
        for (std::size_t s = 0; s < 64; ++s) {
            const auto k = ch::forward_kinematics(f.m, f.states[s].q);
            for (int leg = 0; leg < 4; ++leg) {
                const std::size_t shank = static_cast<std::size_t>(3 + 3 * leg);
                const double y = leg % 2 == 0 ? 0.008 : -0.008;
                cn::constraint_block<double> b;
                b.a = static_cast<int>(shank);
                b.at_a.t = {0, y, -0.16};
                b.at_b = ctga::compose(k.pose[shank], b.at_a);  // held where it is
                if (held[s].add(b) != ctga::error_code::none) throw std::logic_error("chains_constrained: a foot refused");
            }
        }
    }
};

template <class Kernel>
void add_kernel(std::vector<entry>& table, const std::string& name, const quadruped_case& c, Kernel kernel) {
    const quadruped_case* p = &c;
    table.push_back({name,
                     [p, kernel](benchmark::State& st) {
                         std::size_t k = 0;
                         for (auto _ : st) {
                             auto r = kernel(*p, k);
                             benchmark::DoNotOptimize(r);
                             k = (k + 1) & 63;
                         }
                     },
                     [p, kernel](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) {
                             auto r = kernel(*p, i & 63);
                             benchmark::DoNotOptimize(r);
                         }
                     }});
}

[[gnu::noinline]] auto constrained_fd(const quadruped_case& c, std::size_t k) {
    const auto& s = c.f.states[k];
    return cn::constrained_forward_dynamics(c.f.m, s.q, s.qd, s.tau, c.held[k]);
}
[[gnu::noinline]] auto delassus_of(const quadruped_case& c, std::size_t k) { return cn::delassus(c.f.m, c.f.states[k].q, c.held[k]); }
// Solo 12 standing on its feet: hips 0, thighs 0.8, knees −1.6 (each foot 0.223 m under its hip),
// dropped from 2 mm; spheres of 1.6 cm at the feet; h = 2 ms (MuJoCo's default step), μ = 1
// (MuJoCo's default friction), kp 10 N m/rad, damping 0.1 N m s/rad.
standing_scenario standing_quadruped() {
    standing_scenario s;
    s.label = "quadruped";
    for (const auto& b : solo12()) s.bodies.push_back(mujoco_detail::body_of(b));
    s.gravity = {0, 0, -9.81};
    const double r = 0.016;
    s.height = 2 * 0.16 * std::cos(0.8) + r + 0.002;
    for (std::size_t leg = 0; leg < 4; ++leg) {
        s.target.insert(s.target.end(), {0.0, 0.8, -1.6});
        s.feet.push_back({3 + 3 * leg, {0, leg % 2 == 0 ? 0.008 : -0.008, -0.16}, r});
    }
    s.h = 0.002, s.mu = 1.0, s.kp = 10.0, s.damping = 0.1;
    s.settle = 1000, s.measure = 500;
    return s;
}

using sphere_kinds = ctga::collision::shape<ctga::collision::sphere<double>>;
using ground_kinds = ctga::collision::shape<ctga::collision::half_space<double>>;

struct standing_robot {
    ch::model<legged_tree> m = ctga_model<legged_tree>(solo12());
    cn::robot_geometry<legged_tree, sphere_kinds, double, 4> feet;
    std::array<cn::static_shape<ground_kinds>, 1> ground{};
    cn::contact_stepper<legged_tree, double, 8> stepper;
    cn::step_settings<double> settings;
    ch::configuration<legged_tree> q{};
    ch::joint_vector<legged_tree> qd{};
    std::array<double, 12> target{};
    double kp = 0;
    cn::step_report<double> last;

    explicit standing_robot(const standing_scenario& s) {
        for (const foot_sphere& f : s.feet) {
            ctga::motor_map<double> at = ch::tree_detail::identity_map<double>();
            at.t = {f.at[0], f.at[1], f.at[2]};
            if (feet.attach(static_cast<int>(f.body), ctga::collision::sphere<double>{f.radius}, at) != ctga::error_code::none)
                throw std::logic_error("contact_step_quadruped: a foot refused");
        }
        settings.step = s.h, settings.mu = s.mu;
        kp = s.kp;
        for (std::size_t k = 6; k < legged_tree::nv; ++k) stepper.limits.damping[k] = s.damping;
        const ctga::motor<double> g = ctga::rigid_motion(ctga::make_translator(0.0, 0.0, s.height), ctga::make_rotor(0.0, 0.0, 0.0, 1.0));
        for (std::size_t k = 0; k < 8; ++k) q[k] = g[k];
        for (std::size_t j = 0; j < 12; ++j) q[8 + j] = target[j] = s.target[j];
    }
};
[[gnu::noinline]] void ctga_contact_kernel_step(standing_robot& x) {
    ch::joint_vector<legged_tree> tau{};
    for (std::size_t j = 0; j < 12; ++j) tau[6 + j] = x.kp * (x.target[j] - x.q[8 + j]);
    x.last = x.stepper.step(x.m, x.q, x.qd, tau, x.feet, std::span<const cn::static_shape<ground_kinds>>(x.ground), x.settings);
}

void add_standing(std::vector<entry>& table, const standing_scenario& s) {
    auto x = std::make_shared<standing_robot>(s);
    standing_figures fig;
    std::size_t sweeps = 0, unconverged = 0;
    for (std::size_t n = 0; n < s.settle + s.measure; ++n) {
        ctga_contact_kernel_step(*x);
        if (x->last.error != ctga::error_code::none) throw std::logic_error(std::string("contact_step_quadruped: ") + ctga::describe(x->last.error));
        sweeps += x->last.solver.sweeps;
        unconverged += !x->last.solver.converged;
        if (n < s.settle) continue;
        const auto k = ch::forward_kinematics(x->m, x->q, x->qd);
        for (const foot_sphere& f : s.feet) {
            const ctga::motor_map<double>& W = k.pose[f.body];
            const ctga::screw<double>& V = k.v[f.body];  // body axes: (ω, v at the body's origin)
            // the sphere's bottom in body axes, and its material velocity there, in world axes
            const ctga::vec3<double> down{W.R[2][0] * -f.radius, W.R[2][1] * -f.radius, W.R[2][2] * -f.radius};
            const ctga::vec3<double> p{f.at[0] + down[0], f.at[1] + down[1], f.at[2] + down[2]};
            const ctga::vec3<double> w{V[0], V[1], V[2]};
            const ctga::vec3<double> vb = ctga::linear3::add(ctga::vec3<double>{V[3], V[4], V[5]}, ctga::linear3::cross(w, p));
            const ctga::vec3<double> v = ctga::linear3::apply(W.R, vb);
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
}
}  // namespace

void add_constrained(std::vector<entry>& table) {
    static const quadruped_case c;
    add_kernel(table, "constrained_fd_quadruped/ctga", c, constrained_fd);
    add_kernel(table, "delassus_quadruped/ctga", c, delassus_of);
    const standing_scenario s = standing_quadruped();
    add_standing(table, s);
    add_mujoco_standing(table, s);
}
}  // namespace bench::chains
