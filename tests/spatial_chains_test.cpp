// The benchmarks' hand-written spatial kinematic-tree algorithms (bench/spatial_chains.hpp: FK,
// RNEA, CRBA, ABA on plain 6D structs, the competitor of ctga::chains) against the independent
// Featherstone reference in Eigen (support/featherstone.hpp), on random trees
// (support/random_tree.hpp) of 1, 2, 5, 12 and 30 bodies with every joint type (revolute and
// prismatic about x, y, z and about run-time axes, fixed, floating) and floating bases.
//
// The reference's joints are revolute / prismatic about an arbitrary axis, fixed and floating
// (q = (x, y, z, qw, qx, qy, qz), the same layout as ours); a revolute or prismatic joint is
// given here at random either our *_axis kind with the same axis, or one of the kinds about x, y,
// z, its axis in the reference model being then replaced by that unit vector.
//
// Error measure: rel(x, y) = max_k |x_k − y_k| / max(1, max_k |y_k|) (y the reference), ≤ 1e-12.
// FK, RNEA and CRBA agree to a few 1e-15. ABA's q̈ = H⁻¹ (τ − C) is as accurate as H's condition
// number allows: the trees drawn here (light bodies far out, floating joints anywhere) reach
// cond(H) ~ 1e5, and both implementations then differ from a long-double solve by up to ~1e-12
// (this one mostly less than the reference); with this seed the worst ABA difference is ~1e-13.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "../bench/spatial_chains.hpp"
#include "support/catch.hpp"
#include "support/relative_error.hpp"
#include "support/featherstone.hpp"
#include "support/random_tree.hpp"

