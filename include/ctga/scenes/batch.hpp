// Many bodies of one kind, stepped together in a structure-of-arrays layout.
//
//   ctga::batch<double, ctga::subspace::full, ctga::inertia_kind::diagonal, 10'000> bodies{{m, dx, dy, dz}};
//   bodies.add(g0, s0);                        // false once Capacity bodies are held
//   if (bodies.step_rk4(1e-3) != ctga::input_error::none) { /* a NaN or ∞ somewhere */ }
//   ctga::motor<double> g = bodies.pose(7);    // body 7's pose and velocity as ctga types
//
// Layout. For every component of the motor and of the body-frame velocity screw, one contiguous
// array over the bodies (8 + 6 arrays for subspace::full, 4 + 3 for planar): component c of body
// i is g_[c][i]. No heap: std::array storage of a fixed Capacity and a run-time count ≤ Capacity
// (the object is 14 × 8 × Capacity bytes for full bodies in double: put a large batch in static
// or heap storage).
//
// One set of mass properties. A batch holds identical bodies: one `K::data<T>` for all of them
// (bodies of one kind with different masses or moments go in different batches). The mass
// properties are then loop invariants: the reciprocals K::arguments computes on every call of
// body_acceleration (body_kinds.hpp) are hoisted out of the loop and the inertia's scalars sit
// in registers, so the per-body work is the equation of motion and nothing else, and every
// kind, `general` included (60 numbers per body), costs no memory traffic beyond the state.
//
// step_rk4(h) is the classical Runge–Kutta step of ctga::rk4{} on (g, s) in the body frame, the
// motor renormalised afterwards, as loops over the bodies whose bodies are straight-line code:
// load body i's components into ctga multivectors, evaluate the rates with body_motor_rate and
// body_acceleration (always-inline engine code), combine the stages with rk4::step's
// expressions, store; then renormalise. No branch depends on the data and every access is
// unit-stride, so GCC vectorises every loop across bodies (2 bodies per SSE2 register, 4 or 8
// with AVX or AVX-512) with no flags beyond -O2/-O3. The arithmetic is rk4's own, operation for
// operation, so with batch_renormalization::exact (the default) each body gets exactly the
// numbers of ctga::rk4{}.step(body_motion<T, S, K>{body}, x, h), as long as the compiler forms
// no fused multiply-adds (GCC contracts a·b + c by default in C++ when the target has FMA, e.g.
// -march=native, and may do so differently in the two codes: then they agree to rounding).
//
// Renormalisation without branches. motion.hpp's renormalize divides g by its dual-number norm
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
//
// Failures. Each loop that stores also ORs together, branch-free, a flag word per component
// that marks a NaN or an infinity (an integer reduction over the bits of the new state, which
// vectorises too); after the loops step_rk4 tests it once and returns input_error::non_finite
// when any body's new state is not finite (first_non_finite() finds the body). The step is not
// undone: bodies with finite states are stepped correctly, and a non-finite one stays so. A
// non-finite h is rejected before anything is stepped.
//
// aos_step_rk4 is the array-of-structures reference: ctga::rk4{}.step for each body of a
// std::array of motion_states (bench/batch.cpp times the two).
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include "ctga/integrators/methods.hpp"
#include "ctga/integrators/model.hpp"
#include "ctga/mechanics/checked.hpp"
#include "ctga/mechanics/motion.hpp"
#include "ctga/scenes/body_kinds.hpp"

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
// written (not -ffast-math's reassociation). In constant evaluation it is motion.hpp's sqrt,
// as renormalize's is.
template <class T>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr T sqrt_1_4(const T& x) noexcept {
    if (std::is_constant_evaluated() || !binary_ieee<T>) return motion_detail::sqrt(x);
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

// motion.hpp's renormalize without its branches, for a finite g with α ≠ 0, on a motor type M
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

// N ≤ Capacity bodies of subspace S and inertia structure K with one set of mass properties, in
// structure-of-arrays layout (see the top of this file).
template <class T, class S, class K, std::size_t Capacity, batch_renormalization Renormalization = batch_renormalization::exact>
class batch {
public:
    using scalar_type = T;
    using motor_type = typename S::template motor_type<T>;
    using screw_type = typename S::template screw_type<T>;
    using body_type = typename K::template data<T>;
    using model_type = body_motion<T, S, K>;
    using state_type = motion_state<motor_type, screw_type>;

    static constexpr std::size_t motor_size = motor_type::size();
    static constexpr std::size_t screw_size = screw_type::size();

    constexpr batch() noexcept = default;
    constexpr explicit batch(const body_type& body) noexcept : body_(body) {}

    [[nodiscard]] static constexpr std::size_t capacity() noexcept { return Capacity; }
    [[nodiscard]] constexpr std::size_t size() const noexcept { return n_; }
    [[nodiscard]] constexpr const body_type& body() const noexcept { return body_; }
    // The single-body model whose rk4 step the batch's step reproduces.
    [[nodiscard]] constexpr model_type model() const noexcept { return model_type{body_}; }

    constexpr void clear() noexcept { n_ = 0; }

    // Appends a body with pose g and body-frame velocity s; false (and nothing added) when the
    // batch is full. Nothing is validated here: step_rk4 reports non-finite states.
    constexpr bool add(const motor_type& g, const screw_type& s) noexcept {
        if (n_ == Capacity) return false;
        store(n_++, g, s);
        return true;
    }
    constexpr bool add(const state_type& x) noexcept { return add(x.g, x.s); }

    // Body i's pose, velocity and state as ctga types (i < size()).
    [[nodiscard]] constexpr motor_type pose(std::size_t i) const noexcept {
        return load<motor_type>(g_, i, std::make_index_sequence<motor_size>{});
    }
    [[nodiscard]] constexpr screw_type velocity(std::size_t i) const noexcept {
        return load<screw_type>(s_, i, std::make_index_sequence<screw_size>{});
    }
    [[nodiscard]] constexpr state_type state(std::size_t i) const noexcept { return {pose(i), velocity(i)}; }
    constexpr void set(std::size_t i, const motor_type& g, const screw_type& s) noexcept { store(i, g, s); }

    // The contiguous array of motor (screw) component c over the bodies: c in the order of
    // motor_type's (screw_type's) blades, entries 0 … size() − 1 meaningful.
    [[nodiscard]] constexpr const T* motor_component(std::size_t c) const noexcept { return g_[c].data(); }
    [[nodiscard]] constexpr const T* screw_component(std::size_t c) const noexcept { return s_[c].data(); }

    // One classical RK4 step of size h for every body (see the top of this file): the results of
    // ctga::rk4{}.step(model(), state(i), h) with renormalisation. Returns non_finite, having
    // stepped nothing, for a non-finite h; and non_finite, after the step, when some body's new
    // state has a NaN or an infinity.
    constexpr input_error step_rk4(const T& step) noexcept {
        // by value: a reference could point into the arrays the loop stores to, and would be
        // reloaded on every iteration (a block after the loop's exit test: no if-conversion)
        const T h = step;
        if (!is_finite(h)) return input_error::non_finite;
        typename flags::word bad = 0;
        std::array<T, block> scale{}, root{};  // per body of a block: the scale, and n² then its root
        for (std::size_t first = 0; first < n_; first += block) {
            const std::size_t last = first + block < n_ ? first + block : n_;
            bad |= advance(first, last, h);
            measure(first, last, scale, root);
            for (std::size_t j = 0; j < last - first; ++j) root[j] = renormalizer::root(root[j]);
            bad |= apply(first, last, scale, root);
        }
        return flags::any(bad) ? input_error::non_finite : input_error::none;
    }

    // The first body whose state has a NaN or an infinity, or size() when there is none.
    [[nodiscard]] constexpr std::size_t first_non_finite() const noexcept {
        for (std::size_t i = 0; i < n_; ++i) {
            for (std::size_t c = 0; c < motor_size; ++c)
                if (!is_finite(g_[c][i])) return i;
            for (std::size_t c = 0; c < screw_size; ++c)
                if (!is_finite(s_[c][i])) return i;
        }
        return n_;
    }

private:
    using flags = batch_detail::finiteness_flags<T>;
    using renormalizer = batch_detail::renormalizer<motor_type, Renormalization>;

    // The step runs over blocks of this many bodies, in four loops each: advance (the RK4
    // stages, leaving the unnormalised motors in g_), then the three stages of the
    // renormalisation (measure, root, apply; batch_detail::renormalizer), the intermediate
    // numbers in two arrays of a block's length. Each loop's body is then short enough for the
    // processor to overlap many iterations: the renormalisation is a chain of about 40
    // dependent operations (max, division, the Newton steps of the root, division), which in
    // one loop with the stages (~1,000 operations per body) overlapped nothing and took 45% of
    // the step. A block's motors (8 × 256 numbers) stay in the L1 cache between the loops.
    static constexpr std::size_t block = 256;

    // RK4 for bodies [first, last): rk4::step (methods.hpp) with the model's rates written out:
    // rates(model, x) is {motor_rate(g, s), acceleration(g, s)}, shifted(x, c, k) is
    // {g + c k.g, s + c k.s}. Stores the velocities and the unnormalised motors; returns the
    // velocities' finiteness flags.
    CTGA_ALWAYS_INLINE constexpr typename flags::word advance(std::size_t first, std::size_t last, const T h) noexcept {
        const body_type body = body_;  // a loop invariant, visibly not aliased by the stores
        const T h2 = h / T(2);
        const T w = h / T(6);
        typename flags::word bad = 0;
        for (std::size_t i = first; i < last; ++i) {
            const motor_type g = load<motor_type>(g_, i, std::make_index_sequence<motor_size>{});
            const screw_type s = load<screw_type>(s_, i, std::make_index_sequence<screw_size>{});
            const motor_type k1g(body_motor_rate<S, T>(g, s));
            const screw_type k1s(body_acceleration<S, K, T>(body, s));
            const motor_type g2(g + h2 * k1g);
            const screw_type s2(s + h2 * k1s);
            const motor_type k2g(body_motor_rate<S, T>(g2, s2));
            const screw_type k2s(body_acceleration<S, K, T>(body, s2));
            const motor_type g3(g + h2 * k2g);
            const screw_type s3(s + h2 * k2s);
            const motor_type k3g(body_motor_rate<S, T>(g3, s3));
            const screw_type k3s(body_acceleration<S, K, T>(body, s3));
            const motor_type g4(g + h * k3g);
            const screw_type s4(s + h * k3s);
            const motor_type k4g(body_motor_rate<S, T>(g4, s4));
            const screw_type k4s(body_acceleration<S, K, T>(body, s4));
            const motor_type y(g + w * (k1g + T(2) * (k2g + k3g) + k4g));
            const screw_type v(s + w * (k1s + T(2) * (k2s + k3s) + k4s));
            batch_detail::static_for<motor_size>([&](auto c) { g_[c][i] = y[c]; });
            batch_detail::static_for<screw_size>([&](auto c) {
                s_[c][i] = v[c];
                bad |= flags::of(v[c]);
            });
        }
        return bad;
    }

    // Renormalisation, stage 1 for bodies [first, last): the scale and n² of each motor.
    CTGA_ALWAYS_INLINE constexpr void measure(std::size_t first, std::size_t last, std::array<T, block>& scale,
                                              std::array<T, block>& n2) noexcept {
        for (std::size_t i = first; i < last; ++i) {
            const motor_type y = load<motor_type>(g_, i, std::make_index_sequence<motor_size>{});
            std::array<T, 8> x = renormalizer::unpack(y);
            n2[i - first] = renormalizer::measure(x, scale[i - first]);
            if constexpr (Renormalization == batch_renormalization::exact) {  // α/m
                motor_type out = y;
                renormalizer::pack(x, out);
                batch_detail::static_for<motor_size>([&](auto c) {
                    if constexpr (renormalizer::alpha_slot[c]) g_[c][i] = out[c];
                });
            }
        }
    }

    // Renormalisation, stage 3: the motors of bodies [first, last) renormalised in place;
    // returns their finiteness flags.
    CTGA_ALWAYS_INLINE constexpr typename flags::word apply(std::size_t first, std::size_t last,
                                                            const std::array<T, block>& scale,
                                                            const std::array<T, block>& root) noexcept {
        typename flags::word bad = 0;
        for (std::size_t i = first; i < last; ++i) {
            motor_type g = load<motor_type>(g_, i, std::make_index_sequence<motor_size>{});
            std::array<T, 8> x = renormalizer::unpack(g);
            renormalizer::apply(x, scale[i - first], root[i - first]);
            renormalizer::pack(x, g);
            batch_detail::static_for<motor_size>([&](auto c) {
                g_[c][i] = g[c];
                bad |= flags::of(g[c]);
            });
        }
        return bad;
    }

    template <class X, std::size_t N, std::size_t... C>
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr X load(const std::array<std::array<T, Capacity>, N>& a,
                                                             std::size_t i, std::index_sequence<C...>) noexcept {
        return X{a[C][i]...};
    }
    constexpr void store(std::size_t i, const motor_type& g, const screw_type& s) noexcept {
        for (std::size_t c = 0; c < motor_size; ++c) g_[c][i] = g[c];
        for (std::size_t c = 0; c < screw_size; ++c) s_[c][i] = s[c];
    }

    body_type body_{};
    std::size_t n_ = 0;
    alignas(64) std::array<std::array<T, Capacity>, motor_size> g_{};  // g_[c][i]: component c of body i
    alignas(64) std::array<std::array<T, Capacity>, screw_size> s_{};
};

// The array-of-structures reference: ctga::rk4{}.step(model, x, h) for each of the first
// `count` states (all of them by default), each state stored as one motion_state. Returns
// non_finite for a non-finite h (nothing stepped) or when some new state is not finite
// (model.finite, as integrate checks), else none.
template <motion_model M, std::size_t N>
constexpr input_error aos_step_rk4(const M& model, std::array<state_of<M>, N>& states,
                                   const typename M::scalar_type& step, std::size_t count = N) noexcept {
    const typename M::scalar_type h = step;
    if (!is_finite(h)) return input_error::non_finite;
    bool finite = true;
    for (std::size_t i = 0; i < count && i < N; ++i) {
        const checked<state_of<M>> next = rk4{}.step(model, states[i], h);
        states[i] = next.value;
        finite = model.finite(next.value.g, next.value.s) && finite;
    }
    return finite ? input_error::none : input_error::non_finite;
}

}  // namespace ctga
