// Constrained dynamics of kinematic trees (include/ctga/constrained/) against references that do
// not share its route:
//
//   - the KKT system [H −Jᵀ; J 0] [q̈; λ] = [τ − C; −J̇ q̇] assembled densely from crba, rnea, the
//     frame Jacobians and their time variation (frame_jacobian, frame_jacobian_time_variation,
//     checked against the Featherstone reference in frames_test) and solved by Eigen, on a
//     floating tree with a welded foot, a held foot and a loop closure (1e-12);
//   - frictional contacts: the same tree's W and q handed to the independent fc3d reference
//     (tests/support/fc3d_reference.hpp): the forces agree to the tolerance, and the KKT
//     system's q̈ with those forces is the q̈ returned;
//   - a four-bar linkage closed by a point constraint (its rows along the plane's normal are zero:
//     a redundant constraint) driven through a full turn of its crank: Freudenstein's equation
//     holds to 1e-10 along the motion (RK4, h = 1 ms, Baumgarte ω = 20/s);
//   - a pendulum closed as a loop (a body on two slides and a hinge, its pivot held) against the
//     same pendulum built as a tree: q̈ to 1e-12 at the same state, the motion to 1e-9 over 1 s;
//   - refused inputs.
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include <ctga/chains/algorithms.hpp>
#include <ctga/constrained/constrained_dynamics.hpp>
#include <ctga/constrained/constrained_inverse_dynamics.hpp>

#include "support/catch.hpp"
#include "support/fc3d_reference.hpp"
#include "support/worst.hpp"

namespace {

namespace ch = ctga::chains;
namespace cn = ctga::constrained;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using ctga::test::worst;

// A floating base with two legs and an arm: frames "foot_l" (left shank), "foot_r" (right
// shank), "hand" (the arm's last body) and "grip" (on the base, placed at the hand by the test).
using walker = ch::tree<ch::link<-1, ch::floating>,                     // 0 base
                        ch::link<0, ch::revolute_x>,                    // 1 left hip
                        ch::link<1, ch::revolute_y>,                    // 2 left knee
                        ch::link<0, ch::revolute_y>,                    // 3 right hip
                        ch::link<3, ch::revolute<ch::axis::minus_x>>,   // 4 right knee
                        ch::link<0, ch::revolute_z>,                    // 5 shoulder
                        ch::link<5, ch::prismatic_x>,                   // 6 arm slide
                        ch::link<6, ch::revolute_y>,                    // 7 wrist
                        ch::fixed_frame<"foot_l", 2>, ch::fixed_frame<"foot_r", 4>, ch::fixed_frame<"hand", 7>,
                        ch::fixed_frame<"grip", 0>>;

double uniform(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53; }

ctga::checked<ctga::mass_properties<double>> random_body(std::mt19937_64& rng) {
    const double m = uniform(rng, 0.5, 2.0);
    const ctga::vec3<double> c{uniform(rng, -0.1, 0.1), uniform(rng, -0.1, 0.1), uniform(rng, -0.2, 0.0)};
    const double a = uniform(rng, 0.01, 0.05), b = uniform(rng, 0.01, 0.05), d = uniform(rng, 0.01, 0.05), e = uniform(rng, -0.003, 0.003);
    return ctga::make_mass_properties(m, c, ctga::mat3<double>{{{a + b, e, 0}, {e, b + d, 0}, {0, 0, a + d}}});
}
ctga::motor<double> random_placement(std::mt19937_64& rng, double scale) {
    const double x = uniform(rng, -1, 1), y = uniform(rng, -1, 1), z = uniform(rng, -1, 1), n = std::sqrt(x * x + y * y + z * z);
    return ctga::rigid_motion(ctga::make_translator(uniform(rng, -scale, scale), uniform(rng, -scale, scale), uniform(rng, -scale, scale)),
                              ctga::make_rotor(uniform(rng, -1, 1), x / n, y / n, z / n));
}

ch::model<walker> walker_model(std::mt19937_64& rng) {
    ch::model<walker> m;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((m.template link<I>() = *ch::make_link<typename walker::template joint_at<I>>(random_placement(rng, 0.3), random_body(rng))), ...);
    }(std::make_index_sequence<walker::size>{});
    for (std::size_t k = 0; k + 1 < walker::frame_count; ++k) m.frames[k] = *ch::make_frame(random_placement(rng, 0.2));
    return m;
}
void random_state(std::mt19937_64& rng, ch::configuration<walker>& q, ch::joint_vector<walker>& qd, ch::joint_vector<walker>& tau) {
    const ctga::motor<double> g = random_placement(rng, 0.5);
    for (std::size_t k = 0; k < 8; ++k) q[k] = g[k];
    for (std::size_t k = 8; k < walker::nq; ++k) q[k] = uniform(rng, -1, 1);
    for (auto& x : qd) x = uniform(rng, -1, 1);
    for (auto& x : tau) x = uniform(rng, -3, 3);
}

