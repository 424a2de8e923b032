// The shape kinds a scene can hold, as a type: a shape of a scene is a std::variant of its kinds
// (shape<sphere<T>, box<T>, convex_hull<T, 32>>), and a query on two such shapes visits both:
// the pair routines compiled are exactly those of the kinds in the two variants (K × L of them,
// chosen by narrowphase.hpp at compile time), and the run-time choice is the variants' index, a
// jump table, with no virtual call. A pair of kinds without a routine (two meshes, a mesh and a
// half-space) is a compile error naming the pair: a scene keeps its static surroundings
// (half-spaces, meshes, height fields) in a variant of their own, queried only against the moving
// kinds, so that two static kinds never meet.
#pragma once

#include <variant>

#include "ctga/collision/aabb.hpp"
#include "ctga/collision/manifold.hpp"
#include "ctga/collision/narrowphase.hpp"
#include "ctga/collision/ray_cast.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {

template <class... Kinds>
using shape = std::variant<Kinds...>;

template <class... A, class... B, class T>
[[nodiscard]] constexpr separation<T> separation_of(const shape<A...>& a, const motor_map<T>& pa, const shape<B...>& b,
                                                    const motor_map<T>& pb) noexcept {
    return std::visit([&](const auto& x, const auto& y) { return separation_of(x, pa, y, pb); }, a, b);
}

template <class... A, class... B, class T>
[[nodiscard]] constexpr manifold<T> contact_of(const shape<A...>& a, const motor_map<T>& pa, const shape<B...>& b,
                                               const motor_map<T>& pb, const T& margin) noexcept {
    return std::visit([&](const auto& x, const auto& y) { return contact_of(x, pa, y, pb, margin); }, a, b);
}

template <class... A, class T>
[[nodiscard]] constexpr aabb<T> bounds_of(const shape<A...>& a, const motor_map<T>& pa) noexcept {
    return std::visit([&](const auto& x) { return bounds_of(x, pa); }, a);
}

template <class... A, class T>
[[nodiscard]] constexpr ray_hit<T> ray_cast(const shape<A...>& a, const motor_map<T>& pa, const ray<T>& r) noexcept {
    return std::visit([&](const auto& x) { return ray_cast(x, pa, r); }, a);
}

}  // namespace ctga::collision
