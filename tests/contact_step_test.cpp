// Robots that touch (include/ctga/constrained/impulse_dynamics.hpp, contact_step.hpp), against
// references that do not share their route:
//
//   - the impact of a double pendulum's tip on the ground (frictionless, Coulomb, sticking)
//     against the closed form of tests/support/double_pendulum_impact.hpp (the 2 × 2 mass matrix
//     from the kinetic energy, the tip's Jacobian by hand, Moreau's law case by case);
//   - a quadruped (tests/data/quadruped.urdf through the converter) with its URDF's collision
//     geometry (make_geometry: a sphere on each foot, a box on its trunk, a mesh's hull on a hip),
//     dropped onto the ground under a PD controller: at rest the feet's normal forces sum to its
//     weight (center_of_mass's mass times g), no foot slips (< 1 µm/s) and none sinks;
//   - that geometry against the URDF: six shapes on the bodies of their links, of the URDF's sizes
//     (the STL box's eight corners for the hull), each where its link's frame is (frame_pose);
//   - a link resting on its joint limit under gravity: the limit's force is the gravity torque
//     m g c cos q (statics), the overlap gone;
//   - refused input: a limit with lower > upper, a stepper past its capacity;
//   - a start in deep penetration: pushed out no faster than the recovery speed, then at rest.
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string_view>
#include <type_traits>
#include <variant>

#include <ctga/chains/algorithms.hpp>
#include <ctga/constrained/contact_step.hpp>
#include <ctga/constrained/impulse_dynamics.hpp>

#include "quadruped.hpp"  // generated: tools/urdf_to_ctga.py tests/data/quadruped.urdf --name quadruped --floating-base
#include "support/catch.hpp"
#include "support/double_pendulum_impact.hpp"

namespace {

namespace ch = ctga::chains;
namespace cn = ctga::constrained;
namespace co = ctga::collision;
void worst(double& w, double x) { w = x > w ? x : w; }

ctga::motor<double> shifted(double x, double y, double z) { return ctga::rigid_motion(ctga::make_translator(x, y, z), ctga::make_rotor(0.0, 0.0, 0.0, 1.0)); }

// A link hanging along −y from its hinge about z: mass m, centre of mass at c, inertia I about z
// there (a thin rod: the same about x, little about y).
ctga::checked<ctga::mass_properties<double>> rod(double m, double c, double I) {
    return ctga::make_mass_properties(m, ctga::vec3<double>{0, -c, 0}, ctga::mat3<double>{{{I, 0, 0}, {0, 1e-3 * I, 0}, {0, 0, I}}});
}

using pendulum = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_z>, ch::fixed_frame<"tip", 1>>;

}  // namespace

