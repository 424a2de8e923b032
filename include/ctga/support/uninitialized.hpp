// ctga::uninitialized: storage every element of which is written before it is read, such as the
// per-body values of a kinematic tree's passes (chains/passes.hpp: each body's velocity is
// set from its parent's before any child reads it). A multivector is zero when default
// constructed; constructed from this tag it is left as it is, so that an array of them costs
// no clearing (for the 7-body arm's RNEA that clearing was 2 KB of stores per call).
// Reading such an element before writing it is a bug; in a constant expression the compiler
// rejects it.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

namespace ctga {

struct uninitialized_t {
    explicit uninitialized_t() = default;
};
inline constexpr uninitialized_t uninitialized{};

// std::array<V, N> of V(uninitialized) elements (each a prvalue: nothing is copied).
template <class V, std::size_t N>
    requires std::is_constructible_v<V, uninitialized_t>
[[nodiscard]] constexpr std::array<V, N> uninitialized_array() noexcept {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<V, N>{((void)I, V(uninitialized))...};
    }(std::make_index_sequence<N>{});
}

}  // namespace ctga
