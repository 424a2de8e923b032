// Constrained dynamics over a time step, at the velocity level (Moreau's sweeping process; the
// time-stepping of Stewart and Trinkle, Anitescu and Potra, as MuJoCo and Box3D step): over a step
// h from (q, q̇), the impulses r of the constraint rows and the velocity after,
//     (H + h B) (q̇⁺ − q̇) = h (τ − C(q, q̇) − B q̇) + Jᵀ r,       u = J q̇⁺ + b,
// H, C, J at (q, q̇) (crba, constraint_rows.hpp's bias_forces and rows), B the joints' viscous damping (diagonal:
// URDF <dynamics damping>), taken implicitly (stable at any h and damping), and each block's
// condition on u (the solver of constraints/, the tolerance the caller's):
//   contact  K_μ ∋ r ⊥ ũ ∈ K*_μ (Coulomb's cone, De Saxcé's ũ), with b_n = φ/h while apart (φ > 0:
//            the gap may close this step and no more, so the next state does not overlap to first
//            order: a speculative contact) and b_n = max(β φ/h, −v_max) when overlapping (β of the
//            depth removed per step, no faster than v_max: a start in deep penetration is pushed
//            out at v_max, not thrown out in a step);
//   limit    r ≥ 0 ⊥ u ≥ 0, b as a contact's normal;
//   friction |r| ≤ h · bound, u = 0 while inside (a joint's dry friction sticks or slides);
//   point, orientation  u = 0 with b = β φ/h.
// The same elimination as the forces' (constrained_dynamics.hpp): W = J (H + hB)⁻¹ Jᵀ from the tree
// factor of H + hB (delassus.hpp), q = J q̇ + J (H + hB)⁻¹ h (τ − C − B q̇) + b, then
// q̇⁺ = q̇ + (H + hB)⁻¹ (h (τ − C − B q̇) + Jᵀ r).
//
// h = 0 is an impact (impact(), below): q̇⁺ = q̇ + H⁻¹ Jᵀ r with the same conditions and no gap
// terms, the impulse at touchdown of an inelastic collision (Moreau's impact law: the contacts
// that close stop closing, u_n ≥ 0, and their tangential velocity is stopped or slides against
// the cone's bound).
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "ctga/chains/crba.hpp"
#include "ctga/chains/minverse.hpp"
#include "ctga/constrained/constrained_dynamics.hpp"
#include "ctga/constrained/constraint_rows.hpp"
#include "ctga/constrained/constraint_set.hpp"
#include "ctga/constrained/delassus.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::constrained {

template <class T>
struct impulse_settings {
    constrained_settings<T> rows{};  // the solver's tolerance (on impulses, N s) and sweeps; the redundancy floor
    T recovery = T(0.2);             // β: the fraction of an overlap or a bilateral error removed per step
    T recovery_speed = T(1);         // v_max (m/s or rad/s): the fastest an overlap is pushed out
};

template <class Tree, class T, std::size_t Capacity>
struct impulse_result {
    error_code error = error_code::none;
    chains::joint_vector<Tree, T> qd{};   // q̇⁺
    std::array<T, 3 * Capacity> impulse{};  // r, three per block in block order (on entry: the warm start)
    constraints::contact_report<T> report{};
    std::size_t rank = 0;
};

// A step's problem before its solve: the factor of H + hB, z = L⁻ᵀ h (τ − C − B q̇), the rows, Y
// and q = J q̇ + J (H + hB)⁻¹ h (τ − C − B q̇) + b (above). After the impulses r are found (here by
// solve_rows; robot_world.hpp solves them with a world's bodies), q̇⁺ = q̇ + L⁻¹ D⁻¹ (z + Yᵀ r)
// (dynamics_detail::add_forces).
template <class Tree, class T, std::size_t Capacity>
struct impulse_problem {
    chains::algorithm_detail::tree_factor<Tree, T> f;
    std::array<T, Tree::nv> z;
    dynamics_detail::rows_problem<Tree, T, Capacity> x;
};

