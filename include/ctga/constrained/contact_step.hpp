// A time step of a robot that touches, as MuJoCo's step: collision, the rows, one solve for every
// contact, limit and loop, integration (semi-implicit Euler on the configuration space).
//
//   constrained::contact_stepper<robot::tree, double, 24> stepper;
//   stepper.limits = *robot::make_limits<double>();       // URDF <limit>, <dynamics>
//   auto report = stepper.step(m, q, qd, tau, geometry, world, settings);   // q, q̇ advanced by h
//
// One step from (q, q̇):
//   1. the poses of the bodies (world_poses), each robot shape's pose, and the contact manifolds
//      (collision/narrowphase.hpp) of every robot shape with every static shape and of the pairs
//      of robot shapes robot_geometry lets collide, within the speculative margin; each manifold
//      point a contact block (body A the shape's, B the world or the other body, its constraint
//      frame at B's witness with z the normal from B to A, μ the settings');
//   2. each joint of one dof within `limit_margin` of a finite bound a limit block, each joint with
//      friction a friction block; the stepper's permanent blocks (loops, welds) first;
//   3. impulse_dynamics.hpp over h (implicit joint damping), the solver warm-started from the last
//      step's impulses of the same blocks (a contact's id: its two shapes and manifold point), its
//      sweeps (at most the settings' budget) finished by Newton when they stop above the tolerance;
//   4. q ← q ⊕ h q̇⁺ (configuration_space.hpp).
// The report gives the solver's residual and sweeps, the counts and the deepest overlap; a step
// whose blocks pass the capacity, whose limits have lower > upper (limits_reversed), or whose
// inputs or solve fail, leaves (q, q̇) as they were and says why. The impulses over h are the forces (forces(): in each block's constraint axes).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "ctga/chains/configuration_space.hpp"
#include "ctga/chains/joint_limits.hpp"
#include "ctga/chains/world_geometry.hpp"
#include "ctga/collision/aabb.hpp"
#include "ctga/collision/shape_set.hpp"
#include "ctga/constrained/constraint_set.hpp"
#include "ctga/constrained/impulse_dynamics.hpp"
#include "ctga/constrained/robot_geometry.hpp"
#include "ctga/support/checked.hpp"

namespace ctga::constrained {

template <class T>
struct step_settings {
    T step = T(1e-3);            // h (s)
    T mu = T(1);                 // Coulomb's coefficient of every contact
    T margin = T(5e-3);          // contacts found this far apart (m)
    T limit_margin = T(2e-2);    // a limit is a row within this of its bound (rad or m)
    impulse_settings<T> solve{{{T(1e-9), 50}}, T(0.2), T(1)};  // tolerance on the impulses (N s), sweeps before Newton; β; v_max (m/s)
};

template <class T>
struct step_report {
    error_code error = error_code::none;
    constraints::contact_report<T> solver{};
    std::size_t contacts = 0, limits = 0;
    T penetration = T(0);  // the deepest overlap of a contact (m, ≥ 0)
};

template <class Tree, class T, std::size_t Capacity>
class contact_stepper {
   public:
    constraint_set<Tree, T, Capacity> permanent;                           // loops, welds: every step
    chains::joint_limits<Tree, T> limits = chains::unlimited<Tree, T>();  // bounds, damping, friction

    static constexpr std::uint32_t no_partner = ~std::uint32_t{0};

    template <class Shape, std::size_t N, class WorldShape>
    constexpr step_report<T> step(const chains::model<Tree, T>& m, chains::configuration<Tree, T>& q, chains::joint_vector<Tree, T>& qd,
                                  const chains::joint_vector<Tree, T>& tau, const robot_geometry<Tree, Shape, T, N>& geometry,
                                  std::span<const static_shape<WorldShape, T>> world, const step_settings<T>& settings) noexcept {
        step_report<T> report;
        chains::algorithm_detail::joint_maps<Tree, T> X;  // (for the collision's poses and the dynamics)
        const auto statics = [&](auto&& f) {
            for (std::size_t w = 0; w < world.size(); ++w) f(w, world[w].shape, world[w].pose);
        };
        gather(m, q, geometry, statics, [](const auto&, auto&&) {}, settings, X, report);
        if (report.error != error_code::none) return report;
        warm_start();
        impulse_dynamics(m, q, qd, tau, blocks_, settings.step, limits.damping, settings.solve, result_, std::span<T>(scratch_), &X);
        report.solver = result_.report;
        if (result_.error != error_code::none) return report.error = result_.error, report;
        finish(m, q, qd, result_.qd, settings.step);
        return report;
    }

    // ---- the stages (step's; robot_world.hpp's, which solves with a world's bodies) ----

