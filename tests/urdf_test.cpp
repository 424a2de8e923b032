// Robots described in URDF (tests/data/arm7.urdf, tests/data/quadruped.urdf), converted to C++
// headers by tools/urdf_to_ctga.py at build time (tests/CMakeLists.txt), against an independent
// description: the same robots written here by hand from the URDF files' numbers (roll-pitch-yaw
// and the inertial frames' rotations done here in C++, not by the script) and run through the
// Featherstone reference (support/featherstone.hpp). FK, RNEA and CRBA agree to 1e-12 at random
// states; the generated tree types, names and float models are checked too. One unit: most of its
// compile time is the headers (ctga.hpp, Eigen, Catch2), so two parts would cost more in all.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include <ctga/chains/algorithms.hpp>

#include "arm7.hpp"       // generated: tools/urdf_to_ctga.py tests/data/arm7.urdf --name arm7
#include "quadruped.hpp"  // generated: ... tests/data/quadruped.urdf --name quadruped --floating-base
#include "support/catch.hpp"
#include "support/featherstone.hpp"
#include "support/relative_error.hpp"
#include "support/random_tree.hpp"

namespace {

namespace ch = ctga::chains;
namespace fs = ctga::test::featherstone;

// ---- the robots as written in their URDF files ------------------------------------------------

using v3 = std::array<double, 3>;

// A URDF link with the joint above it, the numbers as the URDF file writes them.
struct urdf_body {
    int parent;             // body index, −1 the world
    fs::joint_kind kind;
    v3 axis;                // <axis xyz> (not normalised), joint frame
    v3 xyz, rpy;            // the joint's <origin>
    double mass;
    v3 com, inertial_rpy;   // the <inertial>'s <origin>
    double ixx, ixy, ixz, iyy, iyz, izz;  // about the com, in the inertial frame's axes
};

constexpr auto R = fs::joint_kind::revolute;
constexpr auto F = fs::joint_kind::fixed;
constexpr auto FLOAT = fs::joint_kind::floating;
constexpr v3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1}, O{0, 0, 0};

// tests/data/arm7.urdf: base_link (no inertial) is the world
const std::vector<urdf_body> arm7_urdf{
    // parent, kind, axis, joint xyz, joint rpy, mass, com, inertial rpy, ixx, ixy, ixz, iyy, iyz, izz
    {-1, R, Z, {0, 0, 0.1}, O, 4.0, {0.01, -0.005, 0.15}, O, 0.0330, 0.0002, -0.0001, 0.0320, 0.00015, 0.0050},
    {0, R, Y, {0, 0, 0.3}, O, 3.5, {-0.008, 0.004, 0.14}, O, 0.0290, -0.00015, 0.0001, 0.0285, -0.0001, 0.0044},
    {1, R, Z, {0, 0, 0.3}, O, 3.0, {0.006, 0.007, 0.16}, {0.1, 0.2, 0.3}, 0.0245, 0.0001, 0.00008, 0.0240, -0.00012, 0.0038},
    {2, R, Y, {0, 0, 0.3}, {1.5707963267948966, 0, 0}, 2.5, {0.005, -0.01, 0.13}, O, 0.0205, 0.00012, -0.0001, 0.0200, 0.0001, 0.0031},
    {3, R, Z, {0, 0, 0.3}, O, 1.5, {-0.004, 0.006, 0.15}, O, 0.0123, -0.00008, 0.00006, 0.0120, 0.00005, 0.0019},
    {4, R, Y, {0, 0, 0.3}, O, 1.0, {0.003, -0.002, 0.12}, O, 0.0082, 0.00004, -0.00003, 0.0080, -0.00004, 0.0012},
    {5, R, {0, 0.6, 0.8}, {0, 0, 0.3}, O, 0.5, {0.002, 0.003, 0.05}, O, 0.0012, 0.00001, 0.00002, 0.0011, -0.00001, 0.0006},
    {6, F, Z, {0, 0, 0.1}, {0.1, -0.2, 0.3}, 0.2, {0, 0, 0.03}, O, 0.00015, 0.000005, 0, 0.00014, 0, 0.00008},
};

