// The rows of a tree's constraints at a state (q, q̇), in the paper's terms (§5): a row is a force
// line or a couple (a co-screw) paired with the bodies' screws.
//
// A block's rows are co-screws in the world frame. For a point or a contact: the lines through
// x, the origin of A's constraint frame, along B's constraint axes e (a contact's normal e_z
// first, then e_x, e_y), ℓ = (x × e, e) (collision/line_of_action.hpp); for an orientation the
// couples (e, 0). Row ℓ's entry for dof k is
//     J(ℓ, k) = ⟨ℓ, S_k⟩ for k on A's path only,  −⟨ℓ, S_k⟩ for k on B's path only,  0 else,
// S_k the dof's free direction in the world (world_geometry.hpp): the row's rate ⟨ℓ, V_A − V_B⟩
// is the speed along e of A's point at x relative to B's point there, or the relative angular
// velocity about e. The dofs on both paths move both bodies alike and cancel; the rows visit
// each body's path only (tables from the tree's type). Jᵀ λ applies the force λ e along ℓ to A
// and its reaction to B: one line, so the pair's wrenches balance. With S = (ω, v) the pairing is
// ⟨ℓ, S⟩ = (x × e) · ω + e · v = e · (v + ω × x) (⟨(e, 0), S⟩ = e · ω): six multiply-adds a row
// from its line's six numbers (fill_rows, below), and each body's acceleration at x once a block
// for the biases.
//
// J̇ q̇, the rows' acceleration at q̈ = 0 (the bias of the constrained dynamics): with the world
// velocities V_i = V_λ(i) + Σ_k S_k q̇_k and the accelerations at q̈ = 0, A_i = A_λ(i) + Σ_k [V_i, S_k] q̇_k
// (S_k is fixed in body i, so Ṡ_k = [V_i, S_k], §3's bracket: frame_jacobian.hpp), a body's
// material point at x has the classical acceleration d/dt (v + ω × x) = (A at x) + ω × (v + ω × x),
// so a line's bias is ⟨ℓ, A_A − A_B⟩ + e · (ω_A × v_A(x) − ω_B × v_B(x)), a couple's ⟨(e, 0), A_A − A_B⟩.
// The rows' axes turn with B; where the constraint and its rate hold, the terms of that turning
// vanish, so these rows are exact there (as Pinocchio's contact models are).
//
// A joint's block (a limit, its friction: constraint_set.hpp) has the one row ±e_k on its dof
// (+ for a lower limit, − for an upper), its gap ±(q_k − bound), and two empty rows; it reaches
// the dofs of its body's path (the sweep of delassus.hpp carries e_k up to them).
//
// The gap φ, in B's constraint axes: a point's R_Bᵀ (x_A − x_B) (a contact's normal component is its
// signed distance, > 0 apart); an orientation's sin θ times the axis of R_Bᵀ R_A's turn
// (½ vee(R − Rᵀ)).
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "ctga/chains/world_geometry.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/inertia_transform.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/constrained/constraint_set.hpp"
#include "ctga/mechanics/screw.hpp"

