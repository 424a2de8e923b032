// Robots and free bodies in one world, one solve for every contact: a kinematic tree (a robot; a
// tree may have several roots, so several robots are one tree) stepped with a physics_world's
// moving bodies, static shapes and joints (scenes/world.hpp), so that a gripper holds a box and
// a quadruped kicks a ball.
//
//   using cube = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, collision::box<double>>;
//   constrained::robot_world<robot::tree, double, 32, collision::half_space<double>, cube> w({4}, {.statics = 1, .contacts = 64, .pairs = 16});
//   w.world.add_static(collision::half_space<double>{}, ground, {});      // the world's statics, bodies, joints
//   w.world.add_body<0>(*collision::make_box(0.03, 0.03, 0.03), 500.0, pose, {});
//   w.robot.limits = *robot::make_limits<double>();                      // the robot's stepper's blocks
//   auto report = w.step(m, q, qd, tau, geometry, settings);             // both advanced by settings.step
//
// One step h:
//   1. the world up to its solve (physics_world::begin: collision among its bodies and statics,
//      its rows, the bodies' free velocities, its warm start);
//   2. the robot's blocks (contact_stepper::gather): its shapes against the world's statics and
//      against each other, limits, joint friction, and its shapes against the world's moving bodies
//      (the world's broadphase asked with each shape's box): such a contact is a tree block with B
//      the world, a frame fixed where the body's witness is at the step's start, and a partner, the
//      body, whose side of the block is a world row's side (constraints/contact_rows.hpp) on the
//      same lines: block i's velocity is the tree's J q̇ less the body's point velocity along the
//      frame's axes, u_i = J_i q̇⁺ − L_i(s_B⁺), and its impulse r_i acts on the robot, −r_i on the
//      body (one line: the pair's wrenches balance);
//   3. one frictional problem (constraints/contact_problem.hpp) on the world's rows and the
//      robot's blocks: its operator (scene_delassus) is the world's rows_delassus for the world's
//      rows, constrained_dynamics.hpp's tree_delassus for the robot's (W without forming it) plus
//      the partners' rows_delassus; to settings.solve's tolerance and sweeps, then Newton (W
//      formed by applying unit impulses: W is linear) when the sweeps stop above the tolerance
//      and the problem has at most the world's polish_limit blocks besides the robot's (the
//      sweeps in row order on the calling thread: the world's partitions are not used);
//   4. the robot's q̇⁺ from its impulses (impulse_dynamics.hpp), the world's position correction
//      (on its rows, with every impulse applied) and integration, then q ← q ⊕ h q̇⁺. A body that
//      touches the robot moves this step by its velocity after, as the robot does
//      (physics_world::move_by_velocity_after), so that their gaps close as the rows assumed:
//      by the average, as the world's other bodies move, a ball the arm knocks at 0.8 m/s moved
//      h v / 2 less than the arm's row assumed, and the next step's push out of that overlap
//      added 5e-4 of the energy in a step (measured, the test's arm).
// Each side keeps its own laws: the robot's contacts (with bodies too) push out of overlap by the
// velocity bias β φ / h (impulse_dynamics.hpp) and take the stepper's μ; the world's keep its
// speculative rows, restitution, materials and split-impulse correction. The robot meets a
// kinematic or soft static shape as a fixed, rigid one. Refused: a world with substeps > 0 (the
// soft step: not_supported), and whatever either stepper refuses; a failed step leaves both
// states as they were.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>
#include <span>
#include <utility>
#include <vector>

#include "ctga/constrained/constrained_dynamics.hpp"
#include "ctga/constrained/contact_step.hpp"
#include "ctga/constrained/impulse_dynamics.hpp"
#include "ctga/constraints/contact_problem.hpp"
#include "ctga/constraints/contact_rows.hpp"
#include "ctga/constraints/newton_polish.hpp"
#include "ctga/scenes/world.hpp"
#include "ctga/support/checked.hpp"

