// ctga_chains_bench's derivative kernels (issue 28): the partials of inverse dynamics (∂τ/∂q,
// ∂τ/∂q̇) and of forward dynamics (∂q̈/∂q, ∂q̈/∂q̇, ∂q̈/∂τ) three ways, and H⁻¹, registered as
// rnea_derivatives_<tree>/<implementation>, aba_derivatives_<tree>/…, minverse_<tree>/ctga:
//   ctga   chains::rnea_derivatives, aba_derivatives, minverse: analytical (rnea's also gives H)
//   dual   the same RNEA / ABA on forward-mode dual numbers of nv partials (tests/support/dual.hpp),
//          one pass seeded in q (a floating joint's motor as g (1 + δ/2)), one in q̇ (and in τ)
//   fd     central differences of RNEA / ABA in double, step h = 1e-6 (the floating joint's motor
//          moved by g exp(±h e_k)): 4 nv calls (6 nv for ABA)
// Each entry's counter max_error is the largest |D − D_ref| / max|D_ref| over its matrices on 8
// of the states, D_ref from dual numbers in long double.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ctga/chains/aba_derivatives.hpp>
#include <ctga/chains/minverse.hpp>
#include <ctga/chains/rnea_derivatives.hpp>

#include "chains_kernels.hpp"
#include "support/dual.hpp"
#include <ctga/chains/model_cast.hpp>

namespace bench::chains {

enum class differentiation { ctga, dual, fd };

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

enum class dynamics { inverse, forward, inverse_mass };

// The partials by dual numbers (scalar R) through rnea or aba on md: with respect to q, q̇ and,
// for aba, τ.
template <dynamics A, class Tree, class D>
auto dual_partials(const ch::model<Tree, D>& md, const state<Tree>& s) {
    using R = decltype(ctga_test::value(D{}));
    constexpr std::size_t K = A == dynamics::inverse ? 2 : 3;
    std::array<std::array<std::array<R, Tree::nv>, Tree::nv>, K> out;
    const auto& x0 = A == dynamics::inverse ? s.qdd : s.tau;
    for (std::size_t w = 0; w < K; ++w) {
        ch::configuration<Tree, D> q;
        ch::joint_vector<Tree, D> qd, x;
        std::array<D, Tree::nv> delta;
        for (std::size_t k = 0; k < Tree::nq; ++k) q[k] = D(R(s.q[k]));
        for (std::size_t k = 0; k < Tree::nv; ++k) {
            qd[k] = w == 1 ? D::variable(R(s.qd[k]), k) : D(R(s.qd[k]));
            x[k] = w == 2 ? D::variable(R(x0[k]), k) : D(R(x0[k]));
            delta[k] = w == 0 ? D::variable(R(0), k) : D(R(0));
        }
        if (w == 0) q = moved<Tree>(q, delta, first_order_exp<D>);
        const auto y = A == dynamics::inverse ? ch::rnea(md, q, qd, x) : ch::aba(md, q, qd, x);
        for (std::size_t i = 0; i < Tree::nv; ++i)
            for (std::size_t j = 0; j < Tree::nv; ++j) out[w][i][j] = ctga_test::derivative(y[i], j);
    }
    return out;
}

template <dynamics A, class Tree>
auto fd_partials(const ch::model<Tree>& m, const state<Tree>& s) {
    constexpr double h = 1e-6;
    constexpr std::size_t K = A == dynamics::inverse ? 2 : 3;
    std::array<std::array<std::array<double, Tree::nv>, Tree::nv>, K> out;
    const auto& x0 = A == dynamics::inverse ? s.qdd : s.tau;
    const auto run = [&](const ch::configuration<Tree>& q, const ch::joint_vector<Tree>& qd, const ch::joint_vector<Tree>& x) {
        return A == dynamics::inverse ? ch::rnea(m, q, qd, x) : ch::aba(m, q, qd, x);
    };
    const auto exp_of = [](const ctga::screw<double>& z) { return ctga::exp(z); };
    for (std::size_t j = 0; j < Tree::nv; ++j) {
        std::array<double, Tree::nv> dp{}, dm{};
        dp[j] = h, dm[j] = -h;
        const auto tp = run(moved<Tree>(s.q, dp, exp_of), s.qd, x0), tm = run(moved<Tree>(s.q, dm, exp_of), s.qd, x0);
        auto vp = s.qd, vm = s.qd;
        vp[j] += h, vm[j] -= h;
        const auto up = run(s.q, vp, x0), um = run(s.q, vm, x0);
        for (std::size_t i = 0; i < Tree::nv; ++i)
            out[0][i][j] = (tp[i] - tm[i]) / (2 * h), out[1][i][j] = (up[i] - um[i]) / (2 * h);
        if constexpr (K == 3) {
            auto xp = x0, xm = x0;
            xp[j] += h, xm[j] -= h;
            const auto yp = run(s.q, s.qd, xp), ym = run(s.q, s.qd, xm);
            for (std::size_t i = 0; i < Tree::nv; ++i) out[2][i][j] = (yp[i] - ym[i]) / (2 * h);
        }
    }
    return out;
}

template <class Tree>
struct derivative_fixture {
    fixture<Tree> f;
    ch::model<Tree, ctga_test::dual<Tree::nv>> md = ctga::chains::model_cast<ctga_test::dual<Tree::nv>>(f.m);
};

template <dynamics A, differentiation I, class Tree>
[[gnu::noinline]] auto derivative_kernel(const derivative_fixture<Tree>& d, const state<Tree>& s) {
    if constexpr (I == differentiation::ctga) {
        if constexpr (A == dynamics::inverse) return ch::rnea_derivatives(d.f.m, s.q, s.qd, s.qdd);
        else if constexpr (A == dynamics::forward) return ch::aba_derivatives(d.f.m, s.q, s.qd, s.tau);
        else return ch::minverse(d.f.m, s.q);
    } else if constexpr (I == differentiation::dual) {
        return dual_partials<A>(d.md, s);
    } else {
        return fd_partials<A>(d.f.m, s);
    }
}

// entry (i, j) of matrix w of a kernel's result (w: the order of dual_partials)
template <dynamics A, differentiation I, class R>
double entry_of(const R& r, std::size_t w, std::size_t i, std::size_t j) {
    if constexpr (I != differentiation::ctga) return r[w][i][j];
    else if constexpr (A == dynamics::inverse) return w == 0 ? r.dtau_dq(i, j) : r.dtau_dv(i, j);
    else if constexpr (A == dynamics::forward) return w == 0 ? r.dqdd_dq(i, j) : w == 1 ? r.dqdd_dv(i, j) : r.Minv(i, j);
    else return r(i, j);
}

// max |D − D_ref| / max |D_ref| over 8 states, D_ref by long-double duals
template <dynamics A, differentiation I, class Tree>
double derivative_error(const derivative_fixture<Tree>& d) {
    using L = ctga_test::dual<Tree::nv, long double>;
    const auto ml = ctga::chains::model_cast<L>(d.f.m);
    double worst = 0;
    for (std::size_t k = 0; k < 8; ++k) {
        const auto ref = dual_partials<A == dynamics::inverse ? A : dynamics::forward>(ml, d.f.states[k]);
        const auto r = derivative_kernel<A, I>(d, d.f.states[k]);
        for (std::size_t w = A == dynamics::inverse_mass ? 2 : 0; w < ref.size(); ++w) {
            long double scale = 0, err = 0;
            for (std::size_t i = 0; i < Tree::nv; ++i)
                for (std::size_t j = 0; j < Tree::nv; ++j) {
                    const double x = entry_of<A, I>(r, A == dynamics::inverse_mass ? 0 : w, i, j);
                    scale = std::max(scale, std::abs(ref[w][i][j]));
                    err = std::max(err, std::abs(static_cast<long double>(x) - ref[w][i][j]));
                }
            worst = std::max(worst, static_cast<double>(err / scale));
        }
    }
    return worst;
}

template <dynamics A, differentiation I, class Tree>
void add_derivative(std::vector<entry>& table, const std::string& name, const derivative_fixture<Tree>& d) {
    const derivative_fixture<Tree>* p = &d;
    // computed once per entry, when timed (not for --repeat: callgrind would count it at startup);
    // per entry, not a static of the lambda: two fixtures of one tree type share the lambda's type
    auto error = std::make_shared<std::optional<double>>();
    table.push_back({name,
                     [p, error](benchmark::State& st) {
                         if (!*error) *error = derivative_error<A, I>(*p);
                         std::size_t k = 0;
                         for (auto _ : st) {
                             auto r = derivative_kernel<A, I>(*p, p->f.states[k]);
                             benchmark::DoNotOptimize(r);
                             k = (k + 1) & 63;
                         }
                         st.counters["max_error"] = **error;
                     },
                     [p](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) {
                             auto r = derivative_kernel<A, I>(*p, p->f.states[i & 63]);
                             benchmark::DoNotOptimize(r);
                         }
                     }});
}

