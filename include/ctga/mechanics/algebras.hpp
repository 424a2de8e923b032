// The two algebras of the paper, with the generator order and orientations under which every
// formula of the paper holds exactly, and the embedding of the first in the second.
//
//   Cl(0,3,1) (§3)   screws, rotors, translators, motors
//   Cl(0,6,2) (§5)   the same doubled: co-screws (momenta, wrenches), inertias, mobilities
//
// Cl(0,3,1) sits in Cl(0,6,2) as the subalgebra of e1 e2 e3 e: lift(x) views an element of the
// first in the second (lazily, reading x's own components), lower(y) takes an e-only element back.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/algebra/algebra.hpp"
#include "ctga/operations/operators.hpp"

namespace ctga {

// Cl(0,3,1), §3: screws, rotors, translators, motors.  e1² = e2² = e3² = −1, e² = 0.
using cl031 = algebra<"e1 e2 e3 e", -1, -1, -1, 0>;

// Cl(0,6,2), §5: momenta (co-screws), wrenches, inertias. ai² = ei² = −1, a² = e² = 0, in this
// order: the shuffle product's determinant uses it as the basis order, det(a1,…,e) = +1.
using cl062 = algebra<"a1 a2 a3 a e1 e2 e3 e", -1, -1, -1, 0, -1, -1, -1, 0>;

namespace embedding_detail {

// Generator k of cl031 is generator k + 4 of cl062, in the same order, so orientations carry
// over unchanged.
inline constexpr int e_offset = 4;

template <auto L>
constexpr auto unshifted_layout() {
    layout<L.size()> out = L;
    for (auto& m : out.masks) m >>= e_offset;
    return out;
}
template <auto L>
constexpr bool only_e_blades() {
    for (auto m : L.masks)
        if (m & ((blade_mask{1} << e_offset) - 1)) return false;
    return true;
}

}  // namespace embedding_detail

// x viewed in Cl(0,6,2): an element of Cl(0,3,1) (multivector or expression) embedded as the
// e-half, lazily: the expression reads x's own components, nothing is copied. An element of
// Cl(0,6,2) is returned unchanged, so the paper's formulas accept screws of either algebra.
template <operand X>
[[nodiscard]] constexpr decltype(auto) lift(X&& x) noexcept {
    using alg = typename std::remove_cvref_t<X>::algebra_type;
    static_assert(std::is_same_v<alg, cl031> || std::is_same_v<alg, cl062>,
                  "ctga: lift takes an element of Cl(0,3,1) (or of Cl(0,6,2), returned unchanged)");
    if constexpr (std::is_same_v<alg, cl062>) return std::forward<X>(x);
    else return expr::apply_map<rules::embedding_of<embedding_detail::e_offset>::template rule, cl062>(std::forward<X>(x));
}

// The inverse on e-only elements of Cl(0,6,2): the same coefficients in Cl(0,3,1).
template <class T, auto L>
[[nodiscard]] constexpr auto lower(const multivector<cl062, T, L>& x) noexcept {
    static_assert(embedding_detail::only_e_blades<L>(),
                  "ctga: lower() takes an element of the e-half of Cl(0,6,2) (no a-generators)");
    multivector<cl031, T, embedding_detail::unshifted_layout<L>()> out;
    for (std::size_t i = 0; i < L.size(); ++i) out[i] = x[i];
    return out;
}

}  // namespace ctga
