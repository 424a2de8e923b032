// A user's robot program: a URDF robot (tests/data/legged.urdf, a floating quadruped) through
// ctga_urdf_header(), every public algorithm of the kinematic trees in double and in float, built
// with -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wshadow -Werror (CMakeLists.txt):
// the library's headers must add no warning to a user's strict build.
#include <ctga/chains/batch.hpp>
#include <ctga/chains/model_cast.hpp>
#include <ctga/ctga.hpp>

#include "robot.hpp"

#include <cmath>
#include <cstdio>
#include <random>

static_assert(__cplusplus >= 202002L, "ctga::ctga must bring C++20");

namespace ch = ctga::chains;

template <class T>
bool exercise() {
    const auto made = robot::make_model<T>();
    const auto limits = robot::make_limits<T>();
    if (!made || !limits) return false;
    const ch::model<robot::tree, T>& m = *made;

    std::mt19937_64 rng(7);
    ch::joint_limits<robot::tree, T> box = *limits;
    for (std::size_t k = 0; k < 6; ++k) {  // the floating base's position box
        box.lower[k] = T(-1);
        box.upper[k] = T(1);
    }
    const auto q_random = ch::random_configuration(m, box, rng);
    if (!q_random) return false;
    const auto q = *q_random;
    ch::joint_vector<robot::tree, T> qd{}, qdd{};
    for (std::size_t i = 0; i < qd.size(); ++i) {
        qd[i] = T(0.1) * T(i % 5);
        qdd[i] = T(0.2) - T(0.05) * T(i % 3);
    }

    const auto tau = ch::rnea(m, q, qd, qdd);
    const auto acc = ch::checked_call(ch::aba, m, q, qd, tau);
    if (!acc) return false;
    const auto H = ch::crba(m, q);
    const auto Minv = ch::minverse(m, q);
    const auto id = ch::rnea_derivatives(m, q, qd, qdd);
    const auto fd = ch::aba_derivatives(m, q, qd, tau);
    const auto k = ch::forward_kinematics(m, q, qd);
    const auto foot = ch::frame<"LF_FOOT">;
    const auto X = ch::frame_pose(m, k, foot);
    const auto J = ch::frame_jacobian(m, q, foot, ch::reference::local_world_aligned);
    const auto Jd = ch::frame_jacobian_time_variation(m, k, foot, ch::reference::local_world_aligned);
    const auto dv = ch::frame_motion_derivatives(m, q, qd, qdd, foot, ch::reference::local);
    const auto c = ch::center_of_mass(m, k);
    const auto Ag = ch::centroidal_momentum_matrix(m, k);
    const T ke = ch::tree_kinetic_energy(m, q, qd);
    const T pe = ch::tree_potential_energy(m, q);
    const auto q1 = ch::integrate(m, q, qd);
    const auto v = ch::difference(m, q, q1);
    const auto qh = ch::interpolate(m, q, q1, T(0.5));
    const auto run = ctga::integrate(ctga::lie_rk4{}, ch::tree_motion<robot::tree, T>{m}, {{q}, {qd}}, T(1e-3), 10);
    // six robots in packs of four lanes (chains/batch.hpp): ABA of each, as the scalar call
    struct state {
        ch::configuration<robot::tree, T> q{};
        ch::joint_vector<robot::tree, T> qd{}, tau{}, qdd{};
        ctga::error_code error = ctga::error_code::none;
    };
    std::array<state, 6> robots{};
    for (state& r : robots) r.q = q, r.qd = qd, r.tau = tau;
    const auto lanes = ch::model_cast<ctga::pack<T, 4>>(m);
    const std::size_t failed = ch::batch_call(ch::aba, lanes, robots, &state::qdd, &state::error, 1, &state::q, &state::qd, &state::tau);
    // a point moved by a PGA motor and a plane through three points (geometry/pga.hpp)
    namespace pga = ctga::pga;
    const pga::motor<T> M = pga::make_translator<T>(0, 0, 2) * pga::make_rotor<T>(1, 0, 0, 1);
    const pga::point<T> p = pga::sandwich(M, pga::make_point<T>(1, 0, 0));
    const auto plane = pga::join(p, pga::make_point<T>(0, 1, 0), pga::make_point<T>(0, 0, 1));
    (void)plane;
    if (failed != 0) return false;
    (void)X; (void)J; (void)Jd; (void)dv; (void)c; (void)Ag; (void)id; (void)fd; (void)qh; (void)run;

    // ABA inverts RNEA; H M⁻¹ = 1 (row 0); ⊖ inverts ⊕.
    const T tol = std::is_same_v<T, float> ? T(2e-2) : T(1e-9);
    T worst = 0;
    for (std::size_t i = 0; i < qdd.size(); ++i) {
        worst = std::max(worst, std::abs((*acc)[i] - qdd[i]));
        worst = std::max(worst, std::abs(v[i] - qd[i]));
        worst = std::max(worst, std::abs(robots[5].qdd[i] - (*acc)[i]));
        T row = 0;
        for (std::size_t j = 0; j < qdd.size(); ++j) row += H[0][j] * Minv(j, i);
        worst = std::max(worst, std::abs(row - (i == 0 ? T(1) : T(0))));
    }
    std::printf("%s: worst %.3g, kinetic %.6g, potential %.6g\n", std::is_same_v<T, float> ? "float" : "double",
                static_cast<double>(worst), static_cast<double>(ke), static_cast<double>(pe));
    return worst < tol && std::isfinite(ke) && std::isfinite(pe);
}

int main() {
#if CTGA_CONSUMER_FLOAT  // the add_subdirectory mode (run.cmake): float too; find_package: double
    const bool ok = exercise<double>() && exercise<float>();
#else
    const bool ok = exercise<double>();
#endif
    std::puts(ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
