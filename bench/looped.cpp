// looped_vs_dense/<product>/<implementation>: the full 256 × 256 products of two general
// multivectors of Cl(0,6,2), past the unrolling threshold, so ctga evaluates them as looped
// products (expr/looped.hpp: by blocks of the four low generators), against the naive dense
// reference on the same random operands. Registered here, outside the kernel table of
// suite.cpp (they are not among the paper's operations, and have no spatial or Eigen form).
#include <array>
#include <cstddef>
#include <random>
#include <string>
#include <type_traits>

#include <benchmark/benchmark.h>
#include <ctga/ctga.hpp>
#include <ctga/reference/dense.hpp>

namespace {

using ctga::blade_mask;

constexpr auto all_blades() {
    ctga::layout<ctga::cl062::blade_count> l;
    for (blade_mask m = 0; m < ctga::cl062::blade_count; ++m) {
        l.masks[m] = m;
        l.signs[m] = 1;
    }
    return l;
}
using general = ctga::multivector<ctga::cl062, double, all_blades()>;
using dense_mv = ctga::dense::multivector<ctga::cl062>;

struct operands {
    general x, y;
    dense_mv dx, dy;
};

// 16 random operand pairs, cycled through so that nothing is constant-folded
const std::array<operands, 16>& inputs() {
    static const std::array<operands, 16> sets = [] {
        std::array<operands, 16> s{};
        std::mt19937_64 rng(256);
        std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
        for (operands& o : s) {
            for (std::size_t i = 0; i < general::size(); ++i) {
                o.x[i] = coefficient(rng);
                o.y[i] = coefficient(rng);
            }
            o.dx = ctga::dense::to_dense(o.x);
            o.dy = ctga::dense::to_dense(o.y);
        }
        return s;
    }();
    return sets;
}

template <class Product>
void time_looped(benchmark::State& state, Product product) {
    using node = typename decltype(product(general{}, general{}))::node_type;
    static_assert(ctga::expr::is_looped_node<node>, "past the threshold: looped");
    std::size_t k = 0;
    for (auto _ : state) {
        const operands& o = inputs()[k];
        auto r = ctga::eval(product(o.x, o.y));
        benchmark::DoNotOptimize(r);
        k = (k + 1) % inputs().size();
    }
}

template <class Product>
void time_dense(benchmark::State& state, Product product) {
    std::size_t k = 0;
    for (auto _ : state) {
        const operands& o = inputs()[k];
        auto r = product(o.dx, o.dy);
        benchmark::DoNotOptimize(r);
        k = (k + 1) % inputs().size();
    }
}

template <class Looped, class Dense>
int register_product(const char* name, Looped looped, Dense dense) {
    const std::string base = std::string("looped_vs_dense/") + name;
    benchmark::RegisterBenchmark((base + "/looped").c_str(), [looped](benchmark::State& s) { time_looped(s, looped); });
    benchmark::RegisterBenchmark((base + "/dense").c_str(), [dense](benchmark::State& s) { time_dense(s, dense); });
    return 0;
}

[[maybe_unused]] const int registered[] = {
    register_product("geometric", [](const auto& x, const auto& y) { return x * y; },
                     [](const auto& x, const auto& y) { return ctga::dense::gp(x, y); }),
    register_product("outer", [](const auto& x, const auto& y) { return x ^ y; },
                     [](const auto& x, const auto& y) { return ctga::dense::wedge(x, y); }),
    register_product("shuffle", [](const auto& x, const auto& y) { return x & y; },
                     [](const auto& x, const auto& y) { return ctga::dense::shuffle(x, y); }),
    register_product("left_contraction", [](const auto& x, const auto& y) { return x | y; },
                     [](const auto& x, const auto& y) { return ctga::dense::lcont(x, y); }),
    register_product("right_contraction", [](const auto& x, const auto& y) { return ctga::right_contraction(x, y); },
                     [](const auto& x, const auto& y) { return ctga::dense::rcont(x, y); }),
};

}  // namespace
