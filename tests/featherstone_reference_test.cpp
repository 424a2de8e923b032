// Tests of the Featherstone reference itself (tests/support/featherstone.hpp), which other tests
// use to judge ctga's mechanics: it has to be right first. Nothing here uses ctga.
//
// The checks tie the algorithms to each other and, more importantly, to things computed
// without spatial algebra:
//   * the spatial helpers against their defining identities and Eigen's own rotations;
//   * world placements (composed from 3×3 rotations and origins) against the 6×6 transforms;
//     velocities against finite differences of the placements, accelerations against finite
//     differences of the velocities;
//   * H = Σ J_iᵀ I_i J_i, T = ½ vᵀ H v, gravity torques = ∇V, and, for fixed bases, RNEA
//     against Lagrange's equations with H and V differentiated numerically;
//   * a single free body against the classical Newton–Euler equations at its centre of mass;
//   * a pendulum against its closed form; external forces against Jᵀ f and against gravity;
//   * ABA against RNEA and against H⁻¹(τ − C); power balance along RK4 trajectories.
//
// Error measure: rel(x, y) = max_k |x_k − y_k| / max(1, max_k |y_k|) (y the independent value).
// The worst value of each measure is printed at the end of each test case.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "support/catch.hpp"
#include "support/worst.hpp"
#include "support/featherstone.hpp"
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

// (The helpers take MatrixXd and multiply with lazyProduct, and H is factored by hand below:
// one instantiation each instead of Eigen's large-matrix kernels for every expression type
// keeps this file's compile time down.)

// A B, coefficient by coefficient
MatrixXd mul(const MatrixXd& A, const MatrixXd& B) { return A.lazyProduct(B); }

// Cholesky factor L (H = L Lᵀ) of a symmetric matrix; false if H is not positive definite
bool cholesky(const MatrixXd& H, MatrixXd& L) {
    const Eigen::Index n = H.rows();
    L = MatrixXd::Zero(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
        double d = H(j, j);
        for (Eigen::Index k = 0; k < j; ++k) d -= L(j, k) * L(j, k);
        if (!(d > 0)) return false;
        L(j, j) = std::sqrt(d);
        for (Eigen::Index i = j + 1; i < n; ++i) {
            double x = H(i, j);
            for (Eigen::Index k = 0; k < j; ++k) x -= L(i, k) * L(j, k);
            L(i, j) = x / L(j, j);
        }
    }
    return true;
}

// H⁻¹ b for symmetric positive definite H
VectorXd solve_spd(const MatrixXd& H, const VectorXd& b) {
    MatrixXd L;
    if (!cholesky(H, L)) throw std::runtime_error("solve_spd: not positive definite");
    const Eigen::Index n = H.rows();
    VectorXd y(n), x(n);
    for (Eigen::Index i = 0; i < n; ++i) {   // L y = b
        double s = b[i];
        for (Eigen::Index k = 0; k < i; ++k) s -= L(i, k) * y[k];
        y[i] = s / L(i, i);
    }
    for (Eigen::Index i = n - 1; i >= 0; --i) {   // Lᵀ x = y
        double s = y[i];
        for (Eigen::Index k = i + 1; k < n; ++k) s -= L(k, i) * x[k];
        x[i] = s / L(i, i);
    }
    return x;
}

using ctga::test::worst;

// (ω) from a skew matrix (its skew part)
vec3 vee(const mat3& W) { return 0.5 * vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1)); }

// q + t q̇(q, v): a first-order path through q with velocity coordinates v (fk normalises the
// quaternion of a floating joint)
VectorXd advance(const fs::model& m, const VectorXd& q, const VectorXd& v, double t) {
    return q + t * fs::q_dot(m, q, v);
}

double energy(const fs::model& m, const VectorXd& q, const VectorXd& v) {
    return fs::kinetic_energy(m, q, v) + fs::potential_energy(m, q);
}

std::vector<fs::model> random_models(std::mt19937_64& rng, int count, const fs::random_tree_options& opt = {}) {
    std::vector<fs::model> models;
    for (int k = 0; k < count; ++k) models.push_back(fs::random_tree(rng, opt));
    return models;
}

// the single-body pendulum: a revolute joint whose axis is world y, its mass m at distance L
// "below" the axis (world −z at θ = 0), rotational inertia Ic about the com
struct pendulum {
    fs::model model;
    double m, L, I_axis;   // I_axis = the com inertia about the joint axis
};