namespace ctga::constrained {

template <class T>
struct scene_report {
    error_code error = error_code::none;
    constraints::contact_report<T> solver{};  // the one problem: the world's rows, the robot's blocks
    ctga::step_report<T> world{};              // the world's contacts, overlap, joints, position correction
    step_report<T> robot{};                    // the robot's contacts (those with bodies among them), limits, overlap
    std::size_t touching = 0;                  // the robot's contacts with the world's moving bodies
};

namespace scene_detail {
// W of the world's rows [0, split) and the robot's blocks after them (above, 3.); a robot block's
// partner row has no sides when it has no partner (its block and velocity are then zero).
template <class Tree, class T, std::size_t Capacity>
struct scene_delassus {
    constraints::rows_delassus<T> world;
    dynamics_detail::tree_delassus<Tree, T, Capacity>& tree;
    constraints::rows_delassus<T> partners;
    std::size_t split;

    [[nodiscard]] constexpr std::size_t contacts() const noexcept { return split + tree.contacts(); }
    [[nodiscard]] constexpr mat3<T> block(std::size_t i) const noexcept {
        if (i < split) return world.block(i);
        const mat3<T> a = tree.block(i - split), &b = partners.rows[i - split].block;
        mat3<T> out;
        for (std::size_t r = 0; r < 3; ++r)
            for (std::size_t c = 0; c < 3; ++c) out[r][c] = a[r][c] + b[r][c];
        return out;
    }
    [[nodiscard]] constexpr bool bilateral(std::size_t i) const noexcept { return i < split ? world.bilateral(i) : tree.bilateral(i - split); }
    [[nodiscard]] constexpr bool bounded(std::size_t i) const noexcept { return i < split ? world.bounded(i) : tree.bounded(i - split); }
    [[nodiscard]] constexpr std::array<vec3<T>, 2> bounds(std::size_t i) const noexcept { return i < split ? world.bounds(i) : tree.bounds(i - split); }
    [[nodiscard]] constexpr mat3<T> inverse_block(std::size_t i) const noexcept {
        return i < split ? world.inverse_block(i) : linear3::inverse_symmetric(block(i));
    }
    [[nodiscard]] constexpr std::array<T, 2> step_lengths(std::size_t i) const noexcept {
        return i < split ? world.step_lengths(i) : constraints::step_lengths(block(i));
    }
    [[nodiscard]] constexpr vec3<T> velocity(std::size_t i, std::span<const T> r) const noexcept {
        if (i < split) return world.velocity(i, r);
        return linear3::add(tree.velocity(i - split, {}), partners.velocity(i - split));
    }
    constexpr void apply(std::size_t i, const vec3<T>& dr) noexcept {
        if (i < split) return world.apply(i, dr);
        tree.apply(i - split, dr);
        partners.apply(i - split, dr);
    }
};
}  // namespace scene_detail

template <class Tree, class T, std::size_t Capacity, class Static, class... Kinds>
class robot_world {
    using world_type = physics_world<T, Static, Kinds...>;

   public:
    world_type world;                            // the bodies, statics, joints and their settings
    contact_stepper<Tree, T, Capacity> robot;    // the robot's permanent blocks and limits

    // The world's bodies of each kind and capacities (physics_world's); room for Capacity robot blocks.
    robot_world(const std::array<std::size_t, sizeof...(Kinds)>& bodies, const world_capacity& capacity, const world_settings<T>& settings = {},
                std::pmr::memory_resource* storage = std::pmr::get_default_resource())
        : world(bodies, capacity, settings, storage),
          impulse_(3 * (world_type::rows_for(capacity) + Capacity), storage), mu_(world_type::rows_for(capacity) + Capacity, storage),
          conjugate_(6 * (world_type::rows_for(capacity) + Capacity), storage),
          dense_(dense_size(settings.polish_limit + Capacity), storage), kind_(settings.polish_limit + Capacity, storage),
          bounds_(settings.polish_limit + Capacity, storage) {}

