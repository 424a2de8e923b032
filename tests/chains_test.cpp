// Kinematic trees (include/ctga/chains/) against an independent reference: Featherstone's
// algorithms on 6D spatial vectors with 3×3 rotations and Eigen (support/featherstone.hpp,
// written without ctga). The trees' structures are types: each is drawn at compile time from a
// seed (random_structure below), 1 to 30 bodies mixing every joint type, some on a floating base;
// their parameters and states are drawn at run time, the same numbers given to both.
// PARTS: 8
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

namespace {

namespace ch = ctga::chains;
namespace fs = ctga::test::featherstone;

// ---- tree structures drawn at compile time ---------------------------------------------------

constexpr std::uint64_t splitmix(std::uint64_t& s) {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// joint kinds by number: 0–2 revolute about x, y, z; 3–5 prismatic along x, y, z; 6 revolute
// about a run-time axis; 7 prismatic along one; 8 fixed; 9 floating (body 0 only)
template <int K>
using joint_of = std::conditional_t<
    K == 0, ch::revolute_x,
    std::conditional_t<
        K == 1, ch::revolute_y,
        std::conditional_t<
            K == 2, ch::revolute_z,
            std::conditional_t<
                K == 3, ch::prismatic_x,
                std::conditional_t<
                    K == 4, ch::prismatic_y,
                    std::conditional_t<
                        K == 5, ch::prismatic_z,
                        std::conditional_t<K == 6, ch::revolute_about,
                                           std::conditional_t<K == 7, ch::prismatic_along,
                                                              std::conditional_t<K == 8, ch::fixed, ch::floating>>>>>>>>>;

template <std::uint64_t Seed, std::size_t N, bool Floating>
struct random_structure {
    struct spec {
        std::array<int, N> parent{};
        std::array<int, N> kind{};
    };
    static constexpr spec value = [] {
        spec s;
        std::uint64_t state = Seed;
        for (std::size_t i = 0; i < N; ++i) {
            const std::uint64_t r = splitmix(state);
            // half the time the previous body (long chains), else any earlier body or the world
            s.parent[i] = i == 0 ? -1 : (r & 1) ? static_cast<int>(i) - 1 : static_cast<int>((r >> 8) % (i + 1)) - 1;
            s.kind[i] = (i == 0 && Floating) ? 9 : static_cast<int>((r >> 32) % 9);
        }
        return s;
    }();
    template <std::size_t... I>
    static auto make(std::index_sequence<I...>) -> ch::tree<ch::link<value.parent[I], joint_of<value.kind[I]>>...>;
    using type = decltype(make(std::make_index_sequence<N>{}));
};

// ---- one draw of parameters and state, given to both -------------------------------------------

template <class Tree>
struct draw {
    ch::model<Tree> m;
    fs::model ref;
    ch::configuration<Tree> q{};
    Eigen::VectorXd q_ref;
    ch::joint_vector<Tree> qd{}, qdd{};
    Eigen::VectorXd qd_ref, qdd_ref;
};

template <class J>
constexpr int kind_number() {
    if constexpr (std::is_same_v<J, ch::revolute_x>) return 0;
    else if constexpr (std::is_same_v<J, ch::revolute_y>) return 1;
    else if constexpr (std::is_same_v<J, ch::revolute_z>) return 2;
    else if constexpr (std::is_same_v<J, ch::prismatic_x>) return 3;
    else if constexpr (std::is_same_v<J, ch::prismatic_y>) return 4;
    else if constexpr (std::is_same_v<J, ch::prismatic_z>) return 5;
    else if constexpr (std::is_same_v<J, ch::revolute_about>) return 6;
    else if constexpr (std::is_same_v<J, ch::prismatic_along>) return 7;
    else if constexpr (std::is_same_v<J, ch::fixed>) return 8;
    else return 9;
}

using ctga::test::motor_of;

template <class Tree>
draw<Tree> make_draw(std::mt19937_64& rng) {
    draw<Tree> d;
    d.ref.gravity = fs::vec3(fs::uniform(rng, -2, 2), fs::uniform(rng, -2, 2), -9.81);
    d.m.gravity = {d.ref.gravity[0], d.ref.gravity[1], d.ref.gravity[2]};
    d.ref.bodies.resize(Tree::size);
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            using J = typename Tree::template joint_at<I>;
            constexpr int k = kind_number<J>();
            fs::body& b = d.ref.bodies[I];
            b.parent = Tree::parent[I];
            b.kind = k <= 2 || k == 6 ? fs::joint_kind::revolute
                     : k <= 7         ? fs::joint_kind::prismatic
                     : k == 8         ? fs::joint_kind::fixed
                                      : fs::joint_kind::floating;
            b.axis = k <= 5 ? fs::vec3::Unit(k % 3) : fs::random_unit_vec3(rng);
            b.rotation = fs::random_rotation(rng);
            b.translation = fs::uniform_vec3(rng, 0.5);
            b.mass = fs::uniform(rng, 0.5, 2.0);
            b.com = fs::uniform_vec3(rng, 0.3);
            b.inertia_c = fs::random_inertia_c(rng, b.mass, 0.05, 0.3);
            const ctga::mat3<double> Ic{{{b.inertia_c(0, 0), b.inertia_c(0, 1), b.inertia_c(0, 2)},
                                         {b.inertia_c(1, 0), b.inertia_c(1, 1), b.inertia_c(1, 2)},
                                         {b.inertia_c(2, 0), b.inertia_c(2, 1), b.inertia_c(2, 2)}}};
            const auto mass = ctga::make_mass_properties(b.mass, ctga::vec3<double>{b.com[0], b.com[1], b.com[2]}, Ic);
            const auto link = [&] {
                if constexpr (ch::has_run_time_axis<J>)
                    return ch::make_link<J>(motor_of(b.rotation, b.translation), mass, ctga::vec3<double>{b.axis[0], b.axis[1], b.axis[2]});
                else return ch::make_link<J>(motor_of(b.rotation, b.translation), mass);
            }();
            REQUIRE(link);
            d.m.template link<I>() = *link;
        }(), ...);
    }(std::make_index_sequence<Tree::size>{});
    // the state: the reference's q for a floating joint is (x, y, z, qw, qx, qy, qz), ctga's the motor
    d.q_ref.resize(d.ref.nq());
    d.qd_ref.resize(d.ref.nv());
    d.qdd_ref.resize(d.ref.nv());
    for (int i = 0; i < static_cast<int>(Tree::size); ++i) {
        const fs::body& b = d.ref[i];
        const std::size_t qo = Tree::q_offset[static_cast<std::size_t>(i)];
        const int qr = d.ref.q_index(i);
        if (b.kind == fs::joint_kind::floating) {
            ctga::test::random_floating_base(rng, 0.5, d.q, qo, d.q_ref, qr);
        } else if (b.kind != fs::joint_kind::fixed) {
            d.q[qo] = d.q_ref[qr] = fs::uniform(rng, -2, 2);
        }
    }
    for (std::size_t k = 0; k < Tree::nv; ++k) {
        d.qd[k] = d.qd_ref[static_cast<Eigen::Index>(k)] = fs::uniform(rng, -2, 2);
        d.qdd[k] = d.qdd_ref[static_cast<Eigen::Index>(k)] = fs::uniform(rng, -2, 2);
    }
    return d;
}

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
enum class checks { all, kinematics_and_inverse_dynamics, forward_dynamics_and_jacobians };

