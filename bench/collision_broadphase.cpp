// broadphase_10k/<implementation>: 10,000 boxes moving each step, each iteration one step: every
// proxy given its body's new tight box, then the overlapping pairs collected and counted.
//   ctga    collision::broadphase<double> (broadphase.hpp), margin 0.1 m (Box2D's), no
//           displacement given; move_proxy for each body, then pairs() into a buffer
//   bullet  btDbvtBroadphase (Bullet 3.24, double precision, its defaults: margin 0.05 m, no
//           prediction, hashed pair cache); setAabb for each body, then
//           calculateOverlappingPairs and a pass over the pair cache
// Both sets are supersets of the pairs whose tight boxes overlap (ctga's: the pairs of its fat
// boxes; Bullet's: the pairs its dbvt found, of which it removes 10 % of the stale ones a step),
// so each row counts, from its own candidates, the pairs whose tight boxes overlap: the same work
// for both (two boxes read and compared per candidate), and the same number, checked at
// registration for ten steps (the program stops with a message if they differ), with the ctga
// pairs checked against brute force over all pairs of fat boxes and of tight boxes.
// The scene (deterministic, the same for both): box half extents s (0.5…1.5) per axis with s
// log-uniform in [0.1, 1] m (1 % four times larger), centres uniform in a cube of 40 m, velocities
// up to 2 m/s in random directions reflected at the cube's faces, turning about a random axis at up
// to 2 rad/s, steps of 1/60 s: about 18,600 pairs of overlapping tight boxes. The motion and the
// tight boxes (bounds_of) are computed with the timer paused.
//
//   ctga_collision_bench --benchmark_filter=broadphase --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include <ctga/collision/aabb.hpp>
#include <ctga/collision/box.hpp>
#include <ctga/collision/broadphase.hpp>

#include "collision_bench.hpp"

#ifdef CTGA_BENCH_BULLET
#include <btBulletCollisionCommon.h>
#endif

namespace {

namespace co = ctga::collision;
using ctga::vec3;

constexpr std::size_t bodies = 10'000;
constexpr double half_world = 20.0, dt = 1.0 / 60.0, margin = 0.1;

class scene {
public:
    std::vector<co::aabb<double>> bounds;  // the tight boxes of the current step

    scene() {
        std::mt19937_64 rng(20240607);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        std::normal_distribution<double> n;
        const auto direction = [&] {
            const double x = n(rng), y = n(rng), z = n(rng);
            const double l = std::sqrt(x * x + y * y + z * z);
            return vec3<double>{x / l, y / l, z / l};
        };
        for (std::size_t i = 0; i < bodies; ++i) {
            const double s = (u(rng) < 0.01 ? 4.0 : 1.0) * 0.1 * std::pow(10.0, u(rng));
            const double a = s * (0.5 + u(rng)), b = s * (0.5 + u(rng)), c = s * (0.5 + u(rng));
            body_.push_back({{{a, b, c}}, {}, {}, {}, 0.0, 0.0});
            body& x = body_.back();
            for (double& p : x.position) p = half_world * (2.0 * u(rng) - 1.0);
            const double speed = 2.0 * u(rng);
            const vec3<double> d = direction();
            x.velocity = {speed * d[0], speed * d[1], speed * d[2]};
            x.axis = direction();
            x.angle = 2.0 * std::acos(-1.0) * u(rng);
            x.spin = 2.0 * (2.0 * u(rng) - 1.0);
        }
        bounds.resize(bodies);
        pose();
    }

    void step() {
        for (body& x : body_) {
            for (std::size_t k = 0; k < 3; ++k) {
                x.position[k] += dt * x.velocity[k];
                if ((x.position[k] > half_world && x.velocity[k] > 0.0) || (x.position[k] < -half_world && x.velocity[k] < 0.0))
                    x.velocity[k] = -x.velocity[k];
            }
            x.angle += dt * x.spin;
        }
        pose();
    }

private:
    struct body {
        co::box<double> shape;
        vec3<double> position, velocity, axis;
        double angle, spin;
    };
    std::vector<body> body_;

    // R = cos θ 1 + sin θ [a]× + (1 − cos θ) a aᵀ
    void pose() {
        for (std::size_t i = 0; i < bodies; ++i) {
            const body& x = body_[i];
            const vec3<double>& a = x.axis;
            const double c = std::cos(x.angle), s = std::sin(x.angle), t = 1.0 - c;
            ctga::motor_map<double> m{};
            m.R = {{{c + t * a[0] * a[0], t * a[0] * a[1] - s * a[2], t * a[0] * a[2] + s * a[1]},
                    {t * a[0] * a[1] + s * a[2], c + t * a[1] * a[1], t * a[1] * a[2] - s * a[0]},
                    {t * a[0] * a[2] - s * a[1], t * a[1] * a[2] + s * a[0], c + t * a[2] * a[2]}}};
            m.t = x.position;
            bounds[i] = co::bounds_of(x.shape, m);
        }
    }
};

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "broadphase_10k: %s\n", what);
    std::exit(EXIT_FAILURE);
}

// ---- ctga ----

class ctga_run {
public:
    co::broadphase<double> broadphase{bodies, 8 * bodies, margin};
    std::vector<co::proxy_pair> out = std::vector<co::proxy_pair>(8 * bodies);
    std::size_t candidates = 0;

    explicit ctga_run(const scene& s) {
        for (std::size_t i = 0; i < bodies; ++i)
            if (const auto id = broadphase.create_proxy(s.bounds[i], i); !id || *id != i) fail("ctga: create_proxy failed");
    }