// variant 0: joint frame = world frame, axis +y;  variant 1: axis −y;
// variant 2: joint frame turned (its z axis = world y) and moved to (1, 2, 3), axis +z
pendulum make_pendulum(int variant) {
    pendulum p;
    p.m = 1.7;
    p.L = 0.8;
    fs::body b;
    b.parent = -1;
    b.kind = fs::joint_kind::revolute;
    b.mass = p.m;
    b.inertia_c = vec3(0.01, 0.02, 0.03).asDiagonal();
    if (variant == 0 || variant == 1) {
        b.axis = variant == 0 ? vec3(0, 1, 0) : vec3(0, -1, 0);
        b.com = vec3(0, 0, -p.L);
    } else {
        b.rotation << 1, 0, 0,
                      0, 0, 1,
                      0, -1, 0;   // columns: joint x = world x, joint y = world −z, joint z = world y
        b.translation = vec3(1, 2, 3);
        b.axis = vec3(0, 0, 1);
        b.com = vec3(0, p.L, 0);   // joint y = world −z: hanging down
    }
    p.I_axis = b.axis.dot(b.inertia_c * b.axis);
    p.model.bodies.push_back(b);
    return p;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

TEST_CASE("featherstone reference: spatial algebra helpers", "[featherstone]") {
    std::mt19937_64 rng(1);
    worst W("spatial algebra helpers");
    for (int k = 0; k < 200; ++k) {
        const mat3 E = fs::random_rotation(rng);
        const vec3 r = fs::uniform_vec3(rng, 2.0);
        const mat6 X = fs::plucker(E, r);
        const vec6 mv = fs::random_vector(rng, 6), mv2 = fs::random_vector(rng, 6), f = fs::random_vector(rng, 6);

        CHECK(W("rotation orthonormal", rel(mat3(E * E.transpose()), mat3::Identity())) <= 1e-14);
        CHECK(W("rotation det = 1", rel(E.determinant(), 1.0)) <= 1e-14);
        CHECK(W("plucker_inverse(X) X = 1", rel(mat6(fs::plucker_inverse(X) * X), mat6::Identity())) <= 1e-14);
        CHECK(W("X plucker_inverse(X) = 1", rel(mat6(X * fs::plucker_inverse(X)), mat6::Identity())) <= 1e-14);
        CHECK(W("force_transform(X)^T X = 1", rel(mat6(fs::force_transform(X).transpose() * X), mat6::Identity())) <= 1e-14);
        // ^B X_A moves the reference point: a pure translation r maps (ω, v_A) to (ω, v_A − r × ω)
        {
            const mat6 T = fs::plucker(mat3::Identity(), r);
            vec6 expect;
            expect << mv.head<3>(), mv.tail<3>() - r.cross(mv.head<3>());
            CHECK(W("xlt moves the velocity's point", rel(vec6(T * mv), expect)) <= 1e-14);
        }
        // power is invariant: (X* f)·(X m) = f·m
        CHECK(W("power invariant", rel((fs::force_transform(X) * f).dot(X * mv), f.dot(mv))) <= 1e-13);
        // cross products: crf = −crmᵀ, m × m = 0, X (m1 × m2) = (X m1) × (X m2)
        CHECK(W("crf = -crm^T", rel(fs::crf(mv), mat6(-fs::crm(mv).transpose()))) == 0);
        CHECK(W("m x m = 0", rel(vec6(fs::crm(mv) * mv), vec6::Zero())) <= 1e-15);
        CHECK(W("X (m1 x m2) = (X m1) x (X m2)",
                rel(vec6(X * fs::crm(mv) * mv2), vec6(fs::crm(X * mv) * (X * mv2)))) <= 1e-13);
        // crm in 3D terms: (ω, v) × (ω2, v2) = (ω × ω2, ω × v2 + v × ω2)
        {
            vec6 expect;
            expect << mv.head<3>().cross(mv2.head<3>()),
                mv.head<3>().cross(mv2.tail<3>()) + mv.tail<3>().cross(mv2.head<3>());
            CHECK(W("crm = 3D cross products", rel(vec6(fs::crm(mv) * mv2), expect)) <= 1e-15);
        }
        // rotations: Rodrigues = the quaternion (cos θ/2, sin θ/2 u) = Eigen's AngleAxis
        const vec3 u = fs::random_unit_vec3(rng);
        const double th = fs::uniform(rng, -4.0, 4.0);
        const mat3 Ra = fs::axis_angle(u, th);
        const mat3 Rq = fs::quaternion_rotation(std::cos(th / 2), std::sin(th / 2) * u.x(),
                                                std::sin(th / 2) * u.y(), std::sin(th / 2) * u.z());
        const mat3 Re = Eigen::AngleAxisd(th, u).toRotationMatrix();
        CHECK(W("axis_angle = quaternion_rotation", rel(Ra, Rq)) <= 1e-14);
        CHECK(W("axis_angle = Eigen::AngleAxisd", rel(Ra, Re)) <= 1e-14);
        const Eigen::Vector4d qu = fs::random_quaternion(rng);
        const Eigen::Quaterniond eq(qu[0], qu[1], qu[2], qu[3]);
        CHECK(W("quaternion_rotation = Eigen::Quaterniond",
                rel(fs::quaternion_rotation(qu[0], qu[1], qu[2], qu[3]), mat3(eq.toRotationMatrix()))) <= 1e-14);
        CHECK(W("q and -q", rel(fs::quaternion_rotation(qu[0], qu[1], qu[2], qu[3]),
                                fs::quaternion_rotation(-qu[0], -qu[1], -qu[2], -qu[3]))) == 0);
        // spatial inertia: the momentum of a body with spatial velocity (ω, v) is
        // (I_c ω + c × p, p) with p = m (v + ω × c) the linear momentum
        const double mass = fs::uniform(rng, 0.5, 2.0);
        const vec3 c = fs::uniform_vec3(rng, 0.5);
        const mat3 Ic = fs::random_inertia_c(rng, mass, 0.05, 0.3);
        const vec3 om = mv.head<3>(), vo = mv.tail<3>();
        const vec3 p = mass * (vo + om.cross(c));
        vec6 h;
        h << Ic * om + c.cross(p), p;
        CHECK(W("spatial inertia = momentum", rel(vec6(fs::spatial_inertia(mass, c, Ic) * mv), h)) <= 1e-14);
        // ABA's small inverse (Gauss–Jordan) of an n × n symmetric positive definite matrix
        {
            const int n = 1 + k % 6;
            const MatrixXd A = fs::random_vector(rng, n * n).reshaped(n, n);
            const fs::matn D = mul(A, A.transpose()) + MatrixXd::Identity(n, n);
            CHECK(W("inverse_small(D) D = 1", rel(mul(fs::inverse_small(D), D), MatrixXd::Identity(n, n))) <= 1e-14);
        }
        // and a spatial inertia transforms as X* I X⁻¹: moving the body by X
        const mat6 I6 = fs::spatial_inertia(mass, c, Ic);
        const mat6 IB = fs::force_transform(X) * I6 * fs::plucker_inverse(X);   // in frame B
        const mat6 IB_direct = fs::spatial_inertia(mass, E * (c - r), E * Ic * E.transpose());
        CHECK(W("inertia transform", rel(IB, IB_direct)) <= 1e-13);
    }
}

TEST_CASE("featherstone reference: placements are consistent", "[featherstone]") {
    std::mt19937_64 rng(2);
    worst W("placements");
    fs::random_tree_options opt;
    opt.floating_children = true;
    for (const fs::model& m : random_models(rng, 100, opt)) {
        const VectorXd q = fs::random_q(rng, m);
        const fs::kinematics K = fs::fk(m, q, VectorXd::Zero(m.nv()), VectorXd::Zero(m.nv()));
        REQUIRE(static_cast<int>(K.bodies.size()) == m.size());
        for (int i = 0; i < m.size(); ++i) {
            CHECK(W("rotation orthonormal", rel(mat3(K[i].rotation * K[i].rotation.transpose()), mat3::Identity())) <= 1e-13);
            CHECK(W("X_world = plucker(R^T, p)",
                    rel(K[i].X_world, fs::plucker(K[i].rotation.transpose(), K[i].origin))) <= 1e-12);
            // a point fixed in body i, mapped to world by (R, p) and through the parent's placement
            if (m[i].parent >= 0) {
                const auto& P = K[m[i].parent];
                const vec3 o_in_parent = P.rotation.transpose() * (K[i].origin - P.origin);
                const mat3 R_in_parent = P.rotation.transpose() * K[i].rotation;
                const fs::body& b = m[i];
                const double* qi = q.data() + m.q_index(i);
                const fs::joint_state j = fs::jcalc(b, qi);
                CHECK(W("relative placement = joint", rel(o_in_parent, vec3(b.translation + b.rotation * j.t))) <= 1e-12);
                CHECK(W("relative rotation = joint", rel(R_in_parent, mat3(b.rotation * j.R))) <= 1e-12);
                if (b.kind == fs::joint_kind::revolute) {
                    // the joint axis is fixed: the same in the joint frame and in the body frame
                    CHECK(W("revolute axis fixed", rel(vec3(j.R * b.axis), b.axis)) <= 1e-15);
                }
            }
        }
    }
}

TEST_CASE("featherstone reference: ABA inverts RNEA and equals H^-1 (tau - C)", "[featherstone]") {
    std::mt19937_64 rng(3);
    worst W("ABA vs RNEA");
    fs::random_tree_options opt;
    opt.floating_children = true;
    for (int k = 0; k < 300; ++k) {
        opt.floating_children = k % 2 == 0;
        const fs::model m = fs::random_tree(rng, opt);
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, m.nv());
        const VectorXd a = fs::random_vector(rng, m.nv());
        const std::vector<vec6> f = fs::random_forces(rng, m);
        const VectorXd tau = fs::rnea(m, q, v, a);
        CHECK(W("aba(q, v, rnea(q, v, a)) vs a", rel(fs::aba(m, q, v, tau), a)) <= 1e-10);
        const VectorXd tau_f = fs::rnea(m, q, v, a, f);
        CHECK(W("with f_ext: aba(rnea(a, f), f) vs a", rel(fs::aba(m, q, v, tau_f, f), a)) <= 1e-10);
        // ABA against a dense solve of H q̈ = τ − C(q, v)
        const MatrixXd H = fs::crba(m, q);
        const VectorXd t2 = fs::random_vector(rng, m.nv(), 5.0);
        const VectorXd qdd = solve_spd(H, t2 - fs::rnea(m, q, v, VectorXd::Zero(m.nv()), f));
        CHECK(W("aba vs H^-1 (tau - C)", rel(fs::aba(m, q, v, t2, f), qdd)) <= 1e-10);
    }
}

