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
        const auto sparse = ctga::eval(ctga::looped(op[hana::size_c<1>](x, y)));
        check_close(name, sparse, op[hana::size_c<2>](as_dense(x), as_dense(y)));
    });
}

}  // namespace ctga::test::looped
