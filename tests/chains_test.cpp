// Kinematic trees (include/ctga/chains/) against an independent reference: Featherstone's
// algorithms on 6D spatial vectors with 3×3 rotations and Eigen (support/featherstone.hpp,
// written without ctga). The trees' structures are types: each is drawn at compile time from a
// seed (random_structure below), 1 to 30 bodies mixing every joint type, some on a floating base,
// and the benchmarks' 39-body humanoid with joint kinds drawn at random (random_kinds);
// their parameters and states are drawn at run time, the same numbers given to both.
// PARTS: 12
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>

#include <Eigen/Dense>

#include <ctga/chains/algorithms.hpp>

#include "support/catch.hpp"
#include "support/featherstone.hpp"
#include "support/relative_error.hpp"
#include "support/parts.hpp"
#include "support/random_floating_base.hpp"
#include "support/random_tree.hpp"
#include "support/random_structure.hpp"
#include "../bench/chain_trees.hpp"  // the benchmarks' humanoid: its shape

namespace {

namespace ch = ctga::chains;
namespace fs = ctga::test::featherstone;
using ctga::test::random_structure;
using ctga::test::draw;
using ctga::test::make_draw;

using ctga::test::rel_error;

template <class Tree, std::size_t I>
void check_jacobians(const draw<Tree>& d) {
    const ch::jacobian_matrix<Tree> Jb = ch::frame_jacobian(d.m, d.q, ch::body<I>, ch::reference::local);
    const ch::jacobian_matrix<Tree> Jw = ch::frame_jacobian(d.m, d.q, ch::body<I>, ch::reference::world);
    const Eigen::MatrixXd Jb_ref = fs::jacobian_body(d.ref, d.q_ref, static_cast<int>(I));
    const Eigen::MatrixXd Jw_ref = fs::jacobian_world(d.ref, d.q_ref, static_cast<int>(I));
    INFO("body " << I);
    for (std::size_t c = 0; c < Tree::nv; ++c) {
        const auto col = static_cast<Eigen::Index>(c);
        CHECK(rel_error(Jb[c], Eigen::VectorXd(Jb_ref.col(col))) < 1e-12);
        CHECK(rel_error(Jw[c], Eigen::VectorXd(Jw_ref.col(col))) < 1e-12);
    }
}

// Which checks a unit compiles: all, or one of two halves (a 30-body tree's algorithms are 30
// unrolled bodies each; Clang took 90 s for one unit with all of them).
// (the humanoid's first half is itself two units: kinematics, RNEA and energies; the mass matrix)
enum class checks { all, kinematics_and_inverse_dynamics, forward_dynamics_and_jacobians, kinematics_only, mass_matrix_only };

template <class Tree, checks Which = checks::all>
void compare(std::uint64_t seed, int draws) {
    constexpr bool first = Which == checks::all || Which == checks::kinematics_and_inverse_dynamics ||
                           Which == checks::kinematics_only || Which == checks::mass_matrix_only;
    constexpr bool kinematics = first && Which != checks::mass_matrix_only;
    constexpr bool mass_matrix = first && Which != checks::kinematics_only;
    constexpr bool second = Which == checks::all || Which == checks::forward_dynamics_and_jacobians;
    std::mt19937_64 rng(seed);
    for (int n = 0; n < draws; ++n) {
        const draw<Tree> d = make_draw<Tree>(rng);
        INFO("bodies " << Tree::size << ", nv " << Tree::nv << ", draw " << n);
        ch::body_wrenches<Tree> f{};
        std::vector<fs::vec6> f_ref(Tree::size);
        for (std::size_t i = 0; i < Tree::size; ++i)
            for (std::size_t c = 0; c < 6; ++c) f[i][c] = f_ref[i][static_cast<int>(c)] = fs::uniform(rng, -1, 1);
        ch::joint_vector<Tree> tau{};
        Eigen::VectorXd tau_ref(static_cast<Eigen::Index>(Tree::nv));
        for (std::size_t c = 0; c < Tree::nv; ++c) tau[c] = tau_ref[static_cast<Eigen::Index>(c)] = fs::uniform(rng, -5, 5);
        if constexpr (kinematics) {
            // forward kinematics: poses, velocities, accelerations
            const ch::kinematics<Tree> k = ch::forward_kinematics(d.m, d.q, d.qd, d.qdd);
            const fs::kinematics kr = fs::fk(d.ref, d.q_ref, d.qd_ref, d.qdd_ref);
            for (std::size_t i = 0; i < Tree::size; ++i) {
                const auto& br = kr.bodies[i];
                for (int r = 0; r < 3; ++r) {
                    CHECK(std::abs(k.pose[i].t[static_cast<std::size_t>(r)] - br.origin[r]) < 1e-12 * 10);
                    for (int c = 0; c < 3; ++c)
                        CHECK(std::abs(k.pose[i].R[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] - br.rotation(r, c)) < 1e-12);
                }
                CHECK(rel_error(k.v[i], br.velocity) < 1e-12);
                CHECK(rel_error(k.a[i], br.acceleration) < 1e-12);
            }
            // inverse dynamics, with and without external wrenches
            CHECK(rel_error(ch::rnea(d.m, d.q, d.qd, d.qdd), fs::rnea(d.ref, d.q_ref, d.qd_ref, d.qdd_ref)) < 1e-12);
            CHECK(rel_error(ch::rnea(d.m, d.q, d.qd, d.qdd, f), fs::rnea(d.ref, d.q_ref, d.qd_ref, d.qdd_ref, f_ref)) < 1e-12);
            // energies
            const double ke = fs::kinetic_energy(d.ref, d.q_ref, d.qd_ref), pe = fs::potential_energy(d.ref, d.q_ref);
            CHECK(std::abs(ch::tree_kinetic_energy(d.m, d.q, d.qd) - ke) <= 1e-12 * std::max(1.0, std::abs(ke)));
            CHECK(std::abs(ch::tree_potential_energy(d.m, d.q) - pe) <= 1e-12 * std::max(1.0, std::abs(pe)));
        }
        if constexpr (mass_matrix) {
            // the mass matrix, in both of CRBA's forms (crba.hpp; ch::crba takes the cheaper)
            const Eigen::MatrixXd H_ref = fs::crba(d.ref, d.q_ref);
            CHECK(rel_error(ch::crba(d.m, d.q), H_ref) < 1e-12);
            CHECK(rel_error(ch::algorithm_detail::crba_local(d.m, d.q), H_ref) < 1e-12);
            CHECK(rel_error(ch::algorithm_detail::crba_world(d.m, d.q), H_ref) < 1e-12);
        }
        if constexpr (second) {
            // forward dynamics, with and without external wrenches
            CHECK(rel_error(ch::aba(d.m, d.q, d.qd, tau), fs::aba(d.ref, d.q_ref, d.qd_ref, tau_ref)) < 1e-12);
            CHECK(rel_error(ch::aba(d.m, d.q, d.qd, tau, f), fs::aba(d.ref, d.q_ref, d.qd_ref, tau_ref, f_ref)) < 1e-12);
            // Jacobians of the last body and of a middle one, in its own frame and in the world's
            check_jacobians<Tree, Tree::size - 1>(d);
            check_jacobians<Tree, Tree::size / 2>(d);
        }
    }
}

}  // namespace

