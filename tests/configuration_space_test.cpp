// The configuration space of a tree (chains/configuration_space.hpp): q ⊕ v against the matrix
// exponential of the body-frame twist (a Taylor series, written here), ⊖ and interpolation against
// ⊕, the neutral configuration, random configurations against their limits, and ∂τ/∂q and ∂q̈/∂q
// of the derivatives (rnea_derivatives, aba_derivatives) against central differences along ⊕.
// Also what the checks say of a floating base in Pinocchio's layout, and a joint's armature.
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include <ctga/chains/aba_derivatives.hpp>
#include <ctga/ctga.hpp>

#include "support/catch.hpp"

namespace {

namespace ch = ctga::chains;
using robot = ch::tree<ch::link<-1, ch::floating>, ch::link<0, ch::with_armature<ch::revolute_about>>, ch::link<1, ch::aligned<ch::revolute_y>>,
                       ch::link<0, ch::prismatic_along>, ch::link<3, ch::mimic<ch::revolute_x, 2>>,
                       ch::fixed_frame<"tool", 4>>;
using mat4 = std::array<std::array<double, 4>, 4>;

ctga::motor<double> placement(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    return ctga::rigid_motion(ctga::make_translator(u(rng), u(rng), u(rng)), ctga::make_rotor(2 * u(rng), u(rng), u(rng), 1.0));
}
ctga::vec3<double> unit_axis(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    ctga::vec3<double> a{u(rng), u(rng), 1.0};
    const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (double& x : a) x /= n;
    return a;
}

ch::model<robot> make_robot(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.5, 2);
    const auto mass = [&] {
        const double m = u(rng);
        return ctga::make_mass_properties(m, ctga::vec3<double>{0.1 * u(rng), -0.05, 0.2},
                                          ctga::mat3<double>{{{0.1 * m, 0.01, 0.0}, {0.01, 0.12 * m, 0.0}, {0.0, 0.0, 0.09 * m}}});
    };
    ch::model<robot> m;
    m.link<0>() = *ch::make_link<ch::floating>(ctga::motor<double>{1, 0, 0, 0, 0, 0, 0, 0}, mass());
    m.link<1>() = *ch::make_link<ch::with_armature<ch::revolute_about>>(placement(rng), mass(), unit_axis(rng));
    m.link<2>() = *ch::make_link<ch::aligned<ch::revolute_y>>(ctga::motor<double>(ctga::make_translator(0.1, 0.3, -0.2)), mass());
    m.link<3>() = *ch::make_link<ch::prismatic_along>(placement(rng), mass(), unit_axis(rng));
    m.link<4>() = *ch::make_link<ch::mimic<ch::revolute_x, 2>>(placement(rng), mass(), ch::coupling<double>{-0.7, 0.1});
    m.link<1>().armature = 0.3;  // a rotor on the turning joint (every algorithm: H_11 + 0.3)
    return m;
}

// A state: random joints, a floating base of random pose.
ch::configuration<robot> random_q(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    ch::configuration<robot> q{};
    const ctga::motor<double> g = placement(rng);
    for (std::size_t k = 0; k < 8; ++k) q[k] = g[k];
    for (std::size_t k = 8; k < robot::nq; ++k) q[k] = 2 * u(rng);
    return q;
}
ch::joint_vector<robot> random_v(std::mt19937_64& rng, double scale) {
    std::uniform_real_distribution<double> u(-scale, scale);
    ch::joint_vector<robot> v{};
    for (double& x : v) x = u(rng);
    return v;
}

