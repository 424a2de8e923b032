// Self-test of support/dual.hpp, independent of ctga and Catch2: the partials of dual<3> agree with hand-derived
// derivatives (relative difference ≤ 1e-14) and with central finite differences (≤ 1e-7) on a handful of functions,
// and constexpr evaluation gives exact derivatives. Exit status 0 when every check passes; each failure is printed.
#include "support/dual.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace {

using D = ctga_test::dual<3>;
using P = std::array<double, 3>;

// |a − b| / max(1, |b|).
double rel(double a, double b) { return std::abs(a - b) / std::max(1.0, std::abs(b)); }

int failures = 0;

void check(bool ok, const char* name, const char* what) {
    if (!ok) {
        ++failures;
        std::printf("FAIL %s: %s\n", name, what);
    }
}

// f is called as f(x, y, z) with doubles and with duals; fv and grad are its hand-derived value and gradient at p.
template <class F>
void check_function(const char* name, F f, P p, double fv, P grad) {
    const D x = D::variable(p[0], 0), y = D::variable(p[1], 1), z = D::variable(p[2], 2);
    const D r = f(x, y, z);
    const double plain = f(p[0], p[1], p[2]);

    double e_hand = rel(ctga_test::value(r), fv), e_fd = 0;
    e_hand = std::max(e_hand, rel(ctga_test::value(r), plain));
    for (std::size_t k = 0; k < 3; ++k) {
        e_hand = std::max(e_hand, rel(ctga_test::derivative(r, k), grad[k]));
        const double h = 1e-5 * std::max(1.0, std::abs(p[k]));
        P a = p, b = p;
        a[k] += h;
        b[k] -= h;
        const double fd = (f(a[0], a[1], a[2]) - f(b[0], b[1], b[2])) / (2 * h);
        e_fd = std::max(e_fd, rel(ctga_test::derivative(r, k), fd));
    }
    const bool ok = e_hand <= 1e-14 && e_fd <= 1e-7 && isfinite(r) && !isnan(r);
    std::printf("%s %-28s hand %.2e  finite-difference %.2e\n", ok ? "ok  " : "FAIL", name, e_hand, e_fd);
    if (!ok) ++failures;
}

// Compile-time checks.
constexpr auto cube_at_2 = [] {
    const auto x = ctga_test::dual<1>::variable(2.0, 0);
    return x * x * x;
}();
static_assert(cube_at_2.v == 8.0 && cube_at_2.d[0] == 12.0);

// Product rule: (f g)' = f' g + f g' with f = x² + 3y, g = 2x − y at (1.5, −0.25); every value is exact in binary.
constexpr bool product_rule() {
    using E = ctga_test::dual<2>;
    const E x = E::variable(1.5, 0), y = E::variable(-0.25, 1);
    const E f = x * x + 3 * y, g = 2 * x - y;
    const E fg = f * g;
    for (std::size_t k = 0; k < 2; ++k)
        if (fg.d[k] != f.d[k] * g.v + f.v * g.d[k]) return false;
    return fg.v == f.v * g.v && fg.d[0] == (2 * 1.5) * (2 * 1.5 + 0.25) + (1.5 * 1.5 - 0.75) * 2;
}
static_assert(product_rule());

// Quotient and constant-on-the-left rules, exact in binary: d/dx (1 / x) = −1 / x², d/dx (x / 4) = 1/4.
constexpr bool quotient_rule() {
    using E = ctga_test::dual<1>;
    const E x = E::variable(2.0, 0);
    const E a = 1.0 / x, b = x / 4, c = (x + 1) / (x - 1);  // c' = −2 / (x − 1)²
    return a.v == 0.5 && a.d[0] == -0.25 && b.d[0] == 0.25 && c.v == 3 && c.d[0] == -2;
}
static_assert(quotient_rule());

// Constructors, comparisons and limits.
static_assert(D(0).v == 0 && D(1).v == 1 && static_cast<D>(2).v == 2 && D(0.5f).v == 0.5 && D().d[2] == 0);
static_assert(D(2) == 2 && 2 == D(2) && D(2) != 3 && 3 != D(2) && D(1) < D(2) && D(1) < 2 && 2 > D(1));
static_assert(D(1) <= 1.0 && 1.0f >= D(1) && (D(1) <=> 2) < 0 && (D::variable(3, 1) == D(3)));
static_assert(std::numeric_limits<D>::is_specialized && std::numeric_limits<D>::digits == 53);
static_assert(std::numeric_limits<D>::epsilon() == std::numeric_limits<double>::epsilon());
static_assert(std::numeric_limits<D>::lowest() == -std::numeric_limits<double>::max());
static_assert(ctga_test::abs(D::variable(-2, 0)).d[0] == -1 && ctga_test::abs(D::variable(-2, 0)) == 2);