namespace {

namespace fs = ctga::test::featherstone;
namespace sc = spatial::chains;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using ctga::test::rel;

constexpr std::size_t capacity = 32;
using model_t = sc::model<capacity>;
constexpr double tolerance = 1e-12;

fs::vec3 to_eigen(spatial::vec3 v) { return {v.x, v.y, v.z}; }
spatial::vec3 to_spatial(const fs::vec3& v) { return {v.x(), v.y(), v.z()}; }
fs::mat3 to_eigen(const spatial::mat3& R) {
    fs::mat3 M;
    M << R.r0.x, R.r0.y, R.r0.z, R.r1.x, R.r1.y, R.r1.z, R.r2.x, R.r2.y, R.r2.z;
    return M;
}
spatial::mat3 to_spatial(const fs::mat3& M) {
    return {{M(0, 0), M(0, 1), M(0, 2)}, {M(1, 0), M(1, 1), M(1, 2)}, {M(2, 0), M(2, 1), M(2, 2)}};
}
fs::vec6 to_eigen(const spatial::motion& m) {
    fs::vec6 x;
    x << m.w.x, m.w.y, m.w.z, m.v.x, m.v.y, m.v.z;
    return x;
}
spatial::force to_force(const fs::vec6& x) { return {{x[0], x[1], x[2]}, {x[3], x[4], x[5]}}; }

// Our model for the reference's; revolute / prismatic joints get (at random) a kind about x, y, z
// — then the reference's axis is set to that unit vector — or the *_axis kind.
model_t convert(fs::model& ref, std::mt19937_64& rng, int& kinds_seen) {
    model_t m{};
    m.n = static_cast<std::size_t>(ref.size());
    m.gravity = to_spatial(ref.gravity);
    for (int i = 0; i < ref.size(); ++i) {
        fs::body& b = ref.bodies[static_cast<std::size_t>(i)];
        sc::body& o = m.bodies[static_cast<std::size_t>(i)];
        const int pick = fs::uniform_int(rng, 0, 3);   // 0–2: about x, y, z; 3: run-time axis
        if (b.kind == fs::joint_kind::revolute || b.kind == fs::joint_kind::prismatic) {
            const bool rev = b.kind == fs::joint_kind::revolute;
            if (pick < 3) {
                b.axis = fs::vec3::Unit(pick);
                o.kind = static_cast<sc::joint_kind>((rev ? 0 : 3) + pick);
            } else {
                o.kind = rev ? sc::joint_kind::revolute_axis : sc::joint_kind::prismatic_axis;
            }
        } else {
            o.kind = b.kind == fs::joint_kind::fixed ? sc::joint_kind::fixed : sc::joint_kind::floating;
        }
        kinds_seen |= 1 << static_cast<int>(o.kind);
        o.parent = b.parent;
        o.axis = to_spatial(b.axis);
        o.R = to_spatial(b.rotation);
        o.t = to_spatial(b.translation);
        const fs::mat3& I = b.inertia_c;
        o.I = {b.mass, to_spatial(b.com), {I(0, 0), I(0, 1), I(1, 1), I(0, 2), I(1, 2), I(2, 2)}};
    }
    sc::finalize(m);
    return m;
}

struct worst {
    double fk = 0, rnea = 0, rnea_ext = 0, crba = 0, aba = 0, aba_ext = 0;
};

void check_tree(fs::model ref, std::mt19937_64& rng, worst& w, int& kinds_seen) {
    const model_t m = convert(ref, rng, kinds_seen);
    REQUIRE(static_cast<int>(m.nq) == ref.nq());
    REQUIRE(static_cast<int>(m.nv) == ref.nv());
    const int nv = ref.nv();
    for (int state = 0; state < 3; ++state) {
        const VectorXd q = fs::random_q(rng, ref);
        const VectorXd qd = fs::random_vector(rng, nv, 2.0);
        const VectorXd qdd = fs::random_vector(rng, nv, 2.0);
        const VectorXd tau_in = fs::random_vector(rng, nv, 5.0);
        const std::vector<fs::vec6> fx = fs::random_forces(rng, ref, 3.0);
        std::array<spatial::force, capacity> f_ext{};
        for (std::size_t i = 0; i < fx.size(); ++i) f_ext[i] = to_force(fx[i]);

        // FK
        const fs::kinematics K = fs::fk(ref, q, qd, qdd);
        sc::kinematics<capacity> k;
        sc::fk(m, q.data(), qd.data(), qdd.data(), k);
        std::array<spatial::se3, capacity> poses;
        sc::fk(m, q.data(), poses);
        for (int i = 0; i < ref.size(); ++i) {
            const auto s = static_cast<std::size_t>(i);
            const double e = std::max({rel(to_eigen(k.pose[s].R), K[i].rotation), rel(to_eigen(k.pose[s].t), K[i].origin),
                                       rel(to_eigen(poses[s].R), K[i].rotation), rel(to_eigen(poses[s].t), K[i].origin),
                                       rel(to_eigen(k.v[s]), K[i].velocity), rel(to_eigen(k.a[s]), K[i].acceleration)});
            w.fk = std::max(w.fk, e);
            CHECK(e <= tolerance);
        }

        // RNEA, without and with external forces
        VectorXd tau(nv);
        sc::rnea(m, q.data(), qd.data(), qdd.data(), nullptr, tau.data());
        double e = rel(tau, fs::rnea(ref, q, qd, qdd));
        w.rnea = std::max(w.rnea, e);
        CHECK(e <= tolerance);
        sc::rnea(m, q.data(), qd.data(), qdd.data(), f_ext.data(), tau.data());
        e = rel(tau, fs::rnea(ref, q, qd, qdd, fx));
        w.rnea_ext = std::max(w.rnea_ext, e);
        CHECK(e <= tolerance);

        // CRBA: both triangles
        MatrixXd H(nv, nv);
        H.setConstant(1e300);
        using row_major = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
        row_major Hr(nv, nv);
        Hr.setConstant(1e300);
        sc::crba(m, q.data(), Hr.data());
        H = Hr;
        e = rel(H, fs::crba(ref, q));
        w.crba = std::max(w.crba, e);
        CHECK(e <= tolerance);

        // ABA, without and with external forces
        VectorXd a(nv);
        sc::aba(m, q.data(), qd.data(), tau_in.data(), nullptr, a.data());
        e = rel(a, fs::aba(ref, q, qd, tau_in));
        w.aba = std::max(w.aba, e);
        CHECK(e <= tolerance);
        sc::aba(m, q.data(), qd.data(), tau_in.data(), f_ext.data(), a.data());
        e = rel(a, fs::aba(ref, q, qd, tau_in, fx));
        w.aba_ext = std::max(w.aba_ext, e);
        CHECK(e <= tolerance);
    }
}

}  // namespace

