// The integrators of include/ctga/integrators/ are written once against the motion_model
// concept; here the same methods run on three representations of one rigid body's motion and
// must produce the same numbers:
//
//   ctga     ctga::rigid_body_motion (the library: sparse Cl(0,3,1) / Cl(0,6,2), §3–6)
//   dense    tests/support/dense_model.hpp: the paper's formulas evaluated literally in the naive
//            dense 256-blade Cl(0,6,2) (P = A ∨ (N ∧ s), ṡ = E ∨ (M ∧ (W − ½(s̄P − Ps̄))),
//            N' = (g ḡ) N (g ḡ)*), motors and screws as dense 16-component Cl(0,3,1) elements
//   matrix   tests/support/matrix_model.hpp: the 6×6 formalism of §2 in Eigen (ṡ = M(W − s ×* Ns),
//            N' = H⁻ᵀ N H⁻¹, M' = H M Hᵀ), motors as 8-vectors (dual quaternions)
//
// Error measure (as in exp_log_test / spatial_matrix_test): for a result x and the reference y
// of one quantity (ctga's, all components), rel(x, y) = max_i |x_i − y_i| / max(1, max_i |y_i|).
//
// 1. Primitives on 200 random bodies (boxes of sides 0.2–2.2 turned at random, centre of mass
//    off the origin), poses (|t| ≤ 2√3, θ ≤ 3), screws, wrenches and drifted motors: motor_rate
//    (both frames), exp (θ from 0 to ~17, and ω = 0), compose, bracket, renormalize ≤ 1e-14;
//    acceleration (both frames, free and with a wrench, the fixed frame also against ctga's
//    about_body evaluation) ≤ 1e-14 in the body frame and, in both frames, rel/κ ≤ 1e-15 ≈ 9ε,
//    κ = max|N_ij|·max|M_ij| of the inertia and mobility used (the fixed-frame N', M' have
//    entries m|t|² and |t|²/I_min, κ up to 1.9e3 here: every representation, ctga's included,
//    loses that much; against a long double reference ctga's about_body evaluation is the
//    accurate one). The sign conventions the models rest on are checked on the way: the dense
//    blades of ctga::motor / ctga::screw / ctga::coscrew and the lift (against ctga's own
//    to_dense(lift(·))), N and M built from the mass properties against convert.hpp's matrices,
//    H s = g s g*, H⁻ᵀ P = ḡ P ḡ*, H H⁻¹ = 1, Featherstone's crf(s) = −crm(s)ᵀ = ctga::coadjoint
//    (so ṡ = M(W − crf(s) N s) is ctga's sign) and crm = ctga::bracket, and the dense
//    (g ḡ) N (g ḡ)*, (g ḡ) M (g ḡ)* against inertia_of / mobility_of of the moved mass properties.
//    Measured worst (g++ 12, Release -O3, x86-64):
//      acceleration, body: dense 5.4e-15, matrix 5.8e-15 (rel/κ 2.5e-16)
//      acceleration, fixed: dense 1.0e-13, matrix 8.0e-14 (rel/κ 6.6e-16)
//      motor_rate 2.2e-16, exp 0 (same steps, same rounding), compose 4.0e-16, bracket 2.2e-16,
//      renormalize 0; conventions ≤ 3.6e-15 (M N = 1), the blade mappings exactly 0
//      long double (10 inputs): accelerations rel/κ ≤ 8.2e-20, the others ≤ 9.8e-20
//
// 2. Trajectories: a free asymmetric body (mass 2, centre of mass (0.1, −0.2, 0.3), inertia
//    tensor with off-diagonal terms), a non-trivial pose and velocity, h = 0.01; dense for 200
//    steps, matrix for 2000 steps (and 200), each against ctga, final motor and screw ≤ 1e-12.
//    Every method in both frames. Measured worst:
//      body frame: dense(200) 9.4e-16, matrix(200) 8.3e-16, matrix(2000) 1.9e-14
//      fixed frame: dense(200) 2.6e-15, matrix(200) 2.8e-15, matrix(2000) 1.4e-13
//      a constant wrench: body frame (rk4, lie_rk4) ≤ 4.0e-15 up to matrix(2000); fixed frame
//      (lie_rk4, implicit_midpoint, 200 steps) ≤ 2.9e-15
//
//    Off the unit motors: in the fixed frame, explicit Euler's states and RK4's stages have
//    g g* ≠ 1. ctga's map_of is homogeneous (it reads the rigid motion g encodes, = the map of
//    renormalize(g)), and the two other models evaluate the dynamics at renormalize(g)
//    (evaluate_at_unit_pose, their default): the same function of g in every representation.
//    (The paper's sandwich with g as given would scale N' and M' by |α|⁴; evaluated that way,
//    explicit Euler's trajectories differ by 1e-2 after 200 steps.)
//
// Runtime: about 6.5 s in Release (the dense Cl(0,6,2) products dominate).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <utility>

