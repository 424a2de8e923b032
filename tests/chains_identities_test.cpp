// Kinematic trees checked by identities that need no reference, by a closed-form solution, and
// by their answers to bad input:
//   - ABA(q, q̇, RNEA(q, q̇, q̈)) = q̈; M(q) symmetric positive definite and
//     M q̈ + RNEA(q, q̇, 0) = RNEA(q, q̇, q̈), on a 7-dof arm and on a floating base with four limbs;
//   - power balance dE/dt = q̇ᵀτ along a simulated trajectory (E(T) − E(0) = ∫ q̇ᵀτ dt);
//   - a pendulum's period against the closed form 4 K(sin(θ₀/2)) / ω₀ (Boost.Math);
//   - the implicit midpoint keeping an unactuated arm's energy;
//   - NaN, infinite or out-of-domain q, q̇, τ, invalid inertias and axes: reported errors.
// PARTS: 2
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <Eigen/Dense>
#include <boost/math/special_functions/ellint_1.hpp>

#include <ctga/chains/algorithms.hpp>
#include <ctga/chains/motion.hpp>
#include <ctga/integrators/integrate.hpp>

#include "support/catch.hpp"
#include "support/parts.hpp"

namespace {

namespace ch = ctga::chains;

using arm7 = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_y>, ch::link<1, ch::revolute_z>,
                      ch::link<2, ch::revolute_y>, ch::link<3, ch::revolute_z>, ch::link<4, ch::revolute_y>,
                      ch::link<5, ch::revolute_about>>;
// a trunk on a floating joint and four legs: hip (x), thigh (y), knee (y; one leg prismatic), a fixed foot
using legged = ch::tree<ch::link<-1, ch::floating>, ch::link<0, ch::revolute_x>, ch::link<1, ch::revolute_y>,
                        ch::link<2, ch::revolute_y>, ch::link<3, ch::fixed>, ch::link<0, ch::revolute_x>,
                        ch::link<5, ch::revolute_y>, ch::link<6, ch::revolute_y>, ch::link<7, ch::fixed>,
                        ch::link<0, ch::revolute_x>, ch::link<9, ch::revolute_y>, ch::link<10, ch::prismatic_z>,
                        ch::link<11, ch::fixed>, ch::link<0, ch::revolute_x>, ch::link<13, ch::revolute_y>,
                        ch::link<14, ch::revolute_y>, ch::link<15, ch::fixed>>;

double uniform(std::mt19937_64& rng, double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// Mass properties with principal second moments m g² (so the triangle inequality holds), turned
// by a rotation about a random axis.
ctga::checked<ctga::mass_properties<double>> random_mass(std::mt19937_64& rng) {
    const double m = uniform(rng, 0.5, 3.0);
    std::array<double, 3> s{};
    for (double& x : s) x = m * std::pow(uniform(rng, 0.05, 0.2), 2);
    const Eigen::Vector3d principal(s[1] + s[2], s[0] + s[2], s[0] + s[1]);
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(uniform(rng, -3, 3), Eigen::Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), 1).normalized())
            .toRotationMatrix();
    const Eigen::Matrix3d I = R * principal.asDiagonal() * R.transpose();
    ctga::mat3<double> Ic{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) Ic[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = 0.5 * (I(r, c) + I(c, r));
    return ctga::make_mass_properties(m, ctga::vec3<double>{uniform(rng, -0.1, 0.1), uniform(rng, -0.1, 0.1), uniform(rng, 0, 0.2)}, Ic);
}

// Each joint frame 0.3 m along the parent's z (turned a little about x), random inertias; the last
// arm joint about a general unit axis.
template <class Tree>
ch::model<Tree> make_model(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    ch::model<Tree> m;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            using J = typename Tree::template joint_at<I>;
            const double z = Tree::parent[I] < 0 ? 0.1 : 0.3;
            const ctga::motor<double> placement =
                ctga::rigid_motion(ctga::make_translator(uniform(rng, -0.05, 0.05), uniform(rng, -0.05, 0.05), z),
                                   ctga::make_rotor(uniform(rng, -0.3, 0.3), 1.0, 0.0, 0.0));
            const auto mass = random_mass(rng);
            const auto link = [&] {
                if constexpr (ch::has_run_time_axis<J>) return ch::make_link<J>(placement, mass, ctga::vec3<double>{0.0, 0.6, 0.8});
                else return ch::make_link<J>(placement, mass);
            }();
            REQUIRE(link);
            m.template link<I>() = *link;
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    return m;
}

template <class Tree>
ch::configuration<Tree> random_q(std::mt19937_64& rng) {
    ch::configuration<Tree> q{};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            double* x = q.data() + Tree::q_offset[I];
            if constexpr (Tree::nq_of[I] == 8) {
                const Eigen::Vector3d u = Eigen::Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), 1).normalized();
                const ctga::motor<double> g =
                    ctga::rigid_motion(ctga::make_translator(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, 0, 1)),
                                       ctga::make_rotor(uniform(rng, -3, 3), u[0], u[1], u[2]));
                for (std::size_t k = 0; k < 8; ++k) x[k] = g[k];
            } else if constexpr (Tree::nq_of[I] == 1) {
                x[0] = uniform(rng, -2, 2);
            }
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    return q;
}
template <class Tree>
ch::joint_vector<Tree> random_v(std::mt19937_64& rng, double scale) {
    ch::joint_vector<Tree> v{};
    for (double& x : v) x = uniform(rng, -scale, scale);
    return v;
}

