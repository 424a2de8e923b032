// ctga::pack<T, L>: L numbers of type T (float or double) handled as one, the scalar type of a
// batch of robots (each lane one robot's state, every algorithm one instruction stream for all L).
//
//   using P = ctga::pack<double, 8>;             // one AVX-512 register, two AVX2 ones
//   P q = P::generate([&](std::size_t l) { return robots[l].q0; });
//   P c = cos(q);                                // every lane's cosine, one polynomial
//   double q3 = q[3];
//
// GCC's and Clang's vector extension (`vector_size`) holds the lanes: every operator is one
// vector instruction on the widest registers -march offers (split in halves or quarters on
// narrower ones), always inlined. <experimental/simd> serves the algorithms too (expr/run.hpp
// converts constants through double), but its operators are layers of templates that GCC's
// inliner gives up on inside an algorithm, and its sin and cos are separate calls (measured, the
// arm's RNEA in 8 lanes, GCC 12 -O3 -march=native: 139 ns per robot with native_simd, 46 ns with
// this type).
//
// Comparisons give a `lanes<T, L>` mask, never a bool: code that branches on a value (`if (m > 0)`)
// does not compile for packs; lane-wise code chooses with `select(mask, a, b)` and reports with
// `any(mask)` / `mask[l]`. Lane results equal the scalar code's bit for bit where the operations
// are the same; cos and sin are this file's polynomials (below), within 1 ulp of libm's.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "ctga/support/inline.hpp"
#include "ctga/support/math.hpp"

namespace ctga {

namespace pack_detail {
template <class T>
using bits_of = std::conditional_t<sizeof(T) == 8, std::int64_t, std::int32_t>;
}  // namespace pack_detail

// A lane mask: lane l is true when its bits are all ones (what a vector comparison yields).
template <class T, std::size_t L>
struct lanes {
    using bits = pack_detail::bits_of<T>;
    using vector [[gnu::vector_size(sizeof(T) * L)]] = bits;
    vector m;

    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr bool operator[](std::size_t l) const noexcept { return m[l] != 0; }
    CTGA_ALWAYS_INLINE friend constexpr lanes operator&&(const lanes& a, const lanes& b) noexcept { return {a.m & b.m}; }
    CTGA_ALWAYS_INLINE friend constexpr lanes operator||(const lanes& a, const lanes& b) noexcept { return {a.m | b.m}; }
    CTGA_ALWAYS_INLINE friend constexpr lanes operator!(const lanes& a) noexcept { return {~a.m}; }
};

template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr bool any(const lanes<T, L>& a) noexcept {
    bool r = false;
    for (std::size_t l = 0; l < L; ++l) r = r || a[l];
    return r;
}
template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr bool all(const lanes<T, L>& a) noexcept {
    return !any(!a);
}

template <class T, std::size_t L>
struct pack {
    static_assert(std::is_floating_point_v<T>, "ctga::pack: the lanes are float or double");
    static_assert(L >= 1 && (L & (L - 1)) == 0 && sizeof(T) * L <= 64,
                  "ctga::pack: the lane count is a power of two, at most one 64-byte register");
    using value_type = T;
    using vector [[gnu::vector_size(sizeof(T) * L)]] = T;
    static constexpr std::size_t size = L;

    vector v;

    pack() = default;
    // every lane x (a model's parameter shared by all lanes, a constant of the engine)
    CTGA_ALWAYS_INLINE constexpr pack(T x) noexcept : v(vector{} + x) {}
    // every lane T(x): an integer, or a double in float lanes (a constant of the engine)
    template <class U>
        requires(std::is_arithmetic_v<U> && !std::is_same_v<U, T>)
    CTGA_ALWAYS_INLINE constexpr explicit pack(U x) noexcept : pack(T(x)) {}
    CTGA_ALWAYS_INLINE constexpr explicit pack(const vector& x, std::nullptr_t) noexcept : v(x) {}

    // lane l is f(l)
    template <class F>
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr pack generate(F&& f) noexcept {
        pack p{T(0)};
        for (std::size_t l = 0; l < L; ++l) p.v[l] = f(l);
        return p;
    }

    [[nodiscard]] CTGA_ALWAYS_INLINE constexpr T operator[](std::size_t l) const noexcept { return v[l]; }
    CTGA_ALWAYS_INLINE constexpr void set(std::size_t l, T x) noexcept { v[l] = x; }

