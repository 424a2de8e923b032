// Robots and free bodies in one world (include/ctga/constrained/robot_world.hpp), against
// references that do not share its route:
//
//   - a gripper squeezing a cube that is a world's body against the same cube as a second root
//     of the gripper's tree (contact_stepper: one tree, no world): the same problem reached two
//     ways, so one step from rest gives the same velocities (to the solver's tolerance); then,
//     stepped on, the world's cube held (its weight carried by the fingers' impulses, to
//     rounding) and, the fingers opened, fallen onto the world's ground where it rests;
//   - an arm swinging through a free ball without gravity: the only other force on the arm is its
//     pivot's, so each step keeps the angular momentum about the pivot's axis (the arm's
//     I θ̇ and the ball's I ω + c × m v, taken about the step's start) to rounding, the ball is
//     knocked away, and the kinetic energy does not grow;
//   - the same tree's cube dropped onto a world's ground and onto the stepper's: the same motion;
//   - refused: a world stepped softly (substeps > 0), a step h ≤ 0; both states kept.
#include <array>
#include <cmath>
#include <memory>

#include <ctga/chains/algorithms.hpp>
#include <ctga/constrained/robot_world.hpp>

#include "support/catch.hpp"

namespace {

namespace ch = ctga::chains;
namespace cn = ctga::constrained;
namespace co = ctga::collision;
using ctga::vec3;
void worst(double& w, double x) { w = x > w ? x : w; }

ctga::motor<double> at(double x, double y, double z) { return ctga::motor<double>(ctga::make_translator(x, y, z)); }
ctga::checked<ctga::mass_properties<double>> block(double m, double I, const vec3<double>& c = {}) {
    return ctga::make_mass_properties(m, c, ctga::mat3<double>{{{I, 0, 0}, {0, I, 0}, {0, 0, I}}});
}

using cube_kind = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, co::box<double>>;
using ball_kind = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::sphere, co::sphere<double>>;
using plane = co::half_space<double>;

// Two fingers on slides along y, 5 cm either side of the cube's centre (0, 0, 0.3); pads 4 × 1 × 6 cm.
using gripper = ch::tree<ch::link<-1, ch::prismatic_y>, ch::link<-1, ch::prismatic_y>>;
using gripper_and_cube = ch::tree<ch::link<-1, ch::prismatic_y>, ch::link<-1, ch::prismatic_y>, ch::link<-1, ch::floating>>;
constexpr double side = 0.06, cube_mass = 0.2, finger_mass = 0.1, squeeze = 5.0;
const double density = cube_mass / (side * side * side), cube_I = cube_mass * 2 * side * side / 12;

template <class Tree>
ch::model<Tree> fingers() {
    ch::model<Tree> m;
    m.gravity = {0, 0, -9.81};
    m.template link<0>() = *ch::make_link<ch::prismatic_y>(at(0, 0.05, 0.3), block(finger_mass, 1e-4));
    m.template link<1>() = *ch::make_link<ch::prismatic_y>(at(0, -0.05, 0.3), block(finger_mass, 1e-4));
    return m;
}
template <class Tree>
cn::robot_geometry<Tree, co::box<double>, double, 3> pads() {
    cn::robot_geometry<Tree, co::box<double>, double, 3> g;
    REQUIRE(g.attach(0, *co::make_box(0.02, 0.005, 0.03)) == ctga::error_code::none);
    REQUIRE(g.attach(1, *co::make_box(0.02, 0.005, 0.03)) == ctga::error_code::none);
    return g;
}
// The cube as the tree's third root, at (0, 0, 0.3) for q = identity; its shape last (each
// contact's A a finger, as in a world).
ch::model<gripper_and_cube> fingers_and_cube() {
    ch::model<gripper_and_cube> out = fingers<gripper_and_cube>();
    out.link<2>() = *ch::make_link<ch::floating>(at(0, 0, 0.3), block(cube_mass, cube_I));
    return out;
}
cn::robot_geometry<gripper_and_cube, co::box<double>, double, 3> pads_and_cube() {
    auto g = pads<gripper_and_cube>();
    REQUIRE(g.attach(2, *co::make_box(side / 2, side / 2, side / 2)) == ctga::error_code::none);
    return g;
}
cn::step_settings<double> tight(double h) {
    cn::step_settings<double> s;
    s.step = h;
    s.solve.rows.solver.tolerance = 1e-13;
    s.solve.rows.solver.max_sweeps = 200;
    return s;
}
using gripper_world = cn::robot_world<gripper, double, 16, plane, cube_kind>;

}  // namespace

