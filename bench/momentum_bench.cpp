// The paper's momentum P = A ∨ (N ∧ s) in Cl(0,6,2): ctga's sparse compile-time evaluation
// against the naive dense 256-component reference. (The full suite of issue 5 builds on this.)
#include <array>
#include <random>

#include <benchmark/benchmark.h>
#include <ctga/ctga.hpp>
#include <ctga/reference/dense.hpp>

namespace {

using G = ctga::cl062;
using screw = G::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
// A general inertia (§5): one blade for each pair (co-screw direction, screw direction), the
// 36 entries of the 6×6 matrix of §2 (symmetric, but each entry has its own blade).
using inertia = G::mv<double,
    "a2a3e2e3", "a2a3e3e1", "a2a3e1e2", "a2a3e1e", "a2a3e2e", "a2a3e3e", "a3a1e2e3", "a3a1e3e1",
    "a3a1e1e2", "a3a1e1e", "a3a1e2e", "a3a1e3e", "a1a2e2e3", "a1a2e3e1", "a1a2e1e2", "a1a2e1e",
    "a1a2e2e", "a1a2e3e", "a1ae2e3", "a1ae3e1", "a1ae1e2", "a1ae1e", "a1ae2e", "a1ae3e", "a2ae2e3",
    "a2ae3e1", "a2ae1e2", "a2ae1e", "a2ae2e", "a2ae3e", "a3ae2e3", "a3ae3e1", "a3ae1e2", "a3ae1e",
    "a3ae2e", "a3ae3e">;

constexpr std::size_t batch = 64;  // inputs cycle through a batch, so nothing is constant-folded

template <class X>
std::array<X, batch> random_batch(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::array<X, batch> out{};
    for (auto& x : out)
        for (std::size_t i = 0; i < X::size(); ++i) x[i] = u(rng);
    return out;
}

void momentum_ctga(benchmark::State& state) {
    constexpr auto A = G::basis<"a1a2a3a">;  // the paper's invariant, an exact constant
    const auto N = random_batch<inertia>(1);
    const auto s = random_batch<screw>(2);
    std::size_t k = 0;
    for (auto _ : state) {
        auto P = eval(A & (N[k] ^ s[k]));
        benchmark::DoNotOptimize(P);
        k = (k + 1) % batch;
    }
}
BENCHMARK(momentum_ctga)->Name("momentum/ctga");

void momentum_dense(benchmark::State& state) {
    using dmv = ctga::dense::multivector<G>;
    const auto A = dmv::blade("a1a2a3a");
    std::array<dmv, batch> N, s;
    const auto Ns = random_batch<inertia>(1);
    const auto ss = random_batch<screw>(2);
    for (std::size_t i = 0; i < batch; ++i) {
        N[i] = ctga::dense::to_dense(Ns[i]);
        s[i] = ctga::dense::to_dense(ss[i]);
    }
    std::size_t k = 0;
    for (auto _ : state) {
        auto P = ctga::dense::vee(A, ctga::dense::wedge(N[k], s[k]));
        benchmark::DoNotOptimize(P);
        k = (k + 1) % batch;
    }
}
BENCHMARK(momentum_dense)->Name("momentum/dense");

}  // namespace