MatrixXd dense(const ch::joint_matrix<walker>& H) {
    MatrixXd out(walker::nv, walker::nv);
    for (std::size_t r = 0; r < walker::nv; ++r)
        for (std::size_t c = 0; c < walker::nv; ++c) out(Eigen::Index(r), Eigen::Index(c)) = H[r][c];
    return out;
}

// The reference's rows of "frame A held on frame B" (B's axes), from the frame Jacobians in
// local_world_aligned (ω, the origin's velocity) and J̇ q̇ there (ω̇, the origin's classical
// acceleration): linear rows 3..5, angular 0..2 of the screws.
struct reference_rows {
    MatrixXd J;
    VectorXd bias;
};
template <class FA, class FB>
void add_rows(reference_rows& out, const ch::model<walker>& m, const ch::kinematics<walker>& k, const ch::joint_vector<walker>& qd,
              FA fa, FB fb, bool angular) {
    const auto JA = ch::frame_jacobian(m, k, fa, ch::reference::local_world_aligned);
    const auto dA = ch::frame_jacobian_time_variation(m, k, fa, ch::reference::local_world_aligned);
    ch::jacobian_matrix<walker> JB{}, dB{};
    ctga::motor_map<double> WB;
    if constexpr (std::is_same_v<FB, std::nullptr_t>) {
        WB = ch::frame_pose(m, k, fa);  // held in the world where it is
    } else {
        JB = ch::frame_jacobian(m, k, fb, ch::reference::local_world_aligned);
        dB = ch::frame_jacobian_time_variation(m, k, fb, ch::reference::local_world_aligned);
        WB = ch::frame_pose(m, k, fb);
    }
    const Eigen::Index r0 = out.J.rows();
    out.J.conservativeResize(r0 + 3, walker::nv);
    out.bias.conservativeResize(r0 + 3);
    const std::size_t part = angular ? 0 : 3;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        double bias = 0;
        for (std::size_t c = 0; c < walker::nv; ++c) {
            double x = 0, xd = 0;
            for (std::size_t i = 0; i < 3; ++i) {
                x += WB.R[i][axis] * (JA[c][part + i] - JB[c][part + i]);
                xd += WB.R[i][axis] * (dA[c][part + i] - dB[c][part + i]);
            }
            out.J(r0 + Eigen::Index(axis), Eigen::Index(c)) = x;
            bias += xd * qd[c];
        }
        out.bias[r0 + Eigen::Index(axis)] = bias;
    }
}

// the walker's set: foot_l welded, foot_r's origin held, the hand held on the grip (placed at it)
struct walker_case {
    ch::model<walker> m;
    ch::configuration<walker> q{};
    ch::joint_vector<walker> qd{}, tau{};
    cn::constraint_set<walker, double, 6> C;
    reference_rows ref;
};
walker_case make_walker_case(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    walker_case w;
    w.m = walker_model(rng);
    random_state(rng, w.q, w.qd, w.tau);
    auto k = ch::forward_kinematics(w.m, w.q, w.qd, ch::joint_vector<walker>{});
    // the grip's placement: the hand's pose seen from the base
    w.m.frames[3] = ctga::compose(ctga::inverse(k.pose[0]), ch::frame_pose(w.m, k, ch::frame<"hand">));
    REQUIRE(w.C.fix(w.m, w.q, ch::frame<"foot_l">, cn::hold::weld) == ctga::error_code::none);
    REQUIRE(w.C.fix(w.m, w.q, ch::frame<"foot_r">) == ctga::error_code::none);
    REQUIRE(w.C.close_loop(w.m, ch::frame<"hand">, ch::frame<"grip">) == ctga::error_code::none);
    k = ch::forward_kinematics(w.m, w.q, w.qd, ch::joint_vector<walker>{});
    w.ref.J.resize(0, walker::nv);
    add_rows(w.ref, w.m, k, w.qd, ch::frame<"foot_l">, nullptr, false);
    add_rows(w.ref, w.m, k, w.qd, ch::frame<"foot_l">, nullptr, true);
    add_rows(w.ref, w.m, k, w.qd, ch::frame<"foot_r">, nullptr, false);
    add_rows(w.ref, w.m, k, w.qd, ch::frame<"hand">, ch::frame<"grip">, false);
    return w;
}

