// Exact rational coefficients for the compile-time normal form: the paper's ½ stays ½, and
// ½·2 = 1 exactly, so that cancellations and unit coefficients are seen by the compiler.
#pragma once

#include <cstdint>

namespace ctga::expr {

struct rational {
    std::int64_t num = 0;
    std::int64_t den = 1;  // > 0, gcd(num, den) = 1

    friend constexpr bool operator==(const rational&, const rational&) = default;
};

constexpr std::int64_t gcd(std::int64_t a, std::int64_t b) {
    if (a < 0) a = -a;
    if (b < 0) b = -b;
    while (b != 0) {
        const std::int64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

constexpr rational make_rational(std::int64_t num, std::int64_t den = 1) {
    if (den < 0) { num = -num; den = -den; }
    const std::int64_t g = gcd(num, den);
    return g > 1 ? rational{num / g, den / g} : rational{num, den};
}

constexpr rational operator*(const rational& a, const rational& b) {
    if (a.den == 1 && b.den == 1) return {a.num * b.num, 1};
    return make_rational(a.num * b.num, a.den * b.den);
}
constexpr rational operator+(const rational& a, const rational& b) {
    if (a.den == b.den) return make_rational(a.num + b.num, a.den);
    return make_rational(a.num * b.den + b.num * a.den, a.den * b.den);
}
constexpr rational operator-(const rational& a) { return {-a.num, a.den}; }

constexpr bool is_zero(const rational& a) { return a.num == 0; }
constexpr bool is_unit(const rational& a) { return a.den == 1 && (a.num == 1 || a.num == -1); }

}  // namespace ctga::expr
