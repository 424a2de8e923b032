// Forward-mode automatic differentiation: dual<N, T> carries a value v and its N partial derivatives d[k] with respect
// to N seeded inputs x_0 … x_{N−1}. Every arithmetic operation and elementary function below applies the chain rule to
// the partials, so evaluating a function on duals yields its value and its gradient (one row of a Jacobian) exactly up
// to floating-point rounding, with no step size as in finite differences.
//
// The tests use this type as an independent reference for the library's compile-time (symbolic) Jacobians: the same
// expression evaluated on dual numbers gives derivatives computed by a different method. This header therefore depends
// on nothing from ctga, only on the standard library.
//
// Usage:
//     using D = ctga_test::dual<2>;
//     D x = D::variable(1.5, 0), y = D::variable(-0.5, 1);
//     D f = x * x * y + 2 * sin(y);
//     // value(f) == f(1.5, −0.5), derivative(f, 0) == ∂f/∂x, derivative(f, 1) == ∂f/∂y
//
// Elementary functions (sqrt, abs, fabs, sin, cos, exp, log, atan2, pow, hypot, isfinite, isnan) live in namespace
// ctga_test and are found by argument-dependent lookup: call them unqualified after `using std::sqrt;` etc., so that
// the same code works for double and for dual. Comparisons compare values only; partials do not take part.
#pragma once

#include <array>
#include <cmath>
#include <compare>
#include <cstddef>
#include <limits>
#include <type_traits>

namespace ctga_test {

template <class A>
concept arithmetic = std::is_arithmetic_v<A>;

template <std::size_t N, class T = double>
struct dual {
    T v{};                 // value
    std::array<T, N> d{};  // partial derivatives ∂v/∂x_k, k = 0 … N−1

    constexpr dual() noexcept = default;
    constexpr dual(T x) noexcept : v(x) {}  // a constant: zero partials
    template <arithmetic A>
    constexpr dual(A x) noexcept : v(static_cast<T>(x)) {}  // a constant: zero partials

    // The input x_k with value `value`: ∂/∂x_k = 1, all other partials 0. Requires k < N.
    static constexpr dual variable(T value, std::size_t k) noexcept {
        dual r(value);
        r.d[k] = T(1);
        return r;
    }

    // Unary operators.
    friend constexpr dual operator+(const dual& a) noexcept { return a; }
    friend constexpr dual operator-(const dual& a) noexcept {
        dual r;
        r.v = -a.v;
        for (std::size_t k = 0; k < N; ++k) r.d[k] = -a.d[k];
        return r;
    }

    // dual ∘ dual.  (a ± b)' = a' ± b',  (a b)' = a' b + a b',  (a / b)' = (a' − (a / b) b') / b.
    friend constexpr dual operator+(const dual& a, const dual& b) noexcept {
        dual r;
        r.v = a.v + b.v;
        for (std::size_t k = 0; k < N; ++k) r.d[k] = a.d[k] + b.d[k];
        return r;
    }
    friend constexpr dual operator-(const dual& a, const dual& b) noexcept {
        dual r;
        r.v = a.v - b.v;
        for (std::size_t k = 0; k < N; ++k) r.d[k] = a.d[k] - b.d[k];
        return r;
    }
    friend constexpr dual operator*(const dual& a, const dual& b) noexcept {
        dual r;
        r.v = a.v * b.v;
        for (std::size_t k = 0; k < N; ++k) r.d[k] = a.d[k] * b.v + a.v * b.d[k];
        return r;
    }
    friend constexpr dual operator/(const dual& a, const dual& b) noexcept {
        dual r;
        r.v = a.v / b.v;
        for (std::size_t k = 0; k < N; ++k) r.d[k] = (a.d[k] - r.v * b.d[k]) / b.v;
        return r;
    }

