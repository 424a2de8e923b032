// The algorithms of a kinematic tree (tree.hpp) in the algebra: screws for velocities and
// accelerations (§3), co-screws for forces (§5), each body's inertia N by its ten parameters
// (body_inertia), motor maps for the frames (motor.hpp). Featherstone (2008) names them:
//
//   forward_kinematics   every body's frame, velocity screw and acceleration          (§4.1)
//   rnea                 inverse dynamics τ(q, q̇, q̈): the recursive Newton–Euler
//                        algorithm                                                     (§5.3)
//   crba                 the joint-space mass matrix H(q): composite rigid bodies       (§6.2)
//   kinetic_energy, potential_energy
//
// Everything is in body coordinates: body i's velocity v_i and acceleration a_i are screws in
// its own frame, X_i is the motor map of body i in its parent's frame (placement ∘ joint motion).
// The recursions, with × the Lie bracket of §3 and ×* the coadjoint action {s, P} of §6:
//
//   v_i = X_i⁻¹ v_λ + S_i q̇_i
//   a_i = X_i⁻¹ a_λ + S_i q̈_i + v_i × S_i q̇_i         (a of the world: −g, gravity's trick)
//   f_i = N_i a_i + v_i ×* (N_i v_i) − f_ext,i         (N s = A ∨ (N ∧ s), the momentum of §5)
//   τ_i = f_i(S_i) = f_i ∨ (Q0 ∧ S_i),  f_λ += X_i f_i  (the pairing of §5; ḡ f ḡ* moves f out)
//
// A joint's S_i q̇_i and S_i are the joint's own sparse screws (joints.hpp): one blade for an
// axis joint, so the bracket, the momentum of the mass matrix and the pairing are evaluated by
// the engine on that blade only. The bodies are unrolled at compile time (a fold over their
// indices), each with its own joint type, parent and ancestors.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/chains/joints.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/articulated_inertia.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
using configuration = std::array<T, Tree::nq>;  // q: the joints' numbers in body order
template <class Tree, class T = double>
using joint_vector = std::array<T, Tree::nv>;  // q̇, q̈, τ
template <class Tree, class T = double>
using joint_matrix = std::array<std::array<T, Tree::nv>, Tree::nv>;  // H, row-major
template <class Tree, class T = double>
using body_wrenches = std::array<coscrew<T>, Tree::size>;  // external wrench on each body, body frame

template <class Tree, class T = double>
struct kinematics {
    std::array<motor_map<T>, Tree::size> X;     // body i in its parent's frame
    std::array<motor_map<T>, Tree::size> pose;  // body i in the world frame
    std::array<screw<T>, Tree::size> v;         // velocity, body frame
    std::array<screw<T>, Tree::size> a;         // acceleration (spatial, without gravity), body frame

    // Zero.
    constexpr kinematics() noexcept : X{}, pose{}, v{}, a{} {}
    // Not cleared: for a pass that writes every body's numbers it reads (support/uninitialized.hpp).
    constexpr explicit kinematics(uninitialized_t) noexcept
        : v(uninitialized_array<screw<T>, Tree::size>()), a(uninitialized_array<screw<T>, Tree::size>()) {}
};

