// ctga_chains_bench's step of a grasp (chains_contact_steps.hpp): a parallel gripper on the world,
// two fingers on slides along y, squeezing a free cube between their pads against gravity; the
// cube a second root of the same tree (a floating joint on the world), so that the fingers'
// contacts with it and its weight are one solve:
//   contact_step_grasp/ctga     contact_stepper::step
//   contact_step_grasp/mujoco   mj_step (chains_mujoco.cpp)
// Its figures: the cube's speed (how fast it slips out of the grasp) and the deepest overlap.
#include <array>
#include <memory>

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
}  // namespace

void add_grasp_contact(std::vector<entry>& table) {
    using namespace contact_detail;
    const contact_scenario s = grasp();
    add_contact_step(table, s, std::make_shared<contact_robot<gripper_tree, co::shape<co::sphere<double>, co::box<double>>, 3, 16>>(s, gripper_model(s)));
}
}  // namespace bench::chains
