// Branch-free floating-point kernels for the batch (batch.hpp): loops over many bodies vectorise
// only when their bodies have no control flow, so these do what ctga's scalar code does with
// branches (renormalize_checked, std::sqrt, finiteness checks) without them.
//
// Renormalisation without branches. motor.hpp's renormalize divides g by its dual-number norm
// after scaling by max |αi|. renormalize_checked branches on non-finite input and on α = 0, and
// its √ is std::sqrt, which under the default -fmath-errno compiles to a square-root instruction
// and a guarded call to sqrt() (to set errno for a negative argument): control flow, which stops
// GCC from vectorising a loop that contains it. The batch assumes finite input and does the
// same operations in the same order without branches (batch_detail::renormalizer), taking the
// square root of the scaled |α|² ∈ [1, 4] with sqrt_1_4: branch-free, vectorisable and
// correctly rounded, i.e. std::sqrt's value. For non-finite input or α = 0 it produces NaNs
// (never a finite-looking motor). batch_renormalization::fast replaces the 16 divisions per
// body by one reciprocal and multiplications, and the square root by Newton's iteration for
// 1/|α|; its motors differ from exact's by a few ulps.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include "ctga/integrators/model.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/support/math.hpp"

namespace ctga {

// How a batch renormalises its motors after a step (see the top of the file).
enum class batch_renormalization {
    exact,  // renormalize_checked's operations: the same numbers as ctga::rk4{}, bit for bit
    fast,   // one division per body (1/max |αi|) and Newton's iteration for 1/|α|: within a
            // few ulps of exact
};

namespace batch_detail {

template <std::size_t... I, class F>
CTGA_ALWAYS_INLINE constexpr void static_for(std::index_sequence<I...>, F&& f) {
    (f(std::integral_constant<std::size_t, I>{}), ...);
}
template <std::size_t N, class F>
CTGA_ALWAYS_INLINE constexpr void static_for(F&& f) {
    static_for(std::make_index_sequence<N>{}, static_cast<F&&>(f));
}

// Binary IEEE types get the branch-free square root and the bitwise finiteness flags; any other
// scalar type (a user type, say) uses std::sqrt (found by ADL) and is_finite.
template <class T>
inline constexpr bool binary_ieee = std::numeric_limits<T>::is_iec559 && std::numeric_limits<T>::radix == 2;

template <class T>
inline constexpr bool fast_fma =
#if defined(__FP_FAST_FMA)
    std::is_same_v<T, double> ||
#endif
#if defined(__FP_FAST_FMAF)
    std::is_same_v<T, float> ||
#endif
#if defined(__FP_FAST_FMAL)
    std::is_same_v<T, long double> ||
#endif
    false;

// hi + lo = a b exactly (no overflow or underflow: here a, b ∈ [1, 2]). With a fused
// multiply-add instruction, lo = fma(a, b, −hi); otherwise Dekker's product over Veltkamp's
// splitting into halves of ⌈p/2⌉ bits (exact without contraction, which needs that instruction).
template <class T>
CTGA_ALWAYS_INLINE constexpr void two_product(const T& a, const T& b, T& hi, T& lo) noexcept {
    hi = a * b;
    if constexpr (fast_fma<T>) {
        if (!std::is_constant_evaluated()) {
            lo = std::fma(a, b, -hi);
            return;
        }
    }
    constexpr int half_digits = (std::numeric_limits<T>::digits + 1) / 2;
    constexpr T splitter = [] {
        T c = T(1);
        for (int i = 0; i < half_digits; ++i) c *= T(2);
        return c + T(1);
    }();
    const T ca = splitter * a, cb = splitter * b;
    const T ah = ca - (ca - a), bh = cb - (cb - b);
    const T al = a - ah, bl = b - bh;
    lo = al * bl - (((hi - ah * bh) - al * bh) - ah * bl);
}

// How many Newton steps for 1/√x take the quadratic start below (relative error ≤ 0.030 on
// [1, 4]) to an error e with e² far below the type's ε (e_{k+1} = 1.5 e_k²): 3 for float and
// double (e ≤ 2e-11), 4 for the 64-bit long double.
template <class T>
inline constexpr int rsqrt_steps = [] {
    long double e = 0.031L, target = 1.0L;
    for (int i = 0; i < std::numeric_limits<T>::digits / 2 + 8; ++i) target /= 2;
    int k = 0;
    while (e > target) e = 1.5L * e * e, ++k;
    return k;
}();

// √x for x ∈ [1, 4], correctly rounded (the value std::sqrt returns), without a branch:
//  1. r ≈ 1/√x from a quadratic (relative error ≤ 0.030), then rsqrt_steps Newton steps
//     r ← r (3/2 − (x/2) r²) (multiplications only): error ≤ 2e-11 for double;
//  2. y = x r, and one Newton step for √x on the exact residual x − y² (Dekker's product:
//     x − hi is exact by Sterbenz's lemma): |y − √x| < ½ ulp + 1e-22, a faithful rounding;
//  3. the exact rounding. With u = ε (the ulp of [1, 2)), y = Y u and x = X u for integers X, Y
//     (x ∈ [1, 4] lies on the grid u or 2u), √x rounds to y + u iff x > (y + u/2)², i.e.
//     X/u > Y² + Y + ¼, i.e. (integers) x > y (y + u); and to y − u iff x < (y − u/2)², i.e.
//     x ≤ y (y − u). √x is never a midpoint. Both products are formed exactly (hi + lo) and
//     x − hi is exact, so each test is one exact comparison x − hi > lo (resp. ≤), and the
//     choice is two selects. (At y = 2, x ≤ 4 never rounds up, and 2 − u is y's predecessor.)
// Outside [1, 4] it returns garbage; for a NaN it returns NaN. It needs IEEE arithmetic as
// written (not -ffast-math's reassociation). In constant evaluation it is support/math.hpp's sqrt,
// as renormalize's is.
template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr T sqrt_1_4(const T& x) noexcept {
    if (std::is_constant_evaluated() || !binary_ieee<T>) return math::sqrt(x);
    // a near-minimax quadratic for 1/√x on [1, 4] (Chebyshev interpolation)
    T r = T(1.3143245040136764) + x * (T(-0.3917463524081892) + x * T(0.0475995054464756));
    const T half_x = x / T(2);
    for (int k = 0; k < rsqrt_steps<T>; ++k) r = r * (T(1.5) - half_x * r * r);
    T y = x * r;
    T hi, lo;
    two_product(y, y, hi, lo);
    y = y + (r / T(2)) * ((x - hi) - lo);
    constexpr T u = std::numeric_limits<T>::epsilon();
    const T up = y + u, down = y - u;
    T hi_up, lo_up, hi_down, lo_down;
    two_product(y, up, hi_up, lo_up);
    two_product(y, down, hi_down, lo_down);
    const T out = x - hi_up > lo_up ? up : y;
    return x - hi_down <= lo_down ? down : out;
}

// 1/√x for x ∈ [1, 4] to within a few ulps, without a branch: the quadratic start of sqrt_1_4
// and Newton steps r ← r (3/2 − (x/2) r²) until the error is at rounding level (one more step
// than sqrt_1_4 takes before its exact correction).
template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr T rsqrt_1_4(const T& x) noexcept {
    T r = T(1.3143245040136764) + x * (T(-0.3917463524081892) + x * T(0.0475995054464756));
    const T half_x = x / T(2);
    for (int k = 0; k < rsqrt_steps<T> + 1; ++k) r = r * (T(1.5) - half_x * r * r);
    return r;
}

// motor.hpp's renormalize without its branches, for a finite g with α ≠ 0, on a motor type M
// (a full motor or a subspace's), in three stages that the batch runs as three loops:
//   measure   m = max |αi| and n² = |α/m|² ∈ [1, 4]; exact: α ← α/m (renormalize_checked's
//             first division), the scale is m; fast: the scale is 1/m
//   root      exact: n = √(n²) (sqrt_1_4, std::sqrt's value); fast: 1/n (Newton)
//   apply     exact: g/m/n with renormalize_checked's divisions in its order; fast: g·(1/m)(1/n);
//             then β ← β − (α̂·β) α̂
// The motor is handled as its 8 components in motor<T>'s order and orientation (components M
// does not hold are exact zeros and are skipped, which can change only the sign of a zero).
template <class M, batch_renormalization Mode>
struct renormalizer {
    using T = typename M::scalar_type;
    using full = motor<T>;

