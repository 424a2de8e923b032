// The derivatives of a tree's dynamics (chains/rnea_derivatives.hpp, aba_derivatives.hpp,
// minverse.hpp) against two references on forward-mode dual numbers: the independent Featherstone
// reference (support/featherstone_derivatives.hpp) and ctga's own RNEA and ABA (the scalar type is
// generic; support/dual.hpp), on random trees of 1 to 30 bodies of every joint kind, floating
// bases and external wrenches: ∂τ/∂q (tangent space: a floating joint's motor moved by g exp(δ),
// seeded to first order as g (1 + δ/2)), ∂τ/∂q̇, ∂q̈/∂q, ∂q̈/∂q̇, ∂q̈/∂τ = H⁻¹, with H against CRBA
// and H⁻¹ H = 1. Then the patterns of the result types: every entry marked structural is non-zero
// for some draw, and every entry the reference shows non-zero is marked.
// PARTS: 9
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include <ctga/chains/algorithms.hpp>
#include <ctga/chains/aba_derivatives.hpp>
#include <ctga/chains/minverse.hpp>
#include <ctga/chains/rnea_derivatives.hpp>

#include "support/catch.hpp"
#include "support/dual.hpp"
#include "support/dual_partials.hpp"
#include "support/featherstone_derivatives.hpp"
#include <ctga/chains/model_cast.hpp>
#include "support/parts.hpp"
#include "support/random_structure.hpp"

