// One rigid body's inertia data (paper §5–6): its mass properties (mass_properties.hpp) with N
// and M precomputed, as elements (inertia.hpp) and by ten parameters each (body_inertia.hpp), for
// the equations of motion (dynamics.hpp) and the integrators.
#pragma once

#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/support/checked.hpp"

namespace ctga {

// A rigid body's inertia in its own frame, with what the dynamics needs precomputed once: N and M
// as elements (24 and 36 blades), and both again by their ten parameters, side by side, for the
// equations of motion (acceleration(body, s, W): 24m for the momentum, 24m for the solve).
template <class T = double>
struct rigid_body {
    mass_properties<T> properties;  // m, c, I_c in the body frame
    rigid_inertia<T> N;             // inertia_of(properties)
    mobility<T> M;                  // mobility_of(properties) = N⁻¹
    body_inertia<T> Nb;             // N by (m, h = m c, I_o): body_inertia_of(properties)
    body_mobility<T> Mb;            // M by (1/m, c, J = I_c⁻¹): body_mobility_of(properties)
};

template <class T>
[[nodiscard]] constexpr rigid_body<T> make_rigid_body(const mass_properties<T>& b) noexcept {
    return {b, inertia_of(b), mobility_of(b), body_inertia_of(b), body_mobility_of(b)};
}
// Checked all the way from the raw numbers.
template <class T>
[[nodiscard]] constexpr checked<rigid_body<T>> make_rigid_body(const T& mass, const vec3<T>& com,
                                                               const mat3<T>& inertia_c) noexcept {
    const auto b = make_mass_properties(mass, com, inertia_c);
    if (!b) return {{}, b.error};
    return {make_rigid_body(*b), error_code::none};
}

}  // namespace ctga
