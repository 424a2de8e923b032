// Constrained inverse dynamics: given (q, q̇, q̈) and the constraints that hold (feet on the ground,
// a hand on a handle), the joint torques τ and the constraint forces λ with
//     H q̈ + C(q, q̇) = τ + Jᵀ λ,      τ_u = 0 on the unactuated dofs (a floating base's six),
// what a whole-body controller asks of its robot. With the base unactuated the forces are not
// determined by q̈ alone (four feet: 12 forces for the base's 6 equations); ctga returns the least
// ‖λ‖ that the cones allow:
//     λ = argmin ½ ‖λ‖²   subject to   A λ = b,  λ_i ∈ K_i,
// A = J_uᵀ (the rows' entries on the unactuated dofs), b = (H q̈ + C)_u (rnea), K_i each block's
// set: R³ for a point or orientation block, Coulomb's cone for a contact, λ ≥ 0 on a limit's row,
// |λ| ≤ bound on a joint friction's. Its dual, in y of the unactuated dofs' size,
//     min_y  ½ ‖P_K(Aᵀ y)‖² − bᵀ y        (λ = P_K(Aᵀ y), the projection on the sets),
// is convex and differentiable with gradient A P_K(Aᵀ y) − b: solved by semismooth Newton (the
// generalized Jacobian of each projection, a search on the dual or on ‖A λ − b‖) until ‖A λ − b‖ is at
// most the settings' tolerance. Then τ = H q̈ + C − Jᵀ λ on the actuated dofs. A q̈ the sets
// cannot produce (a base accelerating upwards off the ground, a foot that would have to pull)
// leaves a residual: converged = false, the report says how far.
// Rows are weighed alike (a couple's N m as a force's N). A tree without a floating joint has no
// unactuated dof: λ = 0, τ = rnea.
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include "ctga/chains/rnea.hpp"
#include "ctga/constrained/constrained_dynamics.hpp"
#include "ctga/constrained/constraint_rows.hpp"
#include "ctga/constrained/constraint_set.hpp"
#include "ctga/constraints/friction_cone.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/cholesky.hpp"
#include "ctga/support/math.hpp"

