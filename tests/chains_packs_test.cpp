// The tree algorithms with ctga::pack<double, L> as the scalar (support/pack.hpp): one model cast
// to every lane (chains::model_cast), each lane its own robot's state, against the double
// algorithms run robot by robot (themselves checked against the Featherstone reference in
// chains_test). Random trees with about half their joints aligned, one on a floating base.
//   - Lanes equal the double results to 1e-14 relative where the joints turn (the packs' cos and
//     sin are pack.hpp's polynomials, within 1 ulp of libm's) and bit for bit on a tree whose
//     joints slide (no cos or sin: the same operations in the same order).
//   - batch_call: robots gathered from an array of structures, N not a multiple of the lane count,
//     on one and on two threads, with poisoned robots (a NaN in q, a floating base whose rotor is
//     zero, a NaN in q̇): those are reported (non_finite, not_a_unit_base), every other robot's
//     results are bit for bit those of an all-healthy batch.
//   - batch_integrate: lie_rk4 and the implicit midpoint (Newton and fixed point) over robots on a
//     floating base, each lane against ctga::integrate of its robot alone; a robot too fast for
//     the fixed-point iteration (did_not_converge) and one with a NaN (non_finite) stop there,
//     the others run all their steps.
//   - Frames by name (chains::frame<"tool">, and find_frame / visit_frame at run time): pose,
//     velocity, accelerations, Jacobian and frame_motion_derivatives, lane against robot;
//     checked_call on packs reports each lane's failure (lane_errors) and keeps the other lanes'
//     results; load and store move every number to its lane and back.
// PARTS: 7
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <ctga/chains/algorithms.hpp>
#include <ctga/chains/batch.hpp>
#include <ctga/chains/model_cast.hpp>
#include <ctga/chains/motion.hpp>
#include <ctga/integrators/integrate.hpp>
#include <ctga/integrators/methods.hpp>
#include <ctga/support/pack.hpp>

#include "support/catch.hpp"
#include "support/parts.hpp"
#include "support/random_structure.hpp"

namespace {

namespace ch = ctga::chains;
using ctga::pack;
using ctga::test::draw;
using ctga::test::make_draw;
using ctga::test::random_structure;

// The largest |lane l of a − b| / (1 + |b|) over two structures of numbers (arrays nest).
template <class A, class B, std::size_t K>
double lane_error(const std::array<A, K>& a, const std::array<B, K>& b, std::size_t l);
template <class A, class B>
    requires requires(const A& a) { a.size(); a[0]; }
double lane_error(const A& a, const B& b, std::size_t l);
template <class T, std::size_t L>
double lane_error(const pack<T, L>& a, const T& b, std::size_t l) {
    const double d = std::abs(a[l] - b) / (1 + std::abs(b));
    return d == d ? d : std::numeric_limits<double>::infinity();
}
template <class A, class B, std::size_t K>
double lane_error(const std::array<A, K>& a, const std::array<B, K>& b, std::size_t l) {
    double e = 0;
    for (std::size_t k = 0; k < K; ++k) e = std::max(e, lane_error(a[k], b[k], l));
    return e;
}
// a multivector, a motor_map, a kinematics: compared through their numbers
template <class A, class B>
    requires requires(const A& a) { a.size(); a[0]; }
double lane_error(const A& a, const B& b, std::size_t l) {
    double e = 0;
    for (std::size_t k = 0; k < a.size(); ++k) e = std::max(e, lane_error(a[k], b[k], l));
    return e;
}
// a tree_matrix (nv × nv, entries (i, j))
template <class A, class B>
    requires requires(const A& a) { a(0, 0); A::n; }
double lane_error(const A& a, const B& b, std::size_t l) {
    double e = 0;
    for (std::size_t i = 0; i < A::n; ++i)
        for (std::size_t j = 0; j < A::n; ++j) e = std::max(e, lane_error(a(i, j), b(i, j), l));
    return e;
}
template <class T, std::size_t L>
double lane_error(const ctga::motor_map<pack<T, L>>& a, const ctga::motor_map<T>& b, std::size_t l) {
    return std::max(lane_error(a.R, b.R, l), lane_error(a.t, b.t, l));
}

template <class Tree>
struct robot {
    ch::configuration<Tree> q{};
    ch::joint_vector<Tree> qd{}, qdd{}, tau{};
};

// L robots of one model: the pack states, and each robot's own
template <class Tree, std::size_t L>
struct lanes_of {
    draw<Tree> d;
    std::array<robot<Tree>, L> robots;
    ch::configuration<Tree, pack<double, L>> q;
    ch::joint_vector<Tree, pack<double, L>> qd, qdd, tau;
    ch::model<Tree, pack<double, L>> mp;  // d.m in every lane