TEST_CASE("The impact of a double pendulum's tip on the ground is Moreau's law's closed form", "[constrained][impact]") {
    std::mt19937_64 rng(45);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::array<double, 3> errors{};  // impulse, q̇⁺, frictionless case's tangential impulse
    std::size_t sticking = 0, sliding = 0;
    for (int trial = 0; trial < 24; ++trial) {
        const ctga::test::double_pendulum p{0.5 + U(rng), 0.5 + U(rng), 0.2 + 0.3 * U(rng), 0.01 + 0.05 * U(rng),
                                            0.4 + U(rng), 0.3 + U(rng), 0.2 + 0.2 * U(rng), 0.01 + 0.04 * U(rng)};
        ch::model<pendulum> m;
        m.link<0>() = *ch::make_link<ch::revolute_z>(shifted(0, 0, 0), rod(p.m1, p.c1, p.I1));
        m.link<1>() = *ch::make_link<ch::revolute_z>(shifted(0, -p.l1, 0), rod(p.m2, p.c2, p.I2));
        m.frames[0] = *ch::make_frame(shifted(0, -p.l2, 0));
        const double th1 = 2.0 * U(rng) - 1.0, th2 = (0.3 + 1.5 * U(rng)) * (U(rng) < 0.5 ? -1 : 1);
        std::array<double, 2> thd{4.0 * U(rng) - 2.0, 4.0 * U(rng) - 2.0};
        const auto J = ctga::test::tip_jacobian(p, th1, th2);
        if (J[0][0] * thd[0] + J[0][1] * thd[1] > -0.05) {  // make the tip approach the ground
            thd[0] = -thd[0], thd[1] = -thd[1];
            if (J[0][0] * thd[0] + J[0][1] * thd[1] > -0.05) continue;
        }
        const double mu = std::array<double, 3>{0.0, 0.3, 10.0}[trial % 3];
        const ch::configuration<pendulum> q{th1, th2};
        const ch::joint_vector<pendulum> qd{thd[0], thd[1]};
        cn::constraint_set<pendulum, double, 1> C;
        REQUIRE(C.touch(m, q, ch::frame<"tip">, ctga::vec3<double>{0, 1, 0}, mu) == ctga::error_code::none);
        cn::impulse_settings<double> s;
        s.rows.solver.tolerance = 1e-13;
        const auto got = cn::impact(m, q, qd, C, s);
        REQUIRE(got.error == ctga::error_code::none);
        REQUIRE(got.report.converged);
        const auto want = ctga::test::impact(p, th1, th2, thd, mu);
        (want.sticks ? sticking : sliding) += 1;
        // the contact frame at a +y normal has t1 = +x (constraint_set::contact_frame), t2 = −z: the
        // planar pendulum's tip cannot move along t2, whose row is zero and whose impulse is any that
        // keeps the cone (W is singular there: the solver's answer is one of many, checked by the cone)
        const double scale = std::abs(want.impulse[0]) + 1.0;
        worst(errors[0], std::abs(got.impulse[0] - want.impulse[0]) / scale);
        worst(errors[0], std::abs(got.impulse[1] - want.impulse[1]) / scale);
        CHECK(std::hypot(got.impulse[1], got.impulse[2]) <= mu * got.impulse[0] * (1 + 1e-12));
        worst(errors[1], std::abs(got.qd[0] - want.velocity_after[0]) + std::abs(got.qd[1] - want.velocity_after[1]));
        if (mu == 0.0) worst(errors[2], std::abs(got.impulse[1]));
    }
    std::printf("double pendulum impact: %zu sticking, %zu sliding; impulse %.1e, qd+ %.1e\n", sticking, sliding, errors[0], errors[1]);
    CHECK(sticking >= 4);
    CHECK(sliding >= 8);
    CHECK(errors[0] < 1e-11);
    CHECK(errors[1] < 1e-10);
    CHECK(errors[2] == 0.0);
}

namespace {
using quad = quadruped::tree;
using ground_kinds = co::shape<co::half_space<double>>;

// The quadruped's actuated joints at (hip, thigh, knee) = (0, 0.45, −0.9) on every leg: each foot
// under its hip, 0.36 m below.
ch::configuration<quad> standing(double height) {
    ch::configuration<quad> q{};
    q[0] = 1.0;  // the base's motor: a translation by (0, 0, height)
    const ctga::motor<double> g = shifted(0, 0, height);
    for (std::size_t k = 0; k < 8; ++k) q[k] = g[k];
    for (std::size_t leg = 0; leg < 4; ++leg) q[8 + 3 * leg + 1] = 0.45, q[8 + 3 * leg + 2] = -0.9;
    return q;
}
}  // namespace