namespace algorithm_detail {

// f(std::integral_constant<std::size_t, I>) for I = 0 … N−1, or N−1 … 0.
template <std::size_t N, class F>
CTGA_ALWAYS_INLINE constexpr void forward(F&& f) {
    [&]<std::size_t... I>(std::index_sequence<I...>) { (f(std::integral_constant<std::size_t, I>{}), ...); }(
        std::make_index_sequence<N>{});
}
template <std::size_t N, class F>
CTGA_ALWAYS_INLINE constexpr void backward(F&& f) {
    [&]<std::size_t... I>(std::index_sequence<I...>) { (f(std::integral_constant<std::size_t, N - 1 - I>{}), ...); }(
        std::make_index_sequence<N>{});
}

// S q̇ of a joint: Σ_k S_k q̇_k, in the joint's own screw type (one blade for an axis joint).
template <class J, class P, class T>
CTGA_ALWAYS_INLINE constexpr auto joint_screw(const P& params, const T* x) noexcept {
    if constexpr (J::nv == 1) return typename J::template subspace_type<T>{J::template subspace<0, T>(params) * x[0]};
    else if constexpr (J::nv == 6) return screw<T>{x[0], x[1], x[2], x[3], x[4], x[5]};
    else static_assert(J::nv == 1 || J::nv == 6, "ctga::chains: a joint has 1 or 6 degrees of freedom (or 0: fixed)");
}

// Body I's map in its parent's frame.
template <std::size_t I, class Tree, class T>
CTGA_ALWAYS_INLINE constexpr motor_map<T> joint_map(const model<Tree, T>& m, const configuration<Tree, T>& q) noexcept {
    using J = typename Tree::template joint_at<I>;
    const auto& L = m.template link<I>();
    return J::motion(L.placement, L.joint, q.data() + Tree::q_offset[I]);
}

// The world's acceleration in Featherstone's gravity trick (§5.3) is a pure translation, −g (or 0
// for the true accelerations of forward kinematics): seen from a body on the world with map X
// it is (0, Rᵀ(−g)) (X⁻¹ (0, a) = (Rᵀ 0, Rᵀ(a − t × 0))), 9m 6a instead of a screw's 24m 18a.
template <class T>
CTGA_ALWAYS_INLINE constexpr screw<T> world_acceleration(const motor_map<T>& X, const vec3<T>& a) noexcept {
    const vec3<T> r = linear3::apply_transposed(X.R, a);
    return screw<T>{T(0), T(0), T(0), r[0], r[1], r[2]};
}
template <class T>
constexpr vec3<T> minus(const vec3<T>& g) noexcept {
    return {-g[0], -g[1], -g[2]};
}

enum class pass { poses, velocities, accelerations };

// The number of ancestors of body i (0 for a body on the world).
template <class Tree>
constexpr std::size_t depth_of(std::size_t i) {
    std::size_t d = 0;
    for (int k = Tree::parent[i]; k >= 0; k = Tree::parent[static_cast<std::size_t>(k)]) ++d;
    return d;
}

// The forward pass of §4.1/§5.3 into k: maps, world poses (when Poses), velocities and
// accelerations (as asked), then then(body, k) while the body's numbers are at hand (RNEA's
// forces; the body's map k.X[i] is stored only after it). RNEA and ABA need no world poses:
// only each body's map in its parent. Every number asked for is written before it is read, so
// k may start uninitialized.
struct no_body_work {
    template <class B, class K>
    constexpr void operator()(B, const K&) const noexcept {}
};
template <pass What, bool Poses, class Tree, class T, class Then = no_body_work>
constexpr void forward_pass(kinematics<Tree, T>& k, const model<Tree, T>& m, const configuration<Tree, T>& q, const T* qd,
                            const T* qdd, const vec3<T>& a_world, Then&& then = {}) noexcept {
    forward<Tree::size>([&](auto body) {
        constexpr std::size_t i = decltype(body)::value;
        constexpr int p = Tree::parent[i];
        using J = typename Tree::template joint_at<i>;
        const auto& L = m.template link<i>();
        const motor_map<T> X = joint_map<i>(m, q);  // used from here, stored in k.X after the body's work
        if constexpr (!Poses) {
        } else if constexpr (p < 0) {
            k.pose[i] = X;
        } else {
            const motor_map<T>& W = k.pose[p];
            k.pose[i] = {joint_detail::multiply(W.R, X.R), linear3::add(linear3::apply(W.R, X.t), W.t)};
        }
        if constexpr (What != pass::poses) {
            constexpr std::size_t o = Tree::v_offset[i];
            if constexpr (J::nv == 0) {
                if constexpr (p < 0) {
                    k.v[i] = screw<T>{};
                    if constexpr (What == pass::accelerations) k.a[i] = world_acceleration(X, a_world);
                } else {
                    k.v[i] = transform_inverse(X, k.v[p]);
                    if constexpr (What == pass::accelerations) k.a[i] = transform_inverse(X, k.a[p]);
                }
            } else {
                const auto vJ = joint_screw<J>(L.joint, qd + o);
                if constexpr (p < 0) {
                    k.v[i] = vJ;  // the world does not move
                    if constexpr (What == pass::accelerations)
                        k.a[i] = world_acceleration(X, a_world) + joint_screw<J>(L.joint, qdd + o);
                } else {
                    k.v[i] = transform_inverse(X, k.v[p]) + vJ;
                    if constexpr (What == pass::accelerations)
                        k.a[i] = transform_inverse(X, k.a[p]) + joint_screw<J>(L.joint, qdd + o) + bracket(k.v[i], vJ);
                }
            }
        }
        then(body, k);
        // last: a copy of X read while its parts still sit in the store buffer stalls store forwarding
        k.X[i] = X;
    });
}

}  // namespace algorithm_detail