// rnea_derivatives_<label>/ctga, /dual, /fd; aba_derivatives_<label>/…; minverse_<label>/ctga; or
// only the dynamics listed (D...: a tree's kernels split over units, each within the compile budget)
template <dynamics... D, class Tree>
void add_derivatives(std::vector<entry>& table, const std::string& label, const derivative_fixture<Tree>& d) {
    constexpr auto wanted = [](dynamics a) { return sizeof...(D) == 0 || ((D == a) || ...); };
    if constexpr (wanted(dynamics::inverse)) {
        add_derivative<dynamics::inverse, differentiation::ctga>(table, "rnea_derivatives_" + label + "/ctga", d);
        add_derivative<dynamics::inverse, differentiation::dual>(table, "rnea_derivatives_" + label + "/dual", d);
        add_derivative<dynamics::inverse, differentiation::fd>(table, "rnea_derivatives_" + label + "/fd", d);
    }
    if constexpr (wanted(dynamics::forward)) {
        add_derivative<dynamics::forward, differentiation::ctga>(table, "aba_derivatives_" + label + "/ctga", d);
        add_derivative<dynamics::forward, differentiation::dual>(table, "aba_derivatives_" + label + "/dual", d);
        add_derivative<dynamics::forward, differentiation::fd>(table, "aba_derivatives_" + label + "/fd", d);
    }
    if constexpr (wanted(dynamics::inverse_mass))
        add_derivative<dynamics::inverse_mass, differentiation::ctga>(table, "minverse_" + label + "/ctga", d);
}

}  // namespace bench::chains
