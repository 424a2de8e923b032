// PARTS: 4
// Issue 27's kinematic-tree features against the independent Featherstone reference
// (support/featherstone.hpp, support/featherstone_frames.hpp; plain Eigen, no ctga):
//
//   named frames (fixed_frame, chains::frame<"name">, frame_at<K>, find_frame, visit_frame) and
//   body<I>: frame_pose, frame_velocity, frame_acceleration, frame_classical_acceleration,
//   frame_jacobian (from q and from the kinematics), frame_jacobian_time_variation, each in
//   reference::local, world and local_world_aligned, a frame on the world included;
//   mimic joints (a gripper's finger following the other finger, another branch; a link
//   following its own ancestor): rnea, crba, aba (with and without external wrenches) against
//   rnea_mimic, crba_mimic, aba_mimic, the Jacobians against jacobian_mimic and J̇ against the
//   expanded model's J̇ times G (Ġ = 0);
//   joints about −x, −y and along −z (revolute<axis::minus_x>, <axis::minus_y>,
//   prismatic<axis::minus_z>) in the trees, and in a 3-body tree without mimic joints through
//   rnea and aba's articulated-body pass (the trees with mimic joints solve by Cholesky);
//   center_of_mass, subtree_centers_of_mass, center_of_mass_jacobian, centroidal_momentum and
//   centroidal_momentum_matrix;
//   the floating base's numbers in Pinocchio's / ROS's layout (floating_base_configuration,
//   floating_base_pose, floating_base_velocity, linear_angular);
//   refused inputs (massless_subtree, find_frame's unknown_frame, a NaN coupling, the mass checks).
//
// The trees are written by hand (below): a mobile manipulator with a parallel gripper on a
// floating base (8 bodies, 8 named frames) and a fixed-base arm with a second root (8 bodies,
// 7 named frames). Their parameters (placements with random rotations, masses, centres of mass,
// full inertia tensors, the run-time axes, frame placements) and states are drawn from fixed
// seeds; the same numbers go to ctga and to the reference. The reference models the mimic joints
// by its own couplings (q_follower = r q_leader + o) on the full model; its floating joint reads
// (x, y, z, qw, qx, qy, qz), ctga's the 8 motor coefficients (converted as chains_test.cpp does).
//
// Error measure: rel(x, y) = max_k |x_k − y_k| / max(1, max_k |y_k|), y the reference.
// Tolerances: 1e-12 for every quantity both sides compute by direct formulas (a few hundred flops
// on numbers of size ≤ ~30; worst seen ~1e-14), the identities v = J q̇, J q̈ + J̇ q̇ = acceleration
// and the floating-base round trip included; 1e-11 for forward dynamics (a Cholesky solve or ABA
// on each side: the error grows with the mass matrix's condition number; worst seen ~2e-14).
// Exact (0) where both numbers come from the same code (a frame by name and by index). The worst
// value of each measure is printed at the end of each test case.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include <ctga/chains/algorithms.hpp>

#include "support/catch.hpp"
#include "support/worst.hpp"
#include "support/featherstone.hpp"
#include "support/featherstone_frames.hpp"
#include "support/parts.hpp"
#include "support/random_floating_base.hpp"
#include "support/random_structure.hpp"
#include "support/random_tree.hpp"
#include "support/relative_error.hpp"

