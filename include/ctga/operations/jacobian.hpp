// Exact Jacobians of formulas, at compile time.
//
// A formula's value is a polynomial in its arguments' components (every node of the engine is
// one, expr/derivative.hpp), and the engine evaluates it as a straight-line program of sums of
// monomials. ctga::jacobian differentiates that program by the chain rule along its assignments
// (expr/differentiate.hpp): one program computes every column (one per component of the chosen
// argument), the value's temporaries shared by all, and an entry whose derivative has no terms is
// a structural zero. Where the value loops a product (expr/looped.hpp), whose result the program
// reads as a leaf, each column is instead the differentiated expression tree (expr::derive_t,
// its products re-associated so that the factors free of the column multiply once), the looped
// products the columns read computed once for all of them, and each column's rows from its own
// normal form:
//
//   auto J = ctga::jacobian<1>(ctga::momentum.formula, N, s);       // ∂P/∂s: 6 × 6, N's pattern
//   double x = J(r, c);                                              // ∂ out[r] / ∂ s[c]
//   auto rows = J.dense();                                           // row-major std::array
//   constexpr auto price = ctga::cost_of<decltype(J)>;              // what it runs
//
// Rows are the components of the value in its canonical layout, or of a Target multivector type
// (jacobian<K, Target>: its order and orientation, e.g. a screw's (ω, v)); columns the
// components of argument K in its own type's order, or, for a parametrised argument such as
// body_inertia, its parameters in parameters() order. The pattern (which (row, column) entries
// can be non-zero for some input) is a compile-time constant of the result's type; only those
// entries are stored and computed.
//
// Only formulas are differentiated: the non-polynomial steps of the library (a division by a
// scalar, sqrt, exp and log of screws, renormalisation) are functions outside formulas and have
// no derivative here; jacobian() of anything but a formula or an operation is a compile error.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

#include "ctga/expr/derivative.hpp"
#include "ctga/expr/differentiate.hpp"
#include "ctga/expr/run.hpp"
#include "ctga/expr/shared_units.hpp"
#include "ctga/operations/formula.hpp"
#include "ctga/support/inline.hpp"

namespace ctga {

// Which (row, column) entries of a Jacobian are structurally non-zero, column by column.
template <std::size_t Rows, std::size_t Cols, std::size_t NonZeros>
struct jacobian_pattern {
    std::array<std::uint16_t, NonZeros> row{};
    std::array<std::uint16_t, NonZeros> col{};
    std::array<std::uint32_t, Cols + 1> col_begin{};  // column c's entries: [col_begin[c], col_begin[c + 1])

    static constexpr std::size_t rows = Rows, cols = Cols, non_zeros = NonZeros;
    // the entry's index in the values, −1 when (r, c) is a structural zero
    [[nodiscard]] constexpr int index(std::size_t r, std::size_t c) const noexcept {
        for (std::size_t k = col_begin[c]; k < col_begin[c + 1]; ++k)
            if (row[k] == r) return static_cast<int>(k);
        return -1;
    }
};

// A Jacobian with the compile-time Pattern: the values of its structurally non-zero entries.
template <class T, auto Pattern, expr::cost Price>
struct sparse_jacobian {
    using scalar_type = T;
    static constexpr auto pattern = Pattern;
    static constexpr std::size_t rows = Pattern.rows, cols = Pattern.cols, non_zeros = Pattern.non_zeros;
    static constexpr expr::cost price = Price;

    std::array<T, non_zeros> values{};

