// ctga::algebra<"names", squares...>: a Clifford algebra Cl(p,q,r) given by the ordered list of
// its generators' names and squares (+1, -1 or 0). The order is the basis order: it fixes the
// canonical orientation of every blade and the determinant of the shuffle product (paper §4).
//
//   using cl062 = ctga::algebra<"a1 a2 a3 a e1 e2 e3 e", -1, -1, -1, 0, -1, -1, -1, 0>;
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "ctga/algebra/blade.hpp"
#include "ctga/algebra/fixed_string.hpp"
#include "ctga/algebra/layout.hpp"
#include "ctga/algebra/multivector.hpp"

namespace ctga {

inline constexpr std::size_t max_generators = 16;

namespace detail {

constexpr bool is_name_char(char c) noexcept {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// Generator names split out of a space-separated list.
template <std::size_t N>
struct generator_names {
    std::array<std::string_view, N> names{};
    std::size_t count = 0;   // how many names the list holds (may differ from N: checked)
    bool well_formed = true; // only letters, digits, '_' and separating spaces
};

template <std::size_t N, std::size_t L>
constexpr generator_names<N> split_names(const fixed_string<L>& list) {
    generator_names<N> out;
    const std::string_view s = list.view();
    std::size_t i = 0;
    while (i < s.size()) {
        if (s[i] == ' ') { ++i; continue; }
        std::size_t j = i;
        while (j < s.size() && s[j] != ' ') {
            if (!is_name_char(s[j])) out.well_formed = false;
            ++j;
        }
        if (out.count < N) out.names[out.count] = s.substr(i, j - i);
        ++out.count;
        i = j;
    }
    return out;
}

template <std::size_t N>
constexpr bool names_unique(const generator_names<N>& g) {
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = i + 1; j < N; ++j)
            if (g.names[i] == g.names[j]) return false;
    return true;
}

}  // namespace detail

template <fixed_string Names, int... Squares>
struct algebra {
    static constexpr std::size_t dimension = sizeof...(Squares);
    static constexpr std::array<int, dimension> squares{Squares...};
    static constexpr std::size_t blade_count = std::size_t{1} << dimension;
    static constexpr blade_mask pseudoscalar_mask = static_cast<blade_mask>(blade_count - 1);
    // the generators squaring to 0 and to −1, as blade masks (rules.hpp reads the metric here)
    static constexpr blade_mask null_mask = [] {
        blade_mask m = 0;
        for (std::size_t i = 0; i < dimension; ++i) m |= squares[i] == 0 ? blade_mask{1} << i : 0;
        return m;
    }();
    static constexpr blade_mask negative_mask = [] {
        blade_mask m = 0;
        for (std::size_t i = 0; i < dimension; ++i) m |= squares[i] < 0 ? blade_mask{1} << i : 0;
        return m;
    }();

    static_assert(dimension >= 1, "ctga::algebra: an algebra needs at least one generator");
    static_assert(dimension <= max_generators, "ctga::algebra: at most 16 generators are supported");
    static_assert(((Squares == 1 || Squares == -1 || Squares == 0) && ...),
                  "ctga::algebra: every generator square must be +1, -1 or 0");

private:
    static constexpr auto split = detail::split_names<dimension>(Names);
    static_assert(split.well_formed,
                  "ctga::algebra: generator names may hold only letters, digits and '_', separated by spaces");
    static_assert(split.count == dimension,
                  "ctga::algebra: the number of generator names differs from the number of squares");
    static_assert(detail::names_unique(split), "ctga::algebra: two generators have the same name");

    template <std::size_t N>
    using layout_type = layout<N>;

public:
    [[nodiscard]] static constexpr std::string_view generator_name(std::size_t i) noexcept { return split.names[i]; }
    [[nodiscard]] static constexpr int square(std::size_t i) noexcept { return squares[i]; }

    // The multivector type storing exactly the named blades, in that order and orientation:
    //   using screw = cl031::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
    template <class T, fixed_string... BladeNames>
    using mv = multivector<algebra, T, detail::named_layout_of<algebra, BladeNames...>::value>;

    // coef · (the named blade, orientation as written): blade<"e3e1">(2.0) is −2 e1e3.
    template <fixed_string Name, class T = double>
    [[nodiscard]] static constexpr mv<T, Name> blade(T coef = T(1)) noexcept {
        return mv<T, Name>{coef};
    }

    // The named blade as an exact compile-time constant (coefficient 1, orientation as written):
    // the paper's invariants A = basis<"a1a2a3a">, E = basis<"e1e2e3e">. Products with it cost
    // no multiplication.
    template <fixed_string Name>
    static constexpr basis_blade<algebra, Name> basis{};

    // Generator I (0-based, in the declared order) as a grade-1 multivector.
    template <std::size_t I, class T = double>
    [[nodiscard]] static constexpr auto generator(T coef = T(1)) noexcept {
        static_assert(I < dimension, "ctga: generator index out of range for this algebra");
        if constexpr (I < dimension) {
            constexpr auto l = [] {
                layout_type<1> out;
                out.masks[0] = blade_mask{1} << I;
                out.signs[0] = 1;
                return out;
            }();
            return multivector<algebra, T, l>{coef};
        }
    }

    // Characters of the canonical name of a blade ("1" for the scalar), written through `put`.
    template <class Put>
    static constexpr void write_blade_name(blade_mask m, Put put) {
        if (m == 0) { put('1'); return; }
        for (std::size_t g = 0; g < dimension; ++g)
            if (m >> g & 1u)
                for (char c : split.names[g]) put(c);
    }
    [[nodiscard]] static constexpr std::size_t blade_name_size(blade_mask m) {
        std::size_t n = 0;
        write_blade_name(m, [&](char) { ++n; });
        return n;
    }

    // Read a blade written as a product of distinct generators, e.g. "e3e1" = -e1e3.
    // Generators are matched longest first, so "e10" is one generator when the algebra has one
    // named so. "1" (or "") is the scalar.
    [[nodiscard]] static constexpr parsed_blade parse_blade(std::string_view w) noexcept {
        parsed_blade out;
        if (w == "1") return out;
        std::size_t pos = 0;
        while (pos < w.size()) {
            std::size_t best = dimension, best_len = 0;
            for (std::size_t g = 0; g < dimension; ++g) {
                const auto n = split.names[g];
                if (n.size() > best_len && w.substr(pos, n.size()) == n) { best = g; best_len = n.size(); }
            }
            if (best == dimension) { out.status = blade_name_status::unknown_generator; return out; }
            const blade_mask bit = blade_mask{1} << best;
            if (out.mask & bit) { out.status = blade_name_status::repeated_generator; return out; }
            // appending generator `best` to the right of the blade read so far
            out.sign *= reorder_sign(out.mask, bit);
            out.mask |= bit;
            pos += best_len;
        }
        return out;
    }
};

}  // namespace ctga
