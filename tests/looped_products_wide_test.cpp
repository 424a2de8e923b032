// Looped products (expr/looped.hpp) in Cl(3,0,1), forced, against unrolled evaluation and the
// dense reference, and in a 10-generator algebra: 512 x 512 even and 1024 x 1024 general
// products against the dense reference. (Split from looped_products_test.cpp to keep each
// translation unit's compile time in budget.)
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>

#include "support/properties.hpp"

namespace {

using namespace ctga::test;
namespace dense = ctga::dense;
namespace hana = boost::hana;
using ctga::blade_mask;

using cl301 = ctga::algebra<"e0 e1 e2 e3", 0, 1, 1, 1>;
// 10 generators of every kind of square (the degenerate ones last, as in Cl(0,6,2))
using ten = ctga::algebra<"e1 e2 e3 e4 e5 e6 e7 e8 e9 e10", 1, 1, 1, -1, -1, -1, -1, 1, 0, 0>;

// Every blade of Alg whose grade passes Keep, canonical, ordered by mask.
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

// ---- looped products against the dense reference ----------------------------------------------

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

TEST_CASE("Cl(3,0,1): forcing looped or unrolled gives the same products", "[looped][cl301]") {
    std::mt19937_64 rng(301);
    using full = general<cl301>;
    static_assert(!is_looped<decltype(full{} * full{})>, "192 pairs: unrolled by default");
    const auto a = random_fill<full>(rng);
    const auto b = random_fill<random_mv<cl301, 7, 11>>(rng);
    static_assert(is_looped<decltype(ctga::looped(a * b))>);
    check_all_products<full, random_mv<cl301, 7, 11>>("Cl(3,0,1)", rng);
    check_close("Cl(3,0,1) looped against unrolled", ctga::looped(a * b), ctga::unrolled(a * b));
    check_close("Cl(3,0,1) looped against unrolled, ∨", ctga::looped(a & b), ctga::unrolled(a & b));
}

TEST_CASE("10 generators: 512 x 512 even and 1024 x 1024 general products equal the dense reference",
          "[looped][ten]") {
    std::mt19937_64 rng(10);
    const auto a = random_fill<even<ten>>(rng);
    const auto b = random_fill<even<ten>>(rng);
    static_assert(is_looped<decltype(a * b)> && decltype(a * b)::size() == 512);
    check_close("even * even", a * b, dense::gp(as_dense(a), as_dense(b)));
    check_close("even ∧ even", a ^ b, dense::wedge(as_dense(a), as_dense(b)));
    const auto x = random_fill<general<ten>>(rng);
    const auto y = random_fill<general<ten>>(rng);
    check_close("general * general", x * y, dense::gp(as_dense(x), as_dense(y)));
    check_close("general ∨ general", x & y, dense::vee(as_dense(x), as_dense(y)));
    check_close("general ⌋ general", x | y, dense::lcont(as_dense(x), as_dense(y)));
}

}  // namespace