TEST_CASE("A quadruped stands on four feet: the forces carry its weight, no foot slips", "[constrained][contact_step]") {
    const auto m = *quadruped::make_model<double>();
    static_assert(quad::nv == 18);
    // the URDF's <collision>: a sphere on each foot, the trunk's box and a hip's hull far above the ground
    const auto geometry = quadruped::make_geometry<double>();
    REQUIRE(geometry);
    const double radius = 0.02;  // the feet's spheres
    const std::array<cn::static_shape<ground_kinds>, 1> ground{};
    cn::contact_stepper<quad, double, 16> stepper;
    stepper.limits = *quadruped::make_limits<double>();
    for (std::size_t j = 0; j < 12; ++j) stepper.limits.damping[6 + j] = 10.0;  // the PD's D, taken implicitly by the step
    cn::step_settings<double> s;
    s.mu = 0.8;
    const ch::configuration<quad> target = standing(0.0);
    ch::configuration<quad> q = standing(0.36 + radius + 0.01);  // dropped from 1 cm
    ch::joint_vector<quad> qd{};
    const double h = s.step;
    const auto weight = ch::center_of_mass(m, ch::forward_kinematics(m, q)).mass * 9.81;
    double deepest = 0, force_error = 0, slip = 0, residual = 0;
    for (int n = 0; n < 3000; ++n) {
        ch::joint_vector<quad> tau{};
        for (std::size_t j = 0; j < 12; ++j) tau[6 + j] = 200.0 * (target[8 + j] - q[8 + j]);
        const auto report = stepper.step(m, q, qd, tau, *geometry, std::span<const cn::static_shape<ground_kinds>>(ground), s);
        REQUIRE(report.error == ctga::error_code::none);
        REQUIRE(report.solver.converged);
        worst(residual, report.solver.residual);
        if (n < 2000) continue;  // settled after 2 s; then over the last second:
        worst(deepest, report.penetration);
        CHECK(report.contacts == 4);
        double sum = 0;
        for (std::size_t i = 0; i < stepper.blocks().size(); ++i)
            if (stepper.blocks()[i].kind == cn::block_kind::contact) sum += stepper.impulses()[3 * i] / h;
        worst(force_error, std::abs(sum - weight) / weight);
        const auto k = ch::forward_kinematics(m, q, qd);
        for (const auto& v : {ch::frame_velocity(m, k, ch::frame<"FL_foot">, ch::reference::local_world_aligned),
                              ch::frame_velocity(m, k, ch::frame<"FR_foot">, ch::reference::local_world_aligned),
                              ch::frame_velocity(m, k, ch::frame<"RL_foot">, ch::reference::local_world_aligned),
                              ch::frame_velocity(m, k, ch::frame<"RR_foot">, ch::reference::local_world_aligned)})
            worst(slip, std::hypot(v[3] - v[1] * radius, v[4] + v[0] * radius));  // at the contact point: v + ω × (0, 0, −r)
    }
    std::printf("quadruped standing: forces vs weight %.1e, slip %.1e m/s, overlap %.1e m, solver residual %.1e\n", force_error, slip, deepest,
                residual);
    CHECK(force_error < 1e-6);
    CHECK(slip < 1e-6);
    CHECK(deepest < 1e-6);
}