double rel(const VectorXd& x, const VectorXd& y) { return (x - y).lpNorm<Eigen::Infinity>() / std::max(1.0, y.lpNorm<Eigen::Infinity>()); }
template <class A>
VectorXd vec(const A& a, std::size_t n) {
    VectorXd out = VectorXd::Zero(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) out[Eigen::Index(i)] = a[i];
    return out;
}

TEST_CASE("constrained forward dynamics against the dense KKT system, and the Delassus operator", "[constrained]") {
    worst w("constrained forward dynamics vs KKT (Eigen)");
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        walker_case c = make_walker_case(seed);
        const auto H = dense(ch::crba(c.m, c.q));
        const VectorXd b = vec(c.tau, walker::nv) - vec(ch::rnea(c.m, c.q, c.qd, ch::joint_vector<walker>{}), walker::nv);
        const Eigen::Index n = walker::nv, r = c.ref.J.rows();
        REQUIRE(r == 12);
        MatrixXd K = MatrixXd::Zero(n + r, n + r);
        K.topLeftCorner(n, n) = H;
        K.topRightCorner(n, r) = -c.ref.J.transpose();
        K.bottomLeftCorner(r, n) = c.ref.J;
        VectorXd rhs(n + r);
        rhs << b, -c.ref.bias;
        // (solved in long double)
        using MatrixXl = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
        const MatrixXl Kl = K.cast<long double>();
        const VectorXd x = Kl.fullPivLu().solve(rhs.cast<long double>()).cast<double>();
        const auto out = cn::constrained_forward_dynamics(c.m, c.q, c.qd, c.tau, c.C);
        REQUIRE(out.error == ctga::error_code::none);
        CHECK(out.rank == 12);
        CHECK(out.report.converged);
        // the error grows with W's condition number, on both sides (≈ 1e-17 cond(W) measured):
        // 1e-12 up to cond(W) = 1e4 (18 of these 20 states), 1e-16 cond(W) beyond
        Eigen::JacobiSVD<MatrixXd> svd(c.ref.J * H.ldlt().solve(c.ref.J.transpose()));
        const double cond = svd.singularValues()(0) / svd.singularValues()(11);
        const double tol = 1e-12 * std::max(1.0, cond / 1e4);
        CHECK(w("q̈ (bound 1e-12 max(1, cond(W) / 1e4))", rel(vec(out.qdd, walker::nv), x.head(n))) < tol);
        CHECK(w("λ (bound 1e-12 max(1, cond(W) / 1e4))", rel(vec(out.force, 12), x.tail(r))) < tol);
        w("cond(W) (not an error)", cond);
        // W = J H⁻¹ Jᵀ
        const MatrixXd Wref = c.ref.J * H.ldlt().solve(c.ref.J.transpose());
        const auto W = cn::delassus(c.m, c.q, c.C);
        REQUIRE(W.rows == 12);
        MatrixXd Wc(12, 12);
        for (std::size_t i = 0; i < 12; ++i)
            for (std::size_t j = 0; j < 12; ++j) Wc(Eigen::Index(i), Eigen::Index(j)) = W.W[i][j];
        CHECK(w("W", (Wc - Wref).lpNorm<Eigen::Infinity>() / std::max(1.0, Wref.lpNorm<Eigen::Infinity>())) < 1e-12);
        // the operator the sweeps use without W (u_i = q_i + (Y s)_i, s = D⁻¹ Yᵀ r kept by
        // apply): its blocks and velocities against W_ref r + q, before and after changes of r
        {
            namespace ad = ch::algorithm_detail;
            const auto f = ad::factor_tree<walker>(ch::crba(c.m, c.q));
            cn::tree_motion<walker, double> g(ctga::uninitialized);
            fill_tree_motion(g, c.m, c.q, c.qd);
            cn::constraint_rows<walker, double, 6> R;
            cn::fill_rows(R, g, c.C, c.q, c.qd);
            cn::delassus_parts<walker, double, 6> P;
            cn::fill_sweep(P, f, R);
            std::mt19937_64 rng(seed + 100);
            std::uniform_real_distribution<double> u(-1.0, 1.0);
            std::array<double, 12> qv{}, r{};
            for (std::size_t i = 0; i < 12; ++i) qv[i] = u(rng), r[i] = u(rng);
            cn::dynamics_detail::tree_delassus<walker, double, 6> D(P, f, R, std::span<const double>(qv.data(), 12), c.C.blocks(), 0.0, 1.0,
                                                                    std::span<const double>(r.data(), 12));
            const auto against = [&](const char* what) {
                const VectorXd ref = Wref * vec(r, 12) + vec(qv, 12);
                double worst_u = 0, worst_block = 0;
                for (std::size_t i = 0; i < 4; ++i) {
                    const ctga::vec3<double> ui = D.velocity(i, std::span<const double>(r.data(), 12));
                    const ctga::mat3<double> A = D.block(i);
                    for (std::size_t a = 0; a < 3; ++a) {
                        worst_u = std::max(worst_u, std::abs(ui[a] - ref[Eigen::Index(3 * i + a)]));
                        for (std::size_t b = 0; b < 3; ++b)
                            worst_block = std::max(worst_block, std::abs(A[a][b] - Wref(Eigen::Index(3 * i + a), Eigen::Index(3 * i + b))));
                    }
                }
                const double scale = std::max(1.0, ref.lpNorm<Eigen::Infinity>());
                CHECK(w(what, worst_u / scale) < 1e-12);
                CHECK(w("W's diagonal blocks without W", worst_block / std::max(1.0, Wref.lpNorm<Eigen::Infinity>())) < 1e-12);
            };
            against("W r + q without W, at the warm start");
            for (std::size_t i : {2u, 0u, 3u}) {
                const ctga::vec3<double> dr{u(rng), u(rng), u(rng)};
                for (std::size_t a = 0; a < 3; ++a) r[3 * i + a] += dr[a];
                D.apply(i, dr);
            }
            against("W r + q without W, after three blocks' changes");
        }
    }
}