namespace {

namespace ch = ctga::chains;
using ctga::test::draw;
using ctga::test::make_draw;
using ctga::test::random_structure;
namespace fs = ctga::test::featherstone;

using D = ctga::test::chunk_dual;
template <class Tree>
using dense = std::array<std::array<double, Tree::nv>, Tree::nv>;

// The partials of y = algorithm(q, q̇, x) (rnea: x = q̈; aba: x = τ) by duals, with respect to q
// (tangent space), q̇ and x (support/dual_partials.hpp).
template <class Tree, class Algorithm>
std::array<dense<Tree>, 3> dual_partials(const draw<Tree>& d, const ch::joint_vector<Tree>& x0, Algorithm algorithm) {
    return ctga::test::dual_partials(d.m, d.q, d.qd, x0, algorithm);
}

template <class Tree, class M>
double max_abs_diff(const M& a, const dense<Tree>& b) {
    double e = 0;
    for (std::size_t i = 0; i < Tree::nv; ++i)
        for (std::size_t j = 0; j < Tree::nv; ++j) {
            double x;
            if constexpr (requires { a(i, j); }) x = a(i, j);
            else x = a[i][j];
            e = std::max(e, std::abs(x - b[i][j]));
        }
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
dense<Tree> dense_of(const Eigen::MatrixXd& x) {
    dense<Tree> out{};
    for (std::size_t i = 0; i < Tree::nv; ++i)
        for (std::size_t j = 0; j < Tree::nv; ++j) out[i][j] = x(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    return out;
}

// Which derivatives a unit compiles: all, or one of two halves (a 30-body tree's are 30 unrolled
// bodies and 435 pairs of joints each; one unit with both took 39 s and 1.6 GB).
enum class which { all, inverse_dynamics, forward_dynamics };

// ctga's derivatives against the references: always the Featherstone reference on dual numbers
// (support/featherstone_derivatives.hpp), and with CtgaDuals ctga's own RNEA / ABA on duals.
template <class Tree, bool CtgaDuals, which W = which::all>
void compare(std::uint64_t seed, int draws) {
    constexpr bool inverse = W != which::forward_dynamics, forward = W != which::inverse_dynamics;
    std::mt19937_64 rng(seed);
    using result = ch::rnea_partials<Tree>;
    using matrix = decltype(result::dtau_dq);
    using fmatrix = decltype(ch::aba_partials<Tree>::Minv);
    // seen[i][j]: entry (i, j) was non-zero in some draw (by the reference)
    std::array<std::array<bool, Tree::nv>, Tree::nv> seen{}, fseen{};
    for (int n = 0; n < draws; ++n) {
        const draw<Tree> d = make_draw<Tree>(rng);
        ch::body_wrenches<Tree> f{};
        std::vector<fs::vec6> f_ref(Tree::size);
        for (std::size_t i = 0; i < Tree::size; ++i)
            for (std::size_t c = 0; c < 6; ++c) f[i][c] = f_ref[i][static_cast<int>(c)] = fs::uniform(rng, -1, 1);
        for (int with_f = 0; with_f < 2; ++with_f) {
            INFO("bodies " << Tree::size << ", nv " << Tree::nv << ", draw " << n << (with_f ? ", external wrenches" : ""));
            const std::vector<fs::vec6>& f_or_none = with_f ? f_ref : std::vector<fs::vec6>{};
            ch::body_wrenches<Tree, D> fd{};
            for (std::size_t i = 0; i < Tree::size; ++i)
                for (std::size_t c = 0; c < 6; ++c) fd[i][c] = D(with_f ? f[i][c] : 0.0);
            const auto tau = with_f ? ch::rnea(d.m, d.q, d.qd, d.qdd, f) : ch::rnea(d.m, d.q, d.qd, d.qdd);
            const auto H = ch::crba(d.m, d.q);
            double s = 1;  // max |τ|
            for (std::size_t k = 0; k < Tree::nv; ++k) s = std::max(s, std::abs(tau[k]));
            // each matrix of a result against the same of a reference (relative to the reference's largest entry)
            const auto check = [&](const auto& result, const auto& reference, const char* name) {
                INFO("reference: " << name);
                for (std::size_t w = 0; w < std::min(result.size(), reference.size()); ++w) {
                    INFO("matrix " << w);
                    CHECK(max_abs_diff<Tree>(result[w], reference[w]) <= 1e-12 * max_abs<Tree>(reference[w]));
                }
            };
            if constexpr (inverse) {
                const result r = with_f ? ch::rnea_derivatives(d.m, d.q, d.qd, d.qdd, f) : ch::rnea_derivatives(d.m, d.q, d.qd, d.qdd);
                double e = 0;
                for (std::size_t k = 0; k < Tree::nv; ++k) e = std::max(e, std::abs(r.tau[k] - tau[k]));
                CHECK(e <= 1e-12 * s);
                CHECK(max_abs_diff<Tree>(r.M, H) <= 1e-12 * max_abs<Tree>(H));
                // ∂τ/∂q, ∂τ/∂q̇ and H = ∂τ/∂q̈ (the last against the duals' seeded q̈)
                const std::array<dense<Tree>, 3> mine{r.dtau_dq.dense(), r.dtau_dv.dense(), r.M.dense()};
                const fs::rnea_partials rf = fs::rnea_derivatives(d.ref, d.q_ref, d.qd_ref, d.qdd_ref, f_or_none);
                const std::array<dense<Tree>, 2> ref{dense_of<Tree>(rf.dtau_dq), dense_of<Tree>(rf.dtau_dv)};
                check(mine, ref, "Featherstone's RNEA on dual numbers");
                if constexpr (CtgaDuals)
                    check(mine, dual_partials(d, d.qdd, [&](const auto& md, const auto& q, const auto& qd, const auto& qdd) {
                              return ch::rnea(md, q, qd, qdd, fd);
                          }), "ctga's RNEA on dual numbers");
                // the pattern: nothing the reference shows non-zero is missing
                for (std::size_t i = 0; i < Tree::nv; ++i)
                    for (std::size_t j = 0; j < Tree::nv; ++j) {
                        INFO("entry " << i << ", " << j);
                        const bool nonzero = ref[0][i][j] != 0 || ref[1][i][j] != 0 || H[i][j] != 0;
                        if (nonzero) CHECK(matrix::structural(i, j));
                        seen[i][j] = seen[i][j] || nonzero;
                    }
            }
            if constexpr (forward) {
                // forward dynamics at τ = ID(q̈): ∂q̈/∂q, ∂q̈/∂q̇, ∂q̈/∂τ = H⁻¹
                const auto fwd = with_f ? ch::aba_derivatives(d.m, d.q, d.qd, tau, f) : ch::aba_derivatives(d.m, d.q, d.qd, tau);
                const std::array<dense<Tree>, 3> mine{fwd.dqdd_dq.dense(), fwd.dqdd_dv.dense(), fwd.Minv.dense()};
                Eigen::VectorXd tau_ref(static_cast<Eigen::Index>(Tree::nv));
                for (std::size_t k = 0; k < Tree::nv; ++k) tau_ref[static_cast<Eigen::Index>(k)] = tau[k];
                const fs::aba_partials af = fs::aba_derivatives(d.ref, d.q_ref, d.qd_ref, tau_ref, f_or_none);
                const std::array<dense<Tree>, 3> fref{dense_of<Tree>(af.dqdd_dq), dense_of<Tree>(af.dqdd_dv), dense_of<Tree>(af.dqdd_dtau)};
                check(mine, fref, "Featherstone's ABA on dual numbers");
                if constexpr (CtgaDuals)
                    check(mine, dual_partials(d, tau, [&](const auto& md, const auto& q, const auto& qd, const auto& t) {
                              return ch::aba(md, q, qd, t, fd);
                          }), "ctga's ABA on dual numbers");
                double q_err = 0;
                for (std::size_t k = 0; k < Tree::nv; ++k) q_err = std::max(q_err, std::abs(fwd.qdd[k] - d.qdd[k]));
                CHECK(q_err <= 1e-12 * max_abs<Tree>(fref[2]) * s);
                // H⁻¹ H = 1, minverse alone (relative to ‖H⁻¹‖ ‖H‖: the trees' H reach condition numbers of 1e4)
                const auto Minv = ch::minverse(d.m, d.q);
                double id_err = 0;
                for (std::size_t i = 0; i < Tree::nv; ++i)
                    for (std::size_t j = 0; j < Tree::nv; ++j) {
                        double x = i == j ? -1.0 : 0.0;
                        for (std::size_t k = 0; k < Tree::nv; ++k) x += Minv(i, k) * H[k][j];
                        id_err = std::max(id_err, std::abs(x));
                    }
                CHECK(id_err <= 1e-12 * max_abs<Tree>(fref[2]) * max_abs<Tree>(H));
                for (std::size_t i = 0; i < Tree::nv; ++i)
                    for (std::size_t j = 0; j < Tree::nv; ++j) {
                        INFO("entry " << i << ", " << j);
                        const bool nonzero = fref[0][i][j] != 0 || fref[1][i][j] != 0 || fref[2][i][j] != 0;
                        if (nonzero) CHECK(fmatrix::structural(i, j));
                        fseen[i][j] = fseen[i][j] || nonzero;
                    }
            }
        }
    }
    // and the patterns mark nothing that stays zero
    for (std::size_t i = 0; i < Tree::nv; ++i)
        for (std::size_t j = 0; j < Tree::nv; ++j) {
            INFO("entry " << i << ", " << j);
            if (inverse && matrix::structural(i, j)) CHECK(seen[i][j]);
            if (forward && fmatrix::structural(i, j)) CHECK(fseen[i][j]);
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

#define DERIVATIVES_CASE(name) TEST_CASE("rnea_derivatives, aba_derivatives, minverse = the references on dual numbers, " name)
// One tree per unit (every unit within 30 s); ctga's own RNEA and ABA on duals for the smallest
// trees (their dual instantiations cost 15–20 s more per unit for 5 bodies and more).
#if CTGA_TEST_PART_HOLDS(0)
DERIVATIVES_CASE("1 and 2 bodies") {
    compare<random_structure<1, 1, false>::type, true>(21, 10);
    compare<random_structure<2, 2, true>::type, true>(22, 10);
}
#endif
#if CTGA_TEST_PART_HOLDS(1)
// (about half its joints aligned: placements translations, joints.hpp)
DERIVATIVES_CASE("5 bodies, aligned joints among them") { compare<random_structure<3, 5, false, true, true>::type, false>(23, 10); }
#endif
#if CTGA_TEST_PART_HOLDS(2)
DERIVATIVES_CASE("7 bodies on a floating base") { compare<random_structure<4, 7, true, false, true>::type, false>(24, 10); }
#endif
#if CTGA_TEST_PART_HOLDS(3)
DERIVATIVES_CASE("the legged tree") { compare<legged, false>(25, 5); }
#endif
#if CTGA_TEST_PART_HOLDS(4)
DERIVATIVES_CASE("12 bodies on a floating base") { compare<random_structure<6, 12, true>::type, false>(27, 5); }
#endif
#if CTGA_TEST_PART_HOLDS(5)
DERIVATIVES_CASE("30 bodies: inverse dynamics") { compare<random_structure<7, 30, false>::type, false, which::inverse_dynamics>(28, 3); }
#endif
#if CTGA_TEST_PART_HOLDS(6)
DERIVATIVES_CASE("30 bodies: forward dynamics") { compare<random_structure<7, 30, false>::type, false, which::forward_dynamics>(28, 3); }
#endif
#if CTGA_TEST_PART_HOLDS(7)
DERIVATIVES_CASE("30 bodies on a floating base: inverse dynamics") {
    compare<random_structure<8, 30, true>::type, false, which::inverse_dynamics>(29, 3);
}
#endif
#if CTGA_TEST_PART_HOLDS(8)
DERIVATIVES_CASE("30 bodies on a floating base: forward dynamics") {
    compare<random_structure<8, 30, true>::type, false, which::forward_dynamics>(29, 3);
}
#endif
