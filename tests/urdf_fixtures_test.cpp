// The URDF fixtures tests/data/ur5e.urdf, legged.urdf and mobile_gripper.urdf converted by
// tools/urdf_to_ctga.py at build time (tests/CMakeLists.txt): with default options (fixed links
// merged into their moving ancestor's body, every link a named frame), with --keep-fixed (every
// link its own body) and, for mobile_gripper, with --mimic independent.
//
//   * merged-link inertia: each default model against its --keep-fixed model: the same RNEA,
//     CRBA and ABA (the same q, q̇, q̈, τ numbers: fixed bodies have no coordinates), every link's
//     frame (found by name in both: pose, Jacobian in the three references), the same total mass,
//     centre of mass and its velocity (ur5e: up to base_link_inertia, which the default model
//     lumps into the world and drops);
//   * mimic: mobile_gripper (finger_right mimics finger_left, q = −1·q_left + 0.01) against the
//     --mimic independent model with the coupling applied here: q_ind = expand(q), q̇_ind = G q̇,
//     q̈_ind = G q̈, τ = Gᵀ τ_ind, H = Gᵀ H_ind G, q̈ = (Gᵀ H_ind G)⁻¹ (τ − Gᵀ C_ind), J = J_ind G,
//     G built from the tree types (the mimic body and its master);
//   * mobile_gripper's joints as the URDF writes them: the planar base moves its link by (x, y)
//     and θ about the plane normal after the joint's origin; each other link's pose relative to
//     its parent link is origin ∘ motion(q), written here from the URDF numbers (continuous +z,
//     revolute −y, prismatic −z, a revolute joint about (0.6, 0, 0.8), the fingers);
//   * ur5e: tool0 against UR's published DH forward kinematics (below);
//   * legged: the massless root link's body carries base_inertia's mass; the total mass is the
//     sum of the URDF's masses;
//   * massless_subtree (−1 for every generated model; a body index once a subtree's masses are
//     zeroed), find_frame of every name and of a name the tree does not have, the names;
//   * limited_gripper's loading options: --massless lock --lock elbow=0.7 (elbow, finger_left,
//     thumb and the mimic finger_right locked) against --massless armature=0.01 (every joint
//     free) held at the locked values: every frame's pose, RNEA's free rows; the free
//     model's make_limits against the URDF's numbers, its armatures (and massless_subtree counting
//     them), its mass-0 tensors in the bodies' inertia (the sensor merged into the hand, the rotor).
// Tolerances: 1e-12 relative for two exact routes (support/urdf_compare.hpp's measures, worst
// values printed per test case: ≤ 1e-14, the largest ABA(RNEA(q̈)) = q̈ of the mimic model);
// masses 1e-12 absolute; tool0 against the published DH without the fixture's residues 1e-10.
// Five units (support/parts.hpp): ur5e; legged frames and limited_gripper; the mimic and the names;
// mobile_gripper (merged vs kept, its joints); legged dynamics (as one unit 66 s and 2.4 GB with
// g++ -O2, before limited_gripper).
// PARTS: 5
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include <ctga/chains/algorithms.hpp>

#include "gripper_free.hpp"    // generated: tools/urdf_to_ctga.py tests/data/limited_gripper.urdf --name gripper_free --massless armature=0.01
#include "gripper_locked.hpp"  // ... --name gripper_locked --massless lock --lock elbow=0.7
#include "legged.hpp"               // generated: tools/urdf_to_ctga.py tests/data/legged.urdf --name legged --floating-base
#include "legged_kept.hpp"          // ... --name legged_kept --floating-base --keep-fixed
#include "mobile_gripper.hpp"       // ... tests/data/mobile_gripper.urdf --name mobile_gripper
#include "mobile_gripper_ind.hpp"   // ... --name mobile_gripper_ind --mimic independent
#include "mobile_gripper_kept.hpp"  // ... --name mobile_gripper_kept --keep-fixed
#include "support/catch.hpp"
#include "support/featherstone.hpp"
#include "support/parts.hpp"
#include "support/random_tree.hpp"
#include "support/urdf_compare.hpp"
#include "ur5e.hpp"       // ... tests/data/ur5e.urdf --name ur5e
#include "ur5e_kept.hpp"  // ... --name ur5e_kept --keep-fixed

namespace {

namespace ch = ctga::chains;
namespace fs = ctga::test::featherstone;
using ctga::test::urdf::eigen_jacobian;
using ctga::test::urdf::eigen_matrix;
using ctga::test::urdf::eigen_rotation;
using ctga::test::urdf::eigen_translation;
using ctga::test::urdf::eigen_vector;
using ctga::test::urdf::pose_error;
using ctga::test::urdf::rel;
using ctga::test::urdf::rpy_rotation;
using ctga::test::urdf::W;
using fs::mat3;
using fs::vec3;
using sv = std::string_view;

constexpr double pi = std::numbers::pi;

// a placement (R, t) as a 4 × 4 homogeneous matrix, and the URDF <origin xyz rpy> (each part
// uses some of these)
using mat4 = Eigen::Matrix4d;
[[maybe_unused]] mat4 homogeneous(const mat3& R, const vec3& t) {
    mat4 T = mat4::Identity();
    T.topLeftCorner<3, 3>() = R;
    T.topRightCorner<3, 1>() = t;
    return T;
}
[[maybe_unused]] mat4 origin(const vec3& xyz, const std::array<double, 3>& rpy) { return homogeneous(rpy_rotation(rpy), xyz); }
[[maybe_unused]] mat4 homogeneous(const ctga::motor_map<double>& G) { return homogeneous(eigen_rotation(G), eigen_translation(G)); }
[[maybe_unused]] mat4 rotation_about(const vec3& u, double angle) { return homogeneous(fs::axis_angle(u, angle), vec3::Zero()); }
[[maybe_unused]] mat4 translation(const vec3& t) { return homogeneous(mat3::Identity(), t); }
[[maybe_unused]] double pose_error(const mat4& A, const mat4& B) { return (A - B).topRows<3>().cwiseAbs().maxCoeff(); }

template <class Tree>
ch::model<Tree> built(const ctga::checked<ch::model<Tree>>& m) {
    REQUIRE(m);
    return *m;
}

// ---- a default model against its --keep-fixed model ----------------------------------------------

// Per body of a tree: whether its joint is fixed (fixed, aligned or turned: it does not move).
template <class Tree>
constexpr std::array<bool, Tree::size> fixed_joints = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<bool, Tree::size>{!ch::moves<typename Tree::template joint_at<I>>...};
}(std::make_index_sequence<Tree::size>{});