#include <Eigen/Dense>

#include <ctga/ctga.hpp>
#include <ctga/integrators/integrate.hpp>
#include <ctga/integrators/methods.hpp>
#include <ctga/integrators/model.hpp>
#include <ctga/reference/dense.hpp>

#include "support/catch.hpp"
#include "support/general_reference.hpp"
#include "support/dense_model.hpp"
#include "support/matrix_model.hpp"

namespace {

using namespace ctga;
namespace ct = ctga::test;

// ---- measuring ---------------------------------------------------------------------------------

using ctga::test::rel;  // support/general_reference.hpp
// The same over all components of two arrays of numbers (y the reference).
template <class T, std::size_t N>
double rel_all(const std::array<T, N>& x, const std::array<T, N>& y) {
    long double d = 0, m = 1;
    for (std::size_t i = 0; i < N; ++i) {
        d = std::max(d, std::fabs(static_cast<long double>(x[i]) - static_cast<long double>(y[i])));
        m = std::max(m, std::fabs(static_cast<long double>(y[i])));
    }
    return static_cast<double>(d / m);
}
template <class Alg, class T>
double rel_dense(const dense::multivector<Alg, T>& x, const dense::multivector<Alg, T>& y) {
    return rel_all(x.components(), y.components());
}
// ... and of two Eigen vectors or matrices.
template <class X, class Y>
double rel_eigen(const Eigen::MatrixBase<X>& x, const Eigen::MatrixBase<Y>& y) {
    const double scale = std::max(1.0, static_cast<double>(y.cwiseAbs().maxCoeff()));
    return static_cast<double>((x - y).cwiseAbs().maxCoeff()) / scale;
}

// The worst error seen per quantity, checked against its bound and printed at the end.
struct worst_errors {
    std::map<std::string, std::pair<double, double>> seen;  // name -> (worst, bound)

    // bound < 0: measured and printed, not checked
    void record(const std::string& name, double err, double bound) {
        auto& [w, b] = seen[name];
        b = bound;
        if (!(err <= w)) w = err;  // a NaN sticks
    }
    void check_and_print(const char* title) const {
        std::printf("%s (worst rel, bound):\n", title);
        for (const auto& [name, wb] : seen) {
            if (wb.second < 0) {
                std::printf("  %-58s %.2e  (measured)\n", name.c_str(), wb.first);
                continue;
            }
            std::printf("  %-58s %.2e  (%.0e)\n", name.c_str(), wb.first, wb.second);
            INFO(name << ": worst relative error " << wb.first << ", bound " << wb.second);
            CHECK(wb.first <= wb.second);
        }
    }
};

// ---- inputs ------------------------------------------------------------------------------------

template <class T>
struct random_inputs {
    std::mt19937_64 rng;
    std::uniform_real_distribution<double> u{-1.0, 1.0};

    explicit random_inputs(unsigned seed) : rng(seed) {}

