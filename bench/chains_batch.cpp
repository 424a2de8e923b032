// ctga_batch_bench: many robots at once (chains/batch.hpp). RNEA, ABA and CRBA of the 7-dof arm
// and of the legged tree over batches of robots, robot by robot in doubles and 4 or 8 robots per
// instruction stream (ctga::pack<double, 4 | 8>): batch_<algorithm>_<tree>/<scalar|pack4|pack8>
// (chains_batch_arm7.cpp, chains_batch_tree.cpp); rollouts of 1,024 arms by lie_rk4 on one core
// and on all (chains_batch_rollout.cpp); free bodies in scenes/batch.hpp's structure of arrays and
// in packs (chains_batch_bodies.cpp); and this core's FMA peak per width, which the arm's rows
// report beside their rate. Built with -march=native (this target only: bench/CMakeLists.txt).
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "chains_batch.hpp"

namespace bench::batch {
namespace {
// Gflop/s of independent fused multiply-adds a·x + b on L-lane packs (2L flops each): 16
// accumulators held in registers, enough to cover the FMA latency on every FMA unit, the best of 5
// runs. Without GCC's vectorisers: the 16 scalar chains must stay 16 scalar instructions (the
// packs are vector types of their own and stay so).
template <std::size_t L>
[[gnu::optimize("no-tree-vectorize", "no-tree-slp-vectorize")]] double measure_peak() {
    using P = std::conditional_t<L == 1, double, ctga::pack<double, L>>;
    constexpr int chains = 16;
    volatile double seed_a = 0.999999999, seed_b = 1e-9;
    double best = 0;
    for (int run = 0; run < 5; ++run) {
        const P a(seed_a), b(seed_b);
        std::array<P, chains> x;
        for (int c = 0; c < chains; ++c) x[c] = P(1.0 + 0.01 * c);
        const long n = 20'000'000 / long(L);
        const auto t0 = std::chrono::steady_clock::now();
        for (long k = 0; k < n; ++k)
            for (int c = 0; c < chains; ++c) x[c] = x[c] * a + b;
        const auto t1 = std::chrono::steady_clock::now();
        benchmark::DoNotOptimize(x);
        best = std::max(best, 2.0 * double(L) * chains * double(n) / std::chrono::duration<double>(t1 - t0).count() / 1e9);
    }
    return best;
}
}  // namespace

double fma_peak(std::size_t lanes) {
    static const double peak[3] = {measure_peak<1>(), measure_peak<4>(), measure_peak<8>()};
    return lanes == 1 ? peak[0] : lanes == 4 ? peak[1] : peak[2];
}
}  // namespace bench::batch

int main(int argc, char** argv) {
    using namespace bench::batch;
    std::printf("fma peak: %.1f Gflop/s scalar, %.1f in 4 lanes, %.1f in 8 lanes\n", fma_peak(1), fma_peak(4), fma_peak(8));
    add_arm7();
    add_tree();
    add_rollouts();
    add_bodies();
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}
