// The energies of a kinematic tree: the kinetic energy, §5's ½ s̄ ∨ (N ∧ s) summed over the
// bodies' velocities (the forward pass, passes.hpp), and the potential energy in the model's
// gravity, from the bodies' world poses (forward_kinematics.hpp).
#pragma once

#include <cstddef>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/forward_kinematics.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

struct tree_kinetic_energy_t {
    // ½ Σ v_i ∨ … : the kinetic energy ½ s̄ ∨ (N ∧ s) of §5, summed over the bodies, and the joints'
    // rotors' ½ a q̇² (armature, tree.hpp).
    template <class Tree, class T>
    [[nodiscard]] constexpr T operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                             const joint_vector<Tree, T>& qd) const noexcept {
        kinematics<Tree, T> k{uninitialized};
        algorithm_detail::forward_pass<algorithm_detail::pass::velocities, false>(
            k, m, q, qd.data(), static_cast<const T*>(nullptr), vec3<T>{});
        T e = T(0);
        algorithm_detail::forward<Tree::size>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            e = e + ctga::kinetic_energy(m.template link<i>().inertia, k.v[i]);
        });
        each_armature(m, [&](std::size_t j, const T& a) { e = e + T(0.5) * a * qd[j] * qd[j]; });  // the rotors' ½ a q̇²
        return e;
    }
};
inline constexpr algorithm<tree_kinetic_energy_t, "tree_kinetic_energy"> tree_kinetic_energy{};

struct tree_potential_energy_t {
    // −Σ m_i g·c_i, c_i the world position of body i's centre of mass: with the body's pose (R, t)
    // and h = m c, m_i c_i = R h + m t.
    template <class Tree, class T>
    [[nodiscard]] constexpr T operator()(const model<Tree, T>& m, const configuration<Tree, T>& q) const noexcept {
        const kinematics<Tree, T> k = forward_kinematics(m, q);
        T e = T(0);
        algorithm_detail::forward<Tree::size>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            const body_inertia<T>& N = m.template link<i>().inertia;
            const vec3<T> Rh = linear3::apply(k.pose[i].R, N.first_moment());
            const T mass = N.mass();
            e = e - (m.gravity[0] * (Rh[0] + mass * k.pose[i].t[0]) + m.gravity[1] * (Rh[1] + mass * k.pose[i].t[1]) +
                     m.gravity[2] * (Rh[2] + mass * k.pose[i].t[2]));
        });
        return e;
    }
};
inline constexpr algorithm<tree_potential_energy_t, "tree_potential_energy"> tree_potential_energy{};

}  // namespace ctga::chains
