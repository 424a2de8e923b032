// The clipping step of a contact manifold (collision/convex_manifolds.hpp) written two ways, as
// docs/design.md's collision section reports: the point where segment a b crosses the plane
// n·x = d,
//   clip_segment/vec3   plain 3-vectors: h_a = n·a − d, h_b = n·b − d, x = a + h_a/(h_a − h_b) (b − a)
//                       (what the library uses);
//   clip_segment/pga    ctga::pga: the line a ∨ b (join, 12m 6a), its meet with the plane (12m 8a),
//                       the homogeneous point divided by its weight.
// The same 64 random segments crossing random planes, cycled; both answers checked equal first.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include <benchmark/benchmark.h>

#include <ctga/geometry/pga.hpp>
#include <ctga/mechanics/linear3.hpp>

#include "collision_bench.hpp"

namespace {
using ctga::vec3;
namespace linear3 = ctga::linear3;

struct crossing {
    vec3<double> a, b, n;
    double d;
};

std::array<crossing, 64> make_crossings() {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g;
    std::array<crossing, 64> out{};
    for (crossing& c : out) {
        vec3<double> n{g(rng), g(rng), g(rng)};
        const double l = std::sqrt(linear3::dot(n, n));
        n = linear3::scale(1 / l, n);
        const vec3<double> o{g(rng), g(rng), g(rng)};
        c = {linear3::add_scaled(o, 1.0 + std::abs(g(rng)), n), linear3::add_scaled(o, -1.0 - std::abs(g(rng)), n), n, linear3::dot(n, o)};
        c.a = linear3::add(c.a, vec3<double>{0.3 * g(rng), 0.3 * g(rng), 0.3 * g(rng)});
    }
    return out;
}
const std::array<crossing, 64> crossings = make_crossings();

vec3<double> clip_vec3(const crossing& c) {
    const double ha = linear3::dot(c.n, c.a) - c.d, hb = linear3::dot(c.n, c.b) - c.d;
    return linear3::add_scaled(c.a, ha / (ha - hb), linear3::sub(c.b, c.a));
}
vec3<double> clip_pga(const crossing& c) {
    namespace pga = ctga::pga;
    const pga::line<> l = pga::join(pga::make_point(c.a[0], c.a[1], c.a[2]), pga::make_point(c.b[0], c.b[1], c.b[2]));
    const pga::point<> x = pga::meet(pga::make_plane(c.n[0], c.n[1], c.n[2], -c.d), l);
    const double w = ctga::get<"e1e2e3">(x);
    return {ctga::get<"e0e3e2">(x) / w, ctga::get<"e0e1e3">(x) / w, ctga::get<"e0e2e1">(x) / w};
}

template <vec3<double> (*Clip)(const crossing&)>
void run(benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
        vec3<double> x = Clip(crossings[i]);
        benchmark::DoNotOptimize(x);
        i = (i + 1) & 63;
    }
}
}  // namespace

void bench::collision::register_algebra() {
    for (const crossing& c : crossings) {
        const vec3<double> p = clip_vec3(c), q = clip_pga(c);
        for (std::size_t k = 0; k < 3; ++k)
            if (std::abs(p[k] - q[k]) > 1e-12 * (1 + std::abs(p[k]))) {
                std::fprintf(stderr, "clip_segment: pga and vec3 disagree (%g vs %g)\n", q[k], p[k]);
                std::abort();
            }
    }
    benchmark::RegisterBenchmark("clip_segment/vec3", run<clip_vec3>);
    benchmark::RegisterBenchmark("clip_segment/pga", run<clip_pga>);
}
