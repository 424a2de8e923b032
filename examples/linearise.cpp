// Linearising one body's motion about a steady spin with the exact compile-time Jacobian.
//
// A free body in its own frame moves by ṡ = E ∨ (M ∧ (W − {s, A ∨ (N ∧ s)})) (§6; the formula
// ctga::motion_rate). About a steady spin s₀ = Ω e_k (an equilibrium: {s₀, N s₀} = 0 for a
// principal axis), a small disturbance x = s − s₀ and a small wrench u obey ẋ = A x + B u with
//   A = ∂ṡ/∂s (s₀),   B = ∂ṡ/∂W,
// both from ctga::jacobian: straight-line code, computed from the formula's normal form at
// compile time. The spin about the axis of the intermediate moment is unstable (the tennis
// racket theorem): A has a real positive eigenvalue Ω √((I₂−I₁)(I₃−I₂)/(I₁I₃)); about the
// smallest and the largest moments its eigenvalues are imaginary (or zero). The example prints
// them (Eigen's eigenvalue solver) and checks them against that formula.
#include <cmath>
#include <complex>
#include <cstdio>

#include <Eigen/Eigenvalues>
#include <ctga/ctga.hpp>

int main() {
    using namespace ctga;
    // a box 0.1 × 0.2 × 0.3 m of 1.2 kg, centre of mass at the origin: I₁ < I₂ < I₃
    const double m = 1.2, a = 0.1, b = 0.2, c = 0.3;
    const double I1 = m * (b * b + c * c) / 12, I2 = m * (a * a + c * c) / 12, I3 = m * (a * a + b * b) / 12;
    // principal axes: the largest moment about x (I3), the intermediate about y (I2), the smallest about z (I1)
    const auto body = make_rigid_body(m, vec3<double>{0, 0, 0}, mat3<double>{{{I3, 0, 0}, {0, I2, 0}, {0, 0, I1}}});
    if (!body) {
        std::printf("invalid body: %s\n", describe(body.error));
        return 1;
    }
    const double Omega = 4.0;  // rad/s
    const char* axis_name[3] = {"x (largest moment)", "y (intermediate)", "z (smallest)"};
    const double moment[3] = {I3, I2, I1};
    constexpr std::size_t rows = 6;
    int failures = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        screw<double> s0{};
        s0[k] = Omega;
        const wrench<double> W{};
        const auto A = jacobian<2, lifted_screw<double>>(motion_rate, body->Nb, body->M, s0, W);
        const auto B = jacobian<3, lifted_screw<double>>(motion_rate, body->Nb, body->M, s0, W);
        Eigen::Matrix<double, 6, 6> Ad;
        const auto dense = A.dense();
        for (std::size_t r = 0; r < rows; ++r)
            for (std::size_t j = 0; j < rows; ++j) Ad(static_cast<int>(r), static_cast<int>(j)) = dense[r][j];
        const Eigen::VectorXcd lambda = Eigen::EigenSolver<Eigen::Matrix<double, 6, 6>>(Ad).eigenvalues();
        std::printf("spin %.1f rad/s about %s: A has %zu structurally non-zero entries, B %zu\n  eigenvalues:", Omega,
                    axis_name[k], decltype(A)::non_zeros, decltype(B)::non_zeros);
        double max_real = -1e300;
        for (int i = 0; i < 6; ++i) {
            std::printf(" %+.4f%+.4fi", lambda[i].real(), lambda[i].imag());
            max_real = std::max(max_real, lambda[i].real());
        }
        // the two moments other than the spin axis's
        const double Ia = moment[(k + 1) % 3], Ib = moment[(k + 2) % 3], Ik = moment[k];
        const double d = (Ik - Ia) * (Ik - Ib) / (Ia * Ib);  // λ² = −Ω² d: real when d < 0 (intermediate)
        const double expected = d < 0 ? Omega * std::sqrt(-d) : 0.0;
        std::printf("\n  largest real part %.6f, expected %.6f (%s)\n", max_real, expected,
                    d < 0 ? "unstable: the tennis racket" : "stable: a centre");
        if (std::abs(max_real - expected) > 1e-9 * (1 + expected)) ++failures;
    }
    std::printf("cost of A = ∂ṡ/∂s: %zu multiplications, %zu additions\n",
                cost_of<decltype(jacobian<2, lifted_screw<double>>(motion_rate, body->Nb, body->M, screw<double>{},
                                                                   wrench<double>{}))>.mul,
                cost_of<decltype(jacobian<2, lifted_screw<double>>(motion_rate, body->Nb, body->M, screw<double>{},
                                                                   wrench<double>{}))>.add);
    return failures == 0 ? 0 : 1;
}
