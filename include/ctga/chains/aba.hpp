// Forward dynamics q̈(q, q̇, τ) of a kinematic tree: the articulated body algorithm
// (Featherstone (2008) §7.3), with the articulated inertias as articulated_inertia
// (mechanics/articulated_inertia.hpp).
//
// Three passes (Featherstone Table 7.1), in body coordinates:
//   out:  v_i = X_i⁻¹ v_λ + S_i q̇_i,  c_i = v_i × S_i q̇_i,  N^A_i = N_i,  p^A_i = v_i ×* (N_i v_i) − f_ext,i
//   in:   U_i = N^A_i S_i,  D_i = U_i(S_i) + a_i (a_i: the joint's armature, tree.hpp),  u_i = τ_i − p^A_i(S_i), and the parent receives
//         N^A_λ += X_i (N^A_i − U_i U_iᵀ/D_i),  p^A_λ += X_i (p^a_i),
//         p^a_i = p^A_i + N^a_i c_i + U_i u_i/D_i
//   out:  a'_i = X_i⁻¹ a_λ + c_i,  q̈_i = (u_i − U_i(a'_i))/D_i,  a_i = a'_i + S_i q̈_i
// N^A is an articulated_inertia (21 entries, moved by (g ḡ) N (g ḡ)*); U = N^A S, the pairings
// and N^a c are the engine's formulas, so an axis joint's S (one blade) takes one column of N^A
// and one component of each co-screw, and c = v × S q̇ has the bracket's four non-zero blades.
// A floating joint (S = 1): q̈ = (N^A)⁻¹(τ − p^A) − a' and the parent receives no inertia and
// the force τ (N^a = N^A − N^A (N^A)⁻¹ N^A = 0, p^a = p^A + (τ − p^A)).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/crba.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/rnea.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/articulated_inertia.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/operations/evaluate.hpp"
#include "ctga/support/cholesky.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