    explicit lanes_of(std::uint64_t seed) {
        std::mt19937_64 rng(seed);
        d = make_draw<Tree>(rng);
        mp = ch::model_cast<pack<double, L>>(d.m);
        for (auto& r : robots) {
            const draw<Tree> other = make_draw<Tree>(rng);  // its state only
            r.q = other.q, r.qd = other.qd, r.qdd = other.qdd;
            for (std::size_t k = 0; k < Tree::nv; ++k) r.tau[k] = 3 * other.qdd[k] - other.qd[k];
        }
        q = ch::load<L>(robots, 0, &robot<Tree>::q);
        qd = ch::load<L>(robots, 0, &robot<Tree>::qd);
        qdd = ch::load<L>(robots, 0, &robot<Tree>::qdd);
        tau = ch::load<L>(robots, 0, &robot<Tree>::tau);
    }
};

// Every algorithm, lane against robot; tolerance 0 asks for the same bits.
template <class Tree, std::size_t L>
void compare(std::uint64_t seed, double tolerance) {
    using P = pack<double, L>;
    const lanes_of<Tree, L> x(seed);
    const ch::model<Tree>& m = x.d.m;
    const ch::model<Tree, P>& mp = x.mp;
    const auto tau = ch::rnea(mp, x.q, x.qd, x.qdd);
    const auto qdd = ch::aba(mp, x.q, x.qd, x.tau);
    const auto H = ch::crba(mp, x.q);
    const auto Minv = ch::minverse(mp, x.q);
    const ch::kinematics<Tree, P> k = ch::forward_kinematics(mp, x.q, x.qd, x.qdd);
    constexpr std::size_t last = Tree::size - 1;
    const auto J = ch::frame_jacobian(mp, x.q, ch::body<last>, ch::reference::world);
    const auto com = ch::center_of_mass(mp, k);
    const P energy = ch::tree_kinetic_energy(mp, x.q, x.qd);
    const auto Ag = ch::centroidal_momentum_matrix(mp, k);
    for (std::size_t l = 0; l < L; ++l) {
        INFO("bodies " << Tree::size << ", lanes " << L << ", lane " << l);
        const robot<Tree>& r = x.robots[l];
        CHECK(lane_error(tau, ch::rnea(m, r.q, r.qd, r.qdd), l) <= tolerance);
        CHECK(lane_error(qdd, ch::aba(m, r.q, r.qd, r.tau), l) <= tolerance);
        CHECK(lane_error(H, ch::crba(m, r.q), l) <= tolerance);
        CHECK(lane_error(Minv, ch::minverse(m, r.q), l) <= tolerance);
        const ch::kinematics<Tree> k_l = ch::forward_kinematics(m, r.q, r.qd, r.qdd);
        for (std::size_t i = 0; i < Tree::size; ++i) {
            CHECK(lane_error(k.pose[i], k_l.pose[i], l) <= tolerance);
            CHECK(lane_error(k.v[i], k_l.v[i], l) <= tolerance);
            CHECK(lane_error(k.a[i], k_l.a[i], l) <= tolerance);
        }
        CHECK(lane_error(J, ch::frame_jacobian(m, r.q, ch::body<last>, ch::reference::world), l) <= tolerance);
        const auto com_l = ch::center_of_mass(m, k_l);
        CHECK(lane_error(com.mass, com_l.mass, l) <= tolerance);
        CHECK(lane_error(com.position, com_l.position, l) <= tolerance);
        CHECK(lane_error(com.velocity, com_l.velocity, l) <= tolerance);
        CHECK(lane_error(energy, ch::tree_kinetic_energy(m, r.q, r.qd), l) <= tolerance);
        CHECK(lane_error(Ag, ch::centroidal_momentum_matrix(m, k_l), l) <= tolerance);
    }
}

// The derivatives of RNEA and ABA, lane against robot.
template <class Tree, std::size_t L>
void compare_derivatives(std::uint64_t seed) {
    const lanes_of<Tree, L> x(seed);
    const ch::model<Tree>& m = x.d.m;
    const auto dr = ch::rnea_derivatives(x.mp, x.q, x.qd, x.qdd);
    const auto da = ch::aba_derivatives(x.mp, x.q, x.qd, x.tau);
    for (std::size_t l = 0; l < L; ++l) {
        INFO("bodies " << Tree::size << ", lanes " << L << ", lane " << l);
        const robot<Tree>& r = x.robots[l];
        const auto dr_l = ch::rnea_derivatives(m, r.q, r.qd, r.qdd);
        const auto da_l = ch::aba_derivatives(m, r.q, r.qd, r.tau);
        CHECK(lane_error(dr.dtau_dq, dr_l.dtau_dq, l) <= 1e-13);
        CHECK(lane_error(dr.dtau_dv, dr_l.dtau_dv, l) <= 1e-13);
        CHECK(lane_error(da.qdd, da_l.qdd, l) <= 1e-13);
        CHECK(lane_error(da.dqdd_dq, da_l.dqdd_dq, l) <= 1e-13);
        CHECK(lane_error(da.dqdd_dv, da_l.dqdd_dv, l) <= 1e-13);
    }
}

// A floating base and sliding joints, some aligned: no cos or sin anywhere.
using sliding_tree = ch::tree<ch::link<-1, ch::floating>, ch::link<0, ch::aligned<ch::prismatic_x>>, ch::link<1, ch::prismatic_along>,
                              ch::link<0, ch::prismatic_z>, ch::link<3, ch::fixed>, ch::link<4, ch::aligned<ch::prismatic_y>>>;

// batch_call over n robots (n not a multiple of L) on `threads` threads, robots 2, n − 2 and n − 1
// poisoned when asked.
template <class Tree, std::size_t L>
void check_batch(std::uint64_t seed, std::size_t n, unsigned threads) {
    using P = pack<double, L>;
    struct state {
        ch::configuration<Tree> q{};
        ch::joint_vector<Tree> qd{}, tau{}, qdd{};
        ctga::error_code error = ctga::error_code::did_not_converge;  // overwritten by batch_call
    };
    std::mt19937_64 rng(seed);
    const draw<Tree> d = make_draw<Tree>(rng);
    std::vector<state> healthy(n);
    for (auto& s : healthy) {
        const draw<Tree> other = make_draw<Tree>(rng);
        s.q = other.q, s.qd = other.qd, s.tau = other.qdd;
    }
    std::vector<state> poisoned = healthy;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    poisoned[2].q[Tree::nq - 1] = nan;
    for (std::size_t c = 0; c < 4; ++c) poisoned[n - 2].q[c] = 0;  // the floating base's rotor part
    poisoned[n - 1].qd[0] = nan;
    const auto lanes = ch::model_cast<P>(d.m);
    const std::size_t failed_healthy =
        ch::batch_call(ch::aba, lanes, healthy, &state::qdd, &state::error, threads, &state::q, &state::qd, &state::tau);
    const std::size_t failed =
        ch::batch_call(ch::aba, lanes, poisoned, &state::qdd, &state::error, threads, &state::q, &state::qd, &state::tau);
    CHECK(failed_healthy == 0);
    CHECK(failed == 3);
    for (std::size_t i = 0; i < n; ++i) {
        INFO("robot " << i << " of " << n << ", lanes " << L << ", threads " << threads);
        const state& h = healthy[i];
        CHECK(h.error == ctga::error_code::none);
        CHECK(lane_error(ch::load<1>(healthy, i, &state::qdd), ch::aba(d.m, h.q, h.qd, h.tau), 0) <= 1e-14);
        const ctga::error_code expected = i == 2 || i == n - 1 ? ctga::error_code::non_finite
                                          : i == n - 2         ? ctga::error_code::not_a_unit_base
                                                               : ctga::error_code::none;
        CHECK(poisoned[i].error == expected);
        if (expected == ctga::error_code::none)
            for (std::size_t k = 0; k < Tree::nv; ++k) CHECK(poisoned[i].qdd[k] == h.qdd[k]);
    }
}

// batch_integrate against ctga::integrate robot by robot; robot 1 spins too fast for the step
// (|q̇| = 400 rad/s at h = 0.02: the fixed-point iteration diverges) when `fast`, robot n − 1 has a
// NaN in q̇.
template <class Tree, std::size_t L, class Method>
void check_rollout(const Method& method, std::uint64_t seed, std::size_t n, bool fast, double tolerance) {
    using P = pack<double, L>;
    struct state {
        ch::configuration<Tree> q{};
        ch::joint_vector<Tree> qd{};
        ctga::error_code error = ctga::error_code::unknown_frame;  // overwritten
    };
    std::mt19937_64 rng(seed);
    const draw<Tree> d = make_draw<Tree>(rng);
    std::vector<state> robots(n);
    for (auto& r : robots) {
        const draw<Tree> other = make_draw<Tree>(rng);
        r.q = other.q, r.qd = other.qd;
    }
    if (fast)
        for (auto& v : robots[1].qd) v = 400;
    robots[n - 1].qd[0] = std::numeric_limits<double>::quiet_NaN();
    const std::vector<state> start = robots;
    const double h = fast ? 0.02 : 0.005;
    const long steps = 20;
    const ch::tree_motion<Tree> sim{d.m};
    const ch::tree_motion<Tree, P> lanes{ch::model_cast<P>(d.m)};
    const std::size_t failed = ch::batch_integrate(method, lanes, robots, &state::q, &state::qd, &state::error, h, steps, 2);
    CHECK(failed == (fast ? 2u : 1u));
    for (std::size_t i = 0; i < n; ++i) {
        INFO("robot " << i << " of " << n << ", lanes " << L);
        const auto alone = ctga::integrate(method, sim, {{start[i].q}, {start[i].qd}}, h, steps);
        CHECK(robots[i].error == alone.error);
        if (i == n - 1) {
            CHECK(robots[i].error == ctga::error_code::non_finite);
        } else if (fast && i == 1) {
            CHECK(robots[i].error == ctga::error_code::did_not_converge);
        } else {
            CHECK(robots[i].error == ctga::error_code::none);
            for (std::size_t k = 0; k < Tree::nq; ++k) CHECK(std::abs(robots[i].q[k] - alone.state.g[k]) <= tolerance * (1 + std::abs(alone.state.g[k])));
            for (std::size_t k = 0; k < Tree::nv; ++k) CHECK(std::abs(robots[i].qd[k] - alone.state.s[k]) <= tolerance * (1 + std::abs(alone.state.s[k])));
        }
    }
}

// A floating base, turning and sliding joints and named frames on a body, on the base and on the
// world.
using framed_tree = ch::tree<ch::link<-1, ch::floating>, ch::link<0, ch::revolute_z>, ch::link<1, ch::revolute_about>,
                             ch::link<2, ch::prismatic_x>, ch::fixed_frame<"tool", 3>, ch::fixed_frame<"imu", 0>,
                             ch::fixed_frame<"map", -1>>;

// Frames by name (in the source and through find_frame at run time), lane against robot: pose,
// velocities, accelerations, Jacobian and the derivatives of the velocity and acceleration.
template <std::size_t L>
void compare_frames(std::uint64_t seed) {
    using Tree = framed_tree;
    using P = pack<double, L>;
    lanes_of<Tree, L> x(seed);
    std::mt19937_64 rng(seed + 1);
    std::uniform_real_distribution<double> u(-1, 1);
    for (std::size_t f = 0; f < Tree::frame_count; ++f) {
        const auto g = ctga::renormalize(ctga::motor<double>{1 + u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)});
        const auto placed = ch::make_frame(g);
        REQUIRE(placed);
        x.d.m.frames[f] = *placed;
    }
    x.mp = ch::model_cast<P>(x.d.m);
    const ch::model<Tree>& m = x.d.m;
    const ch::kinematics<Tree, P> k = ch::forward_kinematics(x.mp, x.q, x.qd, x.qdd);
    const auto numbers = [](const auto& model, const auto& kin, const auto& q, const auto& qd, const auto& qdd, auto f) {
        const auto d = ch::frame_motion_derivatives(model, q, qd, qdd, f, ch::reference::local_world_aligned);
        return std::tuple{ch::frame_pose(model, kin, f),
                          ch::frame_velocity(model, kin, f, ch::reference::local),
                          ch::frame_velocity(model, kin, f, ch::reference::world),
                          ch::frame_acceleration(model, kin, f, ch::reference::local_world_aligned),
                          ch::frame_classical_acceleration(model, kin, f, ch::reference::world),
                          ch::frame_jacobian(model, q, f, ch::reference::local),
                          d.dv_dq, d.dv_dv, d.da_dq, d.da_dv, d.da_da};
    };
    const std::size_t imu = *Tree::find_frame("imu");
    const auto tool = numbers(x.mp, k, x.q, x.qd, x.qdd, ch::frame<"tool">);
    const auto on_base = ch::visit_frame<Tree>(imu, [&](auto f) { return numbers(x.mp, k, x.q, x.qd, x.qdd, f); });
    const auto world = numbers(x.mp, k, x.q, x.qd, x.qdd, ch::frame<"map">);
    for (std::size_t l = 0; l < L; ++l) {
        INFO("lanes " << L << ", lane " << l);
        const robot<Tree>& r = x.robots[l];
        const ch::kinematics<Tree> k_l = ch::forward_kinematics(m, r.q, r.qd, r.qdd);
        const auto tool_l = numbers(m, k_l, r.q, r.qd, r.qdd, ch::frame<"tool">);
        const auto on_base_l = ch::visit_frame<Tree>(imu, [&](auto f) { return numbers(m, k_l, r.q, r.qd, r.qdd, f); });
        const auto world_l = numbers(m, k_l, r.q, r.qd, r.qdd, ch::frame<"map">);
        const auto worst = [&](const auto& a, const auto& b) {
            return std::apply([&](const auto&... x) {
                return std::apply([&](const auto&... y) { return std::max({lane_error(x, y, l)...}); }, b);
            }, a);
        };
        CHECK(worst(tool, tool_l) <= 1e-14);
        CHECK(worst(on_base, on_base_l) <= 1e-14);
        CHECK(worst(world, world_l) <= 1e-14);
    }
}

