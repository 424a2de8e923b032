// Printing with blade names: a2a3 + 0.3*a3a - 2*e1e. A coefficient of 1 or −1 is written as
// its sign alone (the scalar keeps its number: 1, -1); a zero multivector is written 0; a scalar
// type that is not arithmetic is written (c)*name.
//
// Orientation: a layout keeps each blade's mask and sign, not the word it was declared with
// (declarations that differ only in the word are one type), so the word is chosen by a rule. A
// blade stored with sign −1 and grade ≥ 2 is written as its canonical name with the last two
// generators swapped: e1e3 → e3e1 (a screw), e0e2e3 → e0e3e2, e0e1e3 → e0e3e1, e0e1e2 → e0e2e1
// (a Cl(3,0,1) point). The rule is the same at grade ≥ 4; at every grade it reproduces exactly
// the declarations that are the canonical name with its last two generators swapped: a2ae3e1
// prints as declared, ee1e2e3 prints e1e2ee3, a3a1e2e prints a1a3ee2. A blade stored with
// sign +1 prints its canonical name, however it was declared (a3a1e3e1 prints a1a3e1e3).
//
// Only <iosfwd> is included: a stream is a std::basic_ostream, complete where the caller streams
// (the caller includes <ostream> or <iostream>), and <ostream> alone costs a translation unit
// ≈ 0.4 s to parse, a third of the whole mechanics header set.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <type_traits>

#include "ctga/algebra/multivector.hpp"
#include "ctga/operations/evaluate.hpp"

namespace ctga {

template <class Char, class Traits, class Alg, class T, auto L>
std::basic_ostream<Char, Traits>& operator<<(std::basic_ostream<Char, Traits>& os, const multivector<Alg, T, L>& x) {
    bool first = true;
    for (std::size_t i = 0; i < L.size(); ++i) {
        T c = x[i];
        const blade_mask m = L.masks[i];
        const bool swapped = L.signs[i] < 0 && blade_grade(m) >= 2;
        if (L.signs[i] < 0 && !swapped) c = -c;
        if constexpr (std::is_arithmetic_v<T>) {
            if (c == T{}) continue;
            const bool negative = c < T{};
            const T a = negative ? -c : c;
            os << (first ? (negative ? "-" : "") : (negative ? " - " : " + "));
            first = false;
            if (m == 0) { os << a; continue; }  // the scalar: its number alone
            if (a != T(1)) os << a << '*';
        } else {
            os << (first ? "" : " + ") << '(' << c << ')';
            first = false;
            if (m == 0) continue;
            os << '*';
        }
        if (!swapped) {
            Alg::write_blade_name(m, [&](char ch) { os << ch; });
        } else {
            // the canonical name with its last two generators g1 < g2 written as g2 g1
            std::size_t g1 = 0, g2 = 0;
            for (std::size_t g = 0; g < Alg::dimension; ++g)
                if (m >> g & 1u) { g1 = g2; g2 = g; }
            for (std::size_t g = 0; g < g1; ++g)
                if (m >> g & 1u) os << Alg::generator_name(g);
            os << Alg::generator_name(g2) << Alg::generator_name(g1);
        }
    }
    if (first) os << '0';
    return os;
}

// An expression prints as its value.
template <class Char, class Traits, class Alg, class T, class Node, class Leaves>
std::basic_ostream<Char, Traits>& operator<<(std::basic_ostream<Char, Traits>& os, const expression<Alg, T, Node, Leaves>& e) {
    return os << eval(e);
}

}  // namespace ctga