TEST_CASE("A gripper holds a world's cube as it holds a cube of its own tree, and lets it fall", "[constrained][robot_world]") {
    const double h = 2e-3, overlap = 1e-4;
    const cn::step_settings<double> settings = tight(h);
    // the world's cube, at rest, the pads overlapping its faces by 0.1 mm, squeezed by 5 N each
    auto scene = std::make_unique<gripper_world>(std::array<std::size_t, 1>{1}, ctga::world_capacity{.statics = 1, .contacts = 64, .pairs = 16});
    REQUIRE(scene->world.add_static(plane{}, at(0, 0, 0), {1.0, 0.0}));
    REQUIRE(scene->world.add_body<0>(*co::make_box(side / 2, side / 2, side / 2), density, at(0, 0, 0.3), {1.0, 0.0}));
    const ch::model<gripper> m = fingers<gripper>();
    const auto geometry = pads<gripper>();
    ch::configuration<gripper> q{-0.015 - overlap, 0.015 + overlap};
    ch::joint_vector<gripper> qd{}, tau{-squeeze, squeeze};
    // the same cube as the tree's third root
    const ch::model<gripper_and_cube> mt = fingers_and_cube();
    const auto geometry_t = pads_and_cube();
    auto tree = std::make_unique<cn::contact_stepper<gripper_and_cube, double, 16>>();
    ch::configuration<gripper_and_cube> qt{q[0], q[1], 1, 0, 0, 0, 0, 0, 0, 0};
    ch::joint_vector<gripper_and_cube> qdt{}, taut{-squeeze, squeeze, 0, 0, 0, 0, 0, 0};
    const std::array<cn::static_shape<plane, double>, 1> ground{};

    // one step from rest: the fingers' and the cube's velocities agree
    const cn::scene_report<double> r = scene->step(m, q, qd, tau, geometry, settings);
    REQUIRE(r.error == ctga::error_code::none);
    const cn::step_report<double> rt = tree->step(mt, qt, qdt, taut, geometry_t, std::span<const cn::static_shape<plane, double>>(ground), settings);
    REQUIRE(rt.error == ctga::error_code::none);
    CHECK(r.solver.converged);
    CHECK(rt.solver.converged);
    CHECK(r.touching == 8);  // four points on each pad
    CHECK(rt.contacts == 8);
    double fingers_gap = 0, cube_gap = 0;
    for (std::size_t k = 0; k < 2; ++k) worst(fingers_gap, std::abs(qd[k] - qdt[k]));
    const ctga::screw<double>& s = scene->world.velocity<0>(0);
    for (std::size_t k = 0; k < 6; ++k) worst(cube_gap, std::abs(s[k] - qdt[2 + k]));  // (the floating joint's: body axes, the world's at rest)
    INFO("one step: fingers' velocity " << fingers_gap << " m/s, the cube's " << cube_gap);
    CHECK(fingers_gap < 1e-10);
    CHECK(cube_gap < 1e-10);
    // the fingers' impulses on the cube (each block's in its axes n, t1, t2: at_b's columns z, x, y)
    const auto on_cube = [&] {
        vec3<double> sum{};
        for (std::size_t i = 0; i < scene->robot.blocks().size(); ++i) {
            if (scene->robot.partner(i) == scene->robot.no_partner) continue;
            const ctga::mat3<double>& E = scene->robot.blocks()[i].at_b.R;
            const std::span<const double> r3 = scene->robot.impulses().subspan(3 * i, 3);
            for (std::size_t a = 0; a < 3; ++a) sum[a] -= r3[0] * E[a][2] + r3[1] * E[a][0] + r3[2] * E[a][1];
        }
        return sum;
    };
    const double weight = cube_mass * 9.81 * h;
    CHECK(std::abs(on_cube()[2] - weight) < 1e-9 * weight);  // (held from the first step: the friction carries it)

    // held: after 0.5 s the cube stays, and the fingers' impulses on it carry its weight
    for (int k = 1; k < 250; ++k) REQUIRE(scene->step(m, q, qd, tau, geometry, settings).error == ctga::error_code::none);
    const vec3<double> held = on_cube();
    INFO("held: vertical impulse " << held[2] << " N s against the weight's " << weight << "; cube at " << ctga::map_of(scene->world.pose<0>(0)).t[2]);
    CHECK(std::abs(held[2] - weight) < 1e-9 * weight);
    CHECK(std::abs(held[1]) < 1e-9);  // the squeezes balance
    double speed = 0;
    for (std::size_t k = 0; k < 6; ++k) worst(speed, std::abs(scene->world.velocity<0>(0)[k]));
    CHECK(speed < 1e-6);

    // opened: the fingers pull back, the cube falls onto the world's ground (0.27 m) and rests there
    tau = {squeeze, -squeeze};
    cn::scene_report<double> last;
    for (int k = 0; k < 500; ++k) {
        last = scene->step(m, q, qd, tau, geometry, settings);
        REQUIRE(last.error == ctga::error_code::none);
    }
    const ctga::motor_map<double> g = ctga::map_of(scene->world.pose<0>(0));
    INFO("fallen: centre at " << g.t[2] << " m, " << last.world.contacts << " ground contacts, " << last.touching << " with the fingers");
    CHECK(last.touching == 0);
    CHECK(last.world.contacts == 4);
    CHECK(std::abs(g.t[2] - side / 2) <= 1.01 * scene->world.settings().slop);  // (the overlap the world leaves)
    speed = 0;
    for (std::size_t k = 0; k < 6; ++k) worst(speed, std::abs(scene->world.velocity<0>(0)[k]));
    CHECK(speed < 1e-6);
}

