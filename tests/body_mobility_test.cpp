// body_mobility: a rigid body's mobility M = N⁻¹ by its ten parameters (1/m, c, J = I_c⁻¹), the
// mass-centre mobility moved by the translation to the centre of mass, M = (t t̄) M_c (t t̄)*.
// Checked against the 36-blade mobility_of (blade by blade, and the velocity it gives), and the
// acceleration it solves for against the general acceleration(N, M, s, W) and against the 6×6
// matrix formalism of §2, N ṡ + {s, N s} = W, solved here by Gaussian elimination on the matrix
// built from m, c, I_c (independent of the library's mobility), on random bodies far from and near
// their centre of mass.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>

#include <ctga/ctga.hpp>

#include "support/catch.hpp"
#include "support/general_reference.hpp"

namespace {
using namespace ctga;

using test::rel;  // support/general_reference.hpp

using vec6d = std::array<double, 6>;
using mat6d = std::array<std::array<double, 6>, 6>;

// §2: N = [[I_c − m Ĉ², m Ĉ], [m Ĉᵀ, m 1]], Ĉ x = c × x.
mat6d inertia_6x6(double m, const vec3<double>& c, const mat3<double>& Ic) {
    const double C[3][3] = {{0, -c[2], c[1]}, {c[2], 0, -c[0]}, {-c[1], c[0], 0}};
    mat6d N{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double CC = 0;
            for (int k = 0; k < 3; ++k) CC += C[i][k] * C[k][j];
            N[i][j] = Ic[i][j] - m * CC;
            N[i][3 + j] = m * C[i][j];
            N[3 + i][j] = m * C[j][i];
            N[3 + i][3 + j] = i == j ? m : 0;
        }
    return N;
}
vec6d times(const mat6d& A, const vec6d& x) {
    vec6d y{};
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) y[i] += A[i][j] * x[j];
    return y;
}
// A x = b by Gaussian elimination with partial pivoting.
vec6d solve(mat6d A, vec6d b) {
    for (int k = 0; k < 6; ++k) {
        int p = k;
        for (int i = k + 1; i < 6; ++i)
            if (std::abs(A[i][k]) > std::abs(A[p][k])) p = i;
        std::swap(A[k], A[p]);
        std::swap(b[k], b[p]);
        for (int i = k + 1; i < 6; ++i) {
            const double f = A[i][k] / A[k][k];
            for (int j = k; j < 6; ++j) A[i][j] -= f * A[k][j];
            b[i] -= f * b[k];
        }
    }
    vec6d x{};
    for (int i = 5; i >= 0; --i) {
        double r = b[i];
        for (int j = i + 1; j < 6; ++j) r -= A[i][j] * x[j];
        x[i] = r / A[i][i];
    }
    return x;
}
// §2: {s, P} = (ω × l + v × p, ω × p) for s = (ω, v), P = (l, p).
vec6d coadjoint_6(const vec6d& s, const vec6d& P) {
    const auto cross = [](double ax, double ay, double az, double bx, double by, double bz) {
        return std::array<double, 3>{ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx};
    };
    const auto a = cross(s[0], s[1], s[2], P[0], P[1], P[2]);
    const auto b = cross(s[3], s[4], s[5], P[3], P[4], P[5]);
    const auto c = cross(s[0], s[1], s[2], P[3], P[4], P[5]);
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2], c[0], c[1], c[2]};
}
template <class X>
vec6d six(const X& x) {
    return {x[0], x[1], x[2], x[3], x[4], x[5]};
}

}  // namespace

// The velocity about the centre of mass costs what Featherstone's solve does (§2.13: ω̇ = J(n − c × f),
// v̇ = f/m + c × ω̇, 24m 18a); the 36-blade mobility costs 36m 30a.
static_assert(cost_of<decltype(body_mobility<>::velocity(std::declval<const coscrew<>&>(),
                                                         std::declval<const body_mobility<>::scalar&>(),
                                                         std::declval<const body_mobility<>::scalar&>(),
                                                         std::declval<const body_mobility<>::scalar&>(),
                                                         std::declval<const body_mobility<>::scalar&>(),
                                                         std::declval<const body_mobility<>::scalar&>(),
                                                         std::declval<const body_mobility<>::scalar&>(),
                                                         std::declval<const body_mobility<>::scalar&>(),
                                                         std::declval<const body_mobility<>::scalar&>(),
                                                         std::declval<const body_mobility<>::scalar&>(),
                                                         std::declval<const body_mobility<>::scalar&>())),
                      lifted_screw<>> == expr::cost{24, 18},
              "the velocity about the centre of mass: 24m 18a");
static_assert(std::is_same_v<decltype(velocity_from(std::declval<const body_mobility<>&>(), std::declval<const coscrew<>&>())), screw<>>);

