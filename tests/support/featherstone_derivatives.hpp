// Derivatives of inverse and forward dynamics of the Featherstone reference
// (support/featherstone.hpp): RNEA's ∂τ/∂q, ∂τ/∂v and ABA's ∂q̈/∂q, ∂q̈/∂v, ∂q̈/∂τ, computed by
// running the reference's own rnea / aba on forward-mode dual numbers (support/dual.hpp through
// support/dual_eigen.hpp). Exact up to rounding (no step size); tests only, independent of ctga.
//
//   rnea_partials rnea_derivatives(m, q, v, a, f_ext = {})   dtau_dq, dtau_dv (nv × nv), tau
//   aba_partials  aba_derivatives(m, q, v, tau, f_ext = {})  dqdd_dq, dqdd_dv, dqdd_dtau (nv × nv), qdd
//
// (all conventions, f_ext and gravity included, are those of support/featherstone.hpp; f_ext is a
// constant: no derivatives with respect to it). tau / qdd are the values of the dual evaluation;
// they agree with fs::rnea / fs::aba to rounding (the self-test measures how closely).
//
// Derivatives with respect to the configuration are taken in the TANGENT SPACE: nv columns, one
// per velocity coordinate, column t = d/dε f(q ⊕ ε e_t) at ε = 0, where
//   revolute / prismatic joint: q ⊕ δ = q + δ (the plain ∂/∂q_k);
//   floating joint, q = (p, Q) = (x, y, z, qw, qx, qy, qz) (origin p and unit quaternion Q that
//     rotates body coordinates into joint-frame coordinates), δ = (ω, v) ∈ R⁶ (angular first,
//     body coordinates, like the joint's velocity coordinates): q ⊕ δ is the body pose moved by
//     the body-frame twist δ, T(q ⊕ δ) = T(q) · exp(δ) (right multiplication, exp of SE(3)).
//     To first order, which is all a derivative sees: Q' = Q ⊗ (1, ½ω), p' = p + R(Q) v.
// Equivalently dq/dε along e_t is fs::q_dot(m, q, e_t), which is how q is seeded: the tangent
// space is the joint's velocity space, so ∂q̈/∂q in these coordinates pairs with v directly.
//
// Evaluation: the nv (q) + nv (v) [+ nv (τ)] input directions are stacked and seeded CHUNK at a
// time on dual<CHUNK>: ⌈2 nv / CHUNK⌉ (RNEA) or ⌈3 nv / CHUNK⌉ (ABA) dual evaluations. A small
// fixed CHUNK keeps one instantiation of rnea / aba on duals (a short compile) for every nv.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "support/dual.hpp"
#include "support/dual_eigen.hpp"
#include "support/featherstone.hpp"

namespace ctga::test::featherstone {

struct rnea_partials {
    Eigen::MatrixXd dtau_dq, dtau_dv;   // nv × nv; dtau_dq in tangent coordinates (above)
    Eigen::VectorXd tau;
};

struct aba_partials {
    Eigen::MatrixXd dqdd_dq, dqdd_dv, dqdd_dtau;   // nv × nv; dqdd_dq in tangent coordinates
    Eigen::VectorXd qdd;
};

namespace derivatives_detail {

inline constexpr int chunk = 8;   // partials per dual evaluation
using dual = ctga_test::dual<static_cast<std::size_t>(chunk), double>;
using vecD = vecX_t<dual>;

// The stacked input directions: column c of block b (b = 0 the configuration's tangent space,
// b = 1, 2 the v-sized inputs) is stacked column b nv + c. An evaluation seeds the stacked
// columns [c0, c0 + chunk): partial k is column c0 + k.

// q with partial k = dq along tangent direction c0 + k (if it is one): fs::q_dot(m, q, e_t)
inline vecD seed_q(const model& m, const Eigen::VectorXd& q, int c0) {
    vecD x = q.cast<dual>();
    const int nv = m.nv();
    for (int k = 0; k < chunk && c0 + k < nv; ++k) {
        const Eigen::VectorXd dq = q_dot(m, q, Eigen::VectorXd::Unit(nv, c0 + k));
        for (Eigen::Index i = 0; i < x.size(); ++i) x[i].d[static_cast<std::size_t>(k)] = dq[i];
    }
    return x;
}

// the v-sized input x of block b: partial k = ∂/∂x_i where b nv + i = c0 + k
inline vecD seed(const Eigen::VectorXd& x, int b, int c0) {
    vecD r = x.cast<dual>();
    const auto nv = static_cast<int>(x.size());
    for (int i = 0; i < nv; ++i) {
        const int k = b * nv + i - c0;
        if (k >= 0 && k < chunk) r[i].d[static_cast<std::size_t>(k)] = 1;
    }
    return r;
}

// the partials of y into the stacked columns [c0, c0 + chunk) of the blocks (nv × nv each)
inline void store(const vecD& y, int c0, std::initializer_list<Eigen::MatrixXd*> blocks) {
    const auto nv = static_cast<int>(y.size());
    for (int k = 0; k < chunk; ++k) {
        const int col = c0 + k;
        if (col >= nv * static_cast<int>(blocks.size())) break;
        Eigen::MatrixXd& M = *blocks.begin()[col / nv];
        for (int i = 0; i < nv; ++i) M(i, col % nv) = y[i].d[static_cast<std::size_t>(k)];
    }
}

inline Eigen::VectorXd values(const vecD& y) {
    Eigen::VectorXd r(y.size());
    for (Eigen::Index i = 0; i < y.size(); ++i) r[i] = y[i].v;
    return r;
}

}  // namespace derivatives_detail

inline rnea_partials rnea_derivatives(const model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                      const Eigen::VectorXd& a, const std::vector<vec6>& f_ext = {}) {
    namespace d = derivatives_detail;
    check_sizes(m, q, &v, &f_ext);
    if (a.size() != m.nv()) throw std::invalid_argument("featherstone: a has the wrong size");
    const int nv = m.nv();
    rnea_partials r;
    r.dtau_dq.resize(nv, nv);
    r.dtau_dv.resize(nv, nv);
    r.tau.resize(nv);
    const d::vecD aD = a.cast<d::dual>();
    for (int c0 = 0; c0 < 2 * nv; c0 += d::chunk) {
        const d::vecD tau = rnea<d::dual>(m, d::seed_q(m, q, c0), d::seed(v, 1, c0), aD, f_ext);
        d::store(tau, c0, {&r.dtau_dq, &r.dtau_dv});
        if (c0 == 0) r.tau = d::values(tau);
    }
    return r;
}

inline aba_partials aba_derivatives(const model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                    const Eigen::VectorXd& tau, const std::vector<vec6>& f_ext = {}) {
    namespace d = derivatives_detail;
    check_sizes(m, q, &v, &f_ext);
    if (tau.size() != m.nv()) throw std::invalid_argument("featherstone: tau has the wrong size");
    const int nv = m.nv();
    aba_partials r;
    r.dqdd_dq.resize(nv, nv);
    r.dqdd_dv.resize(nv, nv);
    r.dqdd_dtau.resize(nv, nv);
    r.qdd.resize(nv);
    for (int c0 = 0; c0 < 3 * nv; c0 += d::chunk) {
        const d::vecD qdd = aba<d::dual>(m, d::seed_q(m, q, c0), d::seed(v, 1, c0), d::seed(tau, 2, c0), f_ext);
        d::store(qdd, c0, {&r.dqdd_dq, &r.dqdd_dv, &r.dqdd_dtau});
        if (c0 == 0) r.qdd = d::values(qdd);
    }
    return r;
}

}  // namespace ctga::test::featherstone