template <std::size_t N>
double max_abs_difference(const std::array<double, N>& a, const std::array<double, N>& b) {
    double e = 0;
    for (std::size_t i = 0; i < N; ++i) e = std::max(e, std::abs(a[i] - b[i]));
    return e;
}
template <std::size_t N>
double max_abs(const std::array<double, N>& a) {
    double e = 1;
    for (double x : a) e = std::max(e, std::abs(x));
    return e;
}

template <class Tree>
void check_dynamics_identities(std::uint64_t seed) {
    const ch::model<Tree> m = make_model<Tree>(seed);
    std::mt19937_64 rng(seed + 1);
    for (int n = 0; n < 20; ++n) {
        const auto q = random_q<Tree>(rng);
        const auto qd = random_v<Tree>(rng, 2), qdd = random_v<Tree>(rng, 3);
        const auto tau = ch::rnea(m, q, qd, qdd);
        // ABA ∘ RNEA = identity
        const auto qdd2 = ch::aba(m, q, qd, tau);
        CHECK(max_abs_difference(qdd2, qdd) <= 1e-12 * max_abs(qdd));
        // M q̈ + C(q, q̇) = τ
        const auto H = ch::crba(m, q);
        const auto bias = ch::rnea(m, q, qd, ch::joint_vector<Tree>{});
        ch::joint_vector<Tree> Hqdd{};
        Eigen::MatrixXd He(Tree::nv, Tree::nv);
        for (std::size_t r = 0; r < Tree::nv; ++r)
            for (std::size_t c = 0; c < Tree::nv; ++c) {
                Hqdd[r] += H[r][c] * qdd[c];
                He(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = H[r][c];
                CHECK(H[r][c] == H[c][r]);  // symmetric exactly: each entry is computed once
            }
        for (std::size_t r = 0; r < Tree::nv; ++r) CHECK(std::abs(Hqdd[r] + bias[r] - tau[r]) <= 1e-12 * max_abs(tau));
        // positive definite: every eigenvalue of the symmetric H is > 0
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(He);
        CHECK(eig.eigenvalues().minCoeff() > 0);
        // kinetic energy ½ q̇ᵀ M q̇
        double quad = 0;
        for (std::size_t r = 0; r < Tree::nv; ++r)
            for (std::size_t c = 0; c < Tree::nv; ++c) quad += 0.5 * qd[r] * H[r][c] * qd[c];
        CHECK(std::abs(ch::tree_kinetic_energy(m, q, qd) - quad) <= 1e-12 * std::max(1.0, quad));
    }
}

// τ = −c q̇ + k sin(q) per 1-dof joint: a damped, driven arm
struct damped_drive {
    template <std::size_t NQ, std::size_t NV>
    constexpr std::array<double, NV> operator()(const std::array<double, NQ>& q, const std::array<double, NV>& qd) const noexcept {
        std::array<double, NV> tau{};
        for (std::size_t i = 0; i < NV; ++i) tau[i] = -0.3 * qd[i] + 2.0 * std::sin(q[i]);
        return tau;
    }
};

}  // namespace