TEST_CASE("featherstone reference: the joint-space inertia matrix", "[featherstone]") {
    std::mt19937_64 rng(4);
    worst W("CRBA");
    fs::random_tree_options opt;
    for (int k = 0; k < 200; ++k) {
        opt.floating_children = k % 3 == 0;
        const fs::model m = fs::random_tree(rng, opt);
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, m.nv());
        const VectorXd a = fs::random_vector(rng, m.nv());
        const MatrixXd H = fs::crba(m, q);
        REQUIRE(H.rows() == m.nv());
        REQUIRE(H.cols() == m.nv());
        if (m.nv() == 0) continue;
        CHECK(W("H symmetric", rel(H, MatrixXd(H.transpose()))) <= 1e-15);
        MatrixXd L;
        CHECK(cholesky(H, L));   // positive definite
        CHECK(W("H = L L^T", rel(mul(L, L.transpose()), H)) <= 1e-14);
        // H a + C = RNEA(a)
        const VectorXd C = fs::rnea(m, q, v, VectorXd::Zero(m.nv()));
        CHECK(W("H a + rnea(q, v, 0) vs rnea(q, v, a)", rel(mul(H, a) + C, fs::rnea(m, q, v, a))) <= 1e-11);
        // H = Σ J_iᵀ I_i J_i, T = ½ vᵀ H v = ½ Σ v_iᵀ I_i v_i
        MatrixXd H2 = MatrixXd::Zero(m.nv(), m.nv());
        const fs::kinematics K = fs::fk(m, q, v, VectorXd::Zero(m.nv()));
        double T2 = 0;
        for (int i = 0; i < m.size(); ++i) {
            const MatrixXd J = fs::jacobian_body(m, q, i);
            const mat6 I = fs::spatial_inertia(m[i]);
            H2 += mul(J.transpose(), mul(I, J));
            T2 += 0.5 * K[i].velocity.dot(I * K[i].velocity);
        }
        CHECK(W("H vs sum J^T I J", rel(H, H2)) <= 1e-12);
        const double T = fs::kinetic_energy(m, q, v);
        CHECK(W("kinetic_energy vs 1/2 v^T H v", rel(T, 0.5 * v.dot(mul(H, v).col(0)))) <= 1e-12);
        CHECK(W("kinetic_energy vs 1/2 sum v_i^T I_i v_i", rel(T, T2)) <= 1e-12);
    }
}

