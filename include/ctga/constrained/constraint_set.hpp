// Constraints on a kinematic tree: loop closures, a frame held in the world (a glued foot, a
// weld), frictional point contacts. Each is made of blocks of three rows acting between two bodies
// of the tree, A and B (B may be the world), through a constraint frame fixed to each: at_a in
// A's body frame, at_b in B's (the world's when B is the world). Kinds of block:
//
//   point        the origin of A's constraint frame stays on the origin of B's (3 rows, bilateral)
//   orientation  A's constraint frame turns with B's (3 rows, bilateral)
//   contact      A's origin touches B's along B's z axis, the normal n from B to A: a unilateral
//                row and two of Coulomb friction with coefficient μ (the cone of constraints/)
//   lower_limit  body A's joint (one dof, k) kept at or above `bound`: one unilateral row on q_k
//   upper_limit  … at or below `bound` (the row −q_k)
//   joint_friction  the joint's dry friction: one row on q̇_k whose force is bounded, |τ_k| ≤ `bound`
// A limit's or friction's block has one row; its other two are empty (zero, with zero force), so
// that every block is three rows and the solver's bounded block (constraints/) takes it as it is.
//
// A weld (a 6-D contact, a flat foot held) is a point and an orientation block. A set holds at
// most Capacity blocks (no allocation); adding past it is capacity_exceeded, and a block is
// refused with the first error it has: two sides on one body (joint_to_itself), a body index past
// the tree (bad_index), a non-finite placement or μ (non_finite), μ < 0 (negative_friction).
//
// Named frames are types (chains::frame<"FL_foot">): a constraint on a frame the tree does not
// have does not compile, and a loop closure between two frames of one body is a static_assert.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "ctga/chains/forward_kinematics.hpp"
#include "ctga/chains/frames.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::constrained {

enum class block_kind : unsigned char { point, orientation, contact, lower_limit, upper_limit, joint_friction };

// A block of one row on a joint's own coordinate (above).
[[nodiscard]] constexpr bool on_joint(block_kind k) noexcept { return k >= block_kind::lower_limit; }

template <class T = double>
struct constraint_block {
    block_kind kind = block_kind::point;
    int a = -1, b = -1;  // the two bodies (−1: the world)
    motor_map<T> at_a = chains::tree_detail::identity_map<T>(), at_b = chains::tree_detail::identity_map<T>();
    T mu = T(0);     // contact: Coulomb's coefficient
    T bound = T(0);  // a limit's bound on q_k; a joint friction's largest force
};

// How a frame is held: its origin only (3 rows), or its pose (6 rows: a weld).
enum class hold : unsigned char { point, weld };

template <class Tree, class T, std::size_t Capacity>
class constraint_set {
   public:
    static constexpr std::size_t capacity = Capacity;

    [[nodiscard]] constexpr std::span<const constraint_block<T>> blocks() const noexcept { return {blocks_.data(), count_}; }
    [[nodiscard]] constexpr std::size_t size() const noexcept { return count_; }
    [[nodiscard]] constexpr bool bilateral() const noexcept {
        for (std::size_t i = 0; i < count_; ++i)
            if (blocks_[i].kind != block_kind::point && blocks_[i].kind != block_kind::orientation) return false;
        return true;
    }
    constexpr void clear() noexcept { count_ = 0; }

    // A block as it is (contacts from collision: a body index, a point and a normal at run time).
    constexpr error_code add(const constraint_block<T>& c) noexcept {
        if (count_ == Capacity) return error_code::capacity_exceeded;
        if (c.a < -1 || c.b < -1 || c.a >= static_cast<int>(Tree::size) || c.b >= static_cast<int>(Tree::size)) return error_code::bad_index;
        if (on_joint(c.kind) && (c.a < 0 || c.b != -1 || Tree::nv_of[static_cast<std::size_t>(c.a)] != 1)) return error_code::bad_index;
        if (c.a == c.b) return error_code::joint_to_itself;
        if (!finite_map(c.at_a) || !finite_map(c.at_b) || !is_finite(c.mu) || !is_finite(c.bound)) return error_code::non_finite;
        if (c.kind == block_kind::contact && c.mu < T(0)) return error_code::negative_friction;
        if (c.kind == block_kind::joint_friction && c.bound < T(0)) return error_code::negative_limit;
        blocks_[count_++] = c;
        return error_code::none;
    }

