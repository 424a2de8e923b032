// ctga_collision_bench's entry: registers every source's rows (collision_bench.hpp) and runs them.
#include <benchmark/benchmark.h>

#include "collision_bench.hpp"

int main(int argc, char** argv) {
    bench::collision::register_pairs();
    bench::collision::register_broadphase();
    bench::collision::register_algebra();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
