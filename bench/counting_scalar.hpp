// A scalar that counts the floating-point operations done on it (ctga_chains_flops): a double and
// four counters. ctga's algorithms are generic in their scalar, so running one on this type gives
// the multiplications, additions (subtractions included) and divisions it executes; negations,
// comparisons and copies are not counted (they are not arithmetic), nor are calls of sin, cos and
// sqrt (counted apart as functions).
#pragma once

#include <cmath>
#include <compare>
#include <limits>

namespace bench::counting {

struct counts {
    long mul = 0, add = 0, div = 0, functions = 0;
};
inline counts tally;  // the operations since the last reset

struct real {
    double v = 0;
    constexpr real() = default;
    constexpr real(double x) : v(x) {}  // NOLINT: converts like a double
    explicit constexpr operator double() const { return v; }
    friend real operator+(real a) { return a; }
    friend real operator-(real a) { return real(-a.v); }
    friend real operator+(real a, real b) { return ++tally.add, real(a.v + b.v); }
    friend real operator-(real a, real b) { return ++tally.add, real(a.v - b.v); }
    friend real operator*(real a, real b) { return ++tally.mul, real(a.v * b.v); }
    friend real operator/(real a, real b) { return ++tally.div, real(a.v / b.v); }
    real& operator+=(real b) { return *this = *this + b; }
    real& operator-=(real b) { return *this = *this - b; }
    real& operator*=(real b) { return *this = *this * b; }
    real& operator/=(real b) { return *this = *this / b; }
    friend bool operator==(real a, real b) { return a.v == b.v; }
    friend auto operator<=>(real a, real b) { return a.v <=> b.v; }
};
inline real sqrt(real a) { return ++tally.functions, real(std::sqrt(a.v)); }
inline real sin(real a) { return ++tally.functions, real(std::sin(a.v)); }
inline real cos(real a) { return ++tally.functions, real(std::cos(a.v)); }
inline real abs(real a) { return real(std::fabs(a.v)); }
inline real fabs(real a) { return real(std::fabs(a.v)); }
inline bool isfinite(real a) { return std::isfinite(a.v); }
inline bool isnan(real a) { return std::isnan(a.v); }

}  // namespace bench::counting

template <>
struct std::numeric_limits<bench::counting::real> : std::numeric_limits<double> {
    using real = bench::counting::real;
    static constexpr real epsilon() noexcept { return real(std::numeric_limits<double>::epsilon()); }
    static constexpr real quiet_NaN() noexcept { return real(std::numeric_limits<double>::quiet_NaN()); }
    static constexpr real infinity() noexcept { return real(std::numeric_limits<double>::infinity()); }
    static constexpr real max() noexcept { return real(std::numeric_limits<double>::max()); }
    static constexpr real min() noexcept { return real(std::numeric_limits<double>::min()); }
    static constexpr real lowest() noexcept { return real(std::numeric_limits<double>::lowest()); }
};