constexpr bool compound() {
    D x = D::variable(3, 0);
    D y = x;
    y += 1;      // x + 1
    y *= x;      // x² + x
    y -= 2.0;    // x² + x − 2
    y /= 2;      // (x² + x − 2) / 2, derivative (2x + 1) / 2
    y = -y + +y * 2;
    return y.v == 5 && y.d[0] == 3.5 && y.d[1] == 0;
}
static_assert(compound());

}  // namespace

int main() {
    using std::atan2;
    using std::cos;
    using std::exp;
    using std::hypot;
    using std::log;
    using std::pow;
    using std::sin;
    using std::sqrt;

    const P p{1.3, -0.7, 2.1};
    const double x = p[0], y = p[1], z = p[2];

    check_function(
        "polynomial x2y+3yz3-2xz+5",
        [](auto a, auto b, auto c) { return a * a * b + 3 * b * c * c * c - 2 * a * c + 5; }, p,
        x * x * y + 3 * y * z * z * z - 2 * x * z + 5,
        {2 * x * y - 2 * z, x * x + 3 * z * z * z, 9 * y * z * z - 2 * x});
    check_function(
        "polynomial (x+y+z)^3 - xyz",
        [](auto a, auto b, auto c) { return (a + b + c) * (a + b + c) * (a + b + c) - a * b * c; }, p,
        (x + y + z) * (x + y + z) * (x + y + z) - x * y * z,
        {3 * (x + y + z) * (x + y + z) - y * z, 3 * (x + y + z) * (x + y + z) - x * z,
         3 * (x + y + z) * (x + y + z) - x * y});
    check_function("x/y", [](auto a, auto b, auto) { return a / b; }, p, x / y, {1 / y, -x / (y * y), 0});
    check_function(
        "sqrt(x*x+y*y)", [](auto a, auto b, auto) { return sqrt(a * a + b * b); }, p, sqrt(x * x + y * y),
        {x / sqrt(x * x + y * y), y / sqrt(x * x + y * y), 0});
    check_function(
        "hypot(x, z)", [](auto a, auto, auto c) { return hypot(a, c); }, p, hypot(x, z),
        {x / hypot(x, z), 0, z / hypot(x, z)});
    check_function(
        "sin(x)*exp(y)", [](auto a, auto b, auto) { return sin(a) * exp(b); }, p, sin(x) * exp(y),
        {cos(x) * exp(y), sin(x) * exp(y), 0});
    check_function(
        "cos(z)*log(x)", [](auto a, auto, auto c) { return cos(c) * log(a); }, p, cos(z) * log(x),
        {cos(z) / x, 0, -sin(z) * log(x)});
    check_function(
        "atan2(y, x)", [](auto a, auto b, auto) { return atan2(b, a); }, p, atan2(y, x),
        {-y / (x * x + y * y), x / (x * x + y * y), 0});
    check_function(
        "pow(x, 3.5)", [](auto a, auto, auto) { return pow(a, 3.5); }, p, pow(x, 3.5), {3.5 * pow(x, 2.5), 0, 0});
    check_function(
        "pow(z, 2) + pow(x, 0)", [](auto a, auto, auto c) { return pow(c, 2) + pow(a, 0); }, p, z * z + 1,
        {0, 0, 2 * z});
    check_function(
        "|y| * z", [](auto, auto b, auto c) { using std::abs; return abs(b) * c; }, p, -y * z, {0, -z, -y});
    // Mixed constants: int, unsigned, float and double on either side of every operator.
    check_function(
        "mixed constants",
        [](auto a, auto b, auto c) {
            auto r = 2 * a + a * 0.5 - 1.0 / a + 3 - b / 4 + (a + 1) * (2 - b) + 0.5f * c - c / 2u;
            r += 1;
            r -= 0.25 * b;
            r *= 2;
            r /= 4.0;
            return r;
        },
        p,
        (2 * x + 0.5 * x - 1.0 / x + 3 - y / 4 + (x + 1) * (2 - y) + 0.5 * z - z / 2 + 1 - 0.25 * y) / 2,
        {(2.5 + 1 / (x * x) + (2 - y)) / 2, (-0.25 - (x + 1) - 0.25) / 2, 0});

    // Runtime edge cases.
    const D zero = D::variable(0.0, 0);
    // d/dx √x at 0 is +inf; the other partials are inf · 0 = NaN, as the chain rule gives.
    check(sqrt(zero).v == 0 && std::isinf(sqrt(zero).d[0]) && sqrt(zero).d[0] > 0, "sqrt(0)", "d/dx should be +inf");
    check(!isfinite(sqrt(zero)) && isnan(sqrt(zero)), "sqrt(0)", "should be non-finite with NaN partials");
    check(isnan(D(std::numeric_limits<D>::quiet_NaN())), "quiet_NaN", "should be NaN");
    check(!isfinite(std::numeric_limits<D>::infinity()), "infinity", "should not be finite");
    check(isfinite(D::variable(1.0, 2)), "isfinite", "a finite variable");

    if (failures == 0) std::printf("all dual self-tests passed\n");
    else std::printf("%d dual self-test(s) failed\n", failures);
    return failures == 0 ? 0 : 1;
}