namespace {

namespace ch = ctga::chains;
namespace fs = ctga::test::featherstone;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using ctga::test::rel;

constexpr double tol = 1e-12;           // direct formulas on both sides
constexpr double tol_solve = 1e-11;     // forward dynamics (a solve on each side)

// ---- the trees -----------------------------------------------------------------------------

// A mobile manipulator on a floating base: a sensor mast on a fixed joint, an arm (yaw, pitch
// about −y, a telescope along −z, a wrist about a non-coordinate axis) and a parallel gripper
// whose right finger follows the left one (a sibling: another branch), q_7 = −1.3 q_6 + 0.02.
using mobile_gripper = ch::tree<ch::link<-1, ch::floating>,                     // 0 base
                                ch::link<0, ch::fixed>,                         // 1 sensor mast
                                ch::link<0, ch::revolute_z>,                    // 2 shoulder yaw
                                ch::link<2, ch::revolute<ch::axis::minus_y>>,   // 3 shoulder pitch
                                ch::link<3, ch::prismatic<ch::axis::minus_z>>,  // 4 telescope
                                ch::link<4, ch::revolute_about>,                // 5 wrist
                                ch::link<5, ch::prismatic_x>,                   // 6 left finger
                                ch::link<5, ch::mimic<ch::prismatic_x, 6>>,     // 7 right finger
                                ch::fixed_frame<"imu", 0>,                      // frames: on the base,
                                ch::fixed_frame<"camera", 1>,                   //   on the fixed link,
                                ch::fixed_frame<"tool", 5>,                     //   three on the wrist,
                                ch::fixed_frame<"flange", 5>,
                                ch::fixed_frame<"grasp", 5>,
                                ch::fixed_frame<"tip_left", 6>,                 //   on each finger,
                                ch::fixed_frame<"tip_right", 7>,
                                ch::fixed_frame<"map", -1>>;                    //   on the world
constexpr ch::coupling<double> finger_coupling{-1.3, 0.02};

// A fixed-base arm whose link 4 turns about a run-time axis following its ancestor, the
// shoulder (q_4 = 0.7 q_1 − 0.1: a four-bar's coupled link), a second branch off the shoulder
// and a second root (a conveyor on the world).
using coupled_arm = ch::tree<ch::link<-1, ch::revolute_z>,                    // 0 base yaw
                             ch::link<0, ch::revolute<ch::axis::minus_y>>,    // 1 shoulder
                             ch::link<1, ch::prismatic_x>,                    // 2 slide
                             ch::link<2, ch::revolute_about>,                 // 3 elbow
                             ch::link<3, ch::mimic<ch::revolute_about, 1>>,   // 4 coupled link
                             ch::link<4, ch::prismatic<ch::axis::minus_z>>,   // 5 plunger
                             ch::link<1, ch::revolute<ch::axis::minus_x>>,    // 6 side branch
                             ch::link<-1, ch::prismatic_along>,               // 7 conveyor (a root)
                             ch::fixed_frame<"base", 0>,
                             ch::fixed_frame<"elbow_a", 3>,                   // two on the elbow
                             ch::fixed_frame<"elbow_b", 3>,
                             ch::fixed_frame<"coupled", 4>,
                             ch::fixed_frame<"tcp", 5>,
                             ch::fixed_frame<"table", -1>,
                             ch::fixed_frame<"belt", 7>>;
constexpr ch::coupling<double> arm_coupling{0.7, -0.1};

// Two arms on a floating base, each a parallel gripper whose right finger follows its left one,
// and a mast: 20 bodies, more steps than runs make small, so the passes visit them by kind
// (runs.hpp), mimic joints among them.
// The mast is aligned (ch::aligned: its placements translations), the left arm turned (ch::turned:
// its placements' rotations signed permutations, a mimic finger among them), the right arm neither.
template <class J>
using al = ch::aligned<J>;
template <class J>
using tu = ch::turned<ch::turn{ch::axis::z, ch::axis::x, ch::axis::y}, J>;
template <class J>
using tu2 = ch::turned<ch::turn{ch::axis::minus_y, ch::axis::x, ch::axis::z}, J>;
using two_grippers = ch::tree<ch::link<-1, ch::floating>,                                               //  0 base
                              ch::link<0, tu<ch::revolute_z>>, ch::link<1, tu2<ch::revolute<ch::axis::minus_y>>>,  //  1 left arm
                              ch::link<2, tu<ch::revolute_x>>, ch::link<3, al<ch::revolute_y>>, ch::link<4, tu2<ch::revolute_about>>,
                              ch::link<5, tu<ch::prismatic_x>>, ch::link<5, ch::mimic<tu2<ch::prismatic_x>, 6>>,  //  6, 7 fingers
                              ch::link<0, ch::fixed>,                                                   //  8 torso
                              ch::link<8, ch::revolute_z>, ch::link<9, ch::revolute<ch::axis::minus_y>>,  //  9 right arm
                              ch::link<10, ch::revolute_x>, ch::link<11, ch::revolute_y>, ch::link<12, ch::revolute_about>,
                              ch::link<13, ch::prismatic_x>, ch::link<13, ch::mimic<ch::prismatic_x, 14>>,  // 14, 15 fingers
                              ch::link<0, al<ch::prismatic<ch::axis::minus_z>>>, ch::link<16, al<ch::revolute_z>>,  // 16 mast
                              ch::link<17, al<ch::revolute_y>>, ch::link<18, al<ch::revolute_x>>>;
static_assert(ch::run_detail::plan<two_grippers>::at(0).by_kind, "two_grippers is visited by kind");

// Joints about −x, −y and along −z without mimic joints: forward dynamics by the articulated-body
// pass (the trees above, with their mimic joints, solve it by Cholesky).
using minus_axes = ch::tree<ch::link<-1, ch::revolute<ch::axis::minus_x>>,
                            ch::link<0, ch::prismatic<ch::axis::minus_z>>,
                            ch::link<1, ch::revolute<ch::axis::minus_y>>>;

// ---- the reference's joint for ctga's ------------------------------------------------------

template <class J>
struct ref_joint;
template <ch::axis A>
struct ref_joint<ch::revolute<A>> {
    static constexpr fs::joint_kind kind = fs::joint_kind::revolute;
    static constexpr int axis = static_cast<int>(A);  // the axis enum's number (−1 below: a run-time axis)
};
template <ch::axis A>
struct ref_joint<ch::prismatic<A>> {
    static constexpr fs::joint_kind kind = fs::joint_kind::prismatic;
    static constexpr int axis = static_cast<int>(A);
};
template <>
struct ref_joint<ch::revolute_about> {
    static constexpr fs::joint_kind kind = fs::joint_kind::revolute;
    static constexpr int axis = -1;
};
template <>
struct ref_joint<ch::prismatic_along> {
    static constexpr fs::joint_kind kind = fs::joint_kind::prismatic;
    static constexpr int axis = -1;
};
template <>
struct ref_joint<ch::fixed> {
    static constexpr fs::joint_kind kind = fs::joint_kind::fixed;
    static constexpr int axis = 0;
};
template <>
struct ref_joint<ch::floating> {
    static constexpr fs::joint_kind kind = fs::joint_kind::floating;
    static constexpr int axis = 0;
};
template <class J, std::size_t M>
struct ref_joint<ch::mimic<J, M>> : ref_joint<J> {};
template <ch::turn P, class J>
struct ref_joint<ch::turned<P, J>> : ref_joint<J> {};

// axis::x, y, z, minus_x, minus_y, minus_z as a unit vector
inline fs::vec3 axis_vector(int a) { return (a < 3 ? 1.0 : -1.0) * fs::vec3::Unit(a % 3); }

using ctga::test::motor_of;
inline ctga::vec3<double> v3(const fs::vec3& x) { return {x[0], x[1], x[2]}; }
inline ctga::mat3<double> m3(const fs::mat3& X) {
    return {{{X(0, 0), X(0, 1), X(0, 2)}, {X(1, 0), X(1, 1), X(1, 2)}, {X(2, 0), X(2, 1), X(2, 2)}}};
}

// ---- ctga's numbers as Eigen matrices ------------------------------------------------------

template <class V>
VectorXd vec(const V& x, std::size_t n) {
    VectorXd out(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) out[static_cast<Eigen::Index>(i)] = x[i];
    return out;
}
// columns of screws / vectors (a Jacobian): M(r, c) = J[c][r]
template <class C>
MatrixXd columns(const C& J, std::size_t rows) {
    MatrixXd out(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(J.size()));
    for (std::size_t c = 0; c < J.size(); ++c)
        for (std::size_t r = 0; r < rows; ++r) out(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = J[c][r];
    return out;
}
template <class M>
MatrixXd rows(const M& H, std::size_t n) {
    MatrixXd out(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (std::size_t r = 0; r < n; ++r)
        for (std::size_t c = 0; c < n; ++c) out(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = H[r][c];
    return out;
}
inline MatrixXd mat(const ctga::mat3<double>& R) { return rows(R, 3); }


using ctga::test::worst;

constexpr ch::reference refs[] = {ch::reference::local, ch::reference::world, ch::reference::local_world_aligned};
inline fs::reference ref_of(ch::reference r) {
    switch (r) {
        case ch::reference::local: return fs::reference::local;
        case ch::reference::world: return fs::reference::world;
        case ch::reference::local_world_aligned: return fs::reference::local_world_aligned;
    }
    return fs::reference::local;
}
inline const char* name_of(ch::reference r) {
    switch (r) {
        case ch::reference::local: return "local";
        case ch::reference::world: return "world";
        case ch::reference::local_world_aligned: return "lwa";
    }
    return "?";
}

// ---- one draw: a model and a state, given to both ------------------------------------------

template <class Tree>
struct draw {
    ch::model<Tree> m;
    fs::model ref;                            // the full model (the followers as ordinary joints)
    std::vector<fs::mimic_coupling> couplings;
    std::vector<fs::frame> frames;            // frame k: ctga's named frame k
    ch::configuration<Tree> q{};
    ch::joint_vector<Tree> qd{}, qdd{}, tau{};
    ch::body_wrenches<Tree> f{};
    VectorXd q_r, qd_r, qdd_r, tau_r;         // the reference's reduced coordinates
    std::vector<fs::vec6> f_ref;
    MatrixXd G;                               // v = G v_r
    VectorXd q_full, qd_full, qdd_full;       // the full model's state
};

template <class Tree>
draw<Tree> make_draw(std::mt19937_64& rng, const ch::coupling<double>& coupling) {
    draw<Tree> d;
    d.ref.gravity = fs::vec3(fs::uniform(rng, -2, 2), fs::uniform(rng, -2, 2), -9.81);
    d.m.gravity = v3(d.ref.gravity);
    d.ref.bodies.resize(Tree::size);
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            using J = typename Tree::template joint_at<I>;
            fs::body& b = d.ref.bodies[I];
            b.parent = Tree::parent[I];
            b.kind = ref_joint<J>::kind;
            b.axis = ref_joint<J>::axis >= 0 ? axis_vector(ref_joint<J>::axis) : fs::random_unit_vec3(rng);
            b.rotation = ch::is_turned<J> ? ctga::test::turn_rotation(ch::placement_turn<J>) : fs::random_rotation(rng);
            b.translation = fs::uniform_vec3(rng, 0.5);
            b.mass = fs::uniform(rng, 0.5, 2.0);
            b.com = fs::uniform_vec3(rng, 0.3);
            b.inertia_c = fs::random_inertia_c(rng, b.mass, 0.05, 0.3);  // a full tensor: random principal axes
            const auto mass = ctga::make_mass_properties(b.mass, v3(b.com), m3(b.inertia_c));
            const ctga::motor<double> X = motor_of(b.rotation, b.translation);
            const auto link = [&] {
                if constexpr (ch::is_mimic<J> && ch::has_run_time_axis<J>) return ch::make_link<J>(X, mass, coupling, v3(b.axis));
                else if constexpr (ch::is_mimic<J>) return ch::make_link<J>(X, mass, coupling);
                else if constexpr (ch::has_run_time_axis<J>) return ch::make_link<J>(X, mass, v3(b.axis));
                else return ch::make_link<J>(X, mass);
            }();
            REQUIRE(link);
            d.m.template link<I>() = *link;
            if constexpr (ch::is_mimic<J>)
                d.couplings.push_back(fs::mimic_coupling{static_cast<int>(I), static_cast<int>(J::master), coupling.multiplier,
                                                         coupling.offset});
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    for (std::size_t k = 0; k < Tree::frame_count; ++k) {
        const fs::frame fr{Tree::frame_body[k], fs::random_rotation(rng), fs::uniform_vec3(rng, 0.4)};
        const auto P = ch::make_frame(motor_of(fr.rotation, fr.translation));
        REQUIRE(P);
        d.m.frames[k] = *P;
        d.frames.push_back(fr);
    }
    // q: ctga's holds the independent joints' numbers in body order, as the reference's q_r;
    // a floating joint's are the motor's 8 coefficients for the reference's (x, y, z, qw, qx, qy, qz)
    d.q_r.resize(fs::mimic_nq(d.ref, d.couplings));
    Eigen::Index qr = 0;
    for (std::size_t i = 0; i < Tree::size; ++i) {
        const fs::body& b = d.ref.bodies[i];
        const std::size_t qo = Tree::q_offset[i];
        if (Tree::master[i] >= 0 || b.kind == fs::joint_kind::fixed) continue;
        if (b.kind == fs::joint_kind::floating) {
            ctga::test::random_floating_base(rng, 1.0, d.q, qo, d.q_r, qr);
            qr += 7;
        } else {
            const double x = b.kind == fs::joint_kind::revolute ? fs::uniform(rng, -3.1, 3.1) : fs::uniform(rng, -0.5, 0.5);
            d.q[qo] = d.q_r[qr++] = x;
        }
    }
    REQUIRE(qr == d.q_r.size());
    REQUIRE(static_cast<int>(Tree::nv) == fs::mimic_nv(d.ref, d.couplings));
    d.qd_r.resize(Tree::nv);
    d.qdd_r.resize(Tree::nv);
    d.tau_r.resize(Tree::nv);
    for (std::size_t k = 0; k < Tree::nv; ++k) {
        const auto e = static_cast<Eigen::Index>(k);
        d.qd[k] = d.qd_r[e] = fs::uniform(rng, -2, 2);
        d.qdd[k] = d.qdd_r[e] = fs::uniform(rng, -2, 2);
        d.tau[k] = d.tau_r[e] = fs::uniform(rng, -5, 5);
    }
    d.f_ref.resize(Tree::size);
    for (std::size_t i = 0; i < Tree::size; ++i)
        for (std::size_t c = 0; c < 6; ++c) d.f[i][c] = d.f_ref[i][static_cast<Eigen::Index>(c)] = fs::uniform(rng, -1, 1);
    d.G = fs::mimic_matrix(d.ref, d.couplings);
    d.q_full = fs::expand_q(d.ref, d.couplings, d.q_r);
    d.qd_full = d.G * d.qd_r;
    d.qdd_full = d.G * d.qdd_r;
    return d;
}

// ---- a frame's motion and Jacobians --------------------------------------------------------

// ctga's numbers for one frame at one state: computed in a template on the frame (the only code
// each frame instantiates), compared by compare_frame below (one instantiation per tree).
template <class Tree>
struct frame_numbers {
    ctga::motor_map<double> pose, pose_from_positions;
    std::array<ctga::screw<double>, 3> velocity, acceleration;       // per reference (refs' order)
    std::array<ctga::vec3<double>, 3> classical;
    std::array<ch::jacobian_matrix<Tree>, 3> J, J_from_kinematics, J_dot;
};

template <class Tree, class F>
frame_numbers<Tree> numbers_of(const draw<Tree>& d, const ch::kinematics<Tree>& k_pos, const ch::kinematics<Tree>& k, F f) {
    frame_numbers<Tree> x;
    x.pose = ch::frame_pose(d.m, k, f);
    x.pose_from_positions = ch::frame_pose(d.m, k_pos, f);
    for (std::size_t i = 0; i < 3; ++i) {
        const ch::reference r = refs[i];
        x.velocity[i] = ch::frame_velocity(d.m, k, f, r);
        x.acceleration[i] = ch::frame_acceleration(d.m, k, f, r);
        x.classical[i] = ch::frame_classical_acceleration(d.m, k, f, r);
        x.J[i] = ch::frame_jacobian(d.m, d.q, f, r);
        x.J_from_kinematics[i] = ch::frame_jacobian(d.m, k_pos, f, r);
        x.J_dot[i] = ch::frame_jacobian_time_variation(d.m, k, f, r);
    }
    return x;
}

// ctga's numbers x for a frame = fr (the reference's) at draw d's state.
template <class Tree>
void compare_frame(const draw<Tree>& d, const frame_numbers<Tree>& x, const fs::frame& fr, worst& w, const std::string& label) {
    INFO("frame " << label);
    const fs::pose P = fs::frame_pose(d.ref, d.q_full, fr);
    CHECK(w("frame_pose R", rel(mat(x.pose.R), P.rotation)) < tol);
    CHECK(w("frame_pose t", rel(vec(x.pose.t, 3), P.origin)) < tol);
    CHECK(rel(mat(x.pose_from_positions.R), mat(x.pose.R)) == 0);  // the same from the poses only
    CHECK(rel(vec(x.pose_from_positions.t, 3), vec(x.pose.t, 3)) == 0);
    for (std::size_t i = 0; i < 3; ++i) {
        const ch::reference r = refs[i];
        INFO("reference " << name_of(r));
        const std::string rn = std::string(" ") + name_of(r);
        const fs::reference rr = ref_of(r);
        const VectorXd v = vec(x.velocity[i], 6);
        const VectorXd a_ref = fs::frame_acceleration(d.ref, d.q_full, d.qd_full, d.qdd_full, fr, rr);
        CHECK(w("frame_velocity" + rn, rel(v, fs::frame_velocity(d.ref, d.q_full, d.qd_full, fr, rr))) < tol);
        CHECK(w("frame_acceleration" + rn, rel(vec(x.acceleration[i], 6), a_ref)) < tol);
        CHECK(w("frame_classical_acceleration" + rn,
                rel(vec(x.classical[i], 3), fs::frame_classical_acceleration(d.ref, d.q_full, d.qd_full, d.qdd_full, fr, rr))) < tol);
        // J and J̇ of the reduced coordinates: the reference's J_mimic = J G and J̇ G
        const MatrixXd J_ref = fs::jacobian_mimic(d.ref, d.couplings, d.q_r, fr, rr);
        const MatrixXd J = columns(x.J[i], 6);
        const MatrixXd Jd = columns(x.J_dot[i], 6);
        const MatrixXd Jd_ref = fs::frame_jacobian_dot(d.ref, d.q_full, d.qd_full, fr, rr).lazyProduct(d.G);
        CHECK(w("frame_jacobian (q)" + rn, rel(J, J_ref)) < tol);
        CHECK(w("frame_jacobian (kinematics)" + rn, rel(columns(x.J_from_kinematics[i], 6), J_ref)) < tol);
        CHECK(w("frame_jacobian_time_variation" + rn, rel(Jd, Jd_ref)) < tol);
        // v = J q̇; J q̈ + J̇ q̇ = the spatial acceleration (local, world), (ω̇, p̈) in world axes (lwa)
        CHECK(w("J qd = velocity" + rn, rel(J * d.qd_r, v)) < tol);
        VectorXd expected = a_ref;
        if (r == ch::reference::local_world_aligned)
            expected.tail<3>() = fs::frame_classical_acceleration(d.ref, d.q_full, d.qd_full, d.qdd_full, fr, fs::reference::world);
        CHECK(w("J qdd + Jdot qd = acceleration" + rn, rel(J * d.qdd_r + Jd * d.qd_r, expected)) < tol);
    }
}

template <class Tree, class F>
void check_frame(const draw<Tree>& d, const ch::kinematics<Tree>& k_pos, const ch::kinematics<Tree>& k, F f,
                 const fs::frame& fr, worst& w, const std::string& label) {
    compare_frame(d, numbers_of(d, k_pos, k, f), fr, w, label);
}

// Every named frame through its run-time name (find_frame, visit_frame: frame_at<K>), the own
// frames of bodies Bodies..., and the frame named `Name` in the source (the same numbers as
// through find_frame). (Each frame instantiates its own code: the bodies are a few, the named
// frames cover the others.)
template <ctga::fixed_string Name, std::size_t... Bodies, class Tree>
void check_frames(const draw<Tree>& d, worst& w) {
    const ch::kinematics<Tree> k_pos = ch::forward_kinematics(d.m, d.q);
    const ch::kinematics<Tree> k = ch::forward_kinematics(d.m, d.q, d.qd, d.qdd);
    for (std::size_t n = 0; n < Tree::frame_count; ++n) {
        const std::string name(Tree::frame_names[n]);
        const ctga::checked<std::size_t> found = Tree::find_frame(name);
        REQUIRE(found);
        REQUIRE(*found == n);
        ch::visit_frame<Tree>(*found, [&](auto f) { check_frame(d, k_pos, k, f, d.frames[n], w, name); });
    }
    (check_frame(d, k_pos, k, ch::body<Bodies>, fs::frame{static_cast<int>(Bodies), fs::mat3::Identity(), fs::vec3::Zero()}, w,
                 "body<" + std::to_string(Bodies) + ">"),
     ...);
    // by name in the source
    constexpr std::size_t K = ch::frame_index<Tree, Name>();
    static_assert(Tree::frame_index_of(Name.view()) == K);
    REQUIRE(*Tree::find_frame(Name.view()) == K);
    const frame_numbers<Tree> by_name = numbers_of(d, k_pos, k, ch::frame<Name>);
    compare_frame(d, by_name, d.frames[K], w, std::string(Name.view()) + " (by name)");
    // the same numbers, bit for bit, as through frame_at<K>
    const frame_numbers<Tree> by_index = numbers_of(d, k_pos, k, ch::frame_at<K>);
    CHECK(rel(mat(by_name.pose.R), mat(by_index.pose.R)) == 0);
    CHECK(rel(vec(by_name.pose.t, 3), vec(by_index.pose.t, 3)) == 0);
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(rel(vec(by_name.velocity[i], 6), vec(by_index.velocity[i], 6)) == 0);
        CHECK(rel(vec(by_name.acceleration[i], 6), vec(by_index.acceleration[i], 6)) == 0);
        CHECK(rel(vec(by_name.classical[i], 3), vec(by_index.classical[i], 3)) == 0);
        CHECK(rel(columns(by_name.J[i], 6), columns(by_index.J[i], 6)) == 0);
        CHECK(rel(columns(by_name.J_dot[i], 6), columns(by_index.J_dot[i], 6)) == 0);
    }
}

// A frame on the world does not move: its pose is its placement, its motion and Jacobian zero.
template <ctga::fixed_string Name, class Tree>
void check_world_frame(const draw<Tree>& d) {
    constexpr std::size_t K = ch::frame_index<Tree, Name>();
    static_assert(Tree::frame_body[K] == -1);
    const ch::kinematics<Tree> k = ch::forward_kinematics(d.m, d.q, d.qd, d.qdd);
    const auto W = ch::frame_pose(d.m, k, ch::frame<Name>);
    CHECK(rel(mat(W.R), d.frames[K].rotation) < tol);
    CHECK(rel(vec(W.t, 3), d.frames[K].translation) < tol);
    for (const ch::reference r : refs) {
        CHECK(vec(ch::frame_velocity(d.m, k, ch::frame<Name>, r), 6).isZero(0));
        CHECK(vec(ch::frame_acceleration(d.m, k, ch::frame<Name>, r), 6).isZero(0));
        CHECK(vec(ch::frame_classical_acceleration(d.m, k, ch::frame<Name>, r), 3).isZero(0));
        CHECK(columns(ch::frame_jacobian(d.m, d.q, ch::frame<Name>, r), 6).isZero(0));
        CHECK(columns(ch::frame_jacobian_time_variation(d.m, k, ch::frame<Name>, r), 6).isZero(0));
    }
}

// ---- dynamics, centre of mass, centroidal momentum -----------------------------------------

template <class Tree>
void check_dynamics(const draw<Tree>& d, worst& w) {
    CHECK(w("rnea", rel(vec(ch::rnea(d.m, d.q, d.qd, d.qdd), Tree::nv),
                        fs::rnea_mimic(d.ref, d.couplings, d.q_r, d.qd_r, d.qdd_r))) < tol);
    CHECK(w("rnea with external wrenches", rel(vec(ch::rnea(d.m, d.q, d.qd, d.qdd, d.f), Tree::nv),
                                               fs::rnea_mimic(d.ref, d.couplings, d.q_r, d.qd_r, d.qdd_r, d.f_ref))) < tol);
    CHECK(w("crba", rel(rows(ch::crba(d.m, d.q), Tree::nv), fs::crba_mimic(d.ref, d.couplings, d.q_r))) < tol);
    CHECK(w("aba", rel(vec(ch::aba(d.m, d.q, d.qd, d.tau), Tree::nv),
                       fs::aba_mimic(d.ref, d.couplings, d.q_r, d.qd_r, d.tau_r))) < tol_solve);
    CHECK(w("aba with external wrenches", rel(vec(ch::aba(d.m, d.q, d.qd, d.tau, d.f), Tree::nv),
                                              fs::aba_mimic(d.ref, d.couplings, d.q_r, d.qd_r, d.tau_r, d.f_ref))) < tol_solve);
}

template <class Tree>
void check_mass_distribution(const draw<Tree>& d, worst& w) {
    const ch::kinematics<Tree> k_pos = ch::forward_kinematics(d.m, d.q);
    const ch::kinematics<Tree> k_vel = ch::forward_kinematics(d.m, d.q, d.qd);
    const ch::center_of_mass_state<double> c = ch::center_of_mass(d.m, k_vel);
    const double M = fs::total_mass(d.ref);
    CHECK(w("center_of_mass mass", std::abs(c.mass - M) / std::max(1.0, M)) < tol);
    CHECK(w("center_of_mass position", rel(vec(c.position, 3), fs::center_of_mass(d.ref, d.q_full))) < tol);
    CHECK(w("center_of_mass velocity", rel(vec(c.velocity, 3), fs::center_of_mass_velocity(d.ref, d.q_full, d.qd_full))) < tol);
    const ch::center_of_mass_state<double> c_pos = ch::center_of_mass(d.m, k_pos);  // no velocities: ċ = 0
    CHECK(rel(vec(c_pos.position, 3), vec(c.position, 3)) == 0);
    CHECK(vec(c_pos.velocity, 3).isZero(0));

    const auto sub = ch::subtree_centers_of_mass(d.m, k_pos);
    const std::vector<fs::subtree_mass> sub_ref = fs::subtree_centers_of_mass(d.ref, d.q_full);
    for (std::size_t i = 0; i < Tree::size; ++i) {
        INFO("subtree of body " << i);
        CHECK(w("subtree_centers_of_mass mass", std::abs(sub[i].mass - sub_ref[i].mass) / std::max(1.0, sub_ref[i].mass)) < tol);
        CHECK(w("subtree_centers_of_mass position", rel(vec(sub[i].position, 3), sub_ref[i].com)) < tol);
    }

    const MatrixXd Jc_ref = fs::center_of_mass_jacobian(d.ref, d.q_full).lazyProduct(d.G);
    const MatrixXd Jc = columns(ch::center_of_mass_jacobian(d.m, d.q), 3);
    CHECK(w("center_of_mass_jacobian (q)", rel(Jc, Jc_ref)) < tol);
    CHECK(w("center_of_mass_jacobian (kinematics)", rel(columns(ch::center_of_mass_jacobian(d.m, k_pos), 3), Jc_ref)) < tol);
    CHECK(w("center_of_mass_jacobian qd = com velocity", rel(Jc * d.qd_r, vec(c.velocity, 3))) < tol);

    // (l, p) and the reference's (n, f): angular momentum about the com, then linear momentum
    const VectorXd h_ref = fs::centroidal_momentum(d.ref, d.q_full, d.qd_full);
    const VectorXd h = vec(ch::centroidal_momentum(d.m, k_vel), 6);
    CHECK(w("centroidal_momentum", rel(h, h_ref)) < tol);
    CHECK(w("centroidal_momentum linear part = M com velocity", rel(h.tail<3>(), M * vec(c.velocity, 3))) < tol);
    const MatrixXd A_ref = fs::centroidal_momentum_matrix(d.ref, d.q_full).lazyProduct(d.G);
    const MatrixXd A = columns(ch::centroidal_momentum_matrix(d.m, d.q), 6);
    CHECK(w("centroidal_momentum_matrix (q)", rel(A, A_ref)) < tol);
    CHECK(w("centroidal_momentum_matrix (kinematics)", rel(columns(ch::centroidal_momentum_matrix(d.m, k_pos), 6), A_ref)) < tol);
    CHECK(w("centroidal_momentum_matrix qd = momentum", rel(A * d.qd_r, h_ref)) < tol);
}

}  // namespace

// ---------------------------------------------------------------------------------------------

// Part 0: the gripper's frames; part 1: the arm (frames, dynamics, centre of mass, centroidal
// momentum) and massless subtrees; part 2: the gripper's dynamics, centre of mass and centroidal
// momentum, the floating base's layout, the tree without mimic joints, refused inputs; part 3:
// two grippers visited by kind. (As one
// unit the file took ~45 s and 2 GB with g++ -O2: each frame of each tree instantiates its own
// Jacobians and J̇, each tree its own dynamics. Each part takes ~22-25 s and ~1.2 GB.)
#if CTGA_TEST_PART_HOLDS(0)
TEST_CASE("frames: a floating-base gripper with a finger mimicking the other (another branch): its frames agree with the "
          "reference",
          "[frames][mimic]") {
    worst w("mobile_gripper frames (floating base, mimic on another branch)");
    for (const std::uint64_t seed : {271u, 272u, 273u, 274u}) {
        std::mt19937_64 rng(seed);
        for (int n = 0; n < 3; ++n) {
            INFO("seed " << seed << ", draw " << n);
            const draw<mobile_gripper> d = make_draw<mobile_gripper>(rng, finger_coupling);
            REQUIRE(d.couplings.size() == 1);
            check_frames<"grasp", 7>(d, w);
            check_world_frame<"map">(d);
        }
    }
}
#endif

#if CTGA_TEST_PART_HOLDS(1)
TEST_CASE("frames: a fixed-base arm with a link mimicking its ancestor and a second root agrees with the reference",
          "[frames][mimic]") {
    worst w("coupled_arm (fixed base, mimic of an ancestor, two roots)");
    for (const std::uint64_t seed : {91u, 92u, 93u, 94u}) {
        std::mt19937_64 rng(seed);
        for (int n = 0; n < 3; ++n) {
            INFO("seed " << seed << ", draw " << n);
            const draw<coupled_arm> d = make_draw<coupled_arm>(rng, arm_coupling);
            REQUIRE(d.couplings.size() == 1);
            check_frames<"elbow_b", 4>(d, w);
            check_world_frame<"table">(d);
            check_dynamics(d, w);
            check_mass_distribution(d, w);
        }
    }
}

TEST_CASE("frames: massless_subtree: the first moving joint that carries no mass, -1 for a good model", "[frames][checked]") {
    const ctga::mat3<double> I0{};
    const ctga::vec3<double> c0{};
    const auto massless = ctga::make_mass_properties(0.0, c0, I0, ctga::mass_check::as_given);
    REQUIRE(massless);
    const ctga::motor<double> X = motor_of(fs::mat3::Identity(), fs::vec3(0.1, 0, 0));
    std::mt19937_64 rng(7);

    draw<coupled_arm> d = make_draw<coupled_arm>(rng, arm_coupling);
    CHECK(ch::massless_subtree(d.m) == -1);
    // the plunger (body 5, a leaf on a moving joint) without mass
    auto m = d.m;
    m.link<5>() = *ch::make_link<ch::prismatic<ch::axis::minus_z>>(X, massless);
    CHECK(ch::massless_subtree(m) == 5);
    // its forward dynamics has no answer: H is singular, aba gives NaN
    for (const double x : ch::aba(m, d.q, d.qd, d.tau)) CHECK(std::isnan(x));
    // and the coupled link above it (a mimic joint moves) too: body 4 comes first
    m.link<4>() =
        *ch::make_link<ch::mimic<ch::revolute_about, 1>>(X, massless, arm_coupling, ctga::vec3<double>{0.6, 0.0, 0.8});
    CHECK(ch::massless_subtree(m) == 4);
    // a massless body that carries mass is fine
    auto m2 = d.m;
    m2.link<3>() = *ch::make_link<ch::revolute_about>(X, massless, ctga::vec3<double>{0.0, 0.6, 0.8});
    CHECK(ch::massless_subtree(m2) == -1);
    // the conveyor, a second root, without mass
    auto m3 = d.m;
    m3.link<7>() = *ch::make_link<ch::prismatic_along>(X, massless, ctga::vec3<double>{0.0, 0.6, 0.8});
    CHECK(ch::massless_subtree(m3) == 7);

    // the gripper: a model's default links have no mass (the floating base's joint moves it)
    ch::model<mobile_gripper> g{};
    CHECK(ch::massless_subtree(g) == 0);
    const auto unit = ctga::make_principal_mass_properties(1.0, 0.1, 0.1, 0.1);
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((g.link<I>().inertia = ctga::body_inertia_of(*unit)), ...);
    }(std::make_index_sequence<mobile_gripper::size>{});
    CHECK(ch::massless_subtree(g) == -1);
    // a massless link on a fixed joint does not move: fine
    g.link<1>() = *ch::make_link<ch::fixed>(X, massless);
    CHECK(ch::massless_subtree(g) == -1);
    // a massless finger that mimics the other moves
    g.link<7>() = *ch::make_link<ch::mimic<ch::prismatic_x, 6>>(X, massless, finger_coupling);
    CHECK(ch::massless_subtree(g) == 7);
}
#endif

#if CTGA_TEST_PART_HOLDS(2)
// (the same seeds as the gripper's frames: the same models and states)
TEST_CASE("frames: the gripper's dynamics, centre of mass and centroidal momentum agree with the reference",
          "[frames][mimic]") {
    worst w("mobile_gripper dynamics, centre of mass, centroidal momentum");
    for (const std::uint64_t seed : {271u, 272u, 273u, 274u}) {
        std::mt19937_64 rng(seed);
        for (int n = 0; n < 3; ++n) {
            INFO("seed " << seed << ", draw " << n);
            const draw<mobile_gripper> d = make_draw<mobile_gripper>(rng, finger_coupling);
            check_dynamics(d, w);
            check_mass_distribution(d, w);
        }
    }
}

// ---- the floating base's numbers in Pinocchio's / ROS's layout -----------------------------

TEST_CASE("frames: floating_base_configuration / floating_base_pose / floating_base_velocity / linear_angular",
          "[frames][floating_base]") {
    worst w("floating base layout");
    std::mt19937_64 rng(2027);
    draw<mobile_gripper> d = make_draw<mobile_gripper>(rng, finger_coupling);
    // the base's joint frame is the world's (Pinocchio's free flyer; the other tests place it anywhere)
    d.m.link<0>().placement = *ch::make_frame(ctga::motor<double>{1, 0, 0, 0, 0, 0, 0, 0});
    d.ref.bodies[0].rotation = fs::mat3::Identity();
    d.ref.bodies[0].translation = fs::vec3::Zero();
    for (int n = 0; n < 20; ++n) {
        INFO("draw " << n);
        // a base pose as position + quaternion (x, y, z, w); every other one with w < 0
        const fs::vec3 p = fs::uniform_vec3(rng, 2.0);
        Eigen::Vector4d wxyz = fs::random_quaternion(rng);
        if (n % 2) wxyz = -wxyz;
        const ch::base_pose<double> pose{v3(p), {wxyz[1], wxyz[2], wxyz[3], wxyz[0]}};
        const ctga::checked<std::array<double, 8>> cfg = ch::floating_base_configuration(pose);
        REQUIRE(cfg);
        // ctga's floating joint with these 8 numbers, the reference's with (x, y, z, qw, qx, qy, qz)
        for (std::size_t k = 0; k < 8; ++k) d.q[k] = (*cfg)[k];
        d.q_r.head<3>() = p;
        d.q_r.segment<4>(3) = wxyz;
        d.q_full = fs::expand_q(d.ref, d.couplings, d.q_r);
        const ch::kinematics<mobile_gripper> k = ch::forward_kinematics(d.m, d.q);
        const ctga::motor_map<double> W = ch::frame_pose(d.m, k, ch::body<0>);
        const fs::pose P = fs::frame_pose(d.ref, d.q_full, fs::frame{0, fs::mat3::Identity(), fs::vec3::Zero()});
        CHECK(w("base pose R", rel(mat(W.R), P.rotation)) < tol);
        CHECK(w("base pose t", rel(vec(W.t, 3), P.origin)) < tol);
        CHECK(w("base pose R = quaternion_rotation(w, x, y, z)",
                rel(mat(W.R), fs::quaternion_rotation(wxyz[0], wxyz[1], wxyz[2], wxyz[3]))) < tol);
        CHECK(w("base pose t = position", rel(vec(W.t, 3), p)) < tol);
        // a frame further out sees the same base pose
        const fs::frame& tool = d.frames[mobile_gripper::frame_index_of("tool")];
        const ctga::motor_map<double> Wt = ch::frame_pose(d.m, k, ch::frame<"tool">);
        const fs::pose Pt = fs::frame_pose(d.ref, d.q_full, tool);
        CHECK(w("tool pose R", rel(mat(Wt.R), Pt.rotation)) < tol);
        CHECK(w("tool pose t", rel(vec(Wt.t, 3), Pt.origin)) < tol);
        // round trip: the same position and quaternion (sign as given)
        const ch::base_pose<double> back = ch::floating_base_pose(*cfg);
        CHECK(w("floating_base_pose position", rel(vec(back.position, 3), p)) < tol);
        const Eigen::Vector4d xyzw(wxyz[1], wxyz[2], wxyz[3], wxyz[0]);
        CHECK(w("floating_base_pose quaternion", rel(vec(back.quaternion, 4), xyzw)) < tol);
        // a quaternion off unit length by rounding is normalised
        ch::base_pose<double> near = pose;
        for (double& x : near.quaternion) x *= 1 + 1e-10;
        const auto cfg_near = ch::floating_base_configuration(near);
        REQUIRE(cfg_near);
        CHECK(w("near-unit quaternion normalised", rel(vec(*cfg_near, 8), vec(*cfg, 8))) < tol);

        // velocities: Pinocchio's (linear, angular) in base axes are the base's local velocity
        const fs::vec3 lin = fs::uniform_vec3(rng, 2.0), ang = fs::uniform_vec3(rng, 2.0);
        const std::array<double, 6> v = ch::floating_base_velocity(v3(lin), v3(ang));
        const std::array<double, 6> la = ch::linear_angular(v);
        CHECK(vec(la, 6) == (VectorXd(6) << lin, ang).finished());
        for (std::size_t c = 0; c < 6; ++c) d.qd[c] = d.qd_r[static_cast<Eigen::Index>(c)] = v[c];
        d.qd_full = d.G * d.qd_r;
        const ch::kinematics<mobile_gripper> kv = ch::forward_kinematics(d.m, d.q, d.qd);
        const VectorXd v_local = vec(ch::frame_velocity(d.m, kv, ch::body<0>, ch::reference::local), 6);
        CHECK(w("base local velocity = (angular, linear)", rel(v_local, (VectorXd(6) << ang, lin).finished())) < tol);
        const fs::frame base{0, fs::mat3::Identity(), fs::vec3::Zero()};
        CHECK(w("base local velocity vs reference",
                rel(v_local, fs::frame_velocity(d.ref, d.q_full, d.qd_full, base, fs::reference::local))) < tol);
        // the base origin's world velocity is R lin
        const VectorXd v_lwa = vec(ch::frame_velocity(d.m, kv, ch::body<0>, ch::reference::local_world_aligned), 6);
        CHECK(w("base origin velocity = R linear", rel(v_lwa.tail<3>(), mat(W.R) * lin)) < tol);
    }
    // refused: a quaternion that is not a rotation, a NaN anywhere
    ch::base_pose<double> bad{{0.1, 0.2, 0.3}, {0.1, 0.2, 0.3, 1.2}};
    CHECK(ch::floating_base_configuration(bad).error == ctga::error_code::not_a_rotation);
    bad.quaternion = {0, 0, 0, 0};
    CHECK(ch::floating_base_configuration(bad).error == ctga::error_code::not_a_rotation);
    bad.quaternion = {0, 0, 0, 1 + 1e-6};
    CHECK(ch::floating_base_configuration(bad).error == ctga::error_code::not_a_rotation);
    bad.quaternion = {0, 0, 0, 1};
    CHECK(ch::floating_base_configuration(bad));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    bad.position[1] = nan;
    CHECK(ch::floating_base_configuration(bad).error == ctga::error_code::non_finite);
    bad.position[1] = 0;
    bad.quaternion[2] = nan;
    CHECK(ch::floating_base_configuration(bad).error == ctga::error_code::non_finite);
    bad.quaternion[2] = std::numeric_limits<double>::infinity();
    CHECK(ch::floating_base_configuration(bad).error == ctga::error_code::non_finite);
}

TEST_CASE("frames: joints about -x, -y and along -z in the articulated-body pass (no mimic joint) agree with the reference",
          "[frames]") {
    worst w("minus_axes (no mimic joints: ABA's articulated pass)");
    for (const std::uint64_t seed : {5u, 6u, 7u}) {
        std::mt19937_64 rng(seed);
        for (int n = 0; n < 4; ++n) {
            INFO("seed " << seed << ", draw " << n);
            const draw<minus_axes> d = make_draw<minus_axes>(rng, {});
            REQUIRE(d.couplings.empty());
            constexpr std::size_t nv = minus_axes::nv;
            CHECK(w("rnea", rel(vec(ch::rnea(d.m, d.q, d.qd, d.qdd), nv), fs::rnea(d.ref, d.q_r, d.qd_r, d.qdd_r))) < tol);
            CHECK(w("aba", rel(vec(ch::aba(d.m, d.q, d.qd, d.tau), nv), fs::aba(d.ref, d.q_r, d.qd_r, d.tau_r))) < tol_solve);
            CHECK(w("aba with external wrenches", rel(vec(ch::aba(d.m, d.q, d.qd, d.tau, d.f), nv),
                                                      fs::aba(d.ref, d.q_r, d.qd_r, d.tau_r, d.f_ref))) < tol_solve);
        }
    }
}

// ---- refused inputs --------------------------------------------------------------------------

TEST_CASE("frames: unknown frames, non-finite couplings, mass checks as given", "[frames][checked]") {
    const ctga::mat3<double> I0{};
    const ctga::vec3<double> c0{};
    const ctga::motor<double> X = motor_of(fs::mat3::Identity(), fs::vec3(0.1, 0, 0));
    std::mt19937_64 rng(7);

    SECTION("find_frame: unknown_frame for a name the tree does not have") {
        const auto none = mobile_gripper::find_frame("no_such");
        CHECK(!none);
        CHECK(none.error == ctga::error_code::unknown_frame);
        CHECK(!coupled_arm::find_frame("tool"));  // the other tree's
        CHECK(!coupled_arm::find_frame(""));
        CHECK(!coupled_arm::find_frame("tcp "));
        const auto tcp = coupled_arm::find_frame("tcp");
        REQUIRE(tcp);
        CHECK(*tcp == 4);
        CHECK(*mobile_gripper::find_frame("map") == 7);
        static_assert(ch::frame_index<mobile_gripper, "flange">() == 3);
        static_assert(mobile_gripper::frame_body[3] == 5 && mobile_gripper::frame_body[4] == 5);
        static_assert(mobile_gripper::frame_count == 8 && coupled_arm::frame_count == 7);
        static_assert(mobile_gripper::nq == 8 + 5 && mobile_gripper::nv == 6 + 5);
        static_assert(coupled_arm::nq == 7 && coupled_arm::nv == 7);
        // visit_frame with an index out of range calls nothing
        int calls = 0;
        ch::visit_frame<mobile_gripper>(mobile_gripper::frame_count, [&](auto) { ++calls; });
        CHECK(calls == 0);
    }
    SECTION("make_link: a non-finite coupling") {
        const auto mass = ctga::make_principal_mass_properties(1.0, 0.1, 0.1, 0.1);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        using finger = ch::mimic<ch::prismatic_x, 6>;
        CHECK(ch::make_link<finger>(X, mass, ch::coupling<double>{-1.3, 0.02}));
        CHECK(ch::make_link<finger>(X, mass, ch::coupling<double>{nan, 0.02}).error == ctga::error_code::non_finite);
        CHECK(ch::make_link<finger>(X, mass, ch::coupling<double>{-1.3, nan}).error == ctga::error_code::non_finite);
        CHECK(ch::make_link<finger>(X, mass, ch::coupling<double>{std::numeric_limits<double>::infinity(), 0}).error ==
              ctga::error_code::non_finite);
        using coupled = ch::mimic<ch::revolute_about, 1>;
        CHECK(ch::make_link<coupled>(X, mass, ch::coupling<double>{nan, 0}, ctga::vec3<double>{0, 0, 1}).error ==
              ctga::error_code::non_finite);
        CHECK(ch::make_link<coupled>(X, mass, ch::coupling<double>{0.7, 0}, ctga::vec3<double>{0, 0, 1.1}).error ==
              ctga::error_code::not_a_unit_axis);
        const auto ok = ch::make_link<coupled>(X, mass, ch::coupling<double>{0.7, -0.1}, ctga::vec3<double>{0, 0.6, 0.8});
        REQUIRE(ok);
        CHECK(ok->joint.multiplier == 0.7);
        CHECK(ok->joint.offset == -0.1);
        CHECK(ok->joint.joint.u[1] == 0.6);
        // a frame's placement is checked as a body's
        CHECK(ch::make_frame(X));
        ctga::motor<double> Xnan = X;
        Xnan[5] = nan;
        CHECK(ch::make_frame(Xnan).error == ctga::error_code::non_finite);
        ctga::motor<double> X2 = X;
        X2[0] *= 2;
        CHECK(ch::make_frame(X2).error == ctga::error_code::not_a_motor);
    }
    SECTION("make_mass_properties: as_given accepts m = 0 and a tensor violating the triangle inequality") {
        CHECK(ctga::make_mass_properties(0.0, c0, I0, ctga::mass_check::as_given));
        CHECK(ctga::make_mass_properties(-1.0, c0, I0, ctga::mass_check::as_given).error == ctga::error_code::non_positive_mass);
        CHECK(ctga::make_mass_properties(0.0, c0, I0).error == ctga::error_code::non_positive_mass);
        // principal moments (1, 1, 3): 3 > 1 + 1
        const ctga::mat3<double> I_bad{{{1, 0, 0}, {0, 1, 0}, {0, 0, 3}}};
        CHECK(ctga::make_mass_properties(1.0, c0, I_bad, ctga::mass_check::as_given));
        CHECK(ctga::make_mass_properties(1.0, c0, I_bad).error == ctga::error_code::triangle_inequality);
        // the same, turned (a full tensor)
        const fs::mat3 R = fs::random_rotation(rng);
        const fs::mat3 I_turned = R * fs::vec3(1, 1, 3).asDiagonal() * R.transpose();
        const fs::mat3 I_sym = 0.5 * (I_turned + I_turned.transpose());
        CHECK(ctga::make_mass_properties(1.0, c0, m3(I_sym), ctga::mass_check::as_given));
        CHECK(ctga::make_mass_properties(1.0, c0, m3(I_sym)).error == ctga::error_code::triangle_inequality);
        // still refused as given: a NaN, an asymmetric tensor
        CHECK(ctga::make_mass_properties(std::numeric_limits<double>::quiet_NaN(), c0, I0, ctga::mass_check::as_given).error ==
              ctga::error_code::non_finite);
        const ctga::mat3<double> I_asym{{{1, 0.5, 0}, {0, 1, 0}, {0, 0, 1}}};
        CHECK(ctga::make_mass_properties(1.0, c0, I_asym, ctga::mass_check::as_given).error == ctga::error_code::not_symmetric);
    }
}
#endif

#if CTGA_TEST_PART_HOLDS(3)
TEST_CASE("frames: two grippers with mimic fingers on a floating base, visited by kind: dynamics agree with the reference",
          "[frames][mimic]") {
    worst w("two_grippers dynamics (by kind, two mimic joints)");
    for (const std::uint64_t seed : {281u, 282u}) {
        std::mt19937_64 rng(seed);
        for (int n = 0; n < 3; ++n) {
            INFO("seed " << seed << ", draw " << n);
            const draw<two_grippers> d = make_draw<two_grippers>(rng, finger_coupling);
            REQUIRE(d.couplings.size() == 2);
            check_dynamics(d, w);
        }
    }
}
#endif