// What a comparison checks: the frames (poses, Jacobians), the dynamics (RNEA, CRBA, ABA, centre
// of mass), or both. A big kept tree checks them in separate units (each under 30 s to compile).
enum class aspects { frames, dynamics, both };

// A (merged) and B (kept) describe one robot: B's bodies on fixed joints are merged into A's
// bodies, so their q, q̇, q̈ and τ are the same numbers. `world_mass` and `world_moment` (its mass
// times its centre, world) are what A lumped into the world and dropped and B still has.
template <aspects What = aspects::both, class A, class B, std::size_t NA, std::size_t NB>
void compare_merged_kept(const ch::model<A>& ma, const ch::model<B>& mb, const std::array<sv, NA>& joints_a,
                         const std::array<sv, NB>& joints_b, std::uint64_t seed, int draws, double world_mass = 0,
                         const vec3& world_moment = vec3::Zero()) {
    static_assert(A::nq == B::nq && A::nv == B::nv, "fixed joints have no coordinates");
    static_assert(A::frame_count == B::frame_count, "both list every URDF link as a frame");
    // B's moving joints are A's, in the same order
    std::vector<sv> moving_b;
    for (std::size_t i = 0; i < B::size; ++i)
        if (!fixed_joints<B>[i]) moving_b.push_back(joints_b[i]);
    CHECK(moving_b == std::vector<sv>(joints_a.begin(), joints_a.end()));
    for (bool f : fixed_joints<A>) CHECK(!f);
    // the frames by name
    std::array<std::size_t, A::frame_count> in_b{};
    for (std::size_t k = 0; k < A::frame_count; ++k) {
        INFO("frame " << A::frame_names[k]);
        const ctga::checked<std::size_t> kb = B::find_frame(A::frame_names[k]);
        REQUIRE(kb);
        in_b[k] = *kb;
    }
    std::mt19937_64 rng(seed);
    for (int n = 0; n < draws; ++n) {
        INFO("draw " << n);
        const ch::configuration<A> q = ctga::test::urdf::random_configuration<A>(rng);
        const ch::joint_vector<A> qd = ctga::test::urdf::random_joint_vector<A>(rng);
        const ch::joint_vector<A> qdd = ctga::test::urdf::random_joint_vector<A>(rng);
        const ch::joint_vector<A> tau = ctga::test::urdf::random_joint_vector<A>(rng, 20);
        const ch::kinematics<A> ka = ch::forward_kinematics(ma, q, qd, qdd);
        const ch::kinematics<B> kb = ch::forward_kinematics(mb, q, qd, qdd);
        if constexpr (What != aspects::dynamics) {
            const auto fa = ctga::test::urdf::all_frames(ma, ka);
            const auto fb = ctga::test::urdf::all_frames(mb, kb);
            for (std::size_t k = 0; k < A::frame_count; ++k) {
                INFO("frame " << A::frame_names[k]);
                CHECK(W("frame pose", pose_error(fa.pose[k], fb.pose[in_b[k]])) < 1e-12);
                for (std::size_t r = 0; r < 3; ++r) {
                    INFO(ctga::test::urdf::reference_name(r));
                    CHECK(W("frame Jacobian", rel(fa.jacobian[k][r], fb.jacobian[in_b[k]][r])) < 1e-12);
                }
            }
        }
        if constexpr (What != aspects::frames) {
            CHECK(W("RNEA", rel(eigen_vector(ch::rnea(ma, q, qd, qdd)), eigen_vector(ch::rnea(mb, q, qd, qdd)))) < 1e-12);
            CHECK(W("CRBA", rel(eigen_matrix(ch::crba(ma, q)), eigen_matrix(ch::crba(mb, q)))) < 1e-12);
            CHECK(W("ABA", rel(eigen_vector(ch::aba(ma, q, qd, tau)), eigen_vector(ch::aba(mb, q, qd, tau)))) < 1e-12);
            const ch::center_of_mass_state<double> ca = ch::center_of_mass(ma, ka), cb = ch::center_of_mass(mb, kb);
            CHECK(W("total mass", std::abs(ca.mass + world_mass - cb.mass)) < 1e-12);
            const vec3 pa(ca.position[0], ca.position[1], ca.position[2]), pb(cb.position[0], cb.position[1], cb.position[2]);
            const vec3 va(ca.velocity[0], ca.velocity[1], ca.velocity[2]), vb(cb.velocity[0], cb.velocity[1], cb.velocity[2]);
            CHECK(W("centre of mass (mass-weighted)", rel(ca.mass * pa + world_moment, cb.mass * pb)) < 1e-12);
            CHECK(W("centre of mass velocity (momentum)", rel(ca.mass * va, cb.mass * vb)) < 1e-12);
            if (world_mass == 0) CHECK(W("centre of mass", rel(pa, pb)) < 1e-12);
        }
    }
}

// ---- mobile_gripper's links as the URDF places them ------------------------------------------------

// Frame `child`'s pose relative to frame `parent` (both by name), at k.
template <class Tree>
mat4 relative(const ctga::test::urdf::frames_at<Tree>& f, sv parent, sv child) {
    const ctga::checked<std::size_t> p = Tree::find_frame(parent), c = Tree::find_frame(child);
    REQUIRE(p);
    REQUIRE(c);
    return homogeneous(f.pose[*p]).inverse() * homogeneous(f.pose[*c]);
}

// ---- UR5e: Universal Robots' published DH parameters ----------------------------------------------
//
// Standard DH: T = Π_i Rz(θ_i) Tz(d_i) Tx(a_i) Rx(α_i), θ_i the joint angles,
//   d = (0.1625, 0, 0, 0.1333, 0.0997, 0.0996), a = (0, −0.425, −0.3922, 0, 0, 0),
//   α = (π/2, 0, 0, π/2, −π/2, 0).
// The URDF's frames follow the ROS description (ur_description): base_link is the DH base frame
// turned by π about z (base_link_inertia and the ROS "base" frame, both yaw π on base_link, ARE
// the DH base frame), tool0 is the DH flange frame (frame 6) exactly, and the joint angles are
// the DH θ's (no offsets). So
//   pose of tool0 in base_link = Rz(π) · T_DH(q),     pose of tool0 in "base" = T_DH(q).
// (Each URDF link i is DH frame i−1 turned by θ_i and moved d_i along z.) The fixture, like UR's
// exported description, carries two rounding residues: the z of wrist_2_joint's and
// wrist_3_joint's origins are −2.044881182297852e-11 and −2.042830148012698e-11 instead of 0.
// In DH terms they are a translation by ε5 = −2.044881182297852e-11 along y before Rz(θ5) and by
// −ε6 = +2.042830148012698e-11 along y before Rz(θ6), so the published DH (no residues) matches
// tool0's rotation to rounding and its position only to ~4e-11 (≤ |ε5| + |ε6|); with the residues
// inserted, to rounding.
struct dh_row {
    double d, a, alpha;
};
constexpr std::array<dh_row, 6> ur5e_dh{{{0.1625, 0, pi / 2},
                                          {0, -0.425, 0},
                                          {0, -0.3922, 0},
                                          {0.1333, 0, pi / 2},
                                          {0.0997, 0, -pi / 2},
                                          {0.0996, 0, 0}}};
