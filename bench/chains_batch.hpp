// The kernels of ctga_batch_bench (bench/chains_batch.cpp): one tree's RNEA, ABA or CRBA over a
// batch of robots kept as an array of structures (bench::chains::state, as users keep them), in
// doubles robot by robot (scalar) or L robots per instruction stream (pack4, pack8: ctga::pack,
// chains/batch.hpp's load and store). Registered as batch_<algorithm>_<tree>/<width>; the time
// reported is per robot evaluation (the counter per_robot), with robots/s, and for the arm the
// arithmetic rate of Featherstone's minimal operation counts (Table 10.1) and its share of this
// core's FMA peak at that width (measured at start-up, chains_batch.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

#include <benchmark/benchmark.h>

#include <ctga/chains/batch.hpp>
#include <ctga/chains/model_cast.hpp>
#include <ctga/support/pack.hpp>

#include "chain_models.hpp"

namespace bench::batch {

namespace ch = ctga::chains;
using chains::state;

enum class algorithm { rnea, aba, crba };

// this core's peak Gflop/s of independent fused multiply-adds, per lane count (1, 4, 8)
double fma_peak(std::size_t lanes);

// Featherstone's operation count (m + a) for an all-revolute chain of n joints, Table 10.1
constexpr double featherstone_flops(algorithm a, double n) {
    switch (a) {
        case algorithm::rnea: return (93 * n - 108) + (81 * n - 100);
        case algorithm::aba: return (224 * n - 259) + (205 * n - 248);
        case algorithm::crba: return (10 * n * n + 22 * n - 32) + (6 * n * n + 37 * n - 43);
    }
    return 0;
}

// the robots of a batch: 512 states (64 distinct, repeated) and room for each result
template <class Tree>
struct robots {
    static constexpr std::size_t count = 512;
    struct robot {
        chains::state<Tree> s;
        ch::joint_vector<Tree> out{};
        ch::joint_matrix<Tree> H{};
    };
    std::vector<robot> r;
    explicit robots(const std::array<state<Tree>, 64>& states) : r(count) {
        for (std::size_t i = 0; i < count; ++i) r[i].s = states[i % 64];
    }
};

template <algorithm A, std::size_t L, class Tree>
void run_batch(const ch::model<Tree, std::conditional_t<L == 1, double, ctga::pack<double, L>>>& m, robots<Tree>& b) {
    using robot = typename robots<Tree>::robot;
    auto& r = b.r;
    if constexpr (L == 1) {
        for (auto& x : r) {
            if constexpr (A == algorithm::rnea) x.out = ch::rnea(m, x.s.q, x.s.qd, x.s.qdd);
            else if constexpr (A == algorithm::aba) x.out = ch::aba(m, x.s.q, x.s.qd, x.s.tau);
            else x.H = ch::crba(m, x.s.q);
        }
    } else {
        const auto q = [](const robot& x) -> const auto& { return x.s.q; };
        const auto qd = [](const robot& x) -> const auto& { return x.s.qd; };
        for (std::size_t first = 0; first < r.size(); first += L) {
            if constexpr (A == algorithm::rnea) {
                const auto qdd = [](const robot& x) -> const auto& { return x.s.qdd; };
                ch::store<L>(ch::rnea(m, ch::load<L>(r, first, q), ch::load<L>(r, first, qd), ch::load<L>(r, first, qdd)), r, first,
                             &robot::out);
            } else if constexpr (A == algorithm::aba) {
                const auto tau = [](const robot& x) -> const auto& { return x.s.tau; };
                ch::store<L>(ch::aba(m, ch::load<L>(r, first, q), ch::load<L>(r, first, qd), ch::load<L>(r, first, tau)), r, first,
                             &robot::out);
            } else {
                ch::store<L>(ch::crba(m, ch::load<L>(r, first, q)), r, first, &robot::H);
            }
        }
    }
}

// batch_<name>/<scalar|pack4|pack8>; n_chain > 0: the tree is an all-revolute chain of that many
// joints, whose Featherstone count gives the Gflop/s and the share of the peak
template <algorithm A, std::size_t L, class Tree>
void add(const std::string& name, const ch::model<Tree>& m, const std::array<state<Tree>, 64>& states, int n_chain) {
    const std::string width = L == 1 ? "scalar" : "pack" + std::to_string(L);
    benchmark::RegisterBenchmark(("batch_" + name + "/" + width).c_str(), [m, states, n_chain](benchmark::State& st) {
        using P = std::conditional_t<L == 1, double, ctga::pack<double, L>>;
        const ch::model<Tree, P> lanes = ch::model_cast<P>(m);
        robots<Tree> b(states);
        for (auto _ : st) {
            run_batch<A, L>(lanes, b);
            benchmark::DoNotOptimize(b.r.data());
            benchmark::ClobberMemory();
        }
        const double n = double(robots<Tree>::count);
        st.counters["per_robot"] = benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
        st.counters["robots_per_s"] = benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
        if (n_chain > 0) {
            const double flops = featherstone_flops(A, n_chain);
            st.counters["gflops"] = benchmark::Counter(n * flops * 1e-9, benchmark::Counter::kIsIterationInvariantRate);
            st.counters["peak_gflops"] = fma_peak(L);
        }
    })->Unit(benchmark::kNanosecond);
}

template <algorithm A, class Tree>
void add_widths(const std::string& name, const ch::model<Tree>& m, const std::array<state<Tree>, 64>& states, int n_chain) {
    add<A, 1>(name, m, states, n_chain);
    add<A, 4>(name, m, states, n_chain);
    add<A, 8>(name, m, states, n_chain);
}

void add_arm7();
void add_tree();
void add_rollouts();
void add_bodies();

}  // namespace bench::batch
