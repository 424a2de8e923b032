// A benchmark executable's table and its main: each entry is timed by Google Benchmark under its
// name, or, with `--repeat NAME N`, called N times and nothing else (for callgrind, which then
// counts the instructions of that kernel alone).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

namespace bench {

struct entry {
    std::string name;
    std::function<void(benchmark::State&)> time;
    std::function<void(std::size_t)> repeat;
};

inline int run(const std::vector<entry>& table, int argc, char** argv) {
    if (argc == 4 && std::strcmp(argv[1], "--repeat") == 0) {
        for (const entry& e : table)
            if (e.name == argv[2]) {
                e.repeat(std::strtoull(argv[3], nullptr, 10));
                return 0;
            }
        std::fprintf(stderr, "%s: no kernel named %s\n", argv[0], argv[2]);
        return 2;
    }
    for (const entry& e : table) benchmark::RegisterBenchmark(e.name.c_str(), e.time);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

}  // namespace bench