TEST_CASE("The URDF's collision geometry: its shapes on their links' bodies, where their frames are", "[constrained][urdf]") {
    const auto m = *quadruped::make_model<double>();
    const auto geometry = quadruped::make_geometry<double>();
    REQUIRE(geometry);
    static_assert(std::is_same_v<quadruped::collision_shape<double>, co::shape<co::sphere<double>, co::box<double>, co::convex_hull<double, 8>>>);
    static_assert(quadruped::collision_count == 6);
    static_assert(quadruped::make_geometry<double>().error == ctga::error_code::none);  // constexpr: the hull too
    const auto shapes = geometry->shapes();
    REQUIRE(shapes.size() == 6);
    CHECK(quadruped::collision_links == std::array<std::string_view, 6>{"trunk", "FL_hip", "FL_foot", "FR_foot", "RL_foot", "RR_foot"});
    // the trunk's box on body 0, the hull on FL_hip's body, each foot's sphere on its calf's (the foot merged into it)
    const std::array<std::string_view, 6> bodies{"trunk", "FL_hip", "FL_calf", "FR_calf", "RL_calf", "RR_calf"};
    for (std::size_t i = 0; i < 6; ++i) CHECK(quadruped::body_names[static_cast<std::size_t>(shapes[i].body)] == bodies[i]);
    CHECK(shapes[0].body == 0);
    CHECK(std::get<co::box<double>>(shapes[0].shape).half == ctga::vec3<double>{0.25, 0.1, 0.05});  // <box size="0.5 0.2 0.1">
    // the hull of meshes/hip_cover.stl: the box's 8 corners, its 6 faces
    const auto& hull = std::get<co::convex_hull<double, 8>>(shapes[1].shape);
    CHECK(hull.vertex_count == 8);
    CHECK(hull.face_count == 6);
    for (std::size_t v = 0; v < hull.vertex_count; ++v) {
        CHECK(std::abs(hull.vertex[v][0]) == 0.03125);
        CHECK((hull.vertex[v][1] == 0.0 || hull.vertex[v][1] == 0.046875));
        CHECK(std::abs(hull.vertex[v][2]) == 0.015625);
    }
    for (std::size_t i = 2; i < 6; ++i) {
        CHECK(std::get<co::sphere<double>>(shapes[i].shape).radius == 0.02);
        CHECK(shapes[i].at.t == ctga::vec3<double>{0, 0, -0.2});  // the foot joint's <origin> in the calf
    }
    // in any configuration each shape is where its link's frame is: its body's pose composed with its placement
    const auto k = ch::forward_kinematics(m, standing(0.3));
    const std::array frames{ch::frame_pose(m, k, ch::frame<"trunk">),   ch::frame_pose(m, k, ch::frame<"FL_hip">),
                            ch::frame_pose(m, k, ch::frame<"FL_foot">), ch::frame_pose(m, k, ch::frame<"FR_foot">),
                            ch::frame_pose(m, k, ch::frame<"RL_foot">), ch::frame_pose(m, k, ch::frame<"RR_foot">)};
    double off = 0;
    for (std::size_t i = 0; i < 6; ++i) {
        const ctga::motor_map<double> X = ctga::compose(k.pose[static_cast<std::size_t>(shapes[i].body)], shapes[i].at);
        for (std::size_t r = 0; r < 3; ++r) {
            worst(off, std::abs(X.t[r] - frames[i].t[r]));
            for (std::size_t c = 0; c < 3; ++c) worst(off, std::abs(X.R[r][c] - frames[i].R[r][c]));
        }
    }
    std::printf("URDF collision geometry: 6 shapes, placements vs the links' frames %.1e\n", off);
    CHECK(off < 1e-15);
    // grown for a shape the user adds (room for two more, and a kind the URDF has not: a cylinder)
    using grown_shape = co::shape<co::sphere<double>, co::box<double>, co::convex_hull<double, 8>, co::cylinder<double>>;
    auto grown = cn::robot_geometry<quadruped::tree, grown_shape, double, 8>::from(*geometry);
    REQUIRE(grown);
    REQUIRE(grown->shapes().size() == 6);
    for (std::size_t i = 0; i < 6; ++i) {
        CHECK(grown->shapes()[i].body == shapes[i].body);
        CHECK(grown->shapes()[i].at.t == shapes[i].at.t);
        CHECK(grown->shapes()[i].shape.index() == shapes[i].shape.index());
    }
    CHECK(std::get<co::box<double>>(grown->shapes()[0].shape).half == ctga::vec3<double>{0.25, 0.1, 0.05});
    for (int a = 0; a < static_cast<int>(quadruped::tree::size); ++a)
        for (int b = 0; b < static_cast<int>(quadruped::tree::size); ++b) CHECK(grown->collides(a, b) == geometry->collides(a, b));
    auto with = *grown;
    CHECK(with.attach(m, ch::frame<"trunk">, *co::make_cylinder(0.05, 0.02)) == ctga::error_code::none);
    CHECK(with.shapes().size() == 7);
    CHECK(std::holds_alternative<co::cylinder<double>>(with.shapes()[6].shape));
    CHECK(cn::robot_geometry<quadruped::tree, grown_shape, double, 5>::from(*geometry).error == ctga::error_code::capacity_exceeded);
}

namespace {
// A hinge about y holding a rod along +x (mass m, centre at c): gravity −z turns it down (q < 0
// lowers it? q about y turns +x towards −z for q > 0).
using arm = ch::tree<ch::link<-1, ch::revolute_y>>;
}  // namespace