template <class Tree, checks Which = checks::all>
void compare(std::uint64_t seed, int draws) {
    constexpr bool first = Which != checks::forward_dynamics_and_jacobians;
    constexpr bool second = Which != checks::kinematics_and_inverse_dynamics;
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
        if constexpr (first) {
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
            // the mass matrix
            CHECK(rel_error(ch::crba(d.m, d.q), fs::crba(d.ref, d.q_ref)) < 1e-12);
            // energies
            const double ke = fs::kinetic_energy(d.ref, d.q_ref, d.qd_ref), pe = fs::potential_energy(d.ref, d.q_ref);
            CHECK(std::abs(ch::tree_kinetic_energy(d.m, d.q, d.qd) - ke) <= 1e-12 * std::max(1.0, std::abs(ke)));
            CHECK(std::abs(ch::tree_potential_energy(d.m, d.q) - pe) <= 1e-12 * std::max(1.0, std::abs(pe)));
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
// each tree's checks in two units (each unit within the compile budget: as one unit the file took
// 46 s and 1.6 GB with g++).
#define CHAINS_CASE(part, name) TEST_CASE("chains: FK, RNEA, ABA, CRBA, Jacobians and energies agree with Featherstone's reference, " name)
#if CTGA_TEST_PART_HOLDS(0)
CHAINS_CASE(0, "1 to 7 bodies") {
    compare<random_structure<1, 1, false>::type>(11, 20);
    compare<random_structure<2, 2, false>::type>(12, 20);
    compare<random_structure<3, 5, false>::type>(13, 20);
    compare<random_structure<4, 7, true>::type>(14, 20);
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
