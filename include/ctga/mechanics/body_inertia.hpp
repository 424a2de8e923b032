// A rigid body's inertia N and mobility M = N⁻¹ by ten parameters each (paper §2, §5), the
// cheapest N and M in formulas: as an argument of a formula (formula.hpp) each parameter is one
// leaf, and the element it makes is N's (or M's) as inertia.hpp stores it.
//
//   body_inertia     N by (m, h = m c, I_o): momentum and energy read ten numbers
//   body_mobility    M by (1/m, c, J = I_c⁻¹): M = (t t̄) M_c (t t̄)*, the mobility about the
//                    centre of mass moved there; the cheapest velocity
#pragma once

#include <tuple>
#include <type_traits>

#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/operations/formula.hpp"

namespace ctga {

// The formulas of body_inertia and body_mobility below, over their ten parameters (leaves of a
// formula, formula.hpp). At namespace scope: as members their parameters would shadow the fields
// of the same names.
namespace body_formulas {
// N = Σ I_o(i,j) (α_i ε̃_j + α_j ε̃_i)/(1 + δ_ij) + m (a2a3e2e3 + a3a1e3e1 + a1a2e1e2) + Ĥ blocks,
// entry (i, j) being the blade α_i ε̃_j (detail/matrix_blades.hpp).
inline constexpr auto inertia = [](auto m, auto hx, auto hy, auto hz, auto ixx, auto iyy, auto izz, auto ixy,
                                   auto ixz, auto iyz) {
    using G = cl062;
    return ixx * G::basis<"a1ae1e"> + iyy * G::basis<"a2ae2e"> + izz * G::basis<"a3ae3e"> +
           ixy * (G::basis<"a1ae2e"> + G::basis<"a2ae1e">) + ixz * (G::basis<"a1ae3e"> + G::basis<"a3ae1e">) +
           iyz * (G::basis<"a2ae3e"> + G::basis<"a3ae2e">) +
           m * (G::basis<"a2a3e2e3"> + G::basis<"a3a1e3e1"> + G::basis<"a1a2e1e2">) +
           // Ĥ in the upper right, −Ĥ = Ĥᵀ in the lower left
           hx * (G::basis<"a3ae3e1"> - G::basis<"a2ae1e2"> + G::basis<"a3a1e3e"> - G::basis<"a1a2e2e">) +
           hy * (G::basis<"a1ae1e2"> - G::basis<"a3ae2e3"> - G::basis<"a2a3e3e"> + G::basis<"a1a2e1e">) +
           hz * (G::basis<"a2ae2e3"> - G::basis<"a1ae3e1"> + G::basis<"a2a3e2e"> - G::basis<"a3a1e1e">);
};

// M_c, the mobility about the centre of mass (entry (i, j) is the blade α̃_j ε_i).
inline constexpr auto mobility_about_centre = [](auto inv_m, auto jxx, auto jyy, auto jzz, auto jxy, auto jxz, auto jyz) {
    using G = cl062;
    return jxx * G::basis<"a2a3e2e3"> + jyy * G::basis<"a3a1e3e1"> + jzz * G::basis<"a1a2e1e2"> +
           jxy * (G::basis<"a3a1e2e3"> + G::basis<"a2a3e3e1">) + jxz * (G::basis<"a1a2e2e3"> + G::basis<"a2a3e1e2">) +
           jyz * (G::basis<"a1a2e3e1"> + G::basis<"a3a1e1e2">) +
           inv_m * (G::basis<"a1ae1e"> + G::basis<"a2ae2e"> + G::basis<"a3ae3e">);
};
// t = 1 + ½(cx e1e + cy e2e + cz e3e), the translation to the centre of mass (§3), in Cl(0,6,2).
inline constexpr auto to_centre = [](auto cx, auto cy, auto cz) {
    using G = cl062;
    return G::basis<"1"> + half * (cx * G::basis<"e1e"> + cy * G::basis<"e2e"> + cz * G::basis<"e3e">);
};
// As an argument of a formula: M = (t t̄) M_c (t t̄)*, the element mobility_of stores.
inline constexpr auto mobility = [](auto inv_m, auto cx, auto cy, auto cz, auto jxx, auto jyy, auto jzz, auto jxy,
                                   auto jxz, auto jyz) {
    // (t t̄) M_c (t t̄)* = t (t̄ M_c t̄*) t*: one sandwich at a time, each fully expanded
    const auto t = to_centre(cx, cy, cz);
    return t * (bar(t) * mobility_about_centre(inv_m, jxx, jyy, jzz, jxy, jxz, jyz) * conj(bar(t))) * conj(t);
};
// The velocity of a co-screw P, t (E ∨ (M_c ∧ (t̄* P t̄))) t* (24m 18a): as a formula's body
// (velocity_of, for larger formulas) and as the formula velocity_from(M, P) runs.
inline constexpr auto velocity_of = [](auto P, auto inv_m, auto cx, auto cy, auto cz, auto jxx, auto jyy, auto jzz,
                                       auto jxy, auto jxz, auto jyz) {
    const auto t = to_centre(cx, cy, cz);
    const auto P_c = conj(bar(t)) * P * bar(t);  // P about the centre of mass: (l − c × p, p)
    const auto s_c = invariants::E & (mobility_about_centre(inv_m, jxx, jyy, jzz, jxy, jxz, jyz) ^ P_c);  // (J l', p/m)
    return t * s_c * conj(t);  // (ω, v' + c × ω)
};
}  // namespace body_formulas

// A rigid body's N by its ten parameters: the mass m, the first moment h = m c and the inertia
// tensor about the body origin I_o (six numbers, symmetric). N = [[I_o, Ĥ], [−Ĥ, m 1]] has 24
// non-zero blades but only ten distinct coefficients: I_o(i, j) and I_o(j, i) are one number, m
// sits on three blades and each h_k on four. Inside a formula each parameter is one leaf, so
// A ∨ (N ∧ s) reads ten numbers instead of 24 and shares their products exactly where the
// hand-written spatial code does (24m 18a either way).
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

