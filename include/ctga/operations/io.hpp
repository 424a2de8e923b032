// Printing with blade names: 3*a2a3 + 2*e1e. A component stored with the opposite orientation
// (a screw's e3e1) is printed under a name of that orientation: for grade ≥ 2 the first two
// generators of the canonical name are swapped (e1e3 → e3e1), which spells −e1e3.
#pragma once

#include <cstddef>
#include <ostream>
#include <type_traits>

#include "ctga/algebra/multivector.hpp"
#include "ctga/operations/evaluate.hpp"

namespace ctga {

template <class Alg, class T, auto L>
std::ostream& operator<<(std::ostream& os, const multivector<Alg, T, L>& x) {
    bool first = true;
    for (std::size_t i = 0; i < L.size(); ++i) {
        T c = x[i];
        const blade_mask m = L.masks[i];
        const bool swapped = L.signs[i] < 0 && blade_grade(m) >= 2;
        if (L.signs[i] < 0 && !swapped) c = -c;
        if constexpr (std::is_arithmetic_v<T>) {
            if (c == T{}) continue;
            const bool negative = c < T{};
            os << (first ? (negative ? "-" : "") : (negative ? " - " : " + ")) << (negative ? -c : c);
        } else {
            os << (first ? "" : " + ") << '(' << c << ')';
        }
        first = false;
        if (m == 0) continue;  // the scalar: its coefficient alone
        os << '*';
        if (!swapped) {
            Alg::write_blade_name(m, [&](char ch) { os << ch; });
        } else {
            // write generator 2, then generator 1, then the rest
            std::size_t g1 = Alg::dimension, g2 = Alg::dimension;
            for (std::size_t g = 0; g < Alg::dimension; ++g)
                if (m >> g & 1u) { if (g1 == Alg::dimension) g1 = g; else if (g2 == Alg::dimension) g2 = g; }
            os << Alg::generator_name(g2) << Alg::generator_name(g1);
            for (std::size_t g = g2 + 1; g < Alg::dimension; ++g)
                if (m >> g & 1u) os << Alg::generator_name(g);
        }
    }
    if (first) os << '0';
    return os;
}

// An expression prints as its value.
template <class Alg, class T, class Node, class Leaves>
std::ostream& operator<<(std::ostream& os, const expression<Alg, T, Node, Leaves>& e) {
    return os << eval(e);
}

}  // namespace ctga