    // lanes from (to) L consecutive numbers: one vector load (store), aligned or not (a batch's
    // structure of arrays, scenes/batch.hpp)
    [[nodiscard]] CTGA_ALWAYS_INLINE static pack load(const T* from) noexcept {
        pack p;
        __builtin_memcpy(&p.v, from, sizeof(vector));
        return p;
    }
    CTGA_ALWAYS_INLINE void store(T* to) const noexcept { __builtin_memcpy(to, &v, sizeof(vector)); }

    CTGA_ALWAYS_INLINE friend constexpr pack operator+(const pack& a, const pack& b) noexcept { return pack(a.v + b.v, nullptr); }
    CTGA_ALWAYS_INLINE friend constexpr pack operator-(const pack& a, const pack& b) noexcept { return pack(a.v - b.v, nullptr); }
    CTGA_ALWAYS_INLINE friend constexpr pack operator*(const pack& a, const pack& b) noexcept { return pack(a.v * b.v, nullptr); }
    CTGA_ALWAYS_INLINE friend constexpr pack operator/(const pack& a, const pack& b) noexcept { return pack(a.v / b.v, nullptr); }
    CTGA_ALWAYS_INLINE friend constexpr pack operator-(const pack& a) noexcept { return pack(-a.v, nullptr); }
    CTGA_ALWAYS_INLINE friend constexpr pack operator+(const pack& a) noexcept { return a; }
    CTGA_ALWAYS_INLINE constexpr pack& operator+=(const pack& b) noexcept { return v += b.v, *this; }
    CTGA_ALWAYS_INLINE constexpr pack& operator-=(const pack& b) noexcept { return v -= b.v, *this; }
    CTGA_ALWAYS_INLINE constexpr pack& operator*=(const pack& b) noexcept { return v *= b.v, *this; }
    CTGA_ALWAYS_INLINE constexpr pack& operator/=(const pack& b) noexcept { return v /= b.v, *this; }

