// Compile-time cost against the number of generators: one geometric product of two general
// multivectors in an algebra of n = CTGA_N generators e1 … en (squares −1, the last one 0, as
// in Cl(0,3,1)), evaluated at run time. CTGA_PRODUCT picks the operands:
//   1  two general vectors         (n blades each)
//   2  two general bivectors       (n(n−1)/2 blades each)
//   3  two general even elements   (2^(n−1) blades each)
//   4  two general multivectors    (2^n blades each)
// ctga has no global product tables: each product's blade pairs, signs and program are
// computed at compile time for that product's operand types, so this is the cost of one
// algebra plus one product. With CTGA_REPORT the program also prints the operand and result
// blade counts and ctga::cost_of (tools/compile-cost.sh builds that variant separately, so
// the measured compile does not include computing the price).
// Measured by tools/compile-cost.sh; not part of any CMake target.
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include <ctga/core.hpp>
#include <ctga/algebra/algebra.hpp>

#ifndef CTGA_N
#define CTGA_N 4
#endif
#ifndef CTGA_PRODUCT
#define CTGA_PRODUCT 2
#endif

namespace {

constexpr std::size_t n = CTGA_N;

// "e1 e2 … en" as a template argument
constexpr std::size_t names_length() {
    std::size_t len = 0;
    for (std::size_t i = 1; i <= n; ++i) len += (i < 10 ? 2 : 3) + (i > 1);
    return len;
}
constexpr auto generator_names() {
    ctga::fixed_string<names_length() + 1> s;
    std::size_t k = 0;
    for (std::size_t i = 1; i <= n; ++i) {
        if (i > 1) s.chars[k++] = ' ';
        s.chars[k++] = 'e';
        if (i >= 10) s.chars[k++] = static_cast<char>('0' + i / 10);
        s.chars[k++] = static_cast<char>('0' + i % 10);
    }
    return s;
}
template <std::size_t... I>
auto make_algebra(std::index_sequence<I...>) -> ctga::algebra<generator_names(), (I + 1 == n ? 0 : -1)...>;
using G = decltype(make_algebra(std::make_index_sequence<n>{}));

// Every blade whose grade passes `keep`, canonical orientation, ordered by mask.
template <class Keep>
constexpr std::size_t blade_count(Keep keep) {
    std::size_t c = 0;
    for (ctga::blade_mask m = 0; m < G::blade_count; ++m) c += keep(ctga::blade_grade(m));
    return c;
}
template <class Keep>
constexpr auto blades_of_grades(Keep keep) {
    ctga::layout<blade_count(Keep{})> l;
    std::size_t i = 0;
    for (ctga::blade_mask m = 0; m < G::blade_count; ++m)
        if (keep(ctga::blade_grade(m))) {
            l.masks[i] = m;
            l.signs[i] = 1;
            ++i;
        }
    return l;
}
#if CTGA_PRODUCT == 1
struct keep_grades { constexpr bool operator()(int g) const { return g == 1; } };
#elif CTGA_PRODUCT == 2
struct keep_grades { constexpr bool operator()(int g) const { return g == 2; } };
#elif CTGA_PRODUCT == 3
struct keep_grades { constexpr bool operator()(int g) const { return g % 2 == 0; } };
#elif CTGA_PRODUCT == 4
struct keep_grades { constexpr bool operator()(int) const { return true; } };
#else
#error "CTGA_PRODUCT must be 1 (vectors), 2 (bivectors), 3 (even elements) or 4 (general multivectors)"
#endif
using operand = ctga::multivector<G, double, blades_of_grades(keep_grades{})>;

}  // namespace

int main(int argc, char** argv) {
    // run-time operands, so that the product is not folded away
    const double x = argc > 1 ? std::atof(argv[1]) : 0.5;
    operand a, b;
    for (std::size_t i = 0; i < operand::size(); ++i) {
        a[i] = x + 0.01 * static_cast<double>(i);
        b[i] = x - 0.02 * static_cast<double>(i);
    }
    const auto r = ctga::eval(a * b);
    double sum = 0;
    for (std::size_t i = 0; i < r.size(); ++i) sum += r[i];
#ifdef CTGA_REPORT
    constexpr auto price = ctga::cost_of<decltype(a * b)>;
    std::printf("%zu %zu %zu %zu\n", operand::size(), r.size(), price.mul, price.add);
#else
    std::printf("%g\n", sum);
#endif
    return 0;
}