    T uniform() { return T(u(rng)); }
    std::array<T, 3> unit() {
        const T x = uniform(), y = uniform(), z = uniform();
        using std::sqrt;
        const T r = sqrt(x * x + y * y + z * z);
        return {x / r, y / r, z / r};
    }
    motor<T> pose() {
        const auto a = unit();
        // Drawn one by one: the order in which a call's arguments are evaluated is unspecified
        // (g++ goes right to left, clang++ left to right), and both compilers must see the same
        // inputs. This is the order g++ drew them in as arguments, so its inputs are unchanged.
        const T angle = T(3) * uniform();
        const T tz = T(2) * uniform(), ty = T(2) * uniform(), tx = T(2) * uniform();
        return motor<T>(rigid_motion(make_translator(tx, ty, tz), make_rotor(angle, a[0], a[1], a[2])));
    }
    screw<T> twist() { return screw<T>{uniform(), uniform(), uniform(), uniform(), uniform(), uniform()}; }
    coscrew<T> cotwist() { return coscrew<T>{uniform(), uniform(), uniform(), uniform(), uniform(), uniform()}; }
    // a box of random sides and mass, turned by a random rotation, centre of mass off the origin
    mass_properties<T> body() {
        const T m = T(2) + uniform(), a = T(1.2) + uniform(), b = T(1.2) + uniform(), c = T(1.2) + uniform();
        const T d[3] = {m * (b * b + c * c) / T(12), m * (a * a + c * c) / T(12), m * (a * a + b * b) / T(12)};
        const motor_map<T> turn = map_of(pose());
        mat3<T> I{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int l = 0; l < 3; ++l) I[i][j] += turn.R[i][l] * d[l] * turn.R[j][l];
        const vec3<T> com{T(0.3) * uniform(), T(0.3) * uniform(), T(0.3) * uniform()};
        return *make_mass_properties(m, com, I);
    }
};

// ---- constant wrenches, one per representation -------------------------------------------------

struct ctga_constant_wrench {
    wrench<double> W;
    wrench<double> operator()(const motor<double>&, const screw<double>&) const { return W; }
};
struct dense_constant_wrench {
    ct::dense62<double> W;
    ct::dense62<double> operator()(const ct::dense31<double>&, const ct::dense31<double>&) const { return W; }
};
struct matrix_constant_wrench {
    ct::vector6<double> W;
    ct::vector6<double> operator()(const ct::vector8<double>&, const ct::vector6<double>&) const { return W; }
};

static_assert(motion_model<ct::dense_motion<double, frame::fixed>>);
static_assert(motion_model<ct::dense_motion<double, frame::body>>);
static_assert(motion_model<ct::dense_motion<long double, frame::body>>);
static_assert(motion_model<ct::matrix_motion<double, frame::fixed>>);
static_assert(motion_model<ct::matrix_motion<double, frame::body>>);
static_assert(motion_model<ct::matrix_motion<long double, frame::fixed>>);

// ---- primitives ------------------------------------------------------------------------------

constexpr double tight = 1e-14;
constexpr double kappa_bound = 1e-15;

TEST_CASE("the conventions the dense and matrix models rest on", "[integrators][representations]") {
    random_inputs<double> in(7);
    worst_errors w;
    for (int k = 0; k < 100; ++k) {
        const mass_properties<double> b = in.body();
        const motor<double> g = in.pose();
        const screw<double> s = in.twist();
        const coscrew<double> P = in.cotwist();

        // dense blades: ctga::motor / screw orientations (β0 on e e1e2e3 = −e1e2e3e), and the lift
        w.record("dense_of(motor) = to_dense(motor)", rel_dense(ct::dense_of(g), dense::to_dense(g)), 0);
        w.record("dense_of(screw) = to_dense(screw)", rel_dense(ct::dense_of(s), dense::to_dense(s)), 0);
        w.record("dense lift = to_dense(ctga::lift)",
                 rel_dense(ct::dense_model_detail::lift(ct::dense_of(s)), dense::to_dense(eval(lift(s)))), 0);
        w.record("dense lift of a motor = to_dense(ctga::lift)",
                 rel_dense(ct::dense_model_detail::lift(ct::dense_of(g)), dense::to_dense(eval(lift(g)))), 0);
        w.record("coscrew_to_dense = to_dense(coscrew)", rel_dense(ct::coscrew_to_dense(P), dense::to_dense(P)), 0);

        // N and M from the mass properties (matrix model) against convert.hpp's matrices of
        // inertia_of / mobility_of
        const auto N6 = ct::inertia_matrix6(b);
        const auto M6 = ct::mobility_matrix6(b);
        const mat6<double> Nc = inertia_matrix(inertia_of(b)), Mc = mobility_matrix(mobility_of(b));
        double dn = 0, dm = 0, sn = 1, sm = 1;
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) {
                const auto I = static_cast<std::size_t>(i), J = static_cast<std::size_t>(j);
                dn = std::max(dn, std::fabs(N6(i, j) - Nc[I][J])), sn = std::max(sn, std::fabs(Nc[I][J]));
                dm = std::max(dm, std::fabs(M6(i, j) - Mc[I][J])), sm = std::max(sm, std::fabs(Mc[I][J]));
            }
        w.record("matrix N = inertia_matrix(inertia_of)", dn / sn, tight);
        w.record("matrix M = mobility_matrix(mobility_of)", dm / sm, tight);
        w.record("matrix M N = 1", rel_eigen(M6 * N6, ct::matrix6<double>::Identity()), tight);

        // H s = g s g*, H⁻ᵀ P = ḡ P ḡ* (motor.hpp), H H⁻¹ = 1
        const auto A = ct::matrix_model_detail::adjoint_of<double>(ct::matrix_of(g));
        w.record("H s = g s g*", rel(ct::to_ctga(ct::vector6<double>(A.H * ct::matrix_of(s))), screw<double>(adjoint(g, s))),
                 tight);
        const ct::vector6<double> HP = A.H_inverse.transpose() * ct::matrix_of(P);
        const coscrew<double> moved_P = transform(map_of(g), P);
        w.record("H^-T P = g_bar P g_bar*", rel_eigen(HP, ct::matrix_of(moved_P)), tight);
        w.record("H H^-1 = 1", rel_eigen(A.H * A.H_inverse, ct::matrix6<double>::Identity()), tight);

        // Featherstone's cross operators: crf(s) = −crm(s)ᵀ, crf = ctga::coadjoint, crm = ctga::bracket
        const screw<double> s2 = in.twist();
        const ct::vector6<double> vs = ct::matrix_of(s), vs2 = ct::matrix_of(s2), vP = ct::matrix_of(P);
        ct::matrix6<double> crm;
        for (int j = 0; j < 6; ++j)
            crm.col(j) = ct::matrix_model_detail::motion_cross<double>(vs, ct::matrix6<double>::Identity().col(j));
        w.record("crf(s) P = -crm(s)^T P",
                 rel_eigen(ct::matrix_model_detail::force_cross<double>(vs, vP), -crm.transpose() * vP), tight);
        w.record("crf(s) P = ctga::coadjoint(s, P)",
                 rel_eigen(ct::matrix_model_detail::force_cross<double>(vs, vP),
                           ct::matrix_of(coscrew<double>(coadjoint(s, P)))),
                 tight);
        w.record("crm(s) s2 = ctga::bracket(s, s2)",
                 rel(ct::to_ctga(ct::matrix_model_detail::motion_cross<double>(vs, vs2)), bracket(s, s2)), tight);

        // the dense sandwich (g ḡ) N (g ḡ)* and (g ḡ) M (g ḡ)* = inertia_of / mobility_of of the
        // mass properties moved by g (c' = R c + t, I' = R I Rᵀ)
        if (k < 20) {
            const ct::dense_motion<double, frame::fixed> D(b);
            const auto moved = D.moved_inertia(ct::dense_of(g));
            const mass_properties<double> in_space = transform(map_of(g), b);
            w.record("dense (g g_bar) N (g g_bar)* = inertia_of(moved)",
                     rel_dense(moved[0], dense::to_dense(inertia_of(in_space))), tight);
            w.record("dense (g g_bar) M (g g_bar)* = mobility_of(moved)",
                     rel_dense(moved[1], dense::to_dense(mobility_of(in_space))), tight);
        }
    }
    w.check_and_print("conventions");
}

