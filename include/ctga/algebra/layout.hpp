// A layout is the blade set of a multivector type: which basis blades it stores, in which
// order, and in which orientation. It is a structural literal type, so it can be a template
// argument: multivector<Alg, T, Layout> has the blade set in its type.
//
// Component i of a multivector with layout L holds the coefficient of signs[i] · (canonical
// blade masks[i]). Types written by the user keep the user's order and orientation (a screw's
// "e3e1" component is stored as written, with sign −1 against canonical e1e3); types computed
// by the library are canonical: ordered by (grade, mask), every sign +1.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "ctga/algebra/blade.hpp"
#include "ctga/algebra/fixed_string.hpp"

namespace ctga {

template <std::size_t N>
struct layout {
    std::array<blade_mask, N> masks{};
    std::array<signed char, N> signs{};

    [[nodiscard]] static constexpr std::size_t size() noexcept { return N; }

    // Index of the stored component for `mask`, or −1 when the blade is structurally zero.
    [[nodiscard]] constexpr int index_of(blade_mask mask) const noexcept {
        for (std::size_t i = 0; i < N; ++i)
            if (masks[i] == mask) return static_cast<int>(i);
        return -1;
    }
    [[nodiscard]] constexpr bool contains(blade_mask mask) const noexcept { return index_of(mask) >= 0; }
};

// The order of canonical layouts: by grade, then by mask.
[[nodiscard]] constexpr bool canonical_less(blade_mask a, blade_mask b) noexcept {
    return blade_grade(a) != blade_grade(b) ? blade_grade(a) < blade_grade(b) : a < b;
}

namespace detail {

constexpr void sort_unique_canonical(std::vector<blade_mask>& v) {
    std::sort(v.begin(), v.end(), canonical_less);
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

// The canonical layout of the blade set Source::masks() (any order, repeats allowed).
// Source::masks() is a constexpr function returning std::vector<blade_mask>; a constexpr vector
// cannot outlive the evaluation, so the size is computed first, then the array filled.
template <class Source>
constexpr auto canonical_layout() {
    constexpr std::size_t n = [] {
        auto v = Source::masks();
        sort_unique_canonical(v);
        return v.size();
    }();
    layout<n> out;
    auto v = Source::masks();
    sort_unique_canonical(v);
    for (std::size_t i = 0; i < n; ++i) {
        out.masks[i] = v[i];
        out.signs[i] = 1;
    }
    return out;
}

// Blade sets as types, to feed canonical_layout.
template <auto L1, auto L2>
struct union_of {
    static constexpr std::vector<blade_mask> masks() {
        std::vector<blade_mask> v(L1.masks.begin(), L1.masks.end());
        v.insert(v.end(), L2.masks.begin(), L2.masks.end());
        return v;
    }
};

}  // namespace detail

template <auto L1, auto L2>
inline constexpr auto layout_union = detail::canonical_layout<detail::union_of<L1, L2>>();

}  // namespace ctga
