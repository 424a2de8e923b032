// multivector<Alg, T, Layout>: the coefficients of exactly the blades of Layout, nothing else.
// The blade set is part of the type, so every expression's result type, and the code that
// computes it, can be worked out by the compiler.
//
// This header knows nothing of how values are computed. A multivector is filled from another
// blade set by copying (signs adjusted), or from any *component source*: a value that names its
// algebra, the blades it can make non-zero (`layout`) and, for a target layout, produces the
// target's components (`evaluate<T, Layout>()`). The expression engine's lazy expressions are
// component sources; so is anything else that keeps that contract.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "ctga/algebra/blade.hpp"
#include "ctga/algebra/fixed_string.hpp"
#include "ctga/algebra/layout.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga {

namespace detail {

// Reading the blade names of a multivector type, with a diagnostic naming the problem.
template <class Alg, fixed_string Name>
struct blade_of {
    static constexpr parsed_blade parsed = Alg::parse_blade(Name.view());
    static_assert(parsed.status != blade_name_status::unknown_generator,
                  "ctga: unknown blade name (one of its factors is not a generator of this algebra)");
    static_assert(parsed.status != blade_name_status::repeated_generator,
                  "ctga: a generator appears twice in a blade name");
    static constexpr blade_mask mask = parsed.mask;
    static constexpr int sign = parsed.sign;
};

template <std::size_t N>
constexpr bool all_distinct(const layout<N>& l) {
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = i + 1; j < N; ++j)
            if (l.masks[i] == l.masks[j]) return false;
    return true;
}

template <class Alg, fixed_string... Names>
struct named_layout_of {
    static constexpr auto value = [] {
        layout<sizeof...(Names)> l;
        std::size_t i = 0;
        ((l.masks[i] = blade_of<Alg, Names>::mask, l.signs[i] = static_cast<signed char>(blade_of<Alg, Names>::sign), ++i),
         ...);
        return l;
    }();
    static_assert(all_distinct(value), "ctga: a blade is listed twice in a multivector type");
};

// The canonical name of a blade as a template argument, so that a diagnostic can show it.
template <class Alg, blade_mask M>
constexpr auto blade_name_string() {
    fixed_string<Alg::blade_name_size(M) + 1> s;
    std::size_t k = 0;
    Alg::write_blade_name(M, [&](char c) { s.chars[k++] = c; });
    return s;
}

// Instantiated only to report a blade the target type cannot hold, its name spelt out
// (fixed_string.hpp): target_type_lacks_blade<'e', '1', 'e', '2', 'e', '3', 'e'>
template <char... Name>
struct target_type_lacks_blade {
    static_assert(reported<target_type_lacks_blade>,
                  "ctga: the target multivector type lacks a blade the source can make non-zero "
                  "(named in target_type_lacks_blade<...>). If an operand appears twice, as R in "
                  "R * x * reverse(R), each appearance is a leaf of its own and the terms that cancel "
                  "between them are not seen: use ctga::sandwich(R, x) or write it as a ctga::formula. "
                  "Otherwise add the blade to the type, or drop it on purpose with ctga::project");
};

template <class Alg, blade_mask M>
using target_lacks = spelt<target_type_lacks_blade, blade_name_string<Alg, M>()>;

// First blade of From that To lacks, as an index into From, or −1.
template <auto From, auto To>
constexpr int first_missing() {
    for (std::size_t i = 0; i < From.size(); ++i)
        if (!To.contains(From.masks[i])) return static_cast<int>(i);
    return -1;
}

struct from_components_t {};

}  // namespace detail

template <class Alg, class T, auto Layout>
class multivector;

// A value that can produce the components of any layout of algebra Alg's blades in scalar type
// T (void: an exact constant, any T), and names the blades it can make non-zero.
template <class S, class Alg, class T, auto Layout>
concept component_source = requires(const S& s) {
    requires std::is_same_v<typename S::algebra_type, Alg>;
    typename S::scalar_type;
    S::layout.size();
    { s.template evaluate<T, Layout>() } -> std::same_as<std::array<T, Layout.size()>>;
};

template <class Alg, class T, auto Layout>
class multivector {
public:
    using algebra_type = Alg;
    using scalar_type = T;
    static constexpr auto layout = Layout;

    [[nodiscard]] static constexpr std::size_t size() noexcept { return Layout.size(); }

    // Zero.
    constexpr multivector() noexcept : c_{} {}
    // Not initialised: for storage that is written before it is read (support/uninitialized.hpp).
    constexpr explicit multivector(uninitialized_t) noexcept {}

    // One coefficient per blade of the layout, in its order and orientation:
    //   cl031::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e"> s{wx, wy, wz, vx, vy, vz};
    // A lone non-scalar blade is constructed explicitly, so that a number never silently
    // becomes a bivector; a lone scalar converts implicitly.
    template <class... U>
        requires(sizeof...(U) == size() && size() > 0 && (std::convertible_to<U, T> && ...))
    constexpr explicit(size() == 1 && Layout.masks[0] != 0) multivector(U... v) noexcept
        : c_{static_cast<T>(v)...} {}