    // dual ∘ arithmetic and arithmetic ∘ dual: the constant has zero partials.
    template <arithmetic A>
    friend constexpr dual operator+(const dual& a, A c) noexcept {
        dual r = a;
        r.v = a.v + static_cast<T>(c);
        return r;
    }
    template <arithmetic A>
    friend constexpr dual operator+(A c, const dual& a) noexcept {
        dual r = a;
        r.v = static_cast<T>(c) + a.v;
        return r;
    }
    template <arithmetic A>
    friend constexpr dual operator-(const dual& a, A c) noexcept {
        dual r = a;
        r.v = a.v - static_cast<T>(c);
        return r;
    }
    template <arithmetic A>
    friend constexpr dual operator-(A c, const dual& a) noexcept {
        dual r = -a;
        r.v = static_cast<T>(c) - a.v;
        return r;
    }
    template <arithmetic A>
    friend constexpr dual operator*(const dual& a, A c) noexcept {
        const T s = static_cast<T>(c);
        dual r;
        r.v = a.v * s;
        for (std::size_t k = 0; k < N; ++k) r.d[k] = a.d[k] * s;
        return r;
    }
    template <arithmetic A>
    friend constexpr dual operator*(A c, const dual& a) noexcept {
        const T s = static_cast<T>(c);
        dual r;
        r.v = s * a.v;
        for (std::size_t k = 0; k < N; ++k) r.d[k] = s * a.d[k];
        return r;
    }
    template <arithmetic A>
    friend constexpr dual operator/(const dual& a, A c) noexcept {
        const T s = static_cast<T>(c);
        dual r;
        r.v = a.v / s;
        for (std::size_t k = 0; k < N; ++k) r.d[k] = a.d[k] / s;
        return r;
    }
    template <arithmetic A>
    friend constexpr dual operator/(A c, const dual& a) noexcept {  // (c / a)' = −(c / a) a' / a
        dual r;
        r.v = static_cast<T>(c) / a.v;
        for (std::size_t k = 0; k < N; ++k) r.d[k] = -r.v * a.d[k] / a.v;
        return r;
    }

    // Compound assignment; an arithmetic right-hand side converts to a constant dual.
    constexpr dual& operator+=(const dual& b) noexcept { return *this = *this + b; }
    constexpr dual& operator-=(const dual& b) noexcept { return *this = *this - b; }
    constexpr dual& operator*=(const dual& b) noexcept { return *this = *this * b; }
    constexpr dual& operator/=(const dual& b) noexcept { return *this = *this / b; }

