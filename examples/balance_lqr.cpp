// Balancing an inverted double pendulum upright by LQR on the exact linearisation of its forward
// dynamics (chains::aba_derivatives: Carpentier and Mansard's ∂q̈/∂q, ∂q̈/∂q̇ and ∂q̈/∂τ = H⁻¹).
//
// The model: two uniform rods on revolute joints about y, one on the world, one on the first's
// tip, BOTH joints actuated (a double pendulum with a motor at the shoulder and the elbow, not
// the underactuated acrobot). It is the smallest tree that is unstable in two modes, built from
// one joint type; with both joints driven the system is fully actuated (B = [0; H⁻¹] has rank 2),
// so the LQR design has no controllability margin to worry about and the example stays about the
// linearisation. The rods stand along +z of their joint frames, so q = 0 is the upright
// equilibrium, and there the gravity-compensating torque is 0.
//
// About x* = (q, q̇) = 0, τ = 0 the motion is ẋ = A x + B τ with
//   A = [[0, I], [∂q̈/∂q, ∂q̈/∂q̇]],   B = [[0], [∂q̈/∂τ]].
// For the controller period h it is discretised by the zero-order hold, [[A_d, B_d], [0, I]] =
// exp(h [[A, B], [0, 0]]) (the exponential by its series to 20 terms: ‖h A‖ < 0.1, far past rounding), the discrete
// algebraic Riccati equation
//   P = Q + A_dᵀ P A_d − A_dᵀ P B_d (R + B_dᵀ P B_d)⁻¹ B_dᵀ P A_d
// is solved by iterating it from P = Q (value iteration, to a fixed point), and
// K = (R + B_dᵀ P B_d)⁻¹ B_dᵀ P A_d. The nonlinear tree is then simulated by lie_rk4 with the
// actuation τ(q, q̇) = −K x (applied at every stage: with h = 1 ms this differs from a sampled
// controller by O(h)), and without it. The program fails unless A − B K is stable and the
// simulated pendulum settles (|q| < 1e-3 rad at the end).
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

#include <Eigen/Dense>
#include <ctga/chains/aba_derivatives.hpp>
#include <ctga/ctga.hpp>

namespace ch = ctga::chains;

