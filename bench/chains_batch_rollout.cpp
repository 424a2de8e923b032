// ctga_batch_bench's rollouts: 1,024 arms (bench/chain_trees.hpp's 7-dof arm, passive: τ = 0)
// stepped 1,000 times by ctga::lie_rk4 (four ABA evaluations a step, chains/motion.hpp) from
// random states: batch_rollout_arm7/<width> on one core and batch_rollout_arm7/<width>_threads on
// every core (chains::for_each_pack, one contiguous run of packs per std::thread). Reported: the
// time per robot-step (per_robot_step).
#include <string>
#include <thread>

#include <ctga/chains/motion.hpp>
#include <ctga/integrators/methods.hpp>

#include "chains_batch.hpp"

namespace bench::batch {
namespace {
using Tree = chains::arm7_tree;
constexpr std::size_t arms = 1024;
constexpr int steps = 1000;
constexpr double h = 1e-3;

struct arm {
    ch::configuration<Tree> q{};
    ch::joint_vector<Tree> qd{};
};

template <std::size_t L>
void roll(const ch::tree_motion<Tree, std::conditional_t<L == 1, double, ctga::pack<double, L>>>& sim, std::vector<arm>& a,
          unsigned threads) {
    using P = typename std::remove_cvref_t<decltype(sim)>::scalar_type;
    ch::for_each_pack<L>(a.size(), threads, [&](std::size_t first) {
        ctga::state_of<std::remove_cvref_t<decltype(sim)>> x;
        if constexpr (L == 1) {
            x.g.x = a[first].q, x.s.x = a[first].qd;
        } else {
            x.g.x = ch::load<L>(a, first, &arm::q);
            x.s.x = ch::load<L>(a, first, &arm::qd);
        }
        for (int k = 0; k < steps; ++k) x = ctga::lie_rk4{}.step(sim, x, P(h)).value;
        if constexpr (L == 1) {
            a[first].q = x.g.x, a[first].qd = x.s.x;
        } else {
            ch::store<L>(x.g.x, a, first, &arm::q);
            ch::store<L>(x.s.x, a, first, &arm::qd);
        }
    });
}

template <std::size_t L>
void add_rollout(const ch::model<Tree>& m, const std::array<chains::state<Tree>, 64>& states, bool all_cores) {
    const std::string name = "batch_rollout_arm7/" + std::string(L == 1 ? "scalar" : "pack" + std::to_string(L)) + (all_cores ? "_threads" : "");
    benchmark::RegisterBenchmark(name.c_str(), [m, states, all_cores](benchmark::State& st) {
        using P = std::conditional_t<L == 1, double, ctga::pack<double, L>>;
        const ch::tree_motion<Tree, P> sim{ch::model_cast<P>(m)};
        std::vector<arm> a(arms);
        for (auto _ : st) {
            st.PauseTiming();
            for (std::size_t i = 0; i < arms; ++i) a[i] = {states[i % 64].q, states[i % 64].qd};
            st.ResumeTiming();
            roll<L>(sim, a, all_cores ? 0 : 1);
            benchmark::DoNotOptimize(a.data());
        }
        st.counters["per_robot_step"] = benchmark::Counter(double(arms) * steps, benchmark::Counter::kIsIterationInvariantRate |
                                                                                     benchmark::Counter::kInvert);
        st.counters["threads"] = all_cores ? std::thread::hardware_concurrency() : 1;
    })->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
}
}  // namespace

void add_rollouts() {
    const auto m = chains::ctga_model<Tree>(chains::arm7());
    const auto states = chains::random_states<Tree>(71);
    for (const bool all_cores : {false, true}) {
        add_rollout<1>(m, states, all_cores);
        add_rollout<4>(m, states, all_cores);
        add_rollout<8>(m, states, all_cores);
    }
}
}  // namespace bench::batch
