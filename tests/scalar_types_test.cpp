// Scalars: float, long double and a user type (dual numbers, written here) through the same
// engine, checked against the dense reference in that type, and for duals against the product
// rule computed in double.
#include <ostream>
#include <random>

#include <ctga/ctga.hpp>
#include <ctga/reference/dense.hpp>

#include "support/catch.hpp"
#include "support/shapes.hpp"

namespace scalars {

// a + b ε with ε² = 0: the ε part of f(x + x′ε) is f′(x) x′. (A named namespace: Clang warns
// about hidden friends it cannot see used in an anonymous one.)
struct dual {
    double re = 0, eps = 0;
    constexpr dual() = default;
    constexpr dual(double r, double e = 0) : re(r), eps(e) {}
    friend constexpr dual operator+(dual a, dual b) { return {a.re + b.re, a.eps + b.eps}; }
    friend constexpr dual operator-(dual a, dual b) { return {a.re - b.re, a.eps - b.eps}; }
    friend constexpr dual operator-(dual a) { return {-a.re, -a.eps}; }
    friend constexpr dual operator*(dual a, dual b) { return {a.re * b.re, a.re * b.eps + a.eps * b.re}; }
    friend constexpr bool operator==(dual, dual) = default;
    friend std::ostream& operator<<(std::ostream& os, dual d) { return os << d.re << "+" << d.eps << "ε"; }
};

}  // namespace scalars

namespace {

using namespace ctga;
using scalars::dual;

template <class T>
using motor = cl031::mv<T, "1", "e2e3", "e3e1", "e1e2", "ee1e2e3", "e1e", "e2e", "e3e">;
template <class T>
using screw = cl031::mv<T, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;

template <class T>
double products_error(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const auto g = test::random_fill<motor<T>>(rng);
    const auto s = test::random_fill<screw<T>>(rng);
    const auto sandwich = eval(g * s * conj(g));
    const auto dg = dense::to_dense(g), ds = dense::to_dense(s);
    const auto expected = dense::gp(dense::gp(dg, ds), dense::conjugate(dg));
    return static_cast<double>(dense::max_abs_diff(dense::to_dense(sandwich), expected) / dense::max_abs(expected));
}

TEST_CASE("float, double and long double agree with the dense reference in their own type", "[scalars]") {
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        CHECK(products_error<float>(seed) <= 1e-6);
        CHECK(products_error<double>(seed) <= 1e-14);
        CHECK(products_error<long double>(seed) <= 1e-17);
    }
}

TEST_CASE("a user scalar type: dual numbers give the derivative of a motor sandwich", "[scalars]") {
    // g(t) = g0 + t g1, s(t) = s0 + t s1; d/dt (g s g*) at t = 0 is g1 s0 g0* + g0 s1 g0* + g0 s0 g1*
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
        const auto g0 = test::random_fill<motor<double>>(rng), g1 = test::random_fill<motor<double>>(rng);
        const auto s0 = test::random_fill<screw<double>>(rng), s1 = test::random_fill<screw<double>>(rng);
        motor<dual> g;
        screw<dual> s;
        for (std::size_t i = 0; i < g.size(); ++i) g[i] = dual(g0[i], g1[i]);
        for (std::size_t i = 0; i < s.size(); ++i) s[i] = dual(s0[i], s1[i]);
        const auto r = eval(g * s * conj(g));
        const auto value = eval(g0 * s0 * conj(g0));
        const auto derivative = eval(g1 * s0 * conj(g0) + g0 * s1 * conj(g0) + g0 * s0 * conj(g1));
        static_assert(decltype(r)::layout.masks == decltype(value)::layout.masks);
        for (std::size_t i = 0; i < r.size(); ++i) {
            CHECK(r[i].re == Approx(value[i]).margin(1e-14));
            const int j = derivative.layout.index_of(r.layout.masks[i]);
            CHECK(r[i].eps == Approx(j < 0 ? 0.0 : derivative[static_cast<std::size_t>(j)]).margin(1e-13));
        }
    }
    constexpr motor<dual> one{dual(1), dual(0), dual(0), dual(0), dual(0), dual(0), dual(0), dual(0)};
    static_assert((one * one) == one, "constexpr with a user scalar type");
}

}  // namespace
