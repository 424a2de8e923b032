// Tests of the dual-number derivatives of the Featherstone reference
// (tests/support/featherstone_derivatives.hpp), which will judge ctga's dynamics derivatives.
// Nothing here uses ctga.
//
//   * RNEA's ∂τ/∂q, ∂τ/∂v and ABA's ∂q̈/∂q, ∂q̈/∂v, ∂q̈/∂τ on random trees (1–30 bodies, floating
//     bases, floating children, external forces) against central differences of the double
//     reference; ∂/∂q along the tangent directions, q ⊕ δ taken here with the exact SE(3)
//     exponential T(q) exp(δ) for floating joints (the derivatives are seeded with q_dot, so this
//     ties the seeding to the stated convention);
//   * ∂q̈/∂τ · H = 1 (H from CRBA), and ABA's partials against RNEA's by the implicit function
//     theorem: ∂q̈/∂x = −H⁻¹ ∂τ/∂x at a = q̈ (x = q, v), H⁻¹ = ∂q̈/∂τ;
//   * tau / qdd of the dual evaluation against fs::rnea / fs::aba;
//   * the translation columns of a floating body attached to the world vanish (uniform gravity:
//     nothing depends on where the tree is), and closed forms: a pendulum, a free body's
//     gravity term (which fixes the sign of the body-frame rotation tangent).
//
// Error measures (y the independent value):
//   rel(x, y)        = max |x − y| / max(1, max |y|);
//   fd_rel(x, y, f)  = max |x − y| / max(1, max |y|, max |f|) against central differences of f:
//     their rounding error is ~ε' |f| / h, and ABA's q̈ reaches several hundred on the random
//     trees (small radii of gyration) while its derivatives can be a few units: the measure
//     scales with |f| too (a wrong derivative is still off by O(|y|): it fails unless
//     |f| / |y| > 1e6). The step is h = 1e-5, not 1e-6: ABA's q-columns are rounding-limited,
//     ε' up to ~1e4 ε (a step in q changes the whole factorisation of the ill-conditioned H, so
//     its rounding does not cancel in the difference, unlike a step in v or τ). Measured worst
//     fd_rel of ∂q̈/∂q over 1200 such trees: 2.0e-6 at h = 1e-6, 6.5e-8 at 1e-5, 3.6e-8 at 2e-5,
//     2.1e-7 at 1e-4 (truncation ~h² |f'''|); RNEA's and the v, τ columns: < 5e-9 at every step;
//   H⁻¹H = 1 is measured relative to max |H| max |H⁻¹| (the residual of an inverse grows with the
//     condition number: raw ~2e-12 for κ(H) ~ 3e4 on these trees, ~1e-15 normalised).
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "support/catch.hpp"
#include "support/featherstone.hpp"
#include "support/featherstone_derivatives.hpp"
#include "support/random_tree.hpp"
#include "support/relative_error.hpp"
#include "support/worst.hpp"

namespace fs = ctga::test::featherstone;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using ctga::test::rel;
using ctga::test::worst;
using fs::mat3;
using fs::vec3;
using fs::vec6;