constexpr std::array<double, 6> ur5e_residue_y{0, 0, 0, 0, -2.044881182297852e-11, 2.042830148012698e-11};

[[maybe_unused]] mat4 dh_forward_kinematics(const std::array<double, 6>& theta, bool with_residues) {
    mat4 T = mat4::Identity();
    for (std::size_t i = 0; i < 6; ++i) {
        if (with_residues) T = T * translation(vec3(0, ur5e_residue_y[i], 0));
        T = T * rotation_about(vec3::UnitZ(), theta[i]) * translation(vec3(0, 0, ur5e_dh[i].d)) *
            translation(vec3(ur5e_dh[i].a, 0, 0)) * rotation_about(vec3::UnitX(), ur5e_dh[i].alpha);
    }
    return T;
}

// ---- the generated tree types ----------------------------------------------------------------------

static_assert(ur5e::tree::size == 6 && ur5e::tree::nq == 6 && ur5e::tree::frame_count == 11);
static_assert(ur5e_kept::tree::size == 10 && ur5e_kept::tree::frame_count == 11);
static_assert(legged::tree::size == 13 && legged::tree::nq == 8 + 12 && legged::tree::nv == 6 + 12 &&
              legged::tree::frame_count == 26);
static_assert(legged_kept::tree::size == 26 && legged_kept::tree::nv == 6 + 12);
// (every joint of these two fixtures has rpy 0 0 0: aligned)
static_assert(std::is_same_v<legged::tree::joint_at<0>, ch::aligned<ch::floating>>);
static_assert(std::is_same_v<legged::tree::joint_at<9>, ch::aligned<ch::revolute<ch::axis::minus_y>>>);   // LH_KFE, axis 0 −1 0
static_assert(std::is_same_v<legged::tree::joint_at<12>, ch::aligned<ch::revolute<ch::axis::minus_y>>>);  // RH_KFE
// mobile_gripper: the planar base as three bodies, then the arm; finger_right mimics finger_left
static_assert(mobile_gripper::tree::size == 9 && mobile_gripper::tree::nq == 8 && mobile_gripper::tree::nv == 8);
static_assert(std::is_same_v<mobile_gripper::tree::joint_at<0>, ch::aligned<ch::prismatic_x>>);
static_assert(std::is_same_v<mobile_gripper::tree::joint_at<1>, ch::aligned<ch::prismatic_y>>);
static_assert(std::is_same_v<mobile_gripper::tree::joint_at<2>, ch::aligned<ch::revolute_z>>);
static_assert(std::is_same_v<mobile_gripper::tree::joint_at<3>, ch::aligned<ch::revolute_z>>);                   // continuous +z
static_assert(std::is_same_v<mobile_gripper::tree::joint_at<4>, ch::aligned<ch::revolute<ch::axis::minus_y>>>);  // 0 −1 0
static_assert(std::is_same_v<mobile_gripper::tree::joint_at<5>, ch::aligned<ch::prismatic<ch::axis::minus_z>>>); // 0 0 −1
static_assert(std::is_same_v<mobile_gripper::tree::joint_at<6>, ch::aligned<ch::revolute_about>>);               // 0.6 0 0.8
static_assert(std::is_same_v<mobile_gripper::tree::joint_at<7>, ch::aligned<ch::prismatic_y>>);
static_assert(std::is_same_v<mobile_gripper::tree::joint_at<8>, ch::mimic<ch::aligned<ch::prismatic_y>, 7>>);
static_assert(std::is_same_v<mobile_gripper_ind::tree::joint_at<8>, ch::aligned<ch::prismatic_y>> && mobile_gripper_ind::tree::nv == 9);
static_assert(std::is_same_v<mobile_gripper_kept::tree::joint_at<10>, ch::mimic<ch::aligned<ch::prismatic_y>, 9>>);
// imu_joint yaws by pi/2 (rpy 0 0 1.5707963267948966): its x axis along the parent's y, y along −x
static_assert(std::is_same_v<mobile_gripper_kept::tree::joint_at<3>,
                             ch::turned<ch::turn{ch::axis::y, ch::axis::minus_x, ch::axis::z}, ch::fixed>>);
static_assert(ch::frame_index<ur5e::tree, "tool0">() == 9 && ur5e::tree::frame_body[9] == 5);
static_assert(ch::frame_index<legged::tree, "LF_FOOT">() == 10 && legged::tree::frame_body[10] == 3);

// ---- the mimic coupling by hand ----------------------------------------------------------------------

// The mimic body of a tree with one (and its master): from the tree type.
template <class Tree>
constexpr std::size_t mimic_body = [] {
    for (std::size_t i = 0; i < Tree::size; ++i)
        if (Tree::master[i] >= 0) return i;
    return Tree::size;
}();

}  // namespace

#if CTGA_TEST_PART_HOLDS(0)
TEST_CASE("urdf fixtures: ur5e merged (flange, tool0 as frames, base_link_inertia lumped into the world) = ur5e --keep-fixed") {
    const auto a = built(ur5e::make_model<double>());
    const auto b = built(ur5e_kept::make_model<double>());
    // base_link_inertia (mass 4.0, centre at its origin: origin xyz 0 0 0 rpy 0 0 π, inertial xyz 0
    // 0 0) stays in the kept model as a body fixed to the world; the default model drops it
    const double m_bli = 4.0;
    const vec3 c_bli = vec3::Zero() + rpy_rotation({0, 0, pi}) * vec3::Zero();
    compare_merged_kept(a, b, ur5e::joint_names, ur5e_kept::joint_names, 501, 10, m_bli, m_bli * c_bli);
    ctga::test::urdf::print_worst("urdf fixtures: ur5e merged vs kept");
}