TEST_CASE("A robot lands on a world's ground as on the stepper's", "[constrained][robot_world]") {
    // the gripper-and-cube tree, fingers wide open, its cube dropped from 2 cm onto the ground:
    // the world's static (no world bodies) and the stepper's static_shape give the same motion
    const cn::step_settings<double> settings = tight(2e-3);
    const ch::model<gripper_and_cube> m = fingers_and_cube();
    const auto geometry = pads_and_cube();
    const ctga::motor<double> start = ctga::rigid_motion(ctga::make_translator(0.01, 0.0, -0.25), ctga::make_rotor(0.2, 0.0, 1.0, 0.0));  // tilted: lands on an edge
    ch::configuration<gripper_and_cube> qa{0.05, -0.05}, qb;
    for (std::size_t k = 0; k < 8; ++k) qa[2 + k] = start[k];
    qb = qa;
    ch::joint_vector<gripper_and_cube> qda{}, qdb{}, tau{};
    auto scene = std::make_unique<cn::robot_world<gripper_and_cube, double, 16, plane, cube_kind>>(
        std::array<std::size_t, 1>{0}, ctga::world_capacity{.statics = 1, .contacts = 16, .pairs = 4});
    REQUIRE(scene->world.add_static(plane{}, at(0, 0, 0), {1.0, 0.0}));
    auto tree = std::make_unique<cn::contact_stepper<gripper_and_cube, double, 16>>();
    const std::array<cn::static_shape<plane, double>, 1> ground{};
    double gap = 0;
    std::size_t landed = 0;
    for (int k = 0; k < 150; ++k) {
        const cn::scene_report<double> a = scene->step(m, qa, qda, tau, geometry, settings);
        const cn::step_report<double> b = tree->step(m, qb, qdb, tau, geometry, std::span<const cn::static_shape<plane, double>>(ground), settings);
        REQUIRE(a.error == ctga::error_code::none);
        REQUIRE(b.error == ctga::error_code::none);
        CHECK(a.robot.contacts == b.contacts);
        landed += a.robot.contacts > 0;
        for (std::size_t i = 0; i < 10; ++i) worst(gap, std::abs(qa[i] - qb[i]));
    }
    INFO("150 steps: configurations apart by " << gap << "; " << landed << " steps on the ground");
    CHECK(landed > 50);
    CHECK(gap < 1e-9);
}

