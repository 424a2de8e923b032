// Robots described in URDF (tests/data/arm7.urdf, tests/data/quadruped.urdf), converted to C++
// headers by tools/urdf_to_ctga.py at build time (tests/CMakeLists.txt), against an independent
// description: the same robots written here by hand from the URDF files' numbers (roll-pitch-yaw
// and the inertial frames' rotations done here in C++, not by the script), every URDF link a body
// (fixed joints included), run through the Featherstone reference (support/featherstone.hpp,
// support/featherstone_frames.hpp).
//
//   * --keep-fixed headers (arm7_kept, quadruped_kept): every link a body, against that reference
//     as it is;
//   * the default headers (arm7, quadruped: fixed links merged into their moving parent's body)
//     against the reference's merge_fixed (RBDA's composite-inertia sum, frames re-expressed):
//     the merged bodies' parameters, and at random states the bodies' FK (poses, velocities,
//     accelerations), every URDF link's frame by name (find_frame: pose, its body, the Jacobian in
//     the three references), RNEA, CRBA and ABA.
// Tolerances: parameters 1e-15 (placements, mass, h, I_o of numbers ≤ 10: a few roundings),
// everything else 1e-12 relative (support/urdf_compare.hpp's measures; worst values printed). Also
// the generated tree types, names (bodies, joints, frames: every URDF link) and the float models.
// The other fixtures (ur5e, legged, mobile_gripper) are urdf_fixtures_test.cpp's.
// Four units (support/parts.hpp): arm7 kept and the rest, arm7 merged, quadruped kept, quadruped
// merged (as one unit 49 s and 1.9 GB with g++ -O2; as two, 31–32 s each at -O3).
// PARTS: 4
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

#include "arm7.hpp"            // generated: tools/urdf_to_ctga.py tests/data/arm7.urdf --name arm7
#include "arm7_kept.hpp"       // ... --name arm7_kept --keep-fixed
#include "quadruped.hpp"       // ... tests/data/quadruped.urdf --name quadruped --floating-base
#include "quadruped_kept.hpp"  // ... --name quadruped_kept --floating-base --keep-fixed
#include "support/catch.hpp"
#include "support/featherstone.hpp"
#include "support/featherstone_frames.hpp"
#include "support/parts.hpp"
#include "support/random_tree.hpp"
#include "support/relative_error.hpp"
#include "support/urdf_compare.hpp"

namespace {

namespace ch = ctga::chains;
namespace fs = ctga::test::featherstone;
using ctga::test::urdf::pose_error;
using ctga::test::urdf::rpy_rotation;
using ctga::test::urdf::rel;
using ctga::test::urdf::W;

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

// Every URDF link's name, in the order of the bodies above; the fixed root link of arm7 (the
// world) first.
const std::vector<std::string_view> arm7_links{"base_link", "link1", "link2", "link3", "link4",
                                               "link5",     "link6", "link7", "tool"};
const std::vector<std::string_view> quadruped_links{
    "trunk",  "FL_hip", "FL_thigh", "FL_calf", "FL_foot", "FR_hip", "FR_thigh", "FR_calf", "FR_foot",
    "RL_hip", "RL_thigh", "RL_calf", "RL_foot", "RR_hip", "RR_thigh", "RR_calf", "RR_foot"};

// The robot as the reference sees it: its bodies and a frame per URDF link (the link's own body
// frame; the world for a fixed root link), named as the URDF names the links.
struct reference_robot {
    fs::model model;
    std::vector<fs::frame> frames;
    std::vector<std::string_view> frame_names;
};

reference_robot reference_robot_of(const std::vector<urdf_body>& urdf, const std::vector<std::string_view>& links,
                                   bool world_root) {
    reference_robot r;
    r.model = reference_of(urdf);
    r.frame_names = links;
    if (world_root) r.frames.push_back(fs::frame{-1, fs::mat3::Identity(), fs::vec3::Zero()});
    for (int i = 0; i < r.model.size(); ++i) r.frames.push_back(fs::frame{i, fs::mat3::Identity(), fs::vec3::Zero()});
    return r;
}

// The fixed links merged into their moving ancestors by the reference (merge_fixed), the frames
// re-expressed on the merged bodies.
[[maybe_unused]] reference_robot merged(const reference_robot& r) {
    const fs::merged_model mm = fs::merge_fixed(r.model, r.frames);
    return reference_robot{mm.merged, mm.frames, r.frame_names};
}

// ---- comparisons -------------------------------------------------------------------------------

using ctga::test::rel_error;

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
            CHECK(W("parameters: placement", pose_error(L.placement, b.rotation, b.translation)) < 1e-15);
            const fs::mat6 N = fs::spatial_inertia(b);
            const ctga::body_inertia<double>& n = L.inertia;
            CHECK(W("parameters: mass", std::abs(n.mass() - N(3, 3))) < 1e-15);
            const ctga::vec3<double> h = n.first_moment();
            const ctga::mat3<double> Io = n.inertia_o();
            const fs::vec3 h_ref = b.mass * b.com;
            for (int r = 0; r < 3; ++r) {
                CHECK(W("parameters: h", std::abs(h[static_cast<std::size_t>(r)] - h_ref[r])) < 1e-15);
                for (int c = 0; c < 3; ++c)
                    CHECK(W("parameters: I_o", std::abs(Io[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] - N(r, c))) < 1e-15);
            }
            // a run-time axis (revolute_about, prismatic_along, aligned or not)
            if constexpr (ch::has_run_time_axis<typename Tree::template joint_at<I>> && !ch::is_mimic<typename Tree::template joint_at<I>>) {
                for (int r = 0; r < 3; ++r) CHECK(std::abs(L.joint.u[static_cast<std::size_t>(r)] - b.axis[r]) < 1e-15);
            }
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    CHECK(m.gravity[0] == ref.gravity[0]);
    CHECK(m.gravity[1] == ref.gravity[1]);
    CHECK(m.gravity[2] == ref.gravity[2]);
}