TEST_CASE("frictional contacts on a tree against the independent fc3d reference", "[constrained]") {
    namespace fc = fc3d_reference;
    worst w("contacts on a tree vs fc3d reference");
    for (std::uint64_t seed = 30; seed < 40; ++seed) {
        std::mt19937_64 rng(seed);
        walker_case c;
        c.m = walker_model(rng);
        random_state(rng, c.q, c.qd, c.tau);
        const double mu[3] = {0.3, 0.8, 0.05};
        // three feet on tilted grounds: foot_l, foot_r, the hand
        const auto k = ch::forward_kinematics(c.m, c.q);
        const auto normal = [&] {
            const double x = uniform(rng, -0.3, 0.3), y = uniform(rng, -0.3, 0.3), n = std::sqrt(x * x + y * y + 1);
            return ctga::vec3<double>{x / n, y / n, 1 / n};
        };
        REQUIRE(c.C.touch(c.m, c.q, ch::frame<"foot_l">, normal(), mu[0]) == ctga::error_code::none);
        REQUIRE(c.C.touch(c.m, c.q, ch::frame<"foot_r">, normal(), mu[1]) == ctga::error_code::none);
        REQUIRE(c.C.touch(c.m, c.q, ch::frame<"hand">, normal(), mu[2]) == ctga::error_code::none);
        (void)k;
        cn::constrained_settings<double> s;
        s.solver.tolerance = 1e-12;
        s.solver.max_sweeps = 100000;
        const auto out = cn::constrained_forward_dynamics(c.m, c.q, c.qd, c.tau, c.C, s);
        REQUIRE(out.error == ctga::error_code::none);
        CHECK(out.report.converged);
        // the same problem for the reference: W from delassus (checked above against Eigen), q
        // from the KKT pieces: q = J H⁻¹ (τ − C) + J̇ q̇
        reference_rows ref;
        ref.J.resize(0, walker::nv);
        const auto kk = ch::forward_kinematics(c.m, c.q, c.qd, ch::joint_vector<walker>{});
        const cn::constraint_set<walker, double, 6>& C = c.C;
        // contact rows are (n, t1, t2): the world frame's z, x, y
        const auto contact_rows = [&](auto f, std::size_t i) {
            reference_rows one;
            one.J.resize(0, walker::nv);
            const auto JA = ch::frame_jacobian(c.m, kk, f, ch::reference::local_world_aligned);
            const auto dA = ch::frame_jacobian_time_variation(c.m, kk, f, ch::reference::local_world_aligned);
            const auto& R = C.blocks()[i].at_b.R;
            one.J.resize(3, walker::nv);
            one.bias.resize(3);
            for (std::size_t j = 0; j < 3; ++j) {
                const std::size_t axis = (j + 2) % 3;
                double bias = 0;
                for (std::size_t col = 0; col < walker::nv; ++col) {
                    double x = 0, xd = 0;
                    for (std::size_t a = 0; a < 3; ++a) x += R[a][axis] * JA[col][3 + a], xd += R[a][axis] * dA[col][3 + a];
                    one.J(Eigen::Index(j), Eigen::Index(col)) = x;
                    bias += xd * c.qd[col];
                }
                one.bias[Eigen::Index(j)] = bias;
            }
            ref.J.conservativeResize(ref.J.rows() + 3, walker::nv);
            ref.bias.conservativeResize(ref.J.rows());
            ref.J.bottomRows(3) = one.J;
            ref.bias.tail(3) = one.bias;
        };
        contact_rows(ch::frame<"foot_l">, 0);
        contact_rows(ch::frame<"foot_r">, 1);
        contact_rows(ch::frame<"hand">, 2);
        const MatrixXd H = dense(ch::crba(c.m, c.q));
        const VectorXd b = vec(c.tau, walker::nv) - vec(ch::rnea(c.m, c.q, c.qd, ch::joint_vector<walker>{}), walker::nv);
        const MatrixXd W = ref.J * H.ldlt().solve(ref.J.transpose());
        const VectorXd q = ref.J * H.ldlt().solve(b) + ref.bias;
        std::vector<fc::real> Wv(81), qv(9), muv(mu, mu + 3);
        for (int i = 0; i < 9; ++i) {
            qv[std::size_t(i)] = q[i];
            for (int j = 0; j < 9; ++j) Wv[std::size_t(9 * i + j)] = W(i, j);
        }
        const auto sol = fc::solve(Wv, qv, muv);
        REQUIRE(sol.converged);
        VectorXd r_ref(9);
        for (int i = 0; i < 9; ++i) r_ref[i] = double(sol.r[std::size_t(i)]);
        // the solution is unique here (W positive definite): forces to the tolerance's order
        CHECK(w("λ", rel(vec(out.force, 9), r_ref)) < 1e-9);
        // q̈ = H⁻¹ (τ − C + Jᵀ λ) with the returned λ
        const VectorXd qdd = H.ldlt().solve(b + ref.J.transpose() * vec(out.force, 9));
        CHECK(w("q̈ given λ", rel(vec(out.qdd, walker::nv), qdd)) < 1e-12);
    }
}