// checked_call on packs: every lane checked on its own. Lane 1 has a NaN in q, lane 2 a floating
// base with a zero rotor part, lane 3 a NaN in q̈; lane 0 a NaN in its lane of the model's
// gravity. The other lanes' results are the double checked_call's.
template <std::size_t L>
void check_checked_call(std::uint64_t seed) {
    static_assert(L >= 6);
    using Tree = framed_tree;
    lanes_of<Tree, L> x(seed);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    x.q[Tree::nq - 1].set(1, nan);
    for (std::size_t c = 0; c < 4; ++c) x.q[c].set(2, 0);
    x.qdd[0].set(3, nan);
    x.mp.gravity[2].set(0, nan);
    const auto healthy = ch::checked_call(ch::rnea, ch::model_cast<pack<double, L>>(x.d.m), x.q, x.qd, x.qdd);
    const auto tau = ch::checked_call(ch::rnea, x.mp, x.q, x.qd, x.qdd);
    static_assert(std::is_same_v<std::remove_cvref_t<decltype(tau.error)>, ctga::lane_errors<L>>);
    for (std::size_t l = 0; l < L; ++l) {
        INFO("lane " << l);
        const ctga::error_code expected = l == 0 || l == 1 || l == 3 ? ctga::error_code::non_finite
                                          : l == 2                   ? ctga::error_code::not_a_unit_base
                                                                     : ctga::error_code::none;
        CHECK(tau.error[l] == expected);
        CHECK(healthy.error[l] == (l == 1 || l == 3 ? ctga::error_code::non_finite
                                   : l == 2         ? ctga::error_code::not_a_unit_base
                                                    : ctga::error_code::none));
        const robot<Tree>& r = x.robots[l];
        if (expected == ctga::error_code::none) {
            const auto one = ch::checked_call(ch::rnea, x.d.m, r.q, r.qd, r.qdd);
            REQUIRE(one);
            CHECK(lane_error(tau.value, *one, l) <= 1e-14);
        }
    }
    // the scalar form reports the same way
    ch::configuration<Tree> q = x.robots[2].q;
    for (std::size_t c = 0; c < 4; ++c) q[c] = 0;
    CHECK(ch::checked_call(ch::rnea, x.d.m, q, x.robots[2].qd, x.robots[2].qdd).error == ctga::error_code::not_a_unit_base);
}