TEST_CASE("featherstone reference: Jacobians and finite differences of placements", "[featherstone]") {
    std::mt19937_64 rng(5);
    worst W("Jacobians and FD");
    fs::random_tree_options opt;
    const double h = 1e-5;
    for (int k = 0; k < 100; ++k) {
        opt.floating_children = k % 2 == 0;
        const fs::model m = fs::random_tree(rng, opt);
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, m.nv());
        const VectorXd a = fs::random_vector(rng, m.nv());
        const fs::kinematics K = fs::fk(m, q, v, a);
        // placements along q ± h q̇, velocities along (q ± h q̇, v ± h a)
        const fs::kinematics Kp = fs::fk(m, advance(m, q, v, h), v + h * a, a);
        const fs::kinematics Km = fs::fk(m, advance(m, q, v, -h), v - h * a, a);
        for (int i = 0; i < m.size(); ++i) {
            const MatrixXd Jb = fs::jacobian_body(m, q, i);
            const MatrixXd Jw = fs::jacobian_world(m, q, i);
            CHECK(W("fk velocity vs J_body v", rel(mul(Jb, v), K[i].velocity)) <= 1e-12);
            const mat6 X0inv = fs::plucker_inverse(K[i].X_world);   // body → world
            CHECK(W("J_world vs X_world^-1 J_body", rel(Jw, mul(X0inv, Jb))) <= 1e-12);

            // d/dt of the placement: Rᵀ Ṙ = ω×, Rᵀ ṗ = v (body coordinates)
            const mat3& R = K[i].rotation;
            const vec3& p = K[i].origin;
            const mat3 Rdot = (Kp[i].rotation - Km[i].rotation) / (2 * h);
            const vec3 pdot = (Kp[i].origin - Km[i].origin) / (2 * h);
            vec6 v_fd;
            v_fd << vee(R.transpose() * Rdot), R.transpose() * pdot;
            CHECK(W("fk velocity vs FD of placement (body)", rel(K[i].velocity, v_fd)) <= 1e-7);
            // world Plücker coordinates: ω_w = Ṙ Rᵀ, and the velocity of the body point at the
            // world origin, ṗ − ω_w × p
            const vec3 ow = vee(Rdot * R.transpose());
            vec6 vw_fd;
            vw_fd << ow, pdot - ow.cross(p);
            CHECK(W("J_world v vs FD of placement (world)", rel(mul(Jw, v), vw_fd)) <= 1e-7);
            // the spatial acceleration in body coordinates is the time derivative of the body
            // coordinates of the spatial velocity
            const vec6 a_fd = (Kp[i].velocity - Km[i].velocity) / (2 * h);
            CHECK(W("fk acceleration vs FD of velocity", rel(K[i].acceleration, a_fd)) <= 1e-7);
        }
    }
}