TEST_CASE("A joint limit holds a link under gravity", "[constrained][contact_step]") {
    const double mass = 2.0, c = 0.4, upper = 0.3;
    ch::model<arm> m;
    m.link<0>() = *ch::make_link<ch::revolute_y>(shifted(0, 0, 0), ctga::make_mass_properties(mass, ctga::vec3<double>{c, 0, 0},
                                                                                                  ctga::mat3<double>{{{1e-4, 0, 0}, {0, 0.02, 0}, {0, 0, 0.02}}}));
    cn::robot_geometry<arm, co::shape<co::sphere<double>>, double, 1> none;
    const std::array<cn::static_shape<co::shape<co::half_space<double>>>, 0> nothing{};
    cn::contact_stepper<arm, double, 2> stepper;
    stepper.limits.lower[0] = -1.0;
    stepper.limits.upper[0] = upper;
    stepper.limits.damping[0] = 0.05;
    cn::step_settings<double> s;
    ch::configuration<arm> q{0.0};
    ch::joint_vector<arm> qd{0.0};
    // gravity turns +x towards −z: about +y that is q increasing (R_y(q) x = (cos q, 0, −sin q))
    for (int n = 0; n < 2000; ++n) {
        const auto report = stepper.step(m, q, qd, ch::joint_vector<arm>{}, none, std::span<const cn::static_shape<co::shape<co::half_space<double>>>>(nothing), s);
        REQUIRE(report.error == ctga::error_code::none);
    }
    REQUIRE(stepper.blocks().size() == 1);
    REQUIRE(stepper.blocks()[0].kind == cn::block_kind::upper_limit);
    const double torque = stepper.impulses()[0] / s.step, statics = mass * 9.81 * c * std::cos(upper);
    std::printf("joint limit under load: overlap %.1e rad, force %.12f vs m g c cos q %.12f\n", q[0] - upper, torque, statics);
    CHECK(std::abs(q[0] - upper) < 1e-9);
    CHECK(std::abs(qd[0]) < 1e-9);
    CHECK(std::abs(torque - statics) < 1e-9 * statics);
}

TEST_CASE("Limits and steps refuse bad input", "[constrained][contact_step]") {
    cn::constraint_set<arm, double, 2> C;
    CHECK(C.limit(0, 1.0, -1.0) == ctga::error_code::limits_reversed);
    CHECK(C.limit(0, std::nan(""), 1.0) == ctga::error_code::non_finite);
    CHECK(C.limit(-1, -1.0, 1.0) == ctga::error_code::bad_index);
    CHECK(C.joint_friction(0, -0.1) == ctga::error_code::negative_limit);
    CHECK(C.limit(0, -1.0, 1.0) == ctga::error_code::none);
    CHECK(C.size() == 2);
    CHECK(C.limit(0, -1.0, 1.0) == ctga::error_code::capacity_exceeded);
    // a stepper of one block, with two limits within reach: refused, the state left as it was
    ch::model<arm> m;
    m.link<0>() = *ch::make_link<ch::revolute_y>(shifted(0, 0, 0), ctga::make_mass_properties(1.0, ctga::vec3<double>{0.1, 0, 0},
                                                                                                  ctga::mat3<double>{{{1e-3, 0, 0}, {0, 1e-2, 0}, {0, 0, 1e-2}}}));
    cn::contact_stepper<arm, double, 1> stepper;
    stepper.limits.lower[0] = -0.01;
    stepper.limits.upper[0] = 0.01;
    cn::robot_geometry<arm, co::shape<co::sphere<double>>, double, 1> none;
    const std::array<cn::static_shape<co::shape<co::half_space<double>>>, 0> nothing{};
    ch::configuration<arm> q{0.0};
    ch::joint_vector<arm> qd{0.5};
    const auto report = stepper.step(m, q, qd, ch::joint_vector<arm>{}, none, std::span<const cn::static_shape<co::shape<co::half_space<double>>>>(nothing), {});
    CHECK(report.error == ctga::error_code::capacity_exceeded);
    CHECK(q[0] == 0.0);
    CHECK(qd[0] == 0.5);
    cn::contact_stepper<arm, double, 2> roomy;
    roomy.limits.lower[0] = 0.2;  // lower > upper
    roomy.limits.upper[0] = -0.2;
    CHECK(roomy.step(m, q, qd, ch::joint_vector<arm>{}, none, std::span<const cn::static_shape<co::shape<co::half_space<double>>>>(nothing), {}).error ==
          ctga::error_code::limits_reversed);
    roomy.limits = ch::unlimited<arm, double>();
    qd[0] = std::nan("");
    CHECK(roomy.step(m, q, qd, ch::joint_vector<arm>{}, none, std::span<const cn::static_shape<co::shape<co::half_space<double>>>>(nothing), {}).error ==
          ctga::error_code::non_finite);
}

