// make_mujoco_case: a tree unit's fixture, description and ctga's results as a mujoco_case
// (chains_mujoco.hpp), so that registering a tree's MuJoCo rows is one line:
//   add_mujoco(table, make_mujoco_case("arm7", f, arm7()));                  rnea, crba and aba
//   add_mujoco(table, make_mujoco_case<algorithm::crba>("chain30", f, chain<30>()));   crba only
// The references are ch::rnea, ch::crba and ch::aba on the fixture's states, the same
// instantiations as the unit's own ctga kernels (chains_kernels.hpp): an algorithm left out of
// the list is neither computed nor instantiated (chain30 splits its algorithms over two units).
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "chains_kernels.hpp"
#include "chains_mujoco.hpp"

namespace bench::chains {

namespace mujoco_detail {

// The joint of a description's body (the benchmarks' trees have axis joints, fixed and floating
// joints; a joint about a run-time axis would be left unsupported, and the case refused).
inline mujoco_body body_of(const body_description& b) {
    mujoco_body out{b.parent, mujoco_joint::unsupported, {0, 0, 0}, b.t, b.mass, b.com, b.Ic};
    using k = sp::joint_kind;
    switch (b.kind) {
        case k::revolute_x: out.joint = mujoco_joint::hinge, out.axis = {1, 0, 0}; break;
        case k::revolute_y: out.joint = mujoco_joint::hinge, out.axis = {0, 1, 0}; break;
        case k::revolute_z: out.joint = mujoco_joint::hinge, out.axis = {0, 0, 1}; break;
        case k::prismatic_x: out.joint = mujoco_joint::slide, out.axis = {1, 0, 0}; break;
        case k::prismatic_y: out.joint = mujoco_joint::slide, out.axis = {0, 1, 0}; break;
        case k::prismatic_z: out.joint = mujoco_joint::slide, out.axis = {0, 0, 1}; break;
        case k::revolute_axis:
        case k::prismatic_axis: break;
        case k::fixed: out.joint = mujoco_joint::fixed; break;
        case k::floating: out.joint = mujoco_joint::free; break;
    }
    return out;
}

}  // namespace mujoco_detail

// The case of fixture f (its model built from description d); A...: the algorithms whose
// references to compute (none listed: rnea, crba and aba). An empty case without MuJoCo.
template <algorithm... A, class Tree>
mujoco_case make_mujoco_case(const std::string& label, [[maybe_unused]] const fixture<Tree>& f,
                             [[maybe_unused]] const description<Tree::size>& d) {
    [[maybe_unused]] constexpr auto wanted = [](algorithm a) { return sizeof...(A) == 0 || ((A == a) || ...); };
    mujoco_case c;
    c.label = label;
    if constexpr (mujoco_enabled) {  // (without MuJoCo, nothing of this is compiled)
        for (const auto& b : d) c.bodies.push_back(mujoco_detail::body_of(b));
        c.gravity = {f.m.gravity[0], f.m.gravity[1], f.m.gravity[2]};
        c.nv = Tree::nv;
        for (std::size_t i = 0; i < Tree::size; ++i) c.nq += Tree::nq_of[i] == 8 ? 7 : Tree::nq_of[i];
        for (const state<Tree>& s : f.states) {
            std::vector<double> q;
            for (std::size_t i = 0; i < Tree::size; ++i) {
                const std::size_t o = Tree::q_offset[i];
                if (Tree::nq_of[i] == 8) {  // the floating joint's motor: its map's translation, its rotor
                    ctga::motor<double> g{};
                    for (std::size_t k = 0; k < 8; ++k) g[k] = s.q[o + k];
                    const auto G = ctga::map_of(g);
                    const double n = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + g[3] * g[3]);
                    q.insert(q.end(), {G.t[0], G.t[1], G.t[2], g[0] / n, g[1] / n, g[2] / n, g[3] / n});
                } else if (Tree::nq_of[i] == 1) {
                    q.push_back(s.q[o]);
                } else if (Tree::nq_of[i] != 0) {
                    throw std::logic_error("make_mujoco_case: a joint of " + std::to_string(Tree::nq_of[i]) + " coordinates");
                }
            }
            c.q.push_back(std::move(q));
            c.qd.emplace_back(s.qd.begin(), s.qd.end());
            c.qdd.emplace_back(s.qdd.begin(), s.qdd.end());
            c.tau.emplace_back(s.tau.begin(), s.tau.end());
            if constexpr (wanted(algorithm::rnea)) {
                const auto tau = ch::rnea(f.m, s.q, s.qd, s.qdd);
                c.tau_ref.emplace_back(tau.begin(), tau.end());
            }
            if constexpr (wanted(algorithm::crba)) {
                const auto H = ch::crba(f.m, s.q);
                std::vector<double> h(Tree::nv * Tree::nv);
                for (std::size_t i = 0; i < Tree::nv; ++i)
                    for (std::size_t j = 0; j < Tree::nv; ++j) h[i * Tree::nv + j] = H[i][j];
                c.H_ref.push_back(std::move(h));
            }
            if constexpr (wanted(algorithm::aba)) {
                const auto qdd = ch::aba(f.m, s.q, s.qd, s.tau);
                c.qdd_ref.emplace_back(qdd.begin(), qdd.end());
            }
        }
    }
    return c;
}

}  // namespace bench::chains
