// The frictional contact problem (include/ctga/constraints/): the cone's projection against
// Moreau's decomposition, one contact against closed forms, and whole problems against the
// independent long-double solver of tests/support/fc3d_reference.hpp (written without reading
// the library's solver).
#include <array>
#include <cmath>
#include <random>
#include <string_view>
#include <vector>

#include <ctga/constraints/contact_problem.hpp>
#include <ctga/constraints/newton_polish.hpp>
#include <ctga/constraints/row_colours.hpp>
#include <ctga/constraints/soft_step.hpp>

#include "support/catch.hpp"
#include "support/fc3d_reference.hpp"

namespace {
namespace cn = ctga::constraints;
using ctga::vec3;
using ctga::mat3;

template <class T>
vec3<T> random_vec(std::mt19937_64& rng, T spread) {
    std::uniform_real_distribution<T> u(-spread, spread);
    const T a = u(rng), b = u(rng), c = u(rng);
    return {a, b, c};
}

// A random problem: W = J Jᵀ + εI (J 3m × (3m + 3)), q random, μ in [0, 1].
struct problem {
    std::size_t m;
    std::vector<double> W, q, mu;
};
problem random_problem(std::mt19937_64& rng, std::size_t m) {
    const std::size_t n = 3 * m, k = n + 3;
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> fr(0.0, 1.0);
    std::vector<double> J(n * k);
    for (double& x : J) x = g(rng);
    problem p{m, std::vector<double>(n * n), std::vector<double>(n), std::vector<double>(m)};
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = 0; b < n; ++b) {
            double s = a == b ? 0.1 : 0.0;
            for (std::size_t c = 0; c < k; ++c) s += J[a * k + c] * J[b * k + c];
            p.W[a * n + b] = s;
        }
    for (double& x : p.q) x = 2 * g(rng);
    for (double& x : p.mu) x = fr(rng);
    return p;
}

template <class T>
std::vector<long double> widen(const std::vector<T>& x) {
    return {x.begin(), x.end()};
}

}  // namespace

TEST_CASE("constraints: the projection on the friction cone splits x into a cone part and a polar part (Moreau)") {
    // x = P_K(x) + P_K°(x), P_K(x) ∈ K, x − P_K(x) in the polar cone −K*, the two orthogonal
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> fr(0.0, 2.0);
    for (int it = 0; it < 2000; ++it) {
        const vec3<double> x = random_vec(rng, 1.0);
        const double mu = it % 10 == 0 ? 0.0 : fr(rng);
        const vec3<double> p = cn::project_on_cone(x, mu);
        const vec3<double> rest = ctga::linear3::sub(x, p);
        CHECK(cn::tangential_norm(p) <= mu * p[0] + 1e-15);                      // in K
        CHECK(mu * cn::tangential_norm(rest) <= -rest[0] + 1e-15);               // −rest in K*
        CHECK(std::abs(ctga::linear3::dot(p, rest)) <= 1e-15);                   // orthogonal
        const vec3<double> again = cn::project_on_cone(p, mu);                   // a projection
        for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(again[k] - p[k]) <= 1e-15);
    }
}

