// ctga_chains_bench's step of a grasp (chains_contact_steps.hpp): a parallel gripper on the world,
// two fingers on slides along y, squeezing a free cube between their pads against gravity; the
// cube a second root of the same tree (a floating joint on the world), so that the fingers'
// contacts with it and its weight are one solve:
//   contact_step_grasp/ctga     contact_stepper::step
//   contact_step_grasp/mujoco   mj_step (chains_mujoco.cpp)
//   contact_step_grasp/ctga_world  the same fingers as a two-root tree in a robot_world, the cube
//                               a world's body (a box body kind), the ground a world's static
// Its figures: the cube's speed (how fast it slips out of the grasp) and the deepest overlap.
#include <array>
#include <memory>

#include <ctga/constrained/robot_world.hpp>

#include "chains_contact_steps.hpp"

namespace bench::chains {
namespace {
using gripper_tree = ch::tree<ch::link<-1, ch::prismatic_y>,  // 0 the left finger, 0.05 m to the left of the cube's centre
                              ch::link<-1, ch::prismatic_y>,  // 1 the right finger
                              ch::link<-1, ch::floating>>;    // 2 the cube

// Fingers of 0.1 kg with pads 4 × 1 × 6 cm; a cube of 6 cm and 0.2 kg, 0.3 m up; each finger's PD
// target 5 mm inside the cube's face (kp 1000 N/m: 5 N of squeeze, 10 N of friction at μ = 1
// against a weight of 1.96 N), damping 20 N s/m; started there (5 mm overlaps the step resolves).
contact_scenario grasp() {
    contact_scenario s;
    s.label = "grasp";
    const std::array<std::array<double, 3>, 3> finger_I{{{1e-4, 0, 0}, {0, 1e-4, 0}, {0, 0, 1e-4}}}, cube_I{{{1.2e-4, 0, 0}, {0, 1.2e-4, 0}, {0, 0, 1.2e-4}}};
    s.bodies = {{-1, mujoco_joint::slide, {0, 1, 0}, {0, 0.05, 0.3}, 0.1, {0, 0, 0}, finger_I},
                {-1, mujoco_joint::slide, {0, 1, 0}, {0, -0.05, 0.3}, 0.1, {0, 0, 0}, finger_I},
                {-1, mujoco_joint::free, {0, 0, 0}, {0, 0, 0}, 0.2, {0, 0, 0}, cube_I}};
    s.gravity = {0, 0, -9.81};
    s.free_start = {contact_detail::free_qpos({0, 0, 0.3}, 0.0)};
    s.target = {-0.02, 0.02};
    s.shapes = {{0, {0, 0, 0}, 0, {0.02, 0.005, 0.03}}, {1, {0, 0, 0}, 0, {0.02, 0.005, 0.03}}, {2, {0, 0, 0}, 0, {0.03, 0.03, 0.03}}};
    s.h = 0.002, s.mu = 1.0, s.kp = 1000.0, s.damping = 20.0;
    s.settle = 1000, s.measure = 500;
    s.held = 2;
    return s;
}

ch::model<gripper_tree> gripper_model(const contact_scenario& s) {
    ch::model<gripper_tree> m;
    m.gravity = {0, 0, -9.81};
    const auto link = [&](std::size_t i) {
        const mujoco_body& b = s.bodies[i];
        return std::pair{ctga::motor<double>(ctga::make_translator(b.t[0], b.t[1], b.t[2])),
                         ctga::make_mass_properties(b.mass, ctga::vec3<double>{b.com[0], b.com[1], b.com[2]}, b.Ic)};
    };
    const auto [p0, b0] = link(0);
    const auto [p1, b1] = link(1);
    const auto [p2, b2] = link(2);
    m.link<0>() = *ch::make_link<ch::prismatic_y>(p0, b0);
    m.link<1>() = *ch::make_link<ch::prismatic_y>(p1, b1);
    m.link<2>() = *ch::make_link<ch::floating>(p2, b2);
    return m;
}
namespace cn = ctga::constrained;
namespace co = ctga::collision;
// The grasp in one world: the fingers (the scenario's bodies 0 and 1) a tree, the cube (body 2) a
// world's body of the same mass and inertia, started as the scenario starts it.
using fingers_tree = ch::tree<ch::link<-1, ch::prismatic_y>, ch::link<-1, ch::prismatic_y>>;
using cube_kind = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, co::box<double>>;
struct grasp_world {
    cn::robot_world<fingers_tree, double, 16, co::half_space<double>, cube_kind> w{{1}, {.statics = 1, .contacts = 32, .pairs = 8}};
    ch::model<fingers_tree> m;
    cn::robot_geometry<fingers_tree, co::box<double>, double, 2> shapes;
    cn::step_settings<double> settings;
    ch::configuration<fingers_tree> q{};
    ch::joint_vector<fingers_tree> qd{};
    double kp = 0;
    std::array<double, 2> target{};
    cn::scene_report<double> last;

