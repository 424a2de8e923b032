// The operations of the algebra on multivectors, each a rule of products.hpp run through a plan.
//
// Operators follow the common geometric-algebra convention:
//   x * y   geometric product          x ^ y   exterior product ∧
//   x & y   shuffle/regressive ∨ (§4)  x | y   left contraction ⌋
//   ~x      reverse                    -x, x + y, x - y, s * x, x * s, x / s
// C++ gives ^, & and | lower precedence than + and ==: write the paper's A ∨ (N ∧ s) as
// A & (N ^ s), with the parentheses the paper has anyway.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/algebra/evaluate.hpp"
#include "ctga/algebra/multivector.hpp"
#include "ctga/algebra/plan.hpp"
#include "ctga/algebra/products.hpp"

namespace ctga {

namespace detail {

template <class X, class Y>
constexpr void check_same_algebra_and_scalar() {
    static_assert(std::is_same_v<typename X::algebra_type, typename Y::algebra_type>,
                  "ctga: the operands belong to different algebras");
    static_assert(std::is_same_v<typename X::scalar_type, typename Y::scalar_type>,
                  "ctga: the operands have different scalar types; convert one explicitly");
}

template <template <class> class Rule, class X, class Y>
constexpr auto bilinear(const X& x, const Y& y) noexcept {
    check_same_algebra_and_scalar<X, Y>();
    using alg = typename X::algebra_type;
    using plan = bilinear_plan<alg, Rule<alg>, X::layout, Y::layout>;
    using result = multivector<alg, typename X::scalar_type, plan::result>;
    return evaluate<result, plan, true>(x, y);
}

template <class Rule, class X>
constexpr auto unary(const X& x) noexcept {
    using plan = unary_plan<typename X::algebra_type, Rule, X::layout>;
    using result = multivector<typename X::algebra_type, typename X::scalar_type, plan::result>;
    return evaluate<result, plan, false>(x, x);
}

template <signed char SignY, class X, class Y>
constexpr auto sum(const X& x, const Y& y) noexcept {
    check_same_algebra_and_scalar<X, Y>();
    using alg = typename X::algebra_type;
    constexpr auto target = layout_union<X::layout, Y::layout>;
    using plan = linear_plan<alg, target, std::array<signed char, 2>{1, SignY}, X::layout, Y::layout>;
    using result = multivector<alg, typename X::scalar_type, target>;
    return evaluate<result, plan, false>(x, y);
}

template <class X, class F>
constexpr X map_components(const X& x, F f) noexcept {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return X(from_components_t{}, std::array<typename X::scalar_type, X::size()>{f(x[I])...});
    }(std::make_index_sequence<X::size()>{});
}

// A scalar as a multivector of the same algebra.
template <class X>
using scalar_mv = multivector<typename X::algebra_type, typename X::scalar_type, layout<1>{{0}, {1}}>;

template <class S, class X>
concept scalar_for = !multivector_type<S> && std::convertible_to<S, typename std::remove_cvref_t<X>::scalar_type>;

}  // namespace detail

// ---- bilinear products -------------------------------------------------------------------

template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto gp(const X& x, const Y& y) noexcept { return detail::bilinear<rules::geometric>(x, y); }
template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto wedge(const X& x, const Y& y) noexcept { return detail::bilinear<rules::exterior>(x, y); }
template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto vee(const X& x, const Y& y) noexcept { return detail::bilinear<rules::regressive>(x, y); }
template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto left_contraction(const X& x, const Y& y) noexcept {
    return detail::bilinear<rules::left_contraction>(x, y);
}
template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto right_contraction(const X& x, const Y& y) noexcept {
    return detail::bilinear<rules::right_contraction>(x, y);
}
template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto scalar_product(const X& x, const Y& y) noexcept {
    return detail::bilinear<rules::scalar>(x, y);
}

template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto operator*(const X& x, const Y& y) noexcept { return gp(x, y); }
template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto operator^(const X& x, const Y& y) noexcept { return wedge(x, y); }
template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto operator&(const X& x, const Y& y) noexcept { return vee(x, y); }
template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto operator|(const X& x, const Y& y) noexcept { return left_contraction(x, y); }

// ---- linear maps -------------------------------------------------------------------------

template <multivector_type X>
[[nodiscard]] constexpr auto reverse(const X& x) noexcept {
    return detail::unary<rules::reverse<typename X::algebra_type>>(x);
}
template <multivector_type X>
[[nodiscard]] constexpr auto operator~(const X& x) noexcept { return reverse(x); }
template <multivector_type X>
[[nodiscard]] constexpr auto involute(const X& x) noexcept {
    return detail::unary<rules::involute<typename X::algebra_type>>(x);
}
// Clifford conjugation, the paper's x*: g g* = 1 for a rigid motion g (§3).
template <multivector_type X>
[[nodiscard]] constexpr auto conj(const X& x) noexcept {
    return detail::unary<rules::conjugate<typename X::algebra_type>>(x);
}
template <int K, multivector_type X>
[[nodiscard]] constexpr auto grade(const X& x) noexcept {
    return detail::unary<rules::grade_projection<typename X::algebra_type, K>>(x);
}
template <multivector_type X>
[[nodiscard]] constexpr auto right_complement(const X& x) noexcept {
    return detail::unary<rules::right_complement<typename X::algebra_type>>(x);
}
template <multivector_type X>
[[nodiscard]] constexpr auto left_complement(const X& x) noexcept {
    return detail::unary<rules::left_complement<typename X::algebra_type>>(x);
}