    // The pairs of overlapping tight boxes among the candidates.
    std::size_t step(const scene& s) {
        for (std::size_t i = 0; i < bodies; ++i) broadphase.move_proxy(static_cast<co::proxy_id>(i), s.bounds[i]);
        const auto n = broadphase.pairs(out);
        if (!n) fail("ctga: pair capacity exceeded");
        candidates = *n;
        std::size_t count = 0;
        for (std::size_t k = 0; k < candidates; ++k) count += co::overlaps(s.bounds[out[k].a], s.bounds[out[k].b]);
        return count;
    }
};

// ---- Bullet ----

#ifdef CTGA_BENCH_BULLET
btVector3 bt(const vec3<double>& x) { return {x[0], x[1], x[2]}; }

class bullet_run {
public:
    btDbvtBroadphase broadphase;
    std::vector<btBroadphaseProxy*> proxy;
    std::size_t candidates = 0;

    explicit bullet_run(const scene& s) {
        for (std::size_t i = 0; i < bodies; ++i)
            proxy.push_back(broadphase.createProxy(bt(s.bounds[i].lower), bt(s.bounds[i].upper), BOX_SHAPE_PROXYTYPE,
                                                   reinterpret_cast<void*>(i + 1), 1, -1, nullptr));
        broadphase.calculateOverlappingPairs(nullptr);
    }
    bullet_run(const bullet_run&) = delete;
    bullet_run& operator=(const bullet_run&) = delete;
    ~bullet_run() {
        for (btBroadphaseProxy* p : proxy) broadphase.destroyProxy(p, nullptr);
    }

    std::size_t step(const scene& s) {
        for (std::size_t i = 0; i < bodies; ++i) broadphase.setAabb(proxy[i], bt(s.bounds[i].lower), bt(s.bounds[i].upper), nullptr);
        broadphase.calculateOverlappingPairs(nullptr);
        const btBroadphasePairArray& pairs = broadphase.getOverlappingPairCache()->getOverlappingPairArray();
        candidates = static_cast<std::size_t>(pairs.size());
        std::size_t count = 0;
        for (int k = 0; k < pairs.size(); ++k) {
            const btBroadphaseProxy& a = *pairs[k].m_pProxy0;
            const btBroadphaseProxy& b = *pairs[k].m_pProxy1;
            count += a.m_aabbMin.x() <= b.m_aabbMax.x() && b.m_aabbMin.x() <= a.m_aabbMax.x() && a.m_aabbMin.y() <= b.m_aabbMax.y() &&
                     b.m_aabbMin.y() <= a.m_aabbMax.y() && a.m_aabbMin.z() <= b.m_aabbMax.z() && b.m_aabbMin.z() <= a.m_aabbMax.z();
        }
        return count;
    }
};
#endif

// ---- the checks, once at registration ----

void check() {
    scene s;
    ctga_run c(s);
#ifdef CTGA_BENCH_BULLET
    bullet_run b(s);
#endif
    std::size_t tight = 0;
    for (int step = 0; step < 10; ++step) {
        s.step();
        tight = c.step(s);
#ifdef CTGA_BENCH_BULLET
        if (b.step(s) != tight) fail("ctga and Bullet count different numbers of overlapping tight boxes");
#endif
    }
    // brute force: the candidates are the pairs of overlapping fat boxes, in order; `tight` those of tight boxes
    std::vector<co::aabb<double>> fat(bodies);
    for (std::size_t i = 0; i < bodies; ++i) fat[i] = c.broadphase.fat_box(static_cast<co::proxy_id>(i));
    std::size_t k = 0, brute_tight = 0;
    for (std::size_t i = 0; i < bodies; ++i)
        for (std::size_t j = i + 1; j < bodies; ++j) {
            brute_tight += co::overlaps(s.bounds[i], s.bounds[j]);
            if (!co::overlaps(fat[i], fat[j])) continue;
            if (k == c.candidates || c.out[k].a != i || c.out[k].b != j) fail("ctga's pairs differ from brute force over the fat boxes");
            ++k;
        }
    if (k != c.candidates || brute_tight != tight) fail("ctga's pairs differ from brute force");
}

void time_ctga(benchmark::State& state) {
    scene s;
    ctga_run c(s);
    std::size_t tight = 0;
    for (auto _ : state) {
        state.PauseTiming();
        s.step();
        state.ResumeTiming();
        tight = c.step(s);
        benchmark::DoNotOptimize(tight);
    }
    state.counters["pairs"] = static_cast<double>(tight);
    state.counters["candidates"] = static_cast<double>(c.candidates);
}

#ifdef CTGA_BENCH_BULLET
void time_bullet(benchmark::State& state) {
    scene s;
    bullet_run b(s);
    std::size_t tight = 0;
    for (auto _ : state) {
        state.PauseTiming();
        s.step();
        state.ResumeTiming();
        tight = b.step(s);
        benchmark::DoNotOptimize(tight);
    }
    state.counters["pairs"] = static_cast<double>(tight);
    state.counters["candidates"] = static_cast<double>(b.candidates);
}
#endif

}  // namespace

void bench::collision::register_broadphase() {
    check();
    benchmark::RegisterBenchmark("broadphase_10k/ctga", time_ctga)->Unit(benchmark::kMicrosecond);
#ifdef CTGA_BENCH_BULLET
    benchmark::RegisterBenchmark("broadphase_10k/bullet", time_bullet)->Unit(benchmark::kMicrosecond);
#endif
}
