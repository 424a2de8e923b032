// TALOS (PAL Robotics' humanoid, 90 kg, 36 dofs here) from its real URDF
// (examples/data/talos_reduced.urdf, floating base, the gripper joints locked by the converter)
// stands with its legs straight, leaning forwards 0.15 rad on its ankles, its joints unpowered
// (τ = 0; the URDF's damping and dry friction on the torso, head and arms, and 5 N m s/rad of
// damping on the legs), and falls: it buckles, lands on its knees, falls forwards onto its pelvis,
// head and hands, and comes to rest face down. Its URDF's collision meshes are not shipped (the
// header is converted with --meshes omit), so the example attaches shapes of its own through
// robot_geometry: a box for each foot and balls on the knees, pelvis, chest, head, shoulders,
// elbows, wrists and hands, of about TALOS's sizes. Steps of 1 ms (constrained/contact_step.hpp)
// over 2.5 s.
//
// Every 0.1 s it prints the kinetic energy, the contacts and limits in the solve, the deepest
// overlap, the solver's residual, the pelvis' height and the lowest joint's. It checks, and returns
// 1 if one fails: no step fails; at the end the robot lies on the ground at rest (kinetic energy
// below 1e-6 J) without overlapping it by more than 1 mm; at no time does a joint go below the
// ground (the shapes carry every limb).
#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <string_view>

#include <ctga/chains/energy.hpp>
#include <ctga/chains/floating_base.hpp>
#include <ctga/chains/forward_kinematics.hpp>
#include <ctga/chains/frames.hpp>
#include <ctga/constrained/contact_step.hpp>

#include "talos.hpp"  // generated: namespace talos { using tree = …; make_model<T>(); make_limits<T>(); }

namespace ch = ctga::chains;
namespace cn = ctga::constrained;
namespace co = ctga::collision;
using robot = talos::tree;
using robot_shape = co::shape<co::sphere<double>, co::box<double>>;
using ground = co::shape<co::half_space<double>>;

// The body of a URDF link, found while compiling: a misspelt link does not compile.
consteval std::size_t body_of(std::string_view link) {
    const auto k = robot::find_frame(link);
    if (!k) throw "talos has no link of this name";
    return static_cast<std::size_t>(robot::frame_body[*k]);
}

