// Exact compile-time Jacobians (ctga::jacobian, operations/jacobian.hpp) against references that
// share nothing with the engine's differentiation: the same formula run on forward-mode dual
// numbers (tests/support/jacobian_check.hpp, tests/support/dual.hpp), and central finite differences.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <random>
#include <tuple>
#include <utility>

#include <ctga/ctga.hpp>
#include <ctga/operations/jacobian.hpp>

#include "support/jacobian_check.hpp"
#include "support/published.hpp"

using namespace ctga;
using namespace ctga_test::jacobians;
using ctga::test::published;

TEST_CASE("momentum P = A ∨ (N ∧ s): ∂P/∂s is N, ∂P/∂N is linear in s, both as dual numbers give", "[jacobian]") {
    const auto make = [](random_source& r) {
        return std::make_tuple(body_inertia_of(random_body(r)), random_multivector<screw<double>>(r));
    };
    CHECK(within("momentum.formula d/d arg 1", check_formula<1, coscrew<double>>(momentum.formula, make), dual_tolerance));
    CHECK(within("momentum.formula d/d arg 0", check_formula<0, coscrew<double>>(momentum.formula, make), dual_tolerance));
    // ∂P/∂s is N's own 6 × 6 matrix: 24 structurally non-zero entries (§2: [[I_o, Ĥ], [−Ĥ, m 1]])
    random_source r{std::mt19937_64{1}};
    const auto [N, s] = make(r);
    const auto J = jacobian<1, coscrew<double>>(momentum.formula, N, s);
    STATIC_REQUIRE(decltype(J)::non_zeros == 24);
    STATIC_REQUIRE(cost_of<decltype(J)> == published<0, 0>);  // the entries are N's parameters, up to sign
}

TEST_CASE("kinetic energy, bracket, coadjoint: exact Jacobians agree with dual numbers", "[jacobian]") {
    using scalar_blade = cl062::mv<double, "1">;
    const auto inertia_and_screw = [](random_source& r) {
        return std::make_tuple(body_inertia_of(random_body(r)), random_multivector<screw<double>>(r));
    };
    CHECK(within("kinetic_energy.formula d/d arg 1", check_formula<1, scalar_blade>(kinetic_energy.formula, inertia_and_screw), dual_tolerance));
    CHECK(within("kinetic_energy.formula d/d arg 0", check_formula<0, scalar_blade>(kinetic_energy.formula, inertia_and_screw), dual_tolerance));
    const auto two_screws = [](random_source& r) {
        return std::make_tuple(random_multivector<screw<double>>(r), random_multivector<screw<double>>(r));
    };
    CHECK(within("bracket.formula d/d arg 0", check_formula<0, screw<double>>(bracket.formula, two_screws), dual_tolerance));
    CHECK(within("bracket.formula d/d arg 1", check_formula<1, screw<double>>(bracket.formula, two_screws), dual_tolerance));
    const auto screw_and_coscrew = [](random_source& r) {
        return std::make_tuple(random_multivector<screw<double>>(r), random_multivector<coscrew<double>>(r));
    };
    CHECK(within("coadjoint.formula d/d arg 0", check_formula<0, coscrew<double>>(coadjoint.formula, screw_and_coscrew), dual_tolerance));
    CHECK(within("coadjoint.formula d/d arg 1", check_formula<1, coscrew<double>>(coadjoint.formula, screw_and_coscrew), dual_tolerance));
}

