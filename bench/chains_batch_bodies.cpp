// ctga_batch_bench's single bodies: 10,000 identical free bodies (inertia_kind::diagonal,
// subspace::full) stepped by classical RK4 with renormalisation, in scenes/batch.hpp
// (batch_bodies/soa: structure of arrays, stepped in packs of this build's width) and as
// hand-made packs of bodies (batch_bodies/pack<L>: ctga::rk4{}.step on body_motion<pack<double,
// L>>, one array of pack states; every lane the numbers of the double step). Reported: the time
// per body-step (per_body_step).
#include <memory>
#include <random>
#include <string>

#include <ctga/integrators/methods.hpp>
#include <ctga/scenes/batch.hpp>

#include "chains_batch.hpp"

namespace bench::batch {
namespace {
namespace kind = ctga::inertia_kind;
using sub = ctga::subspace::full;
constexpr std::size_t bodies = 10'000;
constexpr double h = 1e-3;

template <class T>
constexpr kind::diagonal::data<T> box() {
    return {T(2.0), T(2.0), T(2.5), T(3.0)};
}
using one_body = ctga::body_motion<double, sub, kind::diagonal>;

std::vector<ctga::state_of<one_body>> random_bodies() {
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<ctga::state_of<one_body>> out(bodies);
    for (auto& x : out) {
        x.g = ctga::renormalize(ctga::motor<double>{1 + u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)});
        x.s = ctga::screw<double>{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
    }
    return out;
}

void counters(benchmark::State& st) {
    st.counters["per_body_step"] =
        benchmark::Counter(double(bodies), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <std::size_t L>
void add_packs() {
    benchmark::RegisterBenchmark(("batch_bodies/pack" + std::to_string(L)).c_str(), [](benchmark::State& st) {
        using P = ctga::pack<double, L>;
        using model_t = ctga::body_motion<P, sub, kind::diagonal>;
        const model_t model{box<P>()};
        const auto init = random_bodies();
        std::vector<ctga::state_of<model_t>> x(bodies / L);
        for (std::size_t p = 0; p < x.size(); ++p)
            for (std::size_t l = 0; l < L; ++l) {
                for (std::size_t c = 0; c < 8; ++c) x[p].g[c].set(l, init[p * L + l].g[c]);
                for (std::size_t c = 0; c < 6; ++c) x[p].s[c].set(l, init[p * L + l].s[c]);
            }
        for (auto _ : st) {
            for (auto& y : x) y = ctga::rk4{}.step(model, y, P(h)).value;
            benchmark::DoNotOptimize(x.data());
            benchmark::ClobberMemory();
        }
        counters(st);
    })->Unit(benchmark::kMicrosecond);
}
}  // namespace

void add_bodies() {
    benchmark::RegisterBenchmark("batch_bodies/soa", [](benchmark::State& st) {
        using batch_t = ctga::batch<double, sub, kind::diagonal, bodies>;
        const auto b = std::make_unique<batch_t>(box<double>());  // 1.1 MB: not on the stack
        for (const auto& x : random_bodies()) b->add(x);
        for (auto _ : st) {
            ctga::error_code e = b->step_rk4(h);
            benchmark::DoNotOptimize(e);
            benchmark::ClobberMemory();
        }
        counters(st);
    })->Unit(benchmark::kMicrosecond);
    add_packs<2>();
    add_packs<4>();
    add_packs<8>();
}
}  // namespace bench::batch
