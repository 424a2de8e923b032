// The tennis-racket (Dzhanibekov) effect: a free body spun about its intermediate principal axis
// flips over, again and again, at regular intervals.
//
// Principal moments I = (1, 2, 3) (mass 1, centre of mass at the body origin), body-frame angular
// momentum m0 = (0.01, 2, 0.01): almost a pure spin about the intermediate axis e2, ω = I⁻¹ m =
// (0.01, 1, 0.0033). Integrated in the body frame with ctga::lie_rk4 at h = 0.01 for 200 s. Each
// flip is a sign change of ω2; m(t) is periodic with period 42.91 s (Euler's equations, a Jacobi
// elliptic function), so successive flips are half a period, 21.46 s, apart. The energy and |m|,
// both conserved by the exact motion, measure the integrator's drift.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <ctga/ctga.hpp>

int main() {
    namespace cg = ctga;
    const auto made = cg::make_rigid_body(1.0, cg::vec3<double>{0, 0, 0},
                                          cg::mat3<double>{{{1, 0, 0}, {0, 2, 0}, {0, 0, 3}}});
    if (!made) {
        std::puts(cg::describe(made.error));
        return 1;
    }
    const cg::rigid_body<> body = *made;
    const cg::rigid_body_motion<double, cg::frame::body> model{body};

    const double m0[3] = {0.01, 2, 0.01};
    const cg::screw<> s0{m0[0] / 1, m0[1] / 2, m0[2] / 3, 0, 0, 0};  // ω = I⁻¹ m, v = 0
    const cg::motor<> g0{1, 0, 0, 0, 0, 0, 0, 0};                     // the identity

    const double h = 0.01, t_end = 200;
    const long long steps = std::llround(t_end / h);
    std::vector<double> omega2{s0[1]};  // ω2 at t = n h
    omega2.reserve(static_cast<std::size_t>(steps) + 1);
    const auto run = cg::integrate(cg::lie_rk4{}, model, {g0, s0}, h, steps,
                                   [&](long long, const auto& x) { omega2.push_back(x.s[1]); });
    if (!run) {
        std::printf("stopped after %lld steps: %s\n", run.steps, cg::describe(run.error));
        return 1;
    }

    // flips: sign changes of ω2, located by linear interpolation between the two samples
    std::vector<double> flips;
    for (std::size_t n = 1; n < omega2.size(); ++n)
        if ((omega2[n - 1] < 0) != (omega2[n] < 0))
            flips.push_back(h * (static_cast<double>(n - 1) + omega2[n - 1] / (omega2[n - 1] - omega2[n])));

    std::printf("tennis racket: I = (1, 2, 3), m0 = (0.01, 2, 0.01), lie_rk4, h = %g, t = 0 .. %g\n", h, t_end);
    std::printf("flip     t [s]  interval [s]\n");
    for (std::size_t k = 0; k < flips.size(); ++k) {
        if (k == 0) std::printf("%4zu  %8.4f\n", k + 1, flips[k]);
        else std::printf("%4zu  %8.4f  %8.4f\n", k + 1, flips[k], flips[k] - flips[k - 1]);
    }
    // The exact period of m(t) (Landau & Lifshitz §37): for |m|² < 2E I2 (here) the roles of I1 and
    // I3 swap in T = 4 K(k) √(I1 I2 I3 / ((I3 − I2)(|m|² − 2E I1))),
    // k² = (I2 − I1)(2E I3 − |m|²) / ((I3 − I2)(|m|² − 2E I1)); K by the arithmetic-geometric mean.
    const double m2 = m0[0] * m0[0] + m0[1] * m0[1] + m0[2] * m0[2];
    const double twice_E = m0[0] * m0[0] / 1 + m0[1] * m0[1] / 2 + m0[2] * m0[2] / 3;
    const double Ia = m2 < twice_E * 2 ? 3 : 1, Ib = 2, Ic = m2 < twice_E * 2 ? 1 : 3;
    const double k2 = (Ib - Ia) * (twice_E * Ic - m2) / ((Ic - Ib) * (m2 - twice_E * Ia));
    double a = 1, b = std::sqrt(1 - k2);
    for (int i = 0; i < 40; ++i) {
        const double next = (a + b) / 2;
        b = std::sqrt(a * b), a = next;
    }
    const double period = 4 * (std::acos(-1.0) / (2 * a)) * std::sqrt(Ia * Ib * Ic / ((Ic - Ib) * (m2 - twice_E * Ia)));
    if (flips.size() >= 2) {
        const double mean = (flips.back() - flips.front()) / static_cast<double>(flips.size() - 1);
        std::printf("mean interval %.4f s, exact half-period %.4f s (period of m(t): %.4f s, exact %.4f s)\n", mean,
                    period / 2, 2 * mean, period);
    }

    // conserved quantities: E = ½ s ∨ (N s) and |m|, m the angular part of the body momentum
    const auto momentum_norm = [&](const cg::screw<>& s) {
        const cg::coscrew<> P = cg::momentum(body.N, s);  // (l, p): l = I ω here
        return std::sqrt(P[0] * P[0] + P[1] * P[1] + P[2] * P[2]);
    };
    const double E0 = cg::kinetic_energy(body.N, s0), E1 = cg::kinetic_energy(body.N, run.state.s);
    const double M0 = momentum_norm(s0), M1 = momentum_norm(run.state.s);
    std::printf("energy %.15f -> %.15f, relative drift %.2e\n", E0, E1, (E1 - E0) / E0);
    std::printf("|m|    %.15f -> %.15f, relative drift %.2e\n", M0, M1, (M1 - M0) / M0);

    // ω2(t) as an ASCII strip: 60 columns of 200/60 s, rows from +1 (top) to -1 (bottom); each
    // column marks the range of ω2 over its time interval, so a flip shows as a vertical bar
    constexpr int columns = 60, rows = 9;
    const double top = 1.0, bottom = -1.0;
    const auto row_of = [&](double w) {
        const long r = std::lround((top - w) / (top - bottom) * (rows - 1));
        return r < 0 ? 0 : (r > rows - 1 ? rows - 1 : static_cast<int>(r));
    };
    char grid[rows][columns + 1];
    for (auto& line : grid) {
        for (int c = 0; c < columns; ++c) line[c] = ' ';
        line[columns] = '\0';
    }
    for (int c = 0; c < columns; ++c) grid[row_of(0)][c] = '-';
    const std::size_t per_column = (omega2.size() + columns - 1) / columns;
    for (int c = 0; c < columns; ++c) {
        const std::size_t begin = static_cast<std::size_t>(c) * per_column;
        const std::size_t end = begin + per_column < omega2.size() ? begin + per_column : omega2.size();
        double lo = omega2[begin], hi = omega2[begin];
        for (std::size_t n = begin; n < end; ++n) lo = std::fmin(lo, omega2[n]), hi = std::fmax(hi, omega2[n]);
        for (int r = row_of(hi); r <= row_of(lo); ++r) grid[r][c] = '*';
    }
    std::printf("omega2(t)\n");
    for (int r = 0; r < rows; ++r)
        std::printf("%+5.2f |%s\n", top - (top - bottom) * r / (rows - 1), grid[r]);
    std::printf("      +%s\n", std::string(columns, '-').c_str());
    std::printf("       t = 0%*s%g s\n", columns - 6, "", t_end);
    return 0;
}