TEST_CASE("An arm knocks a free ball away: each step keeps the angular momentum about its pivot", "[constrained][robot_world]") {
    using arm = ch::tree<ch::link<-1, ch::revolute_z>>;
    constexpr double length = 0.5, arm_mass = 1.0, arm_I = 0.02, ball_r = 0.05, ball_mass = 0.3, tip_r = 0.04;
    ch::model<arm> m;
    m.gravity = {0, 0, 0};
    m.link<0>() = *ch::make_link<ch::revolute_z>(at(0, 0, 0), block(arm_mass, arm_I, {0, -length / 2, 0}));
    cn::robot_geometry<arm, co::sphere<double>, double, 1> geometry;
    REQUIRE(geometry.attach(0, *co::make_sphere(tip_r), ctga::motor_map<double>{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, -length, 0}}) ==
            ctga::error_code::none);
    ctga::world_settings<double> ws;
    ws.gravity = {0, 0, 0};
    cn::robot_world<arm, double, 8, plane, ball_kind> scene({1}, {.statics = 0, .contacts = 16, .pairs = 8}, ws);
    // the ball on the tip's circle a little outside it, 0.4 rad ahead: an oblique hit
    const double ahead = 0.4, out = length + 0.03;
    REQUIRE(scene.world.add_body<0>(*co::make_sphere(ball_r), ball_mass / (4.0 / 3.0 * M_PI * ball_r * ball_r * ball_r),
                                    at(out * std::sin(ahead), -out * std::cos(ahead), 0), {0.5, 0.0}));
    ch::configuration<arm> q{0.0};
    ch::joint_vector<arm> qd{3.0}, tau{};
    const double pivot_I = arm_I + arm_mass * length * length / 4, ball_I = 0.4 * ball_mass * ball_r * ball_r;
    const auto momentum = [&](const vec3<double>& c) {  // about the z axis through the pivot
        const ctga::screw<double>& s = scene.world.velocity<0>(0);
        return pivot_I * qd[0] + ball_I * s[2] + ball_mass * (c[0] * s[4] - c[1] * s[3]);
    };
    const auto energy = [&] {
        const ctga::screw<double>& s = scene.world.velocity<0>(0);
        return 0.5 * pivot_I * qd[0] * qd[0] + 0.5 * ball_I * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) +
               0.5 * ball_mass * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    };
    const cn::step_settings<double> settings = tight(1e-3);
    const double L0 = momentum(ctga::map_of(scene.world.pose<0>(0)).t), E0 = energy();
    double drift = 0, gained = 0;
    std::size_t touching = 0;
    for (int k = 0; k < 400; ++k) {
        const vec3<double> c = ctga::map_of(scene.world.pose<0>(0)).t;
        const double before = momentum(c), e = energy();
        const cn::scene_report<double> r = scene.step(m, q, qd, tau, geometry, settings);
        REQUIRE(r.error == ctga::error_code::none);
        CHECK(r.solver.converged);
        touching += r.touching;
        worst(drift, std::abs(momentum(c) - before) / std::abs(L0));
        worst(gained, (energy() - e) / E0);
    }
    const ctga::screw<double>& s = scene.world.velocity<0>(0);
    const double ball_speed = std::sqrt(s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    INFO("angular momentum kept to " << drift << " a step (relative), energy gained at most " << gained << " of E0; " << touching
                                     << " contact steps; ball at " << ball_speed << " m/s, arm at " << qd[0] << " rad/s");
    CHECK(touching > 0);
    CHECK(ball_speed > 0.5);
    CHECK(qd[0] < 3.0 - 0.1);
    CHECK(drift < 1e-12);
    CHECK(gained < 1e-12);
}

TEST_CASE("A robot's world refuses the soft step and a step h <= 0, keeping both states", "[constrained][robot_world]") {
    ctga::world_settings<double> ws;
    ws.substeps = 4;
    auto scene = std::make_unique<gripper_world>(std::array<std::size_t, 1>{1}, ctga::world_capacity{.statics = 1, .contacts = 64, .pairs = 16}, ws);
    REQUIRE(scene->world.add_body<0>(*co::make_box(side / 2, side / 2, side / 2), density, at(0, 0, 0.3)));
    const ch::model<gripper> m = fingers<gripper>();
    const auto geometry = pads<gripper>();
    ch::configuration<gripper> q{-0.01, 0.01};
    ch::joint_vector<gripper> qd{0.1, -0.1}, tau{};
    CHECK(scene->step(m, q, qd, tau, geometry, tight(1e-3)).error == ctga::error_code::not_supported);
    scene->world.settings().substeps = 0;
    CHECK(scene->step(m, q, qd, tau, geometry, tight(0.0)).error == ctga::error_code::non_finite);
    ch::joint_vector<gripper> bad{std::nan(""), 0};
    CHECK(scene->step(m, q, qd, bad, geometry, tight(1e-3)).error == ctga::error_code::non_finite);
    CHECK(q[0] == -0.01);
    CHECK(qd[0] == 0.1);
    CHECK(ctga::map_of(scene->world.pose<0>(0)).t[2] == 0.3);
    CHECK(scene->world.velocity<0>(0)[5] == 0.0);
}