// Part 0: small trees; 1, 2 and 7: twelve bodies (7: the repeated legs); 3 to 6: thirty bodies,
// 8, 9 and 11: the humanoid, 10: small trees with aligned joints, each tree's checks in two units (each unit within the compile budget: as one unit the file took
// 46 s and 1.6 GB with g++).
#define CHAINS_CASE(part, name) TEST_CASE("chains: FK, RNEA, ABA, CRBA, Jacobians and energies agree with Featherstone's reference, " name)
#if CTGA_TEST_PART_HOLDS(0)
CHAINS_CASE(0, "1 to 7 bodies") {
    compare<random_structure<1, 1, false>::type>(11, 20);
    compare<random_structure<2, 2, false>::type>(12, 20);
    compare<random_structure<3, 5, false>::type>(13, 20);
    compare<random_structure<4, 7, true, false, true>::type>(14, 20);  // (with armatures)
}
#endif
#if CTGA_TEST_PART_HOLDS(10)
// About half the joints aligned (placements translations: each body's map a turn about an axis, or
// none, whose zeros the transforms skip), on a fixed and on a floating base.
CHAINS_CASE(10, "aligned joints") {
    compare<random_structure<41, 7, false, true, true>::type>(41, 20);
    compare<random_structure<42, 9, true, true, true>::type>(42, 20);
}
#endif
#if CTGA_TEST_PART_HOLDS(1)
CHAINS_CASE(1, "12 bodies") { compare<random_structure<5, 12, false>::type>(15, 10); }
// A chain whose bodies repeat (revolute y, prismatic x, revolute about an axis) hanging each from
// the previous: one run of four repeats, executed as a loop (chains/runs.hpp).
using repeating_chain = ch::tree<ch::link<-1, ch::revolute_z>,                                                  //
                                 ch::link<0, ch::revolute_y>, ch::link<1, ch::prismatic_x>, ch::link<2, ch::revolute_about>,  //
                                 ch::link<3, ch::revolute_y>, ch::link<4, ch::prismatic_x>, ch::link<5, ch::revolute_about>,  //
                                 ch::link<6, ch::revolute_y>, ch::link<7, ch::prismatic_x>, ch::link<8, ch::revolute_about>,  //
                                 ch::link<9, ch::revolute_y>, ch::link<10, ch::prismatic_x>, ch::link<11, ch::revolute_about>,
                                 ch::link<12, ch::revolute_x>>;