// κ = max|N_ij| · max|M_ij| of the inertia and mobility the acceleration is computed with (moved
// to the fixed frame by g there): the growth of rounding through P = N s and ṡ = M(W − {s, P}).
// The fixed-frame N' has entries m|t|² and M' entries |t|²/I_min: κ reaches ~2e3 on these inputs.
template <class T, frame F>
double condition(const ct::matrix_motion<T, F>& X, const motor<T>& g) {
    if constexpr (F == frame::fixed) {
        const auto A = ct::matrix_model_detail::adjoint_of<T>(ct::matrix_of(g));
        const ct::matrix6<T> Nf = A.H_inverse.transpose() * X.N * A.H_inverse, Mf = A.H * X.M * A.H.transpose();
        return static_cast<double>(Nf.cwiseAbs().maxCoeff() * Mf.cwiseAbs().maxCoeff());
    } else {
        return static_cast<double>(X.N.cwiseAbs().maxCoeff() * X.M.cwiseAbs().maxCoeff());
    }
}

template <frame F>
void compare_primitives(worst_errors& w, unsigned seed, int count) {
    const std::string tag = F == frame::fixed ? " (fixed)" : " (body)";
    random_inputs<double> in(seed);
    for (int k = 0; k < count; ++k) {
        const mass_properties<double> b = in.body();
        const motor<double> g = in.pose();
        const screw<double> s = in.twist();
        const coscrew<double> W = in.cotwist();

        const rigid_body_motion<double, F> C{make_rigid_body(b)};
        const ct::dense_motion<double, F> D(b);
        const ct::matrix_motion<double, F> X(b);
        const rigid_body_motion<double, F, ctga_constant_wrench> Cw{make_rigid_body(b), {W}};
        const ct::dense_motion<double, F, dense_constant_wrench> Dw(b, {ct::coscrew_to_dense(W)});
        const ct::matrix_motion<double, F, matrix_constant_wrench> Xw(b, {ct::matrix_of(W)});

        // each acceleration: the raw rel (checked ≤ 1e-14 in the body frame, printed in the fixed
        // frame) and rel/κ (checked ≤ 1e-15 ≈ 9ε in both)
        const double kappa = condition(X, g);
        const auto acc = [&](const std::string& name, double err) {
            w.record(name + tag, err, F == frame::fixed ? -1.0 : tight);
            w.record(name + tag + " / kappa", err / kappa, kappa_bound);
        };
        const screw<double> a = C.acceleration(g, s), aw = Cw.acceleration(g, s);
        acc("dense acceleration", rel(ct::screw_of_dense(D.acceleration(ct::dense_of(g), ct::dense_of(s))), a));
        acc("matrix acceleration", rel(ct::to_ctga(X.acceleration(ct::matrix_of(g), ct::matrix_of(s))), a));
        acc("dense acceleration, wrench", rel(ct::screw_of_dense(Dw.acceleration(ct::dense_of(g), ct::dense_of(s))), aw));
        acc("matrix acceleration, wrench", rel(ct::to_ctga(Xw.acceleration(ct::matrix_of(g), ct::matrix_of(s))), aw));
        if constexpr (F == frame::fixed) {
            const rigid_body_motion<double, F, ctga_constant_wrench, fixed_frame_evaluation::about_body> Cb{
                make_rigid_body(b), {W}};
            const screw<double> ab = Cb.acceleration(g, s);
            acc("dense acceleration, wrench, vs ctga about_body",
                rel(ct::screw_of_dense(Dw.acceleration(ct::dense_of(g), ct::dense_of(s))), ab));
            acc("matrix acceleration, wrench, vs ctga about_body",
                rel(ct::to_ctga(Xw.acceleration(ct::matrix_of(g), ct::matrix_of(s))), ab));
        }
        w.record("kappa" + tag, kappa, -1.0);
        const motor<double> r = C.motor_rate(g, s);
        w.record("dense motor_rate" + tag, rel(ct::motor_of_dense(D.motor_rate(ct::dense_of(g), ct::dense_of(s))), r),
                 tight);
        w.record("matrix motor_rate" + tag, rel(ct::to_ctga(X.motor_rate(ct::matrix_of(g), ct::matrix_of(s))), r),
                 tight);
    }
}