mat4 homogeneous(const ctga::motor_map<double>& X) {
    mat4 H{};
    for (std::size_t r = 0; r < 3; ++r) {
        for (std::size_t c = 0; c < 3; ++c) H[r][c] = X.R[r][c];
        H[r][3] = X.t[r];
    }
    H[3][3] = 1;
    return H;
}
mat4 product(const mat4& a, const mat4& b) {
    mat4 c{};
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = 0; j < 4; ++j)
            for (std::size_t k = 0; k < 4; ++k) c[i][j] += a[i][k] * b[k][j];
    return c;
}
// exp of the twist [[ω×, v], [0, 0]] (body-frame velocity (ω, v) for unit time): the Taylor series
// of e^{Ξ/2^s}, then squared s times.
mat4 twist_exponential(const std::array<double, 6>& s) {
    const int squarings = 8;
    const double scale = std::ldexp(1.0, -squarings);
    mat4 X{};
    const double w[3] = {s[0] * scale, s[1] * scale, s[2] * scale};
    X[0][1] = -w[2], X[0][2] = w[1], X[1][0] = w[2], X[1][2] = -w[0], X[2][0] = -w[1], X[2][1] = w[0];
    for (std::size_t r = 0; r < 3; ++r) X[r][3] = s[3 + r] * scale;
    mat4 E{}, term{};
    for (std::size_t i = 0; i < 4; ++i) E[i][i] = term[i][i] = 1;
    for (int n = 1; n < 20; ++n) {
        term = product(term, X);
        for (auto& row : term)
            for (double& x : row) x /= n;
        for (std::size_t i = 0; i < 4; ++i)
            for (std::size_t j = 0; j < 4; ++j) E[i][j] += term[i][j];
    }
    for (int k = 0; k < squarings; ++k) E = product(E, E);
    return E;
}

double pose_distance(const ctga::motor_map<double>& a, const ctga::motor_map<double>& b) {
    double d = 0;
    for (std::size_t r = 0; r < 3; ++r) {
        for (std::size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(a.R[r][c] - b.R[r][c]));
        d = std::max(d, std::abs(a.t[r] - b.t[r]));
    }
    return d;
}

}  // namespace

TEST_CASE("q ⊕ v: a joint's q + v, a floating base moved by the exponential of its body-frame twist",
          "[chains][configuration]") {
    std::mt19937_64 rng(41);
    const ch::model<robot> m = make_robot(rng);
    for (int trial = 0; trial < 50; ++trial) {
        const auto q = random_q(rng);
        const auto v = random_v(rng, 2.0);
        const auto q1 = ch::integrate(m, q, v);
        for (std::size_t k = 8; k < robot::nq; ++k) CHECK(q1[k] == Approx(q[k] + v[k - 2]).margin(1e-15));
        CHECK(ctga::near_unit(ctga::motor<double>{q1[0], q1[1], q1[2], q1[3], q1[4], q1[5], q1[6], q1[7]}));
        // the base's pose: X(q) exp(Ξ(v)), against the series
        const auto k0 = ch::forward_kinematics(m, q), k1 = ch::forward_kinematics(m, q1);
        const mat4 expected = product(homogeneous(k0.pose[0]), twist_exponential({v[0], v[1], v[2], v[3], v[4], v[5]}));
        const mat4 got = homogeneous(k1.pose[0]);
        for (std::size_t r = 0; r < 3; ++r)
            for (std::size_t c = 0; c < 4; ++c) CHECK(got[r][c] == Approx(expected[r][c]).margin(1e-13));
    }
}

