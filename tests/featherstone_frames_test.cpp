// Tests of the Featherstone reference's frames, centre of mass, centroidal momentum, mimic joints
// and fixed-link lumping (tests/support/featherstone_frames.hpp). Nothing here uses ctga.
//
// Models: random small trees (4–8 bodies; a floating base in every other model; every model has
// a fixed link with mass, a revolute and a prismatic joint, all on random non-coordinate axes),
// with frames on the world, on a fixed link and on random bodies.
//
// Independent values: finite differences of frame poses / positions along the true motion
// (q(t) integrated from q̇ = q_dot(q, v + a t) by one RK4 step, so that the path is exact to
// O(t⁵) and the second difference sees the true p̈), classical per-body sums, and hand-built
// couplings.
//
// Error measure: rel(x, y) = max_k |x_k − y_k| / max(1, max_k |y_k|) (y the independent value).
// Tolerances:
//   1e-12  for the same quantity computed by two exact routes (rounding: a few hundred flops
//          on numbers of size ≤ ~50, worst seen ~1e-14); tighter where the routes are short;
//   1e-7   for central first differences with h = 1e-5: truncation h²/6 |f'''| ~ 1e-10 · O(10),
//          rounding ~ eps |f| / h ~ 1e-11 · O(10); 1e-7 leaves three orders of margin;
//   1e-5   for the central second difference with h = 1e-4: truncation h²/12 |f''''| ~ 1e-9 ·
//          O(10), rounding ~ 4 eps |p| / h² ~ 1e-7 (|p| ≤ ~5);
//   1e-10  for a solve that inverts a product (aba_mimic ∘ rnea_mimic: the condition number of
//          the reduced mass matrix, as featherstone_reference_test's ABA ∘ RNEA).
// The worst value of each measure is printed at the end of each test case.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "support/catch.hpp"
#include "support/worst.hpp"
#include "support/featherstone_frames.hpp"
#include "support/random_tree.hpp"
#include "support/relative_error.hpp"

namespace fs = ctga::test::featherstone;
using fs::mat3;
using fs::mat6;
using fs::vec3;
using fs::vec6;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using ctga::test::rel;

namespace {


MatrixXd mul(const MatrixXd& A, const MatrixXd& B) { return A.lazyProduct(B); }

using ctga::test::worst;

vec3 vee(const mat3& W) { return 0.5 * vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1)); }

// q(t) for q(0) = q, velocity coordinates v + a s: one RK4 step of q̇ = q_dot(q, v + a s)
VectorXd path(const fs::model& m, const VectorXd& q, const VectorXd& v, const VectorXd& a, double t) {
    const VectorXd k1 = fs::q_dot(m, q, v);
    const VectorXd k2 = fs::q_dot(m, q + 0.5 * t * k1, v + 0.5 * t * a);
    const VectorXd k3 = fs::q_dot(m, q + 0.5 * t * k2, v + 0.5 * t * a);
    const VectorXd k4 = fs::q_dot(m, q + t * k3, v + t * a);
    return q + (t / 6) * (k1 + 2 * k2 + 2 * k3 + k4);
}

const fs::reference all_refs[] = {fs::reference::local, fs::reference::world,
                                  fs::reference::local_world_aligned};
const char* name(fs::reference r) {
    switch (r) {
    case fs::reference::local: return "local";
    case fs::reference::world: return "world";
    case fs::reference::local_world_aligned: return "lwa";
    }
    return "?";
}

// a random tree of 4–8 bodies (floating base or not) with at least one fixed link (with mass),
// one revolute and one prismatic joint
fs::model make_model(std::mt19937_64& rng, bool floating) {
    fs::random_tree_options opt;
    opt.min_bodies = 4;
    opt.max_bodies = 8;
    opt.floating_base_probability = floating ? 1.0 : 0.0;
    opt.world_parent_probability = 0.15;
    fs::model m = fs::random_tree(rng, opt);
    std::vector<int> rest;
    for (int i = 1; i < m.size(); ++i) rest.push_back(i);
    std::shuffle(rest.begin(), rest.end(), rng);
    m.bodies[static_cast<std::size_t>(rest[0])].kind = fs::joint_kind::fixed;
    m.bodies[static_cast<std::size_t>(rest[1])].kind = fs::joint_kind::revolute;
    m.bodies[static_cast<std::size_t>(rest[2])].kind = fs::joint_kind::prismatic;
    return m;
}