    using mask = lanes<T, L>;
    using mask_vector = typename mask::vector;
    CTGA_ALWAYS_INLINE friend constexpr mask operator==(const pack& a, const pack& b) noexcept { return {mask_vector(a.v == b.v)}; }
    CTGA_ALWAYS_INLINE friend constexpr mask operator!=(const pack& a, const pack& b) noexcept { return {mask_vector(a.v != b.v)}; }
    CTGA_ALWAYS_INLINE friend constexpr mask operator<(const pack& a, const pack& b) noexcept { return {mask_vector(a.v < b.v)}; }
    CTGA_ALWAYS_INLINE friend constexpr mask operator<=(const pack& a, const pack& b) noexcept { return {mask_vector(a.v <= b.v)}; }
    CTGA_ALWAYS_INLINE friend constexpr mask operator>(const pack& a, const pack& b) noexcept { return {mask_vector(a.v > b.v)}; }
    CTGA_ALWAYS_INLINE friend constexpr mask operator>=(const pack& a, const pack& b) noexcept { return {mask_vector(a.v >= b.v)}; }
};

// The lanes of T in the widest vector registers the target offers (-march): 64 bytes with
// AVX-512, 32 with AVX, 16 with SSE2 or NEON; 1 (plain T) without vector registers.
template <class T>
inline constexpr std::size_t native_lanes =
#if defined(__AVX512F__)
    64 / sizeof(T);
#elif defined(__AVX__)
    32 / sizeof(T);
#elif defined(__SSE2__) || defined(__ARM_NEON)
    16 / sizeof(T);
#else
    1;
#endif

template <class P>
inline constexpr bool is_pack = false;
template <class T, std::size_t L>
inline constexpr bool is_pack<pack<T, L>> = true;

// a where m holds, b elsewhere (bitwise: no lane's value is rounded or converted)
template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr pack<T, L> select(const lanes<T, L>& m, const pack<T, L>& a, const pack<T, L>& b) noexcept {
    using V = typename lanes<T, L>::vector;
    return pack<T, L>(typename pack<T, L>::vector((m.m & V(a.v)) | (~m.m & V(b.v))), nullptr);
}

// select for every component of a structure of packs (a multivector, a tree's coordinates:
// anything with a static size() and operator[]).
template <class V, class T, std::size_t L>
    requires requires(V& v) {
        V::size();
        v[0];
    }
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr V select(const lanes<T, L>& m, const V& a, const V& b) noexcept {
    V out = a;
    for (std::size_t i = 0; i < V::size(); ++i) out[i] = select(m, a[i], b[i]);
    return out;
}

// Lanes holding a finite number (NaN fails x == x, ±∞ fails x − x == 0, as is_finite).
template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr lanes<T, L> finite_lanes(const pack<T, L>& x) noexcept {
    return x == x && x - x == pack<T, L>(T(0));
}

namespace pack_detail {
// √ of every lane in one instruction per register where the target has it (correctly rounded,
// as std::sqrt: the same bits), else lane by lane. (std::sqrt lane by lane is a scalar
// instruction and a guarded call per lane: errno, -fmath-errno.) The compilers' builtins, not
// <immintrin.h>: that header costs every unit 0.3 s and 100 MB.
template <class T, std::size_t L>
CTGA_ALWAYS_INLINE void sqrt_register(const T* x, T* out) noexcept {
    using vector [[gnu::vector_size(sizeof(T) * L)]] = T;
    vector v, r;
    __builtin_memcpy(&v, x, sizeof(v));
    constexpr bool is_double = sizeof(T) == 8;
#if defined(__AVX512F__) && defined(__clang__)
    if constexpr (sizeof(v) == 64 && is_double) r = __builtin_ia32_sqrtpd512(v, 4);  // 4: the current rounding
    else if constexpr (sizeof(v) == 64) r = __builtin_ia32_sqrtps512(v, 4);
    else
#elif defined(__AVX512F__)
    // GCC's builtin takes the lane mask as a signed char (8 lanes) or short (16 lanes): all lanes
    // is -1 (0xff would overflow the conversion, an error under -Werror).
    if constexpr (sizeof(v) == 64 && is_double) r = __builtin_ia32_sqrtpd512_mask(v, vector{}, -1, 4);
    else if constexpr (sizeof(v) == 64) r = __builtin_ia32_sqrtps512_mask(v, vector{}, -1, 4);
    else
#endif
#if defined(__AVX__)
    if constexpr (sizeof(v) == 32 && is_double) r = __builtin_ia32_sqrtpd256(v);
    else if constexpr (sizeof(v) == 32) r = __builtin_ia32_sqrtps256(v);
    else
#endif
#if defined(__SSE2__)
    if constexpr (sizeof(v) == 16 && is_double) r = __builtin_ia32_sqrtpd(v);
    else if constexpr (sizeof(v) == 16) r = __builtin_ia32_sqrtps(v);
    else
#endif
        for (std::size_t l = 0; l < L; ++l) r[l] = std::sqrt(v[l]);
    __builtin_memcpy(out, &r, sizeof(r));
}
}  // namespace pack_detail

template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE pack<T, L> sqrt(const pack<T, L>& x) noexcept {
    constexpr std::size_t W = native_lanes<T> < L ? native_lanes<T> : L;  // lanes per register
    pack<T, L> out;
    for (std::size_t k = 0; k < L; k += W)
        pack_detail::sqrt_register<T, W>(reinterpret_cast<const T*>(&x.v) + k, reinterpret_cast<T*>(&out.v) + k);
    return out;
}

template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr pack<T, L> abs(const pack<T, L>& x) noexcept {
    return select(x < pack<T, L>(T(0)), -x, x);
}

namespace pack_detail {
// cos x and sin x of every lane with one range reduction (fdlibm's method, here branch-free over
// the lanes): k = round(2x/π), r = x − k π/2 by Cody and Waite's three-piece π/2 (each piece 33
// bits, k·piece exact for |k| < 2²⁰), then fdlibm's kernels on |r| ≤ π/4 (minimax polynomials of
// degree 13 and 14, error below 2⁻⁵⁸ relative) and the quadrant k mod 4. Against glibc's correctly
// rounded results (measured, tests/pack_test.cpp): 1 ulp at most for |x| ≤ 100 (a quarter of the
// results differ by 1 ulp for |x| ≤ 4), 2 ulp up to 2¹⁹ π/2; within 1e-30 absolute next to the
// zeros k π/2 (where the reduction's three pieces leave k · 8.5e-32 of π/2 out); a larger lane (or an infinite one) takes
// std::cos and std::sin, alone; a NaN lane gives NaN.
template <class T, std::size_t L>
CTGA_ALWAYS_INLINE math::cos_sin_pair<pack<T, L>> cos_sin(const pack<T, L>& x) noexcept {
    using P = pack<T, L>;
    using W = double;  // float lanes are reduced and evaluated in double, then rounded
    if constexpr (!std::is_same_v<T, double>) {
        const auto wide = pack_detail::cos_sin(pack<double, L>::generate([&](std::size_t l) { return double(x[l]); }));
        return {P::generate([&](std::size_t l) { return T(wide.cos[l]); }), P::generate([&](std::size_t l) { return T(wide.sin[l]); })};
    } else {
        const P shifter(W(0x1.8p52));  // adding it rounds to an integer, held in the low bits
        const P t = x * P(W(6.36619772367581382433e-01)) + shifter;
        const P k = t - shifter;
        const P r = ((x - k * P(W(1.57079632673412561417e+00))) - k * P(W(6.07710050630396597660e-11))) -
                    k * P(W(2.02226624871116645580e-21));
        const P z = r * r;
        // sin r = r + r³ S(r²), fdlibm's __kernel_sin
        const P s_poly = r + r * z *
                            (P(W(-1.66666666666666324348e-01)) +
                             z * (P(W(8.33333333332248946124e-03)) +
                                  z * (P(W(-1.98412698298579493134e-04)) +
                                       z * (P(W(2.75573137070700676789e-06)) +
                                            z * (P(W(-2.50507602534068634195e-08)) + z * P(W(1.58969099521155010221e-10)))))));
        const P s = select(r == P(W(0)), r, s_poly);  // sin ±0 = ±0 (the polynomial's r + 0 gives +0)
        // cos r = 1 − r²/2 + r⁴ C(r²), fdlibm's __kernel_cos (w = 1 − r²/2 rounded, its error added back)
        const P c_tail = z * z *
                         (P(W(4.16666666666666019037e-02)) +
                          z * (P(W(-1.38888888888741095749e-03)) +
                               z * (P(W(2.48015872894767294178e-05)) +
                                    z * (P(W(-2.75573143513906633035e-07)) +
                                         z * (P(W(2.08757232129817482790e-09)) + z * P(W(-1.13596475577881948265e-11)))))));
        const P hz = P(W(0.5)) * z;
        const P w = P(W(1)) - hz;
        const P c = w + (((P(W(1)) - w) - hz) + c_tail);
        // x = r + k π/2: (cos, sin) = (c, s), (−s, c), (−c, −s), (s, −c) for k mod 4 = 0, 1, 2, 3
        using V = typename lanes<T, L>::vector;
        const V n = V(t.v);
        using B = typename lanes<T, L>::bits;
        const V sign_bit = V{} + (B(1) << 63), one = V{} + B(1), two = V{} + B(2);
        const V cos_sign = ((n + one) & two) << 62, sin_sign = (n & two) << 62;
        const lanes<T, L> odd{-(n & one)};
        const P cos_r = select(odd, s, c), sin_r = select(odd, c, s);
        math::cos_sin_pair<P> out{P(typename P::vector(V(cos_r.v) ^ (cos_sign & sign_bit)), nullptr),
                                  P(typename P::vector(V(sin_r.v) ^ (sin_sign & sign_bit)), nullptr)};
        // lanes beyond the reduction's range (or infinite) from libm, each on its own: the other
        // lanes keep their numbers whatever their neighbours hold
        const P limit(W(823549.6619));  // 2¹⁹ π/2
        if (const auto far = !(abs(x) < limit) && x == x; any(far)) [[unlikely]]
            for (std::size_t l = 0; l < L; ++l)
                if (far[l]) out.cos.set(l, std::cos(x[l])), out.sin.set(l, std::sin(x[l]));
        return out;
    }
}
}  // namespace pack_detail

// Found by argument-dependent lookup from math::cos_sin, math::cos and math::sin (math.hpp).
template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE math::cos_sin_pair<pack<T, L>> cos_sin(const pack<T, L>& x) noexcept {
    return pack_detail::cos_sin(x);
}
template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE pack<T, L> cos(const pack<T, L>& x) noexcept {
    return pack_detail::cos_sin(x).cos;
}
template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE pack<T, L> sin(const pack<T, L>& x) noexcept {
    return pack_detail::cos_sin(x).sin;
}

}  // namespace ctga