TEST_CASE("q₁ ⊖ q₀ inverts ⊕, and interpolation runs along it", "[chains][configuration]") {
    std::mt19937_64 rng(42);
    const ch::model<robot> m = make_robot(rng);
    for (int trial = 0; trial < 50; ++trial) {
        const auto q0 = random_q(rng), q1 = random_q(rng);
        const auto v = random_v(rng, 1.0);  // (the base turns by |ω| ≤ √3 < π: log's range)
        const auto back = ch::difference(m, q0, ch::integrate(m, q0, v));
        for (std::size_t k = 0; k < robot::nv; ++k) CHECK(back[k] == Approx(v[k]).margin(1e-13));
        // integrate(q₀, q₁ ⊖ q₀) reaches q₁'s poses (the motor up to its sign: the same motion)
        const auto d = ch::difference(m, q0, q1);
        const auto reached = ch::integrate(m, q0, d);
        const auto k1 = ch::forward_kinematics(m, q1), kr = ch::forward_kinematics(m, reached);
        for (std::size_t i = 0; i < robot::size; ++i) CHECK(pose_distance(k1.pose[i], kr.pose[i]) < 1e-13);
        // interpolation: the ends, and the middle is half way along the difference
        const auto a = ch::interpolate(m, q0, q1, 0.0);
        for (std::size_t k = 0; k < robot::nq; ++k) CHECK(a[k] == Approx(q0[k]).margin(1e-15));
        const auto b = ch::interpolate(m, q0, q1, 1.0);
        const auto kb = ch::forward_kinematics(m, b);
        for (std::size_t i = 0; i < robot::size; ++i) CHECK(pose_distance(k1.pose[i], kb.pose[i]) < 1e-13);
        const auto half = ch::difference(m, q0, ch::interpolate(m, q0, q1, 0.5));
        for (std::size_t k = 0; k < robot::nv; ++k) CHECK(half[k] == Approx(0.5 * d[k]).margin(1e-13));
    }
    // the neutral configuration puts every body at its placement: the base at the world's origin
    const auto k = ch::forward_kinematics(m, ch::neutral(m));
    CHECK(pose_distance(k.pose[0], ctga::map_of(ctga::motor<double>{1, 0, 0, 0, 0, 0, 0, 0})) == 0);
    CHECK(pose_distance(k.pose[1], ch::forward_kinematics(m, ch::neutral(m)).X[1]) == 0);
}

TEST_CASE("random configurations lie within the limits, an infinite bound they need is reported", "[chains][configuration]") {
    std::mt19937_64 rng(43);
    const ch::model<robot> m = make_robot(rng);
    auto limits = ch::unlimited<robot>();
    // the base's origin in a box; the revolute joint about a run-time axis left unbounded ([−π, π])
    for (std::size_t k = 3; k < 6; ++k) limits.lower[k] = -0.5, limits.upper[k] = 2.0;
    limits.lower[7] = -0.2, limits.upper[7] = 0.9;    // the aligned revolute joint
    limits.lower[8] = -0.05, limits.upper[8] = 0.05;  // the prismatic joint
    double low7 = 1, high7 = -1, low6 = 4, high6 = -4;
    for (int trial = 0; trial < 400; ++trial) {
        const auto q = ch::random_configuration(m, limits, rng);
        REQUIRE(q);
        const auto pose = ch::floating_base_pose(std::array<double, 8>{(*q)[0], (*q)[1], (*q)[2], (*q)[3], (*q)[4], (*q)[5], (*q)[6], (*q)[7]});
        for (std::size_t k = 0; k < 3; ++k) CHECK((pose.position[k] >= -0.5 && pose.position[k] <= 2.0));
        CHECK(ctga::near_unit(ctga::motor<double>{(*q)[0], (*q)[1], (*q)[2], (*q)[3], (*q)[4], (*q)[5], (*q)[6], (*q)[7]}));
        CHECK(((*q)[10] >= -0.05 && (*q)[10] <= 0.05));
        low7 = std::min(low7, (*q)[9]), high7 = std::max(high7, (*q)[9]);
        low6 = std::min(low6, (*q)[8]), high6 = std::max(high6, (*q)[8]);
    }
    CHECK(low7 >= -0.2);
    CHECK(high7 <= 0.9);
    CHECK(low7 < -0.15);  // (uniform: 400 draws reach both ends)
    CHECK(high7 > 0.85);
    CHECK(low6 >= -std::numbers::pi);
    CHECK(high6 <= std::numbers::pi);
    CHECK(low6 < -3.0);
    CHECK(high6 > 3.0);
    // a prismatic joint or a base position without bounds cannot be drawn
    auto open = limits;
    open.upper[8] = HUGE_VAL;
    CHECK(ch::random_configuration(m, open, rng).error == ctga::error_code::unbounded);
    open = limits;
    open.lower[4] = -HUGE_VAL;
    CHECK(ch::random_configuration(m, open, rng).error == ctga::error_code::unbounded);
    open = limits;
    open.lower[7] = 1.0;
    CHECK(ch::random_configuration(m, open, rng).error == ctga::error_code::limits_reversed);
}