// The problem of a step h at (q, q̇); `maps`, when given, are the joints' maps at q (chains'
// fill_joint_maps: the stepper's, computed for collision), else computed here. Refused:
// non-finite inputs, h < 0 (non_finite), negative damping (negative_limit), a massless subtree.
template <class Tree, class T, std::size_t Capacity>
constexpr error_code fill_impulse_problem(impulse_problem<Tree, T, Capacity>& p, const chains::model<Tree, T>& m, const chains::configuration<Tree, T>& q,
                                          const chains::joint_vector<Tree, T>& qd, const chains::joint_vector<Tree, T>& tau,
                                          const constraint_set<Tree, T, Capacity>& C, const T& h, const chains::joint_vector<Tree, T>& damping,
                                          const impulse_settings<T>& settings, const chains::algorithm_detail::joint_maps<Tree, T>* maps = nullptr) noexcept {
    static_assert(!Tree::has_mimic, "ctga::constrained: trees with mimic joints are not supported yet (their H is not the tree factor's)");
    using namespace chains::algorithm_detail;
    if (!dynamics_detail::finite_state(q, qd, tau, damping) || !is_finite(h) || h < T(0)) return error_code::non_finite;
    for (const T& b : damping)
        if (b < T(0)) return error_code::negative_limit;
    joint_maps<Tree, T> own;
    if (!maps) fill_joint_maps(own, m, q);
    const joint_maps<Tree, T>& X = maps ? *maps : own;
    // H + hB = Lᵀ D L; z = L⁻ᵀ h (τ − C − B q̇)
    tree_factor<Tree, T>& f = p.f;
    f = {mass_matrix(m, q, X), {}, true};
    for (std::size_t k = 0; k < Tree::nv; ++k) f.LD[k][k] += h * damping[k];
    factor_tree(f);
    if (!f.positive_definite) return error_code::massless_subtree;
    tree_motion<Tree, T> g(uninitialized);
    fill_tree_motion(g, m, q, qd, X);
    std::array<T, Tree::nv>& z = p.z;
    z = {};
    if (h > T(0)) {
        z = bias_forces(m, g);  // C, from the world motion the rows read (constraint_rows.hpp)
        for (std::size_t k = 0; k < Tree::nv; ++k) z[k] = h * (tau[k] - z[k] - damping[k] * qd[k]);
        transposed_sweep(f, [&](std::size_t k, std::size_t i, const T& l) { z[i] -= l * z[k]; });
    }
    // the rows, W, and q = J q̇ + J (H + hB)⁻¹ h (τ − C − B q̇) + b
    dynamics_detail::fill_problem<false>(p.x, g, q, qd, C, f, z);  // (no J̇ q̇ at the velocity level)
    auto& [R, P, qv] = p.x;
    const T beta = settings.recovery;
    for (std::size_t r = 0; r < R.count; ++r) {
        qv[r] += R.rate[r];
        if (!(h > T(0))) continue;
        const block_kind kind = C.blocks()[r / 3].kind;
        const bool normal = (kind == block_kind::contact || kind == block_kind::lower_limit || kind == block_kind::upper_limit) && r % 3 == 0;
        const bool held = kind == block_kind::point || kind == block_kind::orientation;
        const T phi = R.gap[r];
        const T push = beta * phi / h, fastest = -settings.recovery_speed;
        if (normal) qv[r] += phi > T(0) ? phi / h : (push > fastest ? push : fastest);
        else if (held) qv[r] += beta * phi / h;
    }
    return error_code::none;
}

// q̇⁺ and r over a step h (above); `out.impulse` holds the warm start on entry (zeros, or the last
// step's impulses of the same blocks); with scratch of dynamics_detail::polish_scratch_size(Capacity)
// numbers, a solve the sweeps leave unconverged is finished by Newton (constrained_dynamics.hpp's
// solve_rows). Refused: as fill_impulse_problem.
template <class Tree, class T, std::size_t Capacity>
constexpr void impulse_dynamics(const chains::model<Tree, T>& m, const chains::configuration<Tree, T>& q, const chains::joint_vector<Tree, T>& qd,
                                const chains::joint_vector<Tree, T>& tau, const constraint_set<Tree, T, Capacity>& C, const T& h,
                                const chains::joint_vector<Tree, T>& damping, const impulse_settings<T>& settings,
                                impulse_result<Tree, T, Capacity>& out, std::span<T> scratch = {},
                                const chains::algorithm_detail::joint_maps<Tree, T>* maps = nullptr) noexcept {
    impulse_problem<Tree, T, Capacity> p;
    if ((out.error = fill_impulse_problem(p, m, q, qd, tau, C, h, damping, settings, maps)) != error_code::none) return;
    auto& [R, P, qv] = p.x;
    for (std::size_t r = R.count; r < 3 * Capacity; ++r) out.impulse[r] = T(0);
    out.rank = dynamics_detail::solve_rows(p.f, p.z, R, P, qv, C, settings.rows, h, out.impulse, out.report, scratch);
    if (out.report.error != error_code::none) return void(out.error = out.report.error);
    for (std::size_t k = 0; k < Tree::nv; ++k) out.qd[k] = qd[k] + p.z[k];
}

// The impulse at an impact (h = 0, above): q̇⁺ just after and the impulses r of C's blocks.
template <class Tree, class T, std::size_t Capacity>
[[nodiscard]] constexpr impulse_result<Tree, T, Capacity> impact(const chains::model<Tree, T>& m, const chains::configuration<Tree, T>& q,
                                                                 const chains::joint_vector<Tree, T>& qd, const constraint_set<Tree, T, Capacity>& C,
                                                                 const impulse_settings<T>& settings = {}) noexcept {
    impulse_result<Tree, T, Capacity> out;
    const chains::joint_vector<Tree, T> none{};
    impulse_dynamics(m, q, qd, none, C, T(0), none, settings, out);
    return out;
}

}  // namespace ctga::constrained