#if CTGA_TEST_PART_HOLDS(0)
TEST_CASE("chains: ABA inverts RNEA, the mass matrix is symmetric positive definite and M q̈ + C = τ" CTGA_TEST_PART_NAME) {
    SECTION("7-dof arm") { check_dynamics_identities<arm7>(101); }
    SECTION("floating base with four limbs") { check_dynamics_identities<legged>(202); }
}

TEST_CASE("chains: power balance, E(T) − E(0) = ∫ q̇ᵀτ dt along a simulated arm trajectory" CTGA_TEST_PART_NAME) {
    const ch::tree_motion<arm7, double, damped_drive> sim{make_model<arm7>(303)};
    std::mt19937_64 rng(304);
    typename decltype(sim)::motor_type q{random_q<arm7>(rng)};
    typename decltype(sim)::screw_type qd{random_v<arm7>(rng, 1)};
    const double h = 2.5e-4;
    const auto power = [&](const auto& x) {
        const auto tau = sim.actuation(x.g.x, x.s.x);
        double p = 0;
        for (std::size_t i = 0; i < arm7::nv; ++i) p += x.s.x[i] * tau[i];
        return p;
    };
    ctga::motion_state<decltype(q), decltype(qd)> x{q, qd};
    const double E0 = sim.energy(x.g, x.s);
    // Simpson's rule over pairs of steps: the integral to O(h⁴), as RK4's trajectory
    double work = 0, p_prev = power(x);
    const int pairs = 2000;
    for (int n = 0; n < pairs; ++n) {
        const auto mid = ctga::rk4{}.step(sim, x, h);
        REQUIRE(mid);
        const auto end = ctga::rk4{}.step(sim, mid.value, h);
        REQUIRE(end);
        const double p_end = power(end.value);
        work += (2 * h / 6) * (p_prev + 4 * power(mid.value) + p_end);
        p_prev = p_end;
        x = end.value;
    }
    const double E1 = sim.energy(x.g, x.s);
    INFO("E0 " << E0 << " E1 " << E1 << " work " << work);
    CHECK(std::abs(work) > 0.1);  // the drive does work
    CHECK(std::abs((E1 - E0) - work) <= 1e-9 * std::max(std::abs(E0), std::abs(work)));
}
#endif

#if CTGA_TEST_PART_HOLDS(1)
TEST_CASE("chains: a pendulum's period matches 4 K(sin(θ₀/2)) / ω₀" CTGA_TEST_PART_NAME) {
    // a body on a revolute joint about y, centre of mass l below the pivot
    using pendulum = ch::tree<ch::link<-1, ch::revolute_y>>;
    const double mass = 1.3, l = 0.7, Ic = 0.02;
    ch::model<pendulum> m;
    const auto link = ch::make_link<ch::revolute_y>(
        ctga::rigid_motion(ctga::make_translator(0.0, 0.0, 0.0), ctga::make_rotor(0.0, 0.0, 0.0, 1.0)),
        ctga::make_mass_properties(mass, ctga::vec3<double>{0.0, 0.0, -l}, ctga::mat3<double>{{{Ic, 0.0, 0.0}, {0.0, Ic, 0.0}, {0.0, 0.0, Ic}}}));
    REQUIRE(link);
    m.link<0>() = *link;
    const double g = 9.81, I_pivot = Ic + mass * l * l, omega0 = std::sqrt(mass * g * l / I_pivot);
    for (const double theta0 : {0.3, 1.5, 2.8}) {
        const double period = 4 * boost::math::ellint_1(std::sin(theta0 / 2)) / omega0;
        const ch::tree_motion<pendulum> sim{m};
        // released at rest at θ₀ (about y: θ > 0 swings the centre of mass towards −x … either sign
        // of rotation is a swing): find the times θ̇ changes sign, interpolated, a half period apart
        ctga::motion_state<ch::coordinates<1>, ch::coordinates<1>> x{{{theta0}}, {{0.0}}};
        const double h = 1e-4;
        double t = 0, previous_qd = 0;
        std::array<double, 3> turns{};
        int found = 0;
        while (found < 3 && t < 5 * period) {
            const auto next = ctga::rk4{}.step(sim, x, h);
            REQUIRE(next);
            const double qd1 = next.value.s[0];
            if (t > 0 && (previous_qd < 0) != (qd1 < 0) && qd1 != 0) turns[static_cast<std::size_t>(found++)] = t + h * previous_qd / (previous_qd - qd1);
            previous_qd = qd1;
            x = next.value;
            t += h;
        }
        REQUIRE(found == 3);
        INFO("theta0 " << theta0 << " period " << period << " measured " << (turns[2] - turns[0]));
        // the linear interpolation of θ̇ near a turn is exact to O(h²) in the time
        CHECK(std::abs((turns[2] - turns[0]) - period) <= 1e-7 * period);
    }
}