TEST_CASE("featherstone reference: gravity torques are the gradient of the potential", "[featherstone]") {
    std::mt19937_64 rng(6);
    worst W("gravity = dV/dq");
    fs::random_tree_options opt;
    const double h = 1e-5;
    for (int k = 0; k < 100; ++k) {
        opt.floating_children = k % 2 == 0;
        const fs::model m = fs::random_tree(rng, opt);
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd zero = VectorXd::Zero(m.nv());
        const VectorXd g = fs::rnea(m, q, zero, zero);
        for (int r = 0; r < 3; ++r) {
            const VectorXd dv = fs::random_vector(rng, m.nv());
            const double dV = (fs::potential_energy(m, advance(m, q, dv, h)) -
                               fs::potential_energy(m, advance(m, q, dv, -h))) / (2 * h);
            // scale: the size of the gravity torques
            const double scale = std::max(1.0, g.cwiseAbs().sum());
            CHECK(W("rnea(q, 0, 0) . dv vs dV/dt along q + t qdot(dv)", std::abs(g.dot(dv) - dV) / scale) <= 1e-8);
        }
    }
}

TEST_CASE("featherstone reference: RNEA satisfies Lagrange's equations (fixed base)", "[featherstone]") {
    // τ = H q̈ + Ḣ q̇ − ½ ∂(q̇ᵀ H q̇)/∂q + ∂V/∂q, with the derivatives of H and V by central differences
    std::mt19937_64 rng(7);
    worst W("Lagrange");
    fs::random_tree_options opt;
    opt.floating_base_probability = 0;
    opt.max_bodies = 20;
    const double h = 1e-5;
    for (int k = 0; k < 60; ++k) {
        const fs::model m = fs::random_tree(rng, opt);
        const int n = m.nv();
        REQUIRE(n == m.nq());
        if (n == 0) continue;
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, n);
        const VectorXd a = fs::random_vector(rng, n);
        const MatrixXd H = fs::crba(m, q);
        const MatrixXd Hdot = (fs::crba(m, q + h * v) - fs::crba(m, q - h * v)) / (2 * h);
        VectorXd dT(n), dV(n);
        for (int j = 0; j < n; ++j) {
            const VectorXd e = VectorXd::Unit(n, j);
            dT[j] = 0.5 * (v.dot(mul(fs::crba(m, q + h * e), v).col(0)) - v.dot(mul(fs::crba(m, q - h * e), v).col(0))) / (2 * h);
            dV[j] = (fs::potential_energy(m, q + h * e) - fs::potential_energy(m, q - h * e)) / (2 * h);
        }
        const VectorXd tau_lagrange = mul(H, a) + mul(Hdot, v) - dT + dV;
        const VectorXd tau = fs::rnea(m, q, v, a);
        CHECK(W("rnea vs Lagrange", rel(tau, tau_lagrange)) <= 1e-7);
        // the velocity-product terms alone (no gravity, no acceleration)
        fs::model m0 = m;
        m0.gravity.setZero();
        const VectorXd C = fs::rnea(m0, q, v, VectorXd::Zero(n));
        CHECK(W("C(q, v) vs Hdot v - dT/dq", rel(C, mul(Hdot, v) - dT)) <= 1e-7);
    }
}