// One classical RK4 step of q̈ = acc(q, q̇) on arrays (every joint here is a scalar).
template <class Acc, class Q, class V>
void rk4_step(Acc&& acc, Q& q, V& v, double h) {
    const auto add = [](auto y, const auto& dy, double t) {
        for (std::size_t i = 0; i < y.size(); ++i) y[i] += t * dy[i];
        return y;
    };
    const auto a1 = acc(q, v);
    const auto q2 = add(q, v, h / 2), v2 = add(v, a1, h / 2);
    const auto a2 = acc(q2, v2);
    const auto q3 = add(q, v2, h / 2), v3 = add(v, a2, h / 2);
    const auto a3 = acc(q3, v3);
    const auto q4 = add(q, v3, h), v4 = add(v, a3, h);
    const auto a4 = acc(q4, v4);
    for (std::size_t i = 0; i < q.size(); ++i) {
        q[i] += h / 6 * (v[i] + 2 * v2[i] + 2 * v3[i] + v4[i]);
        v[i] += h / 6 * (a1[i] + 2 * a2[i] + 2 * a3[i] + a4[i]);
    }
}

// ---- a four-bar linkage ------------------------------------------------------------------------
// crank a about the origin, coupler b on its end, rocker c about (d, 0, 0); the coupler's end
// held on the rocker's by a point constraint. Planar in x, y, gravity along −y.
using four_bar = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_z>, ch::link<-1, ch::revolute_z>,
                          ch::fixed_frame<"coupler_end", 1>, ch::fixed_frame<"rocker_end", 2>>;
constexpr double bar_a = 1.0, bar_b = 3.0, bar_c = 2.5, bar_d = 3.0;

ch::model<four_bar> four_bar_model() {
    ch::model<four_bar> m;
    m.gravity = {0, -9.81, 0};
    const auto rod = [](double length, double mass) {
        return ctga::make_mass_properties(mass, ctga::vec3<double>{length / 2, 0, 0},
                                           ctga::mat3<double>{{{1e-3, 0, 0}, {0, mass * length * length / 12, 0}, {0, 0, mass * length * length / 12}}});
    };
    m.link<0>() = *ch::make_link<ch::revolute_z>(ctga::motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), rod(bar_a, 1.0));
    m.link<1>() = *ch::make_link<ch::revolute_z>(ctga::motor<double>(ctga::make_translator(bar_a, 0.0, 0.0)), rod(bar_b, 2.0));
    m.link<2>() = *ch::make_link<ch::revolute_z>(ctga::motor<double>(ctga::make_translator(bar_d, 0.0, 0.0)), rod(bar_c, 1.5));
    m.frames[0] = *ch::make_frame(ctga::motor<double>(ctga::make_translator(bar_b, 0.0, 0.0)));
    m.frames[1] = *ch::make_frame(ctga::motor<double>(ctga::make_translator(bar_c, 0.0, 0.0)));
    return m;
}
// the joint angles that close the loop at crank angle θ (the open branch)
ch::configuration<four_bar> closed_at(double theta) {
    const double ax = bar_a * std::cos(theta), ay = bar_a * std::sin(theta);
    const double dx = bar_d - ax, dy = -ay, L = std::hypot(dx, dy);
    const double along = (bar_b * bar_b - bar_c * bar_c + L * L) / (2 * L), h = std::sqrt(bar_b * bar_b - along * along);
    const double bx = ax + (along * dx - h * dy) / L, by = ay + (along * dy + h * dx) / L;  // the coupler's end, left of A→D
    const double psi = std::atan2(by - ay, bx - ax), phi = std::atan2(by, bx - bar_d);
    return {theta, psi - theta, phi};
}
double freudenstein(double theta, double phi) {
    const double K1 = bar_d / bar_a, K2 = bar_d / bar_c, K3 = (bar_a * bar_a - bar_b * bar_b + bar_c * bar_c + bar_d * bar_d) / (2 * bar_a * bar_c);
    return K1 * std::cos(phi) - K2 * std::cos(theta) + K3 - std::cos(theta - phi);
}