TEST_CASE("dense and matrix models: primitives agree with ctga's", "[integrators][representations]") {
    worst_errors w;
    compare_primitives<frame::body>(w, 11, 200);
    compare_primitives<frame::fixed>(w, 12, 200);

    random_inputs<double> in(13);
    const rigid_body_motion<double, frame::body> C{make_rigid_body(in.body())};
    const ct::dense_motion<double, frame::body> D(C.body.properties);
    const ct::matrix_motion<double, frame::body> X(C.body.properties);
    const double scales[] = {0.0, 1e-12, 1e-6, 1e-3, 0.1, 0.5, 1.0, 2.0, 3.0, 6.0, 10.0};
    for (int k = 0; k < 200; ++k) {
        const screw<double> s = in.twist(), s2 = in.twist();
        const double c = scales[static_cast<std::size_t>(k) % std::size(scales)];
        // exp: angles from 0 to about 17 rad, and pure translations (ω = 0)
        screw<double> z{c * s[0], c * s[1], c * s[2], s[3], s[4], s[5]};
        if (k % 13 == 0) z = screw<double>{0.0, 0.0, 0.0, s[3], s[4], s[5]};
        const motor<double> e = ctga::exp(z);
        w.record("dense exp", rel(ct::motor_of_dense(D.exp(ct::dense_of(z))), e), tight);
        w.record("matrix exp", rel(ct::to_ctga(X.exp(ct::matrix_of(z))), e), tight);

        const motor<double> g = in.pose(), h = in.pose();
        const motor<double> gh = g * h;
        w.record("dense compose", rel(ct::motor_of_dense(D.compose(ct::dense_of(g), ct::dense_of(h))), gh), tight);
        w.record("matrix compose", rel(ct::to_ctga(X.compose(ct::matrix_of(g), ct::matrix_of(h))), gh), tight);

        const screw<double> br = ctga::bracket(s, s2);
        w.record("dense bracket", rel(ct::screw_of_dense(D.bracket(ct::dense_of(s), ct::dense_of(s2))), br), tight);
        w.record("matrix bracket", rel(ct::to_ctga(X.bracket(ct::matrix_of(s), ct::matrix_of(s2))), br), tight);

        // a drifted motor: g scaled and pushed off both relations of §3
        const double drift = k % 2 == 0 ? 1e-3 : 0.3;
        motor<double> d = (1.0 + drift * in.uniform()) * g;
        for (std::size_t i = 0; i < 8; ++i) d[i] += drift * in.uniform();
        const motor<double> n = ctga::renormalize(d);
        w.record("dense renormalize", rel(ct::motor_of_dense(D.renormalize(ct::dense_of(d))), n), tight);
        w.record("matrix renormalize", rel(ct::to_ctga(X.renormalize(ct::matrix_of(d))), n), tight);
    }
    // the error paths: non-finite and α = 0 give NaNs in every representation
    const motor<double> bad{0, 0, 0, 0, 1, 2, 3, 4};
    CHECK(!D.finite(D.renormalize(ct::dense_of(bad)), ct::dense_of(screw<double>{})));
    CHECK(!X.finite(X.renormalize(ct::matrix_of(bad)), ct::vector6<double>::Zero()));
    CHECK(D.magnitude(ct::dense_of(screw<double>{0.5, -3, 1, 2, 0, -1})) == 3.0);
    CHECK(X.magnitude(ct::matrix_of(screw<double>{0.5, -3, 1, 2, 0, -1})) == 3.0);
    w.check_and_print("primitives against ctga (double)");
}