    // Two bodies' inertias in one frame add (§5: N is linear in the mass distribution), so a
    // composite of rigid bodies has a rigid body's N: its ten parameters are the sums (10a).
    [[nodiscard]] friend constexpr body_inertia operator+(const body_inertia& a, const body_inertia& b) noexcept {
        return {a.m + b.m, a.hx + b.hx, a.hy + b.hy, a.hz + b.hz, a.ixx + b.ixx,
                a.iyy + b.iyy, a.izz + b.izz, a.ixy + b.ixy, a.ixz + b.ixz, a.iyz + b.iyz};
    }

    // As an argument of a formula (formula.hpp): ten leaves, and N as the expression they make
    // (body_formulas::inertia).
    [[nodiscard]] constexpr auto parameters() const noexcept { return std::tie(m, hx, hy, hz, ixx, iyy, izz, ixy, ixz, iyz); }
    static constexpr auto element = body_formulas::inertia;
};

template <class T>
[[nodiscard]] constexpr body_inertia<T> body_inertia_of(const mass_properties<T>& b) noexcept {
    const T m = b.mass;
    const vec3<T>& c = b.com;
    const vec3<T> h{m * c[0], m * c[1], m * c[2]};
    const mat3<T> io = inertia_about_origin(b, h);
    using s = typename body_inertia<T>::scalar;
    return {s{m}, s{h[0]}, s{h[1]}, s{h[2]}, s{io[0][0]}, s{io[1][1]}, s{io[2][2]}, s{io[0][1]}, s{io[0][2]}, s{io[1][2]}};
}

// The same element with its 24 blades stored.
template <class T>
[[nodiscard]] constexpr rigid_inertia<T> to_rigid_inertia(const body_inertia<T>& N) noexcept {
    return formula([](auto element) { return element; })(N);
}