TEST_CASE("constrained inverse dynamics: the least forces, and back through forward dynamics", "[constrained]") {
    worst w("constrained inverse dynamics");
    std::size_t on_cone = 0;
    for (std::uint64_t seed = 50; seed < 60; ++seed) {
        // bilateral: a welded foot, a held foot, a loop (12 rows, the base's 6 equations): λ the
        // least-norm solution of J_uᵀ λ = (H q̈ + C)_u, from Eigen on the reference rows
        walker_case c = make_walker_case(seed);
        for (std::size_t k = 0; k < 6; ++k) c.tau[k] = 0;  // an unactuated base
        const auto fwd = cn::constrained_forward_dynamics(c.m, c.q, c.qd, c.tau, c.C);
        REQUIRE(fwd.error == ctga::error_code::none);
        const auto inv = cn::constrained_inverse_dynamics(c.m, c.q, c.qd, fwd.qdd, c.C);
        REQUIRE(inv.error == ctga::error_code::none);
        CHECK(inv.report.residual < 1e-9);  // (the default tolerance 1e-10 N is at rounding's floor for these forces)
        const MatrixXd A = c.ref.J.leftCols(6).transpose();
        const VectorXd b = vec(ch::rnea(c.m, c.q, c.qd, fwd.qdd), walker::nv).head(6);
        const VectorXd least = A.transpose() * (A * A.transpose()).ldlt().solve(b);
        CHECK(w("bilateral λ vs Aᵀ (A Aᵀ)⁻¹ b", rel(vec(inv.force, 12), least)) < 1e-10);
        for (std::size_t k = 0; k < 6; ++k) CHECK(inv.tau[k] == 0.0);
        // H q̈ + C = τ + Jᵀ λ on every dof
        const VectorXd balance = dense(ch::crba(c.m, c.q)) * vec(fwd.qdd, walker::nv) +
                                 vec(ch::rnea(c.m, c.q, c.qd, ch::joint_vector<walker>{}), walker::nv) - vec(inv.tau, walker::nv) -
                                 c.ref.J.transpose() * vec(inv.force, 12);
        CHECK(w("H q̈ + C − τ − Jᵀ λ", balance.lpNorm<Eigen::Infinity>()) < 1e-10);
        // back: forward dynamics under τ gives q̈ (its λ: the one whose J q̈ + J̇ q̇ = 0, unique)
        const auto back = cn::constrained_forward_dynamics(c.m, c.q, c.qd, inv.tau, c.C);
        CHECK(w("forward(inverse(q̈)) − q̈", rel(vec(back.qdd, walker::nv), vec(fwd.qdd, walker::nv))) < 1e-9);

        // contacts: both feet and the hand on the ground (μ 0.1: cones reached), the base
        // unactuated; forward dynamics' λ_f is feasible for the inverse problem, whose λ is the
        // least: in the cones, A λ = b, and λ · (λ_f − λ) ≥ 0 (the optimality of ½‖λ‖² there)
        walker_case d = make_walker_case(seed);
        d.C.clear();
        for (std::size_t k = 0; k < 6; ++k) d.tau[k] = 0;
        const ctga::vec3<double> up{0, 0, 1};
        REQUIRE(d.C.touch(d.m, d.q, ch::frame<"foot_l">, up, 0.1) == ctga::error_code::none);
        REQUIRE(d.C.touch(d.m, d.q, ch::frame<"foot_r">, up, 0.1) == ctga::error_code::none);
        REQUIRE(d.C.touch(d.m, d.q, ch::frame<"hand">, up, 0.1) == ctga::error_code::none);
        cn::constrained_settings<double> s;
        s.solver.tolerance = 1e-12;
        s.solver.max_sweeps = 100000;
        const auto f = cn::constrained_forward_dynamics(d.m, d.q, d.qd, d.tau, d.C, s);
        REQUIRE(f.error == ctga::error_code::none);
        const auto g = cn::constrained_inverse_dynamics(d.m, d.q, d.qd, f.qdd, d.C, s);
        REQUIRE(g.error == ctga::error_code::none);
        CHECK(g.report.converged);
        double dot = 0, norm = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            const double n = g.force[3 * i], t = std::hypot(g.force[3 * i + 1], g.force[3 * i + 2]);
            CHECK(t <= 0.1 * n + 1e-12);
            on_cone += n > 1e-9 && t > 0.1 * n - 1e-9;
            for (std::size_t a = 0; a < 3; ++a) dot += g.force[3 * i + a] * (f.force[3 * i + a] - g.force[3 * i + a]), norm += g.force[3 * i + a] * g.force[3 * i + a];
        }
        w("contacts: λ · (λ_f − λ) / ‖λ‖² (≥ 0)", -dot / std::max(norm, 1.0));
        CHECK(dot >= -1e-10 * std::max(norm, 1.0));
        // A λ = b: forward dynamics' λ_f met the base's equations (τ_u = 0), so J_uᵀ (λ − λ_f) = 0,
        // J's rows (n, t1, t2) = the world's (z, x, y) from the frame Jacobians
        const auto kd = ch::forward_kinematics(d.m, d.q);
        const std::array<ch::jacobian_matrix<walker>, 3> JF{ch::frame_jacobian(d.m, kd, ch::frame<"foot_l">, ch::reference::local_world_aligned),
                                                            ch::frame_jacobian(d.m, kd, ch::frame<"foot_r">, ch::reference::local_world_aligned),
                                                            ch::frame_jacobian(d.m, kd, ch::frame<"hand">, ch::reference::local_world_aligned)};
        double unbalanced = 0;
        for (std::size_t k = 0; k < 6; ++k) {
            double sum = 0;
            for (std::size_t i = 0; i < 3; ++i)
                for (std::size_t a = 0; a < 3; ++a) sum += JF[i][k][3 + (a + 2) % 3] * (g.force[3 * i + a] - f.force[3 * i + a]);
            unbalanced = std::max(unbalanced, std::abs(sum));
        }
        CHECK(w("contacts: J_uᵀ (λ − λ_f)", unbalanced) < 1e-9);
    }
    std::printf("inverse dynamics: %zu contacts of 30 on their cone's boundary\n", on_cone);
    CHECK(on_cone >= 3);
}

