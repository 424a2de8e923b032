// The kernels of ctga_chains_bench (bench/chains.cpp): one non-inlined call (chain_kernel) of an
// algorithm on a tree, in ctga or in the hand-written spatial code, registered as
// <algorithm>_<tree>/<implementation>; jacobian is the local Jacobian of the tree's frame 0. Each tree's kernels are instantiated in their own
// translation unit (chains_arm7.cpp, …), so that no unit compiles every tree.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "chain_models.hpp"
#include "runner.hpp"

namespace bench::chains {

enum class algorithm { fk, rnea, crba, aba, jacobian };
enum class implementation { ctga, spatial };

template <class Tree>
struct fixture {
    static constexpr std::size_t n = Tree::size;
    ch::model<Tree> m;
    sp::model<n> sm;
    std::array<state<Tree>, 64> states;
    spatial::se3 frame = spatial_frame();  // frame 0's placement (the Jacobians')
};

template <class Tree>
fixture<Tree> make_fixture(const description<Tree::size>& d, std::uint64_t seed) {
    return {ctga_model<Tree>(d), spatial_model(d), random_states<Tree>(seed)};
}

template <algorithm A, implementation I, class Tree>
[[gnu::noinline]] auto chain_kernel(const fixture<Tree>& f, const state<Tree>& s) {
    if constexpr (I == implementation::ctga) {
        if constexpr (A == algorithm::fk) return ch::forward_kinematics(f.m, s.q, s.qd, s.qdd);
        else if constexpr (A == algorithm::rnea) return ch::rnea(f.m, s.q, s.qd, s.qdd);
        else if constexpr (A == algorithm::crba) return ch::crba(f.m, s.q);
        else if constexpr (A == algorithm::jacobian) return ch::frame_jacobian(f.m, s.q, ch::frame_at<0>, ch::reference::local);
        else return ch::aba(f.m, s.q, s.qd, s.tau);
    } else {
        if constexpr (A == algorithm::fk) {
            sp::kinematics<Tree::size> k;
            sp::fk(f.sm, s.q_spatial.data(), s.qd.data(), s.qdd.data(), k);
            return k;
        } else if constexpr (A == algorithm::rnea) {
            ch::joint_vector<Tree> tau;
            sp::rnea(f.sm, s.q_spatial.data(), s.qd.data(), s.qdd.data(), nullptr, tau.data());
            return tau;
        } else if constexpr (A == algorithm::crba) {
            std::array<double, Tree::nv * Tree::nv> H;
            sp::crba(f.sm, s.q_spatial.data(), H.data());
            return H;
        } else if constexpr (A == algorithm::jacobian) {
            std::array<double, 6 * Tree::nv> J;
            sp::frame_jacobian(f.sm, s.q_spatial.data(), static_cast<std::size_t>(Tree::frame_body[0]), f.frame, true, J.data());
            return J;
        } else {
            ch::joint_vector<Tree> qdd;
            sp::aba(f.sm, s.q_spatial.data(), s.qd.data(), s.tau.data(), nullptr, qdd.data());
            return qdd;
        }
    }
}

using bench::entry;

template <algorithm A, implementation I, class Tree>
void add(std::vector<entry>& table, const std::string& name, const fixture<Tree>& f) {
    const fixture<Tree>* p = &f;
    table.push_back({name,
                     [p](benchmark::State& st) {
                         std::size_t k = 0;
                         for (auto _ : st) {
                             auto r = chain_kernel<A, I>(*p, p->states[k]);
                             benchmark::DoNotOptimize(r);
                             k = (k + 1) & 63;
                         }
                     },
                     [p](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) {
                             auto r = chain_kernel<A, I>(*p, p->states[i & 63]);
                             benchmark::DoNotOptimize(r);
                         }
                     }});
}

// Registers algorithms A... of one tree, in both implementations: <algorithm>_<label>/<implementation>.
constexpr const char* name_of(algorithm a) {
    return a == algorithm::fk ? "fk" : a == algorithm::rnea ? "rnea" : a == algorithm::crba ? "crba" : a == algorithm::aba ? "aba" : "jacobian";
}
template <algorithm... A, class Tree>
void add_tree(std::vector<entry>& table, const std::string& label, const fixture<Tree>& f) {
    (  // rnea_arm7/ctga, rnea_chain/8/spatial, …
        [&] {
            const std::string name = std::string(name_of(A)) + "_" + label;
            add<A, implementation::ctga>(table, name + "/ctga", f);
            add<A, implementation::spatial>(table, name + "/spatial", f);
        }(),
        ...);
}

// the tables of each translation unit
void add_arm7(std::vector<entry>& table);
void add_chain30(std::vector<entry>& table);  // RNEA and ABA
void add_chain30_crba_fk(std::vector<entry>& table);
void add_legged(std::vector<entry>& table);  // and the quadruped
void add_constrained(std::vector<entry>& table);  // the quadruped's feet held (constrained/)
void add_humanoid_contact(std::vector<entry>& table);  // the humanoid lying on the ground (chains_humanoid_contact.cpp)
void add_grasp_contact(std::vector<entry>& table);  // a gripper holding a cube (chains_grasp_contact.cpp)
void add_humanoid(std::vector<entry>& table);
void add_scaling(std::vector<entry>& table);  // CTGA_CHAINS_SCALING: chains of those sizes
void add_derivatives_arm7(std::vector<entry>& table);  // the derivatives (chains_derivatives.hpp)
void add_derivatives_chain30(std::vector<entry>& table);      // rnea_derivatives, minverse
void add_derivatives_chain30_aba(std::vector<entry>& table);  // aba_derivatives
void add_derivatives_legged(std::vector<entry>& table);
// the real robots' tables (chains_robot.cpp, one unit per robot, each registering itself here)
inline std::vector<void (*)(std::vector<entry>&)>& robot_tables() {
    static std::vector<void (*)(std::vector<entry>&)> tables;
    return tables;
}

}  // namespace bench::chains