// At random states, the same numbers given to both (a floating joint's q is ctga's motor, 8
// numbers, and the reference's (x, y, z, qw, qx, qy, qz)): FK of every body (pose, velocity,
// acceleration), every URDF link's frame found by its name (its body, pose and Jacobian in the
// three references), RNEA, CRBA, and ABA at random τ.
template <class Tree>
void compare_dynamics(const ch::model<Tree>& m, const reference_robot& robot, std::uint64_t seed, int draws) {
    const fs::model& ref = robot.model;
    REQUIRE(ref.size() == static_cast<int>(Tree::size));
    // every URDF link is a frame, and nothing else is
    REQUIRE(Tree::frame_count == robot.frame_names.size());
    std::vector<std::size_t> frame_of(robot.frames.size());
    for (std::size_t j = 0; j < robot.frames.size(); ++j) {
        INFO("frame " << robot.frame_names[j]);
        const ctga::checked<std::size_t> k = Tree::find_frame(robot.frame_names[j]);
        REQUIRE(k);
        frame_of[j] = *k;
        CHECK(Tree::frame_body[*k] == robot.frames[j].parent);  // the merged link's body
    }
    constexpr fs::reference fs_reference[3] = {fs::reference::local, fs::reference::world, fs::reference::local_world_aligned};
    std::mt19937_64 rng(seed);
    for (int n = 0; n < draws; ++n) {
        INFO("draw " << n);
        Eigen::VectorXd q_ref;
        const ch::configuration<Tree> q = ctga::test::urdf::random_configuration<Tree>(rng, &q_ref);
        REQUIRE(q_ref.size() == ref.nq());
        const ch::joint_vector<Tree> qd = ctga::test::urdf::random_joint_vector<Tree>(rng);
        const ch::joint_vector<Tree> qdd = ctga::test::urdf::random_joint_vector<Tree>(rng);
        const ch::joint_vector<Tree> tau = ctga::test::urdf::random_joint_vector<Tree>(rng, 20);
        const Eigen::VectorXd qd_ref = ctga::test::urdf::eigen_vector(qd), qdd_ref = ctga::test::urdf::eigen_vector(qdd),
                              tau_ref = ctga::test::urdf::eigen_vector(tau);
        const ch::kinematics<Tree> k = ch::forward_kinematics(m, q, qd, qdd);
        const fs::kinematics kr = fs::fk(ref, q_ref, qd_ref, qdd_ref);
        for (std::size_t i = 0; i < Tree::size; ++i) {
            INFO("body " << i);
            CHECK(W("FK: pose", pose_error(k.pose[i], kr.bodies[i].rotation, kr.bodies[i].origin)) < 1e-12);
            CHECK(W("FK: velocity", rel_error(k.v[i], kr.bodies[i].velocity)) < 1e-12);
            CHECK(W("FK: acceleration", rel_error(k.a[i], kr.bodies[i].acceleration)) < 1e-12);
        }
        const auto frames = ctga::test::urdf::all_frames(m, k);
        for (std::size_t j = 0; j < robot.frames.size(); ++j) {
            INFO("frame " << robot.frame_names[j]);
            const fs::pose p = fs::frame_pose(ref, q_ref, robot.frames[j]);
            CHECK(W("frame pose", pose_error(frames.pose[frame_of[j]], p.rotation, p.origin)) < 1e-12);
            for (std::size_t r = 0; r < 3; ++r) {
                INFO(ctga::test::urdf::reference_name(r));
                CHECK(W("frame Jacobian", rel(frames.jacobian[frame_of[j]][r], fs::frame_jacobian(ref, q_ref, robot.frames[j], fs_reference[r]))) <
                      1e-12);
            }
        }
        CHECK(W("RNEA", rel_error(ch::rnea(m, q, qd, qdd), fs::rnea(ref, q_ref, qd_ref, qdd_ref))) < 1e-12);
        CHECK(W("CRBA", rel_error(ch::crba(m, q), fs::crba(ref, q_ref))) < 1e-12);
        CHECK(W("ABA", rel_error(ch::aba(m, q, qd, tau), fs::aba(ref, q_ref, qd_ref, tau_ref))) < 1e-12);
    }
}