static_assert(ch::run_detail::plan<repeating_chain>::count == 3 && ch::run_detail::plan<repeating_chain>::at(1).repeats == 4,
              "the repeating chain is body 0, a run of 4 × 3 bodies, body 13");
CHAINS_CASE(1, "a chain of repeated bodies (a run)") { compare<repeating_chain>(19, 10); }
#endif
#if CTGA_TEST_PART_HOLDS(2)
CHAINS_CASE(2, "12 bodies on a floating base") { compare<random_structure<6, 12, true>::type>(16, 10); }
#endif
#if CTGA_TEST_PART_HOLDS(7)
// Three legs on a floating trunk, each hanging from the trunk (absolute) and along itself
// (relative), with a fixed link at the end, and a last body that breaks the pattern: a run of
// three repeats of four bodies.
using repeating_legs = ch::tree<ch::link<-1, ch::floating>,                                                       //
                                ch::link<0, ch::revolute_x>, ch::link<1, ch::revolute_y>, ch::link<2, ch::prismatic_along>,  //
                                ch::link<3, ch::fixed>,                                                           //
                                ch::link<0, ch::revolute_x>, ch::link<5, ch::revolute_y>, ch::link<6, ch::prismatic_along>,  //
                                ch::link<7, ch::fixed>,                                                           //
                                ch::link<0, ch::revolute_x>, ch::link<9, ch::revolute_y>, ch::link<10, ch::prismatic_along>,  //
                                ch::link<11, ch::fixed>, ch::link<0, ch::revolute_about>>;
static_assert(ch::run_detail::plan<repeating_legs>::count == 3 && ch::run_detail::plan<repeating_legs>::at(1).repeats == 3 &&
                  ch::run_detail::plan<repeating_legs>::at(1).length == 4,
              "the legs are body 0, a run of 3 × 4 bodies, body 13");
CHAINS_CASE(7, "legs of repeated bodies on a floating base (a run)") { compare<repeating_legs>(20, 10); }
#endif
#if CTGA_TEST_PART_HOLDS(3)
CHAINS_CASE(3, "30 bodies: FK, RNEA, CRBA, energies") {
    compare<random_structure<7, 30, false>::type, checks::kinematics_and_inverse_dynamics>(17, 5);
}
#endif
#if CTGA_TEST_PART_HOLDS(4)
CHAINS_CASE(4, "30 bodies: ABA, Jacobians") {
    compare<random_structure<7, 30, false>::type, checks::forward_dynamics_and_jacobians>(17, 5);
}
#endif
#if CTGA_TEST_PART_HOLDS(8) || CTGA_TEST_PART_HOLDS(9) || CTGA_TEST_PART_HOLDS(11)
// The humanoid's shape (39 bodies on a floating base) with every joint but the base's drawn, about
// half of them aligned: a tree visited by kind (runs.hpp), CRBA in body frames.
using random_humanoid = ctga::test::random_kinds<31, bench::chains::humanoid_tree, true>::type;  // half aligned
static_assert(ch::run_detail::plan<random_humanoid>::at(0).by_kind, "the humanoid is visited by kind");
#endif
#if CTGA_TEST_PART_HOLDS(8)
CHAINS_CASE(8, "a humanoid: FK, RNEA, energies") { compare<random_humanoid, checks::kinematics_only>(21, 3); }
#endif
#if CTGA_TEST_PART_HOLDS(11)
// (as one unit with part 8 it took 30.6 s under -j2 in the fresh-clone build)
CHAINS_CASE(11, "a humanoid: CRBA in both forms") { compare<random_humanoid, checks::mass_matrix_only>(21, 3); }
#endif
#if CTGA_TEST_PART_HOLDS(9)
CHAINS_CASE(9, "a humanoid: ABA, Jacobians") { compare<random_humanoid, checks::forward_dynamics_and_jacobians>(21, 3); }
#endif
#if CTGA_TEST_PART_HOLDS(5)
CHAINS_CASE(5, "30 bodies on a floating base: FK, RNEA, CRBA, energies") {
    compare<random_structure<8, 30, true>::type, checks::kinematics_and_inverse_dynamics>(18, 5);
}
#endif
#if CTGA_TEST_PART_HOLDS(6)
CHAINS_CASE(6, "30 bodies on a floating base: ABA, Jacobians") {
    compare<random_structure<8, 30, true>::type, checks::forward_dynamics_and_jacobians>(18, 5);
}
#endif