namespace ctga::constrained {

template <class Tree, class T, std::size_t Capacity>
struct constrained_inverse_result {
    error_code error = error_code::none;
    chains::joint_vector<Tree, T> tau{};   // 0 on the unactuated dofs
    std::array<T, 3 * Capacity> force{};   // λ, three per block in block order
    constraints::contact_report<T> report{};  // residual ‖A λ − b‖, Newton steps in sweeps
};

namespace inverse_detail {
// The unactuated dofs: every floating joint's six.
template <class Tree>
inline constexpr std::size_t unactuated_count = [] {
    std::size_t n = 0;
    for (std::size_t i = 0; i < Tree::size; ++i) n += Tree::nv_of[i] == 6 ? 6 : 0;
    return n;
}();
template <class Tree>
inline constexpr auto unactuated = [] {
    std::array<std::size_t, unactuated_count<Tree>> out{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < Tree::size; ++i)
        if (Tree::nv_of[i] == 6)
            for (std::size_t k = 0; k < 6; ++k) out[n++] = Tree::v_offset[i] + k;
    return out;
}();

// P_K(x) of a block and its generalized Jacobian (row-major 3 × 3).
template <class T>
struct projected {
    vec3<T> p;
    mat3<T> D;
};
template <class T>
[[nodiscard]] constexpr projected<T> project(const constraint_block<T>& c, const vec3<T>& x) noexcept {
    const mat3<T> I{{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}};
    projected<T> out{x, I};
    switch (c.kind) {
        case block_kind::point:
        case block_kind::orientation: return out;
        case block_kind::lower_limit:
        case block_kind::upper_limit:
        case block_kind::joint_friction: {
            const T lo = c.kind == block_kind::joint_friction ? -c.bound : T(0);
            const T hi = c.kind == block_kind::joint_friction ? c.bound : std::numeric_limits<T>::infinity();
            const bool inside = x[0] > lo && x[0] < hi;
            return {{x[0] < lo ? lo : (x[0] > hi ? hi : x[0]), T(0), T(0)}, {{{inside ? T(1) : T(0), T(0), T(0)}, {}, {}}}};
        }
        case block_kind::contact: break;
    }
    // Coulomb's cone (friction_cone.hpp's projection): inside, polar, or onto the boundary, where
    // with s = ‖x_t‖, d = x_t / s, k = 1 / (1 + μ²), c = k (x_n + μ s): p = (c, μ c d) and
    // Dp = [[k, μ k dᵀ], [μ k d, μ² k d dᵀ + μ c (1 − d dᵀ) / s]]
    const T mu = c.mu, s = constraints::tangential_norm(x);
    if (s <= mu * x[0]) return out;
    if (mu * s <= -x[0]) return {{}, {}};
    out.p = constraints::project_on_cone(x, mu);
    const T k = T(1) / (T(1) + mu * mu), cn = (x[0] + mu * s) * k;
    const T d[2] = {x[1] / s, x[2] / s};
    out.D[0][0] = k;
    for (std::size_t a = 0; a < 2; ++a) out.D[0][a + 1] = out.D[a + 1][0] = mu * k * d[a];
    for (std::size_t a = 0; a < 2; ++a)
        for (std::size_t b = 0; b < 2; ++b)
            out.D[a + 1][b + 1] = mu * mu * k * d[a] * d[b] + mu * cn / s * ((a == b ? T(1) : T(0)) - d[a] * d[b]);
    return out;
}
}  // namespace inverse_detail

struct constrained_inverse_dynamics_t {
    template <class Tree, class T, std::size_t Capacity>
    [[nodiscard]] constexpr constrained_inverse_result<Tree, T, Capacity> operator()(const chains::model<Tree, T>& m,
                                                                                     const chains::configuration<Tree, T>& q,
                                                                                     const chains::joint_vector<Tree, T>& qd,
                                                                                     const chains::joint_vector<Tree, T>& qdd,
                                                                                     const constraint_set<Tree, T, Capacity>& C,
                                                                                     const constrained_settings<T>& settings = {}) const noexcept {
        static_assert(!Tree::has_mimic, "ctga::constrained: trees with mimic joints are not supported yet (their H is not the tree factor's)");
        constexpr std::size_t U = inverse_detail::unactuated_count<Tree>;
        constexpr const auto& dofs = inverse_detail::unactuated<Tree>;
        constrained_inverse_result<Tree, T, Capacity> out;
        if (!dynamics_detail::finite_state(q, qd, qdd)) return out.error = error_code::non_finite, out;
        const chains::joint_vector<Tree, T> full = chains::rnea(m, q, qd, qdd);  // H q̈ + C
        out.tau = full;
        if constexpr (U > 0) {
            tree_motion<Tree, T> g(uninitialized);
            fill_tree_motion(g, m, q, qd);
            constraint_rows<Tree, T, Capacity> R;
            fill_rows(R, g, C, q, qd);
            const std::size_t n = R.count;
            // λ(y) = P_K(Aᵀ y), F(y) = A λ − b, the dual φ(y) = ½ ‖λ‖² − bᵀ y
            std::array<T, U> y{}, F{};
            std::array<T, 3 * Capacity> lambda{};
            std::array<mat3<T>, Capacity> D{};
            const auto evaluate = [&](const std::array<T, U>& at) {
                T phi = T(0);
                for (std::size_t i = 0; i < C.size(); ++i) {
                    vec3<T> x{};
                    for (std::size_t a = 0; a < 3; ++a)
                        for (std::size_t u = 0; u < U; ++u) x[a] += R.columns[dofs[u]][3 * i + a] * at[u];
                    const auto p = inverse_detail::project(C.blocks()[i], x);
                    D[i] = p.D;
                    for (std::size_t a = 0; a < 3; ++a) lambda[3 * i + a] = p.p[a], phi += p.p[a] * p.p[a] / T(2);
                }
                T norm = T(0);
                for (std::size_t u = 0; u < U; ++u) {
                    T s = -full[dofs[u]];
                    for (std::size_t r = 0; r < n; ++r) s += R.columns[dofs[u]][r] * lambda[r];
                    F[u] = s;
                    norm += s * s;
                    phi -= full[dofs[u]] * at[u];
                }
                return std::array<T, 2>{phi, math::sqrt(norm)};
            };
            auto [phi, residual] = evaluate(y);
            std::size_t steps = 0;
            while (residual > settings.solver.tolerance && steps < 50 && is_finite(residual)) {
                ++steps;
                // G = A Dp Aᵀ (+ a floor on its diagonal where no row reaches a dof), Δy = −G⁻¹ F
                std::array<std::array<T, U>, U> G{};
                T largest = T(0);
                for (std::size_t i = 0; i < C.size(); ++i)
                    for (std::size_t u = 0; u < U; ++u)
                        for (std::size_t v = 0; v <= u; ++v) {
                            T s = T(0);
                            for (std::size_t a = 0; a < 3; ++a)
                                for (std::size_t b = 0; b < 3; ++b)
                                    s += R.columns[dofs[u]][3 * i + a] * D[i][a][b] * R.columns[dofs[v]][3 * i + b];
                            G[u][v] += s;
                        }
                for (std::size_t u = 0; u < U; ++u) largest = G[u][u] > largest ? G[u][u] : largest;
                for (std::size_t u = 0; u < U; ++u) G[u][u] += T(1e-12) * (largest > T(0) ? largest : T(1));
                const auto L = cholesky(G);
                if (!L) break;
                std::array<T, U> minus_F;
                for (std::size_t u = 0; u < U; ++u) minus_F[u] = -F[u];
                const std::array<T, U> step = cholesky_solve(*L, minus_F);
                T slope = T(0);
                for (std::size_t u = 0; u < U; ++u) slope += F[u] * step[u];
                const std::array<T, U> from = y;
                const T phi0 = phi, residual0 = residual;
                T t = T(1);
                bool descended = false;
                // a step is taken where the dual decreases (Armijo) or, near the solution where φ's
                // decrease is below its rounding, where ‖F‖ does
                for (int halving = 0; halving < 30 && !descended; ++halving, t /= T(2)) {
                    for (std::size_t u = 0; u < U; ++u) y[u] = from[u] + t * step[u];
                    const auto next = evaluate(y);
                    phi = next[0], residual = next[1];
                    descended = phi <= phi0 + T(1e-4) * t * slope || residual <= (T(1) - T(1e-4) * t) * residual0;
                }
                if (!descended) break;  // at rounding's floor: the residual is reported as it is
            }
            for (std::size_t r = 0; r < n; ++r) out.force[r] = lambda[r];
            out.report.residual = residual;
            out.report.sweeps = steps;
            out.report.converged = residual <= settings.solver.tolerance;
            if (!is_finite(residual)) return out.error = out.report.error = error_code::non_finite, out;
            // τ = H q̈ + C − Jᵀ λ, 0 on the unactuated dofs
            for (std::size_t k = 0; k < Tree::nv; ++k)
                for (std::size_t r = 0; r < n; ++r) out.tau[k] -= R.columns[k][r] * lambda[r];
            for (std::size_t u = 0; u < U; ++u) out.tau[dofs[u]] = T(0);
        } else {
            out.report.converged = true;
        }
        return out;
    }
};
// (τ, λ, the report) of a tree whose motion q̈ is asked under the constraints of C.
inline constexpr constrained_inverse_dynamics_t constrained_inverse_dynamics{};

}  // namespace ctga::constrained
