// The derivatives of inverse dynamics, ∂τ/∂q, ∂τ/∂q̇ and ∂τ/∂q̈ = H, of a kinematic tree: the
// analytical recursion of Carpentier and Mansard (RSS 2018), written with screws, co-screws, the
// bracket and the coadjoint action (paper §3, §5, §6) in the world frame, where a body's
// derivative columns are one screw for all the bodies it carries.
//
// Configuration derivatives are taken in the tangent space: moving joint j's coordinate k by δ
// moves body j by exp(δ S_jk) in its own frame (X_j(q ⊕ δ) = X_j(q) exp(δ S_jk); for a revolute
// or prismatic joint q ⊕ δ = q + δ, for a floating joint the motor g exp(δ (ω, v)), the
// convention of Pinocchio and of Lie-group MPC). In the world frame that moves everything body j
// carries (its subtree) rigidly by the screw S = S_jk moved out, so every world quantity of the
// subtree X changes by S acting on it, plus what does not move with it (the parent's velocity
// v_λ and acceleration a_λ). With Ψ̇ = v_λ × S and Ψ̈ = a_λ × S + v_λ × Ψ̇, for body i carried:
//
//   ∂S_i = S × S_i,  ∂N_i = S ×* N_i − N_i S×,  ∂v_i = S × v_i + Ψ̇,  ∂a_i = S × a_i + Ψ̈ + Ψ̇ × v_i
//   ∂f_i = S ×* f_i + N_i Ψ̈ + B_i Ψ̇,   B_i y = Ṅ_i y + y ×* h_i   (h_i = N_i v_i, Ṅ_i: inertia_rate)
//
// (f_i = N_i a_i + v_i ×* h_i − f_ext is equivariant, so S's action passes through; the external
// wrenches are fixed in their bodies and move with them.) Summed over the subtree, with the
// composites N^c, Ṅ^c, H^c = Σ h_i, F^c = Σ f_i (plain sums: one frame):
//
//   ∂F_j = S ×* F_j + dF,   dF = N^c_j Ψ̈ + Ṅ^c_j Ψ̇ + Ψ̇ ×* H^c_j
//
// and τ_k = F_k(S_k) gives the entries: for a dof k of j or of an ancestor, ∂τ_k/∂q_jk = (∂F_j)(S_k)
// (the own joint's: dF(S_k), the S ×* F term cancelling ∂S_k); for a dof i of a body that j
// carries, ∂τ_i/∂q_jk = r1_i(Ψ̈) + r2_i(Ψ̇) with r1_i = N^c_i S_i, r2_i = Ṅ^c_i S_i − S_i ×* H^c_i
// (the transpose of B^c_i, by ⟨y ×* H, s⟩ = −⟨s ×* H, y⟩). Velocities: ∂v_i/∂q̇_jk = S,
// ∂a_i/∂q̇_jk = S × v_i + Φ with Φ = Ψ̇ + v_j × S (2Ψ̇ for a one-dof joint), so
//   ∂F_j/∂q̇_jk = Ṅ^c_j S + S ×* H^c_j + N^c_j Φ,    ∂τ_i/∂q̇_jk = r2_i(S) + r1_i(Φ)
// and H = ∂τ/∂q̈: N^c_j S for the column, r1_i(S) for the rows. Every entry pairs two world
// screws and co-screws, and only entries of the tree's pattern (tree_matrix.hpp: joints on one
// branch) are formed; per body the work is a fixed number of screw operations, plus one pairing
// per pair of joints on a branch.
// A tree with mimic joints is differentiated on its expanded tree and reduced by G
// (mimic_expansion.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/mimic_expansion.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/chains/tree_matrix.hpp"
#include "ctga/chains/world_geometry.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/inertia_transform.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
struct rnea_partials {
    joint_vector<Tree, T> tau;                              // τ(q, q̇, q̈), as rnea
    tree_matrix<Tree, T, sparsity::branches> dtau_dq;       // ∂τ/∂q (tangent space, nv columns)
    tree_matrix<Tree, T, sparsity::branches> dtau_dv;       // ∂τ/∂q̇
    tree_matrix<Tree, T, sparsity::branches> M;             // ∂τ/∂q̈ = H, the mass matrix
};

namespace algorithm_detail {

// The world-frame numbers of the recursion: per body its composites, per dof its columns.
template <class Tree, class T>
struct derivative_pass : world_geometry<Tree, T> {
    std::array<screw<T>, Tree::size> v, a, c;      // world velocity, acceleration (−g at the world), v_λ × v
    std::array<body_inertia<T>, Tree::size> Nc, Nc_rate;
    std::array<coscrew<T>, Tree::size> Hc, Fc;     // composite momentum and force
    std::array<screw<T>, Tree::nv> Psi_d, Psi_dd, Phi;