TEST_CASE("featherstone reference: a free body obeys Newton-Euler at its centre of mass", "[featherstone]") {
    std::mt19937_64 rng(8);
    worst W("free body");
    fs::random_tree_options opt;
    opt.min_bodies = opt.max_bodies = 1;
    opt.floating_base_probability = 1;
    for (int k = 0; k < 200; ++k) {
        const fs::model m = fs::random_tree(rng, opt);
        REQUIRE(m.nv() == 6);
        const fs::body& b = m[0];
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, 6);
        const VectorXd a = fs::random_vector(rng, 6);
        const fs::kinematics K = fs::fk(m, q, v, a);
        // the velocity coordinates are the body's spatial velocity in body coordinates
        CHECK(W("fk velocity = v", rel(K[0].velocity, vec6(v))) <= 1e-15);
        CHECK(W("fk acceleration = a", rel(K[0].acceleration, vec6(a))) <= 1e-15);
        const vec3 om = v.head<3>(), vo = v.tail<3>(), omd = a.head<3>(), vod = a.tail<3>();
        const vec3& c = b.com;
        const vec3 vc = vo + om.cross(c);                   // com velocity, body coordinates
        const vec3 ac = vod + omd.cross(c) + om.cross(vc);  // classical com acceleration, body coordinates
        const vec3 gB = K[0].rotation.transpose() * m.gravity;
        const vec3 F = b.mass * (ac - gB);                  // the force the joint must apply
        const vec3 Nc = b.inertia_c * omd + om.cross(b.inertia_c * om);   // Euler, about the com
        vec6 tau_ne;
        tau_ne << Nc + c.cross(F), F;                       // moment about the body origin
        const VectorXd tau = fs::rnea(m, q, v, a);
        CHECK(W("rnea vs Newton-Euler", rel(tau, VectorXd(tau_ne))) <= 1e-12);
        CHECK(W("aba vs a", rel(fs::aba(m, q, v, VectorXd(tau_ne)), a)) <= 1e-12);
        // the joint frame's placement does not change the dynamics in body coordinates except
        // through gravity: with gravity off, moving the joint frame leaves τ unchanged
        fs::model m2 = m;
        m2.gravity.setZero();
        fs::model m3 = m2;
        m3.bodies[0].rotation = fs::random_rotation(rng);
        m3.bodies[0].translation = fs::uniform_vec3(rng, 3.0);
        CHECK(W("no gravity: independent of the joint placement",
                rel(fs::rnea(m3, q, v, a), fs::rnea(m2, q, v, a))) <= 1e-13);
    }
}

