// The derivatives of a frame's velocity and spatial acceleration (chains/frame_derivatives.hpp)
// with respect to q (tangent space), q̇ and q̈, against forward-mode dual numbers run through
// ctga's own forward kinematics and frame_velocity / frame_acceleration (a different code path:
// body-frame kinematics, support/dual_partials.hpp), in the three references, on random trees of
// every joint kind (a floating base included, random gravity) for body frames, and on a hand-made
// tree for a named frame with a random placement; ∂v/∂q̇ = ∂a/∂q̈ = frame_jacobian, and columns of
// joints off the frame's path zero. Tolerance 1e-12 relative to max(1, the reference's largest).
// PARTS: 2
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>

#include <ctga/chains/algorithms.hpp>
#include <ctga/chains/frame_derivatives.hpp>
#include <ctga/chains/frame_jacobian.hpp>
#include <ctga/chains/frames.hpp>

#include "support/catch.hpp"
#include "support/dual_partials.hpp"
#include "support/parts.hpp"
#include "support/random_structure.hpp"

namespace {

namespace ch = ctga::chains;
using ctga::test::draw;
using ctga::test::make_draw;
using ctga::test::random_structure;
namespace fs = ctga::test::featherstone;

constexpr std::array<ch::reference, 3> refs{ch::reference::local, ch::reference::world, ch::reference::local_world_aligned};

// |x − y| ≤ 1e-12 max(1, |y|) over columns c, components i; y[i][c] a dual-number reference
template <class Tree, class Y>
double worst(const ch::jacobian_matrix<Tree>& x, const Y& y, std::size_t first_row) {
    double e = 0, s = 1;
    for (std::size_t c = 0; c < Tree::nv; ++c)
        for (std::size_t i = 0; i < 6; ++i) {
            e = std::max(e, std::abs(x[c][i] - y[first_row + i][c]));
            s = std::max(s, std::abs(y[first_row + i][c]));
        }
    return e / s;
}

template <class Tree, class F>
void check_frame(const draw<Tree>& d, F f) {
    constexpr int body = ch::frame_detail::frame_on<Tree, F>::body;
    for (const ch::reference r : refs) {
        INFO("frame on body " << body << ", reference " << static_cast<int>(r));
        const ch::frame_motion_partials<Tree> p = ch::frame_motion_derivatives(d.m, d.q, d.qd, d.qdd, f, r);
        // (v, a) of the frame, 12 numbers, by duals through the body-frame kinematics
        const auto ref = ctga::test::dual_partials(d.m, d.q, d.qd, d.qdd, [&](const auto& md, const auto& q, const auto& qd, const auto& qdd) {
            const auto k = ch::forward_kinematics(md, q, qd, qdd);
            const auto v = ch::frame_velocity(md, k, f, r);
            const auto a = ch::frame_acceleration(md, k, f, r);
            std::array<ctga::test::chunk_dual, 12> y;
            for (std::size_t i = 0; i < 6; ++i) y[i] = v[i], y[6 + i] = a[i];
            return y;
        });
        CHECK(worst<Tree>(p.dv_dq, ref[0], 0) <= 1e-12);
        CHECK(worst<Tree>(p.dv_dv, ref[1], 0) <= 1e-12);
        CHECK(worst<Tree>(p.da_dq, ref[0], 6) <= 1e-12);
        CHECK(worst<Tree>(p.da_dv, ref[1], 6) <= 1e-12);
        CHECK(worst<Tree>(p.da_da, ref[2], 6) <= 1e-12);
        // ∂v/∂q̇ = ∂a/∂q̈ = J; a column off the frame's path is zero
        const ch::jacobian_matrix<Tree> J = ch::frame_jacobian(d.m, d.q, f, r);
        for (std::size_t c = 0; c < Tree::nv; ++c) {
            INFO("column " << c);
            const bool on_path = body >= 0 && Tree::supports(Tree::body_of_dof[c], static_cast<std::size_t>(body));
            for (std::size_t i = 0; i < 6; ++i) {
                CHECK(std::abs(p.dv_dv[c][i] - J[c][i]) <= 1e-13 * std::max(1.0, std::abs(J[c][i])));
                CHECK(p.da_da[c][i] == p.dv_dv[c][i]);
                if (!on_path) CHECK((p.dv_dq[c][i] == 0 && p.da_dq[c][i] == 0 && p.da_dv[c][i] == 0 && p.dv_dv[c][i] == 0));
            }
        }
    }
}

template <class Tree>
void check_bodies(std::uint64_t seed, int draws) {
    std::mt19937_64 rng(seed);
    for (int n = 0; n < draws; ++n) {
        const draw<Tree> d = make_draw<Tree>(rng);
        INFO("bodies " << Tree::size << ", nv " << Tree::nv << ", draw " << n);
        check_frame(d, ch::body<Tree::size - 1>);
        check_frame(d, ch::body<Tree::size / 2>);
    }
}

// A floating trunk with two branches (a run-time axis, a prismatic joint) and a named frame on
// the second branch's tip, placed at random.
using branched = ch::tree<ch::link<-1, ch::floating>, ch::link<0, ch::revolute_about>, ch::link<1, ch::revolute_y>,
                          ch::link<0, ch::prismatic_z>, ch::link<3, ch::revolute_x>, ch::fixed_frame<"tip", 4>>;

}  // namespace

#if CTGA_TEST_PART_HOLDS(0)
TEST_CASE("frame_motion_derivatives = dual numbers through forward kinematics, body frames of random trees" CTGA_TEST_PART_NAME) {
    check_bodies<random_structure<31, 4, false>::type>(31, 4);
    check_bodies<random_structure<32, 7, true>::type>(32, 3);
}
#endif
#if CTGA_TEST_PART_HOLDS(1)
TEST_CASE("frame_motion_derivatives = dual numbers through forward kinematics, a named frame placed at random" CTGA_TEST_PART_NAME) {
    std::mt19937_64 rng(33);
    for (int n = 0; n < 4; ++n) {
        draw<branched> d = make_draw<branched>(rng);
        const double th = fs::uniform(rng, -2, 2);
        d.m.frames[0] = *ch::make_frame(ctga::rigid_motion(
            ctga::make_translator(fs::uniform(rng, -1, 1), fs::uniform(rng, -1, 1), fs::uniform(rng, -1, 1)),
            ctga::make_rotor(th, 0.6, 0.0, 0.8)));
        INFO("draw " << n);
        check_frame(d, ch::frame<"tip">);
        check_frame(d, ch::body<2>);  // another branch: the prismatic joint's columns zero
    }
}
#endif
