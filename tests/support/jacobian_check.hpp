// What the Jacobian tests share (tests/jacobian_test.cpp, tests/jacobian_transform_test.cpp): random
// inputs, arguments as forward-mode dual numbers (tests/support/dual.hpp), and the comparison of
// ctga::jacobian against them. The dual numbers share nothing with the engine's differentiation.
// The compile-time pattern is checked both ways on random inputs: every entry outside it has an
// exactly zero dual derivative, and every entry in it is non-zero for some input (or, where the
// formula loops a product, only the first).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <random>
#include <tuple>
#include <utility>

#include <ctga/ctga.hpp>
#include <ctga/operations/jacobian.hpp>

#include "support/catch.hpp"
#include "support/dual.hpp"

namespace ctga_test::jacobians {

using namespace ctga;

template <std::size_t N>
using dual = ctga_test::dual<N>;

// ---- random inputs ---------------------------------------------------------------------------

struct random_source {
    std::mt19937_64 rng;
    double operator()() { return std::uniform_real_distribution<double>(-1.0, 1.0)(rng); }
};

template <class X>
X random_multivector(random_source& r) {
    X x;
    for (std::size_t i = 0; i < X::size(); ++i) x[i] = r();
    return x;
}
inline mass_properties<double> random_body(random_source& r) {
    const double m = 1.5 + r();
    const vec3<double> c{0.3 * r(), 0.3 * r(), 0.3 * r()};
    const double a = 1.0 + 0.2 * r(), b = 1.4 + 0.2 * r(), d = 1.9 + 0.2 * r();
    const double xy = 0.1 * r(), xz = 0.1 * r(), yz = 0.1 * r();
    auto p = make_mass_properties(m, c, mat3<double>{{{a, xy, xz}, {xy, b, yz}, {xz, yz, d}}});
    REQUIRE(p);
    return *p;
}

// ---- an argument in dual numbers: argument K's components (or parameters) seeded in order -----

template <std::size_t N, class X>
auto to_dual(const X& x, bool seed) {
    if constexpr (multivector_type<X>) {
        multivector<typename X::algebra_type, dual<N>, X::layout> out;
        for (std::size_t i = 0; i < X::size(); ++i) out[i] = seed ? dual<N>::variable(x[i], i) : dual<N>(x[i]);
        return out;
    } else {  // a parametrised argument: body_inertia<double> → body_inertia<dual<N>>
        using P = decltype(x.parameters());
        auto out = [&]<template <class> class Tpl>(const Tpl<double>*) { return Tpl<dual<N>>{}; }(&x);
        const auto dst = out.parameters();
        std::size_t k = 0;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (
                [&] {
                    const auto& from = std::get<I>(x.parameters());
                    auto& to = const_cast<std::remove_cvref_t<decltype(std::get<I>(dst))>&>(std::get<I>(dst));
                    for (std::size_t j = 0; j < from.size(); ++j, ++k)
                        to[j] = seed ? dual<N>::variable(from[j], k) : dual<N>(from[j]);
                }(),
                ...);
        }(std::make_index_sequence<std::tuple_size_v<P>>{});
        return out;
    }
}

template <class Target, class T>
using rebound = multivector<typename Target::algebra_type, T, Target::layout>;

// max |a − b| / max |b| over a Jacobian's entries.
struct comparison {
    double max_diff = 0, scale = 0;
    [[nodiscard]] double relative() const { return scale > 0 ? max_diff / scale : max_diff; }
};

// ∂f/∂args[K] exactly and by dual numbers; the pattern against the dual derivatives.
template <std::size_t K, class Target, class F, class... Args>
comparison against_dual(const F& f, std::array<std::array<bool, 64>, 64>& seen_nonzero, const Args&... args) {
    const auto J = jacobian<K, Target>(f, args...);
    constexpr std::size_t n = decltype(J)::cols;
    const auto dual_args = [&]<std::size_t... I>(std::index_sequence<I...>) {
        return std::make_tuple(to_dual<n>(args, I == K)...);
    }(std::index_sequence_for<Args...>{});
    const auto value = std::apply([&](const auto&... a) { return rebound<Target, dual<n>>(f(a...)); }, dual_args);
    comparison out;
    for (std::size_t r = 0; r < decltype(J)::rows; ++r)
        for (std::size_t c = 0; c < n; ++c) {
            const double exact = J(r, c), reference = value[r].d[c];
            if (!J.structurally_nonzero(r, c)) CHECK(reference == 0.0);  // the pattern misses nothing
            else if (exact != 0.0) seen_nonzero[r][c] = true;
            out.max_diff = std::max(out.max_diff, std::abs(exact - reference));
            out.scale = std::max(out.scale, std::abs(reference));
        }
    return out;
}

// Every entry of the pattern was non-zero for some input.
template <class J>
void pattern_is_tight(const std::array<std::array<bool, 64>, 64>& seen) {
    std::size_t never = 0;
    for (std::size_t r = 0; r < J::rows; ++r)
        for (std::size_t c = 0; c < J::cols; ++c)
            if (J::structurally_nonzero(r, c) && !seen[r][c]) ++never;
    CHECK(never == 0);
}

// Runs against_dual on `draws` random inputs made by make(); the worst relative difference.
// The pattern is tight unless the formula loops a product (a looped product's blades are all the
// pairs can reach: the cancellations between them are not seen, see the looped adjoint below).
enum class pattern_check { tight, covers };
template <std::size_t K, class Target, class F, class Make>
double check_formula(const F& f, Make make, pattern_check pattern = pattern_check::tight, int draws = 8) {
    std::array<std::array<bool, 64>, 64> seen{};
    double worst = 0;
    random_source r{std::mt19937_64{0x5eed + K}};
    using J = decltype(std::apply([&](const auto&... a) { return jacobian<K, Target>(f, a...); }, make(r)));
    for (int i = 0; i < draws; ++i) {
        const auto args = make(r);
        const comparison c = std::apply([&](const auto&... a) { return against_dual<K, Target>(f, seen, a...); }, args);
        worst = std::max(worst, c.relative());
    }
    if (pattern == pattern_check::tight) pattern_is_tight<J>(seen);
    return worst;
}

constexpr double dual_tolerance = 1e-14;

// The measured agreement, printed for the record, then checked.
inline bool within(const char* what, double relative, double tolerance) {
    std::printf("jacobian %-40s max |exact - dual| / max |dual| = %.2e\n", what, relative);
    return relative <= tolerance;
}

}  // namespace ctga_test::jacobians
