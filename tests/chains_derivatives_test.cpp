// The derivatives of a tree's inverse dynamics (chains/rnea_derivatives.hpp) against forward-mode
// dual numbers run through ctga's own RNEA (the scalar type is generic; support/dual.hpp), on
// random trees of every joint kind, floating bases and external wrenches: ∂τ/∂q (tangent space: a
// floating joint's motor moved by g exp(δ), seeded to first order as g (1 + δ/2)), ∂τ/∂q̇, and H
// against CRBA. Then the pattern of the result type: every entry it marks structural is non-zero
// for some draw, and every entry the duals show non-zero is in it.
// PARTS: 4
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>

#include <ctga/chains/algorithms.hpp>
#include <ctga/chains/rnea_derivatives.hpp>

#include "support/catch.hpp"
#include "support/dual.hpp"
#include "support/model_cast.hpp"
#include "support/parts.hpp"
#include "support/random_structure.hpp"

namespace {

namespace ch = ctga::chains;
using ctga::test::draw;
using ctga::test::make_draw;
using ctga::test::random_structure;

constexpr std::size_t chunk = 6;  // partials per dual evaluation
using D = ctga_test::dual<chunk>;

template <class Tree>
using dense = std::array<std::array<double, Tree::nv>, Tree::nv>;

// ∂τ/∂q and ∂τ/∂q̇ by duals through rnea, columns [c0, c0 + chunk) at a time.
template <class Tree>
std::array<dense<Tree>, 2> dual_partials(const draw<Tree>& d, const ch::body_wrenches<Tree>* f) {
    const ch::model<Tree, D> md = ctga_test::model_cast<D>(d.m);
    ch::body_wrenches<Tree, D> fd{};
    if (f)
        for (std::size_t i = 0; i < Tree::size; ++i)
            for (std::size_t c = 0; c < 6; ++c) fd[i][c] = D((*f)[i][c]);
    std::array<dense<Tree>, 2> out{};
    for (int wrt = 0; wrt < 2; ++wrt)
        for (std::size_t c0 = 0; c0 < Tree::nv; c0 += chunk) {
            ch::configuration<Tree, D> q{};
            ch::joint_vector<Tree, D> qd{}, qdd{};
            for (std::size_t k = 0; k < Tree::nq; ++k) q[k] = D(d.q[k]);
            for (std::size_t k = 0; k < Tree::nv; ++k) {
                qd[k] = wrt == 1 && k >= c0 && k < c0 + chunk ? D::variable(d.qd[k], k - c0) : D(d.qd[k]);
                qdd[k] = D(d.qdd[k]);
            }
            if (wrt == 0)
                for (std::size_t b = 0; b < Tree::size; ++b) {
                    const std::size_t qo = Tree::q_offset[b], vo = Tree::v_offset[b];
                    // the seed of dof k: δ_k with partial k − c0 when in this chunk
                    const auto delta = [&](std::size_t k) { return k >= c0 && k < c0 + chunk ? D::variable(0.0, k - c0) : D(0.0); };
                    if (Tree::nq_of[b] == 1) q[qo] = q[qo] + delta(vo);
                    if (Tree::nq_of[b] == 8) {  // g (1 + ½(ω, v)): the motor moved in its own frame
                        const ctga::motor<D> g{q[qo], q[qo + 1], q[qo + 2], q[qo + 3], q[qo + 4], q[qo + 5], q[qo + 6], q[qo + 7]};
                        const ctga::motor<D> e{D(1.0),           delta(vo) * 0.5,     delta(vo + 1) * 0.5, delta(vo + 2) * 0.5,
                                               D(0.0),           delta(vo + 3) * 0.5, delta(vo + 4) * 0.5, delta(vo + 5) * 0.5};
                        const ctga::motor<D> ge = g * e;
                        for (std::size_t k = 0; k < 8; ++k) q[qo + k] = ge[k];
                    }
                }
            const auto tau = f ? ch::rnea(md, q, qd, qdd, fd) : ch::rnea(md, q, qd, qdd);
            for (std::size_t i = 0; i < Tree::nv; ++i)
                for (std::size_t c = c0; c < std::min(c0 + chunk, Tree::nv); ++c)
                    out[static_cast<std::size_t>(wrt)][i][c] = ctga_test::derivative(tau[i], c - c0);
        }
    return out;
}

template <class Tree, class M>
double max_abs_diff(const M& a, const dense<Tree>& b) {
    double e = 0;
    for (std::size_t i = 0; i < Tree::nv; ++i)
        for (std::size_t j = 0; j < Tree::nv; ++j) e = std::max(e, std::abs(a(i, j) - b[i][j]));
    return e;
}
template <class Tree>
double max_abs(const dense<Tree>& b) {  // (at least 1: the scale of these models' numbers)
    double e = 1;
    for (const auto& row : b)
        for (double x : row) e = std::max(e, std::abs(x));
    return e;
}

template <class Tree>
void compare(std::uint64_t seed, int draws) {
    std::mt19937_64 rng(seed);
    using result = ch::rnea_partials<Tree>;
    using matrix = decltype(result::dtau_dq);
    // seen[i][j]: entry (i, j) was non-zero in some draw (by the duals)
    std::array<std::array<bool, Tree::nv>, Tree::nv> seen{};
    for (int n = 0; n < draws; ++n) {
        const draw<Tree> d = make_draw<Tree>(rng);
        ch::body_wrenches<Tree> f{};
        for (auto& w : f)
            for (std::size_t c = 0; c < 6; ++c) w[c] = ctga::test::featherstone::uniform(rng, -1, 1);
        for (int with_f = 0; with_f < 2; ++with_f) {
            INFO("bodies " << Tree::size << ", nv " << Tree::nv << ", draw " << n << (with_f ? ", external wrenches" : ""));
            const result r = with_f ? ch::rnea_derivatives(d.m, d.q, d.qd, d.qdd, f) : ch::rnea_derivatives(d.m, d.q, d.qd, d.qdd);
            const auto ref = dual_partials(d, with_f ? &f : nullptr);
            const double sq = max_abs<Tree>(ref[0]), sv = max_abs<Tree>(ref[1]);
            CHECK(max_abs_diff<Tree>(r.dtau_dq, ref[0]) <= 1e-12 * sq);
            CHECK(max_abs_diff<Tree>(r.dtau_dv, ref[1]) <= 1e-12 * sv);
            const auto H = ch::crba(d.m, d.q);
            CHECK(max_abs_diff<Tree>(r.M, H) <= 1e-12 * max_abs<Tree>(H));
            const auto tau = with_f ? ch::rnea(d.m, d.q, d.qd, d.qdd, f) : ch::rnea(d.m, d.q, d.qd, d.qdd);
            double e = 0, s = 1;
            for (std::size_t k = 0; k < Tree::nv; ++k) e = std::max(e, std::abs(r.tau[k] - tau[k])), s = std::max(s, std::abs(tau[k]));
            CHECK(e <= 1e-12 * s);
            for (std::size_t i = 0; i < Tree::nv; ++i)
                for (std::size_t j = 0; j < Tree::nv; ++j) {
                    const bool nonzero = ref[0][i][j] != 0 || ref[1][i][j] != 0 || H[i][j] != 0;
                    seen[i][j] = seen[i][j] || nonzero;
                    INFO("entry " << i << ", " << j);
                    if (nonzero) CHECK(matrix::structural(i, j));  // nothing the duals see is missing
                }
        }
    }
    // and the pattern marks nothing that stays zero
    for (std::size_t i = 0; i < Tree::nv; ++i)
        for (std::size_t j = 0; j < Tree::nv; ++j)
            if (matrix::structural(i, j)) {
                INFO("structural entry " << i << ", " << j << " never non-zero");
                CHECK(seen[i][j]);
            }
}

// The legged shape: a floating trunk with four legs (hip x, thigh y, knee y), as the benchmark's
// tree: the legs' entries off each other are structural zeros.
using legged = ch::tree<ch::link<-1, ch::floating>,                                                     //
                        ch::link<0, ch::revolute_x>, ch::link<1, ch::revolute_y>, ch::link<2, ch::revolute_y>,  //
                        ch::link<0, ch::revolute_x>, ch::link<4, ch::revolute_y>, ch::link<5, ch::revolute_y>,  //
                        ch::link<0, ch::revolute_x>, ch::link<7, ch::revolute_y>, ch::link<8, ch::revolute_y>,  //
                        ch::link<0, ch::revolute_x>, ch::link<10, ch::revolute_y>, ch::link<11, ch::revolute_y>>;
static_assert(decltype(ch::rnea_partials<legged>::dtau_dq)::nonzeros == 18 * 18 - 4 * 3 * 9,
              "the legs' 3 × 3 blocks off each other are the legged tree's structural zeros");

}  // namespace

#define DERIVATIVES_CASE(name) TEST_CASE("rnea_derivatives: ∂τ/∂q, ∂τ/∂q̇, H = dual numbers through rnea, " name)
#if CTGA_TEST_PART_HOLDS(0)
DERIVATIVES_CASE("1 to 7 bodies") {
    compare<random_structure<1, 1, false>::type>(21, 10);
    compare<random_structure<2, 2, true>::type>(22, 10);
    compare<random_structure<3, 5, false>::type>(23, 10);
    compare<random_structure<4, 7, true>::type>(24, 10);
}
#endif
#if CTGA_TEST_PART_HOLDS(1)
DERIVATIVES_CASE("the legged tree") { compare<legged>(25, 5); }
#endif
#if CTGA_TEST_PART_HOLDS(2)
DERIVATIVES_CASE("12 bodies") { compare<random_structure<5, 12, false>::type>(26, 5); }
#endif
#if CTGA_TEST_PART_HOLDS(3)
DERIVATIVES_CASE("12 bodies on a floating base") { compare<random_structure<6, 12, true>::type>(27, 5); }
#endif