    // ∂ out[r] / ∂ x[c] (zero where the pattern has no entry).
    [[nodiscard]] constexpr T operator()(std::size_t r, std::size_t c) const noexcept {
        const int k = Pattern.index(r, c);
        return k < 0 ? T(0) : values[static_cast<std::size_t>(k)];
    }
    [[nodiscard]] static constexpr bool structurally_nonzero(std::size_t r, std::size_t c) noexcept {
        return Pattern.index(r, c) >= 0;
    }
    // Row-major, every entry (for Eigen: Eigen::Map<const Eigen::Matrix<T, rows, cols, Eigen::RowMajor>>).
    [[nodiscard]] constexpr std::array<std::array<T, cols>, rows> dense() const noexcept {
        std::array<std::array<T, cols>, rows> out{};
        for (std::size_t c = 0; c < cols; ++c)
            for (std::size_t k = Pattern.col_begin[c]; k < Pattern.col_begin[c + 1]; ++k) out[Pattern.row[k]][c] = values[k];
        return out;
    }
};

namespace jacobian_detail {

// Column c of the Jacobian: component `comp` of leaf `leaf`.
struct column_source {
    std::size_t leaf, comp;
};

// The leaves and components of argument K of a formula taking Args.
template <std::size_t K, class... Args>
struct argument_columns {
    using A = std::remove_cvref_t<std::tuple_element_t<K, std::tuple<Args...>>>;
    static constexpr std::size_t first = expr::first_leaf<Args...>[K];
    static constexpr auto sizes = [] {
        if constexpr (expr::shape_of<A>::parametrised) {
            using P = typename expr::shape_of<A>::parameters;
            return [&]<std::size_t... J>(std::index_sequence<J...>) {
                return std::array<std::size_t, sizeof...(J)>{std::remove_cvref_t<std::tuple_element_t<J, P>>::size()...};
            }(std::make_index_sequence<std::tuple_size_v<P>>{});
        } else {
            return std::array<std::size_t, 1>{A::size()};
        }
    }();
    static constexpr std::size_t count = [] {
        std::size_t n = 0;
        for (std::size_t s : sizes) n += s;
        return n;
    }();
    static constexpr std::array<column_source, count> columns = [] {
        std::array<column_source, count> out{};
        std::size_t c = 0;
        for (std::size_t p = 0; p < sizes.size(); ++p)
            for (std::size_t j = 0; j < sizes[p]; ++j) out[c++] = {first + p, j};
        return out;
    }();
    // the same as factors of a program (program.hpp: leaf << leaf_shift | component)
    static constexpr std::array<std::uint32_t, count> factors = [] {
        std::array<std::uint32_t, count> out{};
        for (std::size_t c = 0; c < count; ++c)
            out[c] = static_cast<std::uint32_t>(columns[c].leaf << expr::leaf_shift | columns[c].comp);
        return out;
    }();
};

// The rows of RowLayout that column node D can make non-zero, as a layout in RowLayout's order
// and orientation, and where each sits in RowLayout.
template <auto RowLayout, class D>
struct column_rows {
    static constexpr auto value_layout = [] {
        if constexpr (expr::is_zero_node<D>) return expr::no_blades;
        else return expr::node_layout<D>;
    }();
    static constexpr std::size_t count = [] {
        std::size_t n = 0;
        for (std::size_t r = 0; r < RowLayout.size(); ++r) n += value_layout.contains(RowLayout.masks[r]);
        return n;
    }();
    static constexpr layout<count> rows = [] {
        layout<count> l;
        std::size_t k = 0;
        for (std::size_t r = 0; r < RowLayout.size(); ++r)
            if (value_layout.contains(RowLayout.masks[r])) l.masks[k] = RowLayout.masks[r], l.signs[k] = RowLayout.signs[r], ++k;
        return l;
    }();
    static constexpr std::array<std::uint16_t, count> index = [] {
        std::array<std::uint16_t, count> out{};
        std::size_t k = 0;
        for (std::size_t r = 0; r < RowLayout.size(); ++r)
            if (value_layout.contains(RowLayout.masks[r])) out[k++] = static_cast<std::uint16_t>(r);
        return out;
    }();
};

template <class Node, auto RowLayout, class Columns, std::size_t C>
using column_t = column_rows<RowLayout, expr::derive_t<Node, Columns::columns[C].leaf, Columns::columns[C].comp>>;

// Column C's entries of the pattern, from entry k on.
template <class Col, class Pattern>
constexpr std::size_t fill_column(Pattern& p, std::size_t k, std::size_t c) {
    p.col_begin[c] = static_cast<std::uint32_t>(k);
    for (std::size_t r = 0; r < Col::count; ++r, ++k) {
        p.row[k] = Col::index[r];
        p.col[k] = static_cast<std::uint16_t>(c);
    }
    return k;
}

// Up to this many terms a Jacobian's program is unrolled (expr::unroll_limit, 64, for other
// programs): all its columns are one program, so it is longer than a value's. ∂ṡ/∂s of the
// equations of motion is 306 terms: unrolled 88 ns, interpreted 0.9 µs, for 0.55 s more compile time.
inline constexpr std::size_t jacobian_unroll_limit = 512;

// A Jacobian from one differentiated tree per column (the value has looped products). The
// looped products, and their operands, that the columns read are computed once for all of them
// (expr/run.hpp, shared units: G N and N G* of the moved inertia, expr/derivative.hpp), then each
// column's own program.
template <class Node, auto RowLayout, class Columns, class Cs = std::make_index_sequence<Columns::count>>
struct by_columns;
template <class Node, auto RowLayout, class Columns, std::size_t... C>
struct by_columns<Node, RowLayout, Columns, std::index_sequence<C...>> {
    static constexpr std::size_t cols = Columns::count;
    static constexpr std::size_t non_zeros = (column_t<Node, RowLayout, Columns, C>::count + ... + 0);
    static constexpr auto pattern = [] {
        jacobian_pattern<RowLayout.size(), cols, non_zeros> p;
        std::size_t k = 0;
        ((k = fill_column<column_t<Node, RowLayout, Columns, C>>(p, k, C)), ...);
        p.col_begin[cols] = static_cast<std::uint32_t>(k);
        return p;
    }();