// tests/data/quadruped.urdf with --floating-base: the trunk is body 0 on a floating joint; each
// leg hip (about x), thigh (y), calf (y), foot (fixed); legs FL (+x, +y), FR (+x, −y), RL, RR.
const std::vector<urdf_body> quadruped_urdf{
    {-1, FLOAT, Z, O, O, 10.0, {0.012, 0.002, -0.004}, O, 0.07, 0.0002, -0.0015, 0.26, 0.0001, 0.28},
    // FL
    {0, R, X, {0.19, 0.05, 0}, O, 0.7, {-0.005, 0.01, 0}, O, 0.00048, 1e-05, 0, 0.00072, 0, 0.0006},
    {1, R, Y, {0, 0.08, 0}, O, 1.0, {-0.003, -0.02, -0.03}, {0, 0.05, 0}, 0.0055, 0, 0.0002, 0.0056, -1e-05, 0.0009},
    {2, R, Y, {0, 0, -0.2}, O, 0.2, {0.004, 0, -0.1}, O, 0.0011, 0, -3e-05, 0.0011, 0, 4e-05},
    {3, F, Z, {0, 0, -0.2}, O, 0.06, O, O, 9.6e-06, 0, 0, 9.6e-06, 0, 9.6e-06},
    // FR
    {0, R, X, {0.19, -0.05, 0}, O, 0.7, {-0.005, -0.01, 0}, O, 0.00048, -1e-05, 0, 0.00072, 0, 0.0006},
    {5, R, Y, {0, -0.08, 0}, O, 1.0, {-0.003, 0.02, -0.03}, {0, 0.05, 0}, 0.0055, 0, 0.0002, 0.0056, 1e-05, 0.0009},
    {6, R, Y, {0, 0, -0.2}, O, 0.2, {0.004, 0, -0.1}, O, 0.0011, 0, -3e-05, 0.0011, 0, 4e-05},
    {7, F, Z, {0, 0, -0.2}, O, 0.06, O, O, 9.6e-06, 0, 0, 9.6e-06, 0, 9.6e-06},
    // RL
    {0, R, X, {-0.19, 0.05, 0}, O, 0.7, {0.005, 0.01, 0}, O, 0.00048, -1e-05, 0, 0.00072, 0, 0.0006},
    {9, R, Y, {0, 0.08, 0}, O, 1.0, {-0.003, -0.02, -0.03}, {0, 0.05, 0}, 0.0055, 0, 0.0002, 0.0056, -1e-05, 0.0009},
    {10, R, Y, {0, 0, -0.2}, O, 0.2, {0.004, 0, -0.1}, O, 0.0011, 0, -3e-05, 0.0011, 0, 4e-05},
    {11, F, Z, {0, 0, -0.2}, O, 0.06, O, O, 9.6e-06, 0, 0, 9.6e-06, 0, 9.6e-06},
    // RR
    {0, R, X, {-0.19, -0.05, 0}, O, 0.7, {0.005, -0.01, 0}, O, 0.00048, 1e-05, 0, 0.00072, 0, 0.0006},
    {13, R, Y, {0, -0.08, 0}, O, 1.0, {-0.003, 0.02, -0.03}, {0, 0.05, 0}, 0.0055, 0, 0.0002, 0.0056, 1e-05, 0.0009},
    {14, R, Y, {0, 0, -0.2}, O, 0.2, {0.004, 0, -0.1}, O, 0.0011, 0, -3e-05, 0.0011, 0, 4e-05},
    {15, F, Z, {0, 0, -0.2}, O, 0.06, O, O, 9.6e-06, 0, 0, 9.6e-06, 0, 9.6e-06},
};

// URDF's roll, pitch, yaw about the fixed axes: R = Rz(yaw) Ry(pitch) Rx(roll), each the
// right-handed elementary rotation written out.
fs::mat3 rpy_rotation(const v3& rpy) {
    const double cr = std::cos(rpy[0]), sr = std::sin(rpy[0]), cp = std::cos(rpy[1]), sp = std::sin(rpy[1]),
                 cy = std::cos(rpy[2]), sy = std::sin(rpy[2]);
    fs::mat3 Rx, Ry, Rz;
    Rx << 1, 0, 0, 0, cr, -sr, 0, sr, cr;
    Ry << cp, 0, sp, 0, 1, 0, -sp, 0, cp;
    Rz << cy, -sy, 0, sy, cy, 0, 0, 0, 1;
    return Rz * Ry * Rx;
}

fs::vec3 eigen(const v3& a) { return fs::vec3(a[0], a[1], a[2]); }