TEST_CASE("∂τ/∂q and ∂q̈/∂q are the derivatives along q ⊕ δ", "[chains][configuration][derivatives]") {
    std::mt19937_64 rng(44);
    const ch::model<robot> m = make_robot(rng);
    const auto q = random_q(rng);
    const auto qd = random_v(rng, 1.0), qdd = random_v(rng, 1.0), tau = random_v(rng, 3.0);
    const auto id = ch::rnea_derivatives(m, q, qd, qdd);
    const auto fd = ch::aba_derivatives(m, q, qd, tau);
    const double h = 1e-6;
    for (std::size_t c = 0; c < robot::nv; ++c) {
        ch::joint_vector<robot> d{};
        d[c] = h;
        const auto plus = ch::integrate(m, q, d);
        d[c] = -h;
        const auto minus = ch::integrate(m, q, d);
        const auto t1 = ch::rnea(m, plus, qd, qdd), t0 = ch::rnea(m, minus, qd, qdd);
        const auto a1 = ch::aba(m, plus, qd, tau), a0 = ch::aba(m, minus, qd, tau);
        for (std::size_t r = 0; r < robot::nv; ++r) {
            CHECK(id.dtau_dq(r, c) == Approx((t1[r] - t0[r]) / (2 * h)).margin(1e-7));
            CHECK(fd.dqdd_dq(r, c) == Approx((a1[r] - a0[r]) / (2 * h)).margin(1e-6));
        }
    }
}

TEST_CASE("a floating base in Pinocchio's layout is reported, converted it is accepted", "[chains][configuration][checks]") {
    std::mt19937_64 rng(45);
    const ch::model<robot> m = make_robot(rng);
    const ch::base_pose<double> pose{{0.3, -0.2, 0.9}, {0.2, -0.1, 0.3, 0.92736184954957}};  // (x y z), (qx qy qz qw)
    ch::configuration<robot> pasted = random_q(rng);
    pasted[0] = 0.3, pasted[1] = -0.2, pasted[2] = 0.9, pasted[3] = 0.2, pasted[4] = -0.1, pasted[5] = 0.3,
    pasted[6] = 0.92736184954957, pasted[7] = 0;  // [x y z qx qy qz qw] into the eight numbers
    const ch::joint_vector<robot> zero{};
    CHECK(ch::checked_call(ch::aba, m, pasted, zero, zero).error == ctga::error_code::not_a_unit_base);
    const ch::tree_motion<robot> sim{m};
    CHECK(ctga::integrate(ctga::lie_rk4{}, sim, {{pasted}, {zero}}, 1e-3, 10).error == ctga::error_code::not_a_unit_base);
    const auto base = ch::floating_base_configuration(pose);
    REQUIRE(base);
    ch::configuration<robot> converted = pasted;
    for (std::size_t k = 0; k < 8; ++k) converted[k] = (*base)[k];
    CHECK(ch::checked_call(ch::aba, m, converted, zero, zero));
    CHECK(ctga::integrate(ctga::lie_rk4{}, sim, {{converted}, {zero}}, 1e-3, 10));
    // a drifted motor (rounding, an integrator's steps) still passes
    ch::configuration<robot> drifted = converted;
    drifted[0] *= 1 + 1e-12;
    CHECK(ch::checked_call(ch::aba, m, drifted, zero, zero));
}