    template <class Shape, std::size_t N>
    scene_report<T> step(const chains::model<Tree, T>& m, chains::configuration<Tree, T>& q, chains::joint_vector<Tree, T>& qd,
                         const chains::joint_vector<Tree, T>& tau, const robot_geometry<Tree, Shape, T, N>& geometry,
                         const step_settings<T>& settings) noexcept {
        scene_report<T> out;
        const T h = settings.step;
        if (!is_finite(h) || !(h > T(0))) return out.error = error_code::non_finite, out;
        if (world.settings().substeps > 0) return out.error = error_code::not_supported, out;
        // 1. the world up to its solve
        if ((out.error = world.begin(h, out.world)) != error_code::none) return world.restore(), out;
        // 2. the robot's blocks
        chains::algorithm_detail::joint_maps<Tree, T> X;
        const auto statics = [&](auto&& f) { world.for_each_static(f); };
        const auto bodies = [&](const collision::aabb<T>& box, auto&& f) { world.for_each_body_near(box, f); };
        robot.gather(m, q, geometry, statics, bodies, settings, X, out.robot);
        if (out.robot.error == error_code::none) {
            robot.warm_start();
            out.robot.error = fill_impulse_problem(problem_, m, q, qd, tau, robot.block_set(), h, robot.limits.damping, settings.solve, &X);
        }
        if ((out.error = out.robot.error) != error_code::none) return world.restore(), out;
        const std::span<const constraint_block<T>> blocks = robot.blocks();
        const std::size_t split = world.rows().size(), m_t = blocks.size(), n = split + m_t;
        out.touching = partner_rows(blocks);
        // 3. one problem, warm-started: the world's impulses are on its bodies (begin), the
        // robot's on the tree (tree_delassus keeps them) and, here, on their partners
        const std::span<T> r(impulse_.data(), 3 * n), r_world = world.impulses(), r_robot = robot.impulses();
        constraints::rows_delassus<T> partners{std::span<const constraints::contact_row<T>>(partner_.data(), m_t), world.mobilities(), world.velocities()};
        for (std::size_t k = 0; k < r_world.size(); ++k) r[k] = r_world[k];
        for (std::size_t k = 0; k < r_robot.size(); ++k) r[r_world.size() + k] = r_robot[k];
        for (std::size_t i = 0; i < m_t; ++i) partners.apply(i, vec3<T>{r_robot[3 * i], r_robot[3 * i + 1], r_robot[3 * i + 2]});
        for (std::size_t i = 0; i < split; ++i) mu_[i] = world.friction()[i];
        for (std::size_t i = 0; i < m_t; ++i) mu_[split + i] = blocks[i].mu;
        auto& [R, P, qv] = problem_.x;
        dynamics_detail::tree_delassus<Tree, T, Capacity> tree(P, problem_.f, R, std::span<const T>(qv.data(), 3 * m_t), blocks, settings.solve.rows.redundancy, h,
                                              std::span<const T>(r_robot.data(), 3 * m_t));
        scene_detail::scene_delassus<Tree, T, Capacity> D{{world.rows(), world.mobilities(), world.velocities()}, tree, partners, split};
        const std::span<const T> mu(mu_.data(), n);
        out.solver = constraints::solve_contacts<T>(D, mu, r, settings.solve.rows.solver, std::span<T>(conjugate_.data(), 6 * n));
        if (!out.solver.converged && out.solver.error == error_code::none && n <= kind_.size()) polish(D, mu, r, settings.solve.rows.solver.tolerance, out.solver);
        if ((out.error = out.solver.error) != error_code::none) return world.restore(), out;
        for (std::size_t k = 0; k < r_world.size(); ++k) r_world[k] = r[k];
        for (std::size_t k = 0; k < r_robot.size(); ++k) r_robot[k] = r[r_world.size() + k];
        out.robot.solver = out.world.contact = out.solver;
        // 4. the robot's q̇⁺, the world's correction and integration, then the robot's
        dynamics_detail::add_forces(problem_.f, problem_.z, R, P, std::span<const T>(r_robot));
        chains::joint_vector<Tree, T> after;
        for (std::size_t k = 0; k < Tree::nv; ++k) after[k] = qd[k] + problem_.z[k];
        for (std::size_t i = 0; i < m_t; ++i)
            if (const std::uint32_t body = robot.partner(i); body != robot.no_partner) world.move_by_velocity_after(body);
        world.correct(h, out.world);
        if ((out.error = world.end(h)) != error_code::none) return out;
        robot.finish(m, q, qd, after, h);
        return out;
    }