namespace {

constexpr double h = 1e-5;          // central-difference step (see fd_rel above)
constexpr double fd_tol = 1e-7;     // fd_rel: central differences against the duals

double max_abs(const MatrixXd& x) { return x.size() == 0 ? 0.0 : x.cwiseAbs().maxCoeff(); }

double fd_rel(const MatrixXd& x, const MatrixXd& y, const VectorXd& f) {
    if (x.rows() != y.rows() || x.cols() != y.cols()) return INFINITY;
    if (y.size() == 0) return 0;
    return max_abs(x - y) / std::max({1.0, max_abs(y), max_abs(f)});
}

// A B, coefficient by coefficient (no large-matrix product kernels: a shorter compile)
MatrixXd mul(const MatrixXd& A, const MatrixXd& B) { return A.lazyProduct(B); }

// Hamilton product of quaternions (w, x, y, z)
Eigen::Vector4d qmul(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
    const vec3 av = a.tail<3>(), bv = b.tail<3>();
    Eigen::Vector4d r;
    r[0] = a[0] * b[0] - av.dot(bv);
    r.tail<3>() = a[0] * bv + b[0] * av + av.cross(bv);
    return r;
}

// q ⊕ δ: revolute / prismatic q + δ; floating T(q) exp(δ), δ = (ω, v) in body coordinates:
// Q' = Q ⊗ exp(ω), p' = p + R(Q) V(ω) v with V = 1 + (1 − cos θ)/θ² ω× + (θ − sin θ)/θ³ ω×²
VectorXd plus(const fs::model& m, const VectorXd& q, const VectorXd& delta) {
    VectorXd r = q;
    for (int i = 0; i < m.size(); ++i) {
        const int iq = m.q_index(i), iv = m.v_index(i);
        switch (m[i].kind) {
        case fs::joint_kind::revolute:
        case fs::joint_kind::prismatic: r[iq] += delta[iv]; break;
        case fs::joint_kind::fixed: break;
        case fs::joint_kind::floating: {
            const vec3 w = delta.segment<3>(iv), u = delta.segment<3>(iv + 3);
            const double th = w.norm();
            const bool small = th < 1e-3;   // series: the closed forms cancel badly for small θ
            const double s = th == 0 ? 0.5 : std::sin(th / 2) / th;
            const double c1 = small ? 0.5 - th * th / 24 : (1 - std::cos(th)) / (th * th);
            const double c2 = small ? 1.0 / 6 - th * th / 120 : (th - std::sin(th)) / (th * th * th);
            const mat3 W = fs::skew(w);
            const mat3 V = mat3::Identity() + c1 * W + c2 * W * W;
            const Eigen::Vector4d Q = q.segment<4>(iq + 3);
            const mat3 R = fs::quaternion_rotation(Q[0], Q[1], Q[2], Q[3]);
            r.segment<3>(iq) = q.segment<3>(iq) + R * (V * u);
            r.segment<4>(iq + 3) = qmul(Q, Eigen::Vector4d(std::cos(th / 2), s * w.x(), s * w.y(), s * w.z()));
            break;
        }
        }
    }
    return r;
}

// central differences of f(x) (x = q through plus, or a v-sized input), nv columns
template <class F>
MatrixXd fd_tangent(const fs::model& m, const VectorXd& q, F f) {
    const int nv = m.nv();
    MatrixXd J(nv, nv);
    for (int t = 0; t < nv; ++t) {
        const VectorXd d = VectorXd::Unit(nv, t) * h;
        J.col(t) = (f(plus(m, q, d)) - f(plus(m, q, -d))) / (2 * h);
    }
    return J;
}
template <class F>
MatrixXd fd_plain(const VectorXd& x, F f) {
    const auto n = x.size();
    MatrixXd J(n, n);
    for (Eigen::Index t = 0; t < n; ++t) {
        const VectorXd d = VectorXd::Unit(n, t) * h;
        J.col(t) = (f(VectorXd(x + d)) - f(VectorXd(x - d))) / (2 * h);
    }
    return J;
}

struct problem {
    fs::model m;
    VectorXd q, v, a;
    std::vector<vec6> f;
};

// tree k of a sequence: floating bases half the time, floating children every third tree,
// external forces every other tree
problem random_problem(std::mt19937_64& rng, int k) {
    fs::random_tree_options opt;
    opt.min_bodies = 1;
    opt.max_bodies = 30;
    opt.floating_base_probability = 0.5;
    opt.floating_children = k % 3 == 0;
    problem p;
    p.m = fs::random_tree(rng, opt);
    p.q = fs::random_q(rng, p.m);
    p.v = fs::random_vector(rng, p.m.nv());
    p.a = fs::random_vector(rng, p.m.nv());
    if (k % 2 == 1) p.f = fs::random_forces(rng, p.m);
    return p;
}

// the largest |entry| in the translation columns of the floating joints attached to the world
double world_floating_translation_columns(const fs::model& m, const MatrixXd& J) {
    double e = 0;
    for (int i = 0; i < m.size(); ++i)
        if (m[i].parent < 0 && m[i].kind == fs::joint_kind::floating && J.rows() > 0)
            e = std::max(e, J.middleCols(m.v_index(i) + 3, 3).cwiseAbs().maxCoeff());
    return e;
}

// an nv × nv matrix
bool square(const MatrixXd& x, int nv) { return x.rows() == nv && x.cols() == nv; }

}  // namespace

TEST_CASE("featherstone derivatives: RNEA against central differences", "[featherstone][derivatives]") {
    std::mt19937_64 rng(11);
    worst W("RNEA derivatives");
    for (int k = 0; k < 120; ++k) {
        const problem p = random_problem(rng, k);
        const fs::model& m = p.m;
        const int nv = m.nv();
        const fs::rnea_partials r = fs::rnea_derivatives(m, p.q, p.v, p.a, p.f);
        REQUIRE(square(r.dtau_dq, nv));
        REQUIRE(square(r.dtau_dv, nv));
        REQUIRE(r.tau.size() == nv);
        CHECK(W("tau vs fs::rnea", rel(r.tau, fs::rnea(m, p.q, p.v, p.a, p.f))) <= 1e-13);
        const MatrixXd Jq = fd_tangent(m, p.q, [&](const VectorXd& x) { return fs::rnea(m, x, p.v, p.a, p.f); });
        const MatrixXd Jv = fd_plain(p.v, [&](const VectorXd& x) { return fs::rnea(m, p.q, x, p.a, p.f); });
        CHECK(W("dtau/dq vs central differences (fd_rel)", fd_rel(r.dtau_dq, Jq, r.tau)) <= fd_tol);
        CHECK(W("dtau/dv vs central differences (fd_rel)", fd_rel(r.dtau_dv, Jv, r.tau)) <= fd_tol);
        W("dtau/dq vs central differences (rel, not checked)", rel(r.dtau_dq, Jq));
        W("dtau/dv vs central differences (rel, not checked)", rel(r.dtau_dv, Jv));
        CHECK(W("world floating joint: translation columns = 0",
                world_floating_translation_columns(m, r.dtau_dq)) == 0);
    }
}