TEST_CASE("a joint's armature: τ + a q̈, H_ii + a, the rotor's energy, and a massless joint it carries",
          "[chains][armature]") {
    std::mt19937_64 rng(46);
    ch::model<robot> m = make_robot(rng);
    ch::model<robot> bare = m;
    bare.link<1>().armature = 0;
    const auto q = random_q(rng);
    const auto qd = random_v(rng, 1.0), qdd = random_v(rng, 1.0);
    const auto tau = ch::rnea(m, q, qd, qdd), tau_bare = ch::rnea(bare, q, qd, qdd);
    for (std::size_t k = 0; k < robot::nv; ++k) CHECK(tau[k] == Approx(tau_bare[k] + (k == 6 ? 0.3 * qdd[k] : 0.0)).margin(1e-13));
    const auto H = ch::crba(m, q), H_bare = ch::crba(bare, q);
    for (std::size_t r = 0; r < robot::nv; ++r)
        for (std::size_t c = 0; c < robot::nv; ++c)
            CHECK(H[r][c] == Approx(H_bare[r][c] + (r == 6 && c == 6 ? 0.3 : 0.0)).margin(1e-13));
    CHECK(ch::tree_kinetic_energy(m, q, qd) == Approx(ch::tree_kinetic_energy(bare, q, qd) + 0.15 * qd[6] * qd[6]).epsilon(1e-14));
    const auto back = ch::aba(m, q, qd, tau);  // a mimic joint: ABA solves H q̈ = τ − C
    for (std::size_t k = 0; k < robot::nv; ++k) CHECK(back[k] == Approx(qdd[k]).margin(1e-11));
    const auto M = ch::rnea_derivatives(m, q, qd, qdd).M;
    for (std::size_t r = 0; r < robot::nv; ++r)
        for (std::size_t c = 0; c < robot::nv; ++c) CHECK(M(r, c) == Approx(H[r][c]).margin(1e-13));
    const auto Minv = ch::minverse(m, q);
    for (std::size_t r = 0; r < robot::nv; ++r)
        for (std::size_t c = 0; c < robot::nv; ++c) {
            double x = 0;
            for (std::size_t k = 0; k < robot::nv; ++k) x += Minv(r, k) * H[k][c];
            CHECK(x == Approx(r == c ? 1.0 : 0.0).margin(1e-12));
        }
    // a chain whose last joint carries no mass: refused, unless it has an armature, or (turning) a
    // rotational inertia
    using arm = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::with_armature<ch::revolute_y>>,
                         ch::link<1, ch::with_armature<ch::prismatic_x>>>;
    ch::model<arm> a;
    a.link<0>().inertia = ctga::body_inertia_of(*ctga::make_principal_mass_properties(1.0, 0.1, 0.1, 0.1));
    CHECK(ch::massless_subtree(a) == 1);
    a.link<1>().armature = 0.01;
    CHECK(ch::massless_subtree(a) == 2);
    a.link<2>().inertia = ctga::body_inertia_of(*ctga::make_mass_properties(
        0.0, ctga::vec3<double>{}, ctga::mat3<double>{{{0.1, 0, 0}, {0, 0.1, 0}, {0, 0, 0.1}}}, ctga::mass_check::as_given));
    CHECK(ch::massless_subtree(a) == 2);  // (a rotational inertia does not resist a prismatic joint)
    a.link<2>().armature = 0.5;
    CHECK(ch::massless_subtree(a) == -1);
    a.link<1>().armature = 0;
    CHECK(ch::massless_subtree(a) == -1);  // (body 2's rotational inertia resists the turning joint 1)
    a.link<1>().armature = -0.1;
    CHECK(ch::checked_call(ch::rnea, a, ch::configuration<arm>{}, ch::joint_vector<arm>{}, ch::joint_vector<arm>{}).error ==
          ctga::error_code::negative_armature);
}