TEST_CASE("urdf fixtures: ur5e's tool0 is UR's published DH forward kinematics, base_link = the DH base turned by π about z") {
    const auto m = built(ur5e::make_model<double>());
    std::mt19937_64 rng(502);
    const mat4 base_link_from_dh = rotation_about(vec3::UnitZ(), pi);  // the constant transform (above)
    for (int n = 0; n < 10; ++n) {
        INFO("configuration " << n);
        std::array<double, 6> theta{};
        ch::configuration<ur5e::tree> q{};
        for (std::size_t i = 0; i < 6; ++i) q[i] = theta[i] = fs::uniform(rng, -2 * pi, 2 * pi);
        const ch::kinematics<ur5e::tree> k = ch::forward_kinematics(m, q);
        const mat4 tool0 = homogeneous(ch::frame_pose(m, k, ch::frame<"tool0">));
        const mat4 base = homogeneous(ch::frame_pose(m, k, ch::frame<"base">));
        const mat4 dh = base_link_from_dh * dh_forward_kinematics(theta, false);
        const mat4 dh_residues = base_link_from_dh * dh_forward_kinematics(theta, true);
        // the published DH: rotation to rounding, position to the fixture's residues
        CHECK(W("tool0 rotation vs published DH", (tool0 - dh).topLeftCorner<3, 3>().cwiseAbs().maxCoeff()) < 1e-12);
        CHECK(W("tool0 position vs published DH (residues ~2e-11)", (tool0 - dh).topRightCorner<3, 1>().cwiseAbs().maxCoeff()) < 1e-10);
        // the DH with the residues: both to rounding
        CHECK(W("tool0 pose vs DH with the URDF's residues", pose_error(tool0, dh_residues)) < 1e-12);
        // the ROS "base" frame is the DH base frame
        CHECK(W("ROS base frame = Rz(π)", pose_error(base, base_link_from_dh)) < 1e-15);
        CHECK(W("tool0 in base = DH with residues", pose_error(base.inverse() * tool0, dh_forward_kinematics(theta, true))) < 1e-12);
    }
    // at q = 0 the published DH puts the flange at (a2 + a3, −d4 − d6, d1 − d5) in the DH base,
    // so at (0.8172, 0.2329, 0.0628) in base_link (x, y turned by π)
    const mat4 tool0_zero = homogeneous(ch::frame_pose(m, ch::forward_kinematics(m, ch::configuration<ur5e::tree>{}), ch::frame<"tool0">));
    CHECK(std::abs(tool0_zero(0, 3) - 0.8172) < 1e-10);
    CHECK(std::abs(tool0_zero(1, 3) - 0.2329) < 1e-10);
    CHECK(std::abs(tool0_zero(2, 3) - 0.0628) < 1e-10);
    ctga::test::urdf::print_worst("urdf fixtures: ur5e DH");
}
#endif

#if CTGA_TEST_PART_HOLDS(1)
TEST_CASE("urdf fixtures: legged merged (massless root, base_inertia, face, feet merged) = legged --keep-fixed: frames") {
    const auto a = built(legged::make_model<double>());
    const auto b = built(legged_kept::make_model<double>());
    compare_merged_kept<aspects::frames>(a, b, legged::joint_names, legged_kept::joint_names, 601, 8);
    ctga::test::urdf::print_worst("urdf fixtures: legged merged vs kept, frames");
}
#endif

#if CTGA_TEST_PART_HOLDS(4)
TEST_CASE("urdf fixtures: legged merged (massless root, base_inertia, face, feet merged) = legged --keep-fixed: dynamics") {
    const auto a = built(legged::make_model<double>());
    const auto b = built(legged_kept::make_model<double>());
    compare_merged_kept<aspects::dynamics>(a, b, legged::joint_names, legged_kept::joint_names, 601, 8);
    ctga::test::urdf::print_worst("urdf fixtures: legged merged vs kept, dynamics");
}

TEST_CASE("urdf fixtures: legged converts with a massless root link, its body carries base_inertia's mass, total mass") {
    const auto a = built(legged::make_model<double>());
    const auto b = built(legged_kept::make_model<double>());
    // the URDF's masses: base_inertia, face, depth_camera (fixed to the root "base", which has no
    // <inertial>), and per leg HIP, THIGH, SHANK, shank_fixed (the feet and the IMU are massless)
    const double base_inertia = 16.8, face = 0.7, depth_camera = 0.12;
    const double leg = 2.04 + 2.1 + 0.33 + 0.14;
    const double total = base_inertia + face + depth_camera + 4 * leg;
    // --keep-fixed: the root body "base" is massless, base_inertia its own body
    CHECK(b.link<0>().inertia.mass() == 0);
    CHECK(legged_kept::body_names[1] == "base_inertia");
    CHECK(b.link<1>().inertia.mass() == base_inertia);
    // default: body 0 (on the floating joint named after the root link) carries the links fixed to it
    CHECK(legged::body_names[0] == "base");
    CHECK(legged::joint_names[0] == "base");
    CHECK(std::abs(a.link<0>().inertia.mass() - (base_inertia + face + depth_camera)) < 1e-12);
    // the hip, thigh and shank bodies: the shank body carries shank_fixed
    CHECK(a.link<1>().inertia.mass() == 2.04);
    CHECK(std::abs(a.link<3>().inertia.mass() - (0.33 + 0.14)) < 1e-12);
    std::mt19937_64 rng(602);
    const ch::configuration<legged::tree> q = ctga::test::urdf::random_configuration<legged::tree>(rng);
    const ch::center_of_mass_state<double> ca = ch::center_of_mass(a, ch::forward_kinematics(a, q));
    CHECK(std::abs(ca.mass - total) < 1e-12);
    double sum = 0;
    [&]<std::size_t... I>(std::index_sequence<I...>) { ((sum += a.link<I>().inertia.mass()), ...); }(std::make_index_sequence<legged::tree::size>{});
    CHECK(std::abs(sum - total) < 1e-12);
    double sum_kept = 0;
    [&]<std::size_t... I>(std::index_sequence<I...>) { ((sum_kept += b.link<I>().inertia.mass()), ...); }(
        std::make_index_sequence<legged_kept::tree::size>{});
    CHECK(std::abs(sum_kept - total) < 1e-12);
}
#endif

#if CTGA_TEST_PART_HOLDS(3)
TEST_CASE("urdf fixtures: mobile_gripper merged (camera, imu, tcp as frames) = mobile_gripper --keep-fixed") {
    const auto a = built(mobile_gripper::make_model<double>());
    const auto b = built(mobile_gripper_kept::make_model<double>());
    compare_merged_kept(a, b, mobile_gripper::joint_names, mobile_gripper_kept::joint_names, 701, 8);
    ctga::test::urdf::print_worst("urdf fixtures: mobile_gripper merged vs kept");
}