    // component k of motor<T> is component index[k] of M, times sign[k] (index −1: not held)
    static constexpr std::array<int, 8> index = [] {
        std::array<int, 8> out{};
        for (std::size_t k = 0; k < 8; ++k) out[k] = M::layout.index_of(full::layout.masks[k]);
        return out;
    }();
    static constexpr std::array<int, 8> sign = [] {
        std::array<int, 8> out{};
        for (std::size_t k = 0; k < 8; ++k)
            out[k] = index[k] < 0 ? 0 : M::layout.signs[static_cast<std::size_t>(index[k])] * full::layout.signs[k];
        return out;
    }();
    static constexpr bool held(std::size_t k) noexcept { return index[k] >= 0; }
    // whether M's component c is one of α's
    static constexpr std::array<bool, M::size()> alpha_slot = [] {
        std::array<bool, M::size()> out{};
        for (std::size_t k = 0; k < 4; ++k)
            if (index[k] >= 0) out[static_cast<std::size_t>(index[k])] = true;
        return out;
    }();
    static constexpr std::size_t first_alpha = held(0) ? 0 : held(1) ? 1 : held(2) ? 2 : 3;  // every motor has one
    static constexpr bool coupled = (held(0) && held(4)) || (held(1) && held(5)) || (held(2) && held(6)) || (held(3) && held(7));