TEST_CASE("constraints: one contact takes off, sticks or slides as the closed forms say") {
    const mat3<double> I{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    // stick: r = −b inside the cone
    const vec3<double> stick = cn::one_contact(I, vec3<double>{-1, 0.3, 0}, 0.5);
    CHECK(std::abs(stick[0] - 1) <= 1e-15);
    CHECK(std::abs(stick[1] + 0.3) <= 1e-15);
    // slide: u_n = 0, r on the cone's edge against the slip: r = (1, −0.5, 0), u = (0, 1.5, 0)
    const vec3<double> slide = cn::one_contact(I, vec3<double>{-1, 2, 0}, 0.5);
    CHECK(std::abs(slide[0] - 1) <= 1e-14);
    CHECK(std::abs(slide[1] + 0.5) <= 1e-14);
    CHECK(std::abs(slide[2]) <= 1e-14);
    // take-off
    const vec3<double> off = cn::one_contact(I, vec3<double>{1, 1, 1}, 0.5);
    CHECK((off[0] == 0 && off[1] == 0 && off[2] == 0));
    // frictionless: the normal impulse alone
    const vec3<double> smooth = cn::one_contact(I, vec3<double>{-2, 5, 1}, 0.0);
    CHECK((smooth[0] == 2 && smooth[1] == 0 && smooth[2] == 0));
    // in a constant expression
    static_assert(cn::one_contact(mat3<double>{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, vec3<double>{-1, 0.3, 0}, 0.5)[0] == 1.0);
    // anisotropic blocks: the natural map vanishes to rounding, in every regime
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> fr(0.0, 1.0);
    int regimes[3] = {0, 0, 0};
    for (int it = 0; it < 3000; ++it) {
        const problem p = random_problem(rng, 1);
        const mat3<double> A{{{p.W[0], p.W[1], p.W[2]}, {p.W[3], p.W[4], p.W[5]}, {p.W[6], p.W[7], p.W[8]}}};
        const vec3<double> b{p.q[0], p.q[1], p.q[2]};
        const vec3<double> r = cn::one_contact(A, b, p.mu[0]);
        const vec3<double> u = ctga::linear3::add(ctga::linear3::apply(A, r), b);
        const vec3<double> F = cn::natural_map(r, u, p.mu[0]);
        CHECK(std::sqrt(ctga::linear3::dot(F, F)) <= 1e-12 * (1 + std::sqrt(ctga::linear3::dot(b, b))));
        ++regimes[r[0] == 0 ? 0 : std::sqrt(ctga::linear3::dot(u, u)) <= 1e-9 ? 1 : 2];
    }
    CHECK(regimes[0] > 100);  // take-off
    CHECK(regimes[1] > 100);  // stick
    CHECK(regimes[2] > 100);  // slide
}

TEST_CASE("constraints: nonsmooth Gauss-Seidel (exact and projected local steps, conjugate directions) and Newton reach the tolerance and the reference solver's impulses") {
    std::mt19937_64 rng(11);
    double worst_gap = 0, worst_projected = 0, worst_newton = 0;
    std::size_t newton_steps = 0;
    for (int it = 0; it < 60; ++it) {
        const std::size_t m = 1 + static_cast<std::size_t>(it % 8);
        problem p = random_problem(rng, m);
        for (double& mu : p.mu) mu *= 0.6;  // unique solutions in practice
        std::vector<double> r(3 * m, 0.0);
        cn::dense_delassus<double> W{p.W, p.q};
        const cn::contact_report<double> rep = cn::solve_contacts(W, std::span<const double>(p.mu), std::span<double>(r), {1e-12, 20000});
        REQUIRE(rep.error == ctga::error_code::none);
        CHECK(rep.converged);
        CHECK(rep.residual <= 1e-12);
        // the residual it reports is the natural map's, computed independently
        CHECK(static_cast<double>(fc3d_reference::natural_map_residual(widen(p.W), widen(p.q), widen(p.mu), widen(r))) <= 1.5e-12);
        const fc3d_reference::result ref = fc3d_reference::solve(widen(p.W), widen(p.q), widen(p.mu));
        REQUIRE(ref.converged);
        for (std::size_t k = 0; k < 3 * m; ++k) worst_gap = std::max(worst_gap, std::abs(r[k] - static_cast<double>(ref.r[k])));
        // the projected local step: the same fixed points
        std::vector<double> rp(3 * m, 0.0);
        const cn::contact_report<double> pr = cn::solve_contacts(W, std::span<const double>(p.mu), std::span<double>(rp),
                                                                 {1e-12, 200000, cn::local_solve::projected});
        CHECK(pr.converged);
        CHECK(static_cast<double>(fc3d_reference::natural_map_residual(widen(p.W), widen(p.q), widen(p.mu), widen(rp))) <= 1.5e-12);
        for (std::size_t k = 0; k < 3 * m; ++k) worst_projected = std::max(worst_projected, std::abs(rp[k] - static_cast<double>(ref.r[k])));
        // and accelerated by conjugate directions
        std::vector<double> rc(3 * m, 0.0), directions(6 * m);
        const cn::contact_report<double> cr = cn::solve_contacts(W, std::span<const double>(p.mu), std::span<double>(rc),
                                                                 {1e-12, 200000, cn::local_solve::projected}, std::span<double>(directions));
        CHECK(cr.converged);
        CHECK(static_cast<double>(fc3d_reference::natural_map_residual(widen(p.W), widen(p.q), widen(p.mu), widen(rc))) <= 1.5e-12);
        for (std::size_t k = 0; k < 3 * m; ++k) worst_projected = std::max(worst_projected, std::abs(rc[k] - static_cast<double>(ref.r[k])));
        // Newton from zero
        std::vector<double> rn(3 * m, 0.0), scratch(cn::newton_scratch_size(m));
        const cn::contact_report<double> nr =
            cn::newton_polish<double>(p.W, p.q, p.mu, std::span<double>(rn), std::span<double>(scratch), 1e-12, 60);
        CHECK(nr.converged);
        newton_steps += nr.sweeps;
        CHECK(static_cast<double>(fc3d_reference::natural_map_residual(widen(p.W), widen(p.q), widen(p.mu), widen(rn))) <= 1.5e-12);
        for (std::size_t k = 0; k < 3 * m; ++k) worst_newton = std::max(worst_newton, std::abs(rn[k] - static_cast<double>(ref.r[k])));
    }
    CHECK(worst_gap <= 1e-8);
    CHECK(worst_projected <= 1e-8);
    CHECK(worst_newton <= 1e-8);
    CHECK(newton_steps <= 60 * 10);  // a few steps a problem (measured: see the closing note of issue 44)
}

TEST_CASE("constraints: float, and bad input refused before any sweep") {
    const std::vector<float> W{2, 0, 0, 0, 2, 0, 0, 0, 2}, q{-1, 0.5f, 0}, mu{0.6f};
    std::vector<float> r(3, 0.0f);
    cn::dense_delassus<float> D{W, q};
    const auto rep = cn::solve_contacts(D, std::span<const float>(mu), std::span<float>(r), {1e-6f, 100});
    CHECK(rep.converged);
    CHECK(std::abs(r[0] - 0.5f) <= 1e-6f);  // sticks: r = −W⁻¹ q = (0.5, −0.25, 0), |r_t| ≤ 0.6 r_n
    CHECK(std::abs(r[1] + 0.25f) <= 1e-6f);

    std::vector<double> Wd{1, 0, 0, 0, 1, 0, 0, 0, 1}, qd{-1, 0, 0}, rd(3, 0.0);
    const std::vector<double> negative{-0.1}, fine{0.3};
    cn::dense_delassus<double> Dd{Wd, qd};
    CHECK(cn::solve_contacts(Dd, std::span<const double>(negative), std::span<double>(rd)).error == ctga::error_code::negative_friction);
    CHECK(std::string_view(ctga::describe(ctga::error_code::negative_friction)).find("friction") != std::string_view::npos);
    std::vector<double> short_r(2, 0.0);
    CHECK(cn::solve_contacts(Dd, std::span<const double>(fine), std::span<double>(short_r)).error == ctga::error_code::size_mismatch);
    qd[1] = std::nan("");
    cn::dense_delassus<double> Dn{Wd, qd};
    CHECK(cn::solve_contacts(Dn, std::span<const double>(fine), std::span<double>(rd)).error == ctga::error_code::non_finite);
    CHECK((rd[0] == 0 && rd[1] == 0 && rd[2] == 0));  // left as given
}

namespace {
// A dense problem whose blocks are all bounded (a joint's limits and motor): each row's impulse
// in an interval.
struct bounded_dense : cn::dense_delassus<double> {
    std::vector<std::array<vec3<double>, 2>> limits;
    [[nodiscard]] bool bounded(std::size_t) const noexcept { return true; }
    [[nodiscard]] std::array<vec3<double>, 2> bounds(std::size_t i) const noexcept { return limits[i]; }
};
}  // namespace

TEST_CASE("contact problem: bounded rows (limits, motors) against every active set") {
    // one block of three rows, u = A r + q, lower ≤ r ≤ upper: the solution is the one choice,
    // among the 27 of each row at its lower bound, at its upper or free (u = 0 there), whose r
    // is within the bounds and whose u has the right sign where a bound holds (A is positive
    // definite, so there is exactly one); found here by trying them all, with Cramer's rule
    std::mt19937 rng(44);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    const double inf = std::numeric_limits<double>::infinity();
    for (int trial = 0; trial < 60; ++trial) {
        mat3<double> B{};
        for (auto& row : B)
            for (double& x : row) x = U(rng);
        mat3<double> A{};
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) {
                for (std::size_t k = 0; k < 3; ++k) A[i][j] += B[i][k] * B[j][k];
                A[i][j] += i == j ? 0.2 : 0.0;
            }
        const vec3<double> q{U(rng), U(rng), U(rng)};
        // a limit [0, ∞), a motor's [−b, b], a row held at zero
        const std::array<vec3<double>, 2> box{vec3<double>{0.0, -0.3 * std::abs(U(rng)), 0.0}, vec3<double>{inf, 0.3 * std::abs(U(rng)), 0.0}};
        vec3<double> expected{};
        int found = 0;
        for (int choice = 0; choice < 27; ++choice) {
            std::array<int, 3> at{choice % 3, choice / 3 % 3, choice / 9};  // 0 lower, 1 upper, 2 free
            bool usable = true;
            for (std::size_t k = 0; k < 3; ++k) usable = usable && (at[k] == 2 || std::isfinite(box[at[k]][k]));
            if (!usable) continue;
            // the free rows solve A_ff r_f = −(q_f + A_fb r_b); the others sit at their bounds
            vec3<double> r{};
            for (std::size_t k = 0; k < 3; ++k) r[k] = at[k] == 2 ? 0.0 : box[at[k]][k];
            mat3<double> M{};
            vec3<double> rhs{};
            for (std::size_t i = 0; i < 3; ++i) {
                if (at[i] != 2) {
                    M[i][i] = 1.0, rhs[i] = r[i];
                    continue;
                }
                rhs[i] = -q[i];
                for (std::size_t j = 0; j < 3; ++j) (at[j] == 2 ? M[i][j] : rhs[i]) += at[j] == 2 ? A[i][j] : -A[i][j] * r[j];
            }
            const auto det = [](const mat3<double>& m) {
                return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
            };
            const double d = det(M);
            for (std::size_t k = 0; k < 3; ++k) {
                mat3<double> Mk = M;
                for (std::size_t i = 0; i < 3; ++i) Mk[i][k] = rhs[i];
                r[k] = det(Mk) / d;
            }
            bool ok = true;
            for (std::size_t k = 0; k < 3; ++k) {
                double u = q[k];
                for (std::size_t j = 0; j < 3; ++j) u += A[k][j] * r[j];
                const double tol = 1e-12;
                if (at[k] == 2) ok = ok && r[k] >= box[0][k] - tol && r[k] <= box[1][k] + tol;
                else if (at[k] == 0) ok = ok && u >= -tol;
                else ok = ok && u <= tol;
            }
            if (ok) expected = r, ++found;
        }
        REQUIRE(found >= 1);
        std::vector<double> W(9), qs(q.begin(), q.end());
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) W[3 * i + j] = A[i][j];
        bounded_dense D{{W, qs}, {box}};
        std::vector<double> r(3, 0.0), mu(1, 0.0);
        cn::contact_settings<double> set;
        set.tolerance = 1e-13;
        set.max_sweeps = 100000;
        const auto report = cn::solve_contacts<double>(D, std::span<const double>(mu), std::span<double>(r), set);
        CHECK(report.converged);
        for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(r[k] - expected[k]) <= 1e-9);
        // Newton, from zero, with the block marked bounded
        std::vector<double> rn(3, 0.0), scratch(cn::newton_scratch_size(1));
        const std::array<unsigned char, 1> kind{cn::bounded_block};
        const auto newton = cn::newton_polish<double>(W, qs, mu, std::span<double>(rn), std::span<double>(scratch), 1e-12, 60,
                                                      std::span<const unsigned char>(kind), std::span<const std::array<vec3<double>, 2>>(&box, 1));
        CHECK(newton.converged);
        for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(rn[k] - expected[k]) <= 1e-9);
    }
}

