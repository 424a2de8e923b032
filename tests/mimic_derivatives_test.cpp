// The derivatives of the dynamics and of a frame's motion on trees with mimic joints
// (chains/mimic_expansion.hpp: the expanded tree, reduced by G): ∂τ/∂q, ∂τ/∂q̇, H, ∂q̈/∂q,
// ∂q̈/∂q̇, H⁻¹ and a frame's ∂v, ∂a against forward-mode dual numbers through ctga's own rnea,
// aba (its Cholesky path for coupled trees) and forward kinematics (support/dual_partials.hpp),
// with and without external wrenches; τ = rnea, H = crba, H⁻¹ H = 1, q̈ = aba; and the patterns
// (tree_matrix.hpp: a dof moves its body and its mimics), every entry the duals show non-zero
// marked structural. Two hand-made trees with random placements, inertias and couplings: a
// gripper (a finger following its sibling, a link following its own ancestor) and a floating
// base whose mimic carries a joint of its own on another branch than its master.
// PARTS: 2
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>

#include <ctga/chains/algorithms.hpp>

#include "support/catch.hpp"
#include "support/dual_partials.hpp"
#include "support/parts.hpp"

namespace {

namespace ch = ctga::chains;
using D = ctga::test::chunk_dual;

double uniform(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

template <class Tree>
ch::model<Tree> random_model(std::mt19937_64& rng) {
    ch::model<Tree> m;
    m.gravity = {uniform(rng, -2, 2), uniform(rng, -2, 2), -9.81};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            using J = typename Tree::template joint_at<I>;
            const double x = uniform(rng, -1, 1), y = uniform(rng, -1, 1), z = uniform(rng, -1, 1), n = std::sqrt(x * x + y * y + z * z);
            const auto placement = ctga::rigid_motion(ctga::make_translator(uniform(rng, -0.3, 0.3), uniform(rng, -0.3, 0.3), uniform(rng, -0.3, 0.3)),
                                                      ctga::make_rotor(uniform(rng, -2, 2), x / n, y / n, z / n));
            const double a = uniform(rng, 0.02, 0.05), b = uniform(rng, 0.02, 0.05), c = uniform(rng, 0.02, 0.05), o = 0.003;
            const auto mass = ctga::make_mass_properties(uniform(rng, 0.5, 2.0), ctga::vec3<double>{uniform(rng, -0.1, 0.1), uniform(rng, -0.1, 0.1), uniform(rng, -0.1, 0.1)},
                                                         ctga::mat3<double>{{{b + c, o, 0.0}, {o, a + c, -o}, {0.0, -o, a + b}}});
            const auto link = [&] {
                if constexpr (ch::is_mimic<J>) return ch::make_link<J>(placement, mass, ch::coupling<double>{uniform(rng, -1.5, 1.5), uniform(rng, -0.2, 0.2)});
                else return ch::make_link<J>(placement, mass);
            }();
            REQUIRE(link);
            m.template link<I>() = *link;
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    if constexpr (Tree::frame_count > 0)
        m.frames[0] = *ch::make_frame(ctga::rigid_motion(ctga::make_translator(0.1, -0.05, 0.2), ctga::make_rotor(0.7, 0.6, 0.0, 0.8)));
    return m;
}

template <class Tree>
using dense = std::array<std::array<double, Tree::nv>, Tree::nv>;

// |x − y| ≤ 1e-12 max(1, max |y|)
template <class Tree, class X>
bool near(const X& x, const dense<Tree>& y) {
    double e = 0, s = 1;
    for (std::size_t i = 0; i < Tree::nv; ++i)
        for (std::size_t j = 0; j < Tree::nv; ++j) e = std::max(e, std::abs(x(i, j) - y[i][j])), s = std::max(s, std::abs(y[i][j]));
    return e <= 1e-12 * s;
}

template <class Tree, class F>
void check(std::uint64_t seed, F frame) {
    std::mt19937_64 rng(seed);
    using B = decltype(ch::rnea_partials<Tree>::dtau_dq);
    using C = decltype(ch::aba_partials<Tree>::Minv);
    std::array<std::array<bool, Tree::nv>, Tree::nv> seen{}, fseen{};
    for (int n = 0; n < 6; ++n) {
        const ch::model<Tree> m = random_model<Tree>(rng);
        ch::configuration<Tree> q{};
        ch::joint_vector<Tree> qd{}, qdd{};
        for (std::size_t b = 0; b < Tree::size; ++b) {
            const std::size_t o = Tree::q_offset[b];
            if (Tree::nq_of[b] == 8) {
                const auto g = ctga::rigid_motion(ctga::make_translator(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)),
                                                  ctga::make_rotor(uniform(rng, -2, 2), 0.0, 0.6, 0.8));
                for (std::size_t k = 0; k < 8 && o + k < Tree::nq; ++k) q[o + k] = g[k];
            } else if (Tree::nq_of[b] == 1) {
                q[o] = uniform(rng, -1.5, 1.5);
            }
        }
        for (std::size_t k = 0; k < Tree::nv; ++k) qd[k] = uniform(rng, -1, 1), qdd[k] = uniform(rng, -2, 2);
        ch::body_wrenches<Tree> f{};
        ch::body_wrenches<Tree, D> fd{};
        for (std::size_t i = 0; i < Tree::size; ++i)
            for (std::size_t c = 0; c < 6; ++c) f[i][c] = n % 2 ? uniform(rng, -1, 1) : 0.0, fd[i][c] = D(f[i][c]);
        INFO("draw " << n);
        // inverse dynamics
        const auto id = ch::rnea_derivatives(m, q, qd, qdd, f);
        const auto ref = ctga::test::dual_partials(m, q, qd, qdd, [&](const auto& md, const auto& x, const auto& xd, const auto& xdd) {
            return ch::rnea(md, x, xd, xdd, fd);
        });
        const auto tau = ch::rnea(m, q, qd, qdd, f);
        const auto H = ch::crba(m, q);
        CHECK(near<Tree>(id.dtau_dq, ref[0]));
        CHECK(near<Tree>(id.dtau_dv, ref[1]));
        CHECK(near<Tree>(id.M, ref[2]));
        CHECK(near<Tree>(id.M, H));
        for (std::size_t k = 0; k < Tree::nv; ++k) CHECK(std::abs(id.tau[k] - tau[k]) <= 1e-12 * std::max(1.0, std::abs(tau[k])));
        // forward dynamics at τ
        const auto fwd = ch::aba_derivatives(m, q, qd, tau, f);
        const auto fref = ctga::test::dual_partials(m, q, qd, tau, [&](const auto& md, const auto& x, const auto& xd, const auto& t) {
            return ch::aba(md, x, xd, t, fd);
        });
        CHECK(near<Tree>(fwd.dqdd_dq, fref[0]));
        CHECK(near<Tree>(fwd.dqdd_dv, fref[1]));
        CHECK(near<Tree>(fwd.Minv, fref[2]));
        for (std::size_t k = 0; k < Tree::nv; ++k) CHECK(std::abs(fwd.qdd[k] - qdd[k]) <= 1e-10 * std::max(1.0, std::abs(qdd[k])));
        const auto Minv = ch::minverse(m, q);
        for (std::size_t i = 0; i < Tree::nv; ++i)
            for (std::size_t j = 0; j < Tree::nv; ++j) {
                double x = i == j ? -1.0 : 0.0;
                for (std::size_t k = 0; k < Tree::nv; ++k) x += Minv(i, k) * H[k][j];
                CHECK(std::abs(x) <= 1e-11);
                const bool nonzero = ref[0][i][j] != 0 || ref[1][i][j] != 0 || H[i][j] != 0;
                const bool fnonzero = fref[0][i][j] != 0 || fref[1][i][j] != 0 || fref[2][i][j] != 0;
                if (nonzero) CHECK(B::structural(i, j));
                if (fnonzero) CHECK(C::structural(i, j));
                seen[i][j] = seen[i][j] || nonzero;
                fseen[i][j] = fseen[i][j] || fnonzero;
            }
        // a frame's motion
        for (const ch::reference r : {ch::reference::local, ch::reference::world, ch::reference::local_world_aligned}) {
            INFO("reference " << static_cast<int>(r));
            const auto p = ch::frame_motion_derivatives(m, q, qd, qdd, frame, r);
            const auto vref = ctga::test::dual_partials(m, q, qd, qdd, [&](const auto& md, const auto& x, const auto& xd, const auto& xdd) {
                const auto k = ch::forward_kinematics(md, x, xd, xdd);
                const auto v = ch::frame_velocity(md, k, frame, r);
                const auto a = ch::frame_acceleration(md, k, frame, r);
                std::array<D, 12> y;
                for (std::size_t i = 0; i < 6; ++i) y[i] = v[i], y[6 + i] = a[i];
                return y;
            });
            double e = 0, s = 1;
            for (std::size_t c = 0; c < Tree::nv; ++c)
                for (std::size_t i = 0; i < 6; ++i) {
                    const double got[5] = {p.dv_dq[c][i], p.dv_dv[c][i], p.da_dq[c][i], p.da_dv[c][i], p.da_da[c][i]};
                    const double want[5] = {vref[0][i][c], vref[1][i][c], vref[0][6 + i][c], vref[1][6 + i][c], vref[2][6 + i][c]};
                    for (int w = 0; w < 5; ++w) e = std::max(e, std::abs(got[w] - want[w])), s = std::max(s, std::abs(want[w]));
                }
            CHECK(e <= 1e-12 * s);
        }
    }
    // the patterns mark nothing that stays zero
    for (std::size_t i = 0; i < Tree::nv; ++i)
        for (std::size_t j = 0; j < Tree::nv; ++j) {
            INFO("entry " << i << ", " << j);
            if (B::structural(i, j)) CHECK(seen[i][j]);
            if (C::structural(i, j)) CHECK(fseen[i][j]);
        }
}

// a wrist and a gripper: finger 3 follows finger 2 (siblings), body 4 follows its ancestor 1
using gripper = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_y>, ch::link<1, ch::prismatic_y>,
                         ch::link<1, ch::mimic<ch::prismatic_y, 2>>, ch::link<2, ch::mimic<ch::revolute_x, 1>>, ch::fixed_frame<"tip", 4>>;
// a floating base; body 2 follows body 1 on another branch and carries body 3's own joint
using coupled = ch::tree<ch::link<-1, ch::floating>, ch::link<0, ch::revolute_x>, ch::link<0, ch::mimic<ch::revolute_y, 1>>,
                         ch::link<2, ch::revolute_z>, ch::link<1, ch::prismatic_x>>;
// dof 7 (body 3) and dof 6 (body 1) lie on two branches, coupled by the mimic (body 2 moves with
// body 1 and carries body 3); dof 8 (body 4, under body 1) and dof 7 are not coupled
using coupled_pattern = ch::tree_matrix<coupled, double, ch::sparsity::branches>;
static_assert(coupled_pattern::structural(7, 6) && coupled_pattern::structural(6, 7) && !coupled_pattern::structural(8, 7),
              "a mimic couples its master's dof with the dofs on its own branch");

}  // namespace

#if CTGA_TEST_PART_HOLDS(0)
TEST_CASE("mimic joints: derivatives = dual numbers, a gripper" CTGA_TEST_PART_NAME) {
    check<gripper>(41, ch::frame<"tip">);
}
#endif
#if CTGA_TEST_PART_HOLDS(1)
TEST_CASE("mimic joints: derivatives = dual numbers, a mimic across branches" CTGA_TEST_PART_NAME) {
    check<coupled>(42, ch::body<3>);
}
#endif