    explicit grasp_world(const contact_scenario& s) {
        const ch::model<gripper_tree> full = gripper_model(s);
        m.gravity = full.gravity;
        m.link<0>() = full.link<0>(), m.link<1>() = full.link<1>();
        const double side = 2 * s.shapes[2].half[0], density = s.bodies[2].mass / (side * side * side);
        if (!w.world.add_static(co::half_space<double>{}, ctga::motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {s.mu, 0.0}) ||
            !w.world.add_body<0>(co::box<double>{{side / 2, side / 2, side / 2}}, density, contact_detail::free_motor(s.free_start[0]), {s.mu, 0.0}))
            throw std::logic_error("contact_step_grasp/ctga_world: the world refused its cube");
        for (int i = 0; i < 2; ++i) {
            const auto& f = s.shapes[static_cast<std::size_t>(i)];
            if (shapes.attach(i, co::box<double>{{f.half[0], f.half[1], f.half[2]}}) != ctga::error_code::none)
                throw std::logic_error("contact_step_grasp/ctga_world: a pad refused");
            q[static_cast<std::size_t>(i)] = target[static_cast<std::size_t>(i)] = s.target[static_cast<std::size_t>(i)];
            w.robot.limits.damping[static_cast<std::size_t>(i)] = s.damping;
        }
        settings.step = s.h, settings.mu = s.mu, kp = s.kp;
    }
};
[[gnu::noinline]] void ctga_world_grasp_step(grasp_world& x) {
    const ch::joint_vector<fingers_tree> tau{x.kp * (x.target[0] - x.q[0]), x.kp * (x.target[1] - x.q[1])};
    x.last = x.w.step(x.m, x.q, x.qd, tau, x.shapes, x.settings);
}
}  // namespace

void add_grasp_contact(std::vector<entry>& table) {
    using namespace contact_detail;
    const contact_scenario s = grasp();
    add_contact_step(table, s, std::make_shared<contact_robot<gripper_tree, co::shape<co::sphere<double>, co::box<double>>, 3, 16>>(s, gripper_model(s)));
    // the same in one world, its figures as add_contact_step's
    const auto x = std::make_shared<grasp_world>(s);
    contact_figures fig;
    std::size_t sweeps = 0, unconverged = 0;
    for (std::size_t n = 0; n < s.settle + s.measure; ++n) {
        ctga_world_grasp_step(*x);
        if (x->last.error != ctga::error_code::none) throw std::logic_error(std::string("contact_step_grasp/ctga_world: ") + ctga::describe(x->last.error));
        sweeps += x->last.solver.sweeps;
        unconverged += !x->last.solver.converged;
        if (n < s.settle) continue;
        const ctga::screw<double>& V = x->w.world.velocity<0>(0);
        fig.slip = std::max(fig.slip, std::sqrt(V[3] * V[3] + V[4] * V[4] + V[5] * V[5]));
        fig.sinking = std::max(fig.sinking, x->last.robot.penetration);
    }
    std::fprintf(stderr,
                 "ctga_chains_bench: ctga contact_step_grasp/ctga_world (h %g s, tolerance %.0e N s): after %zu steps, over %zu: the held "
                 "body's speed %.1e m/s, deepest overlap %.1e m; %.1f sweeps a step, %zu steps unconverged\n",
                 s.h, x->settings.solve.rows.solver.tolerance, s.settle, s.measure, fig.slip, fig.sinking,
                 static_cast<double>(sweeps) / static_cast<double>(s.settle + s.measure), unconverged);
    table.push_back({"contact_step_grasp/ctga_world",
                     [x](benchmark::State& st) {
                         for (auto _ : st) ctga_world_grasp_step(*x);
                     },
                     [x](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) ctga_world_grasp_step(*x);
                     }});
}
}  // namespace bench::chains