TEST_CASE("a four-bar linkage closed by a constraint follows Freudenstein's equation", "[constrained]") {
    worst w("four-bar");
    const auto m = four_bar_model();
    cn::constraint_set<four_bar, double, 1> C;
    REQUIRE(C.close_loop(m, ch::frame<"coupler_end">, ch::frame<"rocker_end">) == ctga::error_code::none);
    cn::constrained_settings<double> s;
    s.stabilization = 20;
    ch::configuration<four_bar> q = closed_at(0.3);
    CHECK(w("Freudenstein at the start", std::abs(freudenstein(q[0], q[2]))) < 1e-14);
    ch::joint_vector<four_bar> v{};
    const auto acc = [&](const ch::configuration<four_bar>& x, const ch::joint_vector<four_bar>& xd) {
        const ch::joint_vector<four_bar> tau{20.0 - 1.0 * xd[0], 0, 0};  // the crank's motor, with its back-EMF
        const auto out = cn::constrained_forward_dynamics(m, x, xd, tau, C, s);
        REQUIRE(out.error == ctga::error_code::none);
        CHECK(out.rank == 2);  // the z row: redundant
        return out.qdd;
    };
    const double h = 2.5e-4;
    double worst_residual = 0;
    for (int step = 0; step < 8000; ++step) {
        rk4_step(acc, q, v, h);
        worst_residual = std::max(worst_residual, std::abs(freudenstein(q[0], q[2])));
    }
    std::printf("four-bar: crank %.6g rad, speed %.6g rad/s\n", q[0], v[0]);
    CHECK(w("Freudenstein along the motion", worst_residual) < 1e-10);
    CHECK(q[0] > 0.3 + 2 * std::numbers::pi);  // driven: the crank turned at least once
}

// ---- a pendulum: a tree, and a loop ----------------------------------------------------------
using hinge = ch::tree<ch::link<-1, ch::revolute_z>>;
using slides = ch::tree<ch::link<-1, ch::prismatic_x>, ch::link<0, ch::prismatic_y>, ch::link<1, ch::revolute_z>>;