// frames: one on the world, one on a fixed link, three on random bodies
std::vector<fs::frame> make_frames(std::mt19937_64& rng, const fs::model& m) {
    std::vector<fs::frame> F;
    int fixed_body = -1;
    for (int i = 0; i < m.size(); ++i)
        if (m[i].kind == fs::joint_kind::fixed) fixed_body = i;
    const int parents[] = {-1, fixed_body, fs::uniform_int(rng, 0, m.size() - 1),
                           fs::uniform_int(rng, 0, m.size() - 1), fs::uniform_int(rng, -1, m.size() - 1)};
    for (int p : parents) F.push_back(fs::frame{p, fs::random_rotation(rng), fs::uniform_vec3(rng, 0.5)});
    return F;
}

// the frame velocity in the three references from central differences of the pose along q(t)
// (velocity coordinates v): ω = Ṙ Rᵀ (world), ṗ; local (Rᵀ ω, Rᵀ ṗ), world (ω, ṗ − ω × p),
// local_world_aligned (ω, ṗ)
vec6 fd_velocity(const fs::model& m, const VectorXd& q, const VectorXd& v, const fs::frame& f,
                 fs::reference ref, double h) {
    const VectorXd zero = VectorXd::Zero(m.nv());
    const fs::pose P0 = fs::frame_pose(m, q, f);
    const fs::pose Pp = fs::frame_pose(m, path(m, q, v, zero, h), f);
    const fs::pose Pm = fs::frame_pose(m, path(m, q, v, zero, -h), f);
    const mat3 Rdot = (Pp.rotation - Pm.rotation) / (2 * h);
    const vec3 pdot = (Pp.origin - Pm.origin) / (2 * h);
    const vec3 w = vee(Rdot * P0.rotation.transpose());
    vec6 x;
    switch (ref) {
    case fs::reference::local: x << P0.rotation.transpose() * w, P0.rotation.transpose() * pdot; break;
    case fs::reference::world: x << w, pdot - w.cross(P0.origin); break;
    case fs::reference::local_world_aligned: x << w, pdot; break;
    }
    return x;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

TEST_CASE("featherstone frames: Jacobians against finite differences of poses", "[featherstone]") {
    std::mt19937_64 rng(101);
    worst W("frame Jacobians");
    const double h = 1e-5;
    for (int k = 0; k < 16; ++k) {
        const fs::model m = make_model(rng, k % 2 == 0);
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, m.nv());
        for (const fs::frame& f : make_frames(rng, m)) {
            // pose: rotation orthonormal, composed from the body's world placement
            const fs::pose P = fs::frame_pose(m, q, f);
            CHECK(W("pose rotation orthonormal", rel(mat3(P.rotation * P.rotation.transpose()), mat3::Identity())) <= 1e-13);
            for (fs::reference ref : all_refs) {
                const std::string r = name(ref);
                const MatrixXd J = fs::frame_jacobian(m, q, f, ref);
                REQUIRE(J.rows() == 6);
                REQUIRE(J.cols() == m.nv());
                CHECK(W("frame_velocity = J v (" + r + ")", rel(fs::frame_velocity(m, q, v, f, ref), mul(J, v))) <= 1e-12);
                CHECK(W("J v vs FD of pose (" + r + ")", rel(mul(J, v), fd_velocity(m, q, v, f, ref, h))) <= 1e-7);
                for (int c = 0; c < m.nv(); ++c) {
                    const VectorXd e = VectorXd::Unit(m.nv(), c);
                    CHECK(W("J column vs FD of pose (" + r + ")", rel(J.col(c), fd_velocity(m, q, e, f, ref, h))) <= 1e-7);
                }
            }
        }
    }
}

