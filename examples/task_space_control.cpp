// Task-space computed-torque control of a UR5e (tests/data/ur5e.urdf, Universal Robots' published
// DH parameters and link masses, converted by tools/urdf_to_ctga.py: the massless flange and tool0
// links are merged into the last body as named frames). The tool moves along a 30 cm straight line
// with a minimum-jerk profile in 2 s while keeping its orientation, and the plant is simulated with
// the articulated-body algorithm.
//
// The controller, every 1 ms, with the frame Jacobian J of tool0 in local_world_aligned (ω and the
// velocity of the tool's origin, world axes) and its time variation J̇:
//   a* = (ω̇_d, p̈_d) + K_d (ẋ_d − J q̇) + K_p e          (e: orientation and position errors)
//   q̈* = J⁺ (a* − J̇ q̇)                                  (damped least squares, J⁺ = Jᵀ(J Jᵀ + λ²)⁻¹)
//   τ  = RNEA(q, q̇, q̈*)                                   (computed torque: gravity, Coriolis, inertia)
// With a = J q̈ + J̇ q̇ exact (the angular acceleration and the classical acceleration of the tool's
// origin), the error obeys ë + K_d ė + K_p e = 0. Printed: the tracking error along the way, and the
// same run without the J̇ q̇ term, to show what it is worth.
#include <array>
#include <cmath>
#include <cstdio>

#include <ctga/ctga.hpp>

#include "ur5e.hpp"  // generated: tools/urdf_to_ctga.py tests/data/ur5e.urdf --name ur5e

namespace ch = ctga::chains;
using tree = ur5e::tree;
using vec3 = ctga::vec3<double>;
constexpr auto tool = ch::frame<"tool0">;

struct errors {
    double max_position, rms_position, max_orientation, final_position;
};

// Minimum-jerk profile s(t) on [0, T] and its first two derivatives.
static std::array<double, 3> min_jerk(double t, double T) {
    const double x = std::fmin(std::fmax(t / T, 0.0), 1.0);
    const double s = x * x * x * (10 - 15 * x + 6 * x * x);
    const double ds = 30 * x * x * (1 - 2 * x + x * x) / T;
    const double dds = 60 * x * (1 - 3 * x + 2 * x * x) / (T * T);
    return {s, ds, dds};
}

static errors run(bool use_jdot) {
    const auto built = ur5e::make_model<double>();
    if (!built) {
        std::printf("model: %s\n", ctga::describe(built.error));
        return {};
    }
    const ch::model<tree>& m = *built;
    ch::configuration<tree> q{0.0, -1.2, 1.6, -1.9, -1.5708, 0.0};  // an elbow-up pose
    ch::joint_vector<tree> qd{};
    const ctga::motor_map<double> start = ch::frame_pose(m, ch::forward_kinematics(m, q), tool);
    const vec3 p0 = start.t, p1 = {p0[0] - 0.15, p0[1] + 0.2, p0[2] - 0.15};  // 0.29 m away
    const double T = 2.0, dt = 1e-3, Kp = 400.0, Kd = 40.0, lambda = 1e-3;
    errors e{};
    double sum2 = 0;
    int n = 0;
    for (double t = 0; t < T + 0.5; t += dt, ++n) {
        const auto k = ch::forward_kinematics(m, q, qd);
        const ctga::motor_map<double> X = ch::frame_pose(m, k, tool);
        const auto J = ch::frame_jacobian(m, k, tool, ch::reference::local_world_aligned);
        const auto Jd = ch::frame_jacobian_time_variation(m, k, tool, ch::reference::local_world_aligned);
        const ctga::screw<double> v = ch::frame_velocity(m, k, tool, ch::reference::local_world_aligned);
        // the desired motion: the start orientation, the position along the line
        const auto [s, ds, dds] = min_jerk(t, T);
        std::array<double, 6> a{};  // a* − J̇ q̇, (angular, linear)
        for (int i = 0; i < 3; ++i) {
            // orientation error ½ Σ_c x_c × x_c,d over the frames' axes (world), zero when aligned
            double eo = 0;
            for (int c = 0; c < 3; ++c) {
                const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
                eo += 0.5 * (X.R[i1][c] * start.R[i2][c] - X.R[i2][c] * start.R[i1][c]);
            }
            const double pd = p0[i] + s * (p1[i] - p0[i]), vd = ds * (p1[i] - p0[i]), ad = dds * (p1[i] - p0[i]);
            a[i] = Kp * eo - Kd * v[i];
            a[3 + i] = ad + Kd * (vd - v[3 + i]) + Kp * (pd - X.t[i]);
            const double err = std::abs(pd - X.t[i]);
            e.max_position = std::fmax(e.max_position, err);
            sum2 += err * err;
            e.max_orientation = std::fmax(e.max_orientation, std::abs(eo));
        }
        if (use_jdot)
            for (std::size_t c = 0; c < tree::nv; ++c)
                for (std::size_t r = 0; r < 6; ++r) a[r] -= Jd[c][r] * qd[c];
        // q̈* = Jᵀ (J Jᵀ + λ²)⁻¹ a
        std::array<std::array<double, 6>, 6> A{};
        for (std::size_t r = 0; r < 6; ++r)
            for (std::size_t c = 0; c < 6; ++c) {
                for (std::size_t j = 0; j < tree::nv; ++j) A[r][c] += J[j][r] * J[j][c];
                if (r == c) A[r][c] += lambda * lambda;
            }
        const auto L = ctga::cholesky(A);
        if (!L) {
            std::printf("singular task Jacobian at t = %.3f\n", t);
            return e;
        }
        const std::array<double, 6> y = ctga::cholesky_solve(*L, a);
        ch::joint_vector<tree> qdd_star{};
        for (std::size_t j = 0; j < tree::nv; ++j)
            for (std::size_t r = 0; r < 6; ++r) qdd_star[j] += J[j][r] * y[r];
        const auto tau = ch::rnea(m, q, qd, qdd_star);  // computed torque
        // the plant: forward dynamics, semi-implicit Euler
        const auto qdd = ch::aba(m, q, qd, tau);
        for (std::size_t j = 0; j < tree::nv; ++j) {
            qd[j] += dt * qdd[j];
            q[j] += dt * qd[j];
        }
    }
    const auto X = ch::frame_pose(m, ch::forward_kinematics(m, q), tool);
    e.rms_position = std::sqrt(sum2 / (3.0 * n));
    e.final_position = std::sqrt((X.t[0] - p1[0]) * (X.t[0] - p1[0]) + (X.t[1] - p1[1]) * (X.t[1] - p1[1]) +
                                 (X.t[2] - p1[2]) * (X.t[2] - p1[2]));
    return e;
}

int main() {
    std::printf("UR5e (%zu bodies, %zu frames), tool0 along a 0.29 m line in 2 s, computed torque at 1 kHz\n", tree::size,
                tree::frame_count);
    const errors with = run(true), without = run(false);
    std::printf("%-22s %14s %14s %16s %14s\n", "", "max |e_p| (m)", "rms |e_p| (m)", "max |e_R| (rad)", "final (m)");
    std::printf("%-22s %14.2e %14.2e %16.2e %14.2e\n", "with Jdot qdot", with.max_position, with.rms_position, with.max_orientation,
                with.final_position);
    std::printf("%-22s %14.2e %14.2e %16.2e %14.2e\n", "without Jdot qdot", without.max_position, without.rms_position,
                without.max_orientation, without.final_position);
    // the controller must track: sub-millimetre along the way, and J̇ q̇ must matter
    return with.max_position < 1e-3 && with.final_position < 1e-4 && without.max_position > with.max_position ? 0 : 1;
}
