// The momentum of an articulated inertia, P = A ∨ (N ∧ s) (paper §5), which momentum computes
// from N's 21 entries instead of through the formula's normal form (mechanics/momentum.hpp):
// checked against the formula itself (momentum.formula, evaluated by the engine) on random
// symmetric N and screws of every sparse type ABA passes (one blade of either orientation, three
// run-time axis blades, the four blades of a bracket v × S q̇, a full screw), and, for a rigid
// body's N (articulated_inertia_of), against the momentum of its ten parameters. And the inverse
// of a floating joint's 6 × 6 D = Sᵀ N S from its Cholesky factor (support/cholesky.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>

#include <ctga/ctga.hpp>

#include "support/catch.hpp"
#include "support/general_reference.hpp"

namespace {
using namespace ctga;
using test::rel;  // support/general_reference.hpp

double uniform(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

// A random symmetric N (its 21 entries; the product does not need N positive definite).
articulated_inertia<double> random_articulated(std::mt19937_64& rng) {
    articulated_inertia<double> N;
    for (std::size_t i = 0; i < 6; ++i)
        for (std::size_t j = i; j < 6; ++j) N.set(i, j, uniform(rng, -2, 2));
    return N;
}

template <class S>
S random_screw(std::mt19937_64& rng) {
    S s;
    for (std::size_t k = 0; k < S::size(); ++k) s[k] = uniform(rng, -3, 3);
    return s;
}

// momentum(N, s) by entries against the formula's evaluation, for screws of type S.
template <class S>
double worst_against_formula(std::mt19937_64& rng, int draws) {
    double worst = 0;
    for (int n = 0; n < draws; ++n) {
        const articulated_inertia<double> N = random_articulated(rng);
        const S s = random_screw<S>(rng);
        const coscrew<double> by_entries = momentum(N, s);
        const coscrew<double> by_formula = momentum.formula(N, s);
        worst = std::max(worst, rel(by_entries, by_formula));
    }
    return worst;
}
}  // namespace

TEST_CASE("articulated inertia: momentum by entries = the formula A ∨ (N ∧ s), for every screw type ABA passes") {
    std::mt19937_64 rng(2701);
    // one blade, as written and reversed (the layout's sign flips the column)
    CHECK(worst_against_formula<cl031::mv<double, "e1e2">>(rng, 20) < 1e-15);
    CHECK(worst_against_formula<cl031::mv<double, "e3e2">>(rng, 20) < 1e-15);
    CHECK(worst_against_formula<cl031::mv<double, "e2e">>(rng, 20) < 1e-15);
    // a run-time axis: three blades, one of them reversed
    CHECK(worst_against_formula<cl031::mv<double, "e2e3", "e1e3", "e1e2">>(rng, 20) < 1e-15);
    CHECK(worst_against_formula<cl031::mv<double, "e1e", "e2e", "e3e">>(rng, 20) < 1e-15);
    // the bracket of a velocity and a revolute-z joint's S q̇: its own sparse type
    using bias_z = std::remove_cvref_t<decltype(eval(bracket.formula(screw<double>{}, cl031::mv<double, "e1e2">{})))>;
    static_assert(bias_z::size() == 4, "v × S q̇ of an axis joint has four blades");
    CHECK(worst_against_formula<bias_z>(rng, 20) < 1e-15);
    // every screw
    CHECK(worst_against_formula<screw<double>>(rng, 20) < 1e-15);
}

TEST_CASE("articulated inertia: a rigid body's N as an articulated inertia has the momentum of its ten parameters") {
    std::mt19937_64 rng(2702);
    for (int n = 0; n < 20; ++n) {
        const double m = uniform(rng, 0.5, 3);
        const vec3<double> c{uniform(rng, -0.5, 0.5), uniform(rng, -0.5, 0.5), uniform(rng, -0.5, 0.5)};
        const double a = uniform(rng, 0.1, 0.3), b = uniform(rng, 0.1, 0.3);
        const mat3<double> Ic{{{a + b, 0.01, 0.02}, {0.01, a + 0.2, -0.01}, {0.02, -0.01, b + 0.2}}};
        const checked<mass_properties<double>> mp = make_mass_properties(m, c, Ic);
        REQUIRE(mp);
        const body_inertia<double> N = body_inertia_of(*mp);
        const screw<double> s = random_screw<screw<double>>(rng);
        const coscrew<double> rigid = momentum(N, s);
        CHECK(rel(momentum(articulated_inertia_of(N), s), rigid) < 1e-14);
        CHECK(rel(momentum(articulated_inertia_of(N), cl031::mv<double, "e3e">{s[5]}), momentum(N, cl031::mv<double, "e3e">{s[5]})) <
              1e-14);
    }
}

// A floating joint's D⁻¹ (chains/minverse.hpp) is cholesky_inverse of its 6 × 6 D: against the
// identity (D⁻¹ D = 1, relative to ‖D⁻¹‖ ‖D‖) and against cholesky_solve on the unit vectors, on
// random positive definite D = B Bᵀ + 0.1 (condition numbers up to about 1e4), and exactly
// symmetric.
namespace {
template <std::size_t N>
void check_cholesky_inverse(std::mt19937_64& rng) {
    std::array<std::array<double, N>, N> B{}, D{};
    for (auto& row : B)
        for (double& x : row) x = uniform(rng, -1, 1);
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j) {
            double s = i == j ? 0.1 : 0.0;
            for (std::size_t k = 0; k < N; ++k) s += B[i][k] * B[j][k];
            D[i][j] = s;
        }
    const auto L = ctga::cholesky(D);
    REQUIRE(L);
    const auto X = ctga::cholesky_inverse(*L);
    double nx = 0, nd = 0, worst_identity = 0, worst_solve = 0;
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j) nx = std::max(nx, std::abs(X[i][j])), nd = std::max(nd, std::abs(D[i][j]));
    for (std::size_t c = 0; c < N; ++c) {
        std::array<double, N> e{};
        e[c] = 1;
        const auto x = ctga::cholesky_solve(*L, e);
        for (std::size_t r = 0; r < N; ++r) {
            double s = 0;
            for (std::size_t k = 0; k < N; ++k) s += X[r][k] * D[k][c];
            worst_identity = std::max(worst_identity, std::abs(s - (r == c ? 1.0 : 0.0)) / (N * nx * nd));
            worst_solve = std::max(worst_solve, std::abs(X[r][c] - x[r]) / nx);
            CHECK(X[r][c] == X[c][r]);
        }
    }
    CHECK(worst_identity < 1e-15);
    CHECK(worst_solve < 1e-12);
}
}  // namespace

TEST_CASE("cholesky_inverse: D⁻¹ D = 1 and D⁻¹ = cholesky_solve on the unit vectors, for random positive definite D") {
    std::mt19937_64 rng(28);
    for (int draw = 0; draw < 200; ++draw) {
        check_cholesky_inverse<6>(rng);
        check_cholesky_inverse<3>(rng);
    }
    std::array<std::array<double, 2>, 2> indefinite{{{1.0, 2.0}, {2.0, 1.0}}};
    CHECK(ctga::cholesky(indefinite).error == ctga::error_code::not_positive_definite);
}