namespace {
using ball = ch::tree<ch::link<-1, ch::floating>>;
}  // namespace

TEST_CASE("A start in deep penetration is pushed out no faster than the recovery speed, and comes to rest", "[constrained][contact_step]") {
    // a ball of 10 cm radius, its centre 5 cm under the ground's surface (half of it inside)
    ch::model<ball> m;
    m.link<0>() = *ch::make_link<ch::floating>(shifted(0, 0, 0), ctga::make_mass_properties(1.0, ctga::vec3<double>{}, ctga::mat3<double>{{{4e-3, 0, 0}, {0, 4e-3, 0}, {0, 0, 4e-3}}}));
    cn::robot_geometry<ball, co::shape<co::sphere<double>>, double, 1> shape;
    REQUIRE(shape.attach(0, co::sphere<double>{0.1}) == ctga::error_code::none);
    const std::array<cn::static_shape<co::shape<co::half_space<double>>>, 1> ground{};
    cn::contact_stepper<ball, double, 4> stepper;
    cn::step_settings<double> s;  // h 1 ms, β 0.2, v_max 1 m/s
    const ctga::motor<double> g = shifted(0, 0, 0.05);
    ch::configuration<ball> q{};
    for (std::size_t k = 0; k < 8; ++k) q[k] = g[k];
    ch::joint_vector<ball> qd{};
    double fastest = 0, first_depth = 0, highest = 0;
    int out_after = -1;
    for (int n = 0; n < 2000; ++n) {
        const auto report = stepper.step(m, q, qd, ch::joint_vector<ball>{}, shape, std::span<const cn::static_shape<co::shape<co::half_space<double>>>>(ground), s);
        REQUIRE(report.error == ctga::error_code::none);
        if (n == 0) first_depth = report.penetration;
        const double z = ctga::map_of(ctga::motor<double>{q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]}).t[2];
        fastest = std::max(fastest, std::abs(qd[5]));  // the body's velocity along its own z (it does not turn)
        highest = std::max(highest, z);
        if (out_after < 0 && z > 0.1 - 1e-6) out_after = n;
    }
    const double z = ctga::map_of(ctga::motor<double>{q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]}).t[2];
    std::printf("deep start: depth %.3f m, out after %d steps, fastest %.3f m/s, highest centre %.4f m, at rest %.1e m/s, centre %.9f m\n",
                first_depth, out_after, fastest, highest, std::abs(qd[5]), z);
    CHECK(first_depth == Approx(0.05).epsilon(1e-12));
    CHECK(fastest <= s.solve.recovery_speed + 9.81 * s.step + 1e-9);  // pushed out at v_max (plus a step of gravity)
    CHECK(out_after > 0);
    CHECK(out_after < 300);
    // the push's speed is kept (the velocity level's recovery is not split from the velocity): the
    // ball leaves the ground at most v_max fast and rises at most v_max² / 2g before it settles
    CHECK(highest <= 0.1 + s.solve.recovery_speed * s.solve.recovery_speed / (2 * 9.81) + 1e-3);
    CHECK(std::abs(qd[5]) < 1e-9);  // at rest on the ground in the end
    CHECK(std::abs(z - 0.1) < 1e-6);
}