int main() {
    using pendulum = ch::tree<ch::link<-1, ch::revolute_y>, ch::link<0, ch::revolute_y>>;
    constexpr int n = static_cast<int>(pendulum::nv);  // 2
    using Mat = Eigen::Matrix<double, 2 * n, 2 * n>;
    using Gain = Eigen::Matrix<double, n, 2 * n>;
    using Dofs = Eigen::Map<const Eigen::Matrix<double, n, n, Eigen::RowMajor>>;

    // 1. two uniform rods (mass m_i, length l_i) standing up: centre of mass at l_i / 2 on +z
    const double m1 = 1.0, l1 = 1.0, m2 = 0.5, l2 = 0.8;
    const auto rod = [](double mass, double l) {
        const double I = mass * l * l / 12, Iz = 1e-4 * mass;  // thin rod across, a little about its axis
        return ctga::make_mass_properties(mass, ctga::vec3<double>{0.0, 0.0, l / 2}, ctga::mat3<double>{{{I, 0, 0}, {0, I, 0}, {0, 0, Iz}}});
    };
    const auto at = [](double z) { return ctga::rigid_motion(ctga::make_translator(0.0, 0.0, z), ctga::make_rotor(0.0, 0.0, 0.0, 1.0)); };
    const auto shoulder = ch::make_link<ch::revolute_y>(at(0.0), rod(m1, l1));
    const auto elbow = ch::make_link<ch::revolute_y>(at(l1), rod(m2, l2));  // on the first rod's tip
    if (!shoulder || !elbow) {
        std::printf("invalid link: %s\n", ctga::describe(shoulder ? elbow.error : shoulder.error));
        return 1;
    }
    ch::model<pendulum> m;
    m.link<0>() = *shoulder;
    m.link<1>() = *elbow;

    // 2. the derivatives at the upright equilibrium
    const ch::configuration<pendulum> q_eq{};
    const ch::joint_vector<pendulum> qd_eq{}, tau_eq{};  // upright, gravity needs no torque
    const auto d = ch::aba_derivatives(m, q_eq, qd_eq, tau_eq);
    std::printf("upright equilibrium: qdd = (%.2e, %.2e) rad/s^2\n", d.qdd[0], d.qdd[1]);
    // a central-difference check of dqdd/dq (revolute joints: the tangent space is q itself)
    double fd_error = 0;
    for (std::size_t j = 0; j < pendulum::nv; ++j) {
        ch::configuration<pendulum> qp = q_eq, qm = q_eq;
        qp[j] += 1e-6;
        qm[j] -= 1e-6;
        const auto ap = ch::aba(m, qp, qd_eq, tau_eq), am = ch::aba(m, qm, qd_eq, tau_eq);
        for (std::size_t i = 0; i < pendulum::nv; ++i) fd_error = std::max(fd_error, std::abs((ap[i] - am[i]) / 2e-6 - d.dqdd_dq(i, j)));
    }
    std::printf("dqdd/dq = [[%.4f, %.4f], [%.4f, %.4f]] 1/s^2 (central differences agree to %.1e)\n", d.dqdd_dq(0, 0),
                d.dqdd_dq(0, 1), d.dqdd_dq(1, 0), d.dqdd_dq(1, 1), fd_error);

    // 3. x = (q, q̇): A, B; zero-order hold for h; the discrete Riccati equation by iteration
    Mat A = Mat::Zero();
    Eigen::Matrix<double, 2 * n, n> B = Eigen::Matrix<double, 2 * n, n>::Zero();
    A.topRightCorner<n, n>().setIdentity();
    A.bottomLeftCorner<n, n>() = Dofs(d.dqdd_dq.data());
    A.bottomRightCorner<n, n>() = Dofs(d.dqdd_dv.data());
    B.bottomRows<n>() = Dofs(d.Minv.data());
    const double h = 1e-3;
    Eigen::Matrix<double, 3 * n, 3 * n> M = Eigen::Matrix<double, 3 * n, 3 * n>::Zero(), term, Phi;
    M.topLeftCorner<2 * n, 2 * n>() = h * A;
    M.topRightCorner<2 * n, n>() = h * B;
    term.setIdentity();
    Phi.setIdentity();
    for (int k = 1; k <= 20; ++k) Phi += (term = term * M / k);
    const Mat Ad = Phi.topLeftCorner<2 * n, 2 * n>();
    const Eigen::Matrix<double, 2 * n, n> Bd = Phi.topRightCorner<2 * n, n>();
    const Mat Q = Eigen::Vector4d(100, 100, 1, 1).asDiagonal();  // weights on q, q̇
    const Eigen::Matrix2d R = Eigen::Matrix2d::Identity();         // on τ
    Mat P = Q;
    Gain K = Gain::Zero();
    int iterations = 0;
    for (double change = 1; change > 1e-10 && iterations < 200'000; ++iterations) {
        K = (R + Bd.transpose() * P * Bd).ldlt().solve(Bd.transpose() * P * Ad);
        const Mat next = Q + Ad.transpose() * P * (Ad - Bd * K);
        change = (next - P).cwiseAbs().maxCoeff() / P.cwiseAbs().maxCoeff();
        P = 0.5 * (next + next.transpose());
    }
    K = (R + Bd.transpose() * P * Bd).ldlt().solve(Bd.transpose() * P * Ad);
    std::printf("discrete LQR, h = %.0f ms, Q = diag(100, 100, 1, 1), R = I: Riccati converged in %d iterations\n", 1e3 * h, iterations);
    std::printf("K = [[%8.3f %8.3f %8.3f %8.3f]\n     [%8.3f %8.3f %8.3f %8.3f]]\n", K(0, 0), K(0, 1), K(0, 2), K(0, 3), K(1, 0),
                K(1, 1), K(1, 2), K(1, 3));

    // 4. eigenvalues: open loop A, closed loop A − B K (and the sampled loop's spectral radius)
    const auto print_eigenvalues = [](const char* label, const Mat& X) {
        const Eigen::Vector4cd lambda = Eigen::EigenSolver<Mat>(X).eigenvalues();
        double max_real = -1e300;
        std::printf("%s:", label);
        for (int i = 0; i < 2 * n; ++i) {
            std::printf("  %+.4f%+.4fi", lambda[i].real(), lambda[i].imag());
            max_real = std::max(max_real, lambda[i].real());
        }
        std::printf("\n");
        return max_real;
    };
    const double open_real = print_eigenvalues("eigenvalues of A        (open loop)  ", A);
    const double closed_real = print_eigenvalues("eigenvalues of A - B K  (closed loop)", A - B * K);
    const double radius = Eigen::EigenSolver<Mat>(Ad - Bd * K).eigenvalues().cwiseAbs().maxCoeff();
    std::printf("open loop %s (largest real part %+.4f); closed loop %s (largest real part %+.4f); "
                "spectral radius of A_d - B_d K %.6f\n",
                open_real > 0 ? "unstable" : "stable", open_real, closed_real < 0 ? "stable" : "UNSTABLE", closed_real, radius);

    // 5. the nonlinear tree from a perturbed start, with τ = −K x and without feedback
    const auto lqr = [K](const ch::configuration<pendulum>& q, const ch::joint_vector<pendulum>& qd) {
        const Eigen::Vector4d x(q[0], q[1], qd[0], qd[1]);
        const Eigen::Vector2d tau = -K * x;
        return ch::joint_vector<pendulum>{tau[0], tau[1]};
    };
    const ch::tree_motion<pendulum, double, decltype(lqr)> sim{m, lqr};
    const ctga::motion_state<ch::coordinates<2>, ch::coordinates<2>> x0{{{0.1, -0.05}}, {{0.0, 0.0}}};
    const double tol = 1e-3;
    const long long steps = 5000;  // 5 s
    double last_outside = 0;       // the last time |q| ≥ tol
    std::printf("balanced from q = (0.1, -0.05) rad, lie_rk4, h = 1 ms:\n    t      q1        q2        qd1       qd2      tau1      tau2\n");
    const auto report = [&](double t, const auto& x) {
        const auto tau = lqr(x.g.x, x.s.x);
        std::printf("  %4.2f %9.5f %9.5f %9.5f %9.5f %9.4f %9.4f\n", t, x.g[0], x.g[1], x.s[0], x.s[1], tau[0], tau[1]);
    };
    report(0, x0);
    const auto run = ctga::integrate(ctga::lie_rk4{}, sim, x0, h, steps, [&](long long k, const auto& x) {
        const double t = h * static_cast<double>(k);
        if (std::max(std::abs(x.g[0]), std::abs(x.g[1])) >= tol) last_outside = t;
        if (k % 250 == 0) report(t, x);
    });
    if (!run) {
        std::printf("simulation stopped: %s\n", ctga::describe(run.error));
        return 1;
    }
    const double q_end = std::max(std::abs(run.state.g[0]), std::abs(run.state.g[1]));
    const bool settled = q_end < tol;
    std::printf("settled: |q| < %.0e rad from t = %.3f s on (|q| = %.1e rad at %.0f s)\n", tol, last_outside + h, q_end,
                h * static_cast<double>(steps));

    const ch::tree_motion<pendulum> fall{m};  // no feedback
    double fell_at = -1;
    const auto dropped = ctga::integrate(ctga::lie_rk4{}, fall, x0, h, steps, [&](long long k, const auto& x) {
        if (fell_at < 0 && std::max(std::abs(x.g[0]), std::abs(x.g[1])) > 0.5) fell_at = h * static_cast<double>(k);
    });
    if (!dropped) {
        std::printf("simulation stopped: %s\n", ctga::describe(dropped.error));
        return 1;
    }
    if (fell_at >= 0) std::printf("without feedback it falls: |q| > 0.5 rad at t = %.3f s\n", fell_at);
    else std::printf("without feedback |q| stayed below 0.5 rad for %.0f s\n", h * static_cast<double>(steps));
    return closed_real < 0 && settled ? 0 : 1;
}