// The placement of a shape at (x, y, z) in its frame's axes.
ctga::motor_map<double> at(double x, double y, double z) { return {{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {x, y, z}}; }

int main() {
    const auto model = talos::make_model<double>();
    const auto limits = talos::make_limits<double>();
    if (!model || !limits) return std::printf("talos: %s\n", ctga::describe(!model ? model.error : limits.error)), 1;
    const ch::model<robot>& m = *model;

    // A foot: a box 21 × 14 cm from the sole (its frame's origin, z up) to 8 cm above it (the ankle
    // is 10.7 cm up). The knees', elbows' and wrists' balls sit on their joints' axes (a link's frame
    // is on its joint); the pelvis' 0.13 m below the base's origin (the hips are 0.271 m below), the
    // chest's below the neck (head_1, 0.316 m above torso_2), the head's above it, a shoulder's on
    // the arm_2 axis (arm_2's <origin> in arm_1's frame), a hand's 3 cm below the gripper's base.
    cn::robot_geometry<robot, robot_shape, double, 15> geometry;
    const co::box<double> foot{{0.105, 0.069, 0.04}};
    const co::sphere<double> knee{0.08}, shoulder{0.08}, elbow{0.06}, wrist{0.05}, hand{0.07};
    for (const ctga::error_code e : {
             geometry.attach(m, ch::frame<"left_sole_link">, foot, at(0, 0, 0.04)),
             geometry.attach(m, ch::frame<"right_sole_link">, foot, at(0, 0, 0.04)),
             geometry.attach(m, ch::frame<"base_link">, co::sphere<double>{0.16}, at(0, 0, -0.13)),
             geometry.attach(m, ch::frame<"torso_2_link">, co::sphere<double>{0.17}, at(0, 0, 0.15)),
             geometry.attach(m, ch::frame<"head_2_link">, co::sphere<double>{0.12}, at(0.02, 0, 0.12)),
             geometry.attach(m, ch::frame<"leg_left_4_link">, knee),
             geometry.attach(m, ch::frame<"leg_right_4_link">, knee),
             geometry.attach(m, ch::frame<"arm_left_1_link">, shoulder, at(0.00493, 0.1365, 0.04673)),
             geometry.attach(m, ch::frame<"arm_right_1_link">, shoulder, at(0.00493, -0.1365, 0.04673)),
             geometry.attach(m, ch::frame<"arm_left_4_link">, elbow),
             geometry.attach(m, ch::frame<"arm_right_4_link">, elbow),
             geometry.attach(m, ch::frame<"arm_left_7_link">, wrist),
             geometry.attach(m, ch::frame<"arm_right_7_link">, wrist),
             geometry.attach(m, ch::frame<"gripper_left_base_link">, hand, at(0, 0, -0.03)),
             geometry.attach(m, ch::frame<"gripper_right_base_link">, hand, at(0, 0, -0.03)),
             // the chest's ball overlaps the pelvis' when the torso bends forwards and the head's by design: not tested
             geometry.exclude(geometry.shapes()[2].body, geometry.shapes()[3].body),
             geometry.exclude(geometry.shapes()[3].body, geometry.shapes()[4].body),
         })
        if (e != ctga::error_code::none) return std::printf("talos: geometry: %s\n", ctga::describe(e)), 1;
    const std::array<cn::static_shape<ground>, 1> world{};  // the ground: z ≤ 0

    cn::contact_stepper<robot, double, 64> stepper;
    stepper.limits = *limits;  // the URDF's <limit>s, and <dynamics> on the torso, head and arms: damping 1 N m s/rad, friction 1 N m
    // the legs, the tree's last twelve dofs: the URDF gives them no damping
    for (std::size_t k = robot::v_offset[body_of("leg_left_1_link")]; k < robot::nv; ++k) stepper.limits.damping[k] = 5.0;
    cn::step_settings<double> settings;  // h = 1 ms
    settings.mu = 0.8;                   // every contact's Coulomb coefficient (the URDF gives none)
    // The solver's tolerance is in N s: TALOS's weight is 0.89 N s a step, and 1e-8 N s holds the
    // impulses to 1e-8 of it (the default 1e-9 N s holds Solo 12's 0.025 N s to 4e-8).
    settings.solve.rows.solver.tolerance = 1e-8;

    // standing: legs straight, the base turned by `lean` about y and the ankles back by as much, so
    // that the soles are level; then the base moved so that they are 1 mm above the ground
    const double lean = 0.15;
    ch::configuration<robot> q{};
    const std::array<double, 4> turn{0, std::sin(lean / 2), 0, std::cos(lean / 2)};  // (x, y, z, w)
    q[robot::q_offset[body_of("leg_left_5_link")]] = q[robot::q_offset[body_of("leg_right_5_link")]] = -lean;  // the ankles' pitch
    const auto turned = ch::floating_base_configuration(ch::base_pose<double>{{0, 0, 0}, turn});
    for (std::size_t k = 0; k < 8; ++k) q[k] = (*turned)[k];
    const ctga::vec3<double> sole = ch::frame_pose(m, ch::forward_kinematics(m, q), ch::frame<"left_sole_link">).t;
    const auto placed = ch::floating_base_configuration(ch::base_pose<double>{{-sole[0], 0, 1e-3 - sole[2]}, turn});
    for (std::size_t k = 0; k < 8; ++k) q[k] = (*placed)[k];
    ch::joint_vector<robot> qd{};
    const ch::joint_vector<robot> tau{};

    std::printf("talos: %zu dofs, %zu bodies, %zu shapes; standing, leaning %.2f rad, unpowered\n", robot::nv, robot::size, geometry.shapes().size(), lean);
    std::printf("   t    kinetic (J)  contacts  limits  overlap (m)  residual (N s)  pelvis z  lowest joint (m)\n");
    double lowest_ever = 1, deepest = 0, worst_residual = 0, kinetic = 0, overlap = 0, pelvis = 0;
    int unconverged = 0;
    const int steps = 2500;
    for (int n = 0; n <= steps; ++n) {
        const auto report = stepper.step(m, q, qd, tau, geometry, std::span<const cn::static_shape<ground>>(world), settings);
        if (report.error != ctga::error_code::none) return std::printf("step %d: %s\n", n, ctga::describe(report.error)), 1;
        unconverged += !report.solver.converged;
        worst_residual = std::fmax(worst_residual, report.solver.residual);
        deepest = std::fmax(deepest, report.penetration);
        // every body's frame is on its joint's axis: the lowest joint
        const auto k = ch::forward_kinematics(m, q);
        double lowest = k.pose[0].t[2];
        for (std::size_t b = 1; b < robot::size; ++b) lowest = std::fmin(lowest, k.pose[b].t[2]);
        lowest_ever = std::fmin(lowest_ever, lowest);
        kinetic = ch::tree_kinetic_energy(m, q, qd), overlap = report.penetration, pelvis = k.pose[0].t[2];
        if (n % 100 == 0)
            std::printf("  %.1f  %10.3e    %3zu      %3zu      %.1e      %.1e        %.3f       %.3f\n", 1e-3 * n, kinetic, report.contacts,
                        report.limits, report.penetration, report.solver.residual, pelvis, lowest);
    }
    std::printf("at %.1f s: kinetic energy %.1e J, overlap %.1e m, pelvis at %.3f m; lowest joint over the fall %.3f m, deepest overlap %.1e m\n",
                1e-3 * steps, kinetic, overlap, pelvis, lowest_ever, deepest);
    std::printf("solver: %d steps stopped above the tolerance, largest residual %.1e N s\n", unconverged, worst_residual);

    // The checks. At rest the kinetic energy is rounding (1e-17 J here); 1e-6 J is the 90 kg moving
    // as one at 0.15 mm/s. The ground's β pushes an overlap out at 20 % a step: at rest none is left.
    bool ok = true;
    const auto check = [&](bool passed, const char* what) {
        if (!passed) std::printf("FAILED: %s\n", what);
        ok = ok && passed;
    };
    check(pelvis < 0.4, "it fell: the pelvis lies lower than 0.4 m");
    check(kinetic < 1e-6, "it came to rest: kinetic energy below 1e-6 J");
    check(overlap < 1e-3, "at rest it overlaps the ground by less than 1 mm");
    check(lowest_ever > 0, "no joint went below the ground");
    return ok ? 0 : 1;
}