// ---- forward kinematics (§4.1) -------------------------------------------------------------------

struct forward_kinematics_t {
    // Every body's frame: its map in the parent's frame (X) and in the world (pose).
    template <class Tree, class T>
    [[nodiscard]] constexpr kinematics<Tree, T> operator()(const model<Tree, T>& m,
                                                                   const configuration<Tree, T>& q) const noexcept {
        kinematics<Tree, T> k;  // v, a: zero
        algorithm_detail::forward_pass<algorithm_detail::pass::poses, true>(k, m, q, static_cast<const T*>(nullptr), static_cast<const T*>(nullptr), vec3<T>{});
        return k;
    }
    // … and every body's velocity screw, body frame.
    template <class Tree, class T>
    [[nodiscard]] constexpr kinematics<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                                   const joint_vector<Tree, T>& qd) const noexcept {
        kinematics<Tree, T> k;  // a: zero
        algorithm_detail::forward_pass<algorithm_detail::pass::velocities, true>(k, m, q, qd.data(), static_cast<const T*>(nullptr), vec3<T>{});
        return k;
    }
    // … and every body's acceleration (the true spatial acceleration, gravity not included).
    template <class Tree, class T>
    [[nodiscard]] constexpr kinematics<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                                   const joint_vector<Tree, T>& qd,
                                                                   const joint_vector<Tree, T>& qdd) const noexcept {
        kinematics<Tree, T> k{uninitialized};  // every member written
        algorithm_detail::forward_pass<algorithm_detail::pass::accelerations, true>(k, m, q, qd.data(), qdd.data(), vec3<T>{});
        return k;
    }
};
inline constexpr forward_kinematics_t forward_kinematics{};

// ---- inverse dynamics: the recursive Newton–Euler algorithm (§5.3) -------------------------------