// The float model: built (every check passed in float) and equal to the double one to float precision.
template <class Tree>
void compare_float(const ch::model<Tree, double>& md, const ch::model<Tree, float>& mf) {
    const auto close = [](double a, float b) { return std::abs(a - static_cast<double>(b)) <= 1e-6 * std::max(1.0, std::abs(a)); };
    const auto close_map = [&](const ctga::motor_map<double>& d, const ctga::motor_map<float>& f) {
        bool ok = true;
        for (std::size_t r = 0; r < 3; ++r) {
            ok = ok && close(d.t[r], f.t[r]);
            for (std::size_t c = 0; c < 3; ++c) ok = ok && close(d.R[r][c], f.R[r][c]);
        }
        return ok;
    };
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            INFO("body " << I);
            const auto& d = md.template link<I>();
            const auto& f = mf.template link<I>();
            CHECK(close_map(d.placement, f.placement));
            for (std::size_t r = 0; r < 3; ++r) {
                CHECK(close(d.inertia.first_moment()[r], f.inertia.first_moment()[r]));
                for (std::size_t c = 0; c < 3; ++c) CHECK(close(d.inertia.inertia_o()[r][c], f.inertia.inertia_o()[r][c]));
            }
            CHECK(close(d.inertia.mass(), f.inertia.mass()));
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    for (std::size_t k = 0; k < Tree::frame_count; ++k) {
        INFO("frame " << Tree::frame_names[k]);
        CHECK(close_map(md.frames[k], mf.frames[k]));
    }
}

// The tree types the URDF files describe: joint types from the axes, bodies depth first, then a
// frame per link, depth first from the root.
template <ctga::fixed_string N, int B>
using FF = ch::fixed_frame<N, B>;
// (the converter wraps a joint whose placement does not turn in aligned<…>: every joint here but
// the arm's fourth, whose origin rolls by pi/2 (turned<…>: y along the parent's z, z along −y),
// and the kept tool's fixed joint, whose rpy is no multiple of pi/2)
template <class J>
using al = ch::aligned<J>;
template <class J>
using rolled = ch::turned<ch::turn{ch::axis::x, ch::axis::z, ch::axis::minus_y}, J>;
using arm7_expected = ch::tree<ch::link<-1, al<ch::revolute_z>>, ch::link<0, al<ch::revolute_y>>, ch::link<1, al<ch::revolute_z>>,
                               ch::link<2, rolled<ch::revolute_y>>, ch::link<3, al<ch::revolute_z>>, ch::link<4, al<ch::revolute_y>>,
                               ch::link<5, al<ch::revolute_about>>,  // the tool merged into link7's body
                               FF<"base_link", -1>, FF<"link1", 0>, FF<"link2", 1>, FF<"link3", 2>, FF<"link4", 3>, FF<"link5", 4>,
                               FF<"link6", 5>, FF<"link7", 6>, FF<"tool", 6>>;