    // 1. and 2. (above): the blocks at q, the joints' maps X filled. `statics(f)` calls
    // f(id, shape, map) for each static shape; `bodies(box, f)` calls f(id, shape, map, margin)
    // for each moving body outside the tree whose box may meet `box` (a robot shape's, grown by
    // the margin): their contacts are blocks with B the world (a frame fixed where the body's
    // witness is at q), their body the block's partner().
    template <class Shape, std::size_t N, class Statics, class Bodies>
    constexpr void gather(const chains::model<Tree, T>& m, const chains::configuration<Tree, T>& q, const robot_geometry<Tree, Shape, T, N>& geometry,
                          const Statics& statics, const Bodies& bodies, const step_settings<T>& settings,
                          chains::algorithm_detail::joint_maps<Tree, T>& X, step_report<T>& report) noexcept {
        static_assert(N < 4096, "ctga::constrained::contact_stepper: at most 4,095 robot shapes (a contact's key)");
        for (std::size_t b = 0; b < Tree::size; ++b)
            if (Tree::nv_of[b] == 1 && limits.lower[Tree::v_offset[b]] > limits.upper[Tree::v_offset[b]]) return void(report.error = error_code::limits_reversed);
        blocks_.clear();
        count_ = 0;
        for (const constraint_block<T>& c : permanent.blocks()) keep(c, key(0, count_), no_partner, report);
        // 1. contacts
        chains::algorithm_detail::fill_joint_maps(X, m, q);
        chains::algorithm_detail::world_poses<Tree, T> g(uninitialized);
        chains::algorithm_detail::fill_world_poses<Tree, T>(g, m, q, X);
        const auto shapes = geometry.shapes();
        const auto pose_of = [&](const auto& s) { return compose(g.pose[static_cast<std::size_t>(s.body)], s.at); };
        const auto add_manifold = [&](const collision::manifold<T>& mf, int a, int b, std::uint64_t pair, std::uint32_t partner) {
            const vec3<T> n = linear3::scale(T(-1), mf.normal);  // from B to A
            for (std::size_t p = 0; p < mf.count; ++p) {
                const collision::contact_point<T>& c = mf.points[p];
                motor_map<T> at_a = chains::tree_detail::identity_map<T>();
                at_a.t = point_in(g.pose[static_cast<std::size_t>(a)], c.point_a);
                // B's frame at its witness, built in B's axes (its tangents turn with B)
                const motor_map<T>* G = b >= 0 ? &g.pose[static_cast<std::size_t>(b)] : nullptr;
                const motor_map<T> at_b = constraint_set<Tree, T, Capacity>::contact_frame(G ? point_in(*G, c.point_b) : c.point_b,
                                                                                         G ? linear3::apply_transposed(G->R, n) : n);
                if (partner != no_partner) partner_point_[count_] = c.point_a;
                keep({block_kind::contact, a, b, at_a, at_b, settings.mu}, key(partner == no_partner ? 1 : 4, (pair << 32) | c.id), partner, report);
                ++report.contacts;
                report.penetration = -c.separation > report.penetration ? -c.separation : report.penetration;
            }
        };
        // each shape's pose and its box grown by the margin, once; the robot's own pairs go to the
        // narrow phase only where their boxes overlap (two shapes within the margin have boxes
        // within it too)
        std::array<motor_map<T>, N> pose;
        std::array<collision::aabb<T>, N> bounds;
        for (std::size_t i = 0; i < shapes.size(); ++i)
            pose[i] = pose_of(shapes[i]), bounds[i] = collision::fattened(collision::bounds_of(shapes[i].shape, pose[i]), settings.margin);
        for (std::size_t i = 0; i < shapes.size(); ++i) {
            statics([&](std::size_t w, const auto& shape, const motor_map<T>& at) {
                add_manifold(collision::contact_of(shapes[i].shape, pose[i], shape, at, settings.margin), shapes[i].body, -1, (i << 16) | w, no_partner);
            });
            bodies(bounds[i], [&](std::uint32_t id, const auto& shape, const motor_map<T>& at, const T& margin) {
                add_manifold(collision::contact_of(shapes[i].shape, pose[i], shape, at, margin), shapes[i].body, -1,
                             (std::uint64_t{i} << 16) | (id & 0xffff), id);  // (a warm start's key: ids 65,536 apart may share one)
            });
            for (std::size_t j = i + 1; j < shapes.size(); ++j)
                if (geometry.collides(shapes[i].body, shapes[j].body) && collision::overlaps(bounds[i], bounds[j]))
                    add_manifold(collision::contact_of(shapes[i].shape, pose[i], shapes[j].shape, pose[j], settings.margin), shapes[i].body,
                                 shapes[j].body, (i << 16) | (j + 0x8000), no_partner);
        }
        // 2. limits and joint friction
        for (std::size_t b = 0; b < Tree::size; ++b) {
            if (Tree::nv_of[b] != 1) continue;
            const std::size_t k = Tree::v_offset[b];
            const T x = q[Tree::q_offset[b]];
            const int body = static_cast<int>(b);
            if (x - limits.lower[k] < settings.limit_margin)
                keep({block_kind::lower_limit, body, -1, {}, {}, T(0), limits.lower[k]}, key(2, 2 * b), no_partner, report);
            if (limits.upper[k] - x < settings.limit_margin)
                keep({block_kind::upper_limit, body, -1, {}, {}, T(0), limits.upper[k]}, key(2, 2 * b + 1), no_partner, report);
            if (limits.friction[k] > T(0)) keep({block_kind::joint_friction, body, -1, {}, {}, T(0), limits.friction[k]}, key(3, b), no_partner, report);
        }
    }