TEST_CASE("chains: the implicit midpoint keeps an unactuated arm's energy" CTGA_TEST_PART_NAME) {
    const ch::tree_motion<arm7> sim{make_model<arm7>(505)};
    std::mt19937_64 rng(506);
    ctga::motion_state<ch::coordinates<7>, ch::coordinates<7>> x{{random_q<arm7>(rng)}, {random_v<arm7>(rng, 1)}};
    const double E0 = sim.energy(x.g, x.s);
    double worst = 0;
    const auto run = ctga::integrate(ctga::implicit_midpoint{}, sim, x, 1e-5, 10'000, [&](long long, const auto& y) {
        worst = std::max(worst, std::abs(sim.energy(y.g, y.s) - E0));
    });
    REQUIRE(run);
    INFO("E0 " << E0 << " worst drift " << worst);
    CHECK(worst <= 1e-10 * std::abs(E0));
}

#if CTGA_TEST_PART_HOLDS(1)
// The implicit midpoint on a tree solves its step by Newton's method with aba_derivatives'
// ∂q̈/∂(q, q̇) (integrators/methods.hpp: ∂F/∂s₁ = 1 − h(½ ∂a/∂q̇ + ¼ h ∂a/∂q)) or by the fixed-point
// iteration: the same step to the convergence tolerance, in fewer iterations.
template <class Tree>
void newton_against_fixed_point(std::uint64_t seed, double h, int steps) {
    const ch::tree_motion<Tree> sim{make_model<Tree>(seed)};
    std::mt19937_64 rng(seed + 1);
    ctga::motion_state<ch::coordinates<Tree::nq>, ch::coordinates<Tree::nv>> x{{random_q<Tree>(rng)}, {random_v<Tree>(rng, 1)}};
    long newton_iterations = 0, fixed_point_iterations = 0;
    const ctga::implicit_midpoint newton{.iterations = &newton_iterations};
    const ctga::implicit_midpoint fixed_point{.solver = ctga::implicit_solver::fixed_point, .iterations = &fixed_point_iterations};
    double worst = 0;
    for (int k = 0; k < steps; ++k) {
        const auto a = newton.step(sim, x, h), b = fixed_point.step(sim, x, h);
        REQUIRE(a);
        REQUIRE(b);
        for (std::size_t i = 0; i < Tree::nv; ++i) worst = std::max(worst, std::abs(a.value.s[i] - b.value.s[i]));
        x = a.value;
    }
    const double per_step_newton = double(newton_iterations) / steps, per_step_fixed = double(fixed_point_iterations) / steps;
    INFO("iterations per step: Newton " << per_step_newton << ", fixed point " << per_step_fixed << "; worst difference " << worst);
    CHECK(worst <= 1e-12 * std::max(1.0, sim.magnitude(x.s)));
    CHECK(per_step_newton < per_step_fixed);
    WARN("implicit midpoint, h = " << h << ", " << Tree::nv << " dofs: iterations per step, Newton " << per_step_newton
                                   << ", fixed point " << per_step_fixed);
}
TEST_CASE("chains: the implicit midpoint's Newton iteration on a tree converges to the fixed point's step in fewer iterations" CTGA_TEST_PART_NAME) {
    newton_against_fixed_point<arm7>(811, 1e-3, 200);
    newton_against_fixed_point<legged>(812, 1e-3, 100);
}
#endif

