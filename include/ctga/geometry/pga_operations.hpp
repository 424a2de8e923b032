// What a user does with Cl(3,0,1)'s elements: move them (sandwich), join and meet them, measure
// and normalise them. Each is a ctga formula, so the engine multiplies out only the terms the
// result's blades need and proves the rest zero: a motor sandwiching a point gives exactly a
// point's four blades, or the program does not compile. Signs and orientations: pga.hpp.
//
//   sandwich(M, x)     M x M̃, in the type of x (point → point, line → line, plane → plane, ...)
//   join(a, b, ...)    a ∨ b ∨ ... (the shuffle product &, elsewhere called regressive): the smallest element containing both
//   meet(a, b, ...)    a ∧ b ∧ ... (the exterior product ^): the largest element both contain
//   norm(x), normalized(x), squared_norm(x)
//
// join and meet return the type of their result's grade: 0 → T (a number), 1 → plane, 2 → line,
// 3 → point, 4 → T (the coefficient of e0e1e2e3). Each is an operation (operations/formula.hpp):
// join.formula(a, b) is the same formula, lazy, to compose further.
#pragma once

#include <type_traits>

#include "ctga/geometry/pga_types.hpp"
#include "ctga/operations/evaluate.hpp"
#include "ctga/operations/formula.hpp"
#include "ctga/operations/operators.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/math.hpp"

namespace ctga::pga {

namespace detail {

// The grade every blade of L has; −1 when L has no blade (the value is zero for every input),
// −2 when the grades differ.
template <auto L>
constexpr int common_grade() {
    if (L.size() == 0) return -1;
    const int g = blade_grade(L.masks[0]);
    for (std::size_t i = 1; i < L.size(); ++i)
        if (blade_grade(L.masks[i]) != g) return -2;
    return g;
}

}  // namespace detail

// Finishing an operation in the element type of its result's grade (see above).
struct into_element_t {
    template <class E>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr auto operator()(const E& e) const noexcept {
        using T = typename E::scalar_type;
        constexpr int g = detail::common_grade<E::layout>();
        static_assert(g != -1, "ctga::pga: this join or meet is zero for every input (the meet of two points, "
                               "the join of two planes, ...): swap join and meet?");
        static_assert(g != -2, "ctga::pga: join and meet take planes, lines, points and directions "
                               "(the result has blades of several grades)");
        if constexpr (g == 0) return scalar_part(e);
        else if constexpr (g == 1) return plane<T>(e);
        else if constexpr (g == 2) return line<T>(e);
        else if constexpr (g == 3) return point<T>(e);
        else if constexpr (g == 4) return e.template get<"e0e1e2e3">();
    }
};
inline constexpr into_element_t into_element{};

// The sandwich M x M̃ of a rotor, translator or motor M (M M̃ = 1) acting on x, returned in x's
// own type. It is the formula ctga::sandwich, with M one argument: the terms that cancel between
// its two appearances are never computed. A result with a blade x's type lacks (M not even, say)
// is a compile error naming the blade.
//   point<> q = sandwich(M, p);            line<> l2 = sandwich(M2 * M1, l);   // M1 first
//   auto lazy = sandwich.formula(M, p);    // the formula, to compose further
template <class F>
struct sandwich_t {
    formula_t<F> formula;

    template <operand M, multivector_type X>
    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr X operator()(const M& m, const X& x) const noexcept {
        return formula(m, x);
    }
};
template <class F>
sandwich_t(formula_t<F>) -> sandwich_t<F>;
inline constexpr sandwich_t sandwich{::ctga::sandwich};

// join(a, b, c) = (a ∨ b) ∨ c: two points make a line, a line and a point (or three points) a
// plane, a point and a plane a number (zero when the point lies on the plane).
inline constexpr operation join{formula([](auto a, auto b, auto... c) { return ((a & b) & ... & c); }), into_element};

// meet(a, b, c) = (a ∧ b) ∧ c: two planes make a line, a plane and a line (or three planes) a
// point, a plane and a point a number (the coefficient of e0e1e2e3, zero when incident).
inline constexpr operation meet{formula([](auto a, auto b, auto... c) { return ((a ^ b) ^ ... ^ c); }), into_element};

// The squared norm: the scalar part of x ⌋ x̃, the sum of the squares of x's coefficients on
// blades without e0. For a plane a² + b² + c², a line |v|², a rotor or motor s² + |B|² of its
// rotor part, a point w²; a direction's is 0 (see norm).
inline constexpr operation squared_norm{formula([](auto x) { return x | ~x; }), scalar_over<1>};

// The norm: √squared_norm(x) (plane: |n|, line: |v|, rotor: 1 when unit); a direction's is its
// length √(x² + y² + z²).
template <class X>
[[nodiscard]] constexpr auto norm(const X& x) noexcept {
    using T = typename X::scalar_type;
    if constexpr (std::is_same_v<X, direction<T>>) return math::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    else return math::sqrt(squared_norm(x));
}

// x scaled to unit norm: a plane to |n| = 1 (then a x + b y + c z + d is the signed distance), a
// line to |v| = 1, a rotor to R R̃ = 1, a direction to length 1. x of norm 0 (the plane at
// infinity e0, a line at infinity, a zero direction) gives non-finite coefficients, never a
// valid-looking element.
template <class X>
    requires(std::is_same_v<X, plane<typename X::scalar_type>> || std::is_same_v<X, line<typename X::scalar_type>> ||
             std::is_same_v<X, rotor<typename X::scalar_type>> || std::is_same_v<X, direction<typename X::scalar_type>>)
[[nodiscard]] constexpr X normalized(const X& x) noexcept {
    using T = typename X::scalar_type;
    return x * (T(1) / norm(x));
}

// A point divided by its weight w: coordinates (x/w, y/w, z/w) and w = 1. A point at infinity
// (w = 0) gives non-finite coordinates; a direction is the type for those.
template <class T>
[[nodiscard]] constexpr point<T> normalized(const point<T>& p) noexcept {
    return point<T>{p[0] / p[3], p[1] / p[3], p[2] / p[3], T(1)};
}

}  // namespace ctga::pga