TEST_CASE("featherstone frames: Jdot, accelerations and the identity a = J a + Jdot v", "[featherstone]") {
    std::mt19937_64 rng(102);
    worst W("frame Jdot and accelerations");
    const double h = 1e-5;
    for (int k = 0; k < 16; ++k) {
        const fs::model m = make_model(rng, k % 2 == 0);
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, m.nv());
        const VectorXd a = fs::random_vector(rng, m.nv());
        const VectorXd zero = VectorXd::Zero(m.nv());
        const VectorXd qp0 = path(m, q, v, zero, h), qm0 = path(m, q, v, zero, -h);   // a = 0
        const VectorXd qpa = path(m, q, v, a, h), qma = path(m, q, v, a, -h);         // v + a t
        for (const fs::frame& f : make_frames(rng, m)) {
            const vec3 acc_world = fs::frame_classical_acceleration(m, q, v, a, f, fs::reference::world);
            for (fs::reference ref : all_refs) {
                const std::string r = name(ref);
                const MatrixXd J = fs::frame_jacobian(m, q, f, ref);
                const MatrixXd Jd = fs::frame_jacobian_dot(m, q, v, f, ref);
                // J̇ = d/dt J(q(t)), q̇ = q_dot(q, v)
                const MatrixXd Jd_fd = (fs::frame_jacobian(m, qp0, f, ref) - fs::frame_jacobian(m, qm0, f, ref)) / (2 * h);
                CHECK(W("Jdot vs FD of J (" + r + ")", rel(Jd, Jd_fd)) <= 1e-7);
                const VectorXd Ja = mul(J, a) + mul(Jd, v);
                // J a + J̇ v = d/dt of the velocity numbers in `ref`
                const vec6 dv_fd = (fs::frame_velocity(m, qpa, v + h * a, f, ref) -
                                    fs::frame_velocity(m, qma, v - h * a, f, ref)) / (2 * h);
                CHECK(W("J a + Jdot v vs FD of frame_velocity (" + r + ")", rel(Ja, dv_fd)) <= 1e-7);
                const vec6 acc = fs::frame_acceleration(m, q, v, a, f, ref);
                if (ref != fs::reference::local_world_aligned) {
                    CHECK(W("frame_acceleration = J a + Jdot v (" + r + ")", rel(acc, Ja)) <= 1e-12);
                    CHECK(W("frame_acceleration vs FD of frame_velocity (" + r + ")", rel(acc, dv_fd)) <= 1e-7);
                } else {
                    // J a + J̇ v = (ω̇, p̈) in world axes; frame_acceleration(lwa) = (ω̇, p̈ − ω × ṗ)
                    vec6 expect;
                    expect << acc.head<3>(), acc_world;
                    CHECK(W("lwa: J a + Jdot v = (angular acc, classical acc world)", rel(Ja, expect)) <= 1e-12);
                    const vec6 vel = fs::frame_velocity(m, q, v, f, ref);
                    vec6 acc2;
                    acc2 << acc.head<3>(), acc_world - vel.head<3>().cross(vel.tail<3>());
                    CHECK(W("lwa: frame_acceleration = (w', p'' - w x p')", rel(acc, acc2)) <= 1e-12);
                    // and the lwa acceleration is the local one rotated
                    const mat3 R = fs::frame_pose(m, q, f).rotation;
                    const vec6 al = fs::frame_acceleration(m, q, v, a, f, fs::reference::local);
                    vec6 rot;
                    rot << R * al.head<3>(), R * al.tail<3>();
                    CHECK(W("lwa: frame_acceleration = diag(R, R) local", rel(acc, rot)) <= 1e-12);
                }
            }
        }
    }
}

TEST_CASE("featherstone frames: classical acceleration against second differences", "[featherstone]") {
    std::mt19937_64 rng(103);
    worst W("classical acceleration");
    const double h = 1e-4;
    for (int k = 0; k < 16; ++k) {
        const fs::model m = make_model(rng, k % 2 == 0);
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, m.nv());
        const VectorXd a = fs::random_vector(rng, m.nv());
        const VectorXd qp = path(m, q, v, a, h), qm = path(m, q, v, a, -h);
        for (const fs::frame& f : make_frames(rng, m)) {
            const fs::pose P0 = fs::frame_pose(m, q, f);
            const vec3 pdd = (fs::frame_pose(m, qp, f).origin - 2 * P0.origin + fs::frame_pose(m, qm, f).origin) / (h * h);
            CHECK(W("classical (world) vs second difference", rel(fs::frame_classical_acceleration(m, q, v, a, f, fs::reference::world), pdd)) <= 1e-5);
            CHECK(W("classical (lwa) vs second difference", rel(fs::frame_classical_acceleration(m, q, v, a, f, fs::reference::local_world_aligned), pdd)) <= 1e-5);
            CHECK(W("classical (local) vs R^T second difference",
                    rel(fs::frame_classical_acceleration(m, q, v, a, f, fs::reference::local), vec3(P0.rotation.transpose() * pdd))) <= 1e-5);
        }
    }
}