TEST_CASE("urdf fixtures: mobile_gripper's planar base moves base_link by (x, y) and θ about the normal, every joint as the URDF writes it") {
    const auto m = built(mobile_gripper::make_model<double>());
    // the planar joint's virtual bodies are massless, named after the joint
    CHECK(mobile_gripper::body_names[0] == "base_planar_x");
    CHECK(mobile_gripper::body_names[1] == "base_planar_y");
    CHECK(mobile_gripper::body_names[2] == "base_link");
    CHECK(mobile_gripper::joint_names[2] == "base_planar");
    CHECK(m.link<0>().inertia.mass() == 0);
    CHECK(m.link<1>().inertia.mass() == 0);
    std::mt19937_64 rng(702);
    for (int n = 0; n < 8; ++n) {
        INFO("draw " << n);
        const ch::configuration<mobile_gripper::tree> q = ctga::test::urdf::random_configuration<mobile_gripper::tree>(rng);
        const ch::joint_vector<mobile_gripper::tree> qd = ctga::test::urdf::random_joint_vector<mobile_gripper::tree>(rng);
        const ch::kinematics<mobile_gripper::tree> k = ch::forward_kinematics(m, q, qd);
        const auto f = ctga::test::urdf::all_frames(m, k);
        // q = (x, y, θ, turret, shoulder, telescope, wrist, finger_left)
        const double x = q[0], y = q[1], theta = q[2];
        // base_planar: origin xyz 0 0 0.05, normal +z: base_link = origin · T(x, y, 0) · Rz(θ)
        const mat4 base = origin({0, 0, 0.05}, {0, 0, 0}) * translation(vec3(x, y, 0)) * rotation_about(vec3::UnitZ(), theta);
        CHECK(W("planar: base_link pose", pose_error(relative(f, "odom", "base_link"), base)) < 1e-12);
        // its velocity (local_world_aligned: ω and the origin's velocity, world axes): (0, 0, θ̇, ẋ, ẏ, 0)
        const ctga::screw<double> v = ch::frame_velocity(m, k, ch::frame<"base_link">, ch::reference::local_world_aligned);
        const std::array<double, 6> v_expected{0, 0, qd[2], qd[0], qd[1], 0};
        double ev = 0;
        for (std::size_t c = 0; c < 6; ++c) ev = std::max(ev, std::abs(v[c] - v_expected[c]));
        CHECK(W("planar: base_link velocity", ev) < 1e-12);
        // the fixed links (merged into base_link's body and hand's)
        CHECK(W("fixed: imu_link", pose_error(relative(f, "base_link", "imu_link"), origin({0.1, 0, 0.21}, {0, 0, pi / 2}))) < 1e-12);
        CHECK(W("fixed: camera_link", pose_error(relative(f, "base_link", "camera_link"), origin({0.3, 0, 0.18}, {0, 0.3, 0}))) < 1e-12);
        CHECK(W("fixed: tcp", pose_error(relative(f, "hand", "tcp"), origin({0, 0, 0.12}, {0, 0, 0}))) < 1e-12);
        // the arm: origin · motion(q) as the URDF's joint type and axis say
        CHECK(W("continuous +z", pose_error(relative(f, "base_link", "turret"),
                                            origin({0, 0, 0.2}, {0, 0, 0}) * rotation_about(vec3(0, 0, 1), q[3]))) < 1e-12);
        CHECK(W("revolute -y", pose_error(relative(f, "turret", "upper_arm"),
                                          origin({0, 0, 0.08}, {0, 0, 0}) * rotation_about(vec3(0, -1, 0), q[4]))) < 1e-12);
        CHECK(W("prismatic -z", pose_error(relative(f, "upper_arm", "forearm_link"),
                                           origin({0, 0, 0.4}, {0, 0, 0}) * translation(q[5] * vec3(0, 0, -1)))) < 1e-12);
        CHECK(W("revolute about (0.6, 0, 0.8)", pose_error(relative(f, "forearm_link", "hand"),
                                                           origin({0, 0, 0.3}, {0, 0, 0}) * rotation_about(vec3(0.6, 0, 0.8), q[6]))) < 1e-12);
        CHECK(W("prismatic +y", pose_error(relative(f, "hand", "finger_left"),
                                           origin({0, 0.01, 0.08}, {0, 0, 0}) * translation(q[7] * vec3(0, 1, 0)))) < 1e-12);
        // the mimic: q_right = −1 · q_left + 0.01
        CHECK(W("mimic prismatic +y", pose_error(relative(f, "hand", "finger_right"),
                                                 origin({0, -0.01, 0.08}, {0, 0, 0}) * translation((-1 * q[7] + 0.01) * vec3(0, 1, 0)))) < 1e-12);
    }
    ctga::test::urdf::print_worst("urdf fixtures: mobile_gripper joints");
}
#endif

