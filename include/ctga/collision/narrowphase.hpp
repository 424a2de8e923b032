// separation_of(A, pose_A, B, pose_B): the separation (separation.hpp) of any two shape kinds,
// chosen at compile time: the pair's own routine (`separation_between`, one per unordered pair, in
// the family headers) for (A, B), or the one for (B, A) seen from A (reversed); else a half-space
// and a convex shape, or two convex shapes, by convex_pairs.hpp. A pair with none is a compile
// error naming it, not a run-time fallback: a scene compiles only the routines of the kinds it can
// hold, and calls them without dispatch at run time.
// contact_of(A, pose_A, B, pose_B, margin): their contact manifold (manifold.hpp), by the pair's
// own routine (primitive_manifolds.hpp, box_pairs.hpp), else from the support features of two
// convex shapes or of a convex shape on a half-space (convex_manifolds.hpp); points farther apart
// than the margin are left out.
#pragma once

#include <concepts>

#include "ctga/collision/box_pairs.hpp"
#include "ctga/collision/convex_manifolds.hpp"
#include "ctga/collision/convex_pairs.hpp"
#include "ctga/collision/half_space.hpp"
#include "ctga/collision/manifold.hpp"
#include "ctga/collision/primitive_manifolds.hpp"
#include "ctga/collision/primitive_pairs.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/collision/surface_queries.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {
namespace narrowphase_detail {
template <class A, class B>
inline constexpr bool no_routine = false;
}

template <class A, class B, class T>
[[nodiscard]] constexpr separation<T> separation_of(const A& a, const motor_map<T>& pa, const B& b, const motor_map<T>& pb) noexcept {
    if constexpr (requires { separation_between(a, pa, b, pb); }) return separation_between(a, pa, b, pb);
    else if constexpr (requires { separation_between(b, pb, a, pa); }) return reversed(separation_between(b, pb, a, pa));
    else if constexpr (std::same_as<A, half_space<T>> && convex_shape<B, T>) return half_space_separation(pa, b, pb);
    else if constexpr (convex_shape<A, T> && std::same_as<B, half_space<T>>) return reversed(half_space_separation(pb, a, pa));
    else if constexpr (convex_shape<A, T> && convex_shape<B, T>) return convex_separation(a, pa, b, pb);
    else static_assert(narrowphase_detail::no_routine<A, B>, "ctga::collision::separation_of: no narrowphase routine for this pair of shape kinds");
}
// The same from the bodies' motors (their maps formed here: 31m 24a and a division each).
template <class A, class B, class T>
[[nodiscard]] constexpr separation<T> separation_of(const A& a, const motor<T>& ga, const B& b, const motor<T>& gb) noexcept {
    return separation_of(a, map_of(ga), b, map_of(gb));
}

template <class A, class B, class T>
[[nodiscard]] constexpr manifold<T> contact_of(const A& a, const motor_map<T>& pa, const B& b, const motor_map<T>& pb, const T& margin) noexcept {
    if constexpr (requires { manifold_between(a, pa, b, pb, margin); }) return manifold_between(a, pa, b, pb, margin);
    else if constexpr (requires { manifold_between(b, pb, a, pa, margin); }) return reversed(manifold_between(b, pb, a, pa, margin));
    else if constexpr (std::same_as<A, half_space<T>> && convex_shape<B, T>) return half_space_manifold(pa, b, pb, margin);
    else if constexpr (convex_shape<A, T> && std::same_as<B, half_space<T>>) return reversed(half_space_manifold(pb, a, pa, margin));
    else if constexpr (convex_shape<A, T> && convex_shape<B, T>) return convex_manifold(a, pa, b, pb, separation_of(a, pa, b, pb), margin);
    else static_assert(narrowphase_detail::no_routine<A, B>, "ctga::collision::contact_of: no manifold routine for this pair of shape kinds");
}

}  // namespace ctga::collision