TEST_CASE("featherstone frames: centre of mass, its Jacobian, subtree masses", "[featherstone]") {
    std::mt19937_64 rng(104);
    worst W("centre of mass");
    const double h = 1e-5;
    for (int k = 0; k < 20; ++k) {
        const fs::model m = make_model(rng, k % 2 == 0);
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, m.nv());
        const VectorXd zero = VectorXd::Zero(m.nv());
        const fs::kinematics K = fs::fk(m, q, v, zero);
        // direct sums over the bodies
        double M = 0;
        vec3 mc = vec3::Zero(), mcd = vec3::Zero();
        std::vector<vec3> ci(static_cast<std::size_t>(m.size()));
        for (int i = 0; i < m.size(); ++i) {
            M += m[i].mass;
            ci[static_cast<std::size_t>(i)] = K[i].origin + K[i].rotation * m[i].com;
            mc += m[i].mass * ci[static_cast<std::size_t>(i)];
            const vec3 w = K[i].velocity.head<3>(), vo = K[i].velocity.tail<3>();
            mcd += m[i].mass * (K[i].rotation * (vo + w.cross(m[i].com)));
        }
        CHECK(W("total_mass", std::abs(fs::total_mass(m) - M)) <= 1e-14);
        const vec3 c = fs::center_of_mass(m, q);
        CHECK(W("center_of_mass vs direct sum", rel(c, vec3(mc / M))) <= 1e-12);
        const vec3 cd = fs::center_of_mass_velocity(m, q, v);
        CHECK(W("com velocity vs direct sum", rel(cd, vec3(mcd / M))) <= 1e-12);
        const vec3 cd_fd = (fs::center_of_mass(m, path(m, q, v, zero, h)) - fs::center_of_mass(m, path(m, q, v, zero, -h))) / (2 * h);
        CHECK(W("com velocity vs FD of com", rel(cd, cd_fd)) <= 1e-7);
        const MatrixXd Jc = fs::center_of_mass_jacobian(m, q);
        REQUIRE(Jc.rows() == 3);
        CHECK(W("J_com v = com velocity", rel(mul(Jc, v), cd)) <= 1e-12);
        for (int col = 0; col < m.nv(); ++col) {
            const VectorXd e = VectorXd::Unit(m.nv(), col);
            const vec3 d = (fs::center_of_mass(m, path(m, q, e, zero, h)) - fs::center_of_mass(m, path(m, q, e, zero, -h))) / (2 * h);
            CHECK(W("J_com column vs FD of com", rel(Jc.col(col), d)) <= 1e-7);
        }
        // subtrees: the sum over every body whose ancestor chain contains i
        const std::vector<fs::subtree_mass> S = fs::subtree_centers_of_mass(m, q);
        REQUIRE(static_cast<int>(S.size()) == m.size());
        for (int i = 0; i < m.size(); ++i) {
            double Mi = 0;
            vec3 mci = vec3::Zero();
            for (int j = 0; j < m.size(); ++j) {
                int a = j;
                while (a >= 0 && a != i) a = m[a].parent;
                if (a != i) continue;
                Mi += m[j].mass;
                mci += m[j].mass * ci[static_cast<std::size_t>(j)];
            }
            CHECK(W("subtree mass", std::abs(S[static_cast<std::size_t>(i)].mass - Mi)) <= 1e-13);
            CHECK(W("subtree com", rel(S[static_cast<std::size_t>(i)].com, vec3(mci / Mi))) <= 1e-12);
        }
    }
}