namespace algorithm_detail {
template <class Tree, class T>
constexpr joint_vector<Tree, T> rnea(const model<Tree, T>& m, const configuration<Tree, T>& q, const joint_vector<Tree, T>& qd,
                                     const joint_vector<Tree, T>& qdd, const body_wrenches<Tree, T>* f_ext) noexcept {
    auto f = uninitialized_array<coscrew<T>, Tree::size>();
    kinematics<Tree, T> k{uninitialized};
    forward_pass<pass::accelerations, false>(
        k, m, q, qd.data(), qdd.data(), minus(m.gravity), [&](auto body, const kinematics<Tree, T>& kb) {
            constexpr std::size_t i = decltype(body)::value;
            const auto& N = m.template link<i>().inertia;
            // f_i = N a_i + v_i ×* (N v_i) − f_ext
            f[i] = momentum(N, kb.a[i]) + coadjoint(kb.v[i], momentum(N, kb.v[i]));
            if (f_ext) f[i] = f[i] - (*f_ext)[i];
        });
    joint_vector<Tree, T> tau{};
    backward<Tree::size>([&](auto body) {
        constexpr std::size_t i = decltype(body)::value;
        constexpr int p = Tree::parent[i];
        using J = typename Tree::template joint_at<i>;
        const auto& L = m.template link<i>();
        if constexpr (J::nv > 0)
            [&]<std::size_t... K>(std::index_sequence<K...>) {
                ((tau[Tree::v_offset[i] + K] = evaluation(f[i], J::template subspace<K, T>(L.joint))), ...);
            }(std::make_index_sequence<J::nv>{});
        if constexpr (p >= 0) f[p] = f[p] + transform(k.X[i], f[i]);
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
inline constexpr rnea_t rnea{};

// ---- the mass matrix: the composite rigid body algorithm (§6.2) ----------------------------------
//
// N^c_i = N_i + Σ_children X_c N^c_c (the composite of body i and everything it carries, moved
// into i's frame: transform(X, body_inertia), 54m 50a). Column (i, k) of H: F = N^c_i S_ik, then
// H(j, l) = F(S_jl) for body i's own dofs and, moving F out through X_i, X_λ(i), …, each ancestor j.

namespace algorithm_detail {
// H(j, ·) = F(S_j) for body j's dofs.
template <std::size_t J, class Tree, class T>
CTGA_ALWAYS_INLINE constexpr void fill_rows(const model<Tree, T>& m, joint_matrix<Tree, T>& H, std::size_t col,
                                            const coscrew<T>& F) noexcept {
    using Jt = typename Tree::template joint_at<J>;
    [&]<std::size_t... L>(std::index_sequence<L...>) {
        ((H[Tree::v_offset[J] + L][col] = H[col][Tree::v_offset[J] + L] =
              evaluation(F, Jt::template subspace<L, T>(m.template link<J>().joint))),
         ...);
    }(std::make_index_sequence<Jt::nv>{});
}
// F moved out of body `Child` into its parent's frame, and the parent's entries filled; then on up.
template <std::size_t Child, class Tree, class T>
CTGA_ALWAYS_INLINE constexpr void fill_ancestors(const model<Tree, T>& m, const std::array<motor_map<T>, Tree::size>& X,
                                                 joint_matrix<Tree, T>& H, std::size_t col, const coscrew<T>& F) noexcept {
    constexpr int p = Tree::parent[Child];
    if constexpr (p >= 0) {
        const coscrew<T> Fp = transform(X[Child], F);
        if constexpr (Tree::template joint_at<static_cast<std::size_t>(p)>::nv > 0) fill_rows<static_cast<std::size_t>(p)>(m, H, col, Fp);
        fill_ancestors<static_cast<std::size_t>(p)>(m, X, H, col, Fp);
    }
}
// Column K of body I's dofs, from F = N^c_I S_IK.
template <std::size_t I, std::size_t K, class Tree, class T>
CTGA_ALWAYS_INLINE constexpr void crba_column(const model<Tree, T>& m, const std::array<motor_map<T>, Tree::size>& X,
                                              joint_matrix<Tree, T>& H, const coscrew<T>& F) noexcept {
    const std::size_t col = Tree::v_offset[I] + K;
    fill_rows<I>(m, H, col, F);
    fill_ancestors<I>(m, X, H, col, F);
}
}  // namespace algorithm_detail

struct crba_t {
    template <class Tree, class T>
    [[nodiscard]] constexpr joint_matrix<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q) const noexcept {
        using namespace algorithm_detail;
        std::array<motor_map<T>, Tree::size> X;
        forward<Tree::size>([&](auto body) { X[decltype(body)::value] = joint_map<decltype(body)::value>(m, q); });
        std::array<body_inertia<T>, Tree::size> Nc = [&]<std::size_t... I>(std::index_sequence<I...>) {
            return std::array<body_inertia<T>, Tree::size>{m.template link<I>().inertia...};
        }(std::make_index_sequence<Tree::size>{});
        backward<Tree::size>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            constexpr int p = Tree::parent[i];
            if constexpr (p >= 0) Nc[p] = Nc[p] + transform(X[i], Nc[i]);
        });
        joint_matrix<Tree, T> H{};
        forward<Tree::size>([&](auto body) {
            constexpr std::size_t i = decltype(body)::value;
            using J = typename Tree::template joint_at<i>;
            if constexpr (J::nv > 0)
                [&]<std::size_t... K>(std::index_sequence<K...>) {
                    (crba_column<i, K>(m, X, H, momentum(Nc[i], J::template subspace<K, T>(m.template link<i>().joint))), ...);
                }(std::make_index_sequence<J::nv>{});
        });
        return H;
    }
};
inline constexpr crba_t crba{};

// ---- forward dynamics: the articulated body algorithm (§7.3) ------------------------------------
//
// Three passes (Featherstone Table 7.1), in body coordinates:
//   out:  v_i = X_i⁻¹ v_λ + S_i q̇_i,  c_i = v_i × S_i q̇_i,  N^A_i = N_i,  p^A_i = v_i ×* (N_i v_i) − f_ext,i
//   in:   U_i = N^A_i S_i,  D_i = U_i(S_i),  u_i = τ_i − p^A_i(S_i), and the parent receives
//         N^A_λ += X_i (N^A_i − U_i U_iᵀ/D_i),  p^A_λ += X_i (p^a_i),
//         p^a_i = p^A_i + N^a_i c_i + U_i u_i/D_i
//   out:  a'_i = X_i⁻¹ a_λ + c_i,  q̈_i = (u_i − U_i(a'_i))/D_i,  a_i = a'_i + S_i q̈_i
// N^A is an articulated_inertia (21 entries, moved by (g ḡ) N (g ḡ)*); U = N^A S, the pairings
// and N^a c are the engine's formulas, so an axis joint's S (one blade) takes one column of N^A
// and one component of each co-screw, and c = v × S q̇ has the bracket's four non-zero blades.
// A floating joint (S = 1): q̈ = (N^A)⁻¹(τ − p^A) − a' and the parent receives no inertia and
// the force τ (N^a = N^A − N^A (N^A)⁻¹ N^A = 0, p^a = p^A + (τ − p^A)).

namespace algorithm_detail {
// The screw component an axis joint's S lies on, 6 for any other joint.
template <class J>
constexpr std::size_t null_component() {
    if constexpr (requires { J::component; }) return J::component;
    else return 6;
}
template <class Tree, class T>
constexpr joint_vector<Tree, T> aba(const model<Tree, T>& m, const configuration<Tree, T>& q, const joint_vector<Tree, T>& qd,
                                    const joint_vector<Tree, T>& tau, const body_wrenches<Tree, T>* f_ext) noexcept {
    kinematics<Tree, T> k{uninitialized};
    forward_pass<pass::velocities, false>(k, m, q, qd.data(), static_cast<const T*>(nullptr), vec3<T>{});
    // N^A_i = N_i, p^A_i = v_i ×* (N_i v_i) − f_ext,i: each array built element by element
    std::array<articulated_inertia<T>, Tree::size> NA = [&]<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<articulated_inertia<T>, Tree::size>{articulated_inertia_of(m.template link<I>().inertia)...};
    }(std::make_index_sequence<Tree::size>{});
    std::array<coscrew<T>, Tree::size> pA = [&]<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<coscrew<T>, Tree::size>{coscrew<T>(coadjoint(k.v[I], momentum(m.template link<I>().inertia, k.v[I])))...};
    }(std::make_index_sequence<Tree::size>{});
    if (f_ext)
        for (std::size_t i = 0; i < Tree::size; ++i) pA[i] = pA[i] - (*f_ext)[i];
    // c_i = v_i × S_i q̇_i in the bracket's own sparse type: four blades for an axis joint (nv = 1, 6 only)
    const auto bias = [&](auto body) {
        constexpr std::size_t i = decltype(body)::value;
        using J = typename Tree::template joint_at<i>;
        return eval(bracket.formula(k.v[i], joint_screw<J>(m.template link<i>().joint, qd.data() + Tree::v_offset[i])));
    };
    // written for the 1-dof joints, read for them only
    auto U = uninitialized_array<coscrew<T>, Tree::size>();  // N^A S
    std::array<T, Tree::size> D_inverse;                     // 1 / U(S)
    std::array<T, Tree::size> u;                             // τ − p^A(S)
    backward<Tree::size>([&](auto body) {
        constexpr std::size_t i = decltype(body)::value;
        constexpr int p = Tree::parent[i];
        using J = typename Tree::template joint_at<i>;
        const auto& L = m.template link<i>();
        if constexpr (J::nv == 1) {
            const auto S = J::template subspace<0, T>(L.joint);
            U[i] = momentum(NA[i], S);
            D_inverse[i] = T(1) / evaluation(U[i], S);
            u[i] = tau[Tree::v_offset[i]] - evaluation(pA[i], S);
            if constexpr (p >= 0) {
                // an axis joint's S is one screw component: N^a has a zero row and column there
                constexpr std::size_t null = null_component<J>();
                const articulated_inertia<T> Na = minus_joint<null>(NA[i], U[i], D_inverse[i]);
                const coscrew<T> pa = pA[i] + momentum(Na, bias(body)) + U[i] * (u[i] * D_inverse[i]);
                NA[p] = NA[p] + transform<null>(k.X[i], Na);
                pA[p] = pA[p] + transform(k.X[i], pa);
            }
        } else if constexpr (J::nv == 0) {
            if constexpr (p >= 0) {
                NA[p] = NA[p] + transform(k.X[i], NA[i]);
                pA[p] = pA[p] + transform(k.X[i], pA[i]);
            }
        } else {
            static_assert(J::nv == 6, "ctga::chains::aba: a joint has 0, 1 or 6 degrees of freedom");
            if constexpr (p >= 0) {
                constexpr std::size_t o = Tree::v_offset[i];
                const coscrew<T> tau_i{tau[o], tau[o + 1], tau[o + 2], tau[o + 3], tau[o + 4], tau[o + 5]};
                pA[p] = pA[p] + transform(k.X[i], tau_i);
            }
        }
    });
    joint_vector<Tree, T> qdd;  // every number written
    auto a = uninitialized_array<screw<T>, Tree::size>();
    const vec3<T> a_world = minus(m.gravity);
    forward<Tree::size>([&](auto body) {
        constexpr std::size_t i = decltype(body)::value;
        constexpr int p = Tree::parent[i];
        constexpr std::size_t o = Tree::v_offset[i];
        using J = typename Tree::template joint_at<i>;
        const auto& L = m.template link<i>();
        screw<T> a_parent;  // X_i⁻¹ a_λ
        if constexpr (p < 0) a_parent = world_acceleration(k.X[i], a_world);
        else a_parent = transform_inverse(k.X[i], a[p]);
        if constexpr (J::nv == 0) {
            a[i] = a_parent;
        } else if constexpr (J::nv == 1) {
            const screw<T> a1 = a_parent + bias(body);
            qdd[o] = (u[i] - evaluation(U[i], a1)) * D_inverse[i];
            a[i] = a1 + J::template subspace<0, T>(L.joint) * qdd[o];
        } else {
            const coscrew<T> tau_i{tau[o], tau[o + 1], tau[o + 2], tau[o + 3], tau[o + 4], tau[o + 5]};
            a[i] = solve(NA[i], coscrew<T>(tau_i - pA[i]));
            const screw<T> d = a[i] - (a_parent + bias(body));
            for (std::size_t r = 0; r < 6; ++r) qdd[o + r] = d[r];
        }
    });
    return qdd;
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
inline constexpr aba_t aba{};

// ---- energies ----------------------------------------------------------------------------------

struct kinetic_energy_t {
    // ½ Σ v_i ∨ … : the kinetic energy ½ s̄ ∨ (N ∧ s) of §5, summed over the bodies.
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
        return e;
    }
};
inline constexpr kinetic_energy_t kinetic_energy{};