TEST_CASE("the adjoint g s g*: Jacobians in the motor and in the screw agree with dual numbers", "[jacobian]") {
    const auto motor_and_screw = [](random_source& r) {
        return std::make_tuple(random_multivector<motor<double>>(r), random_multivector<screw<double>>(r));
    };
    CHECK(within("adjoint d/d arg 0", check_formula<0, screw<double>>(adjoint, motor_and_screw), dual_tolerance));
    CHECK(within("adjoint d/d arg 1", check_formula<1, screw<double>>(adjoint, motor_and_screw), dual_tolerance));

    // The same adjoint with its products looped: the value's program reads them as leaves, so the
    // Jacobian is taken column by column from the differentiated tree (expr/derivative.hpp)
    // instead of from the differentiated program (expr/differentiate.hpp). Both against the dual
    // numbers, and against each other.
    constexpr auto looped_adjoint = formula([](auto g, auto s) { return loop_products(g * s * conj(g)); });
    // (a looped product hides the cancellations of g s g*: its value's layout is wider than a screw)
    using looped_value = std::remove_cvref_t<decltype(eval(looped_adjoint(motor<double>{}, screw<double>{})))>;
    STATIC_REQUIRE(looped_value::size() > screw<double>::size());
    CHECK(within("looped adjoint d/d arg 0", check_formula<0, looped_value>(looped_adjoint, motor_and_screw, pattern_check::covers), dual_tolerance));
    CHECK(within("looped adjoint d/d arg 1", check_formula<1, looped_value>(looped_adjoint, motor_and_screw, pattern_check::covers), dual_tolerance));
    random_source r{std::mt19937_64{3}};
    const auto [g, s] = motor_and_screw(r);
    const auto by_program = jacobian<0, screw<double>>(adjoint, g, s);
    const auto by_columns = jacobian<0, looped_value>(looped_adjoint, g, s);
    for (std::size_t k = 0; k < looped_value::size(); ++k) {
        const int i = screw<double>::layout.index_of(looped_value::layout.masks[k]);
        for (std::size_t j = 0; j < 8; ++j) {
            if (i < 0) {  // outside a screw: zero, up to rounding
                CHECK(std::abs(by_columns(k, j)) <= 1e-14);
            } else {
                const double exact = screw<double>::layout.signs[static_cast<std::size_t>(i)] * by_program(static_cast<std::size_t>(i), j);
                CHECK(std::abs(by_columns(k, j) - exact) <= 1e-14 * (1 + std::abs(exact)));
            }
        }
    }
}

TEST_CASE("the equations of motion ṡ = E ∨ (M ∧ (W − {s, A ∨ (N ∧ s)})): ∂ṡ/∂s, ∂ṡ/∂W, ∂ṡ/∂N", "[jacobian]") {
    const auto body_state = [](random_source& r) {
        const mass_properties<double> b = random_body(r);
        return std::make_tuple(body_inertia_of(b), mobility_of(b), random_multivector<screw<double>>(r),
                               random_multivector<wrench<double>>(r));
    };
    CHECK(within("motion_rate d/d arg 2", check_formula<2, lifted_screw<double>>(motion_rate, body_state), dual_tolerance));
    CHECK(within("motion_rate d/d arg 3", check_formula<3, lifted_screw<double>>(motion_rate, body_state), dual_tolerance));
    CHECK(within("motion_rate d/d arg 0", check_formula<0, lifted_screw<double>>(motion_rate, body_state), dual_tolerance));

    // the formula's value is acceleration()'s
    random_source r{std::mt19937_64{7}};
    const auto [N, M, s, W] = body_state(r);
    const screw<double> a = acceleration(N, M, s, W);
    const lifted_screw<double> a_formula = motion_rate(N, M, s, W);
    for (std::size_t i = 0; i < 6; ++i) CHECK(std::abs(a[i] - a_formula[i]) <= 1e-13 * (1 + std::abs(a[i])));

    // central finite differences agree to their own truncation error (h = 1e-5: error ~ h²)
    const auto J = jacobian<2, lifted_screw<double>>(motion_rate, N, M, s, W);
    STATIC_REQUIRE(cost_of<decltype(J)> == published<240, 231>);  // ∂ṡ/∂s with M's 36 blades (README)
    double worst = 0, scale = 0;
    for (std::size_t c = 0; c < 6; ++c) {
        const double h = 1e-5;
        screw<double> up = s, down = s;
        up[c] += h;
        down[c] -= h;
        const lifted_screw<double> fu = motion_rate(N, M, up, W), fd = motion_rate(N, M, down, W);
        for (std::size_t row = 0; row < 6; ++row) {
            worst = std::max(worst, std::abs((fu[row] - fd[row]) / (2 * h) - J(row, c)));
            scale = std::max(scale, std::abs(J(row, c)));
        }
    }
    std::printf("jacobian motion_rate d/ds against central differences (h = 1e-5): %.2e\n", worst / scale);
    CHECK(worst / scale <= 1e-8);
    CHECK(worst / scale > 0);  // finite differences are not exact: the comparison is a real one
}

