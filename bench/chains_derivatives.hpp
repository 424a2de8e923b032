// ctga_chains_bench's derivative kernels (issue 28): ∂τ/∂q and ∂τ/∂q̇ of a tree three ways,
// registered as rnea_derivatives_<tree>/<implementation>:
//   ctga   chains::rnea_derivatives (chains/rnea_derivatives.hpp), analytical; also gives H
//   dual   the same RNEA on forward-mode dual numbers of nv partials (tests/support/dual.hpp), one
//          pass seeded in q (a floating joint's motor as g (1 + δ/2)), one in q̇
//   fd     central differences of RNEA in double, step h = 1e-6 (the floating joint's motor moved
//          by g exp(±h e_k)): 4 nv calls
// Each entry's counter max_error is the largest |D − D_ref| / max|D_ref| over ∂τ/∂q and ∂τ/∂q̇ on
// 8 of the states, D_ref from dual numbers in long double.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <ctga/chains/rnea_derivatives.hpp>

#include "chains_kernels.hpp"
#include "support/dual.hpp"
#include "support/model_cast.hpp"

namespace bench::chains {

enum class differentiation { ctga, dual, fd };

template <class Tree>
using partials_of = std::array<std::array<std::array<double, Tree::nv>, Tree::nv>, 2>;  // ∂τ/∂q, ∂τ/∂q̇

// q moved by δ in the tangent space: revolute/prismatic q + δ, a floating motor g · e(δ), e = exp
// (or 1 + δ/2 to first order, for dual numbers).
template <class Tree, class S, class Exp>
ch::configuration<Tree, S> moved(const ch::configuration<Tree, S>& q, const std::array<S, Tree::nv>& delta, Exp exp_of) {
    ch::configuration<Tree, S> out = q;
    [&]<std::size_t... B>(std::index_sequence<B...>) {
        ([&] {
            constexpr std::size_t qo = Tree::q_offset[B], vo = Tree::v_offset[B];
            if constexpr (Tree::nq_of[B] == 1) out[qo] = q[qo] + delta[vo];
            if constexpr (Tree::nq_of[B] == 8) {
                const ctga::motor<S> g{q[qo], q[qo + 1], q[qo + 2], q[qo + 3], q[qo + 4], q[qo + 5], q[qo + 6], q[qo + 7]};
                const ctga::motor<S> ge =
                    g * exp_of(ctga::screw<S>{delta[vo], delta[vo + 1], delta[vo + 2], delta[vo + 3], delta[vo + 4], delta[vo + 5]});
                for (std::size_t k = 0; k < 8; ++k) out[qo + k] = ge[k];
            }
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    return out;
}
template <class S>
ctga::motor<S> first_order_exp(const ctga::screw<S>& z) {
    const S h(0.5);
    return {S(1.0), z[0] * h, z[1] * h, z[2] * h, S(0.0), z[3] * h, z[4] * h, z[5] * h};
}

// ∂τ/∂q, ∂τ/∂q̇ by dual numbers of scalar R through rnea on md.
template <class Tree, class D>
auto dual_partials(const ch::model<Tree, D>& md, const state<Tree>& s) {
    using R = decltype(ctga_test::value(D{}));
    std::array<std::array<std::array<R, Tree::nv>, Tree::nv>, 2> out;
    ch::configuration<Tree, D> q;
    ch::joint_vector<Tree, D> qd, qdd;
    for (std::size_t k = 0; k < Tree::nq; ++k) q[k] = D(R(s.q[k]));
    for (std::size_t k = 0; k < Tree::nv; ++k) qd[k] = D(R(s.qd[k])), qdd[k] = D(R(s.qdd[k]));
    std::array<D, Tree::nv> delta;
    for (std::size_t k = 0; k < Tree::nv; ++k) delta[k] = D::variable(R(0), k);
    const auto tq = ch::rnea(md, moved<Tree>(q, delta, first_order_exp<D>), qd, qdd);
    for (std::size_t k = 0; k < Tree::nv; ++k) qd[k] = D::variable(R(s.qd[k]), k);
    for (std::size_t k = 0; k < Tree::nq; ++k) q[k] = D(R(s.q[k]));
    const auto tv = ch::rnea(md, q, qd, qdd);
    for (std::size_t i = 0; i < Tree::nv; ++i)
        for (std::size_t j = 0; j < Tree::nv; ++j)
            out[0][i][j] = ctga_test::derivative(tq[i], j), out[1][i][j] = ctga_test::derivative(tv[i], j);
    return out;
}

template <class Tree>
partials_of<Tree> fd_partials(const ch::model<Tree>& m, const state<Tree>& s) {
    constexpr double h = 1e-6;
    partials_of<Tree> out;
    for (std::size_t j = 0; j < Tree::nv; ++j) {
        std::array<double, Tree::nv> dp{}, dm{};
        dp[j] = h, dm[j] = -h;
        const auto exp_of = [](const ctga::screw<double>& z) { return ctga::exp(z); };
        const auto tp = ch::rnea(m, moved<Tree>(s.q, dp, exp_of), s.qd, s.qdd);
        const auto tm = ch::rnea(m, moved<Tree>(s.q, dm, exp_of), s.qd, s.qdd);
        auto vp = s.qd, vm = s.qd;
        vp[j] += h, vm[j] -= h;
        const auto up = ch::rnea(m, s.q, vp, s.qdd), um = ch::rnea(m, s.q, vm, s.qdd);
        for (std::size_t i = 0; i < Tree::nv; ++i)
            out[0][i][j] = (tp[i] - tm[i]) / (2 * h), out[1][i][j] = (up[i] - um[i]) / (2 * h);
    }
    return out;
}

template <class Tree>
struct derivative_fixture {
    fixture<Tree> f;
    ch::model<Tree, ctga_test::dual<Tree::nv>> md = ctga_test::model_cast<ctga_test::dual<Tree::nv>>(f.m);
};

template <differentiation I, class Tree>
[[gnu::noinline]] auto derivative_kernel(const derivative_fixture<Tree>& d, const state<Tree>& s) {
    if constexpr (I == differentiation::ctga) return ch::rnea_derivatives(d.f.m, s.q, s.qd, s.qdd);
    else if constexpr (I == differentiation::dual) return dual_partials(d.md, s);
    else return fd_partials(d.f.m, s);
}

// max |D − D_ref| / max |D_ref| over 8 states, D_ref by long-double duals
template <differentiation I, class Tree>
double derivative_error(const derivative_fixture<Tree>& d) {
    using L = ctga_test::dual<Tree::nv, long double>;
    const auto ml = ctga_test::model_cast<L>(d.f.m);
    double worst = 0;
    for (std::size_t k = 0; k < 8; ++k) {
        const auto ref = dual_partials(ml, d.f.states[k]);
        const auto r = derivative_kernel<I>(d, d.f.states[k]);
        for (std::size_t w = 0; w < 2; ++w) {
            long double scale = 0, err = 0;
            for (std::size_t i = 0; i < Tree::nv; ++i)
                for (std::size_t j = 0; j < Tree::nv; ++j) {
                    const double x = [&] {
                        if constexpr (I == differentiation::ctga) return w == 0 ? r.dtau_dq(i, j) : r.dtau_dv(i, j);
                        else return r[w][i][j];
                    }();
                    scale = std::max(scale, std::abs(ref[w][i][j]));
                    err = std::max(err, std::abs(static_cast<long double>(x) - ref[w][i][j]));
                }
            worst = std::max(worst, static_cast<double>(err / scale));
        }
    }
    return worst;
}

template <differentiation I, class Tree>
void add_derivative(std::vector<entry>& table, const std::string& name, const derivative_fixture<Tree>& d) {
    const derivative_fixture<Tree>* p = &d;
    const double error = derivative_error<I>(d);
    table.push_back({name,
                     [p, error](benchmark::State& st) {
                         std::size_t k = 0;
                         for (auto _ : st) {
                             auto r = derivative_kernel<I>(*p, p->f.states[k]);
                             benchmark::DoNotOptimize(r);
                             k = (k + 1) & 63;
                         }
                         st.counters["max_error"] = error;
                     },
                     [p](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) {
                             auto r = derivative_kernel<I>(*p, p->f.states[i & 63]);
                             benchmark::DoNotOptimize(r);
                         }
                     }});
}

// rnea_derivatives_<label>/ctga, /dual, /fd
template <class Tree>
void add_derivatives(std::vector<entry>& table, const std::string& label, const derivative_fixture<Tree>& d) {
    add_derivative<differentiation::ctga>(table, "rnea_derivatives_" + label + "/ctga", d);
    add_derivative<differentiation::dual>(table, "rnea_derivatives_" + label + "/dual", d);
    add_derivative<differentiation::fd>(table, "rnea_derivatives_" + label + "/fd", d);
}

void add_derivatives_arm7(std::vector<entry>& table);
void add_derivatives_chain30(std::vector<entry>& table);
void add_derivatives_legged(std::vector<entry>& table);

}  // namespace bench::chains
