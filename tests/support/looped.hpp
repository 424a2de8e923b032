// Shared by the looped-product tests: the algebras, whole-algebra and even shapes, and every
// bilinear operation of two shapes forced looped against the dense reference.
#pragma once

#include <cstddef>
#include <string>

#include "support/properties.hpp"

namespace ctga::test::looped {

namespace dense = ctga::dense;
namespace hana = boost::hana;
using ctga::blade_mask;

using cl301 = ctga::algebra<"e0 e1 e2 e3", 0, 1, 1, 1>;
// 10 generators of every kind of square (the degenerate ones last, as in Cl(0,6,2))
using ten = ctga::algebra<"e1 e2 e3 e4 e5 e6 e7 e8 e9 e10", 1, 1, 1, -1, -1, -1, -1, 1, 0, 0>;

// Every blade of Alg (or every even one), canonical, ordered by mask.
template <class Alg, bool EvenOnly>
constexpr auto blades() {
    constexpr std::size_t n = EvenOnly ? Alg::blade_count / 2 : Alg::blade_count;
    ctga::layout<n> l;
    std::size_t k = 0;
    for (blade_mask m = 0; m < Alg::blade_count; ++m)
        if (!EvenOnly || ctga::blade_grade(m) % 2 == 0) {
            l.masks[k] = m;
            l.signs[k++] = 1;
        }
    return l;
}
template <class Alg>
using general = ctga::multivector<Alg, double, blades<Alg, false>()>;
template <class Alg>
using even = ctga::multivector<Alg, double, blades<Alg, true>()>;

// The dense value restricted to the blades of layout L (a projection, as ctga::project).
template <class Alg, auto L>
dense::multivector<Alg, double> keep_only(const dense::multivector<Alg, double>& d) {
    dense::multivector<Alg, double> out;
    for (blade_mask m : L.masks) out[m] = d[m];
    return out;
}

template <class E>
constexpr bool is_looped = ctga::expr::is_looped_node<typename std::remove_cvref_t<E>::node_type>;

// Each bilinear rule of X and Y: looped (by the engine's choice or forced), against dense.
template <class X, class Y, class Rng>
void check_all_products(const std::string& where, Rng& rng) {
    const auto x = random_fill<X>(rng);
    const auto y = random_fill<Y>(rng);
    hana::for_each(bilinear_ops, [&](const auto& op) {
        const std::string name = where + ", " + hana::to<const char*>(op[hana::size_c<0>]);
        const auto sparse = ctga::eval(ctga::loop_products(op[hana::size_c<1>](x, y)));
        check_close(name, sparse, op[hana::size_c<2>](as_dense(x), as_dense(y)));
    });
}

// Whether a looped product runs as a block product (expr::block_plan) or by the table loop.
template <class Node>
inline constexpr bool runs_by_blocks = false;
template <class R, class X, class Y>
inline constexpr bool runs_by_blocks<ctga::expr::looped<R, X, Y>> =
    ctga::expr::block_plan<R, ctga::expr::operand_layout<X>, ctga::expr::operand_layout<Y>>::used;
template <class E>
constexpr bool by_blocks = runs_by_blocks<typename std::remove_cvref_t<E>::node_type>;

// Each bilinear rule as a template of the algebra, with its dense counterpart.
inline const auto bilinear_rules = hana::make_tuple(
    hana::make_tuple(BOOST_HANA_STRING("geometric"), hana::template_<ctga::rules::geometric>,
                     [](const auto& x, const auto& y) { return dense::gp(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("exterior"), hana::template_<ctga::rules::exterior>,
                     [](const auto& x, const auto& y) { return dense::wedge(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("shuffle"), hana::template_<ctga::rules::shuffle>,
                     [](const auto& x, const auto& y) { return dense::shuffle(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("left contraction"), hana::template_<ctga::rules::left_contraction>,
                     [](const auto& x, const auto& y) { return dense::lcont(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("right contraction"), hana::template_<ctga::rules::right_contraction>,
                     [](const auto& x, const auto& y) { return dense::rcont(x, y); }),
    hana::make_tuple(BOOST_HANA_STRING("scalar product"), hana::template_<ctga::rules::scalar>,
                     [](const auto& x, const auto& y) { return dense::scalar_product(x, y); }));

// The values of output layout OL as a dense multivector.
template <class Alg, auto OL>
dense::multivector<Alg, double> dense_of(const std::array<double, OL.size()>& v) {
    dense::multivector<Alg, double> d;
    for (std::size_t k = 0; k < OL.size(); ++k) d[OL.masks[k]] = OL.signs[k] * v[k];
    return d;
}

// Both loops of every bilinear rule on X and Y, called directly whichever the engine would
// choose: the block product (every rule splits over the generators) and the table loop, each
// against dense.
template <class X, class Y, class Rng>
void check_both_loops(const std::string& where, Rng& rng) {
    using Alg = typename X::algebra_type;
    const auto x = random_fill<X>(rng);
    const auto y = random_fill<Y>(rng);
    const auto dx = as_dense(x), dy = as_dense(y);
    hana::for_each(bilinear_rules, [&](const auto& r) {
        using Rule = typename std::remove_cvref_t<decltype(r[hana::size_c<1>])>::template apply<Alg>::type;
        using rows = ctga::expr::pair_rows<Rule, X::layout, Y::layout>;
        using plan = ctga::expr::block_plan<Rule, X::layout, Y::layout>;
        static_assert(plan::census.splits, "every bilinear rule splits over the generators");
        constexpr auto OL = rows::outputs;
        const std::string name = where + ", " + hana::to<const char*>(r[hana::size_c<0>]);
        const auto expected = r[hana::size_c<2>](dx, dy);
        check_close(name + " by blocks",
                    dense_of<Alg, OL>(ctga::expr::run_blocks<double, plan, X::layout, Y::layout, OL>(x.data(), y.data())),
                    expected);
        check_close(name + " by the table loop",
                    dense_of<Alg, OL>(ctga::expr::run_rows<double, rows, Y::layout, OL>(x.data(), y.data())), expected);
        // the same product with the halves of the generators swapped (an automorphism where the
        // halves have the same squares, expr::swapped_layout): by blocks over the swapped
        // blades, read back through the swap
        if constexpr (ctga::expr::halves_swap<Rule>) {
            constexpr auto SX = ctga::expr::swapped_layout<Rule, X::layout>;
            constexpr auto SY = ctga::expr::swapped_layout<Rule, Y::layout>;
            using swapped = ctga::expr::block_plan<Rule, SX, SY>;
            std::array<double, swapped::universe> acc{};
            ctga::expr::run_blocks_into<double, swapped, SX, SY>(acc.data(), x.data(), y.data());
            check_close(name + " by blocks, halves swapped",
                        dense_of<Alg, OL>(ctga::expr::gather<double, swapped::universe, ctga::expr::swapped_layout<Rule, OL>>(acc.data())),
                        expected);
        }
    });
}

// x ē with x a motor of one half of Cl(0,6,2) and ē a blade of the other (a Jacobian column of the
// moved inertia): 8 blocks of one low blade each, one dense block once the halves are swapped.
inline constexpr auto motor_times_blade = [] {
    ctga::layout<8> l;
    constexpr blade_mask even4[8] = {0x0, 0x3, 0x5, 0x6, 0x9, 0xa, 0xc, 0xf};
    for (std::size_t i = 0; i < 8; ++i) {
        l.masks[i] = static_cast<blade_mask>(even4[i] << 4 | 0x9);
        l.signs[i] = static_cast<signed char>(i % 3 == 1 ? -1 : 1);  // some stored orientations reversed
    }
    return l;
}();

}  // namespace ctga::test::looped
