// A capsule: the points within radius r of the segment from (0, 0, −h) to (0, 0, h) on its body's
// z axis (h = 0: a sphere). Its mass at density ρ is a cylinder's, m_c = ρ π r² 2h, and two
// hemispheres', m_s = ρ (4/3) π r³; about the centre, Izz = m_c r²/2 + (2/5) m_s r² and
// Ixx = Iyy = m_c (r²/4 + h²/3) + m_s ((2/5) r² + h² + (3/4) h r) (a hemisphere of mass m_s/2 has
// (2/5)(m_s/2) r² about a diameter of its flat face, whose centre is h from the capsule's and 3r/8
// from its own centre of mass: the parallel-axis theorem twice gives (m_s/2)(h² + (3/4) h r)).
#pragma once

#include <numbers>

#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

template <class T = double>
struct capsule {
    T radius;
    T half_height;  // of the segment: the capsule is 2 (h + r) long
};

// Reported: non_finite, non_positive_size (r ≤ 0 or h < 0).
template <class T>
[[nodiscard]] constexpr checked<capsule<T>> make_capsule(const T& radius, const T& half_height) noexcept {
    if (!is_finite(radius) || !is_finite(half_height)) return {{}, error_code::non_finite};
    if (!(radius > T(0)) || !(half_height >= T(0))) return {{}, error_code::non_positive_size};
    return {capsule<T>{radius, half_height}, error_code::none};
}

// The core: the segment; its support point along u is the end on u's side (the +z end when u ⟂ z).
template <class T>
[[nodiscard]] constexpr vec3<T> core_support(const capsule<T>& c, const vec3<T>& u) noexcept {
    return {T(0), T(0), u[2] < T(0) ? -c.half_height : c.half_height};
}
template <class T>
[[nodiscard]] constexpr T core_radius(const capsule<T>& c) noexcept {
    return c.radius;
}

template <class T>
[[nodiscard]] constexpr checked<mass_properties<T>> mass_of(const capsule<T>& c, const T& density) noexcept {
    const T r = c.radius, h = c.half_height, r2 = r * r;
    const T mc = density * std::numbers::pi_v<T> * r2 * T(2) * h;
    const T ms = density * T(4) / T(3) * std::numbers::pi_v<T> * r2 * r;
    const T izz = mc * r2 / T(2) + T(2) / T(5) * ms * r2;
    const T ixx = mc * (r2 / T(4) + h * h / T(3)) + ms * (T(2) / T(5) * r2 + h * h + T(3) / T(4) * h * r);
    return make_principal_mass_properties(mc + ms, ixx, ixx, izz);
}

}  // namespace ctga::collision