// load and store between robots' arrays and packs: every number in its lane and back, for K ≥ L
// numbers a robot (transposed blocks, the last one overlapping) and K < L (lane by lane), the
// last pack partial.
template <class T, std::size_t L, std::size_t K>
void check_load_store() {
    struct state {
        std::array<std::array<T, K>, 3> x{};
        T other = 0;
    };
    std::vector<state> robots(2 * L + 3);
    for (std::size_t i = 0; i < robots.size(); ++i)
        for (std::size_t a = 0; a < 3; ++a)
            for (std::size_t k = 0; k < K; ++k) robots[i].x[a][k] = T(1000 * i + 100 * a + k);
    std::vector<state> back(robots.size());
    for (std::size_t first = 0; first < robots.size(); first += L) {
        const auto p = ch::load<L>(robots, first, &state::x);
        for (std::size_t l = 0; l < L; ++l) {
            const state& r = robots[std::min(first + l, robots.size() - 1)];  // past the end: the last robot
            for (std::size_t a = 0; a < 3; ++a)
                for (std::size_t k = 0; k < K; ++k) CHECK(p[a][k][l] == r.x[a][k]);
        }
        ch::store<L>(p, back, first, &state::x);
    }
    for (std::size_t i = 0; i < robots.size(); ++i) CHECK(back[i].x == robots[i].x);
}

}  // namespace