    explicit constexpr derivative_pass(uninitialized_t)
        : world_geometry<Tree, T>(uninitialized), v(uninitialized_array<screw<T>, Tree::size>()),
          a(uninitialized_array<screw<T>, Tree::size>()), c(uninitialized_array<screw<T>, Tree::size>()), Hc(uninitialized_array<coscrew<T>, Tree::size>()),
          Fc(uninitialized_array<coscrew<T>, Tree::size>()), Psi_d(uninitialized_array<screw<T>, Tree::nv>()),
          Psi_dd(uninitialized_array<screw<T>, Tree::nv>()), Phi(uninitialized_array<screw<T>, Tree::nv>()) {}
};

// The rest is the same for every joint, in the world frame: loops over the bodies at run time,
// compiled once for any tree. Forwards, body i after its parent, first what the velocities give:
// v, the dofs' Ψ̇ and Φ, c = Σ Ψ̇ q̇ = v_λ × v (the acceleration of the joints' motion), and the
// body's N, Ṅ, h = N v and v ×* h − f_ext (f's velocity terms) as the composites' first terms …
// (Inertial = false: the kinematics only, for a frame's derivatives, frame_derivatives.hpp.)
template <bool Inertial = true, class Tree, class T>
constexpr void derivative_velocities(derivative_pass<Tree, T>& d, std::size_t i, const T* qd, const body_wrenches<Tree, T>* f_ext) noexcept {
    const int p = Tree::parent[i];
    const std::size_t o = Tree::v_offset[i], nv = Tree::nv_of[i];
    const screw<T> v_p = p < 0 ? screw<T>{} : d.v[static_cast<std::size_t>(p)];
    screw<T> v = v_p, c{};
    for (std::size_t k = o; k < o + nv; ++k) {
        // the world does not move: Ψ̇ = 0 on it
        if (p < 0) d.Psi_d[k] = screw<T>{};
        else d.Psi_d[k] = bracket(v_p, d.S[k]);
        v = v + d.S[k] * qd[k];
        c = c + d.Psi_d[k] * qd[k];
    }
    // Φ = Ψ̇ + v_j × S: 2Ψ̇ for one dof (v_j × S = v_λ × S), else with the joint's own motion
    for (std::size_t k = o; k < o + nv; ++k)
        d.Phi[k] = nv == 1 ? screw<T>(d.Psi_d[k] + d.Psi_d[k]) : screw<T>(d.Psi_d[k] + bracket(v, d.S[k]));
    d.v[i] = v;
    d.c[i] = c;
    if constexpr (Inertial) {
        const body_inertia<T>& N = d.N[i];
        d.Nc[i] = N;
        d.Nc_rate[i] = inertia_rate(N, v);
        d.Hc[i] = momentum(N, v);
        d.Fc[i] = coadjoint(v, d.Hc[i]);
        if (f_ext) d.Fc[i] = d.Fc[i] - transform(d.pose[i], (*f_ext)[i]);
    }
}
// … then what the accelerations give: a = a_λ + c + Σ S q̈ (−g at the world), Ψ̈ and f's N a.
template <bool Inertial = true, class Tree, class T>
constexpr void derivative_accelerations(derivative_pass<Tree, T>& d, std::size_t i, const screw<T>& a_world, const T* qdd) noexcept {
    const int p = Tree::parent[i];
    const std::size_t o = Tree::v_offset[i], nv = Tree::nv_of[i];
    const screw<T> a_p = p < 0 ? a_world : d.a[static_cast<std::size_t>(p)];
    screw<T> a = a_p + d.c[i];
    for (std::size_t k = o; k < o + nv; ++k) {
        const screw<T>& S = d.S[k];
        if (p < 0) d.Psi_dd[k] = bracket(a_p, S);  // Ψ̇ = 0
        else d.Psi_dd[k] = bracket(a_p, S) + bracket(d.v[static_cast<std::size_t>(p)], d.Psi_d[k]);
        a = a + S * qdd[k];
    }
    d.a[i] = a;
    if constexpr (Inertial) d.Fc[i] = d.Fc[i] + momentum(d.N[i], a);
}

// Backwards: body j's composites are complete when it is reached (its children, later bodies,
// have added theirs); then its dofs' columns and rows, and its composites go to its parent. Out
// has dtau_dq and dtau_dv, and τ and M where it has them (rnea_partials; aba_derivatives needs
// neither).
template <class Tree, class T, class Out>
constexpr void derivative_backward(derivative_pass<Tree, T>& d, Out& out) noexcept {
    constexpr bool mass = requires { out.M; };
    using tables = branch_tables<Tree>;
    for (std::size_t j = Tree::size; j-- > 0;) {
        const int p = Tree::parent[j];
        const std::size_t o = Tree::v_offset[j], nv = Tree::nv_of[j];
        for (std::size_t c = o; c < o + nv; ++c) {
            const screw<T>& S = d.S[c];
            const coscrew<T> r1 = momentum(d.Nc[j], S);
            const coscrew<T> NS = momentum(d.Nc_rate[j], S);
            const coscrew<T> SH = coadjoint(S, d.Hc[j]);
            const coscrew<T> r2 = NS - SH;
            // a body on the world: Ψ̇ = 0, and Φ = 0 for one dof (the terms are left out)
            const coscrew<T> dFv = p < 0 && nv == 1 ? coscrew<T>(NS + SH) : coscrew<T>(NS + SH + momentum(d.Nc[j], d.Phi[c]));
            const coscrew<T> dF = p < 0 ? momentum(d.Nc[j], d.Psi_dd[c])
                                        : coscrew<T>(momentum(d.Nc[j], d.Psi_dd[c]) + momentum(d.Nc_rate[j], d.Psi_d[c]) +
                                                     coadjoint(d.Psi_d[c], d.Hc[j]));
            if constexpr (mass) out.tau[c] = pairing(d.Fc[j], S);
            // the joint's own block
            for (std::size_t k = o; k < o + nv; ++k) {
                out.dtau_dq(k, c) = pairing(dF, d.S[k]);
                out.dtau_dv(k, c) = pairing(dFv, d.S[k]);
                if constexpr (mass) out.M(k, c) = pairing(r1, d.S[k]);
            }
            // the ancestors' rows of this column, and this row's entries in their columns
            const coscrew<T> dFq = dF + coadjoint(S, d.Fc[j]);
            for (std::size_t e = tables::supporting.first[j]; e < tables::supporting.first[j + 1]; ++e) {
                const std::size_t k = tables::supporting.list[e];
                out.dtau_dq(k, c) = pairing(dFq, d.S[k]);
                out.dtau_dv(k, c) = pairing(dFv, d.S[k]);
                if constexpr (mass) out.M(k, c) = out.M(c, k) = pairing(r1, d.S[k]);
                out.dtau_dv(c, k) = pairing(r2, d.S[k]) + pairing(r1, d.Phi[k]);
                out.dtau_dq(c, k) = tables::on_world[k] ? pairing(r1, d.Psi_dd[k])  // Ψ̇_k = 0 on the world
                                                        : pairing(r1, d.Psi_dd[k]) + pairing(r2, d.Psi_d[k]);
            }
        }
        if (p >= 0) {
            const std::size_t q = static_cast<std::size_t>(p);
            d.Nc[q] = d.Nc[q] + d.Nc[j];
            d.Nc_rate[q] = d.Nc_rate[q] + d.Nc_rate[j];
            d.Hc[q] = d.Hc[q] + d.Hc[j];
            d.Fc[q] = d.Fc[q] + d.Fc[j];
        }
    }
}

}  // namespace algorithm_detail