struct potential_energy_t {
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
inline constexpr potential_energy_t potential_energy{};


// ---- the geometric Jacobian of a body's frame --------------------------------------------------
//
// v_I = J q̇: column k of joint j is the velocity body I has when only q̇_k moves, S_jk seen from
// body I's frame (world: from the world's). For j on the path from I to the root it is S_jk moved
// out of body j, g_j S_jk g_j* = transform(pose_j, S_jk) (§3), then into body I; for any other
// joint it is zero. The body is a compile-time index: chains::body<I>.

template <std::size_t I>
inline constexpr std::integral_constant<std::size_t, I> body{};

template <class Tree, class T = double>
using jacobian_matrix = std::array<screw<T>, Tree::nv>;  // column k: a screw

namespace algorithm_detail {
template <std::size_t J, class Tree, class T>
CTGA_ALWAYS_INLINE constexpr void world_columns(const model<Tree, T>& m, const kinematics<Tree, T>& k,
                                                jacobian_matrix<Tree, T>& out) noexcept {
    using Jt = typename Tree::template joint_at<J>;
    [&]<std::size_t... K>(std::index_sequence<K...>) {
        ((out[Tree::v_offset[J] + K] = transform(k.pose[J], screw<T>(Jt::template subspace<K, T>(m.template link<J>().joint)))),
         ...);
    }(std::make_index_sequence<Jt::nv>{});
    if constexpr (Tree::parent[J] >= 0) world_columns<static_cast<std::size_t>(Tree::parent[J])>(m, k, out);
}
}  // namespace algorithm_detail

struct world_jacobian_t {
    // Velocity of body I in world coordinates (ω, v of the point at the world origin) = J q̇.
    template <class Tree, class T, std::size_t I>
    [[nodiscard]] constexpr jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                                std::integral_constant<std::size_t, I>) const noexcept {
        static_assert(I < Tree::size, "ctga::chains::world_jacobian: no such body in the tree");
        jacobian_matrix<Tree, T> out{};
        algorithm_detail::world_columns<I>(m, forward_kinematics(m, q), out);
        return out;
    }
};
inline constexpr world_jacobian_t world_jacobian{};

