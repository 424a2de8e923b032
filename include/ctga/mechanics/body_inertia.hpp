// A rigid body's inertia element N (§5) by its ten parameters: the mass m, the first moment
// h = m c and the inertia tensor about the body origin I_o (six numbers, symmetric).
//
// N = [[I_o, Ĥ], [−Ĥ, m 1]] has 24 non-zero blades, but only ten distinct coefficients: I_o(i, j)
// and I_o(j, i) are one number, m sits on three blades and each h_k on four. rigid_inertia stores
// the 24 blades; body_inertia stores the ten numbers, each a grade-0 element, and builds N as
// the sum of ten exact constant blocks scaled by them:
//
//   N = Σ I_o(i,j) (α_i ε̃_j + α_j ε̃_i)/(1 + δ_ij) + m (a2a3e2e3 + a3a1e3e1 + a1a2e1e2)
//     + h_x (a3ae3e1 − a2ae1e2 + a3a1e3e … ) + …   (entry (i, j) is the blade α_i ε̃_j, design.md §7)
//
// Inside a formula each parameter is one leaf, so A ∨ (N ∧ s) reads ten numbers instead of 24
// and shares their products exactly where the hand-written spatial code does (24m 18a either way).
// The typed functions below and the transform by a motor_map work on the ten numbers.
#pragma once

#include "ctga/algebra/operations.hpp"
#include "ctga/expr/inline.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motion.hpp"
#include "ctga/mechanics/spatial.hpp"
#include "ctga/mechanics/transform.hpp"

namespace ctga {

template <class T = double>
struct body_inertia {
    using scalar = cl062::mv<T, "1">;
    scalar m, hx, hy, hz;            // mass and first moment h = m c
    scalar ixx, iyy, izz, ixy, ixz, iyz;  // I_o, the inertia tensor about the body origin

    [[nodiscard]] constexpr T mass() const noexcept { return m[0]; }
    [[nodiscard]] constexpr vec3<T> first_moment() const noexcept { return {hx[0], hy[0], hz[0]}; }
    [[nodiscard]] constexpr mat3<T> inertia_o() const noexcept {
        return {{{ixx[0], ixy[0], ixz[0]}, {ixy[0], iyy[0], iyz[0]}, {ixz[0], iyz[0], izz[0]}}};
    }
};

namespace body_inertia_detail {
using G = cl062;
// N from the ten parameters, as an expression over them (their order as in body_inertia).
inline constexpr auto element = [](auto m, auto hx, auto hy, auto hz, auto ixx, auto iyy, auto izz, auto ixy, auto ixz,
                                   auto iyz) {
    return ixx * G::basis<"a1ae1e"> + iyy * G::basis<"a2ae2e"> + izz * G::basis<"a3ae3e"> +
           ixy * (G::basis<"a1ae2e"> + G::basis<"a2ae1e">) + ixz * (G::basis<"a1ae3e"> + G::basis<"a3ae1e">) +
           iyz * (G::basis<"a2ae3e"> + G::basis<"a3ae2e">) +
           m * (G::basis<"a2a3e2e3"> + G::basis<"a3a1e3e1"> + G::basis<"a1a2e1e2">) +
           // Ĥ in the upper right, −Ĥ = Ĥᵀ in the lower left
           hx * (G::basis<"a3ae3e1"> - G::basis<"a2ae1e2"> + G::basis<"a3a1e3e"> - G::basis<"a1a2e2e">) +
           hy * (G::basis<"a1ae1e2"> - G::basis<"a3ae2e3"> - G::basis<"a2a3e3e"> + G::basis<"a1a2e1e">) +
           hz * (G::basis<"a2ae2e3"> - G::basis<"a1ae3e1"> + G::basis<"a2a3e2e"> - G::basis<"a3a1e1e">);
};
}  // namespace body_inertia_detail

// The paper's formulas with N given by its ten parameters (the argument order of body_inertia).
namespace paper {
inline constexpr auto momentum_of_parameters = formula([](auto s, auto... q) {
    return invariants::A & (body_inertia_detail::element(q...) ^ lift(s));
});
inline constexpr auto twice_kinetic_energy_of_parameters = formula([](auto s, auto... q) {
    return bar(lift(s)) & (body_inertia_detail::element(q...) ^ lift(s));
});
}  // namespace paper

// f(s, m, hx, …, iyz) with N's ten parameters as the trailing arguments.
template <class F, class S, class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr auto with_parameters(const F& f, const S& s, const body_inertia<T>& N) noexcept {
    return f(s, N.m, N.hx, N.hy, N.hz, N.ixx, N.iyy, N.izz, N.ixy, N.ixz, N.iyz);
}

template <class T>
[[nodiscard]] constexpr body_inertia<T> body_inertia_of(const mass_properties<T>& b) noexcept {
    const T m = b.mass;
    const vec3<T>& c = b.com;
    const vec3<T> h{m * c[0], m * c[1], m * c[2]};
    const T hc = linear3::dot(h, c);
    // I_o = I_c + m(|c|² 1 − c cᵀ), the parallel-axis theorem
    const auto io = [&](int i, int j) { return b.inertia_c[i][j] + (i == j ? hc : T(0)) - h[i] * c[j]; };
    using s = typename body_inertia<T>::scalar;
    return {s{m}, s{h[0]}, s{h[1]}, s{h[2]}, s{io(0, 0)}, s{io(1, 1)}, s{io(2, 2)}, s{io(0, 1)}, s{io(0, 2)}, s{io(1, 2)}};
}

// The same element with its 24 blades stored.
template <class T>
[[nodiscard]] constexpr rigid_inertia<T> to_rigid_inertia(const body_inertia<T>& N) noexcept {
    return formula([](auto... q) { return body_inertia_detail::element(q...); })(N.m, N.hx, N.hy, N.hz, N.ixx, N.iyy,
                                                                                    N.izz, N.ixy, N.ixz, N.iyz);
}

template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr coscrew<T> momentum(const body_inertia<T>& N, const screw<T>& s) noexcept {
    return with_parameters(paper::momentum_of_parameters, s, N);
}
template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr T kinetic_energy(const body_inertia<T>& N, const screw<T>& s) noexcept {
    return scalar_part(with_parameters(paper::twice_kinetic_energy_of_parameters, s, N)) / T(2);
}

// (g ḡ) N (g ḡ)* on the ten parameters (transform_detail::move_inertia, 54m 50a).
template <class T>
[[nodiscard]] constexpr body_inertia<T> transform(const motor_map<T>& G, const body_inertia<T>& N) noexcept {
    using s = typename body_inertia<T>::scalar;
    const transform_detail::moved_inertia<T> n = transform_detail::move_inertia(G, N.mass(), N.first_moment(), N.inertia_o());
    return {N.m, s{n.h[0]}, s{n.h[1]}, s{n.h[2]}, s{n.xx}, s{n.yy}, s{n.zz}, s{n.xy}, s{n.xz}, s{n.yz}};
}

}  // namespace ctga