TEST_CASE("body_mobility is the element M of mobility_of, M = (t tbar) M_c (t tbar)*", "[mechanics][inertia]") {
    // a box-like body whose inertia and centre of mass are exact in binary: the blades agree to rounding
    const auto props = make_mass_properties(2.0, vec3<double>{0.5, -0.25, 0.75},
                                            mat3<double>{{{2.0, 0.25, 0.0}, {0.25, 1.5, -0.5}, {0.0, -0.5, 1.0}}});
    REQUIRE(props);
    const body_mobility<double> Mb = body_mobility_of(*props);
    const mobility<double> M36 = mobility_of(*props);
    CHECK(rel(to_mobility(Mb), M36) <= 1e-15);
    // and as a matrix it is the inverse of §2's N
    const mat6<double> M = mobility_matrix(to_mobility(Mb));
    const mat6d N = inertia_6x6(props->mass, props->com, props->inertia_c);
    double worst = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            double nm = 0;
            for (int k = 0; k < 6; ++k) nm += N[i][k] * M[k][j];
            worst = std::max(worst, std::abs(nm - (i == j ? 1.0 : 0.0)));
        }
    CHECK(worst <= 1e-14);
}

TEST_CASE("acceleration about the centre of mass agrees with the general mobility and the 6x6 formalism",
          "[mechanics][dynamics]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1), pos(0.5, 2.0);
    double worst_blades = 0, worst_velocity = 0, worst_velocity_6 = 0, worst_formula = 0, worst_general = 0,
           worst_6x6 = 0, worst_lhs = 0, worst_rates = 0;
    for (int n = 0; n < 500; ++n) {
        const double a = pos(rng), b = pos(rng), c = pos(rng), m = pos(rng);
        const double reach = n % 2 == 0 ? 0.3 : 3.0;  // centre of mass near and far from the body origin
        const motor_map<double> Q = map_of(ctga::exp(screw<double>{2 * u(rng), 2 * u(rng), 2 * u(rng), 0, 0, 0}));
        const auto props = make_mass_properties(
            m, vec3<double>{reach * u(rng), reach * u(rng), reach * u(rng)},
            linear3::rotate_symmetric(Q.R, mat3<double>{{{m * (b * b + c * c) / 12, 0, 0}, {0, m * (a * a + c * c) / 12, 0},
                                                          {0, 0, m * (a * a + b * b) / 12}}}));
        REQUIRE(props);
        const rigid_body<double> body = make_rigid_body(*props);
        const screw<double> s{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
        const wrench<double> W{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
        const coscrew<double> P{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
        const mat6d N6 = inertia_6x6(m, props->com, props->inertia_c);

        worst_blades = std::max(worst_blades, rel(to_mobility(body.Mb), body.M));
        // the velocity a co-screw gets: structured, 36 blades, E ∨ (M ∧ P) through the element, N⁻¹ P
        const screw<double> v = velocity_from(body.Mb, P);
        worst_velocity = std::max(worst_velocity, rel(v, velocity_from(body.M, P)));
        worst_velocity_6 = std::max(worst_velocity_6, rel(six(v), solve(N6, six(P))));
        worst_formula = std::max(worst_formula, rel(v, lower(lifted_screw<double>(velocity_from.formula(body.Mb, P)))));

        // ṡ: structured, general, and N⁻¹ (W − {s, N s}) of §2
        const screw<double> sd = acceleration(body, s, W);
        worst_general = std::max(worst_general, rel(sd, acceleration(body.N, body.M, s, W)));
        const vec6d Ns = times(N6, six(s)), cor = coadjoint_6(six(s), Ns);
        const vec6d rhs{W[0] - cor[0], W[1] - cor[1], W[2] - cor[2], W[3] - cor[3], W[4] - cor[4], W[5] - cor[5]};
        worst_6x6 = std::max(worst_6x6, rel(six(sd), solve(N6, rhs)));
        // §6: N ∧ ṡ + ½((s̄N − Ns̄) ∧ s) = W E, every coefficient of the difference; its terms are of
        // size |N||ṡ|, so rounding is relative to that
        const auto diff = eval(eval(motion_lhs(body.N, s, sd)) - eval(W * invariants::E));
        double d = 0, n_max = 0, sd_max = 0;
        for (std::size_t i = 0; i < diff.size(); ++i) d = std::max(d, std::abs(diff[i]));
        for (std::size_t i = 0; i < body.N.size(); ++i) n_max = std::max(n_max, std::abs(body.N[i]));
        for (std::size_t i = 0; i < 6; ++i) sd_max = std::max(sd_max, std::abs(sd[i]));
        worst_lhs = std::max(worst_lhs, d / std::max(1.0, n_max * sd_max));
        // what the integrators call
        worst_rates = std::max(worst_rates, rel(body_frame_rates(body, motor<double>{1, 0, 0, 0, 0, 0, 0, 0}, s, W).s_dot, sd));
    }
    std::printf("body_mobility: blades %.1e; velocity vs 36 blades %.1e, vs N6^-1 P %.1e, vs formula %.1e; acceleration vs "
                "general %.1e, vs 6x6 %.1e, sec. 6 lhs %.1e, body_frame_rates %.1e\n",
                worst_blades, worst_velocity, worst_velocity_6, worst_formula, worst_general, worst_6x6, worst_lhs,
                worst_rates);
    CHECK(worst_blades <= 1e-13);
    CHECK(worst_velocity <= 1e-13);
    CHECK(worst_velocity_6 <= 1e-12);
    CHECK(worst_formula <= 1e-13);
    CHECK(worst_general <= 1e-13);
    CHECK(worst_6x6 <= 1e-12);
    CHECK(worst_lhs <= 1e-13);
    CHECK(worst_rates == 0);
}