TEST_CASE("dense and matrix models in long double", "[integrators][representations]") {
    using ld = long double;
    worst_errors w;
    random_inputs<ld> in(17);
    constexpr double bound = 1e-17;        // 64-bit significand: ε ≈ 1.1e-19
    constexpr double kappa_ld = 1e-18;     // accelerations: rel/κ (see compare_primitives)
    for (int k = 0; k < 10; ++k) {
        const mass_properties<ld> b = in.body();
        const motor<ld> g = in.pose(), h = in.pose();
        const screw<ld> s = in.twist(), s2 = in.twist();
        const rigid_body_motion<ld, frame::fixed> Cf{make_rigid_body(b)};
        const rigid_body_motion<ld, frame::body> Cb{make_rigid_body(b)};
        const ct::dense_motion<ld, frame::fixed> Df(b);
        const ct::dense_motion<ld, frame::body> Db(b);
        const ct::matrix_motion<ld, frame::fixed> Xf(b);
        const ct::matrix_motion<ld, frame::body> Xb(b);
        const double kf = condition(Xf, g), kb = condition(Xb, g);
        w.record("dense acceleration (fixed) / kappa",
                 rel(ct::screw_of_dense(Df.acceleration(ct::dense_of(g), ct::dense_of(s))), Cf.acceleration(g, s)) / kf,
                 kappa_ld);
        w.record("dense acceleration (body) / kappa",
                 rel(ct::screw_of_dense(Db.acceleration(ct::dense_of(g), ct::dense_of(s))), Cb.acceleration(g, s)) / kb,
                 kappa_ld);
        w.record("matrix acceleration (fixed) / kappa",
                 rel(ct::to_ctga(Xf.acceleration(ct::matrix_of(g), ct::matrix_of(s))), Cf.acceleration(g, s)) / kf,
                 kappa_ld);
        w.record("matrix acceleration (body) / kappa",
                 rel(ct::to_ctga(Xb.acceleration(ct::matrix_of(g), ct::matrix_of(s))), Cb.acceleration(g, s)) / kb,
                 kappa_ld);
        const screw<ld> z = ld(2) * s;
        w.record("dense exp", rel(ct::motor_of_dense(Db.exp(ct::dense_of(z))), ctga::exp(z)), bound);
        w.record("matrix exp", rel(ct::to_ctga(Xb.exp(ct::matrix_of(z))), ctga::exp(z)), bound);
        w.record("dense compose", rel(ct::motor_of_dense(Db.compose(ct::dense_of(g), ct::dense_of(h))), motor<ld>(g * h)),
                 bound);
        w.record("matrix compose", rel(ct::to_ctga(Xb.compose(ct::matrix_of(g), ct::matrix_of(h))), motor<ld>(g * h)),
                 bound);
        w.record("dense bracket", rel(ct::screw_of_dense(Db.bracket(ct::dense_of(s), ct::dense_of(s2))), bracket(s, s2)),
                 bound);
        w.record("matrix bracket", rel(ct::to_ctga(Xb.bracket(ct::matrix_of(s), ct::matrix_of(s2))), bracket(s, s2)),
                 bound);
    }
    w.check_and_print("primitives against ctga (long double)");
}

