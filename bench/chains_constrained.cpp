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
#include <numbers>
#include <type_traits>
#include <utility>

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
using sphere_kinds = ctga::collision::shape<ctga::collision::sphere<double>>;
using ground_kinds = ctga::collision::shape<ctga::collision::half_space<double>>;

// The base's start as ctga's motor and as MuJoCo's free joint's qpos (make_mujoco_case's
// conversion: the map's translation, the rotor's four numbers).
ctga::motor<double> base_motor(double height, double angle_about_y) {
    return ctga::rigid_motion(ctga::make_translator(0.0, 0.0, height), ctga::make_rotor(angle_about_y, 0.0, 1.0, 0.0));
}
std::array<double, 7> base_qpos(const ctga::motor<double>& g) {
    const auto G = ctga::map_of(g);
    return {G.t[0], G.t[1], G.t[2], g[0], g[1], g[2], g[3]};
}

// Solo 12 standing on its feet: hips 0, thighs 0.8, knees −1.6 (each foot 0.223 m under its hip),
// dropped from 2 mm; spheres of 1.6 cm at the feet; h = 2 ms (MuJoCo's default step), μ = 1
// (MuJoCo's default friction), kp 10 N m/rad, damping 0.1 N m s/rad.
standing_scenario standing_quadruped() {
    standing_scenario s;
    s.label = "quadruped";
    for (const auto& b : solo12()) s.bodies.push_back(mujoco_detail::body_of(b));
    s.gravity = {0, 0, -9.81};
    const double r = 0.016;
    s.base = base_qpos(base_motor(2 * 0.16 * std::cos(0.8) + r + 0.002, 0.0));
    for (std::size_t leg = 0; leg < 4; ++leg) {
        s.target.insert(s.target.end(), {0.0, 0.8, -1.6});
        s.feet.push_back({3 + 3 * leg, {0, leg % 2 == 0 ? 0.008 : -0.008, -0.16}, r});
    }
    s.h = 0.002, s.mu = 1.0, s.kp = 10.0, s.damping = 0.1;
    s.settle = 1000, s.measure = 500;
    return s;
}

// The humanoid (chain_models.hpp, 44 dofs) lying face down, every joint held at 0: spheres of
// 5 cm at its pelvis, knees, ankles, torso, head, elbows and wrists (11 contacts; its own pairs
// tested too), dropped from 2 mm; h, μ as the quadruped's, kp 100 N m/rad, damping 1 N m s/rad.
standing_scenario lying_humanoid() {
    standing_scenario s;
    s.label = "humanoid";
    for (const auto& b : humanoid()) s.bodies.push_back(mujoco_detail::body_of(b));
    s.gravity = {0, 0, -9.81};
    const double r = 0.05;
    s.base = base_qpos(base_motor(r + 0.002, std::numbers::pi / 2));  // the body's z (head) to the world's x
    s.target.assign(humanoid_tree::nv - 6, 0.0);
    const std::array<std::pair<std::size_t, double>, 11> at{{{0, 0.0}, {4, 0.0}, {6, -0.05}, {10, 0.0}, {12, -0.05}, {14, 0.2}, {16, 0.1},
                                                             {20, 0.0}, {23, -0.05}, {31, 0.0}, {34, -0.05}}};
    for (const auto& [body, z] : at) s.feet.push_back({body, {0, 0, z}, r});
    s.h = 0.002, s.mu = 1.0, s.kp = 100.0, s.damping = 1.0;
    s.settle = 1000, s.measure = 500;
    return s;
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
void add_standing(std::vector<entry>& table, const standing_scenario& s, std::shared_ptr<Robot> x) {
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
}  // namespace

void add_constrained(std::vector<entry>& table) {
    static const quadruped_case c;
    add_kernel(table, "constrained_fd_quadruped/ctga", c, constrained_fd);
    add_kernel(table, "delassus_quadruped/ctga", c, delassus_of);
    const standing_scenario quadruped = standing_quadruped(), humanoid = lying_humanoid();
    add_standing(table, quadruped,
                 std::make_shared<standing_robot<legged_tree, 4, 8>>(quadruped, ctga_model<legged_tree>(solo12()), base_motor(quadruped.base[2], 0.0)));
    add_standing(table, humanoid,
                 std::make_shared<standing_robot<humanoid_tree, 11, 24>>(humanoid, ctga_model<humanoid_tree>(bench::chains::humanoid()),
                                                                          base_motor(humanoid.base[2], std::numbers::pi / 2)));
}
}  // namespace bench::chains