struct rnea_derivatives_t {
    template <class Tree, class T>
    [[nodiscard]] constexpr rnea_partials<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                              const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& qdd) const noexcept {
        return run(m, q, qd, qdd, static_cast<const body_wrenches<Tree, T>*>(nullptr));
    }
    // … with an external wrench on each body (body frame, about the body's origin), as rnea.
    template <class Tree, class T>
    [[nodiscard]] constexpr rnea_partials<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                              const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& qdd,
                                                              const body_wrenches<Tree, T>& f_ext) const noexcept {
        return run(m, q, qd, qdd, &f_ext);
    }

private:
    template <class Tree, class T>
    static constexpr rnea_partials<Tree, T> run(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& qdd,
                                                const body_wrenches<Tree, T>* f_ext) noexcept {
        using namespace algorithm_detail;
        if constexpr (Tree::has_mimic) {  // on the expanded tree, reduced by G (mimic_expansion.hpp)
            const expansion<Tree, T> x(m);
            const auto all = run(x.m, x.configuration_of(q), x.velocities_of(qd), x.velocities_of(qdd), f_ext);
            return {x.reduce(all.tau), x.reduce(all.dtau_dq), x.reduce(all.dtau_dv), x.reduce(all.M)};
        } else {
            derivative_pass<Tree, T> d{uninitialized};
            fill_world_geometry(d, m, q);
            const screw<T> a_world{T(0), T(0), T(0), -m.gravity[0], -m.gravity[1], -m.gravity[2]};
            for (std::size_t i = 0; i < Tree::size; ++i) {
                derivative_velocities(d, i, qd.data(), f_ext);
                derivative_accelerations(d, i, a_world, qdd.data());
            }
            rnea_partials<Tree, T> out{{}, tree_matrix<Tree, T, sparsity::branches>(uninitialized),
                                       tree_matrix<Tree, T, sparsity::branches>(uninitialized),
                                       tree_matrix<Tree, T, sparsity::branches>(uninitialized)};
            derivative_backward(d, out);
            // a joint's armature a_k: τ_k += a_k q̈_k and M_kk += a_k (∂τ/∂q, ∂τ/∂q̇ do not see it)
            each_armature(m, [&](std::size_t k, const T& a) {
                out.tau[k] += a * qdd[k];
                out.M(k, k) += a;
            });
            return out;
        }
    }
};
// The derivatives of τ = rnea(m, q, q̇, q̈[, f_ext]) with τ itself: rnea_partials.
inline constexpr algorithm<rnea_derivatives_t, "rnea_derivatives"> rnea_derivatives{};

}  // namespace ctga::chains
