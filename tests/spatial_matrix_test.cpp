// The mechanics of §2–6 against the 6×6 matrix formalism of §2, written independently with
// Eigen (tests only; ctga itself never includes Eigen). 1,000 random bodies, poses, velocities
// and wrenches; for each, every quantity the library computes is compared with its 6×6 form:
//
//   screws s = (ω, v), co-screws P = (l, p), R by Rodrigues, T x = t × x,
//   H = [[R, 0], [T R, R]],  H⁻ᵀ = [[R, T R], [0, R]],
//   N6 = [[I_c − m Ĉ², m Ĉ], [m Ĉᵀ, m 1]],  M6 = N6⁻¹,
//   P = N6 s,  E_k = ½ sᵀ N6 s,  P(s) = Pᵀ s,
//   [s1, s2] = (ω1×ω2, ω1×v2 − ω2×v1) = ad_s1 s2,  ad_s = [[ω̂, 0], [v̂, ω̂]],
//   {s, P} = (ω×l + v×p, ω×p) = −ad_sᵀ P,
//   N → H⁻ᵀ N H⁻¹,  M → H M Hᵀ,  dN/dt = −ad_sᵀ N − N ad_s,
//   N6 ṡ + {s, N6 s} = W  (solved with LDLT, in the fixed frame and in the body frame).
//
// The reference is computed in long double (x86-64: 64-bit significand, ε ≈ 1.1e-19), so what
// is measured is ctga's own rounding, not the reference's.
//
// Error measure (stated once, used for every quantity): for ctga's values x and the
// reference's y of one quantity (all components of a vector or matrix, or one scalar),
//   rel(x, y) = max_i |x_i − y_i| / max(1, max_i |y_i|),
// the largest component error relative to the largest reference component (absolute when
// all components are below 1). Every quantity must have rel ≤ 1e-12. The worst rel seen for
// each quantity is printed at the end of the run.
//
// Besides, make_mass_properties must reject non-finite inputs, m ≤ 0, a non-symmetric or
// non-positive-definite tensor and principal moments violating the triangle inequality.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include <ctga/support/checked.hpp>
#include <ctga/mechanics/convert.hpp>
#include <ctga/mechanics/dynamics.hpp>
#include <ctga/mechanics/inertia.hpp>
#include <ctga/mechanics/inertia_matrix.hpp>
#include <ctga/mechanics/inertia_transform.hpp>
#include <ctga/mechanics/linear3.hpp>
#include <ctga/mechanics/mass_properties.hpp>
#include <ctga/mechanics/momentum.hpp>
#include <ctga/mechanics/motor.hpp>
#include <ctga/mechanics/rigid_body.hpp>

#include "support/catch.hpp"

