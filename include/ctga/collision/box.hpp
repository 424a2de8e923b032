// A box with half extents (a, b, c) about its body's origin, edges along the body's axes. Its mass
// at density ρ is ρ 8abc with Ixx = m (b² + c²)/3, Iyy = m (a² + c²)/3, Izz = m (a² + b²)/3 about
// its centre (a full edge length 2a: m (2a)²/12 = m a²/3).
#pragma once

#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

template <class T = double>
struct box {
    vec3<T> half;  // half extents along x, y, z
};

// Reported: non_finite, non_positive_size (a half extent ≤ 0).
template <class T>
[[nodiscard]] constexpr checked<box<T>> make_box(const T& a, const T& b, const T& c) noexcept {
    if (!is_finite(a) || !is_finite(b) || !is_finite(c)) return {{}, error_code::non_finite};
    if (!(a > T(0)) || !(b > T(0)) || !(c > T(0))) return {{}, error_code::non_positive_size};
    return {box<T>{{a, b, c}}, error_code::none};
}

// The support point along u: the corner on u's side of each axis (+ where u's component is 0).
// The box is its own core (radius 0).
template <class T>
[[nodiscard]] constexpr vec3<T> core_support(const box<T>& x, const vec3<T>& u) noexcept {
    return {u[0] < T(0) ? -x.half[0] : x.half[0], u[1] < T(0) ? -x.half[1] : x.half[1], u[2] < T(0) ? -x.half[2] : x.half[2]};
}
template <class T>
[[nodiscard]] constexpr T core_radius(const box<T>&) noexcept {
    return T(0);
}

template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> mass_of(const box<T>& x, const T& density) noexcept {
    const T a2 = x.half[0] * x.half[0], b2 = x.half[1] * x.half[1], c2 = x.half[2] * x.half[2];
    const T m = density * T(8) * x.half[0] * x.half[1] * x.half[2];
    return make_principal_mass_properties(m, m * (b2 + c2) / T(3), m * (a2 + c2) / T(3), m * (a2 + b2) / T(3));
}

}  // namespace ctga::collision