#define PACKS_CASE(name) TEST_CASE("chains on packs: " name CTGA_TEST_PART_NAME)
#if CTGA_TEST_PART_HOLDS(0)
PACKS_CASE("every lane equals the double algorithms on its robot, 5 bodies, 4 lanes") {
    compare<random_structure<51, 5, false, true, true>::type, 4>(51, 1e-14);
}
#endif
#if CTGA_TEST_PART_HOLDS(1)
PACKS_CASE("sliding joints on a floating base: every lane bit for bit the double algorithms, 2 lanes") {
    compare<sliding_tree, 2>(57, 0);
}
#endif
#if CTGA_TEST_PART_HOLDS(2)
PACKS_CASE("every lane equals the double algorithms on its robot, 5 bodies on a floating base, 8 lanes") {
    compare<random_structure<52, 5, true, true, true>::type, 8>(53, 1e-14);
}
#endif
#if CTGA_TEST_PART_HOLDS(3)
PACKS_CASE("derivatives of RNEA and ABA, 5 bodies on a floating base, 4 lanes") {
    compare_derivatives<random_structure<54, 5, true, true>::type, 4>(54);
}
#endif
#if CTGA_TEST_PART_HOLDS(4)
PACKS_CASE("batch_call: N not a multiple of the lanes, poisoned robots reported, the others untouched") {
    using Tree = random_structure<55, 6, true, true>::type;
    check_batch<Tree, 4>(55, 23, 1);
    check_batch<Tree, 4>(56, 10, 2);
    check_batch<Tree, 8>(57, 13, 2);
}
#endif
#if CTGA_TEST_PART_HOLDS(5)
PACKS_CASE("batch_integrate: lie_rk4 and the implicit midpoint lane by lane, a diverging and a poisoned robot stopped") {
    using Tree = random_structure<58, 4, true, true>::type;
    check_rollout<Tree, 4>(ctga::lie_rk4{}, 58, 11, false, 1e-13);
    check_rollout<Tree, 4>(ctga::implicit_midpoint{}, 59, 7, false, 1e-12);
    check_rollout<Tree, 4>(ctga::implicit_midpoint{.solver = ctga::implicit_solver::fixed_point}, 60, 6, true, 1e-12);
}
#endif
#if CTGA_TEST_PART_HOLDS(6)
PACKS_CASE("frames by name, checked_call on packs, load and store, lane by lane") {
    compare_frames<4>(61);
    check_checked_call<8>(62);
    check_load_store<double, 2, 1>();
    check_load_store<double, 4, 7>();
    check_load_store<double, 8, 7>();
    check_load_store<double, 8, 2>();
    check_load_store<float, 16, 7>();
    check_load_store<float, 4, 1>();
}
#endif