// ---- trajectories ------------------------------------------------------------------------------

constexpr double trajectory_bound = 1e-12;
constexpr double h = 0.01;
constexpr long long dense_steps = 200;
constexpr long long matrix_steps = 2000;

mass_properties<double> asymmetric_body() {
    return *make_mass_properties(2.0, vec3<double>{0.1, -0.2, 0.3},
                                 mat3<double>{{{0.9, 0.05, -0.02}, {0.05, 0.7, 0.03}, {-0.02, 0.03, 0.5}}});
}
motor<double> initial_pose() { return rigid_motion(make_translator(0.3, -0.5, 0.2), make_rotor(0.8, 0.48, 0.6, 0.64)); }
screw<double> initial_velocity() { return screw<double>{0.7, -0.4, 1.1, 0.2, 0.3, -0.1}; }

struct trajectory_errors {
    double dense_g, dense_s, matrix_g, matrix_s, matrix200_g, matrix200_s;
    long long long_steps;
    bool all_ran;
};

// One method on the three models from the same state; errors of dense (dense_steps) and matrix
// (long_steps and dense_steps) against ctga after as many steps.
template <class Method, class CtgaModel, class DenseModel, class MatrixModel>
trajectory_errors run_three(const Method& method, const CtgaModel& C, const DenseModel& D, const MatrixModel& X,
                            long long long_steps = matrix_steps) {
    const motor<double> g0 = initial_pose();
    const screw<double> s0 = initial_velocity();
    const auto c_short = integrate(method, C, {g0, s0}, h, dense_steps);
    const auto c_long = integrate(method, C, {g0, s0}, h, long_steps);
    const auto d_short = integrate(method, D, {ct::dense_of(g0), ct::dense_of(s0)}, h, dense_steps);
    const auto x_short = integrate(method, X, {ct::matrix_of(g0), ct::matrix_of(s0)}, h, dense_steps);
    const auto x_long = integrate(method, X, {ct::matrix_of(g0), ct::matrix_of(s0)}, h, long_steps);
    return {rel(ct::motor_of_dense(d_short.state.g), c_short.state.g),
            rel(ct::screw_of_dense(d_short.state.s), c_short.state.s),
            rel(ct::to_ctga(x_long.state.g), c_long.state.g),
            rel(ct::to_ctga(x_long.state.s), c_long.state.s),
            rel(ct::to_ctga(x_short.state.g), c_short.state.g),
            rel(ct::to_ctga(x_short.state.s), c_short.state.s),
            long_steps,
            c_short && c_long && d_short && x_short && x_long};
}

