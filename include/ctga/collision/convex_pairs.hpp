// The separation of any two convex shapes, for the pairs without a closed form or a routine of
// their own (hulls, cylinders, a capsule and a box, …): each shape is a core grown by a radius
// (core_support, core_radius: a sphere its centre, a capsule its segment, a box, a cylinder or a
// hull itself), and the Minkowski sum of cores and radii gives
//   cores apart by δ (GJK, gjk.hpp):      distance = δ − r_A − r_B along the cores' closest points;
//   cores overlapping by p (EPA, epa.hpp): distance = −p − r_A − r_B along EPA's normal,
// the witnesses moved out by the radii along the normal. Cores within rounding of each other
// (1024 ε of the simplex's size) go to EPA, which tells touching from overlapping. GJK's
// tolerance 1e-14 is relative to the distance squared, EPA's 1e-12 relative to the size of the
// Minkowski difference: exact to rounding for polytopes, for curved cores (a cylinder's rim)
// within the tolerance of the sampled curve.
// A half-space and any convex shape: its deepest point along −n is the support point along −n
// (less the radius), as in primitive_pairs.hpp's closed forms.
#pragma once

#include <cstddef>
#include <limits>

#include "ctga/collision/epa.hpp"
#include "ctga/collision/gjk.hpp"
#include "ctga/collision/half_space.hpp"
#include "ctga/collision/primitive_pairs.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"

namespace ctga::collision {

// A shape the convex routines take: a support function of its core and a radius.
template <class S, class T>
concept convex_shape = requires(const S& s, const vec3<T>& u) {
    { core_support(s, u) } -> std::convertible_to<vec3<T>>;
    { core_radius(s) } -> std::convertible_to<T>;
};

template <class A, class B, class T>
[[nodiscard]] constexpr separation<T> convex_separation(const A& a, const motor_map<T>& pa, const B& b, const motor_map<T>& pb) noexcept {
    const T ra = core_radius(a), rb = core_radius(b);
    gjk_detail::simplex<T> last;
    const gjk_result<T> result = gjk_detail::run(a, pa, b, pb, T(1e-14), last);
    // apart by more than rounding (a face resting on a face can leave the origin 1e-16 off GJK's
    // last triangle while the cores overlap: that is EPA's to decide)
    T size = T(0);
    for (std::size_t i = 0; i < last.n; ++i) size = size > length(last.v[i].w) ? size : length(last.v[i].w);
    if (!result.overlap && result.distance > T(1024) * std::numeric_limits<T>::epsilon() * size) {
        const vec3<T> d = linear3::sub(result.point_b, result.point_a);
        const vec3<T> n = linear3::scale(T(1) / length(d), d);
        return {result.distance - ra - rb, n, linear3::add_scaled(result.point_a, ra, n), linear3::add_scaled(result.point_b, -rb, n)};
    }
    const penetration<T> p = epa(a, pa, b, pb, last, T(1e-12));
    return {-p.depth - ra - rb, p.normal, linear3::add_scaled(p.point_a, ra, p.normal), linear3::add_scaled(p.point_b, -rb, p.normal)};
}

// A half-space A and a convex shape B: B's support point along −n, less its radius.
template <class B, class T>
[[nodiscard]] constexpr separation<T> half_space_separation(const motor_map<T>& pa, const B& b, const motor_map<T>& pb) noexcept {
    const vec3<T> n = axis_of(pa, 2);
    const vec3<T> deepest = gjk_detail::world_support(b, pb, linear3::scale(T(-1), n));
    return primitive_detail::below(pa, n, linear3::add_scaled(deepest, -core_radius(b), n));
}

}  // namespace ctga::collision