namespace ctga::constrained {

namespace rows_detail {
// The dofs on body b's path to the world (its own and its ancestors'), ascending, and whether dof
// k is on it.
template <class Tree>
struct paths {
    static constexpr auto on = [](std::size_t b, std::size_t k) { return Tree::supports(Tree::body_of_dof[k], b); };
    static constexpr auto dof = [](std::size_t, std::size_t k) { return k; };
    static constexpr auto lists = chains::algorithm_detail::make_dof_lists<Tree, std::size_t, decltype(on), decltype(dof)>();
    static constexpr std::array<std::array<bool, Tree::nv>, Tree::size> member = [] {
        std::array<std::array<bool, Tree::nv>, Tree::size> out{};
        for (std::size_t b = 0; b < Tree::size; ++b)
            for (std::size_t k = 0; k < Tree::nv; ++k) out[b][k] = on(b, k);
        return out;
    }();
    [[nodiscard]] static constexpr bool holds(int b, std::size_t k) noexcept { return b >= 0 && member[static_cast<std::size_t>(b)][k]; }
};
}  // namespace rows_detail

// The rows from the first block of a mask to the end of its last: [3 lowest, 3 (highest + 1)).
[[nodiscard]] constexpr std::array<std::size_t, 2> row_span(std::uint64_t mask) noexcept {
    return mask == 0 ? std::array<std::size_t, 2>{0, 0}
                     : std::array<std::size_t, 2>{std::size_t(3) * static_cast<std::size_t>(std::countr_zero(mask)),
                                                  std::size_t(3) * (64 - static_cast<std::size_t>(std::countl_zero(mask)))};
}

// Every body's pose, velocity and acceleration at q̈ = 0 in the world, and its dofs' S (above).
template <class Tree, class T>
struct tree_motion : chains::algorithm_detail::world_poses<Tree, T> {
    std::array<screw<T>, Tree::size> V, A;
    explicit constexpr tree_motion(uninitialized_t) : chains::algorithm_detail::world_poses<Tree, T>(uninitialized) {}
};
template <class Tree, class T, class Maps = chains::algorithm_detail::maps_of_q>
constexpr void fill_tree_motion(tree_motion<Tree, T>& g, const chains::model<Tree, T>& m, const chains::configuration<Tree, T>& q,
                                const chains::joint_vector<Tree, T>& qd, const Maps& maps = {}) noexcept {
    chains::algorithm_detail::fill_world_poses<Tree, T>(g, m, q, maps);
    for (std::size_t i = 0; i < Tree::size; ++i) {
        const int p = Tree::parent[i];
        const std::size_t o = Tree::v_offset[i], n = Tree::nv_of[i];
        screw<T> V = p < 0 ? screw<T>{} : g.V[static_cast<std::size_t>(p)];
        for (std::size_t k = o; k < o + n; ++k) V = V + g.S[k] * qd[k];
        screw<T> A = p < 0 ? screw<T>{} : g.A[static_cast<std::size_t>(p)];
        for (std::size_t k = o; k < o + n; ++k) A = A + bracket(V, g.S[k]) * qd[k];
        g.V[i] = V;
        g.A[i] = A;
    }
}

// C(q, q̇), the joint forces at q̈ = 0 (rnea's), from the same world motion: with each body's
// inertia moved out to the world, N_i, and gravity as the world's acceleration −g (Featherstone's
// trick, rnea.hpp), f_i = N_i (A_i − g) + V_i ×* (N_i V_i); a subtree's F_i = f_i + Σ_children F_c
// are plain sums in one frame, and C_k = F_i(S_k) for dof k of body i (no transforms up the tree:
// the world motion has the poses and S_k already).
template <class Tree, class T>
[[nodiscard]] constexpr std::array<T, Tree::nv> bias_forces(const chains::model<Tree, T>& m, const tree_motion<Tree, T>& g) noexcept {
    std::array<body_inertia<T>, Tree::size> N;
    [&]<std::size_t... I>(std::index_sequence<I...>) { ((N[I] = m.template link<I>().inertia), ...); }(std::make_index_sequence<Tree::size>{});
    const vec3<T> up = chains::algorithm_detail::minus(m.gravity);
    const screw<T> lift{T(0), T(0), T(0), up[0], up[1], up[2]};
    std::array<coscrew<T>, Tree::size> F;
    for (std::size_t i = 0; i < Tree::size; ++i) {  // (one loop for every body: the same work in the world frame)
        const body_inertia<T> Ni = transform(g.pose[i], N[i]);
        const screw<T> a = g.A[i] + lift;
        F[i] = momentum(Ni, a) + coadjoint(g.V[i], momentum(Ni, g.V[i]));
    }
    for (std::size_t i = Tree::size; i-- > 0;)
        if (const int p = Tree::parent[i]; p >= 0) F[static_cast<std::size_t>(p)] = F[static_cast<std::size_t>(p)] + F[i];
    std::array<T, Tree::nv> C;
    for (std::size_t k = 0; k < Tree::nv; ++k) C[k] = pairing(F[Tree::body_of_dof[k]], g.S[k]);
    return C;
}

// The rows of a set's blocks (3 each, in block order), stored by dof: columns[k][r] = J(r, k),
// zero off the rows' paths (past the last row: unset); reach[k] has bit p set when dof k is on block
// p's paths (delassus.hpp visits those blocks' rows only: a foot's rows reach its leg and the base).
template <class Tree, class T, std::size_t Capacity>
struct constraint_rows {
    static_assert(Capacity <= 64, "ctga::constrained: a constraint set holds at most 64 blocks (a 64-bit mask per dof says which reach it)");
    static constexpr std::size_t max_rows = 3 * Capacity;
    std::size_t count = 0;
    std::array<std::array<T, max_rows>, Tree::nv> columns;
    std::array<std::uint64_t, Tree::nv> reach;
    std::array<T, max_rows> gap, rate, bias;               // φ, J q̇, J̇ q̇
};

namespace rows_detail {
template <class T>
[[nodiscard]] constexpr vec3<T> angular_of(const screw<T>& s) noexcept { return {s[0], s[1], s[2]}; }
template <class T>
[[nodiscard]] constexpr vec3<T> linear_of(const screw<T>& s) noexcept { return {s[3], s[4], s[5]}; }
}  // namespace rows_detail

// (Bias false: without J̇ q̇, the velocity level's rows.) Two passes: each block's lines ℓ = (x × e,
// e) (a couple's (e, 0)) by rows, stored by component, then each body's dofs over the span of the
// blocks reaching them, J(r, k) = σ ⟨ℓ_r, S_k⟩ with σ = +1, −1 or 0 by the block's paths (above):
// six multiply-adds a row, vectorised across the rows (measured: a grasp's 24 rows 522 → 283 ns,
// Solo 12's four feet 335 → 361 ns, against the entries by block and dof).
template <bool Bias = true, class Tree, class T, std::size_t Capacity>
constexpr void fill_rows(constraint_rows<Tree, T, Capacity>& R, const tree_motion<Tree, T>& g, const constraint_set<Tree, T, Capacity>& C,
                         const chains::configuration<Tree, T>& q, const chains::joint_vector<Tree, T>& qd) noexcept {
    using P = rows_detail::paths<Tree>;
    constexpr std::size_t max_rows = 3 * Capacity;
    const auto world_of = [&](int body, const motor_map<T>& at) { return body < 0 ? at : compose(g.pose[static_cast<std::size_t>(body)], at); };
    const auto point_of = [&](int body, const vec3<T>& x) {
        return body < 0 ? x : linear3::add(linear3::apply(g.pose[static_cast<std::size_t>(body)].R, x), g.pose[static_cast<std::size_t>(body)].t);
    };
    const std::size_t rows = 3 * C.size();
    R.count = rows;
    R.reach.fill(0);
    for (auto& column : R.columns)
        for (std::size_t r = 0; r < rows; ++r) column[r] = T(0);
    std::array<std::array<T, max_rows>, 6> line;  // ℓ by component: moment (x × e or e), then direction (e or 0)
    std::array<T, max_rows> rate;                 // J q̇ (local: the columns' stores cannot alias it)
    for (std::size_t p = 0; p < C.size() && p < Capacity; ++p) {  // (p < Capacity: what the set holds, said for GCC's bounds analysis)
        const constraint_block<T>& c = C.blocks()[p];
        const std::size_t r0 = 3 * p;
        const auto reach = [&](int body) {
            if (body < 0) return;
            const std::size_t u = static_cast<std::size_t>(body);
            for (std::size_t n = P::lists.first[u]; n < P::lists.first[u + 1]; ++n) R.reach[P::lists.list[n]] |= std::uint64_t(1) << p;
        };
        reach(c.a);
        if (on_joint(c.kind)) {
            const std::size_t u = static_cast<std::size_t>(c.a), k = Tree::v_offset[u];
            const T sign = c.kind == block_kind::upper_limit ? T(-1) : T(1);
            for (std::size_t j = r0; j < r0 + 3; ++j) {
                rate[j] = R.bias[j] = R.gap[j] = T(0);
                for (auto& component : line) component[j] = T(0);
            }
            rate[r0] = sign * qd[k];
            R.gap[r0] = c.kind == block_kind::joint_friction ? T(0) : sign * (q[Tree::q_offset[u]] - c.bound);
            continue;
        }
        reach(c.b);
        const bool line_kind = c.kind != block_kind::orientation;
        const motor_map<T> WB = world_of(c.b, c.at_b);
        vec3<T> x, tilt{};
        if (line_kind) {
            x = point_of(c.a, c.at_a.t);  // (a line needs A's point only)
        } else {
            const motor_map<T> WA = world_of(c.a, c.at_a);
            x = WA.t;
            mat3<T> turn;  // R_Bᵀ R_A
            for (std::size_t r = 0; r < 3; ++r)
                for (std::size_t s = 0; s < 3; ++s) turn[r][s] = WB.R[0][r] * WA.R[0][s] + WB.R[1][r] * WA.R[1][s] + WB.R[2][r] * WA.R[2][s];
            tilt = {(turn[2][1] - turn[1][2]) / T(2), (turn[0][2] - turn[2][0]) / T(2), (turn[1][0] - turn[0][1]) / T(2)};
        }
        const vec3<T> d = linear3::apply_transposed(WB.R, linear3::sub(x, WB.t));
        // the bias e · (b_A − b_B): a body's acceleration at x (a line: the spatial one there, plus
        // ω × (v + ω × x), above), or its angular acceleration (a couple)
        vec3<T> b_ab{};
        if constexpr (Bias) {
            const auto at_x = [&](int body) {
                if (body < 0) return vec3<T>{};
                const screw<T>& V = g.V[static_cast<std::size_t>(body)];
                const screw<T>& A = g.A[static_cast<std::size_t>(body)];
                const vec3<T> alpha = rows_detail::angular_of(A);
                if (!line_kind) return alpha;
                const vec3<T> w = rows_detail::angular_of(V);
                const vec3<T> v_x = linear3::add(rows_detail::linear_of(V), linear3::cross(w, x));
                return linear3::add(linear3::add(rows_detail::linear_of(A), linear3::cross(alpha, x)), linear3::cross(w, v_x));
            };
            b_ab = linear3::sub(at_x(c.a), at_x(c.b));
        }
        for (std::size_t j = 0; j < 3; ++j) {
            const std::size_t r = r0 + j, axis = c.kind == block_kind::contact ? (j + 2) % 3 : j;  // contact: z, x, y
            const vec3<T> e{WB.R[0][axis], WB.R[1][axis], WB.R[2][axis]};
            const vec3<T> moment = line_kind ? linear3::cross(x, e) : e;
            for (std::size_t i = 0; i < 3; ++i) line[i][r] = moment[i], line[3 + i][r] = line_kind ? e[i] : T(0);
            rate[r] = T(0);
            R.bias[r] = linear3::dot(e, b_ab);
            R.gap[r] = c.kind == block_kind::orientation ? tilt[axis] : c.kind == block_kind::contact && j > 0 ? T(0) : d[axis];
        }
    }
    // each dof's column over its span: σ ⟨ℓ, S_k⟩ (σ per block: +1 on A's path only, −1 on B's
    // only, 0 on both, or for a joint's block; the same for a body's dofs), zero elsewhere; the
    // rates J q̇ with it
    for (std::size_t b = 0; b < Tree::size; ++b) {
        const std::size_t o = Tree::v_offset[b], dofs = Tree::nv_of[b];
        if (dofs == 0) continue;
        const auto [first, last] = row_span(R.reach[o]);
        std::array<T, max_rows> sign;
        for (std::size_t p = first / 3; p < last / 3; ++p) {
            const constraint_block<T>& c = C.blocks()[p];
            sign[3 * p] = sign[3 * p + 1] = sign[3 * p + 2] = on_joint(c.kind) ? T(0) : T(int(P::holds(c.a, o)) - int(P::holds(c.b, o)));
        }
        for (std::size_t k = o; k < o + dofs; ++k) {
            auto& column = R.columns[k];
            const screw<T>& S = g.S[k];
            const T qk = qd[k];
            for (std::size_t r = first; r < last; ++r) {
                const T entry = sign[r] * (line[0][r] * S[0] + line[1][r] * S[1] + line[2][r] * S[2] + line[3][r] * S[3] + line[4][r] * S[4] +
                                           line[5][r] * S[5]);
                column[r] = entry;
                rate[r] += entry * qk;
            }
        }
    }
    for (std::size_t r = 0; r < rows; ++r) R.rate[r] = rate[r];
    // a joint's row: ±1 on its dof
    for (std::size_t p = 0; p < C.size(); ++p)
        if (const constraint_block<T>& c = C.blocks()[p]; on_joint(c.kind))
            R.columns[Tree::v_offset[static_cast<std::size_t>(c.a)]][3 * p] = c.kind == block_kind::upper_limit ? T(-1) : T(1);
}

}  // namespace ctga::constrained