    // 3. (before the solve) each block's impulse from the last step's of the same key, else zero.
    constexpr void warm_start() noexcept {
        for (std::size_t i = 0; i < count_; ++i) {  // (keys are unique; a block is most often where it was last step: looked for from there)
            vec3<T> r{};
            for (std::size_t n = 0; n < last_count_; ++n)
                if (const std::size_t j = (i + n) % last_count_; last_keys_[j] == keys_[i]) {
                    r = {last_[3 * j], last_[3 * j + 1], last_[3 * j + 2]};
                    break;
                }
            for (std::size_t a = 0; a < 3; ++a) result_.impulse[3 * i + a] = r[a];
        }
        for (std::size_t r = 3 * count_; r < 3 * Capacity; ++r) result_.impulse[r] = T(0);
    }

    // 4. the impulses kept for the next warm start; q ← q ⊕ h q̇⁺, q̇ ← q̇⁺.
    constexpr void finish(const chains::model<Tree, T>& m, chains::configuration<Tree, T>& q, chains::joint_vector<Tree, T>& qd,
                          const chains::joint_vector<Tree, T>& after, const T& h) noexcept {
        last_count_ = count_;
        last_keys_ = keys_;
        last_ = result_.impulse;
        chains::joint_vector<Tree, T> dq;
        for (std::size_t k = 0; k < Tree::nv; ++k) dq[k] = h * after[k];
        q = chains::integrate(m, q, dq);
        qd = after;
    }

    // The last step's blocks and their impulses (N s; over h: the mean forces); during a step, the
    // blocks gathered and the impulses being solved for.
    [[nodiscard]] constexpr std::span<const constraint_block<T>> blocks() const noexcept { return blocks_.blocks(); }
    [[nodiscard]] constexpr std::span<const T> impulses() const noexcept { return {result_.impulse.data(), 3 * blocks_.size()}; }
    [[nodiscard]] constexpr std::span<T> impulses() noexcept { return {result_.impulse.data(), 3 * blocks_.size()}; }
    [[nodiscard]] constexpr const constraint_set<Tree, T, Capacity>& block_set() const noexcept { return blocks_; }
    // Block i's body outside the tree (gather's `bodies`), or no_partner; with a partner, A's
    // point of the block in the world (its rows' lines pass through it).
    [[nodiscard]] constexpr std::uint32_t partner(std::size_t i) const noexcept { return partner_[i]; }
    [[nodiscard]] constexpr const vec3<T>& partner_point(std::size_t i) const noexcept { return partner_point_[i]; }

   private:
    static constexpr std::uint64_t key(std::uint64_t kind, std::uint64_t id) noexcept { return (kind << 60) | id; }
    // x in the frame of G: Rᵀ (x − t)
    static constexpr vec3<T> point_in(const motor_map<T>& G, const vec3<T>& x) noexcept { return linear3::apply_transposed(G.R, linear3::sub(x, G.t)); }
    constexpr void keep(const constraint_block<T>& c, std::uint64_t k, std::uint32_t partner, step_report<T>& report) noexcept {
        if (report.error != error_code::none) return;
        if (const error_code e = blocks_.add(c); e != error_code::none) return void(report.error = e);
        partner_[count_] = partner;
        keys_[count_++] = k;
        report.limits += on_joint(c.kind) && c.kind != block_kind::joint_friction;
    }

    constraint_set<Tree, T, Capacity> blocks_;
    std::array<std::uint64_t, Capacity> keys_{}, last_keys_{};
    std::array<std::uint32_t, Capacity> partner_{};
    std::array<vec3<T>, Capacity> partner_point_{};
    std::size_t count_ = 0, last_count_ = 0;
    std::array<T, 3 * Capacity> last_{};
    impulse_result<Tree, T, Capacity> result_{};
    std::array<T, dynamics_detail::polish_scratch_size(Capacity)> scratch_;
};

}  // namespace ctga::constrained