namespace {

// ---- the independent reference: §2 in Eigen, long double ------------------------------------

using Real = long double;
using V3 = Eigen::Matrix<Real, 3, 1>;
using M3 = Eigen::Matrix<Real, 3, 3>;
using V6 = Eigen::Matrix<Real, 6, 1>;
using M6 = Eigen::Matrix<Real, 6, 6>;
using Quat = Eigen::Quaternion<Real>;

constexpr double tolerance = 1e-12;

// x̂, the cross-product matrix: hat(x) y = x × y.
M3 hat(const V3& x) {
    M3 m;
    m << 0, -x(2), x(1), x(2), 0, -x(0), -x(1), x(0), 0;
    return m;
}

// Rodrigues: R = cos θ 1 + sin θ û + (1 − cos θ) u uᵀ, the rotation by +θ about the unit axis u.
M3 rodrigues(const V3& u, Real theta) {
    return std::cos(theta) * M3::Identity() + std::sin(theta) * hat(u) + (1 - std::cos(theta)) * u * u.transpose();
}

M6 blocks(const M3& a, const M3& b, const M3& c, const M3& d) {
    M6 m;
    m << a, b, c, d;
    return m;
}

// §2: H = [[R, 0], [T R, R]] on screws, H⁻ᵀ = [[R, T R], [0, R]] on co-screws.
M6 screw_map(const M3& R, const V3& t) { return blocks(R, M3::Zero(), hat(t) * R, R); }
M6 coscrew_map(const M3& R, const V3& t) { return blocks(R, hat(t) * R, M3::Zero(), R); }

// §2: N = [[I_c − m Ĉ², m Ĉ], [m Ĉᵀ, m 1]] from the mass properties.
M6 spatial_inertia(Real m, const V3& c, const M3& Ic) {
    const M3 C = hat(c);
    return blocks(Ic - m * C * C, m * C, m * C.transpose(), m * M3::Identity());
}

// ad_s = [[ω̂, 0], [v̂, ω̂]]: [s1, s2] = ad_s1 s2, and {s, P} = −ad_sᵀ P.
M6 ad(const V6& s) {
    const M3 w = hat(s.head<3>());
    return blocks(w, M3::Zero(), hat(s.tail<3>()), w);
}
V6 lie_bracket(const V6& s1, const V6& s2) {
    const V3 w1 = s1.head<3>(), v1 = s1.tail<3>(), w2 = s2.head<3>(), v2 = s2.tail<3>();
    V6 r;
    r << w1.cross(w2), w1.cross(v2) - w2.cross(v1);
    return r;
}
V6 coadjoint_action(const V6& s, const V6& P) {
    const V3 w = s.head<3>(), v = s.tail<3>(), l = P.head<3>(), p = P.tail<3>();
    V6 r;
    r << w.cross(l) + v.cross(p), w.cross(p);
    return r;
}

// The equation of motion N ṡ + {s, N s} = W, solved for ṡ (N symmetric positive definite).
V6 solve_acceleration(const M6& N, const V6& s, const V6& W) {
    return Eigen::LDLT<M6>(N).solve(W - coadjoint_action(s, N * s));
}

// The screw motion g(τ) = exp(τ s/2): rotation by |ω|τ about the axis through q = ω × v/|ω|²
// along ω, with the translation h|ω|τ along it (pitch h = ω·v/|ω|²): x ↦ R(x − q) + q + h|ω|τ ω̂.
// Returns H(τ) (needs ω ≠ 0).
M6 screw_motion_map(const V6& s, Real tau) {
    const V3 w = s.head<3>(), v = s.tail<3>();
    const Real n = w.norm();
    const V3 u = w / n, q = w.cross(v) / (n * n);
    const Real pitch = w.dot(v) / (n * n);
    const M3 R = rodrigues(u, n * tau);
    const V3 t = (M3::Identity() - R) * q + pitch * n * tau * u;
    return screw_map(R, t);
}

// ---- conversions and the error measure -----------------------------------------------------

V3 ld(const ctga::vec3<double>& x) { return V3(x[0], x[1], x[2]); }
V6 ld(const ctga::vec6<double>& x) {
    V6 r;
    for (int i = 0; i < 6; ++i) r(i) = x[static_cast<std::size_t>(i)];
    return r;
}
M3 ld(const ctga::mat3<double>& x) {
    M3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r(i, j) = x[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    return r;
}
M6 ld(const ctga::mat6<double>& x) {
    M6 r;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) r(i, j) = x[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    return r;
}
V6 ld(const ctga::screw<double>& s) { return ld(ctga::to_vector6(s)); }
V6 ld(const ctga::coscrew<double>& P) { return ld(ctga::to_vector6(P)); }

ctga::vec6<double> to_double(const V6& x) {
    ctga::vec6<double> r{};
    for (int i = 0; i < 6; ++i) r[static_cast<std::size_t>(i)] = static_cast<double>(x(i));
    return r;
}

// rel(x, y) = max|x − y| / max(1, max|y|), y the reference.
template <class X, class Y>
double rel(const Eigen::MatrixBase<X>& x, const Eigen::MatrixBase<Y>& y) {
    const Real diff = (x - y).cwiseAbs().maxCoeff();
    const Real scale = std::max<Real>(1, y.cwiseAbs().maxCoeff());
    return static_cast<double>(diff / scale);
}
double rel(Real x, Real y) { return static_cast<double>(std::abs(x - y) / std::max<Real>(1, std::abs(y))); }

// ---- §6's equation of motion in the paper's own form ----------------------------------------

// N ∧ ṡ + ½((s̄N − Ns̄) ∧ s) (ctga::motion_lhs) against the 6×6 value (N6 ṡ + {s, N6 s}) E:
// every coefficient of the difference, over max(1, max|reference|). ṡ is any screw here (not
// the solution, whose equation would cancel large Coriolis terms against W).
double motion_lhs_error(const ctga::rigid_inertia<double>& N, const ctga::screw<double>& s,
                        const ctga::screw<double>& sdot, const V6& expected) {
    const auto lhs = ctga::eval(ctga::motion_lhs(N, s, sdot));
    const auto rhs = ctga::eval(ctga::coscrew_from_vector6(to_double(expected)) * ctga::invariants::E);
    const auto diff = ctga::eval(lhs - rhs);
    Real worst = 0;
    for (std::size_t i = 0; i < diff.size(); ++i) worst = std::max<Real>(worst, std::abs(Real(diff[i])));
    return static_cast<double>(worst / std::max<Real>(1, expected.cwiseAbs().maxCoeff()));
}

// ---- one random case ----------------------------------------------------------------------

struct sample {
    int index = 0;
    double mass = 0;
    ctga::vec3<double> com{}, axis{}, t{};
    ctga::mat3<double> inertia_c{};
    double theta = 0;
    ctga::vec6<double> s{}, s2{}, W{}, P{};
};

std::string describe(const sample& c) {
    std::ostringstream o;
    o.precision(17);
    const auto v = [&o](const char* name, const auto& a) {
        o << "  " << name << " = (";
        for (std::size_t i = 0; i < a.size(); ++i) o << (i ? ", " : "") << a[i];
        o << ")\n";
    };
    o << "case " << c.index << ":\n  m = " << c.mass << "\n";
    v("com", c.com);
    for (std::size_t i = 0; i < 3; ++i) v(i == 0 ? "I_c row 0" : i == 1 ? "I_c row 1" : "I_c row 2", c.inertia_c[i]);
    v("axis u", c.axis);
    o << "  theta = " << c.theta << "\n";
    v("t", c.t);
    v("s", c.s);
    v("s2", c.s2);
    v("W", c.W);
    v("P", c.P);
    return o.str();
}

// The worst error per quantity, in order of first appearance, and the checks themselves (one
// non-template function holds the Catch2 macros).
struct worst_error {
    std::string quantity;
    double error = 0;
    int at_case = -1;
    int checks = 0;
};
std::vector<worst_error>& table() {
    static std::vector<worst_error> t;
    return t;
}

void record(const char* quantity, double err, const sample& c) {
    auto& t = table();
    auto it = std::find_if(t.begin(), t.end(), [&](const worst_error& w) { return w.quantity == quantity; });
    if (it == t.end()) it = t.insert(t.end(), worst_error{quantity});
    ++it->checks;
    if (!(err <= it->error)) it->error = err, it->at_case = c.index;  // NaN sticks
    INFO(quantity << ": relative error " << err << " (tolerance " << tolerance << ")");
    const double in_tolerances = err / tolerance;  // Catch prints this ratio legibly
    if (!(in_tolerances <= 1)) {
        INFO(describe(c));
        CHECK(in_tolerances <= 1);
    } else {
        CHECK(in_tolerances <= 1);
    }
}

// Other measurements, each with its own bound (not the 1e-12 of a rounding comparison):
//   finite differences of the reference (truncation error O(h⁴)): rel ≤ 1e-9;
//   the opposite sign of dN/dt against the finite difference: max|difference| / max|dN/dt| ≥ 1
//   (it is 2 when the difference is accurate: the opposite sign is plainly wrong).
struct aux_measure {
    std::string what;
    double worst = 0;
    double least = std::numeric_limits<double>::infinity();
};
std::vector<aux_measure>& aux_table() {
    static std::vector<aux_measure> t;
    return t;
}
enum class bound { at_most, at_least };
void record_aux(const char* what, double err, bound kind, double limit, int at_case) {
    auto& t = aux_table();
    auto it = std::find_if(t.begin(), t.end(), [&](const aux_measure& w) { return w.what == what; });
    if (it == t.end()) it = t.insert(t.end(), aux_measure{what});
    if (!(err <= it->worst)) it->worst = err;
    if (err < it->least) it->least = err;
    INFO(what << " (case " << at_case << "): " << err);
    if (kind == bound::at_most) CHECK(err <= limit);
    if (kind == bound::at_least) CHECK(err >= limit);
}

void print_tables(int cases) {
    std::printf(
        "\nspatial_matrix_test: %d random cases; worst rel = max|ctga - eigen| / max(1, max|eigen|), bound 1e-12\n",
        cases);
    for (const auto& w : table())
        std::printf("  %-66s %10.3e  (case %4d, %5d checks)\n", w.quantity.c_str(), w.error, w.at_case, w.checks);
    std::printf("other measurements (bounds in the names), min and max over the cases:\n");
    for (const auto& w : aux_table()) std::printf("  %-66s min %10.3e  max %10.3e\n", w.what.c_str(), w.least, w.worst);
    std::fflush(stdout);
}

TEST_CASE("the mechanics agree with the 6x6 formalism of §2 on 1,000 random cases", "[mechanics][spatial][eigen]") {
    constexpr int cases = 1000;
    std::mt19937_64 rng(0x5e11'6b4c'2010'0602ULL);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
    std::uniform_real_distribution<double> log_mass(std::log(0.1), std::log(100.0));
    std::uniform_real_distribution<double> moment_per_mass(0.01, 1.0);  // principal moment / mass
    std::normal_distribution<double> gauss(0, 1);

    const auto random_axis = [&] {
        for (;;) {
            const ctga::vec3<double> a{gauss(rng), gauss(rng), gauss(rng)};
            const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
            if (n > 1e-3) return ctga::vec3<double>{a[0] / n, a[1] / n, a[2] / n};
        }
    };
    const auto random6 = [&](double scale) {
        ctga::vec6<double> v{};
        for (double& x : v) x = scale * unit(rng);
        return v;
    };

    for (int k = 0; k < cases; ++k) {
        // ---- inputs ----
        sample c;
        c.index = k;
        c.mass = std::exp(log_mass(rng));  // log-uniform in [0.1, 100]
        c.com = {unit(rng), unit(rng), unit(rng)};
        double d[3];
        do {  // principal moments, sorted, until the triangle inequality I3 ≤ I1 + I2 holds
            for (double& x : d) x = c.mass * moment_per_mass(rng);
            std::sort(d, d + 3);
        } while (!(d[2] <= d[0] + d[1]));
        {  // I_c = Q diag(d) Qᵀ for a random rotation Q, then made exactly symmetric
            const ctga::vec3<double> qa = random_axis();
            const Eigen::Matrix3d Q =
                Eigen::AngleAxisd(angle(rng), Eigen::Vector3d(qa[0], qa[1], qa[2])).toRotationMatrix();
            const Eigen::Matrix3d I = Q * Eigen::Vector3d(d[0], d[1], d[2]).asDiagonal() * Q.transpose();
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    c.inertia_c[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = (I(i, j) + I(j, i)) / 2;
        }
        c.axis = random_axis();
        c.theta = angle(rng);
        c.t = {10 * unit(rng), 10 * unit(rng), 10 * unit(rng)};
        const double scale = k % 50 == 49 ? 1e3 : 1.0;  // 20 cases with large velocities and wrenches
        c.s = random6(scale);
        c.s2 = random6(scale);
        c.W = random6(scale);
        c.P = random6(scale);

        // ---- reference (long double) ----
        const Real m = c.mass;
        const V3 com = ld(c.com), u = ld(c.axis), t = ld(c.t);
        const M3 Ic = ld(c.inertia_c);
        const M3 R = rodrigues(u, c.theta);
        const M6 H = screw_map(R, t);
        const M6 HinvT = coscrew_map(R, t);
        const M6 Hinv = HinvT.transpose();
        const M6 N6 = spatial_inertia(m, com, Ic);
        const M6 M6ref = N6.inverse();
        const M6 N6f = HinvT * N6 * Hinv;  // the inertia moved by g (fixed frame)
        const M6 M6f = H * M6ref * H.transpose();
        const V6 s = ld(c.s), s2 = ld(c.s2), W = ld(c.W), P = ld(c.P);

        // ---- ctga ----
        const auto mp_checked = ctga::make_mass_properties(c.mass, c.com, c.inertia_c);
        INFO("case " << k);
        REQUIRE(mp_checked.error == ctga::error_code::none);
        const ctga::mass_properties<double>& mp = *mp_checked;
        const ctga::rigid_inertia<double> N = ctga::inertia_of(mp);
        const ctga::mobility<double> M = ctga::mobility_of(mp);
        const ctga::motor<double> g = ctga::rigid_motion(ctga::make_translator(c.t[0], c.t[1], c.t[2]),
                                                         ctga::make_rotor(c.theta, c.axis[0], c.axis[1], c.axis[2]));
        const ctga::motor_map<double> G = ctga::map_of(g);
        const auto cs = ctga::screw_from_vector6(c.s), cs2 = ctga::screw_from_vector6(c.s2);
        const auto cW = ctga::coscrew_from_vector6(c.W), cP = ctga::coscrew_from_vector6(c.P);

        // ---- the reference's own identities ----
        record("reference: H^-T block form vs H.inverse().transpose()", rel(HinvT, H.inverse().transpose()), c);
        record("reference: M6 * N6 = 1", rel(M6ref * N6, M6::Identity()), c);
        record("reference: duality s1^T {s2, P} = [s1, s2]^T P",
               rel(s.dot(coadjoint_action(s2, P)), lie_bracket(s, s2).dot(P)), c);
        record("reference: bracket = ad_s1 s2, coadjoint = -ad_s^T P",
               std::max(rel(ad(s) * s2, lie_bracket(s, s2)), rel(-ad(s).transpose() * P, coadjoint_action(s, P))), c);

        // ---- motors (§3): g = t r as a dual quaternion α + ε β, β = ½ t α ----
        {
            const Real half_angle = Real(c.theta) / 2;
            const Quat alpha(std::cos(half_angle), std::sin(half_angle) * u(0), std::sin(half_angle) * u(1),
                             std::sin(half_angle) * u(2));
            const Quat tq(0, t(0), t(1), t(2));
            const Quat beta_raw = tq * alpha;
            Eigen::Matrix<Real, 8, 1> ref, got;
            ref << alpha.w(), alpha.x(), alpha.y(), alpha.z(), beta_raw.w() / 2, beta_raw.x() / 2, beta_raw.y() / 2,
                beta_raw.z() / 2;
            for (int i = 0; i < 8; ++i) got(i) = g[static_cast<std::size_t>(i)];
            record("rigid_motion(translation, rotation) vs dual quaternion", rel(got, ref), c);

            // dg/dt for the fixed-frame velocity s = (ω, v): α̇ = ½ ω α (spatial angular velocity)
            // and, t being the body origin, ṫ = ω × t + v, β̇ = ½ (ṫ α + t α̇).
            const Quat wq(0, s(0), s(1), s(2));
            const V3 tdot = s.head<3>().cross(t) + s.tail<3>();
            const Quat alpha_dot = wq * alpha;  // ×½ below
            const Quat beta_dot = Quat(0, tdot(0), tdot(1), tdot(2)) * alpha;
            const Quat t_alpha_dot = tq * alpha_dot;
            Eigen::Matrix<Real, 8, 1> gdot;
            gdot << alpha_dot.w() / 2, alpha_dot.x() / 2, alpha_dot.y() / 2, alpha_dot.z() / 2,
                (beta_dot.w() + t_alpha_dot.w() / 2) / 2, (beta_dot.x() + t_alpha_dot.x() / 2) / 2,
                (beta_dot.y() + t_alpha_dot.y() / 2) / 2, (beta_dot.z() + t_alpha_dot.z() / 2) / 2;

            const ctga::rigid_body<double> body = ctga::make_rigid_body(mp);
            const ctga::state_rate<double> fixed = ctga::fixed_frame_rates(body, g, cs, cW);
            for (int i = 0; i < 8; ++i) got(i) = fixed.g_dot[static_cast<std::size_t>(i)];
            record("fixed_frame_rates: g_dot = s g / 2", rel(got, gdot), c);

            // The same state in the body frame: s_b = H⁻¹ s, W_b = Hᵀ W (rounded to double, and
            // the body-frame reference computed from the rounded values).
            const ctga::vec6<double> sb_d = to_double(V6(H.inverse() * s)), Wb_d = to_double(V6(H.transpose() * W));
            const V6 sb = ld(sb_d), Wb = ld(Wb_d);
            const ctga::state_rate<double> in_body =
                ctga::body_frame_rates(body, g, ctga::screw_from_vector6(sb_d), ctga::coscrew_from_vector6(Wb_d));
            for (int i = 0; i < 8; ++i) got(i) = in_body.g_dot[static_cast<std::size_t>(i)];
            record("body_frame_rates: g_dot = g s_b / 2", rel(got, gdot), c);

            // ṡ: fixed frame (N6 moved by g) and body frame (N6 constant), by LDLT
            const V6 sdot = solve_acceleration(N6f, s, W);
            const V6 sdot_b = solve_acceleration(N6, sb, Wb);
            record("reference: fixed-frame s_dot = H * body-frame s_dot_b", rel(H * sdot_b, sdot), c);
            {
                // LDLT's residual, over the size of the terms that cancel in it (with |s| ~ 1e3 the
                // Coriolis term {s, N s} is ~1e7 times W): max|N ṡ + {s, N s} − W| / max(1, each term).
                const V6 Nsdot = N6f * sdot, coriolis = coadjoint_action(s, N6f * s);
                const Real terms = std::max(
                    {Real(1), Nsdot.cwiseAbs().maxCoeff(), coriolis.cwiseAbs().maxCoeff(), W.cwiseAbs().maxCoeff()});
                record("reference: N6 s_dot + {s, N6 s} = W (LDLT residual / max term)",
                       static_cast<double>((Nsdot + coriolis - W).cwiseAbs().maxCoeff() / terms), c);
            }
            // The fixed-frame problem is the worst conditioned here (cond(H⁻ᵀ N6 H⁻¹) reaches ~9e5
            // with |t| up to 17): ctga's worst rel is ~2e-13 (fixed_frame_rates) to ~4e-13
            // (acceleration on moved elements). For scale, measured once with this seed: the same
            // solve by Eigen in double (H, N6, H⁻ᵀ N6 H⁻¹, LDLT) reaches rel 1.7e-12 against this
            // reference, and iterative refinement moves the long double reference by ≤ 4.4e-16.
            record("fixed_frame_rates: s_dot", rel(ld(fixed.s_dot), sdot), c);

            record("body_frame_rates: s_dot", rel(ld(in_body.s_dot), sdot_b), c);
            record("fixed-frame s_dot vs H * body-frame s_dot (both ctga)", rel(ld(fixed.s_dot), H * ld(in_body.s_dot)),
                   c);

            // acceleration() on the inertia and mobility moved as elements (not via mass properties)
            const ctga::screw<double> acc = ctga::acceleration(ctga::transform(G, N), ctga::transform(G, M), cs, cW);
            record("acceleration(H^-T N H^-1, H M H^T, s, W)", rel(ld(acc), sdot), c);
        }

        // ---- the map of a motor, and its action on screws and co-screws (§2) ----
        record("map_of(g).R vs Rodrigues", rel(ld(G.R), R), c);
        record("map_of(g).t", rel(ld(G.t), t), c);
        record("transform(g, screw) vs H s", rel(ld(ctga::transform(g, cs)), H * s), c);
        {
            const ctga::screw<double> gsg = ctga::adjoint(g, cs);
            record("adjoint(g, s) = g s g* vs H s", rel(ld(gsg), H * s), c);
        }
        record("transform(g, coscrew) vs H^-T P", rel(ld(ctga::transform(g, cP)), HinvT * P), c);

        // ---- inertia and mobility (§5) ----
        record("inertia_matrix(inertia_of(mp)) vs N6", rel(ld(ctga::inertia_matrix(N)), N6), c);
        record("mobility_matrix(mobility_of(mp)) vs N6^-1", rel(ld(ctga::mobility_matrix(M)), M6ref), c);
        record("momentum(N, s) = A v (N ^ s) vs N6 s", rel(ld(ctga::momentum(N, cs)), N6 * s), c);
        record("kinetic_energy(N, s) vs s^T N6 s / 2", rel(Real(ctga::kinetic_energy(N, cs)), s.dot(N6 * s) / 2), c);
        record("velocity_from(M, P) = E v (M ^ P) vs N6^-1 P", rel(ld(ctga::velocity_from(M, cP)), M6ref * P), c);
        record("pairing(P, s) vs P^T s", rel(Real(ctga::pairing(cP, cs)), P.dot(s)), c);

        // ---- bracket, coadjoint action and their duality (§2, §6) ----
        const ctga::screw<double> br = ctga::bracket(cs, cs2);
        const ctga::coscrew<double> co = ctga::coadjoint(cs2, cP);
        record("bracket(s1, s2)", rel(ld(br), lie_bracket(s, s2)), c);
        record("coadjoint(s, P)", rel(ld(co), coadjoint_action(s2, P)), c);
        {
            // s1ᵀ {s2, P} = [s1, s2]ᵀ P, both sides through ctga
            const Real lhs = ctga::pairing(co, cs), rhs = ctga::pairing(cP, br);
            record("duality: pairing(coadjoint(s2, P), s1) vs reference", rel(lhs, s.dot(coadjoint_action(s2, P))),
                   c);
            record("duality: pairing(P, bracket(s1, s2)) vs reference", rel(rhs, lie_bracket(s, s2).dot(P)), c);
        }

        // ---- moving inertias and mobilities (§2: N → H⁻ᵀ N H⁻¹, M → H M Hᵀ) ----
        const ctga::rigid_inertia<double> Nf = ctga::transform(G, N);
        record("transform(g, rigid_inertia) vs H^-T N6 H^-1", rel(ld(ctga::inertia_matrix(Nf)), N6f), c);
        {
            const ctga::mass_properties<double> moved = ctga::transform(G, mp);
            record("transform(g, mass_properties): com vs R c + t", rel(ld(moved.com), R * com + t), c);
            record("transform(g, mass_properties): I_c vs R I_c R^T", rel(ld(moved.inertia_c), R * Ic * R.transpose()),
                   c);
            record("inertia_of(transform(g, mp)) vs H^-T N6 H^-1",
                   rel(ld(ctga::inertia_matrix(ctga::inertia_of(moved))), N6f), c);
            record("mobility_of(transform(g, mp)) vs H N6^-1 H^T",
                   rel(ld(ctga::mobility_matrix(ctga::mobility_of(moved))), M6f), c);
        }
        record("transform(g, mobility) vs H N6^-1 H^T", rel(ld(ctga::mobility_matrix(ctga::transform(G, M))), M6f), c);
        record("momentum(transform(g, N), s) vs H^-T N6 H^-1 s", rel(ld(ctga::momentum(Nf, cs)), N6f * s), c);
        {
            // general elements: any 36 coefficients
            ctga::mat6<double> X{}, Y{};
            for (auto& row : X)
                for (double& x : row) x = unit(rng);
            for (auto& row : Y)
                for (double& y : row) y = unit(rng);
            const ctga::inertia<double> Xi = ctga::inertia_from_matrix(X);
            const ctga::mobility<double> Ym = ctga::mobility_from_matrix(Y);
            record("inertia_matrix(inertia_from_matrix(X)) = X", rel(ld(ctga::inertia_matrix(Xi)), ld(X)), c);
            record("mobility_matrix(mobility_from_matrix(Y)) = Y", rel(ld(ctga::mobility_matrix(Ym)), ld(Y)), c);
            record("transform(g, inertia) (36 blades) vs H^-T X H^-1",
                   rel(ld(ctga::inertia_matrix(ctga::transform(G, Xi))), HinvT * ld(X) * Hinv), c);
            record("transform(g, mobility) (any Y) vs H Y H^T",
                   rel(ld(ctga::mobility_matrix(ctga::transform(G, Ym))), H * ld(Y) * H.transpose()), c);
        }

        // ---- dN/dt (§6) ----
        {
            const M6 Ndot_body = -ad(s).transpose() * N6 - N6 * ad(s);
            const M6 Ndot_fixed = -ad(s).transpose() * N6f - N6f * ad(s);
            record("inertia_rate(N, s) vs -ad_s^T N6 - N6 ad_s",
                   rel(ld(ctga::inertia_matrix(ctga::inertia_rate(N, cs))), Ndot_body), c);
            record("inertia_rate(H^-T N H^-1, s) vs -ad_s^T N - N ad_s",
                   rel(ld(ctga::inertia_matrix(ctga::inertia_rate(Nf, cs))), Ndot_fixed), c);

            // The sign, settled by differentiating N(τ) = H(τ)⁻ᵀ N H(τ)⁻¹ along g(τ) = exp(τ s/2),
            // H(τ) from the screw motion's rotation and translation. Richardson-extrapolated
            // central differences (error O(h⁴)); the step scales with 1/|s|.
            const Real h = Real(1e-3) / std::max<Real>(1, s.norm());
            const auto N_at = [&](Real tau) {
                const M6 Ht = screw_motion_map(s, tau);
                const M6 Hti = Ht.inverse();
                return M6(Hti.transpose() * N6f * Hti);
            };
            const auto H_at = [&](Real tau) { return screw_motion_map(s, tau); };
            const M6 D1 = (N_at(h) - N_at(-h)) / (2 * h), D2 = (N_at(h / 2) - N_at(-h / 2)) / h;
            const M6 Nfd = (4 * D2 - D1) / 3;
            const M6 E1 = (H_at(h) - H_at(-h)) / (2 * h), E2 = (H_at(h / 2) - H_at(-h / 2)) / h;
            const M6 Hfd = (4 * E2 - E1) / 3;
            record_aux("finite difference (<= 1e-9): dH/dt at 0 along exp(t s/2) vs ad_s", rel(Hfd, ad(s)),
                       bound::at_most, 1e-9, k);
            record_aux("finite difference (<= 1e-9): dN/dt vs -ad_s^T N - N ad_s", rel(Nfd, Ndot_fixed), bound::at_most,
                       1e-9, k);
            record_aux("finite difference (<= 1e-9): dN/dt vs ctga::inertia_rate (paper)",
                       rel(ld(ctga::inertia_matrix(ctga::inertia_rate(Nf, cs))), Nfd), bound::at_most, 1e-9, k);
            // the opposite sign, relative to the derivative itself (2 for an accurate difference)
            record_aux("finite difference (>= 1): |dN/dt - (+ad_s^T N + N ad_s)| / |dN/dt|",
                       static_cast<double>((Nfd + Ndot_fixed).cwiseAbs().maxCoeff() / Nfd.cwiseAbs().maxCoeff()),
                       bound::at_least, 1.0, k);
            // dP/dt = W with P = N(t) s(t): (N s)' = Ṅ s + N ṡ, and Ṅ s = {s, N s} (ad_s s = 0)
            record("reference: dN/dt s = {s, N s}", rel(Ndot_fixed * s, coadjoint_action(s, N6f * s)), c);
            record("motion_lhs(N, s, sdot) vs (N6 sdot + {s, N6 s}) E",
                   motion_lhs_error(N, cs, cs2, N6 * s2 + coadjoint_action(s, N6 * s)), c);
            record("motion_lhs(H^-T N H^-1, s, sdot) vs (N sdot + {s, N s}) E",
                   motion_lhs_error(Nf, cs, cs2, N6f * s2 + coadjoint_action(s, N6f * s)), c);
        }
    }

    print_tables(cases);
}

// ---- rejected inputs ------------------------------------------------------------------------

TEST_CASE("make_mass_properties rejects what no rigid body has", "[mechanics][spatial][checked]") {
    using ctga::error_code;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const ctga::vec3<double> com{0.1, -0.2, 0.3};
    // a valid tensor, non-diagonal: principal moments (1, 2, 2.5) rotated
    const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const auto tensor = [&Q](double d0, double d1, double d2) {
        const Eigen::Matrix3d I = Q * Eigen::Vector3d(d0, d1, d2).asDiagonal() * Q.transpose();
        ctga::mat3<double> out{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                out[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = (I(i, j) + I(j, i)) / 2;
        return out;
    };
    const ctga::mat3<double> good = tensor(1, 2, 2.5);
    REQUIRE(ctga::make_mass_properties(2.0, com, good).error == error_code::none);

    SECTION("NaN or infinity in any input") {
        for (double bad : {nan, inf, -inf}) {
            CHECK(ctga::make_mass_properties(bad, com, good).error == error_code::non_finite);
            for (std::size_t i = 0; i < 3; ++i) {
                ctga::vec3<double> c = com;
                c[i] = bad;
                CHECK(ctga::make_mass_properties(2.0, c, good).error == error_code::non_finite);
                for (std::size_t j = 0; j < 3; ++j) {
                    ctga::mat3<double> I = good;
                    I[i][j] = bad;
                    CHECK(ctga::make_mass_properties(2.0, com, I).error == error_code::non_finite);
                }
            }
        }
    }
    SECTION("m <= 0") {
        for (double m : {0.0, -0.0, -1.0, -1e-300})
            CHECK(ctga::make_mass_properties(m, com, good).error == error_code::non_positive_mass);
    }
    SECTION("a non-symmetric tensor") {
        ctga::mat3<double> I = good;
        I[0][1] += 1e-3;
        CHECK(ctga::make_mass_properties(2.0, com, I).error == error_code::not_symmetric);
        I = good;
        I[2][1] -= 0.5;
        CHECK(ctga::make_mass_properties(2.0, com, I).error == error_code::not_symmetric);
    }
    SECTION("a tensor that is not positive definite") {
        CHECK(ctga::make_mass_properties(2.0, com, tensor(1, 1, 0)).error == error_code::not_positive_definite);
        CHECK(ctga::make_mass_properties(2.0, com, tensor(1, 1, -0.5)).error == error_code::not_positive_definite);
        CHECK(ctga::make_mass_properties(2.0, com, tensor(-1, 2, 2.5)).error == error_code::not_positive_definite);
        CHECK(ctga::make_mass_properties(2.0, com, ctga::mat3<double>{}).error == error_code::not_positive_definite);
    }
    SECTION("principal moments violating the triangle inequality") {
        const ctga::mat3<double> diag{{{1, 0, 0}, {0, 1, 0}, {0, 0, 3}}};
        CHECK(ctga::make_mass_properties(2.0, com, diag).error == error_code::triangle_inequality);
        CHECK(ctga::make_mass_properties(2.0, com, tensor(1, 1, 3)).error == error_code::triangle_inequality);
        CHECK(ctga::make_mass_properties(2.0, com, tensor(3, 1, 1)).error == error_code::triangle_inequality);
        CHECK(ctga::make_mass_properties(2.0, com, tensor(1, 2, 3.001)).error == error_code::triangle_inequality);
        // equality is a lamina, allowed
        CHECK(ctga::make_mass_properties(2.0, com, tensor(1, 2, 3)).error == error_code::none);
    }
}

}  // namespace