   private:
    static constexpr std::size_t dense_size(std::size_t blocks) noexcept {
        return 9 * blocks * blocks + 6 * blocks + constraints::newton_scratch_size(blocks);
    }
    // Each robot block's row on its partner body: the block's lines (through A's point, along its
    // frame's axes n, t1, t2: constraint_rows.hpp) on the body's side a, which feels −r (contact_rows.hpp);
    // no sides without a partner. Returns the blocks with partners.
    std::size_t partner_rows(std::span<const constraint_block<T>> blocks) noexcept {
        std::size_t touching = 0;
        for (std::size_t i = 0; i < blocks.size(); ++i) {
            constraints::contact_row<T>& row = partner_[i];
            row = {};
            const std::uint32_t body = robot.partner(i);
            if (body == robot.no_partner) continue;
            const constraint_block<T>& c = blocks[i];
            const vec3<T>& x = robot.partner_point(i);
            const mat3<T>& E = c.at_b.R;  // (B the world: its axes are the world's)
            row.direction = {vec3<T>{E[0][2], E[1][2], E[2][2]}, vec3<T>{E[0][0], E[1][0], E[2][0]}, vec3<T>{E[0][1], E[1][1], E[2][1]}};
            row.a = constraints::make_side(body, world.centre(body), x, row.direction);
            row.block = constraints::delassus_block<T>(row, world.mobilities());
            ++touching;
        }
        return touching;
    }
    // Newton on W formed densely: column k the change of the velocities under a unit impulse on
    // row k (applied and taken back), then newton_polish.hpp from r, the change applied.
    void polish(scene_detail::scene_delassus<Tree, T, Capacity>& D, std::span<const T> mu, std::span<T> r, const T& tolerance,
                constraints::contact_report<T>& report) noexcept {
        const std::size_t m = D.contacts(), n = 3 * m;
        const std::span<T> W(dense_.data(), n * n), q(dense_.data() + n * n, n), before(dense_.data() + n * n + n, n),
            rest(dense_.data() + n * n + 2 * n, dense_.size() - n * n - 2 * n);
        for (std::size_t i = 0; i < m; ++i) {
            const vec3<T> u = D.velocity(i, r);
            for (std::size_t a = 0; a < 3; ++a) q[3 * i + a] = u[a];
        }
        for (std::size_t k = 0; k < n; ++k) {
            vec3<T> e{};
            e[k % 3] = T(1);
            r[k] += T(1);
            D.apply(k / 3, e);
            for (std::size_t i = 0; i < m; ++i) {
                const vec3<T> u = D.velocity(i, r);
                for (std::size_t a = 0; a < 3; ++a) W[(3 * i + a) * n + k] = u[a] - q[3 * i + a];
            }
            r[k] -= T(1);
            D.apply(k / 3, linear3::scale(T(-1), e));
        }
        for (std::size_t i = 0; i < n; ++i) {  // q = u − W r
            before[i] = r[i];
            for (std::size_t k = 0; k < n; ++k) q[i] -= W[i * n + k] * r[k];
        }
        for (std::size_t i = 0; i < m; ++i) {
            kind_[i] = D.bounded(i) ? constraints::bounded_block : D.bilateral(i) ? constraints::bilateral_block : constraints::contact_block;
            bounds_[i] = D.bounds(i);
        }
        const constraints::contact_report<T> newton =
            constraints::newton_polish<T>(W, q, mu, r, rest, tolerance, 30, std::span<const unsigned char>(kind_.data(), m),
                                          std::span<const std::array<vec3<T>, 2>>(bounds_.data(), m));
        for (std::size_t i = 0; i < m; ++i) D.apply(i, vec3<T>{r[3 * i] - before[3 * i], r[3 * i + 1] - before[3 * i + 1], r[3 * i + 2] - before[3 * i + 2]});
        report.residual = newton.residual, report.converged = newton.converged, report.error = newton.error;
        report.polish_steps += newton.sweeps;
    }

    impulse_problem<Tree, T, Capacity> problem_;
    std::array<constraints::contact_row<T>, Capacity> partner_{};
    std::pmr::vector<T> impulse_, mu_, conjugate_, dense_;
    std::pmr::vector<unsigned char> kind_;
    std::pmr::vector<std::array<vec3<T>, 2>> bounds_;
};

}  // namespace ctga::constrained
