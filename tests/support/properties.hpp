// The property checks run in every algebra: the sparse engine against the naive dense
// reference for every product and linear map, and the algebraic laws, on random inputs of
// several compile-time shapes. Each algebra's test file instantiates these.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <tuple>
#include <utility>

#include <boost/hana.hpp>
#include <ctga/ctga.hpp>
#include <ctga/reference/dense.hpp>

#include "support/catch.hpp"
#include "support/parts.hpp"
#include "support/shapes.hpp"

namespace ctga::test {

namespace hana = boost::hana;

inline constexpr double tolerance = 1e-12;

// max |a − b| / max |b| over all 2^n components (the absolute error when b is zero).
template <class Alg, class T>
double relative_error(const dense::multivector<Alg, T>& a, const dense::multivector<Alg, T>& b) {
    const double scale = static_cast<double>(dense::max_abs(b));
    const double diff = static_cast<double>(dense::max_abs_diff(a, b));
    return scale > 0 ? diff / scale : diff;
}

template <class Alg, class T>
const dense::multivector<Alg, T>& as_dense(const dense::multivector<Alg, T>& d) { return d; }
template <operand X>
auto as_dense(const X& x) { return dense::to_dense(eval(x)); }

template <class X, class Y>
double relative_error(const X& a, const Y& b) {
    return relative_error(as_dense(a), as_dense(b));
}

// One comparison, reported with its name and error when it fails. (The Catch2 macros sit in
// one non-template function: expanding them per operand type pair dominated compile time.)
inline void report(const std::string& what, double err) {
    INFO(what << ": relative error " << err);
    CHECK(err <= tolerance);
}

template <class A, class B>
void check_close(const std::string& what, const A& a, const B& b) {
    report(what, relative_error(a, b));
}

// Each bilinear operation as (sparse engine, dense reference).
inline const auto bilinear_ops = hana::make_tuple(
    hana::make_tuple(BOOST_HANA_STRING("geometric *"), [](const auto& x, const auto& y) { return x * y; },
                     [](const auto& x, const auto& y) { return dense::gp(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("exterior ^"), [](const auto& x, const auto& y) { return x ^ y; },
                     [](const auto& x, const auto& y) { return dense::wedge(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("shuffle &"), [](const auto& x, const auto& y) { return x & y; },
                     [](const auto& x, const auto& y) { return dense::shuffle(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("left contraction |"), [](const auto& x, const auto& y) { return x | y; },
                     [](const auto& x, const auto& y) { return dense::lcont(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("right contraction"),
                     [](const auto& x, const auto& y) { return right_contraction(x, y); },
                     [](const auto& x, const auto& y) { return dense::rcont(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("scalar product"),
                     [](const auto& x, const auto& y) { return scalar_product(x, y); },
                     [](const auto& x, const auto& y) { return dense::scalar_product(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("sum +"), [](const auto& x, const auto& y) { return x + y; },
                     [](const auto& x, const auto& y) { return x + y; }),
    hana::make_tuple(BOOST_HANA_STRING("difference -"), [](const auto& x, const auto& y) { return x - y; },
                     [](const auto& x, const auto& y) { return x - y; }));

// A permutation of the generators that keeps squares: a random shuffle within each class of
// equal squares (drawn at compile time from Seed).
template <class Alg, std::uint64_t Seed>
constexpr std::array<int, Alg::dimension> square_preserving_permutation() {
    std::array<int, Alg::dimension> p{};
    for (std::size_t i = 0; i < Alg::dimension; ++i) p[i] = static_cast<int>(i);
    std::uint64_t s = Seed;
    for (std::size_t i = Alg::dimension; i-- > 1;) {
        const std::size_t j = splitmix(s) % (i + 1);
        if (Alg::squares[p[i]] == Alg::squares[p[j]]) std::swap(p[i], p[j]);
    }
    return p;
}

// The sign of a permutation (parity of its inversions).
template <std::size_t N>
constexpr double permutation_sign(const std::array<int, N>& p) {
    int inversions = 0;
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = i + 1; j < N; ++j) inversions += p[i] > p[j];
    return inversions % 2 ? -1.0 : 1.0;
}

template <class Alg>
constexpr std::array<int, Alg::dimension> bar_permutation() {
    std::array<int, Alg::dimension> p{};
    for (std::size_t i = 0; i < Alg::dimension; ++i) p[i] = static_cast<int>((i + Alg::dimension / 2) % Alg::dimension);
    return p;
}

template <class Alg, auto Perm, class X>
auto apply_permutation(const X& x) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) { return automorphism<Perm[I]...>(x); }(
        std::make_index_sequence<Alg::dimension>{});
}

// True when the generators' second half repeats the first half's squares, so that the
// paper's bar (i ↔ i + n/2) is an automorphism.
template <class Alg>
constexpr bool doubled() {
    if (Alg::dimension % 2) return false;
    for (std::size_t i = 0; i < Alg::dimension / 2; ++i)
        if (Alg::squares[i] != Alg::squares[i + Alg::dimension / 2]) return false;
    return true;
}

template <class Alg>
constexpr bool non_degenerate() {
    for (int s : Alg::squares) if (s == 0) return false;
    return true;
}

// ---- checks -----------------------------------------------------------------------------

// Every bilinear operation on (x, y), sparse against dense.
template <class X, class Y>
void check_products_against_dense(const X& x, const Y& y) {
    const auto dx = as_dense(x);
    const auto dy = as_dense(y);
    hana::for_each(bilinear_ops, [&](const auto& op) {
        check_close(hana::to<const char*>(op[hana::size_c<0>]), op[hana::size_c<1>](x, y),
                         op[hana::size_c<2>](dx, dy));
    });
}

// Every linear map on x, sparse against dense.
template <class Alg, class X>
void check_linear_maps_against_dense(const X& x) {
    const auto dx = as_dense(x);
    check_close("reverse ~", ~x, dense::reverse(dx));
    check_close("involute", involute(x), dense::involute(dx));
    check_close("conj (paper's *)", conj(x), dense::conjugate(dx));
    check_close("negation", -x, -dx);
    check_close("scaling", 2.5 * x, 2.5 * dx);
    check_close("right complement", right_complement(x), dense::right_complement(dx));
    check_close("left complement", left_complement(x), dense::left_complement(dx));
    [&]<std::size_t... K>(std::index_sequence<K...>) {
        (check_close("grade<" + std::to_string(K) + ">", grade<static_cast<int>(K)>(x),
                          dense::grade(dx, static_cast<int>(K))),
         ...);
    }(std::make_index_sequence<Alg::dimension + 1>{});
    constexpr auto perm = square_preserving_permutation<Alg, 11>();
    check_close("automorphism", apply_permutation<Alg, square_preserving_permutation<Alg, 11>()>(x),
                dense::automorphism(dx, perm));
    if constexpr (doubled<Alg>()) check_close("bar", bar(x), dense::bar(dx));
}

// Products inside a law are whole lazy expressions in algebras of up to 4 generators (the
// engine's staging and cancellation at work); in larger algebras inner results are
// materialised first, which keeps the compile time of these suites in budget (nested
// expressions are the subject of expression_engine_test.cpp).
template <class Alg, class X>
constexpr decltype(auto) inner(X&& x) {
    if constexpr (Alg::dimension <= 4) return std::forward<X>(x);
    else return eval(std::forward<X>(x));
}

// The algebraic laws on a triple, within the sparse engine itself.
template <class Alg, class X, class Y, class Z>
void check_laws(const X& x, const Y& y, const Z& z) {
    const auto in = [](auto&& e) -> decltype(auto) { return inner<Alg>(std::forward<decltype(e)>(e)); };
    check_close("associativity of *", in(x * y) * z, x * in(y * z));
    check_close("associativity of ^", in(x ^ y) ^ z, x ^ in(y ^ z));
    check_close("associativity of &", in(x & y) & z, x & in(y & z));
    check_close("left distributivity of *", x * in(y + z), in(x * y) + in(x * z));
    check_close("right distributivity of *", in(x + y) * z, in(x * z) + in(y * z));
    check_close("distributivity of ^", in(x + y) ^ z, in(x ^ z) + in(y ^ z));
    check_close("distributivity of &", x & in(y + z), in(x & y) + in(x & z));
    check_close("distributivity of |", x | in(y - z), in(x | y) - in(x | z));
    check_close("(xy)* = y* x*", conj(in(x * y)), in(conj(y)) * in(conj(x)));
    check_close("reverse is an anti-automorphism", ~in(x * y), in(~y) * in(~x));
    check_close("involute is an automorphism", involute(in(x * y)), in(involute(x)) * in(involute(y)));
    // A permutation σ of generators with equal squares is an automorphism of * and ^; the
    // shuffle product's determinant picks up sign(σ):  σ(x ∨ y) = sign(σ) σ(x) ∨ σ(y).
    constexpr auto perm = square_preserving_permutation<Alg, 29>();
    const auto aut = [](const auto& m) { return apply_permutation<Alg, square_preserving_permutation<Alg, 29>()>(m); };
    check_close("automorphism of *", aut(in(x * y)), in(aut(x)) * in(aut(y)));
    check_close("automorphism of ^", aut(in(x ^ y)), in(aut(x)) ^ in(aut(y)));
    check_close("automorphism of &, up to sign(σ)", aut(in(x & y)), permutation_sign(perm) * in(in(aut(x)) & in(aut(y))));
    if constexpr (doubled<Alg>()) {
        // bar swaps the two halves: sign (−1)^((n/2)²), +1 for Cl(0,6,2) as the paper needs (§5)
        constexpr double bar_sign = permutation_sign(bar_permutation<Alg>());
        check_close("bar of *", bar(in(x * y)), in(bar(x)) * in(bar(y)));
        check_close("bar of ^", bar(in(x ^ y)), in(bar(x)) ^ in(bar(y)));
        check_close("bar of &, up to its sign", bar(in(x & y)), bar_sign * in(in(bar(x)) & in(bar(y))));
        check_close("bar is an involution", bar(in(bar(x))), x);
    }
    // ∨ through the metric-free complements, valid in every algebra:  x ∨ y = lc(rc x ∧ rc y)
    check_close("shuffle = complement formula", x & y,
                left_complement(in(in(right_complement(x)) ^ in(right_complement(y)))));
}

// In a non-degenerate algebra the pseudoscalar formula of Lounesto (paper §4),
// ((x I⁻¹) ∧ (y I⁻¹)) I, equals the shuffle product up to the sign (−1)^((n−j)(n−k)) for
// grades j, k: the determinant convention det(e1,…,en) = +1 against the dual by I⁻¹.
template <class Alg, class X, class Y>
void check_pseudoscalar_formula(const X& x, const Y& y) {
    constexpr int n = static_cast<int>(Alg::dimension);
    constexpr layout<1> li{{Alg::pseudoscalar_mask}, {1}};
    const multivector<Alg, double, li> I{1.0};
    const auto I_inv = I / scalar_part(I * I);
    [&]<std::size_t... J>(std::index_sequence<J...>) {
        ([&]<std::size_t Jg>() {
            const auto xj = grade<static_cast<int>(Jg)>(x);
            [&]<std::size_t... K>(std::index_sequence<K...>) {
                ([&] {
                    const auto yk = grade<static_cast<int>(K)>(y);
                    constexpr double sign = ((n - static_cast<int>(Jg)) * (n - static_cast<int>(K))) % 2 ? -1.0 : 1.0;
                    check_close("shuffle = pseudoscalar formula, grades " + std::to_string(Jg) + "," +
                                         std::to_string(K),
                                     xj & yk, sign * (((xj * I_inv) ^ (yk * I_inv)) * I));
                }(), ...);
            }(std::make_index_sequence<n + 1>{});
        }.template operator()<J>(), ...);
    }(std::make_index_sequence<n + 1>{});
}

// The grades that the product of an r-blade and an s-blade can have:
// geometric |r−s|, |r−s|+2, …, r+s;  exterior r+s.
template <class Alg, int R, int S, class Rng>
void check_grades_of_blade_products(Rng& rng) {
    using vec = grade_mv<Alg, 1>;
    // an r-blade as the exterior product of r random vectors (r ≥ 1)
    auto blade = [&]<int G>() {
        if constexpr (G == 1) return random_fill<vec>(rng);
        else return eval([&]<std::size_t... I>(std::index_sequence<I...>) {
            return (random_fill<vec>(rng) ^ ... ^ (static_cast<void>(I), random_fill<vec>(rng)));
        }(std::make_index_sequence<G - 1>{}));
    };
    const auto a = blade.template operator()<R>();
    const auto b = blade.template operator()<S>();
    constexpr auto geometric_grades_ok = [](const auto& l) {
        for (blade_mask m : l.masks) {
            const int g = blade_grade(m);
            if (g < (R > S ? R - S : S - R) || g > R + S || (g + R + S) % 2 != 0) return false;
        }
        return true;
    };
    static_assert(geometric_grades_ok(decltype(a * b)::layout), "type of a blade product has a wrong grade");
    constexpr auto wedge_layout = decltype(a ^ b)::layout;
    static_assert([&] { for (blade_mask m : wedge_layout.masks) if (blade_grade(m) != R + S) return false; return true; }(),
                  "type of an exterior product of blades has a wrong grade");
    // numerically, through the dense reference: nothing outside those grades
    const auto d = dense::gp(as_dense(a), as_dense(b));
    double outside = 0, scale = static_cast<double>(dense::max_abs(d));
    for (blade_mask m = 0; m < Alg::blade_count; ++m) {
        const int g = blade_grade(m);
        const bool allowed = g >= (R > S ? R - S : S - R) && g <= R + S && (g + R + S) % 2 == 0;
        if (!allowed) outside = std::max(outside, std::abs(static_cast<double>(d[m])));
    }
    INFO("grades of a " << R << "-blade times an " << S << "-blade");
    CHECK(outside <= tolerance * (scale > 0 ? scale : 1.0));
}

// ---- the suite, in parts (support/parts.hpp) ---------------------------------------------

struct suite_part {
    std::size_t index, count;
    [[nodiscard]] constexpr bool holds(std::size_t item) const { return item % count == index; }
};
inline constexpr suite_part this_part{CTGA_TEST_PART, CTGA_TEST_PARTS};
static_assert(this_part.index < this_part.count, "CTGA_TEST_PART must be below CTGA_TEST_PARTS");

// The work items of the suite over n shapes, most expensive first so that parts get a share of
// each kind: the laws on the n cyclic triples, every ordered pair of shapes against the dense
// reference, every shape through every linear map, Lounesto's formula on the first shape (the
// widest), the grades of products of blades.
template <std::size_t N>
struct suite_items {
    static constexpr std::size_t laws = 0, products = laws + N, maps = products + N * N, pseudoscalar = maps + N,
                                 grades = pseudoscalar + 1, count = grades + 1;
};

template <class Alg, std::size_t Item, class... Shapes, class Rng>
void run_suite_item(Rng& rng) {
    constexpr std::size_t n = sizeof...(Shapes);
    using items = suite_items<n>;
    using shapes = std::tuple<Shapes...>;
    if constexpr (!this_part.holds(Item)) {
        return;
    } else if constexpr (Item < items::products) {
        constexpr std::size_t i = Item - items::laws;
        check_laws<Alg>(random_fill<std::tuple_element_t<i, shapes>>(rng),
                        random_fill<std::tuple_element_t<(i + 1) % n, shapes>>(rng),
                        random_fill<std::tuple_element_t<(i + 2) % n, shapes>>(rng));
    } else if constexpr (Item < items::maps) {
        constexpr std::size_t pair = Item - items::products;
        check_products_against_dense(random_fill<std::tuple_element_t<pair / n, shapes>>(rng),
                                     random_fill<std::tuple_element_t<pair % n, shapes>>(rng));
    } else if constexpr (Item < items::pseudoscalar) {
        check_linear_maps_against_dense<Alg>(random_fill<std::tuple_element_t<Item - items::maps, shapes>>(rng));
    } else if constexpr (Item == items::pseudoscalar) {
        using first = std::tuple_element_t<0, shapes>;
        if constexpr (non_degenerate<Alg>()) check_pseudoscalar_formula<Alg>(random_fill<first>(rng), random_fill<first>(rng));
    } else {
        // blades of grade up to 3 (up to 2 past 8 generators, where two generic 3-blades already
        // make 14,400 blade pairs)
        constexpr int top = Alg::dimension < 3 ? static_cast<int>(Alg::dimension) : Alg::dimension > 8 ? 2 : 3;
        [&]<int... R>(std::integer_sequence<int, R...>) {
            ([&]<int Rg>() {
                [&]<int... S>(std::integer_sequence<int, S...>) {
                    (check_grades_of_blade_products<Alg, Rg + 1, S + 1>(rng), ...);
                }(std::make_integer_sequence<int, top>{});
            }.template operator()<R>(), ...);
        }(std::make_integer_sequence<int, top>{});
    }
}

// The suite for one algebra over a list of shapes (multivector types), this part's items of it,
// `trials` times on fresh random inputs (each part draws its own).
template <class Alg, class... Shapes>
void run_suite(std::uint64_t seed, int trials = 3) {
    std::mt19937_64 rng(seed + 7919 * this_part.index);
    for (int t = 0; t < trials; ++t)
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (run_suite_item<Alg, I, Shapes...>(rng), ...);
        }(std::make_index_sequence<suite_items<sizeof...(Shapes)>::count>{});
}

// The shapes used in algebras of up to 5 generators: every blade at once, the vectors, the
// bivectors, and two random sparse sets with random orientations.
template <class G>
void run_small_suite(std::uint64_t seed) {
    run_suite<G, random_mv<G, 1, G::blade_count>, grade_mv<G, 1>, grade_mv<G, 2>, random_mv<G, 2, 3>,
              random_mv<G, 3, 5>>(seed);
}

}  // namespace ctga::test