    // A loop closure: frame FA's origin (and, for a weld, its axes) held on frame FB's.
    template <class FA, class FB>
    constexpr error_code close_loop(const chains::model<Tree, T>& m, FA fa, FB fb, hold h = hold::point) noexcept {
        using A = chains::frame_detail::frame_on<Tree, FA>;
        using B = chains::frame_detail::frame_on<Tree, FB>;
        static_assert(A::body != B::body, "ctga::constrained::close_loop: the two frames are on one body (a loop closure there holds nothing)");
        return add_held(h, A::body, chains::frame_detail::placement(m, fa), B::body, chains::frame_detail::placement(m, fb));
    }
    // Frame F held where it is at q (a foot glued, a weld to the world).
    template <class F>
    constexpr error_code fix(const chains::model<Tree, T>& m, const chains::configuration<Tree, T>& q, F f, hold h = hold::point) noexcept {
        using A = chains::frame_detail::frame_on<Tree, F>;
        static_assert(A::body >= 0, "ctga::constrained::fix: the frame is on the world (fixing it holds nothing)");
        return add_held(h, A::body, chains::frame_detail::placement(m, f), -1, chains::frame_pose(m, chains::forward_kinematics(m, q), f));
    }
    // Frame F's origin touching the world at its place at q, the world's normal n there (unit,
    // pointing to the robot's side), friction μ.
    template <class F>
    constexpr error_code touch(const chains::model<Tree, T>& m, const chains::configuration<Tree, T>& q, F f, const vec3<T>& n,
                               const T& mu) noexcept {
        using A = chains::frame_detail::frame_on<Tree, F>;
        static_assert(A::body >= 0, "ctga::constrained::touch: the frame is on the world");
        const motor_map<T> W = chains::frame_pose(m, chains::forward_kinematics(m, q), f);
        const T length = math::sqrt(linear3::dot(n, n));
        if (!is_finite(length)) return error_code::non_finite;
        if (!(length > T(0))) return error_code::zero_direction;
        return add({block_kind::contact, A::body, -1, chains::frame_detail::placement(m, f), contact_frame(W.t, linear3::scale(T(1) / length, n)), mu});
    }

    // Body i's joint (one dof) kept within [lower, upper]: a block per finite bound (none for ±∞).
    // Refused: a joint of other than one dof (bad_index), lower > upper (limits_reversed).
    constexpr error_code limit(int body, const T& lower, const T& upper) noexcept {
        if (lower != lower || upper != upper) return error_code::non_finite;
        if (lower > upper) return error_code::limits_reversed;
        if (is_finite(lower))
            if (const error_code e = add({block_kind::lower_limit, body, -1, {}, {}, T(0), lower}); e != error_code::none) return e;
        return is_finite(upper) ? add({block_kind::upper_limit, body, -1, {}, {}, T(0), upper}) : error_code::none;
    }
    // Body i's joint's dry friction, |τ| ≤ f while it sticks (URDF <dynamics friction>).
    constexpr error_code joint_friction(int body, const T& f) noexcept { return add({block_kind::joint_friction, body, -1, {}, {}, T(0), f}); }

    // The world frame of a contact at x with unit normal n: z = n, x and y any tangents.
    [[nodiscard]] static constexpr motor_map<T> contact_frame(const vec3<T>& x, const vec3<T>& n) noexcept {
        // the tangent from the axis n is least along (Frisvad's basis would do as well)
        const bool off_x = (n[0] < T(0) ? -n[0] : n[0]) < T(0.6);
        const vec3<T> e = off_x ? vec3<T>{T(1), T(0), T(0)} : vec3<T>{T(0), T(1), T(0)};
        vec3<T> t1 = linear3::sub(e, linear3::scale(linear3::dot(e, n), n));
        t1 = linear3::scale(T(1) / math::sqrt(linear3::dot(t1, t1)), t1);
        const vec3<T> t2 = linear3::cross(n, t1);
        return {{{{t1[0], t2[0], n[0]}, {t1[1], t2[1], n[1]}, {t1[2], t2[2], n[2]}}}, x};
    }

   private:
    static constexpr bool finite_map(const motor_map<T>& g) noexcept {
        for (const auto& row : g.R)
            for (const T& x : row)
                if (!is_finite(x)) return false;
        return is_finite(g.t[0]) && is_finite(g.t[1]) && is_finite(g.t[2]);
    }
    constexpr error_code add_held(hold h, int a, const motor_map<T>& at_a, int b, const motor_map<T>& at_b) noexcept {
        if (h == hold::weld && count_ + 2 > Capacity) return error_code::capacity_exceeded;
        const error_code e = add({block_kind::point, a, b, at_a, at_b, T(0)});
        if (e != error_code::none || h == hold::point) return e;
        return add({block_kind::orientation, a, b, at_a, at_b, T(0)});
    }

    std::array<constraint_block<T>, Capacity> blocks_{};
    std::size_t count_ = 0;
};

}  // namespace ctga::constrained