TEST_CASE("featherstone frames: centroidal momentum", "[featherstone]") {
    std::mt19937_64 rng(105);
    worst W("centroidal momentum");
    for (int k = 0; k < 20; ++k) {
        const fs::model m = make_model(rng, k % 2 == 0);
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, m.nv());
        const fs::kinematics K = fs::fk(m, q, v, VectorXd::Zero(m.nv()));
        const vec3 G = fs::center_of_mass(m, q);
        // classical: L_G = Σ R I_c Rᵀ ω + (c_i − G) × m_i ċ_i, p = Σ m_i ċ_i
        vec3 L = vec3::Zero(), p = vec3::Zero();
        for (int i = 0; i < m.size(); ++i) {
            const mat3& R = K[i].rotation;
            const vec3 w = R * K[i].velocity.head<3>();
            const vec3 cdot = R * (K[i].velocity.tail<3>() + K[i].velocity.head<3>().cross(m[i].com));
            const vec3 c = K[i].origin + R * m[i].com;
            L += R * m[i].inertia_c * R.transpose() * w + (c - G).cross(m[i].mass * cdot);
            p += m[i].mass * cdot;
        }
        vec6 h_direct;
        h_direct << L, p;
        const vec6 h = fs::centroidal_momentum(m, q, v);
        CHECK(W("centroidal momentum vs classical sum", rel(h, h_direct)) <= 1e-12);
        const MatrixXd A = fs::centroidal_momentum_matrix(m, q);
        REQUIRE(A.rows() == 6);
        REQUIRE(A.cols() == m.nv());
        CHECK(W("A_G v = h", rel(mul(A, v), h)) <= 1e-12);
        CHECK(W("A_G linear rows = M J_com", rel(A.bottomRows(3), fs::total_mass(m) * fs::center_of_mass_jacobian(m, q))) <= 1e-12);
    }
}