TEST_CASE("featherstone derivatives: ABA against central differences, CRBA and RNEA", "[featherstone][derivatives]") {
    std::mt19937_64 rng(12);
    worst W("ABA derivatives");
    for (int k = 0; k < 120; ++k) {
        const problem p = random_problem(rng, k);
        const fs::model& m = p.m;
        const int nv = m.nv();
        const VectorXd tau = fs::random_vector(rng, nv, 5.0);
        const fs::aba_partials r = fs::aba_derivatives(m, p.q, p.v, tau, p.f);
        REQUIRE(square(r.dqdd_dq, nv));
        REQUIRE(square(r.dqdd_dv, nv));
        REQUIRE(square(r.dqdd_dtau, nv));
        REQUIRE(r.qdd.size() == nv);
        CHECK(W("qdd vs fs::aba", rel(r.qdd, fs::aba(m, p.q, p.v, tau, p.f))) <= 1e-11);   // rounding x cond(H)
        const MatrixXd Jq = fd_tangent(m, p.q, [&](const VectorXd& x) { return fs::aba(m, x, p.v, tau, p.f); });
        const MatrixXd Jv = fd_plain(p.v, [&](const VectorXd& x) { return fs::aba(m, p.q, x, tau, p.f); });
        const MatrixXd Jt = fd_plain(tau, [&](const VectorXd& x) { return fs::aba(m, p.q, p.v, x, p.f); });
        CHECK(W("dqdd/dq vs central differences (fd_rel)", fd_rel(r.dqdd_dq, Jq, r.qdd)) <= fd_tol);
        CHECK(W("dqdd/dv vs central differences (fd_rel)", fd_rel(r.dqdd_dv, Jv, r.qdd)) <= fd_tol);
        CHECK(W("dqdd/dtau vs central differences (fd_rel)", fd_rel(r.dqdd_dtau, Jt, r.qdd)) <= fd_tol);
        W("dqdd/dq vs central differences (rel, not checked)", rel(r.dqdd_dq, Jq));
        W("dqdd/dv vs central differences (rel, not checked)", rel(r.dqdd_dv, Jv));
        W("dqdd/dtau vs central differences (rel, not checked)", rel(r.dqdd_dtau, Jt));
        CHECK(W("world floating joint: translation columns = 0",
                world_floating_translation_columns(m, r.dqdd_dq)) == 0);
        // ∂q̈/∂τ = H⁻¹
        const MatrixXd H = fs::crba(m, p.q);
        const double residual = rel(mul(r.dqdd_dtau, H), MatrixXd::Identity(nv, nv));
        W("dqdd/dtau H = 1 (rel, not checked)", residual);
        if (nv > 0)
            CHECK(W("dqdd/dtau H = 1 (rel / (max|H| max|H^-1|))", residual / (max_abs(H) * max_abs(r.dqdd_dtau))) <= 1e-14);
        // RNEA(q, v, ABA(q, v, τ)) = τ for all (q, v): ∂q̈/∂x = −H⁻¹ ∂τ/∂x at a = q̈
        const fs::rnea_partials i = fs::rnea_derivatives(m, p.q, p.v, r.qdd, p.f);
        CHECK(W("dqdd/dq = -H^-1 dtau/dq", rel(r.dqdd_dq, MatrixXd(-mul(r.dqdd_dtau, i.dtau_dq)))) <= 1e-10);
        CHECK(W("dqdd/dv = -H^-1 dtau/dv", rel(r.dqdd_dv, MatrixXd(-mul(r.dqdd_dtau, i.dtau_dv)))) <= 1e-10);
    }
}

