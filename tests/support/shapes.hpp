// Blade sets ("shapes") for the property tests, chosen at compile time: a constexpr generator
// draws random blades and random orientations, so every test exercises non-canonical layouts.
#pragma once

#include <array>
#include <cstdint>
#include <random>

#include <ctga/ctga.hpp>

namespace ctga::test {

// SplitMix64: a tiny, good generator usable in constant expressions.
constexpr std::uint64_t splitmix(std::uint64_t& s) {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// K distinct random blades of Alg with random orientations.
template <class Alg, std::uint64_t Seed, std::size_t K>
constexpr layout<K> random_layout() {
    static_assert(K <= Alg::blade_count);
    layout<K> l;
    std::uint64_t s = Seed * 7919 + Alg::dimension;
    for (std::size_t i = 0; i < K;) {
        const auto m = static_cast<blade_mask>(splitmix(s) % Alg::blade_count);
        bool seen = false;
        for (std::size_t j = 0; j < i; ++j) seen |= l.masks[j] == m;
        if (seen) continue;
        l.masks[i] = m;
        l.signs[i] = (splitmix(s) & 1) ? 1 : -1;
        ++i;
    }
    return l;
}

template <class Alg>
constexpr std::size_t grade_size(int g) {
    std::size_t n = 0;
    for (blade_mask m = 0; m < Alg::blade_count; ++m) n += blade_grade(m) == g;
    return n;
}

// Every blade of grade G, canonical orientation.
template <class Alg, int G>
constexpr auto grade_layout() {
    layout<grade_size<Alg>(G)> l;
    std::size_t i = 0;
    for (blade_mask m = 0; m < Alg::blade_count; ++m)
        if (blade_grade(m) == G) { l.masks[i] = m; l.signs[i] = 1; ++i; }
    return l;
}

template <class Alg, std::uint64_t Seed, std::size_t K>
using random_mv = multivector<Alg, double, random_layout<Alg, Seed, K>()>;
template <class Alg, int G, class T = double>
using grade_mv = multivector<Alg, T, grade_layout<Alg, G>()>;

// Fill every stored component with a uniform random value in [-1, 1].
template <class X, class Rng>
X random_fill(Rng& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    X x;
    for (std::size_t i = 0; i < X::size(); ++i) x[i] = static_cast<typename X::scalar_type>(u(rng));
    return x;
}

}  // namespace ctga::test