TEST_CASE("a pendulum closed as a loop moves as the same pendulum built as a tree", "[constrained]") {
    worst w("pendulum loop vs tree");
    const auto bob = ctga::make_mass_properties(2.0, ctga::vec3<double>{0.4, 0.05, 0},
                                                 ctga::mat3<double>{{{0.01, 0, 0}, {0, 0.02, 0}, {0, 0, 0.03}}});
    const auto carriage = ctga::make_mass_properties(0.7, ctga::vec3<double>{0, 0, 0}, ctga::mat3<double>{{{0.01, 0, 0}, {0, 0.01, 0}, {0, 0, 0.01}}});
    const ctga::motor<double> origin(ctga::make_translator(0.0, 0.0, 0.0));
    ch::model<hinge> tree;
    tree.gravity = {0, -9.81, 0};
    tree.link<0>() = *ch::make_link<ch::revolute_z>(origin, bob);
    ch::model<slides> loop;
    loop.gravity = tree.gravity;
    loop.link<0>() = *ch::make_link<ch::prismatic_x>(origin, carriage);
    loop.link<1>() = *ch::make_link<ch::prismatic_y>(origin, carriage);
    loop.link<2>() = *ch::make_link<ch::revolute_z>(origin, bob);
    ch::configuration<slides> q{0, 0, 0.9};
    ch::joint_vector<slides> v{0, 0, -0.5};
    cn::constraint_set<slides, double, 1> C;
    REQUIRE(C.fix(loop, q, ch::body<2>) == ctga::error_code::none);
    cn::constrained_settings<double> s;
    s.stabilization = 20;
    {
        const auto out = cn::constrained_forward_dynamics(loop, q, v, ch::joint_vector<slides>{}, C, s);
        const auto a = ch::aba(tree, ch::configuration<hinge>{q[2]}, ch::joint_vector<hinge>{v[2]}, ch::joint_vector<hinge>{});
        CHECK(w("θ̈ at the start", std::abs(out.qdd[2] - a[0]) / std::max(1.0, std::abs(a[0]))) < 1e-12);
        CHECK(w("slides' q̈ at the start", std::max(std::abs(out.qdd[0]), std::abs(out.qdd[1]))) < 1e-12);
    }
    double th = q[2], om = v[2];
    const double h = 1e-3;
    for (int step = 0; step < 1000; ++step) {
        rk4_step([&](const auto& x, const auto& xd) { return cn::constrained_forward_dynamics(loop, x, xd, ch::joint_vector<slides>{}, C, s).qdd; },
                 q, v, h);
        std::array<double, 1> x{th}, xd{om};
        rk4_step([&](const auto& y, const auto& yd) { return ch::aba(tree, y, yd, ch::joint_vector<hinge>{}); }, x, xd, h);
        th = x[0], om = xd[0];
    }
    CHECK(w("θ after 1 s", std::abs(q[2] - th)) < 1e-9);
    CHECK(w("θ̇ after 1 s", std::abs(v[2] - om)) < 1e-9);
    CHECK(w("pivot drift after 1 s", std::hypot(q[0], q[1])) < 1e-9);
}

TEST_CASE("constraint sets refuse bad blocks", "[constrained]") {
    using E = ctga::error_code;
    cn::constraint_set<walker, double, 2> C;
    cn::constraint_block<double> b;
    b.a = 1;
    b.b = 1;
    CHECK(C.add(b) == E::joint_to_itself);
    b.b = 9;
    CHECK(C.add(b) == E::bad_index);
    b.b = -1;
    b.kind = cn::block_kind::contact;
    b.mu = -0.1;
    CHECK(C.add(b) == E::negative_friction);
    b.mu = std::nan("");
    CHECK(C.add(b) == E::non_finite);
    b.mu = 0.5;
    b.at_b.t[0] = std::numeric_limits<double>::infinity();
    CHECK(C.add(b) == E::non_finite);
    b.at_b.t[0] = 0;
    CHECK(C.add(b) == E::none);
    std::mt19937_64 rng(5);
    const auto m = walker_model(rng);
    ch::configuration<walker> q{};
    ch::joint_vector<walker> qd{}, tau{};
    random_state(rng, q, qd, tau);
    CHECK(C.fix(m, q, ch::frame<"foot_l">, cn::hold::weld) == E::capacity_exceeded);  // one place left, a weld needs two
    CHECK(C.size() == 1);
    CHECK(C.touch(m, q, ch::frame<"foot_r">, ctga::vec3<double>{0, 0, 0}, 0.5) == E::zero_direction);
    qd[3] = std::nan("");
    CHECK(cn::constrained_forward_dynamics(m, q, qd, tau, C).error == E::non_finite);
}

}  // namespace