// The reference model: joint frame = the joint's <origin>, body inertia about the com in the
// link's axes = R_inertial I R_inertialᵀ.
fs::model reference_of(const std::vector<urdf_body>& urdf) {
    fs::model m;
    for (const urdf_body& u : urdf) {
        fs::body b;
        b.parent = u.parent;
        b.kind = u.kind;
        b.axis = eigen(u.axis).normalized();
        b.rotation = rpy_rotation(u.rpy);
        b.translation = eigen(u.xyz);
        b.mass = u.mass;
        b.com = eigen(u.com);
        fs::mat3 I;
        I << u.ixx, u.ixy, u.ixz, u.ixy, u.iyy, u.iyz, u.ixz, u.iyz, u.izz;
        const fs::mat3 Ri = rpy_rotation(u.inertial_rpy);
        b.inertia_c = Ri * I * Ri.transpose();
        m.bodies.push_back(b);
    }
    return m;
}

// ---- comparisons -------------------------------------------------------------------------------

using ctga::test::rel_error;

double max_abs_diff(const ctga::motor_map<double>& G, const fs::mat3& R, const fs::vec3& t) {
    double e = 0;
    for (int r = 0; r < 3; ++r) {
        e = std::max(e, std::abs(G.t[static_cast<std::size_t>(r)] - t[r]));
        for (int c = 0; c < 3; ++c)
            e = std::max(e, std::abs(G.R[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] - R(r, c)));
    }
    return e;
}

// The generated model's parameters against the reference's, body by body: the placement (R, t)
// and the ten inertia parameters (m, h = m c, I_o: RBDA's spatial inertia about the body origin).
template <class Tree>
void compare_parameters(const ch::model<Tree>& m, const fs::model& ref) {
    REQUIRE(ref.size() == static_cast<int>(Tree::size));
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            INFO("body " << I);
            const fs::body& b = ref[static_cast<int>(I)];
            const auto& L = m.template link<I>();
            CHECK(max_abs_diff(L.placement, b.rotation, b.translation) < 1e-14);
            const fs::mat6 N = fs::spatial_inertia(b);
            const ctga::body_inertia<double>& n = L.inertia;
            CHECK(std::abs(n.mass() - N(3, 3)) < 1e-15);
            const ctga::vec3<double> h = n.first_moment();
            const ctga::mat3<double> Io = n.inertia_o();
            const fs::vec3 h_ref = b.mass * b.com;
            for (int r = 0; r < 3; ++r) {
                CHECK(std::abs(h[static_cast<std::size_t>(r)] - h_ref[r]) < 1e-15);
                for (int c = 0; c < 3; ++c)
                    CHECK(std::abs(Io[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] - N(r, c)) < 1e-15);
            }
            if constexpr (std::is_same_v<typename Tree::template joint_at<I>, ch::revolute_about>) {
                for (int r = 0; r < 3; ++r) CHECK(std::abs(L.joint.u[static_cast<std::size_t>(r)] - b.axis[r]) < 1e-15);
            }
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    CHECK(m.gravity[0] == ref.gravity[0]);
    CHECK(m.gravity[1] == ref.gravity[1]);
    CHECK(m.gravity[2] == ref.gravity[2]);
}

// FK (poses, velocities, accelerations), RNEA and CRBA at random states, the same numbers given
// to both; a floating joint's q is ctga's motor (8 numbers) and the reference's (x, y, z, qw, qx,
// qy, qz).
template <class Tree>
void compare_dynamics(const ch::model<Tree>& m, const fs::model& ref, std::uint64_t seed, int draws) {
    std::mt19937_64 rng(seed);
    for (int n = 0; n < draws; ++n) {
        INFO("draw " << n);
        ch::configuration<Tree> q{};
        ch::joint_vector<Tree> qd{}, qdd{};
        Eigen::VectorXd q_ref(ref.nq()), qd_ref(ref.nv()), qdd_ref(ref.nv());
        for (int i = 0; i < ref.size(); ++i) {
            const std::size_t qo = Tree::q_offset[static_cast<std::size_t>(i)];
            const int qr = ref.q_index(i);
            if (ref[i].kind == fs::joint_kind::floating) {
                const Eigen::Quaterniond quat(fs::random_rotation(rng));
                const fs::vec3 t = fs::uniform_vec3(rng, 1.0);
                const ctga::motor<double> g = ctga::rigid_motion(ctga::make_translator(t[0], t[1], t[2]),
                                                                 ctga::rotor<double>{quat.w(), quat.x(), quat.y(), quat.z()});
                if constexpr (Tree::nq >= 8)  // (else GCC sees q[qo + 7] out of the arm's 7 numbers)
                    for (std::size_t k = 0; k < 8; ++k) q[qo + k] = g[k];
                q_ref.segment<3>(qr) = t;
                q_ref.segment<4>(qr + 3) << quat.w(), quat.x(), quat.y(), quat.z();
            } else if (ref[i].kind != fs::joint_kind::fixed) {
                q[qo] = q_ref[qr] = fs::uniform(rng, -3, 3);
            }
        }
        for (std::size_t k = 0; k < Tree::nv; ++k) {
            qd[k] = qd_ref[static_cast<Eigen::Index>(k)] = fs::uniform(rng, -2, 2);
            qdd[k] = qdd_ref[static_cast<Eigen::Index>(k)] = fs::uniform(rng, -2, 2);
        }
        const ch::kinematics<Tree> k = ch::forward_kinematics(m, q, qd, qdd);
        const fs::kinematics kr = fs::fk(ref, q_ref, qd_ref, qdd_ref);
        for (std::size_t i = 0; i < Tree::size; ++i) {
            INFO("body " << i);
            CHECK(max_abs_diff(k.pose[i], kr.bodies[i].rotation, kr.bodies[i].origin) < 1e-12);
            CHECK(rel_error(k.v[i], kr.bodies[i].velocity) < 1e-12);
            CHECK(rel_error(k.a[i], kr.bodies[i].acceleration) < 1e-12);
        }
        CHECK(rel_error(ch::rnea(m, q, qd, qdd), fs::rnea(ref, q_ref, qd_ref, qdd_ref)) < 1e-12);
        CHECK(rel_error(ch::crba(m, q), fs::crba(ref, q_ref)) < 1e-12);
    }
}

