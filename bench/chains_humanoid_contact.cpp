// ctga_chains_bench's step of the humanoid lying on the ground (chains_contact_steps.hpp):
//   contact_step_humanoid/ctga     contact_stepper::step
//   contact_step_humanoid/mujoco   mj_step (chains_mujoco.cpp)
#include <array>
#include <memory>
#include <numbers>
#include <utility>

#include "chains_contact_steps.hpp"

namespace bench::chains {
namespace {
// The humanoid (chain_models.hpp, 44 dofs) lying face down, every joint held at 0: spheres of
// 5 cm at its pelvis, knees, ankles, torso, head, elbows and wrists (11 contacts; its own pairs
// tested too), dropped from 2 mm; h, μ as the quadruped's, kp 100 N m/rad, damping 1 N m s/rad.
contact_scenario lying_humanoid() {
    contact_scenario s;
    s.label = "humanoid";
    for (const auto& b : humanoid()) s.bodies.push_back(mujoco_detail::body_of(b));
    s.gravity = {0, 0, -9.81};
    const double r = 0.05;
    s.free_start = {contact_detail::free_qpos({0, 0, r + 0.002}, std::numbers::pi / 2)};  // the body's z (head) to the world's x
    s.target.assign(humanoid_tree::nv - 6, 0.0);
    const std::array<std::pair<std::size_t, double>, 11> at{{{0, 0.0}, {4, 0.0}, {6, -0.05}, {10, 0.0}, {12, -0.05}, {14, 0.2}, {16, 0.1},
                                                             {20, 0.0}, {23, -0.05}, {31, 0.0}, {34, -0.05}}};
    for (const auto& [body, z] : at) s.shapes.push_back({body, {0, 0, z}, r, {}});
    s.h = 0.002, s.mu = 1.0, s.kp = 100.0, s.damping = 1.0;
    s.settle = 1000, s.measure = 500;
    return s;
}

}  // namespace

void add_humanoid_contact(std::vector<entry>& table) {
    using namespace contact_detail;
    const contact_scenario s = lying_humanoid();
    add_contact_step(table, s, std::make_shared<contact_robot<humanoid_tree, co::shape<co::sphere<double>>, 11, 24>>(s, ctga_model<humanoid_tree>(humanoid())));
}
}  // namespace bench::chains