TEST_CASE("featherstone derivatives: closed forms and edge cases", "[featherstone][derivatives]") {
    worst W("derivatives, closed forms");
    const double g = 9.81;
    SECTION("pendulum: revolute about z, centre of mass at (l, 0, 0), gravity -y") {
        fs::model m;
        m.gravity = vec3(0, -g, 0);
        fs::body b;
        b.kind = fs::joint_kind::revolute;
        b.axis = vec3::UnitZ();
        b.mass = 1.7;
        b.com = vec3(0.6, 0, 0);
        b.inertia_c = vec3(0.01, 0.02, 0.03).asDiagonal();
        m.bodies.push_back(b);
        const double Io = 0.03 + b.mass * 0.36;   // about the axis
        // τ = Io θ̈ + m g l cos θ;  θ̈ = (τ − m g l cos θ) / Io
        for (double th : {-2.5, -0.4, 0.0, 0.9, 2.0}) {
            const VectorXd q = VectorXd::Constant(1, th), v = VectorXd::Constant(1, 0.7);
            const VectorXd a = VectorXd::Constant(1, -0.3), tau = VectorXd::Constant(1, 1.1);
            const fs::rnea_partials r = fs::rnea_derivatives(m, q, v, a);
            CHECK(W("pendulum tau", rel(r.tau[0], Io * -0.3 + b.mass * g * 0.6 * std::cos(th))) <= 1e-14);
            CHECK(W("pendulum dtau/dq", rel(r.dtau_dq(0, 0), -b.mass * g * 0.6 * std::sin(th))) <= 1e-14);
            CHECK(W("pendulum dtau/dv", std::abs(r.dtau_dv(0, 0))) <= 1e-15);
            const fs::aba_partials s = fs::aba_derivatives(m, q, v, tau);
            CHECK(W("pendulum dqdd/dq", rel(s.dqdd_dq(0, 0), b.mass * g * 0.6 * std::sin(th) / Io)) <= 1e-14);
            CHECK(W("pendulum dqdd/dv", std::abs(s.dqdd_dv(0, 0))) <= 1e-15);
            CHECK(W("pendulum dqdd/dtau", rel(s.dqdd_dtau(0, 0), 1 / Io)) <= 1e-14);
        }
    }
    SECTION("free body, centre of mass at the origin: d(-m R^T g)/d(body rotation) = -m (R^T g)x") {
        std::mt19937_64 rng(13);
        fs::model m;
        m.gravity = vec3(0.4, -1.1, -g);
        fs::body b;
        b.kind = fs::joint_kind::floating;
        b.mass = 2.3;
        b.inertia_c = fs::random_inertia_c(rng, b.mass, 0.1, 0.3);
        m.bodies.push_back(b);
        for (int k = 0; k < 10; ++k) {
            const VectorXd q = fs::random_q(rng, m), v = fs::random_vector(rng, 6), a = fs::random_vector(rng, 6);
            // τ = (I_c ω̇ + ω × I_c ω, m (v̇ + ω × v − Rᵀ g)): only the last term depends on q, and
            // Rᵀ g turns to (1 − δω×) Rᵀ g under R exp(δω×)
            const mat3 R = fs::quaternion_rotation(q[3], q[4], q[5], q[6]);
            MatrixXd expect = MatrixXd::Zero(6, 6);
            expect.block<3, 3>(3, 0) = -b.mass * fs::skew(vec3(R.transpose() * m.gravity));
            const fs::rnea_partials r = fs::rnea_derivatives(m, q, v, a);
            CHECK(W("free body dtau/dq", rel(r.dtau_dq, expect)) <= 1e-14);
            // and q̈ = M⁻¹ (τ − bias): dq̈/dq = −M⁻¹ dτ/dq = (0, (Rᵀ g)×)
            const fs::aba_partials s = fs::aba_derivatives(m, q, v, a);
            expect.block<3, 3>(3, 0) = fs::skew(vec3(R.transpose() * m.gravity));
            CHECK(W("free body dqdd/dq", rel(s.dqdd_dq, expect)) <= 1e-14);
        }
    }
    SECTION("no degrees of freedom: empty matrices") {
        fs::model m;
        m.bodies.push_back(fs::body{});   // fixed
        const VectorXd e(0);
        const fs::rnea_partials r = fs::rnea_derivatives(m, e, e, e);
        CHECK(r.dtau_dq.size() == 0);
        CHECK(r.dtau_dv.size() == 0);
        CHECK(r.tau.size() == 0);
        const fs::aba_partials s = fs::aba_derivatives(m, e, e, e);
        CHECK(s.dqdd_dq.size() == 0);
        CHECK(s.dqdd_dtau.size() == 0);
        CHECK(s.qdd.size() == 0);
    }
    SECTION("wrong sizes throw") {
        fs::model m;
        fs::body b;
        b.kind = fs::joint_kind::revolute;
        m.bodies.push_back(b);
        const VectorXd one = VectorXd::Zero(1), two = VectorXd::Zero(2);
        CHECK_THROWS_AS(fs::rnea_derivatives(m, two, one, one), std::invalid_argument);
        CHECK_THROWS_AS(fs::rnea_derivatives(m, one, two, one), std::invalid_argument);
        CHECK_THROWS_AS(fs::aba_derivatives(m, one, one, two), std::invalid_argument);
    }
}
