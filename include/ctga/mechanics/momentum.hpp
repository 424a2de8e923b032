// The operations of an inertia (paper §5–6): the momentum P = A ∨ (N ∧ s), the kinetic energy,
// dN/dt of a moving body and the velocity a mobility gives a co-screw, s = E ∨ (M ∧ P).
//
// N is any inertia element (inertia.hpp; body_inertia passes its ten parameters, body_inertia.hpp;
// articulated_inertia its 21), s a screw of Cl(0,3,1) or lifted, P a co-screw, M a mobility.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/articulated_inertia.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/operations/formula.hpp"
#include "ctga/support/inline.hpp"

namespace ctga {

namespace inertia_detail {
inline constexpr auto momentum_formula = [](auto N, auto s) { return invariants::A & (N ^ lift(s)); };
using momentum_operation = operation<std::remove_const_t<decltype(momentum_formula)>, into_t<coscrew>>;

// Row r of N s over the screw components a screw type L holds: Σ_c ±N(r, c) s_c (the sign where L
// orients blade c against screw<T>).
template <std::size_t R, auto L, class T, std::size_t... I>
CTGA_ALWAYS_INLINE constexpr T row_times(const articulated_inertia<T>& N, const multivector<cl031, T, L>& s,
                                         std::index_sequence<I...>) noexcept {
    constexpr auto S = screw<T>::layout;
    return ((L.signs[I] * S.signs[S.index_of(L.masks[I])] > 0 ? N(R, S.index_of(L.masks[I])) * s[I]
                                                              : -(N(R, S.index_of(L.masks[I])) * s[I])) +
            ...);
}
}  // namespace inertia_detail

// §5: the momentum P = A ∨ (N ∧ s); 24m 18a for a rigid body's N.
// An articulated inertia (articulated_inertia.hpp, N = [[A, B], [Bᵀ, C]] by its 21 entries) takes
// the product entry by entry, P_r = Σ_c N(r, c) s_c over the screw components s's type holds: one
// column of N for an axis joint's S, 24m 18a for the bracket v × S q̇ (four blades). These are
// the numbers of the formula (tests/articulated_inertia_test.cpp), without its symbolic normal form
// over 21 leaves, which cost ABA's translation unit 0.7 s per use at -O2. The lazy
// momentum.formula is A ∨ (N ∧ s) for every N.
struct momentum_t : inertia_detail::momentum_operation {
    using inertia_detail::momentum_operation::operator();
    template <class T, auto L>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr coscrew<T> operator()(const articulated_inertia<T>& N,
                                                                     const multivector<cl031, T, L>& s) const noexcept {
        static_assert([] {
            for (std::size_t i = 0; i < L.size(); ++i)
                if (!screw<T>::layout.contains(L.masks[i])) return false;
            return L.size() > 0;
        }(), "ctga::momentum of an articulated inertia: s must be a screw (blades of e2e3 e3e1 e1e2 e1e e2e e3e)");
        return [&]<std::size_t... R>(std::index_sequence<R...>) {
            return coscrew<T>{inertia_detail::row_times<R, L>(N, s, std::make_index_sequence<L.size()>{})...};
        }(std::make_index_sequence<6>{});
    }
};
inline constexpr momentum_t momentum{{formula(inertia_detail::momentum_formula), into<coscrew>}};

// §5: the kinetic energy E_k = ½ s̄ ∨ (N ∧ s) (the formula is twice it).
inline constexpr operation kinetic_energy{formula([](auto N, auto s) { return bar(lift(s)) & (N ^ lift(s)); }),
                                          scalar_over<2>};

namespace inertia_detail {
inline constexpr auto inertia_rate_formula = [](auto N, auto s) {
    const auto x = lift(s);
    return half * (x * N - N * x) + half * (bar(x) * N - N * bar(x));
};
using inertia_rate_operation = operation<std::remove_const_t<decltype(inertia_rate_formula)>, into_t<inertia>>;
}  // namespace inertia_detail

// §6: dN/dt = ½(sN − Ns) + ½(s̄N − Ns̄) for a body moving with velocity s (= s ×* N − N s×,
// Featherstone (2008) §2.14).
// A body_inertia's rate is again ten parameters of the same form (a rate of zero mass): each
// point c of the body moves at ċ = ω × c + u for s = (ω, u), so ḣ = ω × h + m u and, from
// I_o = Σ m(|c|² 1 − c cᵀ),
//   İ_o = [ω]× I_o − I_o [ω]× + 2(h·u) 1 − (u hᵀ + h uᵀ),   [ω]× I_o − I_o [ω]× = A + Aᵀ for A = [ω]× I_o
// (I_o symmetric, [ω]× skew), 33m 33a; the formula's element is inertia_rate.formula
// (tests/articulated_inertia_test.cpp checks the two agree).
struct inertia_rate_t : inertia_detail::inertia_rate_operation {
    using inertia_detail::inertia_rate_operation::operator();
    template <class T>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr body_inertia<T> operator()(const body_inertia<T>& N, const screw<T>& s) const noexcept {
        using sc = typename body_inertia<T>::scalar;
        const vec3<T> w{s[0], s[1], s[2]}, u{s[3], s[4], s[5]};
        const T m = N.mass();
        const vec3<T> h = N.first_moment();
        const mat3<T> I = N.inertia_o();
        const vec3<T> hdot = linear3::add(linear3::cross(w, h), vec3<T>{m * u[0], m * u[1], m * u[2]});
        mat3<T> A;  // A(i, j) = (ω × I_j)_i, I_j the columns of I
        for (std::size_t i = 0; i < 3; ++i) {
            const std::size_t a = (i + 1) % 3, b = (i + 2) % 3;
            for (std::size_t j = 0; j < 3; ++j) A[i][j] = w[a] * I[b][j] - w[b] * I[a][j];
        }
        const T hu2 = T(2) * linear3::dot(h, u);
        mat3<T> R;
        for (std::size_t i = 0; i < 3; ++i) {
            R[i][i] = T(2) * (A[i][i] - u[i] * h[i]) + hu2;
            for (std::size_t j = i + 1; j < 3; ++j) R[i][j] = A[i][j] + A[j][i] - (u[i] * h[j] + h[i] * u[j]);
        }
        return {sc{T(0)},     sc{hdot[0]},  sc{hdot[1]},  sc{hdot[2]},  sc{R[0][0]},
                sc{R[1][1]},  sc{R[2][2]},  sc{R[0][1]},  sc{R[0][2]},  sc{R[1][2]}};
    }
};
inline constexpr inertia_rate_t inertia_rate{{formula(inertia_detail::inertia_rate_formula), into<inertia>}};

// The velocity a mobility gives a co-screw: s = E ∨ (M ∧ P), a screw of Cl(0,3,1).
struct lowered_screw_t {
    template <class E>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr screw<typename E::scalar_type> operator()(const E& e) const noexcept {
        return lower(lifted_screw<typename E::scalar_type>(e));
    }
};
namespace inertia_detail {
inline constexpr auto velocity_formula = [](auto M, auto P) { return invariants::E & (M ^ P); };
using velocity_operation = operation<std::remove_const_t<decltype(velocity_formula)>, lowered_screw_t>;
}  // namespace inertia_detail
// velocity_from(M, P): the velocity s = E ∨ (M ∧ P) of a momentum P (§5), for any mobility
// element; a body_mobility and a co-screw take the form about the centre of mass,
// t (E ∨ (M_c ∧ (t̄* P t̄))) t* (body_mobility), the same s at 24m 18a. The lazy
// velocity_from.formula is E ∨ (M ∧ P) for every M.
struct velocity_from_t : inertia_detail::velocity_operation {
    using inertia_detail::velocity_operation::operator();
    // A rigid body's mobility by its ten parameters: t (E ∨ (M_c ∧ (t̄* P t̄))) t* (body_mobility)
    // in coordinates, P = (l, p): l' = l − c × p (P about the centre of mass), ω = J l', v' = p/m
    // (M_c), v = v' + c × ω (back by t). The same 24m 18a as body_mobility::velocity, whose
    // symbolic normal form (eleven arguments, three sandwiches) costs a translation unit about
    // 1.3 s and 150 MB to compile: the formula stays for larger formulas (the scenes' body
    // kinds), this call is the one the equations of motion make. tests/body_mobility_test.cpp
    // checks both against the 36 blades and against Gaussian elimination on §2's 6×6 N.
    template <class T>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr screw<T> operator()(const body_mobility<T>& M, const coscrew<T>& P) const noexcept {
        const vec3<T> c{M.cx[0], M.cy[0], M.cz[0]}, p{P[3], P[4], P[5]};
        const vec3<T> cp = linear3::cross(c, p);
        const vec3<T> l{P[0] - cp[0], P[1] - cp[1], P[2] - cp[2]};
        const vec3<T> w{M.jxx[0] * l[0] + M.jxy[0] * l[1] + M.jxz[0] * l[2], M.jxy[0] * l[0] + M.jyy[0] * l[1] + M.jyz[0] * l[2],
                        M.jxz[0] * l[0] + M.jyz[0] * l[1] + M.jzz[0] * l[2]};
        const vec3<T> cw = linear3::cross(c, w);
        const T inv_m = M.inv_m[0];
        return screw<T>{w[0], w[1], w[2], inv_m * p[0] + cw[0], inv_m * p[1] + cw[1], inv_m * p[2] + cw[2]};
    }
};
inline constexpr velocity_from_t velocity_from{{formula(inertia_detail::velocity_formula), lowered_screw_t{}}};

}  // namespace ctga