TEST_CASE("chains: a floating base moves on the group: lie_rk4 keeps its motor a unit motor" CTGA_TEST_PART_NAME) {
    const ch::tree_motion<legged> sim{make_model<legged>(707)};
    std::mt19937_64 rng(708);
    ctga::motion_state<ch::coordinates<legged::nq>, ch::coordinates<legged::nv>> x{{random_q<legged>(rng)}, {random_v<legged>(rng, 1)}};
    const double E0 = sim.energy(x.g, x.s);
    const auto run = ctga::integrate(ctga::lie_rk4{}, sim, x, 1e-4, 2'000);
    REQUIRE(run);
    const ctga::motor<double> g{run.state.g[0], run.state.g[1], run.state.g[2], run.state.g[3],
                                run.state.g[4], run.state.g[5], run.state.g[6], run.state.g[7]};
    const auto defect = ctga::unit_defect(g);
    CHECK(std::abs(defect.alpha_norm) < 1e-12);
    CHECK(std::abs(defect.alpha_beta) < 1e-12);
    // no forces but gravity: energy kept to the method's accuracy
    CHECK(std::abs(sim.energy(run.state.g, run.state.s) - E0) <= 1e-8 * std::abs(E0));
}

TEST_CASE("chains: bad input is reported, never a silent NaN" CTGA_TEST_PART_NAME) {
    const ch::model<arm7> m = make_model<arm7>(909);
    std::mt19937_64 rng(910);
    const auto q = random_q<arm7>(rng);
    const auto qd = random_v<arm7>(rng, 1), tau = random_v<arm7>(rng, 1);
    REQUIRE(ch::checked_call(ch::aba, m, q, qd, tau));
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    SECTION("NaN or infinite q, q̇, τ") {
        for (std::size_t i = 0; i < 7; ++i)
            for (const double bad : {nan, inf, -inf}) {
                auto q1 = q, qd1 = qd, tau1 = tau;
                q1[i] = bad;
                CHECK(ch::checked_call(ch::aba, m, q1, qd, tau).error == ctga::error_code::non_finite);
                CHECK(ch::checked_call(ch::rnea, m, q1, qd, tau).error == ctga::error_code::non_finite);
                CHECK(ch::checked_call(ch::crba, m, q1).error == ctga::error_code::non_finite);
                qd1[i] = bad;
                CHECK(ch::checked_call(ch::aba, m, q, qd1, tau).error == ctga::error_code::non_finite);
                CHECK(ch::checked_call(ch::tree_kinetic_energy, m, q, qd1).error == ctga::error_code::non_finite);
                tau1[i] = bad;
                CHECK(ch::checked_call(ch::aba, m, q, qd, tau1).error == ctga::error_code::non_finite);
            }
    }
    SECTION("a result that overflows") {
        auto qd1 = qd;
        qd1[3] = 1e200;
        CHECK(ch::checked_call(ch::rnea, m, q, qd1, tau).error == ctga::error_code::non_finite);
    }
    SECTION("NaN gravity") {
        auto m1 = m;
        m1.gravity[2] = nan;
        CHECK(ch::checked_call(ch::aba, m1, q, qd, tau).error == ctga::error_code::non_finite);
    }
    SECTION("a floating base's configuration that is no motor") {
        const ch::model<legged> ml = make_model<legged>(911);
        auto ql = random_q<legged>(rng);
        REQUIRE(ch::checked_call(ch::crba, ml, ql));
        for (std::size_t k = 0; k < 4; ++k) ql[k] = 0;
        CHECK(ch::checked_call(ch::crba, ml, ql).error == ctga::error_code::not_a_unit_base);
    }
    SECTION("invalid inertias and axes, when the model is built") {
        const ctga::motor<double> g = ctga::rigid_motion(ctga::make_translator(0.0, 0.0, 0.3), ctga::make_rotor(0.0, 0.0, 0.0, 1.0));
        const auto ok = ctga::make_principal_mass_properties(1.0, 0.1, 0.1, 0.1);
        CHECK(ch::make_link<ch::revolute_z>(g, ok));
        CHECK(ch::make_link<ch::revolute_z>(g, ctga::make_principal_mass_properties(0.0, 0.1, 0.1, 0.1)).error ==
              ctga::error_code::non_positive_mass);
        CHECK(ch::make_link<ch::revolute_z>(g, ctga::make_principal_mass_properties(1.0, 0.1, 0.1, 0.5)).error ==
              ctga::error_code::triangle_inequality);
        CHECK(ch::make_link<ch::revolute_z>(g, ctga::make_principal_mass_properties(1.0, -0.1, 0.1, 0.1)).error ==
              ctga::error_code::not_positive_definite);
        CHECK(ch::make_link<ch::revolute_about>(g, ok, ctga::vec3<double>{0.0, 0.6, 0.81}).error == ctga::error_code::not_a_unit_axis);
        CHECK(ch::make_link<ch::prismatic_along>(g, ok, ctga::vec3<double>{0.0, 0.0, 0.0}).error == ctga::error_code::not_a_unit_axis);
        CHECK(ch::make_link<ch::revolute_about>(g, ok, ctga::vec3<double>{nan, 0.0, 1.0}).error == ctga::error_code::non_finite);
        CHECK(ch::make_link<ch::revolute_z>(ctga::motor<double>{}, ok).error == ctga::error_code::not_a_motor);
        // an aligned joint's placement must be a translation: turned turns by 1 rad about z; g, a
        // translation, is accepted
        const ctga::motor<double> turned = ctga::rigid_motion(ctga::make_translator(0.0, 0.0, 0.3), ctga::make_rotor(1.0, 0.0, 0.0, 1.0));
        CHECK(ch::make_link<ch::aligned<ch::revolute_z>>(turned, ok).error == ctga::error_code::not_aligned);
        CHECK(ch::make_link<ch::aligned<ch::floating>>(turned, ok).error == ctga::error_code::not_aligned);
        CHECK(ch::make_link<ch::aligned<ch::revolute_z>>(g, ok));
        const ctga::motor<double> shifted = ctga::motor<double>(ctga::make_translator(0.1, -0.2, 0.3));
        const auto aligned_link = ch::make_link<ch::aligned<ch::revolute_z>>(shifted, ok);
        REQUIRE(aligned_link);
        CHECK(aligned_link->placement.t == ctga::vec3<double>{0.1, -0.2, 0.3});
        // a turn of 1e-9 rad is no rounding: refused too
        const ctga::motor<double> nearly = ctga::rigid_motion(ctga::make_translator(0.1, 0.0, 0.0), ctga::make_rotor(1e-9, 0.0, 0.0, 1.0));
        CHECK(ch::make_link<ch::aligned<ch::prismatic_x>>(nearly, ok).error == ctga::error_code::not_aligned);
        // a placement far from a unit motor is refused, not renormalised into another motion: the
        // rotor cos ½ + 5 sin ½ e1e2 (an axis (0, 0, 5) used as if unit) would have become a
        // rotation by 2.44 rad
        const ctga::motor<double> far{std::cos(0.5), 0.0, 0.0, 5 * std::sin(0.5), 0.0, 0.0, 0.0, 0.3};
        CHECK(ch::make_link<ch::revolute_z>(far, ok).error == ctga::error_code::not_a_motor);
        // rounding-sized drift is repaired: the link's frame is the motor's own rotation
        ctga::motor<double> drifted = ctga::make_rotor(1.0, 0.0, 0.0, 1.0);
        for (std::size_t k = 0; k < 4; ++k) drifted[k] *= 1 + 1e-12;
        const auto repaired = ch::make_link<ch::revolute_z>(drifted, ok);
        REQUIRE(repaired);
        CHECK(std::abs(repaired->placement.R[0][0] - std::cos(1.0)) <= 1e-15);
        CHECK(std::abs(repaired->placement.R[1][0] - std::sin(1.0)) <= 1e-15);
    }
    SECTION("a model edited after it was built: every number of it is checked") {
        auto m1 = m;
        m1.link<3>().inertia.ixy = ctga::cl062::mv<double, "1">{nan};
        CHECK(ch::checked_call(ch::rnea, m1, q, qd, tau).error == ctga::error_code::non_finite);
        auto m2 = m;
        m2.link<5>().placement.t[1] = nan;
        CHECK(ch::checked_call(ch::crba, m2, q).error == ctga::error_code::non_finite);
        auto m3 = m;
        m3.link<0>().inertia.m = ctga::cl062::mv<double, "1">{std::numeric_limits<double>::infinity()};
        CHECK(ch::checked_call(ch::aba, m3, q, qd, tau).error == ctga::error_code::non_finite);
        REQUIRE(ch::checked_call(ch::aba, m, q, qd, tau));
    }
    SECTION("a simulation started from a NaN state stops at once") {
        const ch::tree_motion<arm7> sim{m};
        auto qd1 = qd;
        qd1[2] = nan;
        const auto run = ctga::integrate(ctga::rk4{}, sim, {{q}, {qd1}}, 1e-3, 10);
        CHECK(run.error == ctga::error_code::non_finite);
        CHECK(run.steps == 0);
    }
}
#endif