struct body_jacobian_t {
    // Velocity of body I in its own frame (the v of forward_kinematics) = J q̇.
    template <class Tree, class T, std::size_t I>
    [[nodiscard]] constexpr jacobian_matrix<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                                std::integral_constant<std::size_t, I>) const noexcept {
        static_assert(I < Tree::size, "ctga::chains::body_jacobian: no such body in the tree");
        const kinematics<Tree, T> k = forward_kinematics(m, q);
        jacobian_matrix<Tree, T> out{};
        algorithm_detail::world_columns<I>(m, k, out);
        for (std::size_t c = 0; c < Tree::nv; ++c)
            if (Tree::supports(Tree::body_of_dof[c], I)) out[c] = transform_inverse(k.pose[I], out[c]);
        return out;
    }
};
inline constexpr body_jacobian_t body_jacobian{};

// ---- checked calls -----------------------------------------------------------------------------
//
//   auto qdd = chains::checked_call(chains::aba, m, q, qd, tau);   // checked<joint_vector>
//   if (!qdd) std::puts(ctga::describe(qdd.error));
//
// The algorithms above are plain arithmetic: a NaN in q gives a NaN in τ. checked_call runs one
// on inputs it has checked and checks its result, so nothing non-finite passes for an answer:
//   non_finite    a NaN or infinity in q, q̇, q̈, τ, the wrenches or gravity, or in the result
//   not_a_motor   a floating joint's configuration with a zero rotor part (no rigid motion)
// (A model's inertias and axes were checked when it was built: make_link.)