// The float model: built (every check passed in float) and equal to the double one to float precision.
template <class Tree>
void compare_float(const ch::model<Tree, double>& md, const ch::model<Tree, float>& mf) {
    const auto close = [](double a, float b) { return std::abs(a - static_cast<double>(b)) <= 1e-6 * std::max(1.0, std::abs(a)); };
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            INFO("body " << I);
            const auto& d = md.template link<I>();
            const auto& f = mf.template link<I>();
            for (std::size_t r = 0; r < 3; ++r) {
                CHECK(close(d.placement.t[r], f.placement.t[r]));
                CHECK(close(d.inertia.first_moment()[r], f.inertia.first_moment()[r]));
                for (std::size_t c = 0; c < 3; ++c) {
                    CHECK(close(d.placement.R[r][c], f.placement.R[r][c]));
                    CHECK(close(d.inertia.inertia_o()[r][c], f.inertia.inertia_o()[r][c]));
                }
            }
            CHECK(close(d.inertia.mass(), f.inertia.mass()));
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
}

// The tree types the URDF files describe: joint types from the axes, bodies depth first.
using arm7_expected = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_y>, ch::link<1, ch::revolute_z>,
                               ch::link<2, ch::revolute_y>, ch::link<3, ch::revolute_z>, ch::link<4, ch::revolute_y>,
                               ch::link<5, ch::revolute_about>, ch::link<6, ch::fixed>>;
static_assert(std::is_same_v<arm7::tree, arm7_expected>);
using quadruped_expected =
    ch::tree<ch::link<-1, ch::floating>,                                                   //
             ch::link<0, ch::revolute_x>, ch::link<1, ch::revolute_y>, ch::link<2, ch::revolute_y>, ch::link<3, ch::fixed>,  //
             ch::link<0, ch::revolute_x>, ch::link<5, ch::revolute_y>, ch::link<6, ch::revolute_y>, ch::link<7, ch::fixed>,  //
             ch::link<0, ch::revolute_x>, ch::link<9, ch::revolute_y>, ch::link<10, ch::revolute_y>, ch::link<11, ch::fixed>,  //
             ch::link<0, ch::revolute_x>, ch::link<13, ch::revolute_y>, ch::link<14, ch::revolute_y>, ch::link<15, ch::fixed>>;
static_assert(std::is_same_v<quadruped::tree, quadruped_expected>);
static_assert(arm7::tree::nq == 7 && arm7::tree::nv == 7);
static_assert(quadruped::tree::nq == 8 + 12 && quadruped::tree::nv == 6 + 12);
// make_model is a constant expression (ctga::rotation's cos and sin are ctga::math's, which are
// constexpr with g++ and Clang)
static_assert(arm7::make_model<double>() && quadruped::make_model<float>());

}  // namespace

