// A string usable as a template argument (C++20 class-type NTTP), so that blade and
// generator names written in the paper's spelling ("e3e1", "a1a2a3a") can name types.
#pragma once

#include <cstddef>
#include <string_view>

namespace ctga {

template <std::size_t N>
struct fixed_string {
    char chars[N]{};  // includes the terminating '\0'

    constexpr fixed_string() noexcept = default;
    constexpr fixed_string(const char (&s)[N]) noexcept {
        for (std::size_t i = 0; i < N; ++i) chars[i] = s[i];
    }
    [[nodiscard]] constexpr std::string_view view() const noexcept { return {chars, N - 1}; }
    [[nodiscard]] constexpr std::size_t size() const noexcept { return N - 1; }
};

}  // namespace ctga