TEST_CASE("featherstone frames: mimic joints", "[featherstone]") {
    std::mt19937_64 rng(106);
    worst W("mimic joints");
    for (int k = 0; k < 30; ++k) {
        const fs::model m = make_model(rng, k % 2 == 0);
        // couplings among the 1-dof joints: one, or two when there are four of them
        std::vector<int> one;
        for (int i = 0; i < m.size(); ++i)
            if (m[i].kind == fs::joint_kind::revolute || m[i].kind == fs::joint_kind::prismatic) one.push_back(i);
        std::shuffle(one.begin(), one.end(), rng);
        std::vector<fs::mimic_coupling> cs;
        cs.push_back({one[0], one[1], fs::uniform(rng, -2, 2), fs::uniform(rng, -0.5, 0.5)});
        if (one.size() >= 4) cs.push_back({one[2], one[3], fs::uniform(rng, -2, 2), fs::uniform(rng, -0.5, 0.5)});

        // the full state with the couplings applied by hand, and its independent part
        VectorXd q = fs::random_q(rng, m), v = fs::random_vector(rng, m.nv()), a = fs::random_vector(rng, m.nv());
        std::vector<bool> follows_q(static_cast<std::size_t>(m.nq()), false), follows_v(static_cast<std::size_t>(m.nv()), false);
        for (const fs::mimic_coupling& c : cs) {
            q[m.q_index(c.follower)] = c.ratio * q[m.q_index(c.leader)] + c.offset;
            v[m.v_index(c.follower)] = c.ratio * v[m.v_index(c.leader)];
            a[m.v_index(c.follower)] = c.ratio * a[m.v_index(c.leader)];
            follows_q[static_cast<std::size_t>(m.q_index(c.follower))] = true;
            follows_v[static_cast<std::size_t>(m.v_index(c.follower))] = true;
        }
        std::vector<double> qr, vr, ar;
        std::vector<int> reduced_of(static_cast<std::size_t>(m.nv()), -1);   // v index → v_r index
        for (int j = 0; j < m.nq(); ++j)
            if (!follows_q[static_cast<std::size_t>(j)]) qr.push_back(q[j]);
        for (int j = 0; j < m.nv(); ++j)
            if (!follows_v[static_cast<std::size_t>(j)]) {
                reduced_of[static_cast<std::size_t>(j)] = static_cast<int>(vr.size());
                vr.push_back(v[j]);
                ar.push_back(a[j]);
            }
        const VectorXd q_r = Eigen::Map<const VectorXd>(qr.data(), static_cast<Eigen::Index>(qr.size()));
        const VectorXd v_r = Eigen::Map<const VectorXd>(vr.data(), static_cast<Eigen::Index>(vr.size()));
        const VectorXd a_r = Eigen::Map<const VectorXd>(ar.data(), static_cast<Eigen::Index>(ar.size()));
        REQUIRE(q_r.size() == fs::mimic_nq(m, cs));
        REQUIRE(v_r.size() == fs::mimic_nv(m, cs));
        CHECK(W("expand_q vs hand", rel(fs::expand_q(m, cs, q_r), q)) <= 1e-15);   // (≤ 1 ulp: FMA contraction)
        CHECK(W("reduce_q vs hand", rel(fs::reduce_q(m, cs, q), q_r)) == 0);   // copies
        const MatrixXd G = fs::mimic_matrix(m, cs);
        CHECK(W("G v_r vs hand", rel(mul(G, v_r), v)) <= 1e-15);

        // τ_r by hand: the independent entries, plus ratio · τ_follower on the leader's entry
        const VectorXd tau = fs::rnea(m, q, v, a);
        VectorXd tau_r(v_r.size());
        for (int j = 0; j < m.nv(); ++j)
            if (reduced_of[static_cast<std::size_t>(j)] >= 0) tau_r[reduced_of[static_cast<std::size_t>(j)]] = tau[j];
        for (const fs::mimic_coupling& c : cs)
            tau_r[reduced_of[static_cast<std::size_t>(m.v_index(c.leader))]] += c.ratio * tau[m.v_index(c.follower)];
        const VectorXd tau_mimic = fs::rnea_mimic(m, cs, q_r, v_r, a_r);
        CHECK(W("rnea_mimic vs hand-coupled rnea", rel(tau_mimic, tau_r)) <= 1e-12);

        const MatrixXd H = fs::crba_mimic(m, cs, q_r);
        CHECK(W("crba_mimic symmetric", rel(H, MatrixXd(H.transpose()))) <= 1e-14);
        CHECK_NOTHROW(fs::detail::solve_spd(H, v_r));   // Cholesky succeeds: positive definite
        CHECK(W("v_r^T H_r v_r = 2 T(q, G v_r)", std::abs(v_r.dot(mul(H, v_r).col(0)) - 2 * fs::kinetic_energy(m, q, v)) /
                                                   std::max(1.0, 2 * fs::kinetic_energy(m, q, v))) <= 1e-12);
        CHECK(W("H_r a_r + rnea_mimic(a = 0) = rnea_mimic", rel(mul(H, a_r) + fs::rnea_mimic(m, cs, q_r, v_r, VectorXd::Zero(v_r.size())), tau_mimic)) <= 1e-11);
        CHECK(W("aba_mimic(rnea_mimic(a_r)) = a_r", rel(fs::aba_mimic(m, cs, q_r, v_r, tau_mimic), a_r)) <= 1e-10);
        // with external forces
        const std::vector<vec6> fx = fs::random_forces(rng, m);
        CHECK(W("with f_ext: aba_mimic(rnea_mimic(a_r, f), f) = a_r",
                rel(fs::aba_mimic(m, cs, q_r, v_r, fs::rnea_mimic(m, cs, q_r, v_r, a_r, fx), fx), a_r)) <= 1e-10);

        for (const fs::frame& f : make_frames(rng, m))
            for (fs::reference ref : all_refs)
                CHECK(W("jacobian_mimic v_r = frame_velocity(q, G v_r)",
                        rel(mul(fs::jacobian_mimic(m, cs, q_r, f, ref), v_r), fs::frame_velocity(m, q, v, f, ref))) <= 1e-12);
    }
}