    // Comparisons on the value only. != and the reversed forms (c == a, c < a) are rewritten from these by C++20.
    friend constexpr bool operator==(const dual& a, const dual& b) noexcept { return a.v == b.v; }
    template <arithmetic A>
    friend constexpr bool operator==(const dual& a, A c) noexcept {
        return a.v == static_cast<T>(c);
    }
    friend constexpr auto operator<=>(const dual& a, const dual& b) noexcept { return a.v <=> b.v; }
    template <arithmetic A>
    friend constexpr auto operator<=>(const dual& a, A c) noexcept {
        return a.v <=> static_cast<T>(c);
    }
};

// Accessors.
template <std::size_t N, class T>
constexpr T value(const dual<N, T>& x) noexcept {
    return x.v;
}
template <std::size_t N, class T>
constexpr T derivative(const dual<N, T>& x, std::size_t k) noexcept {
    return x.d[k];
}

namespace detail {
// r.v = fv, r.d[k] = g · a.d[k]: the chain rule for a function of one argument with derivative g at a.v.
template <std::size_t N, class T>
constexpr dual<N, T> chain(const dual<N, T>& a, const T& fv, const T& g) noexcept {
    dual<N, T> r;
    r.v = fv;
    for (std::size_t k = 0; k < N; ++k) r.d[k] = g * a.d[k];
    return r;
}
}  // namespace detail

// |a| = ±a; at a.v == 0 this returns a (derivative +1, one subgradient of |x|).
template <std::size_t N, class T>
constexpr dual<N, T> abs(const dual<N, T>& a) noexcept {
    return a.v < T(0) ? -a : a;
}
template <std::size_t N, class T>
constexpr dual<N, T> fabs(const dual<N, T>& a) noexcept {
    return abs(a);
}

// √a: derivative 1 / (2√a), infinite at a.v == 0.
template <std::size_t N, class T>
inline dual<N, T> sqrt(const dual<N, T>& a) noexcept {
    using std::sqrt;
    const T s = sqrt(a.v);
    return detail::chain(a, s, T(1) / (T(2) * s));
}

template <std::size_t N, class T>
inline dual<N, T> sin(const dual<N, T>& a) noexcept {
    using std::cos;
    using std::sin;
    return detail::chain(a, T(sin(a.v)), T(cos(a.v)));
}

template <std::size_t N, class T>
inline dual<N, T> cos(const dual<N, T>& a) noexcept {
    using std::cos;
    using std::sin;
    return detail::chain(a, T(cos(a.v)), T(-sin(a.v)));
}

template <std::size_t N, class T>
inline dual<N, T> exp(const dual<N, T>& a) noexcept {
    using std::exp;
    const T e = exp(a.v);
    return detail::chain(a, e, e);
}

template <std::size_t N, class T>
inline dual<N, T> log(const dual<N, T>& a) noexcept {
    using std::log;
    return detail::chain(a, T(log(a.v)), T(1) / a.v);
}

// atan2(y, x): ∂/∂y = x / (x² + y²), ∂/∂x = −y / (x² + y²); undefined at the origin.
template <std::size_t N, class T>
inline dual<N, T> atan2(const dual<N, T>& y, const dual<N, T>& x) noexcept {
    using std::atan2;
    dual<N, T> r;
    r.v = atan2(y.v, x.v);
    const T q = x.v * x.v + y.v * y.v;
    for (std::size_t k = 0; k < N; ++k) r.d[k] = (x.v * y.d[k] - y.v * x.d[k]) / q;
    return r;
}
template <std::size_t N, class T, arithmetic A>
inline dual<N, T> atan2(const dual<N, T>& y, A x) noexcept {
    return atan2(y, dual<N, T>(x));
}
template <std::size_t N, class T, arithmetic A>
inline dual<N, T> atan2(A y, const dual<N, T>& x) noexcept {
    return atan2(dual<N, T>(y), x);
}

// a^p for a constant exponent p: derivative p a^(p−1); for p == 0 the result is the constant 1.
template <std::size_t N, class T, arithmetic A>
inline dual<N, T> pow(const dual<N, T>& a, A p) noexcept {
    using std::pow;
    const T e = static_cast<T>(p);
    if (e == T(0)) return dual<N, T>(T(1));
    return detail::chain(a, T(pow(a.v, e)), T(e * pow(a.v, e - T(1))));
}

// hypot(a, b) = √(a² + b²): ∂/∂a = a / hypot, ∂/∂b = b / hypot; undefined at a = b = 0.
template <std::size_t N, class T>
inline dual<N, T> hypot(const dual<N, T>& a, const dual<N, T>& b) noexcept {
    using std::hypot;
    dual<N, T> r;
    r.v = hypot(a.v, b.v);
    for (std::size_t k = 0; k < N; ++k) r.d[k] = (a.v * a.d[k] + b.v * b.d[k]) / r.v;
    return r;
}
template <std::size_t N, class T, arithmetic A>
inline dual<N, T> hypot(const dual<N, T>& a, A b) noexcept {
    return hypot(a, dual<N, T>(b));
}
template <std::size_t N, class T, arithmetic A>
inline dual<N, T> hypot(A a, const dual<N, T>& b) noexcept {
    return hypot(dual<N, T>(a), b);
}

// True when the value and every partial are finite.
template <std::size_t N, class T>
inline bool isfinite(const dual<N, T>& a) noexcept {
    using std::isfinite;
    if (!isfinite(a.v)) return false;
    for (std::size_t k = 0; k < N; ++k)
        if (!isfinite(a.d[k])) return false;
    return true;
}

// True when the value or any partial is NaN.
template <std::size_t N, class T>
inline bool isnan(const dual<N, T>& a) noexcept {
    using std::isnan;
    if (isnan(a.v)) return true;
    for (std::size_t k = 0; k < N; ++k)
        if (isnan(a.d[k])) return true;
    return false;
}

}  // namespace ctga_test

// The limits of dual<N, T> are those of T, returned as constants (zero partials).
template <std::size_t N, class T>
struct std::numeric_limits<ctga_test::dual<N, T>> {
    using D = ctga_test::dual<N, T>;
    using L = std::numeric_limits<T>;

    static constexpr bool is_specialized = true;
    static constexpr bool is_signed = L::is_signed;
    static constexpr bool is_integer = L::is_integer;
    static constexpr bool is_exact = L::is_exact;
    static constexpr bool has_infinity = L::has_infinity;
    static constexpr bool has_quiet_NaN = L::has_quiet_NaN;
    static constexpr bool has_signaling_NaN = L::has_signaling_NaN;
    static constexpr int digits = L::digits;
    static constexpr int digits10 = L::digits10;
    static constexpr int max_digits10 = L::max_digits10;
    static constexpr int radix = L::radix;

    static constexpr D min() noexcept { return D(L::min()); }
    static constexpr D max() noexcept { return D(L::max()); }
    static constexpr D lowest() noexcept { return D(L::lowest()); }
    static constexpr D epsilon() noexcept { return D(L::epsilon()); }
    static constexpr D round_error() noexcept { return D(L::round_error()); }
    static constexpr D infinity() noexcept { return D(L::infinity()); }
    static constexpr D quiet_NaN() noexcept { return D(L::quiet_NaN()); }
    static constexpr D signaling_NaN() noexcept { return D(L::signaling_NaN()); }
    static constexpr D denorm_min() noexcept { return D(L::denorm_min()); }
};
