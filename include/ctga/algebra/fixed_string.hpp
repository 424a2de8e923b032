// A string usable as a template argument (C++20 class-type NTTP), so that blade and
// generator names written in the paper's spelling ("e3e1", "a1a2a3a") can name types; and how a
// compile error names a problem (a blade, a frame, an argument) in its first lines.
#pragma once

#include <cstddef>
#include <string_view>
#include <utility>

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

// A misuse the types can see is reported by instantiating a class template named for the
// problem, its details as its template arguments, whose static_assert(reported<itself>, "…")
// fails: GCC's first line is then "In instantiation of 'struct problem<details>'", Clang's the
// failed requirement 'reported<problem<details>>', whatever the depth of the call.
template <class Problem>
inline constexpr bool reported = false;

// A name as a problem's arguments, character by character: spelt<problem, "tool0"> is
// problem<'t', 'o', 'o', 'l', '0'>, which GCC and Clang print as text (Clang prints a fixed_string
// argument as its character codes).
namespace fixed_string_detail {
template <template <char...> class Problem, fixed_string Name, std::size_t... I>
auto spell(std::index_sequence<I...>) -> Problem<Name.chars[I]...>;
}  // namespace fixed_string_detail
template <template <char...> class Problem, fixed_string Name>
using spelt = decltype(fixed_string_detail::spell<Problem, Name>(std::make_index_sequence<Name.size()>{}));

}  // namespace ctga
