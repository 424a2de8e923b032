// batch_step/*: 10 000 identical free bodies of inertia_kind::diagonal stepped by classical RK4
// (with renormalisation), in the batch of include/ctga/scenes/batch.hpp (soa: structure of arrays
// stepped in SIMD packs of the target's width, 2 doubles in ctga_bench's SSE2 build; soa_lanes1:
// the same loop with double as the scalar, one body at a time; both rk4's numbers, bit for bit)
// and as an array of motion_states stepped one by one with ctga::rk4{} (aos); subspace::full, and
// subspace::planar (*_planar). items_per_second is body-steps per second. The states are random
// (a fixed seed), the same in both layouts; each iteration is one step of every body, applied to
// the evolving state.
//
//   ctga_bench --benchmark_filter=batch --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <array>
#include <cmath>
#include <memory>
#include <random>

#include <benchmark/benchmark.h>

#include <ctga/scenes/batch.hpp>

namespace {

namespace sub = ctga::subspace;
namespace kind = ctga::inertia_kind;

constexpr std::size_t bodies = 10'000;
constexpr double h = 1e-3;
constexpr kind::diagonal::data<double> box{2.0, 2.0, 2.5, 3.0};  // m, dx, dy, dz

template <class S>
using state_t = ctga::motion_state<typename S::template motor_type<double>, typename S::template screw_type<double>>;

// Body i's random initial state: a rigid motion (axis uniform on the sphere; e3 for planar bodies)
// and a velocity with components in [−1, 1].
template <class S>
state_t<S> random_state(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::normal_distribution<double> n;
    double ax = n(rng), ay = n(rng), az = n(rng);
    const double len = std::sqrt(ax * ax + ay * ay + az * az);
    ax /= len, ay /= len, az /= len;
    double tx = 2 * u(rng), ty = 2 * u(rng), tz = 2 * u(rng);
    if constexpr (std::is_same_v<S, sub::planar>) ax = ay = 0, az = 1, tz = 0;
    const ctga::motor<double> g = ctga::rigid_motion(ctga::make_translator(tx, ty, tz), ctga::make_rotor(3.1 * u(rng), ax, ay, az));
    const ctga::screw<double> s{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
    return {ctga::project<typename S::template motor_type<double>>(g), ctga::project<typename S::template screw_type<double>>(s)};
}

template <class S, std::size_t Lanes>
void soa(benchmark::State& state) {
    using batch_t = ctga::batch<double, S, kind::diagonal, bodies, Lanes>;
    const auto b = std::make_unique<batch_t>(box);  // 1.1 MB for full bodies: not on the stack
    std::mt19937_64 rng(2024);
    for (std::size_t i = 0; i < bodies; ++i) b->add(random_state<S>(rng));
    batch_t* p = b.get();
    benchmark::DoNotOptimize(p);
    for (auto _ : state) {
        ctga::error_code e = p->step_rk4(h);
        benchmark::DoNotOptimize(e);
        benchmark::ClobberMemory();
    }
    if (p->first_non_finite() != p->size()) state.SkipWithError("a body's state became non-finite");
    state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(bodies));
}

template <class S>
void aos(benchmark::State& state) {
    using model_t = ctga::body_motion<double, S, kind::diagonal>;
    const model_t model{box};
    const auto states = std::make_unique<std::array<ctga::state_of<model_t>, bodies>>();
    std::mt19937_64 rng(2024);
    for (auto& x : *states) x = random_state<S>(rng);
    auto* p = states.get();
    benchmark::DoNotOptimize(p);
    for (auto _ : state) {
        ctga::error_code e = ctga::aos_step_rk4(model, *p, h);
        benchmark::DoNotOptimize(e);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(bodies));
}

// Registered at static initialisation, before suite.cpp's main registers the kernel table.
constexpr std::size_t native = ctga::native_lanes<double>;
[[maybe_unused]] benchmark::internal::Benchmark* const registered[] = {
    benchmark::RegisterBenchmark("batch_step/soa", soa<sub::full, native>)->Unit(benchmark::kMicrosecond),
    benchmark::RegisterBenchmark("batch_step/soa_lanes1", soa<sub::full, 1>)->Unit(benchmark::kMicrosecond),
    benchmark::RegisterBenchmark("batch_step/aos", aos<sub::full>)->Unit(benchmark::kMicrosecond),
    benchmark::RegisterBenchmark("batch_step/soa_planar", soa<sub::planar, native>)->Unit(benchmark::kMicrosecond),
    benchmark::RegisterBenchmark("batch_step/soa_planar_lanes1", soa<sub::planar, 1>)->Unit(benchmark::kMicrosecond),
    benchmark::RegisterBenchmark("batch_step/aos_planar", aos<sub::planar>)->Unit(benchmark::kMicrosecond),
};

}  // namespace
