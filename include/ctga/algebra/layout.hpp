// A layout is the blade set of a multivector type: which basis blades it stores, in which
// order, and in which orientation. It is a structural literal type, so it can be a template
// argument: multivector<Alg, T, Layout> has the blade set in its type.
//
// Component i of a multivector with layout L holds the coefficient of signs[i] · (canonical
// blade masks[i]). Types written by the user keep the user's order and orientation (a screw's
// "e3e1" component is stored as written, with sign −1 against canonical e1e3); types computed
// by the library are canonical: ordered by (grade, mask), every sign +1.
#pragma once

#include <array>
#include <cstddef>

#include "ctga/algebra/blade.hpp"
#include "ctga/algebra/fixed_string.hpp"
#include "ctga/support/sort.hpp"

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

// The canonical layout of the union of two blade sets.
template <auto L1, auto L2>
constexpr auto union_size() {
    std::size_t n = L1.size();
    for (blade_mask m : L2.masks) n += !L1.contains(m);
    return n;
}

template <auto L1, auto L2>
constexpr auto make_union() {
    layout<union_size<L1, L2>()> out;
    std::size_t n = 0;
    for (blade_mask m : L1.masks) out.masks[n++] = m;
    for (blade_mask m : L2.masks)
        if (!L1.contains(m)) out.masks[n++] = m;
    merge_sort(out.masks.data(), out.masks.size(), canonical_less);
    for (auto& s : out.signs) s = 1;
    return out;
}

}  // namespace detail

template <auto L1, auto L2>
inline constexpr auto layout_union = detail::make_union<L1, L2>();

}  // namespace ctga
