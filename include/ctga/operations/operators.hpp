// The operations of the algebra on its elements. Each builds a lazy expression
// (expr/expression.hpp) whose node is a rule of algebra/rules.hpp; the whole expression is
// compiled into one straight-line program when it is assigned, evaluated or read (evaluate.hpp).
//
// Operators follow the common geometric-algebra convention:
//   x * y   geometric product          x ^ y   exterior product ∧
//   x & y   shuffle product ∨ (§4)     x | y   left contraction ⌋
//   ~x      reverse                    -x, x + y, x - y, s * x, x * s, x / s, half * x
// C++ gives ^, & and | lower precedence than + and ==: write the paper's A ∨ (N ∧ s) as
// A & (N ^ s), with the parentheses the paper has anyway.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "ctga/algebra/multivector.hpp"
#include "ctga/algebra/rules.hpp"
#include "ctga/expr/expression.hpp"

namespace ctga {

// ---- bilinear products -------------------------------------------------------------------

// A bilinear product by a rule of algebra/rules.hpp, as a function object: gp(x, y), wedge(x, y), …
template <template <class> class Rule>
struct bilinear_product {
    template <operand X, operand Y>
    [[nodiscard]] constexpr auto operator()(X&& x, Y&& y) const noexcept {
        return expr::combine<expr::bilinear<Rule>>(std::forward<X>(x), std::forward<Y>(y));
    }
};
inline constexpr bilinear_product<rules::geometric> gp{};
inline constexpr bilinear_product<rules::exterior> wedge{};
inline constexpr bilinear_product<rules::shuffle> shuffle{};
inline constexpr bilinear_product<rules::left_contraction> left_contraction{};
inline constexpr bilinear_product<rules::right_contraction> right_contraction{};
inline constexpr bilinear_product<rules::scalar> scalar_product{};

template <operand X, operand Y>
[[nodiscard]] constexpr auto operator*(X&& x, Y&& y) noexcept { return gp(std::forward<X>(x), std::forward<Y>(y)); }
template <operand X, operand Y>
[[nodiscard]] constexpr auto operator^(X&& x, Y&& y) noexcept { return wedge(std::forward<X>(x), std::forward<Y>(y)); }
template <operand X, operand Y>
[[nodiscard]] constexpr auto operator&(X&& x, Y&& y) noexcept { return shuffle(std::forward<X>(x), std::forward<Y>(y)); }
template <operand X, operand Y>
[[nodiscard]] constexpr auto operator|(X&& x, Y&& y) noexcept {
    return left_contraction(std::forward<X>(x), std::forward<Y>(y));
}

template <operand X, operand Y>
[[nodiscard]] constexpr auto operator+(X&& x, Y&& y) noexcept {
    return expr::combine<expr::additive<1>>(std::forward<X>(x), std::forward<Y>(y));
}
template <operand X, operand Y>
[[nodiscard]] constexpr auto operator-(X&& x, Y&& y) noexcept {
    return expr::combine<expr::additive<-1>>(std::forward<X>(x), std::forward<Y>(y));
}

// ---- linear maps -------------------------------------------------------------------------

// A linear blade rule of algebra/rules.hpp, as a function object: reverse(x), conj(x), …
template <template <class> class Rule>
struct linear_map {
    template <operand X>
    [[nodiscard]] constexpr auto operator()(X&& x) const noexcept {
        return expr::apply_map<Rule>(std::forward<X>(x));
    }
};
inline constexpr linear_map<rules::reverse> reverse{};
inline constexpr linear_map<rules::involute> involute{};
inline constexpr linear_map<rules::conjugate> conj{};  // Clifford conjugation, the paper's x*: g g* = 1 (§3)
inline constexpr linear_map<rules::right_complement> right_complement{};
inline constexpr linear_map<rules::left_complement> left_complement{};

template <operand X>
[[nodiscard]] constexpr auto operator~(X&& x) noexcept { return reverse(std::forward<X>(x)); }
template <int K, operand X>
[[nodiscard]] constexpr auto grade(X&& x) noexcept {
    return expr::apply_map<rules::grade_projection_of<K>::template rule>(std::forward<X>(x));
}
template <operand X>
[[nodiscard]] constexpr auto operator-(X&& x) noexcept {
    return expr::apply_scale<expr::rational{-1, 1}>(std::forward<X>(x));
}

// The algebra automorphism sending generator i to generator Images...[i]. It is one only when
// each generator goes to a generator with the same square; anything else is rejected.
template <int... Images, operand X>
[[nodiscard]] constexpr auto automorphism(X&& x) noexcept {
    using alg = typename std::remove_cvref_t<X>::algebra_type;
    static_assert(sizeof...(Images) == alg::dimension, "ctga: an automorphism needs exactly one image per generator");
    if constexpr (sizeof...(Images) == alg::dimension) {
        constexpr std::array<int, alg::dimension> perm{Images...};
        constexpr bool permutation = [&] {
            std::array<bool, alg::dimension> hit{};
            for (int p : perm) {
                if (p < 0 || p >= static_cast<int>(alg::dimension) || hit[static_cast<std::size_t>(p)]) return false;
                hit[static_cast<std::size_t>(p)] = true;
            }
            return true;
        }();
        static_assert(permutation, "ctga: the automorphism's images are not a permutation of the generators");
        constexpr bool squares_kept = [&] {
            if (!permutation) return true;
            for (std::size_t i = 0; i < alg::dimension; ++i)
                if (alg::squares[i] != alg::squares[static_cast<std::size_t>(perm[i])]) return false;
            return true;
        }();
        static_assert(squares_kept, "ctga: the automorphism maps a generator to one with a different square");
        if constexpr (permutation && squares_kept)
            return expr::apply_map<rules::permutation_of<perm>::template rule>(std::forward<X>(x));
    }
}

// The paper's bar involution (§5) on a doubled algebra: generator i ↔ generator i + n/2
// (in Cl(0,6,2): ai ↔ ei, a ↔ e).
template <operand X>
[[nodiscard]] constexpr auto bar(X&& x) noexcept {
    constexpr std::size_t n = std::remove_cvref_t<X>::algebra_type::dimension;
    static_assert(n % 2 == 0, "ctga: bar needs a doubled algebra (an even number of generators)");
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return automorphism<static_cast<int>((I + n / 2) % n)...>(std::forward<X>(x));
    }(std::make_index_sequence<n>{});
}

