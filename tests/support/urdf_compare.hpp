// What tests/urdf_test.cpp and tests/urdf_fixtures_test.cpp share: random states for a generated
// tree (a floating joint's q a random unit motor), ctga's results as Eigen matrices, every named
// frame's pose and Jacobian (the three references) of a tree computed once per frame, and the
// worst error of each measure, printed at the end of a test case.
//
// Error measure: rel(x, y) = max_k |x_k − y_k| / max(1, max_k |y_k|), y the value compared with
// (support/relative_error.hpp); poses: the largest entry of |R − R'| and |t − t'|.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include <ctga/chains/algorithms.hpp>

#include "support/featherstone.hpp"
#include "support/random_tree.hpp"
#include "support/relative_error.hpp"

namespace ctga::test::urdf {

namespace ch = ctga::chains;
namespace fs = ctga::test::featherstone;

// ---- the worst value of each measure -------------------------------------------------------------

inline std::map<std::string, double>& worst_table() {
    static std::map<std::string, double> table;
    return table;
}
// records x under `what` and returns it (CHECK(W("rnea", e) <= 1e-12))
inline double W(const std::string& what, double x) {
    double& w = worst_table()[what];
    w = std::max(w, x);
    return x;
}
// prints and clears the table (at the end of a test case)
inline void print_worst(const char* test) {
    std::printf("%s: worst errors\n", test);
    for (const auto& [what, x] : worst_table()) std::printf("  %-58s %.3g\n", what.c_str(), x);
    worst_table().clear();
}

// ---- ctga's numbers as Eigen ---------------------------------------------------------------------

template <std::size_t N>
Eigen::VectorXd eigen_vector(const std::array<double, N>& x) {
    Eigen::VectorXd out(static_cast<Eigen::Index>(N));
    for (std::size_t i = 0; i < N; ++i) out[static_cast<Eigen::Index>(i)] = x[i];
    return out;
}
template <std::size_t N>
Eigen::MatrixXd eigen_matrix(const std::array<std::array<double, N>, N>& H) {
    Eigen::MatrixXd out(static_cast<Eigen::Index>(N), static_cast<Eigen::Index>(N));
    for (std::size_t r = 0; r < N; ++r)
        for (std::size_t c = 0; c < N; ++c) out(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = H[r][c];
    return out;
}
// a Jacobian (column k a screw (ω, v)) as 6 × nv
template <std::size_t N>
Eigen::MatrixXd eigen_jacobian(const std::array<ctga::screw<double>, N>& J) {
    Eigen::MatrixXd out(6, static_cast<Eigen::Index>(N));
    for (std::size_t c = 0; c < N; ++c)
        for (std::size_t r = 0; r < 6; ++r) out(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = J[c][r];
    return out;
}
inline fs::mat3 eigen_rotation(const ctga::motor_map<double>& G) {
    fs::mat3 R;
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c) R(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = G.R[r][c];
    return R;
}
inline fs::vec3 eigen_translation(const ctga::motor_map<double>& G) { return fs::vec3(G.t[0], G.t[1], G.t[2]); }

// URDF's roll, pitch, yaw about the fixed axes: R = Rz(yaw) Ry(pitch) Rx(roll), each the
// right-handed elementary rotation written out.
inline fs::mat3 rpy_rotation(const std::array<double, 3>& rpy) {
    const double cr = std::cos(rpy[0]), sr = std::sin(rpy[0]), cp = std::cos(rpy[1]), sp = std::sin(rpy[1]),
                 cy = std::cos(rpy[2]), sy = std::sin(rpy[2]);
    fs::mat3 Rx, Ry, Rz;
    Rx << 1, 0, 0, 0, cr, -sr, 0, sr, cr;
    Ry << cp, 0, sp, 0, 1, 0, -sp, 0, cp;
    Rz << cy, -sy, 0, sy, cy, 0, 0, 0, 1;
    return Rz * Ry * Rx;
}

using ctga::test::rel;
// a pose against (R, t): the largest entry of |R − R'| and |t − t'|
inline double pose_error(const ctga::motor_map<double>& G, const fs::mat3& R, const fs::vec3& t) {
    return std::max((eigen_rotation(G) - R).cwiseAbs().maxCoeff(), (eigen_translation(G) - t).cwiseAbs().maxCoeff());
}
inline double pose_error(const ctga::motor_map<double>& G, const ctga::motor_map<double>& H) {
    return pose_error(G, eigen_rotation(H), eigen_translation(H));
}

// ---- random states --------------------------------------------------------------------------------

// A configuration of a generated tree: a floating joint's 8 numbers the motor of a random rotation
// and a translation in [−1, 1]³, every one-dof joint's angle or length in [−3, 3]. With `ref`, the
// same configuration as the Featherstone reference's q: per body in body order, a floating joint's
// (x, y, z, qw, qx, qy, qz) and a one-dof joint's number (a tree without mimic joints).
template <class Tree>
ch::configuration<Tree> random_configuration(std::mt19937_64& rng, Eigen::VectorXd* ref = nullptr) {
    std::vector<double> r_numbers;
    ch::configuration<Tree> q{};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            using J = typename Tree::template joint_at<I>;
            constexpr std::size_t o = Tree::q_offset[I];
            if constexpr (J::nq == 8) {  // floating (or aligned<floating>)
                const Eigen::Quaterniond r(fs::random_rotation(rng));
                const fs::vec3 t = fs::uniform_vec3(rng, 1.0);
                const ctga::motor<double> g =
                    ctga::rigid_motion(ctga::make_translator(t[0], t[1], t[2]), ctga::rotor<double>{r.w(), r.x(), r.y(), r.z()});
                for (std::size_t k = 0; k < 8; ++k) q[o + k] = g[k];
                r_numbers.insert(r_numbers.end(), {t[0], t[1], t[2], r.w(), r.x(), r.y(), r.z()});
            } else if constexpr (J::nq == 1) {
                q[o] = fs::uniform(rng, -3, 3);
                r_numbers.push_back(q[o]);
            }
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    if (ref) *ref = Eigen::Map<const Eigen::VectorXd>(r_numbers.data(), static_cast<Eigen::Index>(r_numbers.size()));
    return q;
}

template <class Tree>
ch::joint_vector<Tree> random_joint_vector(std::mt19937_64& rng, double half_width = 2) {
    ch::joint_vector<Tree> x{};
    for (double& e : x) e = fs::uniform(rng, -half_width, half_width);
    return x;
}

// ---- every named frame of a tree ---------------------------------------------------------------------

inline constexpr std::array<ch::reference, 3> references{ch::reference::local, ch::reference::world,
                                                         ch::reference::local_world_aligned};
inline const char* reference_name(std::size_t r) {
    constexpr const char* names[] = {"local", "world", "local_world_aligned"};
    return names[r];
}

// Frame k's world pose and its Jacobians in the three references, for every named frame of the
// tree, at q (k: forward_kinematics(m, q)); each frame's code instantiated once.
template <class Tree>
struct frames_at {
    std::array<ctga::motor_map<double>, Tree::frame_count> pose;
    std::array<std::array<Eigen::MatrixXd, 3>, Tree::frame_count> jacobian;
};
template <class Tree>
frames_at<Tree> all_frames(const ch::model<Tree>& m, const ch::kinematics<Tree>& k) {
    frames_at<Tree> out;
    [&]<std::size_t... K>(std::index_sequence<K...>) {
        ([&] {
            out.pose[K] = ch::frame_pose(m, k, ch::frame_at<K>);
            for (std::size_t r = 0; r < 3; ++r)
                out.jacobian[K][r] = eigen_jacobian(ch::frame_jacobian(m, k, ch::frame_at<K>, references[r]));
        }(), ...);
    }(std::make_index_sequence<Tree::frame_count>{});
    return out;
}

}  // namespace ctga::test::urdf