TEST_CASE("featherstone reference: a pendulum", "[featherstone]") {
    worst W("pendulum");
    const double g = 9.81;
    for (int variant = 0; variant < 3; ++variant) {
        const pendulum p = make_pendulum(variant);
        const fs::model& m = p.model;
        const double Ipiv = p.I_axis + p.m * p.L * p.L;
        for (int k = -8; k <= 8; ++k) {
            const double th = 0.4 * k;
            VectorXd q(1), v(1), z(1);
            q << th;
            v << 0.7 * std::sin(k);
            z << 0;
            // the com: at θ the pendulum has swung so that V = m g (z_joint − L cos θ)
            const fs::kinematics K = fs::fk(m, q, v, z);
            const vec3 com = K[0].origin + K[0].rotation * m[0].com;
            const double z0 = variant == 2 ? 3.0 : 0.0;
            CHECK(W("com height", std::abs(com.z() - (z0 - p.L * std::cos(th)))) <= 1e-15);
            CHECK(W("potential", rel(fs::potential_energy(m, q), p.m * g * (z0 - p.L * std::cos(th)))) <= 1e-14);
            CHECK(W("H = I + m L^2", rel(fs::crba(m, q)(0, 0), Ipiv)) <= 1e-14);
            CHECK(W("kinetic = 1/2 (I + m L^2) thetadot^2", rel(fs::kinetic_energy(m, q, v), 0.5 * Ipiv * v[0] * v[0])) <= 1e-14);
            // holding torque at rest: τ = dV/dθ = m g L sin θ
            CHECK(W("rnea at rest = m g L sin", rel(fs::rnea(m, q, z, z)[0], p.m * g * p.L * std::sin(th))) <= 1e-14);
            // with velocity and acceleration: no velocity-product torque for one dof
            VectorXd a(1);
            a << 1.3;
            CHECK(W("rnea = (I + m L^2) a + m g L sin",
                    rel(fs::rnea(m, q, v, a)[0], Ipiv * a[0] + p.m * g * p.L * std::sin(th))) <= 1e-14);
            // free swing: θ̈ = −m g L sin θ / (I + m L²)
            CHECK(W("aba free swing", rel(fs::aba(m, q, v, z)[0], -p.m * g * p.L * std::sin(th) / Ipiv)) <= 1e-14);
            VectorXd tau(1);
            tau << 2.5;
            CHECK(W("aba with torque", rel(fs::aba(m, q, v, tau)[0], (tau[0] - p.m * g * p.L * std::sin(th)) / Ipiv)) <= 1e-14);
        }
    }
}

TEST_CASE("featherstone reference: external forces", "[featherstone]") {
    worst W("external forces");
    // the pendulum at θ = 0 pushed horizontally (+x, world) at its com by F: the push swings it
    // towards negative θ (the com's x is −L sin θ), so holding it takes τ = +L F
    {
        const pendulum p = make_pendulum(0);
        const double F = 3.0;
        VectorXd z = VectorXd::Zero(1);
        std::vector<vec6> f(1);
        const vec3 force(F, 0, 0), at = p.model[0].com;   // θ = 0: body coordinates = world coordinates
        f[0] << at.cross(force), force;
        CHECK(W("pushed pendulum holding torque", rel(fs::rnea(p.model, z, z, z, f)[0], p.L * F)) <= 1e-14);
        CHECK(W("pushed pendulum, free: aba", rel(fs::aba(p.model, z, z, z, f)[0],
                                                  -p.L * F / (p.I_axis + p.m * p.L * p.L))) <= 1e-14);
    }
    std::mt19937_64 rng(9);
    fs::random_tree_options opt;
    for (int k = 0; k < 150; ++k) {
        opt.floating_children = k % 2 == 0;
        const fs::model m = fs::random_tree(rng, opt);
        const VectorXd q = fs::random_q(rng, m);
        const VectorXd v = fs::random_vector(rng, m.nv());
        const VectorXd a = fs::random_vector(rng, m.nv());
        const std::vector<vec6> f = fs::random_forces(rng, m, 3.0);
        // τ = rnea without − Σ J_iᵀ f_i (f_i acting on body i, body coordinates)
        VectorXd expect = fs::rnea(m, q, v, a);
        for (int i = 0; i < m.size(); ++i) expect -= mul(fs::jacobian_body(m, q, i).transpose(), f[static_cast<std::size_t>(i)]);
        CHECK(W("rnea(f) vs rnea - sum J^T f", rel(fs::rnea(m, q, v, a, f), expect)) <= 1e-12);
        // forces that cancel gravity on every body (m_i g upwards at the com) = no gravity
        const fs::kinematics K = fs::fk(m, q, v, a);
        std::vector<vec6> anti(static_cast<std::size_t>(m.size()));
        for (int i = 0; i < m.size(); ++i) {
            const vec3 up = -m[i].mass * (K[i].rotation.transpose() * m.gravity);
            anti[static_cast<std::size_t>(i)] << m[i].com.cross(up), up;
        }
        fs::model m0 = m;
        m0.gravity.setZero();
        CHECK(W("antigravity forces = gravity off (rnea)", rel(fs::rnea(m, q, v, a, anti), fs::rnea(m0, q, v, a))) <= 1e-12);
        const VectorXd tau = fs::random_vector(rng, m.nv());
        CHECK(W("antigravity forces = gravity off (aba)", rel(fs::aba(m, q, v, tau, anti), fs::aba(m0, q, v, tau))) <= 1e-10);
    }
}

