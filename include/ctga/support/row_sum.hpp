// ctga::row_sum<T, Count, L>: a running sum s = −Σ_e c_e x_e of short rows x_e (Count numbers
// each, contiguous: a matrix's row or part of one), held in registers for the whole sum: Count / L
// packs of L lanes (pack.hpp) and Count % L single numbers, every step unrolled at compile time.
//
//   row_sum<double, 18, native_lanes<double>> s;          // zero
//   for (k : list) s.subtract(B(k, j), A.data() + k * n);  // s −= B(k, j) A(k, ·)
//   s.each([&](std::size_t i, double v) { out(i, j) = v; });
//
// Products of a matrix with a sparse one are such sums (H⁻¹ ∂τ, column by column over ∂τ's
// pattern; H⁻¹ from its factor, row by row over a dof's path): kept in registers they are bound by
// their multiply-adds; a loop over the row in memory loads and stores the partial sums at every
// step (measured, Solo 12's two products H⁻¹ ∂τ/∂q, H⁻¹ ∂τ/∂q̇: 1.25 µs in memory, 0.77 µs so).
// L = 1 holds plain numbers: any T (robots in lanes, dual numbers), and constant evaluation
// (pack's loads are not constexpr); row_lanes<T> is native_lanes for float and double, else 1.
// Count / L packs should fit the registers (at most about 12 of 16; callers split longer rows).
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/support/inline.hpp"
#include "ctga/support/pack.hpp"

namespace ctga {

template <class T>
inline constexpr std::size_t row_lanes = std::is_same_v<T, float> || std::is_same_v<T, double> ? native_lanes<T> : 1;

template <class T, std::size_t Count, std::size_t L>
struct row_sum {
    static_assert(L == 1 || (std::is_floating_point_v<T> && L == native_lanes<T>), "ctga::row_sum: L is 1 or the native lanes of a float");
    using P = std::conditional_t<L == 1, T, pack<T, L>>;
    static constexpr std::size_t packs = Count / L, rest = Count % L;

    P p[packs + 1];  // (+ 1: no array of size 0)
    T r[rest + 1];

    CTGA_ALWAYS_INLINE constexpr row_sum() noexcept : row_sum(std::make_index_sequence<packs>{}, std::make_index_sequence<rest>{}) {}

    // s −= c x[0 … Count)
    CTGA_ALWAYS_INLINE constexpr void subtract(const T& c, const T* x) noexcept {
        subtract(c, x, std::make_index_sequence<packs>{}, std::make_index_sequence<rest>{});
    }
    // f(i, s_i) for i = 0 … Count − 1, in order
    template <class F>
    CTGA_ALWAYS_INLINE constexpr void each(F&& f) const noexcept {
        each(f, std::make_index_sequence<packs>{}, std::make_index_sequence<rest>{});
    }
    // s into to[0 … Count)
    CTGA_ALWAYS_INLINE constexpr void store(T* to) const noexcept {
        if constexpr (L == 1) each([&](std::size_t i, const T& v) CTGA_INLINE_LAMBDA { to[i] = v; });
        else store(to, std::make_index_sequence<packs>{}, std::make_index_sequence<rest>{});
    }

private:
    template <std::size_t... C, std::size_t... R>
    CTGA_ALWAYS_INLINE constexpr row_sum(std::index_sequence<C...>, std::index_sequence<R...>) noexcept
        : p{((void)C, P(T(0)))..., P(T(0))}, r{((void)R, T(0))..., T(0)} {}
    [[nodiscard]] CTGA_ALWAYS_INLINE static constexpr P load(const T* x) noexcept {
        if constexpr (L == 1) return *x;
        else return P::load(x);
    }
    template <std::size_t... C, std::size_t... R>
    CTGA_ALWAYS_INLINE constexpr void subtract(const T& c, const T* x, std::index_sequence<C...>, std::index_sequence<R...>) noexcept {
        const P cs(c);
        ((p[C] -= cs * load(x + L * C)), ...);
        ((r[R] -= c * x[L * packs + R]), ...);
    }
    template <class F, std::size_t... C, std::size_t... R>
    CTGA_ALWAYS_INLINE constexpr void each(F& f, std::index_sequence<C...>, std::index_sequence<R...>) const noexcept {
        if constexpr (L == 1) (f(C, p[C]), ...);
        else
            (..., [&]() CTGA_INLINE_LAMBDA {
                for (std::size_t l = 0; l < L; ++l) f(L * C + l, p[C][l]);
            }());
        (f(L * packs + R, r[R]), ...);
    }
    template <std::size_t... C, std::size_t... R>
    CTGA_ALWAYS_INLINE void store(T* to, std::index_sequence<C...>, std::index_sequence<R...>) const noexcept {
        (p[C].store(to + L * C), ...);
        ((to[L * packs + R] = r[R]), ...);
    }
};

}  // namespace ctga
