// Basis blades as bitmasks. Bit i set means generator i (in the algebra's declared order)
// is a factor; the canonical orientation of a blade is its generators in ascending order.
// These rules are metric-free; the metric (generator squares) enters only in rules.hpp.
#pragma once

#include <bit>
#include <cstdint>

namespace ctga {

using blade_mask = std::uint32_t;

// A basis blade with a sign: sign * (canonical blade `mask`). sign == 0 means "zero".
struct signed_blade {
    blade_mask mask = 0;
    int sign = 0;
    friend constexpr bool operator==(signed_blade, signed_blade) = default;
};

[[nodiscard]] constexpr int blade_grade(blade_mask m) noexcept { return std::popcount(m); }

// Bit j of parity_above(a) is the parity of a's generators above j (a prefix-xor from the top);
// bit j of parity_below(a), of those below j.
[[nodiscard]] constexpr blade_mask parity_above(blade_mask a) noexcept {
    blade_mask p = a >> 1;
    p ^= p >> 1;
    p ^= p >> 2;
    p ^= p >> 4;
    p ^= p >> 8;
    p ^= p >> 16;
    return p;
}
[[nodiscard]] constexpr blade_mask parity_below(blade_mask a) noexcept {
    blade_mask p = a << 1;
    p ^= p << 1;
    p ^= p << 2;
    p ^= p << 4;
    p ^= p << 8;
    p ^= p << 16;
    return p;
}

// Sign of the permutation that sorts the word (generators of a ascending, then generators of
// b ascending) into ascending order: (-1)^(number of pairs i in a, j in b with i > j), the
// parity of b's bits where parity_above(a) is set. For disjoint a, b this is the sign in
// a ∧ b = reorder_sign(a, b) · (a|b).
[[nodiscard]] constexpr int reorder_sign(blade_mask a, blade_mask b) noexcept {
    return (std::popcount(parity_above(a) & b) & 1) ? -1 : 1;
}

// Outcome of reading a blade name such as "e3e1" or "a1a2a3a" (algebra::parse_blade).
enum class blade_name_status { ok, unknown_generator, repeated_generator };

struct parsed_blade {
    blade_name_status status = blade_name_status::ok;
    blade_mask mask = 0;
    int sign = 1;  // the written order's orientation relative to the canonical one
};

// Signs of the grade-dependent involutions of a grade-k blade.
[[nodiscard]] constexpr int reverse_sign(int k) noexcept { return ((k * (k - 1) / 2) & 1) ? -1 : 1; }
[[nodiscard]] constexpr int involute_sign(int k) noexcept { return (k & 1) ? -1 : 1; }
[[nodiscard]] constexpr int conjugate_sign(int k) noexcept { return ((k * (k + 1) / 2) & 1) ? -1 : 1; }

}  // namespace ctga