    template <std::size_t K>
    using tree = expr::derive_t<Node, Columns::columns[K].leaf, Columns::columns[K].comp>;
    template <std::size_t K>
    static constexpr auto column_units() {
        if constexpr (column_t<Node, RowLayout, Columns, K>::count == 0) return expr::type_list<>{};
        else return expr::root_units<tree<K>>();
    }
    using units = typename expr::unique_by_hash<decltype((expr::type_list<>{} + ... + column_units<C>()))>::type;

    // the shared units once, then each column's own work
    template <std::size_t K>
    static constexpr expr::cost column_price() {
        using col = column_t<Node, RowLayout, Columns, K>;
        if constexpr (col::count == 0) return expr::cost{};
        else return expr::root_price<tree<K>, col::rows>();
    }
    static constexpr expr::cost price = expr::units_price(units{}) + (column_price<C>() + ... + expr::cost{});

    template <std::size_t K, class J, class T, class Store>
    CTGA_ALWAYS_INLINE static constexpr void evaluate_column(J& out, const T* const* leaves, const Store& store) noexcept {
        using col = column_t<Node, RowLayout, Columns, K>;
        if constexpr (col::count > 0) {
            const auto v = expr::compute_from_units<T, units, tree<K>, col::rows, jacobian_unroll_limit>(leaves, store);
            for (std::size_t r = 0; r < col::count; ++r) out.values[J::pattern.col_begin[K] + r] = v[r];
        }
    }
    template <class J, class E>
    CTGA_ALWAYS_INLINE static constexpr void evaluate(J& out, const E& e) noexcept {
        using T = typename E::scalar_type;
        using store_type = typename expr::unit_store<T, units>::type;
        const auto leaves = e.template leaf_data<T>();
        store_type store{};
        expr::compute_units<T, units>(leaves.data(), store, std::make_index_sequence<std::tuple_size_v<store_type>>{});
        (evaluate_column<C>(out, leaves.data(), store), ...);
    }
};


// A Jacobian from the value's program differentiated (expr/differentiate.hpp): one program for
// all columns, sharing the value's temporaries.
template <class Program, class Columns>
struct by_program {
    using D = expr::program_jacobian<Program, Columns::factors>;
    static constexpr std::size_t non_zeros = D::non_zeros;
    static constexpr auto pattern = [] {
        jacobian_pattern<D::rows, Columns::count, non_zeros> p;
        for (std::size_t c = 0; c < Columns::count; ++c) {
            p.col_begin[c] = D::draft.column_begin[c];
            for (std::size_t k = D::draft.column_begin[c]; k < D::draft.column_begin[c + 1]; ++k) {
                p.row[k] = D::draft.row[k];
                p.col[k] = static_cast<std::uint16_t>(c);
            }
        }
        p.col_begin[Columns::count] = static_cast<std::uint32_t>(non_zeros);
        return p;
    }();
    static constexpr expr::cost price = D::price;