TEST_CASE("constraints: rows in colours share no moving body, a group's lanes give bit for bit what each row gives alone") {
    // 300 rows between 40 bodies (a fifth against a static side), 6 colours: some rows find none
    std::mt19937_64 rng(44);
    std::uniform_int_distribution<std::uint32_t> pick(0, 39);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    constexpr std::size_t m = 300, bodies = 40, colours = 6;
    std::vector<cn::contact_row<double>> rows(m);
    std::vector<cn::mobility<double>> M(bodies);
    for (cn::mobility<double>& x : M) {
        const vec3<double> d{0.5 + u(rng) * u(rng), 0.7 + u(rng) * u(rng), 0.9 + u(rng) * u(rng)};
        x.inverse_mass = 1.5 + u(rng);
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) x.inverse_inertia[i][j] = (i == j ? d[i] : 0.1 * (u(rng) + u(rng)));
        x.inverse_inertia[1][0] = x.inverse_inertia[0][1], x.inverse_inertia[2][0] = x.inverse_inertia[0][2], x.inverse_inertia[2][1] = x.inverse_inertia[1][2];
    }
    for (std::size_t i = 0; i < m; ++i) {
        cn::contact_row<double>& row = rows[i];
        const std::uint32_t a = pick(rng), b = pick(rng);
        const vec3<double> n = ctga::linear3::scale(1.0 / std::sqrt(3.0), vec3<double>{1.0, 1.0, 1.0});
        const std::array<vec3<double>, 2> t = cn::tangents(n);
        row.direction = {n, t[0], t[1]};
        row.a = cn::make_side(a, random_vec(rng, 1.0), random_vec(rng, 1.0), row.direction);
        row.b = i % 5 == 0 || b == a ? cn::row_side<double>{} : cn::make_side(b, random_vec(rng, 1.0), random_vec(rng, 1.0), row.direction);
        row.block = cn::delassus_block<double>(row, M);
        row.step_length = cn::step_lengths(row.block);
        row.mu = 0.5, row.compliance = 0.0, row.bias = {};
        row.bounded = i % 37 == 0;
    }
    std::vector<std::uint64_t> used(bodies);
    std::vector<std::uint32_t> colour_of(m), order(m), start(colours + 2);
    const std::size_t coloured = cn::colour_rows<double>(rows, colours, used, colour_of, order, start,
                                                         [&](std::size_t i) { return rows[i].bounded; });
    // every row once; within a colour in row order and no moving body twice
    std::vector<int> seen(m, 0);
    for (std::uint32_t i : order) ++seen[i];
    CHECK(std::count(seen.begin(), seen.end(), 1) == int(m));
    CHECK(start[colours] == coloured);
    for (std::size_t c = 0; c < colours; ++c) {
        std::vector<int> on(bodies, 0);
        for (std::size_t k = start[c]; k < start[c + 1]; ++k) {
            const cn::contact_row<double>& row = rows[order[k]];
            for (std::uint32_t body : {row.a.body, row.b.body})
                if (body != cn::no_body) CHECK(++on[body] == 1);
            if (k > start[c]) CHECK(order[k] > order[k - 1]);
            CHECK(!row.bounded);
        }
    }
    // a row left over is bounded, or every colour held one of its bodies when its turn came
    std::size_t over = 0;
    for (std::size_t k = coloured; k < m; ++k) {
        const std::uint32_t i = order[k];
        if (rows[i].bounded) continue;
        ++over;
        for (std::size_t c = 0; c < colours; ++c) {
            bool blocked = false;
            for (std::size_t j = start[c]; j < start[c + 1] && order[j] < i; ++j)
                for (std::uint32_t x : {rows[order[j]].a.body, rows[order[j]].b.body})
                    blocked = blocked || (x != cn::no_body && (x == rows[i].a.body || x == rows[i].b.body));
            CHECK(blocked);
        }
    }
    CHECK(over > 0);  // (the test meets overflow)

    // colour 0's rows in groups of 4 lanes against one lane each: the same impulses and screws
    constexpr std::size_t L = 4;
    std::vector<ctga::screw<double>> s(bodies + 1), s1(bodies + 1);
    for (std::size_t b = 0; b < bodies; ++b)
        for (std::size_t c = 0; c < 6; ++c) s[b][c] = s1[b][c] = u(rng);
    cn::soft_sweep_settings<double> set{cn::make_soft(60.0, 10.0, 1.0 / 240), cn::make_soft(60.0, 2.0, 1.0 / 240), 3.0, 1.0 / 240, false};
    for (const bool relax : {false, true}) {
        set.relax = relax;
        for (std::size_t k = start[0]; k < start[1]; k += L) {
            cn::row_group<double, L> g;
            for (std::size_t l = 0; l < L; ++l) {
                if (k + l < start[1]) cn::fill_lane(g, l, order[k + l], rows[order[k + l]], std::span<const cn::mobility<double>>(M), bodies);
                else cn::empty_lane(g, l, bodies, ~std::uint32_t{0});
                for (std::size_t c = 0; c < 3; ++c) g.r[c].set(l, 0.1 * (u(rng) + 1)), g.gap[c].set(l, 0.01 * u(rng)), g.surface[c].set(l, 0.0);
                g.spring_rate.set(l, 0.0);
            }
            cn::lane_screws<double, L> sa = cn::gather(s.data(), g.a), sb = cn::gather(s.data(), g.b);
            cn::row_group<double, L> before = g;
            cn::soft_group(g, false, sa, sb, set);
            cn::scatter(s.data(), g.a, sa), cn::scatter(s.data(), g.b, sb);
            for (std::size_t l = 0; l < L && k + l < start[1]; ++l) {
                cn::row_group<double, 1> one;
                cn::fill_lane(one, 0, order[k + l], rows[order[k + l]], std::span<const cn::mobility<double>>(M), bodies);
                for (std::size_t c = 0; c < 3; ++c) one.r[c].set(0, before.r[c][l]), one.gap[c].set(0, before.gap[c][l]), one.surface[c].set(0, 0.0);
                one.spring_rate.set(0, 0.0);
                cn::lane_screws<double, 1> a1 = cn::gather(s1.data(), one.a), b1 = cn::gather(s1.data(), one.b);
                cn::soft_group(one, false, a1, b1, set);
                cn::scatter(s1.data(), one.a, a1), cn::scatter(s1.data(), one.b, b1);
                for (std::size_t c = 0; c < 3; ++c) CHECK(one.r[c][0] == g.r[c][l]);
            }
        }
    }
    for (std::size_t b = 0; b <= bodies; ++b)
        for (std::size_t c = 0; c < 6; ++c) CHECK(s[b][c] == s1[b][c]);
    for (std::size_t c = 0; c < 6; ++c) CHECK(s[bodies][c] == 0.0);  // no body stays zero
}