TEST_CASE("spatial_chains: FK, RNEA, CRBA, ABA against the Featherstone reference", "[spatial_chains]") {
    std::mt19937_64 rng(20240611);
    worst w;
    int kinds_seen = 0;
    for (const int size : {1, 2, 5, 12, 30}) {
        for (int variant = 0; variant < 3; ++variant) {
            fs::random_tree_options opt;
            opt.min_bodies = opt.max_bodies = size;
            // 0: fixed or floating base at random; 1: floating base; 2: floating joints anywhere
            opt.floating_base_probability = variant == 0 ? 0.3 : 1.0;
            opt.floating_children = variant == 2;
            const int trees = size <= 2 ? 12 : size <= 12 ? 8 : 4;
            for (int t = 0; t < trees; ++t) {
                INFO("size " << size << ", variant " << variant << ", tree " << t);
                check_tree(fs::random_tree(rng, opt), rng, w, kinds_seen);
            }
        }
    }
    std::printf("spatial_chains worst rel. errors: fk %.2e rnea %.2e rnea+f_ext %.2e crba %.2e aba %.2e aba+f_ext %.2e\n",
                w.fk, w.rnea, w.rnea_ext, w.crba, w.aba, w.aba_ext);
    CHECK(kinds_seen == (1 << 10) - 1);   // every joint type was exercised
}

TEST_CASE("spatial_chains: a pendulum and a free body by hand", "[spatial_chains]") {
    // a point-like mass on a massless rod of length l about z... (a revolute_x joint, gravity −z)
    sc::model<2> m{};
    const double l = 0.7, mass = 2.0;
    m.n = 1;
    m.gravity = {0, 0, -9.81};
    m.bodies[0] = {-1, sc::joint_kind::revolute_x, {1, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0},
                   {mass, {0, 0, -l}, {0, 0, 0, 0, 0, 0}}};
    sc::finalize(m);
    const double q = 0.4, qd = 0.3;
    double tau = 0, qdd = 0, H = 0;
    const double zero = 0;
    sc::rnea(m, &q, &qd, &zero, nullptr, &tau);
    CHECK(tau == Approx(mass * 9.81 * l * std::sin(q)));   // holding torque
    sc::crba(m, &q, &H);
    CHECK(H == Approx(mass * l * l));
    sc::aba(m, &q, &qd, &zero, nullptr, &qdd);
    CHECK(qdd == Approx(-9.81 / l * std::sin(q)));

    // a free body at rest falls with −g
    sc::model<1> f{};
    f.n = 1;
    f.gravity = {0, 0, -9.81};
    f.bodies[0] = {-1, sc::joint_kind::floating, {0, 0, 1}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0},
                   {1.5, {0.1, 0.2, 0.3}, {0.1, 0.01, 0.2, 0.02, 0.03, 0.3}}};
    sc::finalize(f);
    const double qf[7] = {0, 0, 0, 1, 0, 0, 0}, v0[6] = {}, t0[6] = {};
    double a[6];
    sc::aba(f, qf, v0, t0, nullptr, a);
    for (int k = 0; k < 5; ++k) CHECK(std::abs(a[k]) < 1e-12);
    CHECK(a[5] == Approx(-9.81));
}
