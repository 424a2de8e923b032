// A tree's joint limits and joint friction (URDF <limit> and <dynamics>), per velocity number k
// (Tree::v_offset[i] is body i's first): data for what runs above the dynamics (a controller's
// bounds, random_configuration, the contact layers' limit constraints), not forces the
// algorithms apply.
//
//   auto limits = robot::make_limits<double>();            // the URDF header's, checked
//   limits->upper[robot::tree::v_offset[3]]                // body 3's joint's upper position
//
// For a joint of one degree of freedom, lower and upper bound its coordinate q (rad or m). For a
// floating joint (velocity numbers (ω, v)), the entries of v bound the base origin's position in
// the joint frame, x, y, z, and the entries of ω are unbounded (a rotation has no box). A bound
// that is absent is ±∞ (a continuous joint, a velocity without limit).
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include "ctga/chains/tree.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
struct joint_limits {
    static_assert(std::numeric_limits<T>::has_infinity,
                  "ctga::chains::joint_limits: the scalar type must have an infinity (float, double, long double)");
    std::array<T, Tree::nv> lower{}, upper{};  // position bounds, lower[k] ≤ q_k ≤ upper[k]
    std::array<T, Tree::nv> velocity{};        // |q̇_k| ≤ velocity[k]
    std::array<T, Tree::nv> effort{};          // |τ_k| ≤ effort[k]
    std::array<T, Tree::nv> damping{};         // viscous damping coefficient: τ_k = −damping[k] q̇_k
    std::array<T, Tree::nv> friction{};        // Coulomb (dry) friction: |τ_k| ≤ friction[k] while it sticks
};

// No bounds, no damping, no friction.
template <class Tree, class T = double>
[[nodiscard]] constexpr joint_limits<Tree, T> unlimited() noexcept {
    constexpr T inf = std::numeric_limits<T>::infinity();
    joint_limits<Tree, T> out;
    out.lower.fill(-inf);
    out.upper.fill(inf);
    out.velocity.fill(inf);
    out.effort.fill(inf);
    return out;
}

// The limits checked: no NaN, lower ≤ upper (limits_reversed), velocity, effort, damping and
// friction ≥ 0 (negative_limit). Infinite bounds are allowed (none).
template <class Tree, class T>
[[nodiscard]] constexpr checked<joint_limits<Tree, T>> check_limits(const joint_limits<Tree, T>& l) noexcept {
    for (std::size_t k = 0; k < Tree::nv; ++k) {
        const T x[6] = {l.lower[k], l.upper[k], l.velocity[k], l.effort[k], l.damping[k], l.friction[k]};
        for (const T& v : x)
            if (v != v) return {{}, error_code::non_finite};
        if (!(l.lower[k] <= l.upper[k])) return {{}, error_code::limits_reversed};
        if (l.velocity[k] < T(0) || l.effort[k] < T(0) || l.damping[k] < T(0) || l.friction[k] < T(0))
            return {{}, error_code::negative_limit};
    }
    return {l, error_code::none};
}

}  // namespace ctga::chains