#if CTGA_TEST_PART_HOLDS(2)
TEST_CASE("urdf fixtures: mobile_gripper's mimic finger against --mimic independent with the coupling applied by hand") {
    using A = mobile_gripper::tree;
    using B = mobile_gripper_ind::tree;
    const auto a = built(mobile_gripper::make_model<double>());
    const auto b = built(mobile_gripper_ind::make_model<double>());
    static_assert(A::size == B::size && B::nv == A::nv + 1);
    CHECK(mobile_gripper::joint_names == mobile_gripper_ind::joint_names);
    // the mimic and its master, from the tree type: finger_right follows finger_left
    constexpr std::size_t follower = mimic_body<A>;
    static_assert(follower < A::size && mimic_body<B> == B::size);
    constexpr std::size_t master = static_cast<std::size_t>(A::master[follower]);
    CHECK(mobile_gripper::joint_names[follower] == "finger_right_joint");
    CHECK(mobile_gripper::joint_names[master] == "finger_left_joint");
    // <mimic joint="finger_left_joint" multiplier="-1" offset="0.01"/>
    const double multiplier = -1, offset = 0.01;
    CHECK(a.link<follower>().joint.multiplier == multiplier);
    CHECK(a.link<follower>().joint.offset == offset);
    // G (B::nv × A::nv): v_ind = G v
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(B::nv, A::nv);
    for (std::size_t i = 0; i < A::size; ++i) {
        const auto vb = static_cast<Eigen::Index>(B::v_offset[i]);
        if (A::master[i] >= 0) {
            G(vb, static_cast<Eigen::Index>(A::v_offset[static_cast<std::size_t>(A::master[i])])) = multiplier;
        } else {
            for (std::size_t d = 0; d < A::nv_of[i]; ++d) G(vb + static_cast<Eigen::Index>(d), static_cast<Eigen::Index>(A::v_offset[i] + d)) = 1;
        }
    }
    const auto expand = [&](const ch::configuration<A>& q) {
        ch::configuration<B> out{};
        for (std::size_t i = 0; i < A::size; ++i) {
            if (A::master[i] >= 0) out[B::q_offset[i]] = multiplier * q[A::q_offset[static_cast<std::size_t>(A::master[i])]] + offset;
            else
                for (std::size_t d = 0; d < A::nq_of[i]; ++d) out[B::q_offset[i] + d] = q[A::q_offset[i] + d];
        }
        return out;
    };
    const auto times = [](const Eigen::MatrixXd& M, const ch::joint_vector<A>& x) {
        const Eigen::VectorXd y = M * eigen_vector(x);
        ch::joint_vector<B> out{};
        for (std::size_t k = 0; k < B::nv; ++k) out[k] = y[static_cast<Eigen::Index>(k)];
        return out;
    };
    std::mt19937_64 rng(801);
    for (int n = 0; n < 8; ++n) {
        INFO("draw " << n);
        const ch::configuration<A> q = ctga::test::urdf::random_configuration<A>(rng);
        const ch::joint_vector<A> qd = ctga::test::urdf::random_joint_vector<A>(rng);
        const ch::joint_vector<A> qdd = ctga::test::urdf::random_joint_vector<A>(rng);
        const ch::joint_vector<A> tau = ctga::test::urdf::random_joint_vector<A>(rng, 20);
        const ch::configuration<B> qi = expand(q);
        const ch::joint_vector<B> qdi = times(G, qd), qddi = times(G, qdd);
        const Eigen::MatrixXd Gt = G.transpose();
        CHECK(W("RNEA: tau = G^T tau_ind", rel(eigen_vector(ch::rnea(a, q, qd, qdd)), Gt * eigen_vector(ch::rnea(b, qi, qdi, qddi)))) < 1e-12);
        const Eigen::MatrixXd H = Gt * eigen_matrix(ch::crba(b, qi)) * G;
        CHECK(W("CRBA: H = G^T H_ind G", rel(eigen_matrix(ch::crba(a, q)), H)) < 1e-12);
        // forward dynamics: (G^T H_ind G) q̈ = τ − G^T C_ind, C_ind = rnea_ind(q_ind, G q̇, 0)
        const Eigen::VectorXd bias = Gt * eigen_vector(ch::rnea(b, qi, qdi, ch::joint_vector<B>{}));
        const Eigen::VectorXd qdd_ref = H.llt().solve(eigen_vector(tau) - bias);
        CHECK(W("ABA = (G^T H_ind G)^-1 (tau - G^T C_ind)", rel(eigen_vector(ch::aba(a, q, qd, tau)), qdd_ref)) < 1e-12);
        CHECK(W("ABA(RNEA(qdd)) = qdd", rel(eigen_vector(ch::aba(a, q, qd, ch::rnea(a, q, qd, qdd))), eigen_vector(qdd))) < 1e-12);
        // frames: the same poses; J = J_ind G
        const auto fa = ctga::test::urdf::all_frames(a, ch::forward_kinematics(a, q));
        const auto fb = ctga::test::urdf::all_frames(b, ch::forward_kinematics(b, qi));
        for (std::size_t k = 0; k < A::frame_count; ++k) {
            INFO("frame " << A::frame_names[k]);
            REQUIRE(B::frame_names[k] == A::frame_names[k]);
            CHECK(W("frame pose", pose_error(fa.pose[k], fb.pose[k])) < 1e-12);
            for (std::size_t r = 0; r < 3; ++r) {
                INFO(ctga::test::urdf::reference_name(r));
                CHECK(W("frame Jacobian: J = J_ind G", rel(fa.jacobian[k][r], fb.jacobian[k][r] * G)) < 1e-12);
            }
        }
    }
    ctga::test::urdf::print_worst("urdf fixtures: mobile_gripper mimic");
}

TEST_CASE("urdf fixtures: massless_subtree is -1 for every generated model and names the body once a subtree's masses are zeroed") {
    const auto ur = built(ur5e::make_model<double>());
    const auto urk = built(ur5e_kept::make_model<double>());
    const auto lg = built(legged::make_model<double>());
    const auto lgk = built(legged_kept::make_model<double>());
    const auto mg = built(mobile_gripper::make_model<double>());
    const auto mgk = built(mobile_gripper_kept::make_model<double>());
    const auto mgi = built(mobile_gripper_ind::make_model<double>());
    CHECK(ch::massless_subtree(ur) == -1);
    CHECK(ch::massless_subtree(urk) == -1);
    CHECK(ch::massless_subtree(lg) == -1);
    CHECK(ch::massless_subtree(lgk) == -1);  // its massless root body carries base_inertia
    CHECK(ch::massless_subtree(mg) == -1);   // the planar base's massless virtual bodies carry base_link
    CHECK(ch::massless_subtree(mgk) == -1);
    CHECK(ch::massless_subtree(mgi) == -1);
    const ctga::body_inertia<double> none{};
    REQUIRE(none.mass() == 0);
    {  // ur5e: wrist_3_link (tool0, flange merged in, massless) without mass: its joint, body 5
        auto m = ur;
        m.link<5>().inertia = none;
        CHECK(ch::massless_subtree(m) == 5);
    }
    {  // legged: everything below LF_HFE (the thigh, the shank with shank_fixed and the foot)
        auto m = lg;
        m.link<2>().inertia = none;
        m.link<3>().inertia = none;
        CHECK(ch::massless_subtree(m) == 2);
        m.link<1>().inertia = none;  // and the hip: LF_HAA's body
        CHECK(ch::massless_subtree(m) == 1);
    }
    {  // legged --keep-fixed: the shank and the fixed links below it (shank_fixed has mass)
        auto m = lgk;
        m.link<8>().inertia = none;
        CHECK(ch::massless_subtree(m) == -1);  // LF_shank_fixed (body 9) still carries 0.14 kg
        m.link<9>().inertia = none;
        CHECK(ch::massless_subtree(m) == 8);
    }
    {  // mobile_gripper: everything below wrist_joint (the hand with tcp, both fingers)
        auto m = mg;
        m.link<6>().inertia = none;
        m.link<7>().inertia = none;
        m.link<8>().inertia = none;
        CHECK(ch::massless_subtree(m) == 6);
    }
    {  // the mimic finger alone: a mimic joint moves (its body is the first massless moving subtree)
        auto m = mg;
        m.link<8>().inertia = none;
        CHECK(ch::massless_subtree(m) == 8);
        m = mg;
        m.link<7>().inertia = none;  // the master finger
        CHECK(ch::massless_subtree(m) == 7);
    }
}