    constexpr multivector(detail::from_components_t, const std::array<T, size()>& c) noexcept : c_(c) {}

    // From another blade set of the same algebra: every blade of the source must be in this type
    // (a compile error names the first one that is not; ctga::project drops blades on purpose).
    // A copy, with the sign flipped where the two types orient a blade differently. (A template
    // is never the copy constructor, so same-layout copies stay trivial.)
    template <auto L2>
    constexpr multivector(const multivector<Alg, T, L2>& x) noexcept : c_{} {
        constexpr int missing = detail::first_missing<L2, Layout>();
        if constexpr (missing >= 0) {
            (void)sizeof(detail::target_lacks<Alg, L2.masks[missing]>);
        } else {
            for (std::size_t i = 0; i < L2.size(); ++i) {
                const auto k = static_cast<std::size_t>(Layout.index_of(L2.masks[i]));
                c_[k] = L2.signs[i] * Layout.signs[k] > 0 ? x[i] : T(-x[i]);
            }
        }
    }

    // From a component source (a lazy expression): the same rule, every blade the source can make
    // non-zero must be in this type, and only this type's components are computed.
    template <class S>
        requires(!std::is_same_v<S, multivector> && component_source<S, Alg, T, Layout>)
    CTGA_ALWAYS_INLINE constexpr multivector(const S& source) noexcept {
        static_assert(std::is_void_v<typename S::scalar_type> || std::is_same_v<T, typename S::scalar_type>,
                      "ctga: the expression's scalar type differs from the multivector's");
        constexpr int missing = detail::first_missing<S::layout, Layout>();
        if constexpr (missing >= 0) (void)sizeof(detail::target_lacks<Alg, S::layout.masks[missing]>);
        else c_ = source.template evaluate<T, Layout>();
    }

    [[nodiscard]] constexpr T& operator[](std::size_t i) noexcept { return c_[i]; }
    [[nodiscard]] constexpr const T& operator[](std::size_t i) const noexcept { return c_[i]; }
    [[nodiscard]] constexpr T* data() noexcept { return c_.data(); }
    [[nodiscard]] constexpr const T* data() const noexcept { return c_.data(); }
    [[nodiscard]] constexpr const std::array<T, size()>& components() const noexcept { return c_; }

    // The coefficient of a blade named as written ("e3e1" reads −(coefficient of e1e3));
    // zero when the blade is not in the type.
    template <fixed_string Name>
    [[nodiscard]] constexpr T get() const noexcept {
        using b = detail::blade_of<Alg, Name>;
        constexpr int i = Layout.index_of(b::mask);
        if constexpr (i < 0) return T{};
        else if constexpr (b::sign * Layout.signs[i] > 0) return c_[i];
        else return -c_[i];
    }

    // Set the coefficient of a blade named as written; the blade must be in the type.
    template <fixed_string Name>
    constexpr void set(const T& value) noexcept {
        using b = detail::blade_of<Alg, Name>;
        constexpr int i = Layout.index_of(b::mask);
        static_assert(i >= 0, "ctga: set<Name>: this multivector type does not hold that blade");
        if constexpr (i >= 0) c_[i] = (b::sign * Layout.signs[i] > 0) ? value : T(-value);
    }

private:
    std::array<T, size()> c_;  // zero unless constructed from uninitialized
};

template <class X>
inline constexpr bool is_multivector_v = false;
template <class Alg, class T, auto L>
inline constexpr bool is_multivector_v<multivector<Alg, T, L>> = true;

template <class X>
concept multivector_type = is_multivector_v<std::remove_cvref_t<X>>;

template <fixed_string Name, class Alg, class T, auto L>
[[nodiscard]] constexpr T get(const multivector<Alg, T, L>& x) noexcept {
    return x.template get<Name>();
}

// One basis blade with coefficient exactly 1 (orientation as written): algebra::basis<"a1a2a3a">,
// the paper's A. It holds no number; operations take it as an exact constant, so a product with
// it costs no multiplication.
template <class Alg, fixed_string Name>
struct basis_blade {
    using algebra_type = Alg;
    using scalar_type = void;  // exact: takes the scalar type of what it meets
    using blade = detail::blade_of<Alg, Name>;
    // read the name where the constant is declared (G::basis<"…">), not where it is first used
    static_assert(blade::parsed.status == blade_name_status::ok, "ctga: basis<Name>: Name is not a blade of this algebra");
    static constexpr ctga::layout<1> layout{{blade::mask}, {static_cast<signed char>(blade::sign)}};
};

template <class X>
inline constexpr bool is_basis_blade_v = false;
template <class Alg, fixed_string Name>
inline constexpr bool is_basis_blade_v<basis_blade<Alg, Name>> = true;

}  // namespace ctga
