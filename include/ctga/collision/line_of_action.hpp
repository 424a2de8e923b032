// A contact's force as the paper's co-screw (§5): a force along a unit direction n through the point
// x is a line, the wrench P = (x × n, n) in coscrew.hpp's (l, p) = (τ, F) order (moment about the
// origin, force), with l·p = 0 as a line's must. Its pairing with a body's screw s = (ω, v), both
// about the same origin, is the paper's evaluation map
//   P(s) = ω·(x × n) + v·n = n·(v + ω × x),
// the speed along n of the body's point at x. For a manifold point with normal n (from A to B) the
// rows of the contact problem (parts 2 and 3) are these pairings: P(s_B) − P(s_A) the normal
// approach rate, and the same with two tangents t₁, t₂ ⟂ n for friction.
#pragma once

#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/linear3.hpp"

namespace ctga::collision {

template <class T>
[[nodiscard]] constexpr coscrew<T> line_of_action(const vec3<T>& x, const vec3<T>& n) noexcept {
    const vec3<T> moment = linear3::cross(x, n);
    return coscrew<T>{moment[0], moment[1], moment[2], n[0], n[1], n[2]};
}

}  // namespace ctga::collision