TEST_CASE("a dense copy and the pattern's entries agree", "[jacobian]") {
    random_source r{std::mt19937_64{3}};
    const auto N = body_inertia_of(random_body(r));
    const auto s = random_multivector<screw<double>>(r);
    const auto J = jacobian<1, coscrew<double>>(momentum.formula, N, s);
    const auto D = J.dense();
    std::size_t zeros = 0;
    for (std::size_t i = 0; i < 6; ++i)
        for (std::size_t j = 0; j < 6; ++j) {
            CHECK(D[i][j] == J(i, j));
            zeros += !J.structurally_nonzero(i, j);
            if (!J.structurally_nonzero(i, j)) CHECK(D[i][j] == 0.0);
        }
    CHECK(zeros == 12);
    // N s by the Jacobian's matrix is the momentum itself (P is linear in s)
    const coscrew<double> P = momentum(N, s);
    for (std::size_t i = 0; i < 6; ++i) {
        double x = 0;
        for (std::size_t j = 0; j < 6; ++j) x += D[i][j] * s[j];
        CHECK(std::abs(x - P[i]) <= 1e-14 * (1 + std::abs(P[i])));
    }
}

TEST_CASE("the implicit midpoint by Newton's method with the exact ∂a/∂s: same step, fewer iterations",
          "[jacobian][integrators]") {
    random_source r{std::mt19937_64{11}};
    const auto body = make_rigid_body(random_body(r));
    const rigid_body_motion<double, frame::body> body_frame{body};
    const rigid_body_motion<double, frame::fixed> fixed_frame{body};
    const motor<double> g = exp(screw<double>{0.3, -0.2, 0.5, 0.1, 0.4, -0.3});
    const screw<double> s{1.5, -2.0, 0.7, 0.3, -0.1, 0.2};
    const auto compare = [&](const auto& model, double h) {
        long newton_iterations = 0, fixed_iterations = 0;
        implicit_midpoint newton{}, fixed{};
        newton.iterations = &newton_iterations;
        fixed.solver = implicit_solver::fixed_point;
        fixed.iterations = &fixed_iterations;
        const auto a = newton.step(model, {g, s}, h);
        const auto b = fixed.step(model, {g, s}, h);
        REQUIRE(a);
        REQUIRE(b);
        for (std::size_t i = 0; i < 6; ++i) CHECK(std::abs(a->s[i] - b->s[i]) <= 1e-13 * (1 + std::abs(b->s[i])));
        for (std::size_t i = 0; i < 8; ++i) CHECK(std::abs(a->g[i] - b->g[i]) <= 1e-13);
        std::printf("implicit midpoint h = %g: Newton %ld iterations, fixed point %ld\n", h, newton_iterations,
                    fixed_iterations);
        CHECK(newton_iterations < fixed_iterations);
    };
    compare(body_frame, 0.01);
    compare(body_frame, 0.1);
    compare(fixed_frame, 0.05);
    // where the fixed-point iteration no longer contracts (h |ω| ≈ 2.6), Newton still converges
    long n = 0;
    implicit_midpoint newton{};
    newton.iterations = &n;
    implicit_midpoint fixed{};
    fixed.solver = implicit_solver::fixed_point;
    CHECK(newton.step(body_frame, {g, s}, 1.0));
    CHECK_FALSE(fixed.step(body_frame, {g, s}, 1.0));
    // and its step keeps the kinetic energy, a quadratic invariant of the body-frame velocity equation
    const auto y = newton.step(body_frame, {g, s}, 1.0);
    REQUIRE(y);
    const double e0 = kinetic_energy(body.Nb, s), e1 = kinetic_energy(body.Nb, y->s);
    CHECK(std::abs(e1 - e0) <= 1e-12 * e0);
}