// The algebra automorphism sending generator i to generator Images...[i]. It is one only when
// each generator goes to a generator with the same square; anything else is rejected.
template <int... Images, multivector_type X>
[[nodiscard]] constexpr auto automorphism(const X& x) noexcept {
    using alg = typename X::algebra_type;
    static_assert(sizeof...(Images) == alg::dimension,
                  "ctga: an automorphism needs exactly one image per generator");
    if constexpr (sizeof...(Images) == alg::dimension) {
        constexpr std::array<int, alg::dimension> perm{Images...};
        constexpr bool permutation = [&] {
            std::array<bool, alg::dimension> hit{};
            for (int p : perm) {
                if (p < 0 || p >= static_cast<int>(alg::dimension) || hit[p]) return false;
                hit[p] = true;
            }
            return true;
        }();
        static_assert(permutation, "ctga: the automorphism's images are not a permutation of the generators");
        constexpr bool squares_kept = [&] {
            if (!permutation) return true;
            for (std::size_t i = 0; i < alg::dimension; ++i)
                if (alg::squares[i] != alg::squares[perm[i]]) return false;
            return true;
        }();
        static_assert(squares_kept,
                      "ctga: the automorphism maps a generator to one with a different square");
        if constexpr (permutation && squares_kept) return detail::unary<rules::permutation<alg, perm>>(x);
    }
}

// The paper's bar involution (§5) on a doubled algebra: generator i ↔ generator i + n/2
// (in Cl(0,6,2): ai ↔ ei, a ↔ e).
template <multivector_type X>
[[nodiscard]] constexpr auto bar(const X& x) noexcept {
    using alg = typename X::algebra_type;
    constexpr std::size_t n = alg::dimension;
    static_assert(n % 2 == 0, "ctga: bar needs a doubled algebra (an even number of generators)");
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return automorphism<static_cast<int>((I + n / 2) % n)...>(x);
    }(std::make_index_sequence<n>{});
}

// Keep only the blades of Target (a multivector type), dropping the rest on purpose.
template <multivector_type Target, multivector_type X>
[[nodiscard]] constexpr Target project(const X& x) noexcept {
    detail::check_same_algebra_and_scalar<Target, X>();
    using plan = detail::linear_plan<typename X::algebra_type, Target::layout, std::array<signed char, 2>{1, 1}, X::layout>;
    return detail::evaluate<Target, plan, false>(x, x);
}

// ---- sums and scalars --------------------------------------------------------------------

template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto operator+(const X& x, const Y& y) noexcept { return detail::sum<1>(x, y); }
template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr auto operator-(const X& x, const Y& y) noexcept { return detail::sum<-1>(x, y); }
template <multivector_type X>
[[nodiscard]] constexpr X operator-(const X& x) noexcept {
    return detail::map_components(x, [](const auto& c) { return -c; });
}

template <multivector_type X, detail::scalar_for<X> S>
[[nodiscard]] constexpr X operator*(const S& s, const X& x) noexcept {
    const typename X::scalar_type k(s);
    return detail::map_components(x, [&](const auto& c) { return k * c; });
}
template <multivector_type X, detail::scalar_for<X> S>
[[nodiscard]] constexpr X operator*(const X& x, const S& s) noexcept {
    const typename X::scalar_type k(s);
    return detail::map_components(x, [&](const auto& c) { return c * k; });
}
template <multivector_type X, detail::scalar_for<X> S>
[[nodiscard]] constexpr X operator/(const X& x, const S& s) noexcept {
    const typename X::scalar_type k(s);
    return detail::map_components(x, [&](const auto& c) { return c / k; });
}
template <multivector_type X, detail::scalar_for<X> S>
[[nodiscard]] constexpr auto operator+(const X& x, const S& s) noexcept { return x + detail::scalar_mv<X>(s); }
template <multivector_type X, detail::scalar_for<X> S>
[[nodiscard]] constexpr auto operator+(const S& s, const X& x) noexcept { return detail::scalar_mv<X>(s) + x; }
template <multivector_type X, detail::scalar_for<X> S>
[[nodiscard]] constexpr auto operator-(const X& x, const S& s) noexcept { return x - detail::scalar_mv<X>(s); }
template <multivector_type X, detail::scalar_for<X> S>
[[nodiscard]] constexpr auto operator-(const S& s, const X& x) noexcept { return detail::scalar_mv<X>(s) - x; }

// Equal when every blade has the same coefficient (absent blades count as zero).
template <multivector_type X, multivector_type Y>
[[nodiscard]] constexpr bool operator==(const X& x, const Y& y) noexcept {
    detail::check_same_algebra_and_scalar<X, Y>();
    using T = typename X::scalar_type;
    auto coefficient = [](const auto& m, blade_mask b) -> T {
        const int i = m.layout.index_of(b);
        if (i < 0) return T{};
        return m.layout.signs[i] > 0 ? m[i] : T(-m[i]);
    };
    constexpr auto all = layout_union<X::layout, Y::layout>;
    for (blade_mask b : all.masks)
        if (!(coefficient(x, b) == coefficient(y, b))) return false;
    return true;
}

// The scalar (grade-0) coefficient.
template <multivector_type X>
[[nodiscard]] constexpr auto scalar_part(const X& x) noexcept { return x.template get<"1">(); }

}  // namespace ctga