static_assert(std::is_same_v<arm7::tree, arm7_expected>);
using arm7_kept_expected = ch::tree<ch::link<-1, al<ch::revolute_z>>, ch::link<0, al<ch::revolute_y>>, ch::link<1, al<ch::revolute_z>>,
                                    ch::link<2, rolled<ch::revolute_y>>, ch::link<3, al<ch::revolute_z>>, ch::link<4, al<ch::revolute_y>>,
                                    ch::link<5, al<ch::revolute_about>>, ch::link<6, ch::fixed>,  //
                                    FF<"base_link", -1>, FF<"link1", 0>, FF<"link2", 1>, FF<"link3", 2>, FF<"link4", 3>,
                                    FF<"link5", 4>, FF<"link6", 5>, FF<"link7", 6>, FF<"tool", 7>>;
static_assert(std::is_same_v<arm7_kept::tree, arm7_kept_expected>);
using quadruped_expected =
    ch::tree<ch::link<-1, al<ch::floating>>,                                                                      //
             ch::link<0, al<ch::revolute_x>>, ch::link<1, al<ch::revolute_y>>, ch::link<2, al<ch::revolute_y>>,          // FL
             ch::link<0, al<ch::revolute_x>>, ch::link<4, al<ch::revolute_y>>, ch::link<5, al<ch::revolute_y>>,          // FR
             ch::link<0, al<ch::revolute_x>>, ch::link<7, al<ch::revolute_y>>, ch::link<8, al<ch::revolute_y>>,          // RL
             ch::link<0, al<ch::revolute_x>>, ch::link<10, al<ch::revolute_y>>, ch::link<11, al<ch::revolute_y>>,        // RR
             FF<"trunk", 0>,                                                                                   //
             FF<"FL_hip", 1>, FF<"FL_thigh", 2>, FF<"FL_calf", 3>, FF<"FL_foot", 3>,                              //
             FF<"FR_hip", 4>, FF<"FR_thigh", 5>, FF<"FR_calf", 6>, FF<"FR_foot", 6>,                              //
             FF<"RL_hip", 7>, FF<"RL_thigh", 8>, FF<"RL_calf", 9>, FF<"RL_foot", 9>,                              //
             FF<"RR_hip", 10>, FF<"RR_thigh", 11>, FF<"RR_calf", 12>, FF<"RR_foot", 12>>;
static_assert(std::is_same_v<quadruped::tree, quadruped_expected>);
using quadruped_kept_expected =
    ch::tree<ch::link<-1, al<ch::floating>>,                                                                                   //
             ch::link<0, al<ch::revolute_x>>, ch::link<1, al<ch::revolute_y>>, ch::link<2, al<ch::revolute_y>>, ch::link<3, al<ch::fixed>>,     //
             ch::link<0, al<ch::revolute_x>>, ch::link<5, al<ch::revolute_y>>, ch::link<6, al<ch::revolute_y>>, ch::link<7, al<ch::fixed>>,     //
             ch::link<0, al<ch::revolute_x>>, ch::link<9, al<ch::revolute_y>>, ch::link<10, al<ch::revolute_y>>, ch::link<11, al<ch::fixed>>,   //
             ch::link<0, al<ch::revolute_x>>, ch::link<13, al<ch::revolute_y>>, ch::link<14, al<ch::revolute_y>>, ch::link<15, al<ch::fixed>>,  //
             FF<"trunk", 0>,                                                                                                //
             FF<"FL_hip", 1>, FF<"FL_thigh", 2>, FF<"FL_calf", 3>, FF<"FL_foot", 4>,                                           //
             FF<"FR_hip", 5>, FF<"FR_thigh", 6>, FF<"FR_calf", 7>, FF<"FR_foot", 8>,                                           //
             FF<"RL_hip", 9>, FF<"RL_thigh", 10>, FF<"RL_calf", 11>, FF<"RL_foot", 12>,                                        //
             FF<"RR_hip", 13>, FF<"RR_thigh", 14>, FF<"RR_calf", 15>, FF<"RR_foot", 16>>;