    template <class J, class E>
    CTGA_ALWAYS_INLINE static constexpr void evaluate(J& out, const E& e) noexcept {
        using T = typename E::scalar_type;
        if constexpr (non_zeros == 0) return;
        else if constexpr (D::terms.size() <= jacobian_unroll_limit) out.values = expr::run<T, D, non_zeros>(e.template leaf_data<T>().data());
        else out.values = expr::run_interpreted<T, D, non_zeros>(e.template leaf_data<T>().data());
    }
};

// Differentiate the program where it has no looped products, column by column where it has.
template <class Node, auto RowLayout, class Columns>
constexpr auto choose_method() {
    using P = expr::program<Node, RowLayout>;
    if constexpr (P::looped_count == 0) return by_program<P, Columns>{};
    else return by_columns<Node, RowLayout, Columns>{};
}
template <class Node, auto RowLayout, class Columns>
using method_t = decltype(choose_method<Node, RowLayout, Columns>());

// The rows: Target's layout, or the value's canonical one.
template <class E, class Target>
constexpr auto row_layout_of() {
    if constexpr (std::is_void_v<Target>) {
        return E::layout;
    } else {
        // the staged normal form's blades include the value's: where Target holds them all, the
        // value's own layout (a full expansion) is not needed
        using N = typename E::node_type;
        constexpr auto& staged = expr::traits<N>::terms;
        constexpr auto staged_layout = expr::output_layout<expr::distinct_outputs(staged)>(staged);
        if constexpr (detail::first_missing<staged_layout, Target::layout>() >= 0)
            static_assert(detail::first_missing<E::layout, Target::layout>() < 0,
                          "ctga::jacobian: the Target type lacks a blade the formula's value can make non-zero");
        return Target::layout;
    }
}


}  // namespace jacobian_detail

namespace jacobian_detail {
template <class X>
struct formula_of {
    static_assert(sizeof(X) == 0,
                  "ctga::jacobian: differentiates a formula (ctga::formula(...)) or an operation (its .formula): a "
                  "polynomial in its arguments; anything else (a division, sqrt, exp, log, renormalisation) has no "
                  "compile-time derivative");
};
template <class F>
struct formula_of<formula_t<F>> {
    static constexpr const formula_t<F>& get(const formula_t<F>& f) noexcept { return f; }
};
template <class F, class Finish>
struct formula_of<operation<F, Finish>> {
    static constexpr const formula_t<F>& get(const operation<F, Finish>& op) noexcept { return op.formula; }
};
}  // namespace jacobian_detail

// ∂ f(args...) / ∂ args[K]: the exact Jacobian, rows the value's components (canonical layout,
// or Target's), columns the components (or parameters) of argument K. See the top of this file.
template <std::size_t K, class Target = void, class F, formula_argument... Args>
[[nodiscard]] constexpr auto jacobian(const F& f, const Args&... args) noexcept {
    static_assert(K < sizeof...(Args), "ctga::jacobian: the formula has no argument K");
    using A = std::remove_cvref_t<std::tuple_element_t<K, std::tuple<Args...>>>;
    static_assert(multivector_type<A> || parametrised_operand<A>,
                  "ctga::jacobian: argument K must be a multivector or a parametrised argument (body_inertia, …)");
    const auto e = jacobian_detail::formula_of<F>::get(f)(args...);
    using E = std::remove_cvref_t<decltype(e)>;
    constexpr auto rows = jacobian_detail::row_layout_of<E, Target>();
    using columns = jacobian_detail::argument_columns<K, Args...>;
    using method = jacobian_detail::method_t<typename E::node_type, rows, columns>;
    sparse_jacobian<typename E::scalar_type, method::pattern, method::price> J;
    method::evaluate(J, e);
    return J;
}

}  // namespace ctga
