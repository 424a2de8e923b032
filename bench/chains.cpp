// ctga_chains_bench: forward kinematics, RNEA, CRBA and ABA of kinematic trees in ctga::chains and
// in hand-written spatial code (bench/spatial_chains.hpp), as Google Benchmarks named
// <algorithm>_<tree>/<implementation>: rnea_arm7/ctga, rnea_arm7/spatial, aba_chain30/…, fk_tree/…
// (trees in bench/chain_models.hpp). With CTGA_CHAINS_SCALING it is ctga_chains_scaling instead:
// rnea_chain/<N>/<implementation>, aba_chain/<N>/…, crba_chain/<N>/… for N = 1 … 64 bodies.
//
// Each kernel is one non-inlined call (chain_kernel) on one of 64 random states in memory,
// cycling, so nothing folds and callgrind can count the instructions of a call alone:
//   ctga_chains_bench --repeat NAME N        call one kernel N times and exit
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "chain_models.hpp"

namespace {

using namespace bench::chains;

enum class algorithm { fk, rnea, crba, aba };
enum class implementation { ctga, spatial };

template <class Tree>
struct fixture {
    static constexpr std::size_t n = Tree::size;
    ch::model<Tree> m;
    sp::model<n> sm;
    std::array<state<Tree>, 64> states;
};

template <class Tree>
fixture<Tree> make_fixture(const description<Tree::size>& d, std::uint64_t seed) {
    return {ctga_model<Tree>(d), spatial_model(d), random_states<Tree>(seed)};
}

// What a call returns: the joint vector, the mass matrix, or every body's kinematics.
template <class Tree>
struct spatial_results {
    sp::kinematics<Tree::size> k;
    std::array<double, Tree::nv * Tree::nv> H;
};

template <algorithm A, implementation I, class Tree>
[[gnu::noinline]] auto chain_kernel(const fixture<Tree>& f, const state<Tree>& s) {
    if constexpr (I == implementation::ctga) {
        if constexpr (A == algorithm::fk) return ch::forward_kinematics(f.m, s.q, s.qd, s.qdd);
        else if constexpr (A == algorithm::rnea) return ch::rnea(f.m, s.q, s.qd, s.qdd);
        else if constexpr (A == algorithm::crba) return ch::crba(f.m, s.q);
        else return ch::aba(f.m, s.q, s.qd, s.tau);
    } else {
        if constexpr (A == algorithm::fk) {
            sp::kinematics<Tree::size> k;
            sp::fk(f.sm, s.q_spatial.data(), s.qd.data(), s.qdd.data(), k);
            return k;
        } else if constexpr (A == algorithm::rnea) {
            ch::joint_vector<Tree> tau;
            sp::rnea(f.sm, s.q_spatial.data(), s.qd.data(), s.qdd.data(), nullptr, tau.data());
            return tau;
        } else if constexpr (A == algorithm::crba) {
            std::array<double, Tree::nv * Tree::nv> H;
            sp::crba(f.sm, s.q_spatial.data(), H.data());
            return H;
        } else {
            ch::joint_vector<Tree> qdd;
            sp::aba(f.sm, s.q_spatial.data(), s.qd.data(), s.tau.data(), nullptr, qdd.data());
            return qdd;
        }
    }
}

struct entry {
    std::string name;
    std::function<void(benchmark::State&)> time;
    std::function<void(std::size_t)> repeat;
};

template <algorithm A, implementation I, class Tree>
void add(std::vector<entry>& table, const std::string& name, const fixture<Tree>& f) {
    const fixture<Tree>* p = &f;
    table.push_back({name,
                     [p](benchmark::State& st) {
                         std::size_t k = 0;
                         for (auto _ : st) {
                             auto r = chain_kernel<A, I>(*p, p->states[k]);
                             benchmark::DoNotOptimize(r);
                             k = (k + 1) & 63;
                         }
                     },
                     [p](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) {
                             auto r = chain_kernel<A, I>(*p, p->states[i & 63]);
                             benchmark::DoNotOptimize(r);
                         }
                     }});
}

template <class Tree>
void add_tree(std::vector<entry>& table, const std::string& label, const fixture<Tree>& f, bool with_fk, bool with_crba) {
    const auto both = [&]<algorithm A>(const std::string& name) {
        add<A, implementation::ctga>(table, name + "/ctga", f);
        add<A, implementation::spatial>(table, name + "/spatial", f);
    };
    const auto name = [&](const char* a) { return std::string(a) + "_" + label; };  // rnea_arm7, rnea_chain/8
    both.template operator()<algorithm::rnea>(name("rnea"));
    both.template operator()<algorithm::aba>(name("aba"));
    if (with_crba) both.template operator()<algorithm::crba>(name("crba"));
    if (with_fk) both.template operator()<algorithm::fk>(name("fk"));
}

#ifndef CTGA_CHAINS_SCALING
std::vector<entry> all_kernels() {
    static const auto arm = make_fixture<arm7_tree>(arm7(), 71);
    static const auto chain30 = make_fixture<chain30_tree>(chain<30>(), 72);
    static const auto tree = make_fixture<legged_tree>(legged(), 73);
    std::vector<entry> t;
    add_tree(t, "arm7", arm, true, true);
    add_tree(t, "chain30", chain30, true, true);
    add_tree(t, "tree", tree, true, true);
    return t;
}
#else
template <std::size_t... N>
std::vector<entry> scaling_kernels() {
    std::vector<entry> t;
    (
        [&] {
            static const auto f = make_fixture<chain_tree<N>>(chain<N>(), 100 + N);
            add_tree(t, "chain/" + std::to_string(N), f, false, true);
        }(),
        ...);
    return t;
}
std::vector<entry> all_kernels() { return scaling_kernels<CTGA_CHAINS_SCALING>(); }
#endif

}  // namespace

int main(int argc, char** argv) {
    const std::vector<entry> table = all_kernels();
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