    // M's components (any indexable) to motor<T>'s and back
    template <class C>
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr std::array<T, 8> unpack(const C& c) noexcept {
        std::array<T, 8> x{};
        static_for<8>([&](auto k) {
            if constexpr (held(k)) {
                const T v = c[static_cast<std::size_t>(index[k])];
                x[k] = sign[k] > 0 ? v : -v;
            }
        });
        return x;
    }
    template <class C>
    CTGA_ALWAYS_INLINE static constexpr void pack(const std::array<T, 8>& x, C& c) noexcept {
        static_for<8>([&](auto k) {
            if constexpr (held(k)) c[static_cast<std::size_t>(index[k])] = sign[k] > 0 ? x[k] : -x[k];
        });
    }

    // Stage 1: returns n² and sets the scale (α is divided by m in exact mode).
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr T measure(std::array<T, 8>& x, T& scale) noexcept {
        T m = T(0);
        static_for<4>([&](auto k) {
            if constexpr (held(k)) {
                const T a = x[k] > -x[k] ? x[k] : -x[k];  // |x| (as a max: one instruction)
                m = a > m ? a : m;
            }
        });
        std::array<T, 4> a{};
        if constexpr (Mode == batch_renormalization::exact) {
            static_for<4>([&](auto k) {
                if constexpr (held(k)) a[k] = x[k] = x[k] / m;
            });
            scale = m;
        } else {
            scale = T(1) / m;
            static_for<4>([&](auto k) {
                if constexpr (held(k)) a[k] = x[k] * scale;
            });
        }
        T n2 = a[first_alpha] * a[first_alpha];
        static_for<4>([&](auto k) {
            if constexpr (held(k) && k != first_alpha) n2 = n2 + a[k] * a[k];
        });
        return n2;
    }

    // Stage 2.
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr T root(const T& n2) noexcept {
        if constexpr (Mode == batch_renormalization::exact) return sqrt_1_4(n2);
        else return rsqrt_1_4(n2);
    }

    // Stage 3, on measure's output.
    CTGA_ALWAYS_INLINE static constexpr void apply(std::array<T, 8>& x, const T& scale, const T& root) noexcept {
        if constexpr (Mode == batch_renormalization::exact) {
            static_for<8>([&](auto k) {
                if constexpr (held(k) && k >= 4) x[k] = x[k] / scale;  // β/m (α was divided in measure)
            });
            static_for<8>([&](auto k) {
                if constexpr (held(k)) x[k] /= root;
            });
        } else {
            const T s = scale * root;  // 1/|α|
            static_for<8>([&](auto k) {
                if constexpr (held(k)) x[k] = x[k] * s;
            });
        }
        if constexpr (coupled) {
            T d = T(0);
            bool started = false;  // a constant once unrolled
            static_for<4>([&](auto k) {
                if constexpr (held(k) && held(k + 4)) {
                    d = started ? d + x[k] * x[k + 4] : x[k] * x[k + 4];
                    started = true;
                }
            });
            static_for<4>([&](auto k) {
                if constexpr (held(k) && held(k + 4)) x[k + 4] -= d * x[k];
            });
        }
    }

    // The three stages on one motor.
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr M run(const M& g) noexcept {
        std::array<T, 8> x = unpack(g);
        T scale{};
        const T n2 = measure(x, scale);
        apply(x, scale, root(n2));
        M out;
        pack(x, out);
        return out;
    }
};

template <batch_renormalization Mode = batch_renormalization::exact, class M>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr M renormalize_unguarded(const M& g) noexcept {
    return renormalizer<M, Mode>::run(g);
}

// A flag word that is non-zero in its marked bit when x is NaN or ±∞, built without a branch so
// that OR-ing it over a loop is a vectorisable reduction: for an IEEE binary type the exponent
// field plus one unit of it carries into the sign bit exactly when the field is all ones.
template <class T>
struct finiteness_flags {
    using word = std::conditional_t<binary_ieee<T> && sizeof(T) == 8, std::uint64_t,
                                    std::conditional_t<binary_ieee<T> && sizeof(T) == 4, std::uint32_t, unsigned>>;
    static constexpr bool bitwise = binary_ieee<T> && (sizeof(T) == 8 || sizeof(T) == 4);

    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr word of(const T& x) noexcept {
        if constexpr (bitwise) {
            constexpr int mantissa = std::numeric_limits<T>::digits - 1;
            constexpr word exponent = ((word(1) << (sizeof(T) * 8 - 1 - mantissa)) - 1) << mantissa;
            return (std::bit_cast<word>(x) & exponent) + (word(1) << mantissa);
        } else {
            return is_finite(x) ? word(0) : word(1);
        }
    }
    [[nodiscard]] static constexpr bool any(word w) noexcept {
        if constexpr (bitwise) return (w >> (sizeof(T) * 8 - 1)) != 0;
        else return w != 0;
    }
};

}  // namespace batch_detail

}  // namespace ctga