void record(worst_errors& w, const std::string& name, const trajectory_errors& e) {
    INFO(name);
    CHECK(e.all_ran);
    w.record(name + ": dense(200) motor", e.dense_g, trajectory_bound);
    w.record(name + ": dense(200) screw", e.dense_s, trajectory_bound);
    w.record(name + ": matrix(200) motor", e.matrix200_g, trajectory_bound);
    w.record(name + ": matrix(200) screw", e.matrix200_s, trajectory_bound);
    if (e.long_steps != dense_steps) {
        w.record(name + ": matrix(" + std::to_string(e.long_steps) + ") motor", e.matrix_g, trajectory_bound);
        w.record(name + ": matrix(" + std::to_string(e.long_steps) + ") screw", e.matrix_s, trajectory_bound);
    }
}

template <frame F, class Method>
void same_trajectory(worst_errors& w, const std::string& name, const Method& method) {
    const mass_properties<double> b = asymmetric_body();
    const rigid_body_motion<double, F> C{make_rigid_body(b)};
    record(w, name + (F == frame::fixed ? " fixed" : " body"),
           run_three(method, C, ct::dense_motion<double, F>(b), ct::matrix_motion<double, F>(b)));
}

// A constant wrench (a torque and a force, in the model's frame), 200 steps for every model.
// Not 2000 in the fixed frame: the wrench carries the body 20–40 from the origin in 20 s, where
// evaluating the dynamics in space amplifies rounding by κ ~ |t|⁴ in every representation: there
// ctga's own in_space and about_body runs differ by 8e-8 (a constant force) or 3e-12 (a couple).
template <frame F, class Method>
void same_trajectory_with_wrench(worst_errors& w, const std::string& name, const Method& method) {
    const mass_properties<double> b = asymmetric_body();
    const coscrew<double> W{0.05, -0.1, 0.02, 0.3, -0.2, -0.4};
    const rigid_body_motion<double, F, ctga_constant_wrench> C{make_rigid_body(b), {W}};
    const ct::dense_motion<double, F, dense_constant_wrench> D(b, {ct::coscrew_to_dense(W)});
    const ct::matrix_motion<double, F, matrix_constant_wrench> X(b, {ct::matrix_of(W)});
    record(w, name + (F == frame::fixed ? " fixed" : " body") + " +wrench",
           run_three(method, C, D, X, F == frame::fixed ? dense_steps : matrix_steps));
}

TEST_CASE("the same integrator gives the same trajectory to 1e-12 relative in the ctga, dense and matrix "
          "representations",
          "[integrators][representations]") {
    worst_errors w;
    // every method in both frames; in the fixed frame explicit Euler's states and RK4's stages
    // are off g g* = 1, where every representation evaluates the rigid motion g encodes
    same_trajectory<frame::body>(w, "explicit_euler", explicit_euler{});
    same_trajectory<frame::body>(w, "rk4", rk4{});
    same_trajectory<frame::body>(w, "lie_rk4", lie_rk4{});
    same_trajectory<frame::body>(w, "implicit_midpoint", implicit_midpoint{});
    same_trajectory<frame::fixed>(w, "explicit_euler", explicit_euler{});
    same_trajectory<frame::fixed>(w, "rk4", rk4{});
    same_trajectory<frame::fixed>(w, "lie_rk4", lie_rk4{});
    same_trajectory<frame::fixed>(w, "implicit_midpoint", implicit_midpoint{});
    // with an applied wrench
    same_trajectory_with_wrench<frame::body>(w, "rk4", rk4{});
    same_trajectory_with_wrench<frame::body>(w, "lie_rk4", lie_rk4{});
    same_trajectory_with_wrench<frame::fixed>(w, "lie_rk4", lie_rk4{});
    same_trajectory_with_wrench<frame::fixed>(w, "implicit_midpoint", implicit_midpoint{});
    w.check_and_print("trajectories against ctga, h = 0.01");

}

}  // namespace
