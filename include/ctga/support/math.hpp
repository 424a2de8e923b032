// Scalar helpers usable in constant expressions as well as at run time, for any scalar type with
// the arithmetic operators (float, double, long double, a user's type).
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

namespace ctga {

// True when every argument is a finite number. Written without std::isfinite so that it is usable
// in constant expressions: NaN fails x == x, ±∞ fails the bound.
template <class T>
[[nodiscard]] constexpr bool is_finite(const T& x) noexcept {
    return x == x && x - x == x - x;
}
template <class... T>
[[nodiscard]] constexpr bool all_finite(const T&... x) noexcept {
    return (is_finite(x) && ...);
}

// A scalar type whose comparisons give a mask of lanes, not a bool (ctga::pack, pack.hpp): code
// that would branch on a value chooses lane by lane with select(mask, a, b) instead.
template <class T>
concept lane_wise = requires(const T& a) { select(a > a, a, a); };

namespace math {

// √x: in constant evaluation Newton's iteration from above (monotone in exact arithmetic, stopped
// when it no longer decreases; not always correctly rounded), at run time std::sqrt.
template <class T>
[[nodiscard]] constexpr T sqrt(const T& x) noexcept {
    if constexpr (!lane_wise<T>) {
        if (std::is_constant_evaluated()) {
            if (!(x > T(0)) || !is_finite(x)) return x < T(0) ? std::numeric_limits<T>::quiet_NaN() : x;
            T y = x > T(1) ? x : T(1);  // y ≥ √x
            for (;;) {
                const T next = (y + x / y) / T(2);
                if (!(next < y)) return y;
                y = next;
            }
        }
    }
    using std::sqrt;
    return sqrt(x);
}

// cos x and sin x together: in constant evaluation x is reduced by the nearest multiple k of π/2,
// r = x − k π/2 with |r| ≤ π/4, and the Taylor series of cos r and sin r are summed until the terms
// no longer change the sums; for float and double all of it in long double (on x86-64 the
// 64-bit significand makes the results correctly rounded but for rare ties, and the reduction
// exact to ~1e-18 |x|). At run time std::cos and std::sin. (Clang does not evaluate std::cos in
// constant expressions.)
template <class T>
struct cos_sin_pair {
    T cos, sin;
};
template <class T>
[[nodiscard]] constexpr cos_sin_pair<T> cos_sin(const T& x) noexcept {
    // (a scalar type that is not a floating-point number, a dual number or a SIMD pack, takes its
    // own cos and sin, found by argument-dependent lookup)
    if constexpr (std::is_floating_point_v<T>) {
        if (std::is_constant_evaluated()) {
            if (!is_finite(x)) return {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::quiet_NaN()};
            using R = long double;
            const R half_pi = R(1.5707963267948966192313216916397514L);
            const R y = R(x);
            const R kf = y / half_pi;
            const long long k = static_cast<long long>(kf < R(0) ? kf - R(0.5) : kf + R(0.5));
            const R r = y - R(k) * half_pi;
            R c = R(1), s = r, term_c = R(1), term_s = r;
            const R r2 = r * r;
            for (int n = 1; n < 40; ++n) {
                term_c = -term_c * r2 / R((2 * n - 1) * (2 * n));
                term_s = -term_s * r2 / R((2 * n) * (2 * n + 1));
                const R c1 = c + term_c, s1 = s + term_s;
                if (c1 == c && s1 == s) break;
                c = c1, s = s1;
            }
            switch (((k % 4) + 4) % 4) {  // x = r + k π/2
                case 0: return {T(c), T(s)};
                case 1: return {T(-s), T(c)};
                case 2: return {T(-c), T(-s)};
                default: return {T(s), T(-c)};
            }
        }
    }
    using std::cos;
    using std::sin;
    return {cos(x), sin(x)};
}
template <class T>
[[nodiscard]] constexpr T cos(const T& x) noexcept {
    if (std::is_constant_evaluated()) return cos_sin(x).cos;
    using std::cos;
    return cos(x);
}
template <class T>
[[nodiscard]] constexpr T sin(const T& x) noexcept {
    if (std::is_constant_evaluated()) return cos_sin(x).sin;
    using std::sin;
    return sin(x);
}

}  // namespace math
}  // namespace ctga