namespace algorithm_detail {
template <class T>
constexpr bool finite_all(const T& x) noexcept {
    if constexpr (std::is_arithmetic_v<T>) return is_finite(x);
    else if constexpr (requires { x.R; x.t; }) return finite_all(x.R) && finite_all(x.t);
    else if constexpr (requires { x.X; x.pose; x.v; x.a; }) return finite_all(x.X) && finite_all(x.pose) && finite_all(x.v) && finite_all(x.a);
    else if constexpr (requires { x.links; x.gravity; }) return finite_all(x.gravity);
    else if constexpr (multivector_type<T>) {
        for (std::size_t i = 0; i < T::size(); ++i)
            if (!is_finite(x[i])) return false;
        return true;
    } else {
        for (const auto& e : x)
            if (!finite_all(e)) return false;
        return true;
    }
}
// A floating joint's eight numbers are a motor when its rotor part is not zero (map_of reads any
// such motor as the rigid motion it encodes).
template <class Tree, class T>
constexpr error_code check_configuration(const std::array<T, Tree::nq>& q) noexcept {
    if (!finite_all(q)) return error_code::non_finite;
    for (std::size_t i = 0; i < Tree::size; ++i)
        if (Tree::nq_of[i] == 8) {
            const T* g = q.data() + Tree::q_offset[i];
            if (!(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + g[3] * g[3] > T(0))) return error_code::not_a_motor;
        }
    return error_code::none;
}
}  // namespace algorithm_detail

template <class Algorithm, class Tree, class T, class... Args>
[[nodiscard]] constexpr auto checked_call(const Algorithm& algorithm, const model<Tree, T>& m, const configuration<Tree, T>& q,
                                          const Args&... args) noexcept -> checked<decltype(algorithm(m, q, args...))> {
    using result = decltype(algorithm(m, q, args...));
    if (!algorithm_detail::finite_all(m)) return {result{}, error_code::non_finite};
    if (const error_code e = algorithm_detail::check_configuration<Tree>(q); e != error_code::none) return {result{}, e};
    if (!(algorithm_detail::finite_all(args) && ...)) return {result{}, error_code::non_finite};
    const result r = algorithm(m, q, args...);
    if (!algorithm_detail::finite_all(r)) return {result{}, error_code::non_finite};
    return {r, error_code::none};
}

}  // namespace ctga::chains
