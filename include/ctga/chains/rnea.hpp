// Inverse dynamics τ(q, q̇, q̈) of a kinematic tree: the recursive Newton–Euler algorithm
// (Featherstone (2008) §5.3). The forward pass (passes.hpp) gives each body's velocity v_i and
// acceleration a_i in its own frame, the world's acceleration −g standing for gravity; then, with
// ×* the coadjoint action {s, P} of §6,
//
//   f_i = N_i a_i + v_i ×* (N_i v_i) − f_ext,i         (N s = A ∨ (N ∧ s), the momentum of §5)
//   τ_i = f_i(S_i) = f_i ∨ (Q0 ∧ S_i),  f_λ += X_i f_i  (the pairing of §5; ḡ f ḡ* moves f out)
// and a mimic joint's r f_i(S_i) is added to its master's τ; a joint's armature a_i adds a_i q̈_i.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

namespace algorithm_detail {
template <class Tree, class T>
constexpr joint_vector<Tree, T> rnea(const model<Tree, T>& m, const configuration<Tree, T>& q, const joint_vector<Tree, T>& qd,
                                     const joint_vector<Tree, T>& qdd, const body_wrenches<Tree, T>* f_ext) noexcept {
    auto f = uninitialized_array<coscrew<T>, Tree::size>();
    kinematics<Tree, T> k{uninitialized};
    forward_pass<pass::accelerations, false>(
        k, m, q, qd.data(), qdd.data(), minus(m.gravity), [&](const auto& body, const kinematics<Tree, T>& kb) {
            const std::size_t i = body.i;
            const auto& N = body.link(m).inertia;
            // f_i = N a_i + v_i ×* (N v_i) − f_ext
            f[i] = momentum(N, kb.a[i]) + coadjoint(kb.v[i], momentum(N, kb.v[i]));
            if (f_ext) f[i] = f[i] - (*f_ext)[i];
        });
    joint_vector<Tree, T> tau{};
    each_body_backward(m, [&](const auto& body) {
        using B = std::remove_cvref_t<decltype(body)>;
        using J = typename B::joint;
        const std::size_t i = body.i;
        const auto& L = body.link(m);
        if constexpr (J::nv > 0)
            [&]<std::size_t... K>(std::index_sequence<K...>) {
                ((tau[body.v_own + K] = pairing(f[i], J::template subspace<K, T>(L.joint))), ...);
            }(std::make_index_sequence<J::nv>{});
        if constexpr (!B::root) f[body.p] = f[body.p] + transform<map_shape<J>>(k.X[i], f[i]);
    });
    // a joint's armature a_k: τ_k += a_k q̈_k (its rotor, reflected onto the joint)
    each_armature(m, [&](std::size_t dof, const T& a) { tau[dof] += a * qdd[dof]; });
    // a mimic joint's torque r f_i(S_i) goes to its master (τ = Gᵀ τ_all, joints.hpp); f_i is final
    // once body i has passed it on
    if constexpr (Tree::has_mimic)
        forward<Tree::size>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            using J = typename Tree::template joint_at<i>;
            if constexpr (is_mimic<J>) {
                const auto& L = m.template link<i>();
                tau[Tree::v_offset[J::master]] += L.joint.multiplier * pairing(f[i], J::template subspace<0, T>(L.joint));
            }
        });
    return tau;
}
}  // namespace algorithm_detail

struct rnea_t {
    // τ = ID(q, q̇, q̈): the joint forces that give the bodies acceleration q̈ under gravity.
    template <class Tree, class T>
    [[nodiscard]] constexpr joint_vector<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                       const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& qdd) const noexcept {
        return algorithm_detail::rnea(m, q, qd, qdd, static_cast<const body_wrenches<Tree, T>*>(nullptr));
    }
    // … with an external wrench acting on each body (body frame, about the body's origin).
    template <class Tree, class T>
    [[nodiscard]] constexpr joint_vector<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                       const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& qdd,
                                                       const body_wrenches<Tree, T>& f_ext) const noexcept {
        return algorithm_detail::rnea(m, q, qd, qdd, &f_ext);
    }
};
inline constexpr algorithm<rnea_t, "rnea"> rnea{};

}  // namespace ctga::chains