// The coefficient of one blade (named as written) as a scalar expression.
template <fixed_string Name, operand X>
[[nodiscard]] constexpr auto coeff(X&& x) noexcept {
    using alg = typename std::remove_cvref_t<X>::algebra_type;
    using b = detail::blade_of<alg, Name>;
    return expr::apply_map<rules::coefficient_of<b::mask, b::sign>::template rule>(std::forward<X>(x));
}

// ---- scalars -----------------------------------------------------------------------------

namespace detail {
template <class S, class X>
concept runtime_scalar_for =
    !operand<S> && !is_rational_v<std::remove_cvref_t<S>> &&
    (std::is_void_v<typename std::remove_cvref_t<X>::scalar_type> ||
     std::convertible_to<S, typename std::remove_cvref_t<X>::scalar_type>);

template <class S, class X>
using scalar_of = std::conditional_t<std::is_void_v<typename std::remove_cvref_t<X>::scalar_type>, std::remove_cvref_t<S>,
                                     typename std::remove_cvref_t<X>::scalar_type>;

template <class X, class S>
constexpr auto scalar_operand(const S& s) noexcept {
    using T = scalar_of<S, X>;
    return expr::scalar_expression<typename std::remove_cvref_t<X>::algebra_type, T>(static_cast<T>(s));
}
}  // namespace detail

template <class S, operand X>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator*(const S& s, X&& x) noexcept {
    return detail::scalar_operand<X>(s) * std::forward<X>(x);
}
template <operand X, class S>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator*(X&& x, const S& s) noexcept {
    return std::forward<X>(x) * detail::scalar_operand<X>(s);
}
template <operand X, class S>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator/(X&& x, const S& s) noexcept {
    using T = detail::scalar_of<S, X>;
    return std::forward<X>(x) * detail::scalar_operand<X>(T(1) / static_cast<T>(s));
}
template <operand X, class S>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator+(X&& x, const S& s) noexcept {
    return std::forward<X>(x) + detail::scalar_operand<X>(s);
}
template <class S, operand X>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator+(const S& s, X&& x) noexcept {
    return detail::scalar_operand<X>(s) + std::forward<X>(x);
}
template <operand X, class S>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator-(X&& x, const S& s) noexcept {
    return std::forward<X>(x) - detail::scalar_operand<X>(s);
}
template <class S, operand X>
    requires detail::runtime_scalar_for<S, X>
[[nodiscard]] constexpr auto operator-(const S& s, X&& x) noexcept {
    return detail::scalar_operand<X>(s) - std::forward<X>(x);
}

// Exact rational factors: half * (s1 * s2 − s2 * s1).
template <std::int64_t N, std::int64_t D, operand X>
[[nodiscard]] constexpr auto operator*(q<N, D>, X&& x) noexcept {
    return expr::apply_scale<q<N, D>::value>(std::forward<X>(x));
}
template <operand X, std::int64_t N, std::int64_t D>
[[nodiscard]] constexpr auto operator*(X&& x, q<N, D>) noexcept {
    return expr::apply_scale<q<N, D>::value>(std::forward<X>(x));
}

}  // namespace ctga
