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

namespace math {

// √x: in constant evaluation Newton's iteration from above (monotone in exact arithmetic, stopped
// when it no longer decreases; not always correctly rounded), at run time std::sqrt.
template <class T>
[[nodiscard]] constexpr T sqrt(const T& x) noexcept {
    if (std::is_constant_evaluated()) {
        if (!(x > T(0)) || !is_finite(x)) return x < T(0) ? std::numeric_limits<T>::quiet_NaN() : x;
        T y = x > T(1) ? x : T(1);  // y ≥ √x
        for (;;) {
            const T next = (y + x / y) / T(2);
            if (!(next < y)) return y;
            y = next;
        }
    } else {
        using std::sqrt;
        return sqrt(x);
    }
}

}  // namespace math
}  // namespace ctga