TEST_CASE("featherstone reference: power balance", "[featherstone]") {
    std::mt19937_64 rng(10);
    worst W("power balance");
    fs::random_tree_options opt;
    opt.max_bodies = 12;
    for (int k = 0; k < 40; ++k) {
        opt.floating_base_probability = k % 2 == 0 ? 0.0 : 0.5;
        const fs::model m = fs::random_tree(rng, opt);
        const int n = m.nv();
        VectorXd q = fs::random_q(rng, m);
        VectorXd v = fs::random_vector(rng, n);
        const VectorXd tau = fs::random_vector(rng, n, 2.0);

        // pointwise: d/dt (T + V) = vᵀ τ at t = 0, by central differences along (q + t q̇, v + t q̈)
        {
            const VectorXd qdd = fs::aba(m, q, v, tau);
            const double h = 1e-5;
            const double dE = (energy(m, advance(m, q, v, h), v + h * qdd) -
                               energy(m, advance(m, q, v, -h), v - h * qdd)) / (2 * h);
            const double scale = std::max(1.0, v.cwiseAbs().dot(tau.cwiseAbs()) + std::abs(dE));
            CHECK(W("dE/dt vs v.tau at a point (FD)", std::abs(dE - v.dot(tau)) / scale) <= 1e-6);
        }
        // along a trajectory: E(T) − E(0) = ∫ vᵀ τ dt, both integrated with RK4 (step 1e-3, 200 steps)
        {
            const double dt = 1e-3;
            const int steps = 200;
            double work = 0;
            const double E0 = energy(m, q, v);
            auto deriv = [&](const VectorXd& qq, const VectorXd& vv, VectorXd& dq, VectorXd& dv, double& dw) {
                dq = fs::q_dot(m, qq, vv);
                dv = fs::aba(m, qq, vv, tau);
                dw = vv.dot(tau);
            };
            for (int s = 0; s < steps; ++s) {
                VectorXd k1q, k1v, k2q, k2v, k3q, k3v, k4q, k4v;
                double k1w, k2w, k3w, k4w;
                deriv(q, v, k1q, k1v, k1w);
                deriv(q + 0.5 * dt * k1q, v + 0.5 * dt * k1v, k2q, k2v, k2w);
                deriv(q + 0.5 * dt * k2q, v + 0.5 * dt * k2v, k3q, k3v, k3w);
                deriv(q + dt * k3q, v + dt * k3v, k4q, k4v, k4w);
                q += dt / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
                v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
                work += dt / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
            }
            const double E1 = energy(m, q, v);
            const double scale = std::max({1.0, std::abs(E0), std::abs(E1), std::abs(work)});
            CHECK(W("E(T) - E(0) vs work (RK4 trajectory)", std::abs(E1 - E0 - work) / scale) <= 1e-6);
        }
    }
}

TEST_CASE("featherstone reference: model bookkeeping", "[featherstone]") {
    fs::model m;
    fs::body b;
    b.kind = fs::joint_kind::floating;
    m.bodies.push_back(b);            // q 0..6, v 0..5
    b.parent = 0;
    b.kind = fs::joint_kind::fixed;
    m.bodies.push_back(b);            // none
    b.kind = fs::joint_kind::revolute;
    m.bodies.push_back(b);            // q 7, v 6
    b.parent = 1;
    b.kind = fs::joint_kind::prismatic;
    m.bodies.push_back(b);            // q 8, v 7
    CHECK(m.nq() == 9);
    CHECK(m.nv() == 8);
    CHECK(m.q_index(2) == 7);
    CHECK(m.v_index(2) == 6);
    CHECK(m.q_index(3) == 8);
    CHECK(m.v_index(3) == 7);
    VectorXd q = VectorXd::Zero(9);
    q[3] = 1;
    CHECK_THROWS(fs::rnea(m, VectorXd::Zero(8), VectorXd::Zero(8), VectorXd::Zero(8)));
    CHECK_THROWS(fs::rnea(m, q, VectorXd::Zero(9), VectorXd::Zero(8)));
    CHECK_THROWS(fs::rnea(m, q, VectorXd::Zero(8), VectorXd::Zero(8), std::vector<vec6>(3)));
    CHECK_NOTHROW(fs::rnea(m, q, VectorXd::Zero(8), VectorXd::Zero(8), std::vector<vec6>(4, vec6::Zero())));
    // the Jacobian of body 3 has no columns for body 2's joint (not an ancestor)
    const MatrixXd J = fs::jacobian_body(m, q, 3);
    CHECK(J.col(6).isZero());
    CHECK(!J.col(7).isZero());
}