TEST_CASE("urdf: the motor convention the generator relies on: map_of(rigid_motion(make_translator(t), make_rotor(θ, u))) is (Rot(u, θ), t)") {
    // a right-handed quarter turn about z takes x to y
    const ctga::motor_map<double> G = ctga::map_of(ctga::rigid_motion(ctga::make_translator(1.0, 2.0, 3.0),
                                                                      ctga::make_rotor(std::acos(0.0), 0.0, 0.0, 1.0)));
    fs::mat3 quarter_z;
    quarter_z << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    CHECK(max_abs_diff(G, quarter_z, fs::vec3(1, 2, 3)) < 1e-15);
    // and in general Rodrigues' rotation R = 1 + sin θ û + (1 − cos θ) û² (right hand), t as given
    std::mt19937_64 rng(7);
    for (int n = 0; n < 20; ++n) {
        const fs::vec3 u = fs::random_unit_vec3(rng), t = fs::uniform_vec3(rng, 1.0);
        const double theta = fs::uniform(rng, -4, 4);
        const ctga::motor_map<double> H =
            ctga::map_of(ctga::rigid_motion(ctga::make_translator(t[0], t[1], t[2]), ctga::make_rotor(theta, u[0], u[1], u[2])));
        CHECK(max_abs_diff(H, fs::axis_angle(u, theta), t) < 1e-14);
    }
    // URDF's rpy as written here: roll about x first, then pitch about y, then yaw about z (fixed axes)
    fs::mat3 roll90;
    roll90 << 1, 0, 0, 0, 0, -1, 0, 1, 0;
    CHECK((rpy_rotation({std::acos(0.0), 0, 0}) - roll90).cwiseAbs().maxCoeff() < 1e-15);
    CHECK((rpy_rotation({0.1, -0.2, 0.3}) -
           fs::axis_angle(fs::vec3::UnitZ(), 0.3) * fs::axis_angle(fs::vec3::UnitY(), -0.2) * fs::axis_angle(fs::vec3::UnitX(), 0.1))
              .cwiseAbs()
              .maxCoeff() < 1e-15);
}

TEST_CASE("urdf: arm7 (a 7-dof arm, fixed base) agrees with the reference built from its URDF numbers") {
    const auto m = arm7::make_model<double>();
    REQUIRE(m);
    const fs::model ref = reference_of(arm7_urdf);
    compare_parameters(*m, ref);
    compare_dynamics(*m, ref, 101, 8);
}

TEST_CASE("urdf: quadruped (floating base, four legs) agrees with the reference built from its URDF numbers") {
    const auto m = quadruped::make_model<double>();
    REQUIRE(m);
    const fs::model ref = reference_of(quadruped_urdf);
    compare_parameters(*m, ref);
    compare_dynamics(*m, ref, 202, 8);
}

TEST_CASE("urdf: the float models build and equal the double ones to float precision") {
    const auto ad = arm7::make_model<double>();
    const auto af = arm7::make_model<float>();
    REQUIRE(ad);
    REQUIRE(af);
    compare_float(*ad, *af);
    const auto qd = quadruped::make_model<double>();
    const auto qf = quadruped::make_model<float>();
    REQUIRE(qd);
    REQUIRE(qf);
    compare_float(*qd, *qf);
    static_assert(std::is_same_v<decltype(af), const ctga::checked<ch::model<arm7::tree, float>>>);
}

TEST_CASE("urdf: body and joint names in body order") {
    using sv = std::string_view;
    const std::array<sv, 8> arm_bodies{"link1", "link2", "link3", "link4", "link5", "link6", "link7", "tool"};
    const std::array<sv, 8> arm_joints{"joint1", "joint2", "joint3", "joint4", "joint5", "joint6", "joint7", "tool_joint"};
    CHECK(arm7::body_names == arm_bodies);
    CHECK(arm7::joint_names == arm_joints);
    const std::array<sv, 17> quad_bodies{"trunk",   "FL_hip",  "FL_thigh", "FL_calf", "FL_foot", "FR_hip",
                                         "FR_thigh", "FR_calf", "FR_foot",  "RL_hip",  "RL_thigh", "RL_calf",
                                         "RL_foot", "RR_hip",  "RR_thigh", "RR_calf", "RR_foot"};
    const std::array<sv, 17> quad_joints{"floating_base",  "FL_hip_joint",   "FL_thigh_joint", "FL_calf_joint",
                                         "FL_foot_joint",  "FR_hip_joint",   "FR_thigh_joint", "FR_calf_joint",
                                         "FR_foot_joint",  "RL_hip_joint",   "RL_thigh_joint", "RL_calf_joint",
                                         "RL_foot_joint",  "RR_hip_joint",   "RR_thigh_joint", "RR_calf_joint",
                                         "RR_foot_joint"};
    CHECK(quadruped::body_names == quad_bodies);
    CHECK(quadruped::joint_names == quad_joints);
    static_assert(arm7::body_names[7] == "tool" && quadruped::joint_names[0] == "floating_base");
}
