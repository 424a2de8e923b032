// ctga_chains_flops: the floating-point operations ctga's RNEA, ABA and CRBA execute on the chain
// benchmarks' trees (bench/chain_models.hpp), counted by running them on a counting scalar
// (counting_scalar.hpp), and this core's scalar peak: independent multiplications and additions
// on doubles, six chains of each, so that no result waits for another (this unit is compiled
// without vectorisation: one double per instruction). Prints TSV lines
//   flops <tree> <algorithm> <mul> <add> <div> <functions>
//   peak <Gflop/s>
// read by tools/render_benchmarks.py (docs/benchmarks.md: how close to the limit).
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "chain_models.hpp"
#include "counting_scalar.hpp"
#include <ctga/chains/model_cast.hpp>

namespace {

using namespace bench::chains;
using bench::counting::real;
using bench::counting::tally;

template <class F>
void count(const char* tree, const char* algorithm, F&& f) {
    tally = {};
    f();
    std::printf("flops\t%s\t%s\t%ld\t%ld\t%ld\t%ld\n", tree, algorithm, tally.mul, tally.add, tally.div, tally.functions);
}

template <class Tree, std::size_t N>
void run(const char* name, const description<N>& d) {
    const auto m = ctga::chains::model_cast<real>(ctga_model<Tree>(d));
    const state<Tree> s = random_states<Tree>(71)[0];
    ch::configuration<Tree, real> q;
    ch::joint_vector<Tree, real> qd, qdd, tau;
    for (std::size_t k = 0; k < Tree::nq; ++k) q[k] = real(s.q[k]);
    for (std::size_t k = 0; k < Tree::nv; ++k) qd[k] = real(s.qd[k]), qdd[k] = real(s.qdd[k]), tau[k] = real(s.tau[k]);
    count(name, "rnea", [&] { (void)ch::rnea(m, q, qd, qdd); });
    count(name, "aba", [&] { (void)ch::aba(m, q, qd, tau); });
    count(name, "crba", [&] { (void)ch::crba(m, q); });
}

// Gflop/s of independent scalar multiplications and additions, the best of 5 runs: six chains of
// each in named variables, held in registers (eight of each would spill: 16 xmm registers), so
// that no operation waits for another's result longer than its latency.
double scalar_peak(int seed) {
    double best = 0;
    for (int run = 0; run < 5; ++run) {
        const double f = 1.0 + 1e-12 * seed, g = 1e-9 * seed;
        double p0 = 1, p1 = 1.1, p2 = 1.2, p3 = 1.3, p4 = 1.4, p5 = 1.5;
        double s0 = 0, s1 = 0.1, s2 = 0.2, s3 = 0.3, s4 = 0.4, s5 = 0.5;
        const long n = 50'000'000;
        const auto t0 = std::chrono::steady_clock::now();
        for (long k = 0; k < n; ++k) {
            p0 *= f, p1 *= f, p2 *= f, p3 *= f, p4 *= f, p5 *= f;
            s0 += g, s1 += g, s2 += g, s3 += g, s4 += g, s5 += g;
        }
        const auto t1 = std::chrono::steady_clock::now();
        if (p0 + p1 + p2 + p3 + p4 + p5 + s0 + s1 + s2 + s3 + s4 + s5 == 0) std::printf("#\n");
        best = std::max(best, 12.0 * static_cast<double>(n) / std::chrono::duration<double>(t1 - t0).count() / 1e9);
    }
    return best;
}

}  // namespace

int main(int argc, char**) {
    run<arm7_tree>("arm7", arm7());
    run<arm7_general_tree>("arm7_general", arm7());  // the arm's joints not declared aligned
    run<chain30_tree>("chain30", chain<30>());
    run<legged_tree>("tree", legged());
    run<legged_tree>("quadruped", solo12());
    run<humanoid_tree>("humanoid", humanoid());
    std::printf("peak\t%.2f\n", scalar_peak(argc));
}
