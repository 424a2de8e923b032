// ctga_bench: every operation of kernels.hpp in every implementation, as Google Benchmarks named
// <operation>/<implementation>. Inputs cycle through a batch of 64 random sets (nothing is
// constant-folded) and every result is consumed.
//
//   ctga_bench [Google Benchmark flags]      time the suite
//   ctga_bench --repeat NAME N               call one kernel N times and exit (for callgrind,
//                                            which counts the instructions of the kernel alone)
#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "kernels.hpp"
#include "runner.hpp"

namespace {

const bench::input_batches& inputs() {
    static const bench::input_batches batches = bench::make_inputs(64, 2024);
    return batches;
}

using bench::entry;

// Registers operation `op` for every implementation: kernel(in) is called with each one's inputs.
template <class Kernel>
void add_operation(std::vector<entry>& table, const std::string& op, Kernel kernel) {
    const auto add = [&](const std::string& impl, const auto& batch) {
        const auto* b = &batch;
        table.push_back({op + "/" + impl,
                         [b, kernel](benchmark::State& state) {
                             std::size_t k = 0;
                             for (auto _ : state) {
                                 auto r = kernel((*b)[k]);
                                 benchmark::DoNotOptimize(r);
                                 k = (k + 1) % b->size();
                             }
                         },
                         [b, kernel](std::size_t n) {
                             for (std::size_t i = 0; i < n; ++i) {
                                 auto r = kernel((*b)[i % b->size()]);
                                 benchmark::DoNotOptimize(r);
                             }
                         }});
    };
    add("ctga", inputs().ctga);
    add("spatial", inputs().spatial);
    add("eigen", inputs().eigen);
    add("dense", inputs().dense);
}

std::vector<entry> all_operations() {
    std::vector<entry> t;
    add_operation(t, "momentum", [](const auto& in) { return bench::momentum(in); });
    add_operation(t, "energy", [](const auto& in) { return bench::energy(in); });
    add_operation(t, "bracket", [](const auto& in) { return bench::bracket(in); });
    add_operation(t, "coadjoint", [](const auto& in) { return bench::coadjoint(in); });
    add_operation(t, "motor_product", [](const auto& in) { return bench::motor_product(in); });
    add_operation(t, "screw_transform", [](const auto& in) { return bench::screw_transform(in); });
    add_operation(t, "coscrew_transform", [](const auto& in) { return bench::coscrew_transform(in); });
    add_operation(t, "inertia_transform", [](const auto& in) { return bench::inertia_transform(in); });
    add_operation(t, "eom", [](const auto& in) { return bench::eom(in); });
    add_operation(t, "step", [](const auto& in) { return bench::step(in); });
    return t;
}

}  // namespace

int main(int argc, char** argv) { return bench::run(all_operations(), argc, argv); }
