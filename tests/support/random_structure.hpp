// Random kinematic trees drawn at compile time from a seed (their structure is a type: 1 to 30
// bodies mixing every joint type, some on a floating base; or a given shape with random joint
// kinds), and one draw of parameters and state
// given both to ctga and to the Featherstone reference (support/featherstone.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <type_traits>
#include <utility>

#include <Eigen/Dense>

#include <ctga/chains/tree.hpp>
#include <ctga/chains/passes.hpp>

#include "support/catch.hpp"
#include "support/featherstone.hpp"
#include "support/random_floating_base.hpp"
#include "support/random_tree.hpp"

namespace ctga::test {

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
// about a run-time axis; 7 prismatic along one; 8 fixed; 9 floating (body 0 only); K + 10: the
// same joint turned (ch::turned<turn_number<K / 100>, …>: its placement's rotation one of the 24
// signed permutations that are rotations, number 0 the identity: ch::aligned); K + 20 (K % 100 <
// 8): with an armature (ch::with_armature), turned or not
template <int K>
using plain_joint_of = std::conditional_t<
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
template <int K>
using geared_of = std::conditional_t<(K < 20), plain_joint_of<K % 10>, ch::with_armature<plain_joint_of<(K % 20 < 8 ? K % 10 : 0)>>>;
// the N-th rotation among the signed permutations (N < 24; 0: the identity)
constexpr ch::turn turn_number(int n) {
    const ch::axis plus[3] = {ch::axis::x, ch::axis::y, ch::axis::z}, minus[3] = {ch::axis::minus_x, ch::axis::minus_y, ch::axis::minus_z};
    int found = 0;
    for (int p = 0; p < 6; ++p)  // the permutations of (0, 1, 2), the identity first
        for (int signs = 0; signs < 8; ++signs) {
            const int i = p / 2, j = (i + 1 + p % 2) % 3, k = 3 - i - j;
            const ch::turn t{(signs & 1) ? minus[i] : plus[i], (signs & 2) ? minus[j] : plus[j], (signs & 4) ? minus[k] : plus[k]};
            if (t.is_rotation() && found++ == n) return t;
        }
    return {};
}
template <int K>
using joint_of = std::conditional_t<(K % 20 < 10), geared_of<K % 100>, ch::turned<turn_number(K / 100), geared_of<K % 100>>>;

// + 10: turned, half of those aligned (turn number 0), the others by a turn drawn from r
constexpr int turned_kind(std::uint64_t r) { return 10 + (((r >> 40) & 1) ? 0 : 100 * static_cast<int>(1 + (r >> 41) % 23)); }

template <std::uint64_t Seed, std::size_t N, bool Floating, bool Aligned = false, bool Armature = false>
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
            if (Aligned && ((r >> 24) & 1)) s.kind[i] += turned_kind(r);  // about half the joints turned
            if (Armature && s.kind[i] % 10 < 8 && i % 3 == 1) s.kind[i] += 20;  // every third body's, if 1-dof
        }
        return s;
    }();
    template <std::size_t... I>
    static auto make(std::index_sequence<I...>) -> ch::tree<ch::link<value.parent[I], joint_of<value.kind[I]>>...>;
    using type = decltype(make(std::make_index_sequence<N>{}));
};

// A tree of the given shape (parents, body 0 on a floating joint) with the other joint kinds
// drawn from the seed: the benchmarks' humanoid (bench/chain_trees.hpp) as a random tree.
template <std::uint64_t Seed, class Shape, bool Aligned = false>
struct random_kinds {
    static constexpr std::size_t N = Shape::size;
    static constexpr std::array<int, N> kind = [] {
        std::array<int, N> k{};
        std::uint64_t state = Seed;
        for (std::size_t i = 0; i < N; ++i) {
            const std::uint64_t r = splitmix(state);
            k[i] = i == 0 ? 9 : static_cast<int>((r >> 32) % 9);
            if (Aligned && ((r >> 24) & 1)) k[i] += turned_kind(r);
        }
        return k;
    }();
    template <std::size_t... I>
    static auto make(std::index_sequence<I...>) -> ch::tree<ch::link<Shape::parent[I], joint_of<kind[I]>>...>;
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

// J without turned<…>: the joint the reference is given (with the turn's rotation when turned)
template <class J>
struct plain {
    using type = J;
};
template <ch::turn P, class J>
struct plain<ch::turned<P, J>> {
    using type = typename plain<J>::type;
};
template <class J>
struct plain<ch::with_armature<J>> {
    using type = J;
};
template <class J>
using plain_of = typename plain<J>::type;

// a turn's rotation as the reference's matrix
inline fs::mat3 turn_rotation(const ch::turn& P) {
    const ctga::mat3<double> R = ch::turn_matrix<double>(P);
    fs::mat3 out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out(i, j) = R[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    return out;
}

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


template <class Tree>
draw<Tree> make_draw(std::mt19937_64& rng) {
    draw<Tree> d;
    d.ref.gravity = fs::vec3(fs::uniform(rng, -2, 2), fs::uniform(rng, -2, 2), -9.81);
    d.m.gravity = {d.ref.gravity[0], d.ref.gravity[1], d.ref.gravity[2]};
    d.ref.bodies.resize(Tree::size);
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ([&] {
            using J = typename Tree::template joint_at<I>;
            constexpr int k = kind_number<plain_of<J>>();
            fs::body& b = d.ref.bodies[I];
            b.parent = Tree::parent[I];
            b.kind = k <= 2 || k == 6 ? fs::joint_kind::revolute
                     : k <= 7         ? fs::joint_kind::prismatic
                     : k == 8         ? fs::joint_kind::fixed
                                      : fs::joint_kind::floating;
            b.axis = k <= 5 ? fs::vec3::Unit(k % 3) : fs::random_unit_vec3(rng);
            b.rotation = ch::is_turned<J> ? turn_rotation(ch::placement_turn<J>) : fs::random_rotation(rng);
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
            // a joint with an armature: 0.1 × its body's mass (from the numbers drawn)
            if constexpr (ch::has_armature<J>) d.m.template link<I>().armature = b.armature = 0.1 * b.mass;
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

}  // namespace ctga::test