static_assert(std::is_same_v<quadruped_kept::tree, quadruped_kept_expected>);
static_assert(arm7::tree::nq == 7 && arm7::tree::nv == 7 && arm7_kept::tree::nq == 7 && arm7_kept::tree::nv == 7);
static_assert(quadruped::tree::nq == 8 + 12 && quadruped::tree::nv == 6 + 12);
static_assert(quadruped_kept::tree::nq == 8 + 12 && quadruped_kept::tree::nv == 6 + 12);
#if CTGA_TEST_PART_HOLDS(0)
// make_model is a constant expression (ctga::rotation's cos and sin are ctga::math's, which are
// constexpr with g++ and Clang)
static_assert(arm7::make_model<double>() && quadruped::make_model<float>());
#endif

}  // namespace

#if CTGA_TEST_PART_HOLDS(0)
TEST_CASE("urdf: the motor convention the generator relies on: map_of(rigid_motion(make_translator(t), make_rotor(θ, u))) is (Rot(u, θ), t)") {
    // a right-handed quarter turn about z takes x to y
    const ctga::motor_map<double> G = ctga::map_of(ctga::rigid_motion(ctga::make_translator(1.0, 2.0, 3.0),
                                                                      ctga::make_rotor(std::acos(0.0), 0.0, 0.0, 1.0)));
    fs::mat3 quarter_z;
    quarter_z << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    CHECK(pose_error(G, quarter_z, fs::vec3(1, 2, 3)) < 1e-15);
    // and in general Rodrigues' rotation R = 1 + sin θ û + (1 − cos θ) û² (right hand), t as given
    std::mt19937_64 rng(7);
    for (int n = 0; n < 20; ++n) {
        const fs::vec3 u = fs::random_unit_vec3(rng), t = fs::uniform_vec3(rng, 1.0);
        const double theta = fs::uniform(rng, -4, 4);
        const ctga::motor_map<double> H =
            ctga::map_of(ctga::rigid_motion(ctga::make_translator(t[0], t[1], t[2]), ctga::make_rotor(theta, u[0], u[1], u[2])));
        CHECK(pose_error(H, fs::axis_angle(u, theta), t) < 1e-14);
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

TEST_CASE("urdf: arm7 --keep-fixed (every link a body) agrees with the reference built from its URDF numbers") {
    const auto m = arm7_kept::make_model<double>();
    REQUIRE(m);
    const reference_robot ref = reference_robot_of(arm7_urdf, arm7_links, true);
    compare_parameters(*m, ref.model);
    compare_dynamics(*m, ref, 101, 8);
    ctga::test::urdf::print_worst("urdf: arm7_kept");
}

#endif
#if CTGA_TEST_PART_HOLDS(2)
TEST_CASE("urdf: arm7 (the tool merged into link7's body) agrees with the reference's merge_fixed of its URDF numbers") {
    const auto m = arm7::make_model<double>();
    REQUIRE(m);
    const reference_robot ref = merged(reference_robot_of(arm7_urdf, arm7_links, true));
    REQUIRE(ref.model.size() == 7);
    compare_parameters(*m, ref.model);
    compare_dynamics(*m, ref, 102, 8);
    ctga::test::urdf::print_worst("urdf: arm7");
}

#endif

#if CTGA_TEST_PART_HOLDS(1)
TEST_CASE("urdf: quadruped --keep-fixed (floating base, four legs, feet as bodies) agrees with the reference") {
    const auto m = quadruped_kept::make_model<double>();
    REQUIRE(m);
    const reference_robot ref = reference_robot_of(quadruped_urdf, quadruped_links, false);
    compare_parameters(*m, ref.model);
    compare_dynamics(*m, ref, 201, 8);
    ctga::test::urdf::print_worst("urdf: quadruped_kept");
}

#endif
#if CTGA_TEST_PART_HOLDS(3)
TEST_CASE("urdf: quadruped (feet merged into the calves) agrees with the reference's merge_fixed") {
    const auto m = quadruped::make_model<double>();
    REQUIRE(m);
    const reference_robot ref = merged(reference_robot_of(quadruped_urdf, quadruped_links, false));
    REQUIRE(ref.model.size() == 13);
    compare_parameters(*m, ref.model);
    compare_dynamics(*m, ref, 202, 8);
    ctga::test::urdf::print_worst("urdf: quadruped");
}

#endif

#if CTGA_TEST_PART_HOLDS(0)
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

TEST_CASE("urdf: body, joint and frame names") {
    using sv = std::string_view;
    // bodies: the moving links (the fixed ones merged); frames: every URDF link, depth first
    const std::array<sv, 7> arm_bodies{"link1", "link2", "link3", "link4", "link5", "link6", "link7"};
    const std::array<sv, 7> arm_joints{"joint1", "joint2", "joint3", "joint4", "joint5", "joint6", "joint7"};
    const std::array<sv, 9> arm_frames{"base_link", "link1", "link2", "link3", "link4", "link5", "link6", "link7", "tool"};
    CHECK(arm7::body_names == arm_bodies);
    CHECK(arm7::joint_names == arm_joints);
    CHECK(arm7::tree::frame_names == arm_frames);
    const std::array<sv, 8> arm_kept_bodies{"link1", "link2", "link3", "link4", "link5", "link6", "link7", "tool"};
    const std::array<sv, 8> arm_kept_joints{"joint1", "joint2", "joint3", "joint4", "joint5", "joint6", "joint7", "tool_joint"};
    CHECK(arm7_kept::body_names == arm_kept_bodies);
    CHECK(arm7_kept::joint_names == arm_kept_joints);
    CHECK(arm7_kept::tree::frame_names == arm_frames);

    // the floating base joint is named after the root link
    const std::array<sv, 13> quad_bodies{"trunk",    "FL_hip",  "FL_thigh", "FL_calf", "FR_hip",   "FR_thigh", "FR_calf",
                                         "RL_hip",   "RL_thigh", "RL_calf", "RR_hip",  "RR_thigh", "RR_calf"};
    const std::array<sv, 13> quad_joints{"trunk",          "FL_hip_joint",   "FL_thigh_joint", "FL_calf_joint", "FR_hip_joint",
                                         "FR_thigh_joint", "FR_calf_joint",  "RL_hip_joint",   "RL_thigh_joint", "RL_calf_joint",
                                         "RR_hip_joint",   "RR_thigh_joint", "RR_calf_joint"};
    const std::array<sv, 17> quad_frames{"trunk",    "FL_hip",  "FL_thigh", "FL_calf",  "FL_foot", "FR_hip",
                                         "FR_thigh", "FR_calf", "FR_foot",  "RL_hip",   "RL_thigh", "RL_calf",
                                         "RL_foot",  "RR_hip",  "RR_thigh", "RR_calf",  "RR_foot"};
    CHECK(quadruped::body_names == quad_bodies);
    CHECK(quadruped::joint_names == quad_joints);
    CHECK(quadruped::tree::frame_names == quad_frames);
    const std::array<sv, 17> quad_kept_bodies{"trunk",    "FL_hip",  "FL_thigh", "FL_calf",  "FL_foot", "FR_hip",
                                              "FR_thigh", "FR_calf", "FR_foot",  "RL_hip",   "RL_thigh", "RL_calf",
                                              "RL_foot",  "RR_hip",  "RR_thigh", "RR_calf",  "RR_foot"};
    const std::array<sv, 17> quad_kept_joints{"trunk",          "FL_hip_joint",   "FL_thigh_joint", "FL_calf_joint",
                                              "FL_foot_joint",  "FR_hip_joint",   "FR_thigh_joint", "FR_calf_joint",
                                              "FR_foot_joint",  "RL_hip_joint",   "RL_thigh_joint", "RL_calf_joint",
                                              "RL_foot_joint",  "RR_hip_joint",   "RR_thigh_joint", "RR_calf_joint",
                                              "RR_foot_joint"};
    CHECK(quadruped_kept::body_names == quad_kept_bodies);
    CHECK(quadruped_kept::joint_names == quad_kept_joints);
    CHECK(quadruped_kept::tree::frame_names == quad_frames);
    static_assert(arm7_kept::body_names[7] == "tool" && arm7::tree::frame_names[8] == "tool");
    static_assert(quadruped::joint_names[0] == "trunk" && quadruped_kept::joint_names[0] == "trunk");
    static_assert(ch::frame_index<quadruped::tree, "RR_foot">() == 16 && quadruped::tree::frame_body[16] == 12);
}
#endif