TEST_CASE("featherstone frames: merging fixed links changes no dynamics", "[featherstone]") {
    std::mt19937_64 rng(107);
    worst W("merge_fixed");
    int merged_into_world = 0, fixed_chains = 0;
    for (int k = 0; k < 30; ++k) {
        fs::model m = make_model(rng, k % 3 == 0);
        // more fixed links: a fixed child of a fixed link, sometimes a fixed body on the world
        if (k % 2 == 1) {
            fs::body b = m.bodies.back();
            b.parent = 0;
            for (int i = 0; i < m.size(); ++i)
                if (m[i].kind == fs::joint_kind::fixed) b.parent = i;
            b.kind = fs::joint_kind::fixed;
            b.rotation = fs::random_rotation(rng);
            m.bodies.push_back(b);
            b.parent = m.size() - 1;
            b.kind = fs::joint_kind::revolute;
            b.axis = fs::random_unit_vec3(rng);
            m.bodies.push_back(b);
        }
        if (k % 3 == 1) m.bodies[0].kind = fs::joint_kind::fixed;
        const std::vector<fs::frame> frames = make_frames(rng, m);
        const fs::merged_model mm = fs::merge_fixed(m, frames);
        const fs::model& n = mm.merged;
        REQUIRE(n.nq() == m.nq());
        REQUIRE(n.nv() == m.nv());
        REQUIRE(static_cast<int>(mm.body_map.size()) == m.size());
        REQUIRE(mm.frames.size() == frames.size());
        double dropped = 0;
        for (int i = 0; i < m.size(); ++i) {
            if (m[i].kind == fs::joint_kind::fixed && m[i].parent >= 0 && m[m[i].parent].kind == fs::joint_kind::fixed) ++fixed_chains;
            if (mm.body_map[static_cast<std::size_t>(i)] < 0) {
                ++merged_into_world;
                dropped += m[i].mass;
            }
        }
        for (const fs::body& b : n.bodies) CHECK(b.kind != fs::joint_kind::fixed);
        CHECK(W("total mass + dropped (merged into the world)", std::abs(fs::total_mass(n) + dropped - fs::total_mass(m))) <= 1e-13);

        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, m.nv());
        const VectorXd a = fs::random_vector(rng, m.nv());
        const VectorXd tau = fs::random_vector(rng, m.nv(), 5.0);
        CHECK(W("rnea", rel(fs::rnea(n, q, v, a), fs::rnea(m, q, v, a))) <= 1e-12);
        CHECK(W("crba", rel(fs::crba(n, q), fs::crba(m, q))) <= 1e-12);
        CHECK(W("aba", rel(fs::aba(n, q, v, tau), fs::aba(m, q, v, tau))) <= 1e-12);
        // every old body's placement: world pose of the new body composed with `placement`
        for (int i = 0; i < m.size(); ++i) {
            const fs::frame body_frame{i, mat3::Identity(), vec3::Zero()};
            const fs::pose P = fs::frame_pose(m, q, body_frame);
            const fs::pose& pl = mm.placement[static_cast<std::size_t>(i)];
            const fs::pose Q = fs::frame_pose(n, q, fs::frame{mm.body_map[static_cast<std::size_t>(i)], pl.rotation, pl.origin});
            CHECK(W("body placements", std::max(rel(Q.rotation, P.rotation), rel(Q.origin, P.origin))) <= 1e-12);
        }
        for (std::size_t j = 0; j < frames.size(); ++j) {
            const fs::pose P = fs::frame_pose(m, q, frames[j]);
            const fs::pose Q = fs::frame_pose(n, q, mm.frames[j]);
            CHECK(W("frame poses", std::max(rel(Q.rotation, P.rotation), rel(Q.origin, P.origin))) <= 1e-12);
            for (fs::reference ref : all_refs) {
                CHECK(W("frame Jacobians", rel(fs::frame_jacobian(n, q, mm.frames[j], ref), fs::frame_jacobian(m, q, frames[j], ref))) <= 1e-12);
                CHECK(W("frame Jdot", rel(fs::frame_jacobian_dot(n, q, v, mm.frames[j], ref), fs::frame_jacobian_dot(m, q, v, frames[j], ref))) <= 1e-12);
            }
        }
        if (dropped == 0) {
            CHECK(W("center of mass (nothing merged into the world)", rel(fs::center_of_mass(n, q), fs::center_of_mass(m, q))) <= 1e-12);
            CHECK(W("centroidal momentum (nothing merged into the world)", rel(fs::centroidal_momentum(n, q, v), fs::centroidal_momentum(m, q, v))) <= 1e-12);
        }
    }
    // the cases this test is meant to exercise did occur
    CHECK(merged_into_world > 0);
    CHECK(fixed_chains > 0);
}