// A rigid body's mobility M = N⁻¹ by its ten parameters: 1/m, the centre of mass c and
// J = I_c⁻¹ (six numbers, symmetric). About its centre of mass a rigid body's inertia is block
// diagonal, N_c = [[I_c, 0], [0, m 1]], and so is its mobility, M_c = [[J, 0], [0, (1/m) 1]]:
//   M_c = Σ J(i,j) α̃_j ε_i + (1/m)(a1ae1e + a2ae2e + a3ae3e)          (i, j < 3)
// (for principal axes §5's diagonal N with the blocks swapped: 1/d_i on a2a3e2e3, …, 1/m on
// a1ae1e, …). A mobility moves as an inertia does, M → (g ḡ) M (g ḡ)* (§5: the sandwich by g ḡ
// distributes over ∧ and ∨ and fixes E, so s = E ∨ (M ∧ P) moves to g s g* = E ∨ (M' ∧ ḡ P ḡ*);
// as a matrix M' = H M Hᵀ). The body's M is therefore M_c moved by the translation to the centre
// of mass, t = 1 + ½(cx e1e + cy e2e + cz e3e) (§3):
//   M = (t t̄) M_c (t t̄)*                                               (element, below)
// and, since (t t̄)* (t t̄) = 1 and t commutes with co-screws, t̄ with screws (even elements on
// disjoint generators), the velocity it gives is
//   E ∨ (M ∧ P) = t (E ∨ (M_c ∧ (t̄* P t̄))) t*                          (velocity, below)
// i.e. l' = l − c × p, then ω = J l', v' = p/m, then v = v' + c × ω: Featherstone's §2.13 solve
// with the inverse rotational inertia, 24m 18a against 36m 30a for the 36 blades of mobility_of.
template <class T = double>
struct body_mobility {
    using scalar = cl062::mv<T, "1">;
    scalar inv_m, cx, cy, cz;             // 1/m and the centre of mass c
    scalar jxx, jyy, jzz, jxy, jxz, jyz;  // J = I_c⁻¹

    [[nodiscard]] constexpr auto parameters() const noexcept {
        return std::tie(inv_m, cx, cy, cz, jxx, jyy, jzz, jxy, jxz, jyz);
    }
    static constexpr auto about_centre = body_formulas::mobility_about_centre;
    static constexpr auto to_centre = body_formulas::to_centre;
    static constexpr auto element = body_formulas::mobility;
    static constexpr auto velocity_of = body_formulas::velocity_of;
    static constexpr auto velocity = formula(velocity_of);
};

template <class T>
[[nodiscard]] constexpr body_mobility<T> body_mobility_of(const mass_properties<T>& b) noexcept {
    const mat3<T> J = linear3::inverse_symmetric(b.inertia_c);
    using s = typename body_mobility<T>::scalar;
    return {s{T(1) / b.mass}, s{b.com[0]}, s{b.com[1]}, s{b.com[2]},
            s{J[0][0]},       s{J[1][1]},  s{J[2][2]},  s{J[0][1]}, s{J[0][2]}, s{J[1][2]}};
}

// The same element with its 36 blades stored.
template <class T>
[[nodiscard]] constexpr mobility<T> to_mobility(const body_mobility<T>& M) noexcept {
    return formula([](auto element) { return element; })(M);
}

// A body's inertia or mobility (its ten parameters) in scalar type U, every parameter U(x): a
// pack broadcasts it to every lane, keeping each number's bits (chains::model_cast,
// inertia_kind::body_cast).
template <class U, template <class> class X, class T>
    requires(std::is_same_v<X<T>, body_inertia<T>> || std::is_same_v<X<T>, body_mobility<T>>)
[[nodiscard]] constexpr X<U> parameters_cast(const X<T>& x) noexcept {
    return std::apply([](const auto&... p) { return X<U>{typename X<U>::scalar{U(p[0])}...}; }, x.parameters());
}

}  // namespace ctga