// find_frame of every name gives its index; an unknown name, unknown_frame.
template <class Tree, std::size_t N>
void check_frame_names(const std::array<sv, N>& links) {
    static_assert(Tree::frame_count == N);
    CHECK(Tree::frame_names == links);
    for (std::size_t k = 0; k < N; ++k) {
        INFO(links[k]);
        const ctga::checked<std::size_t> f = Tree::find_frame(links[k]);
        REQUIRE(f);
        CHECK(*f == k);
    }
    const ctga::checked<std::size_t> none = Tree::find_frame("no_such_frame");
    CHECK(!none);
    CHECK(none.error == ctga::error_code::unknown_frame);
}

TEST_CASE("urdf fixtures: every URDF link is a frame, found by name, an unknown name is unknown_frame, body and joint names") {
    // the links depth first from the root, children in document order
    const std::array<sv, 11> ur5e_links{"base_link",    "base_link_inertia", "shoulder_link", "upper_arm_link",
                                        "forearm_link", "wrist_1_link",      "wrist_2_link",  "wrist_3_link",
                                        "flange",       "tool0",             "base"};
    check_frame_names<ur5e::tree>(ur5e_links);
    check_frame_names<ur5e_kept::tree>(ur5e_links);
    const std::array<sv, 26> legged_links{
        "base",     "base_inertia", "imu_link", "face",           "depth_camera", "depth_camera_optical", "LF_HIP",
        "LF_THIGH", "LF_SHANK",     "LF_shank_fixed", "LF_FOOT",  "RF_HIP",       "RF_THIGH",             "RF_SHANK",
        "RF_shank_fixed", "RF_FOOT", "LH_HIP",  "LH_THIGH",       "LH_SHANK",     "LH_shank_fixed",       "LH_FOOT",
        "RH_HIP",   "RH_THIGH",     "RH_SHANK", "RH_shank_fixed", "RH_FOOT"};
    check_frame_names<legged::tree>(legged_links);
    check_frame_names<legged_kept::tree>(legged_links);
    const std::array<sv, 11> gripper_links{"odom",         "base_link", "imu_link",    "camera_link",  "turret", "upper_arm",
                                           "forearm_link", "hand",      "finger_left", "finger_right", "tcp"};
    check_frame_names<mobile_gripper::tree>(gripper_links);
    check_frame_names<mobile_gripper_kept::tree>(gripper_links);
    check_frame_names<mobile_gripper_ind::tree>(gripper_links);

    const std::array<sv, 6> ur5e_bodies{"shoulder_link", "upper_arm_link", "forearm_link", "wrist_1_link", "wrist_2_link", "wrist_3_link"};
    const std::array<sv, 6> ur5e_joints{"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                        "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint"};
    CHECK(ur5e::body_names == ur5e_bodies);
    CHECK(ur5e::joint_names == ur5e_joints);
    // the floating joint is named after the root link
    const std::array<sv, 13> legged_joints{"base",   "LF_HAA", "LF_HFE", "LF_KFE", "RF_HAA", "RF_HFE", "RF_KFE",
                                           "LH_HAA", "LH_HFE", "LH_KFE", "RH_HAA", "RH_HFE", "RH_KFE"};
    CHECK(legged::joint_names == legged_joints);
    const std::array<sv, 9> gripper_joints{"base_planar_x",   "base_planar_y", "base_planar",       "turret_joint",      "shoulder_joint",
                                           "telescope_joint", "wrist_joint",   "finger_left_joint", "finger_right_joint"};
    CHECK(mobile_gripper::joint_names == gripper_joints);
}
#endif

#if CTGA_TEST_PART_HOLDS(6)
namespace {
// Every named frame's world pose (poses only: one frame_pose per frame).
template <class Tree>
std::array<ctga::motor_map<double>, Tree::frame_count> frame_poses(const ch::model<Tree>& m, const ch::kinematics<Tree>& k) {
    std::array<ctga::motor_map<double>, Tree::frame_count> out;
    [&]<std::size_t... K>(std::index_sequence<K...>) {
        ((out[K] = ch::frame_pose(m, k, ch::frame_at<K>)), ...);
    }(std::make_index_sequence<Tree::frame_count>{});
    return out;
}

// limited_gripper.urdf's bodies: gripper_free (--massless armature=0.01) has them all, gripper_locked
// (--massless lock --lock elbow=0.7) the three free joints; the locked values.
using free_tree = gripper_free::tree;
using locked_tree = gripper_locked::tree;
static_assert(free_tree::size == 7 && free_tree::nv == 6 && free_tree::nq == 6 && free_tree::has_mimic);
static_assert(locked_tree::size == 3 && locked_tree::nv == 3 && !locked_tree::has_mimic);
static_assert(free_tree::frame_count == 10 && locked_tree::frame_count == 10);
static_assert(std::is_empty_v<decltype(ch::model<free_tree>{}.link<5>().armature)>);  // the mimic finger: none
}  // namespace

TEST_CASE("urdf fixtures: limited_gripper --massless lock --lock elbow=0.7 is the free gripper held at the locked values (frames, RNEA)") {
    const auto f = built(gripper_free::make_model<double>());
    const auto l = built(gripper_locked::make_model<double>());
    CHECK(gripper_locked::joint_names == std::array<sv, 3>{"shoulder", "wrist", "spinner"});
    CHECK(locked_tree::frame_names == free_tree::frame_names);
    // the free model's velocity number of each locked model's coordinate, by joint name
    std::array<std::size_t, locked_tree::nv> in_free{};
    for (std::size_t i = 0; i < locked_tree::size; ++i) {
        std::size_t b = 0;
        while (gripper_free::joint_names[b] != gripper_locked::joint_names[i]) ++b;
        in_free[locked_tree::v_offset[i]] = free_tree::v_offset[b];
    }
    // the locked joints' values in the free model (finger_right, the mimic, follows: −1 · 0 + 0.01)
    const std::array<std::pair<sv, double>, 3> locked{{{"elbow", 0.7}, {"finger_left", 0.0}, {"thumb", 0.2}}};
    std::mt19937_64 rng(901);
    for (int n = 0; n < 8; ++n) {
        INFO("draw " << n);
        const ch::configuration<locked_tree> q = ctga::test::urdf::random_configuration<locked_tree>(rng);
        const ch::joint_vector<locked_tree> qd = ctga::test::urdf::random_joint_vector<locked_tree>(rng);
        const ch::joint_vector<locked_tree> qdd = ctga::test::urdf::random_joint_vector<locked_tree>(rng);
        ch::configuration<free_tree> qf{};
        ch::joint_vector<free_tree> qdf{}, qddf{};
        for (std::size_t k = 0; k < locked_tree::nv; ++k) qf[in_free[k]] = q[k], qdf[in_free[k]] = qd[k], qddf[in_free[k]] = qdd[k];
        for (const auto& [joint, value] : locked)
            for (std::size_t b = 0; b < free_tree::size; ++b)
                if (gripper_free::joint_names[b] == joint) qf[free_tree::q_offset[b]] = value;
        const auto pl = frame_poses(l, ch::forward_kinematics(l, q));
        const auto pf = frame_poses(f, ch::forward_kinematics(f, qf));
        for (std::size_t k = 0; k < locked_tree::frame_count; ++k) {
            INFO("frame " << locked_tree::frame_names[k]);
            CHECK(W("frame pose, locked vs free at the locked values", pose_error(pl[k], pf[k])) < 1e-12);
        }
        // the free model's rows of the free coordinates, the locked ones at rest (q̇ = q̈ = 0): for
        // random q̈ this is H's block too (τ = H q̈ + C), so CRBA is not instantiated here
        const Eigen::VectorXd tl = eigen_vector(ch::rnea(l, q, qd, qdd)), tf = eigen_vector(ch::rnea(f, qf, qdf, qddf));
        Eigen::VectorXd t_rows(3);
        for (std::size_t r = 0; r < 3; ++r) t_rows[static_cast<Eigen::Index>(r)] = tf[static_cast<Eigen::Index>(in_free[r])];
        CHECK(W("RNEA, locked vs the free rows", rel(tl, t_rows)) < 1e-12);
    }
    ctga::test::urdf::print_worst("urdf fixtures: limited_gripper locked vs free");
}

TEST_CASE("urdf fixtures: limited_gripper's make_limits are the URDF's numbers, its armatures are in the model, its mass-0 tensors in the inertia") {
    constexpr double inf = std::numeric_limits<double>::infinity();
    // velocity numbers: shoulder, elbow, wrist (continuous: no bounds), spinner (continuous, no
    // <limit>, friction only), finger_left, thumb; the mimic finger_right has none
    const auto lim = gripper_free::make_limits<double>();
    REQUIRE(lim);
    CHECK(lim->lower == std::array<double, 6>{-2.5, -0.3, -inf, -inf, 0.0, 0.2});
    CHECK(lim->upper == std::array<double, 6>{2.5, 2.0, inf, inf, 0.04, 1.0});
    CHECK(lim->velocity == std::array<double, 6>{3.0, 4.0, 6.0, inf, 0.1, 1.0});
    CHECK(lim->effort == std::array<double, 6>{80.0, 40.0, 10.0, inf, 20.0, 5.0});
    CHECK(lim->damping == std::array<double, 6>{0.5, 0.1, 0, 0, 0, 0});
    CHECK(lim->friction == std::array<double, 6>{0.2, 0, 0, 0.01, 0, 0});
    CHECK(free_tree::v_offset[6] == 5);  // thumb, body 6
    const auto lim_locked = gripper_locked::make_limits<float>();  // shoulder, wrist, spinner
    REQUIRE(lim_locked);
    CHECK(lim_locked->lower == std::array<float, 3>{-2.5f, -std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()});
    CHECK(lim_locked->friction == std::array<float, 3>{0.2f, 0, 0.01f});
    // the armatures of the joints with no inertia below them, and massless_subtree counts them
    auto f = built(gripper_free::make_model<double>());
    CHECK(f.link<4>().armature == 0.01);  // finger_left
    CHECK(f.link<6>().armature == 0.01);  // thumb
    static_assert(ch::has_armature<free_tree::joint_at<4>> && ch::has_armature<free_tree::joint_at<6>>);
    static_assert(std::is_same_v<free_tree::joint_at<4>, ch::aligned<ch::with_armature<ch::prismatic_y>>>);
    static_assert(!ch::has_armature<free_tree::joint_at<0>>);  // the others have none in their type
    CHECK(ch::massless_subtree(f) == -1);
    f.link<6>().armature = 0;
    CHECK(ch::massless_subtree(f) == 6);
    f.link<6>().armature = 0.01;
    f.link<4>().armature = 0;
    CHECK(ch::massless_subtree(f) == 4);
    f.link<4>().armature = 0.01;
    // the rotor: mass 0, its tensor only (spinner turns about x: the rotational inertia loads it)
    CHECK(f.link<3>().inertia.mass() == 0);
    CHECK(f.link<3>().inertia.inertia_o() == ctga::mat3<double>{{{2e-5, 0, 0}, {0, 1e-5, 0}, {0, 0, 1e-5}}});
    f.link<3>().inertia = ctga::body_inertia<double>{};
    CHECK(ch::massless_subtree(f) == 3);
    // the hand's body: the hand (0.5 kg at (0, 0, 0.04)) and the mass-0 sensor's tensor turned by
    // its yaw 0.7, without a parallel-axis term
    const auto g = built(gripper_free::make_model<double>());
    const mat3 R = rpy_rotation({0, 0, 0.7});
    mat3 Is;
    Is << 1e-4, 1e-5, 0, 1e-5, 2e-4, 0, 0, 0, 2.5e-4;
    const vec3 c(0, 0, 0.04);
    const mat3 Ih = vec3(4e-4, 3e-4, 2e-4).asDiagonal();
    const mat3 expected = Ih + 0.5 * (c.squaredNorm() * mat3::Identity() - c * c.transpose()) + R * Is * R.transpose();
    const ctga::mat3<double> io = g.link<2>().inertia.inertia_o();
    double e = 0;
    for (Eigen::Index i = 0; i < 3; ++i)
        for (Eigen::Index j = 0; j < 3; ++j) e = std::max(e, std::abs(io[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] - expected(i, j)));
    CHECK(e < 1e-17);
    CHECK(g.link<2>().inertia.mass() == 0.5);
}
#endif