namespace algorithm_detail {
// The screw component an axis joint's S lies on, where N^a = N^A − U Uᵀ/D has a zero row and
// column; 6 for any other joint.
// (With an armature a, N^a S = U a/D: no component is zero.)
template <class J>
constexpr std::size_t null_component() {
    if constexpr (requires { J::component; } && !has_armature<J>) return J::component;
    else return 6;
}
// A tree with mimic joints (joints.hpp) couples a mimic and its master, often on different
// branches (two gripper fingers), which ABA's recursion cannot take: its forward dynamics solves
// H q̈ = τ − C(q, q̇) with H = Gᵀ H_all G (crba) and C = rnea(q, q̇, 0) (with the external
// wrenches), by Cholesky. A singular H gives NaN (massless_subtree names the cause beforehand).
template <class Tree, class T>
constexpr joint_vector<Tree, T> coupled_forward_dynamics(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                         const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& tau,
                                                         const body_wrenches<Tree, T>* f_ext) noexcept {
    const joint_vector<Tree, T> zero{};
    const joint_vector<Tree, T> C = f_ext ? chains::rnea(m, q, qd, zero, *f_ext) : chains::rnea(m, q, qd, zero);
    joint_vector<Tree, T> b;
    for (std::size_t i = 0; i < Tree::nv; ++i) b[i] = tau[i] - C[i];
    const auto L = cholesky(chains::crba(m, q));
    if (!L) {
        b.fill(std::numeric_limits<T>::quiet_NaN());
        return b;
    }
    return cholesky_solve(*L, b);
}

// The three passes above (a tree without mimic joints).
template <class Tree, class T>
constexpr joint_vector<Tree, T> articulated_body(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                 const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& tau,
                                                 const body_wrenches<Tree, T>* f_ext) noexcept {
    // p^A_i = v_i ×* (N_i v_i) − f_ext,i while v_i is at hand
    kinematics<Tree, T> k{uninitialized};
    auto pA = uninitialized_array<coscrew<T>, Tree::size>();
    forward_pass<pass::velocities, false>(k, m, q, qd.data(), static_cast<const T*>(nullptr), vec3<T>{},
                                          [&](const auto& b, const kinematics<Tree, T>& kb) {
                                              const auto& N = b.link(m).inertia;
                                              pA[b.i] = coadjoint(kb.v[b.i], momentum(N, kb.v[b.i]));
                                              if (f_ext) pA[b.i] = pA[b.i] - (*f_ext)[b.i];
                                          });
    // N^A_i = N_i (built element by element)
    std::array<articulated_inertia<T>, Tree::size> NA = [&]<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<articulated_inertia<T>, Tree::size>{articulated_inertia_of(m.template link<I>().inertia)...};
    }(std::make_index_sequence<Tree::size>{});
    // c_i = v_i × S_i q̇_i in the bracket's own sparse type: four blades for an axis joint (nv = 1, 6 only)
    const auto bias = [&](const auto& b) {
        using J = typename std::remove_cvref_t<decltype(b)>::joint;
        return eval(bracket.formula(k.v[b.i], joint_screw<J>(b.link(m).joint, qd.data() + b.v_own)));
    };
    // written for the 1-dof joints, read for them only
    auto U = uninitialized_array<coscrew<T>, Tree::size>();  // N^A S
    std::array<T, Tree::size> D_inverse;                     // 1 / U(S)
    std::array<T, Tree::size> u;                             // τ − p^A(S)
    // (this step inlined into the loop over the legs: the legged tree's ABA 1.01× → 0.97× the
    // hand-written code; the last pass's step inlined too cost the 7-dof arm 7 %)
    each_body_backward(m, [&](const auto& b) CTGA_INLINE_LAMBDA {
        using B = std::remove_cvref_t<decltype(b)>;
        using J = typename B::joint;
        const std::size_t i = b.i;
        const auto& L = b.link(m);
        if constexpr (J::nv == 1) {
            const auto S = J::template subspace<0, T>(L.joint);
            U[i] = momentum(NA[i], S);
            if constexpr (has_armature<J>) D_inverse[i] = T(1) / (pairing(U[i], S) + L.armature);  // + the rotor's
            else D_inverse[i] = T(1) / pairing(U[i], S);
            u[i] = tau[b.v_own] - pairing(pA[i], S);
            if constexpr (!B::root) {
                // an axis joint's S is one screw component: N^a has a zero row and column there
                constexpr std::size_t null = null_component<J>();
                const articulated_inertia<T> Na = minus_joint<null>(NA[i], U[i], D_inverse[i]);
                const coscrew<T> pa = pA[i] + momentum(Na, bias(b)) + U[i] * (u[i] * D_inverse[i]);
                NA[b.p] = NA[b.p] + transform<null, map_shape<J>>(k.X[i], Na);
                pA[b.p] = pA[b.p] + transform<map_shape<J>>(k.X[i], pa);
            }
        } else if constexpr (J::nv == 0) {
            if constexpr (!B::root) {
                NA[b.p] = NA[b.p] + transform<6, map_shape<J>>(k.X[i], NA[i]);
                pA[b.p] = pA[b.p] + transform<map_shape<J>>(k.X[i], pA[i]);
            }
        } else {
            static_assert(J::nv == 6, "ctga::chains::aba: a joint has 0, 1 or 6 degrees of freedom");
            if constexpr (!B::root) {
                const std::size_t o = b.v_own;
                const coscrew<T> tau_i{tau[o], tau[o + 1], tau[o + 2], tau[o + 3], tau[o + 4], tau[o + 5]};
                pA[b.p] = pA[b.p] + transform<map_shape<J>>(k.X[i], tau_i);
            }
        }
    });
    joint_vector<Tree, T> qdd;  // every number written
    auto a = uninitialized_array<screw<T>, Tree::size>();
    const vec3<T> a_world = minus(m.gravity);
    each_body(m, [&](const auto& b) {
        using B = std::remove_cvref_t<decltype(b)>;
        using J = typename B::joint;
        const std::size_t i = b.i, o = b.v_own;
        const auto& L = b.link(m);
        screw<T> a_parent;  // X_i⁻¹ a_λ
        if constexpr (B::root) a_parent = world_acceleration<map_shape<J>>(k.X[i], a_world);
        else a_parent = transform_inverse<map_shape<J>>(k.X[i], a[b.p]);
        if constexpr (J::nv == 0) {
            a[i] = a_parent;
        } else if constexpr (J::nv == 1) {
            const screw<T> a1 = a_parent + bias(b);
            qdd[o] = (u[i] - pairing(U[i], a1)) * D_inverse[i];
            a[i] = a1 + J::template subspace<0, T>(L.joint) * qdd[o];
        } else {
            const coscrew<T> tau_i{tau[o], tau[o + 1], tau[o + 2], tau[o + 3], tau[o + 4], tau[o + 5]};
            a[i] = solve(NA[i], coscrew<T>(tau_i - pA[i]));
            const screw<T> d = a[i] - (a_parent + bias(b));
            for (std::size_t r = 0; r < 6; ++r) qdd[o + r] = d[r];
        }
    });
    return qdd;
}

template <class Tree, class T>
constexpr joint_vector<Tree, T> aba(const model<Tree, T>& m, const configuration<Tree, T>& q, const joint_vector<Tree, T>& qd,
                                    const joint_vector<Tree, T>& tau, const body_wrenches<Tree, T>* f_ext) noexcept {
    if constexpr (Tree::has_mimic) return coupled_forward_dynamics(m, q, qd, tau, f_ext);
    else return articulated_body(m, q, qd, tau, f_ext);
}
}  // namespace algorithm_detail

struct aba_t {
    // q̈ = FD(q, q̇, τ): the joint accelerations the forces τ give under gravity.
    template <class Tree, class T>
    [[nodiscard]] constexpr joint_vector<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                      const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& tau) const noexcept {
        return algorithm_detail::aba(m, q, qd, tau, static_cast<const body_wrenches<Tree, T>*>(nullptr));
    }
    // … with an external wrench acting on each body (body frame, about the body's origin).
    template <class Tree, class T>
    [[nodiscard]] constexpr joint_vector<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                      const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& tau,
                                                      const body_wrenches<Tree, T>& f_ext) const noexcept {
        return algorithm_detail::aba(m, q, qd, tau, &f_ext);
    }
};
inline constexpr algorithm<aba_t, "aba"> aba{};

}  // namespace ctga::chains
