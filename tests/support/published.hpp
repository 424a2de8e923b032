// The operation counts the documentation prints, as the tests assert them.
//
// README.md, docs/design.md, docs/engine.md and docs/mechanics.md print counts as "24m 18a" (or
// "42m" alone). Each such figure is written in a test as
//   static_assert(ctga::cost_of<E> == published<24, 18>);        // the engine's price of E
//   CHECK(counted([&] { ... }) == published<24, 18>);             // arithmetic counted on a scalar
//   static_assert(ctga::cost_of<E>.mul == published_mul<42>);
// or, for a figure quoted from elsewhere (another library's or a book's count, which no test of
// ours can measure), as cited<38, 37> beside the source it comes from. tests/docs/check_docs.py
// (CTest: docs.published_counts) reads every published<…>, published_mul<…> and cited<…> in
// tests/ and fails when the documents print a count that is not among them.
#pragma once

#include <cstddef>

#include <ctga/expr/normal_form.hpp>

namespace ctga::test {

template <std::size_t Mul, std::size_t Add>
inline constexpr expr::cost published{Mul, Add};
template <std::size_t Mul>
inline constexpr std::size_t published_mul = Mul;
template <std::size_t Mul, std::size_t Add = 0>
inline constexpr expr::cost cited{Mul, Add};

}  // namespace ctga::test
