// ctga_contact_bench: scenes of many bodies that touch (scenes/world.hpp) beside Bullet 3.24
// (btDiscreteDynamicsWorld at its defaults, double precision) and MuJoCo 2.2.2 (its defaults:
// Newton, pyramidal cones; free bodies, the grid's joints as `connect` equalities), on the scenes of
// ../shared/reference/contact.md (Box3D's definitions, so that figures compare):
//   large_pyramid  5,050 unit cubes (half extent 0.5, density 100) in a pyramid of base 100 on a
//                  ground box (400, 1, 400) at y = −1, friction 0.6; gravity 10 down; 60 Hz; 200
//                  steps from rest
//   joint_grid     100 × 100 spheres of radius 0.4 (density 1) at (k, −i, 0), row 0 fixed;
//                  spherical joints to the neighbour above and to the left; the spheres do not
//                  collide; 100 steps
// <scene>/ctga_2threads splits the bodies in two parts swept at once (world_settings::partitions),
// which changes the order of the sweeps, not the problem. Each iteration runs the whole scene from its start. Counters: ms_per_step, and the scene's
// accuracy: the top cube's displacement at the end (drift, m), the largest penetration seen (m),
// the largest joint gap seen (m). ctga at its settings (world_settings: a tolerance on the
// natural-map residual and a budget of sweeps); the work–precision rows <scene>_work/ctga_<n>
// give it a budget of n sweeps.
//
//   ctga_contact_bench --benchmark_filter=joint_grid
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>
#include <cstdlib>

#include <benchmark/benchmark.h>

#include <ctga/collision/box.hpp>
#include <ctga/collision/half_space.hpp>
#include <ctga/collision/sphere.hpp>
#include <ctga/scenes/world.hpp>

#ifdef CTGA_BENCH_BULLET
#include <btBulletDynamicsCommon.h>
#endif
#ifdef CTGA_BENCH_MUJOCO
#include <cstdio>
#include <sstream>

#include "mujoco_xml.hpp"
#endif

namespace {

using ctga::motor;
namespace collision = ctga::collision;
constexpr double h = 1.0 / 60, gravity = 10.0;
constexpr int pyramid_base = 100, pyramid_steps = 200;
constexpr int grid_size = 100, grid_steps = 100;
constexpr double cube_half = 0.5, cube_density = 100.0, friction = 0.6;
constexpr double sphere_radius = 0.4, sphere_density = 1.0;

struct scene_result {
    double ms_per_step = 0, drift = 0, penetration = 0, joint_error = 0;
};

void report(benchmark::State& state, const scene_result& r) {
    state.counters["ms_per_step"] = r.ms_per_step;
    state.counters["drift"] = r.drift;
    state.counters["penetration"] = r.penetration;
    state.counters["joint_error"] = r.joint_error;
}

// cube j of row i of the pyramid
ctga::vec3<double> pyramid_cube(int i, int j) {
    return {(i + 1) * cube_half + 2 * (j - i) * cube_half - pyramid_base * cube_half, (2 * i + 1) * cube_half, 0.0};
}

template <class Run>
scene_result timed(int steps, Run&& run) {
    scene_result r;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) run(r);
    r.ms_per_step = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / steps;
    return r;
}

// ---- ctga ------------------------------------------------------------------------------------

using cube = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, collision::box<double>>;
using ball = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::sphere, collision::sphere<double>>;

ctga::world_settings<double> ctga_settings(std::size_t sweeps, std::size_t threads = 1) {
    ctga::world_settings<double> s;
    s.threads = threads;
    s.partitions = threads;  // one part per thread (one thread and two parts give the same numbers as two threads)
    s.gravity = {0.0, -gravity, 0.0};
    s.solver.tolerance = 1e-6;
    s.solver.max_sweeps = sweeps;
    s.solver.check_every = 4;
    return s;
}

scene_result ctga_pyramid(std::size_t sweeps, std::size_t threads = 1) {
    constexpr std::size_t n = pyramid_base * (pyramid_base + 1) / 2;
    auto w = std::make_unique<ctga::physics_world<double, collision::box<double>, cube>>(
        std::array<std::size_t, 1>{n}, ctga::world_capacity{.statics = 1, .contacts = 16 * n, .pairs = 8 * n}, ctga_settings(sweeps, threads));
    w->add_static(*collision::make_box(400.0, 1.0, 400.0), motor<double>(ctga::make_translator(0.0, -1.0, 0.0)), {friction, 0.0});
    const auto box = *collision::make_box(cube_half, cube_half, cube_half);
    for (int i = 0; i < pyramid_base; ++i)
        for (int j = i; j < pyramid_base; ++j) {
            const ctga::vec3<double> c = pyramid_cube(i, j);
            w->add_body<0>(box, cube_density, motor<double>(ctga::make_translator(c[0], c[1], c[2])), {friction, 0.0});
        }
    const ctga::vec3<double> top = pyramid_cube(pyramid_base - 1, pyramid_base - 1);
    scene_result r = timed(pyramid_steps, [&](scene_result& out) {
        const ctga::step_report<double> s = w->step(h);
        out.penetration = std::max(out.penetration, s.penetration);
    });
    const ctga::vec3<double> d = ctga::linear3::sub(ctga::map_of(w->pose<0>(n - 1)).t, top);
    r.drift = std::sqrt(ctga::linear3::dot(d, d));
    return r;
}

scene_result ctga_grid(std::size_t sweeps, std::size_t threads = 1) {
    constexpr std::size_t n = (grid_size - 1) * grid_size;
    auto w = std::make_unique<ctga::physics_world<double, collision::half_space<double>, ball>>(
        std::array<std::size_t, 1>{n}, ctga::world_capacity{.statics = 0, .contacts = 16, .pairs = 16, .joints = 2 * n},
        ctga_settings(sweeps, threads));
    collision::filter none;
    none.group = -1;  // the spheres do not collide
    const auto sphere = *collision::make_sphere(sphere_radius);
    const auto id = [](int i, int k) { return static_cast<std::size_t>((i - 1) * grid_size + k); };
    for (int i = 1; i < grid_size; ++i)
        for (int k = 0; k < grid_size; ++k)
            w->add_body<0>(sphere, sphere_density, motor<double>(ctga::make_translator(double(k), double(-i), 0.0)), {}, {}, none);
    for (int i = 1; i < grid_size; ++i)
        for (int k = 0; k < grid_size; ++k) {
            if (i == 1) w->add_joint({ctga::body<0>(id(i, k)), ctga::ground, {0.0, 0.5, 0.0}, {double(k), -0.5, 0.0}});
            else w->add_joint({ctga::body<0>(id(i, k)), ctga::body<0>(id(i - 1, k)), {0.0, 0.5, 0.0}, {0.0, -0.5, 0.0}});
            if (k > 0) w->add_joint({ctga::body<0>(id(i, k)), ctga::body<0>(id(i, k - 1)), {-0.5, 0.0, 0.0}, {0.5, 0.0, 0.0}});
        }
    return timed(grid_steps, [&](scene_result& out) {
        const ctga::step_report<double> s = w->step(h);
        out.joint_error = std::max(out.joint_error, s.joint_error);
    });
}

// ---- Bullet ----------------------------------------------------------------------------------

#ifdef CTGA_BENCH_BULLET
struct bullet_world {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btDefaultMotionState>> states;
    std::vector<std::unique_ptr<btRigidBody>> bodies;
    std::vector<std::unique_ptr<btTypedConstraint>> joints;

    bullet_world() { world.setGravity(btVector3(0, -gravity, 0)); }
    ~bullet_world() {
        for (auto& j : joints) world.removeConstraint(j.get());
        for (auto& b : bodies) world.removeRigidBody(b.get());
    }
    btRigidBody* add(btCollisionShape* shape, double mass, const btVector3& at, double mu, int group = 1, int mask = -1) {
        btTransform p;
        p.setIdentity();
        p.setOrigin(at);
        btVector3 inertia(0, 0, 0);
        if (mass > 0) shape->calculateLocalInertia(mass, inertia);
        states.push_back(std::make_unique<btDefaultMotionState>(p));
        btRigidBody::btRigidBodyConstructionInfo info(mass, states.back().get(), shape, inertia);
        info.m_friction = mu;
        bodies.push_back(std::make_unique<btRigidBody>(info));
        bodies.back()->setActivationState(DISABLE_DEACTIVATION);
        world.addRigidBody(bodies.back().get(), group, mask);
        return bodies.back().get();
    }
    double penetration() {
        double deepest = 0;
        for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
            const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
            for (int c = 0; c < m->getNumContacts(); ++c) deepest = std::max(deepest, -double(m->getContactPoint(c).getDistance()));
        }
        return deepest;
    }
};

scene_result bullet_pyramid() {
    bullet_world b;
    b.shapes.push_back(std::make_unique<btBoxShape>(btVector3(400, 1, 400)));
    b.add(b.shapes.back().get(), 0.0, btVector3(0, -1, 0), friction);
    b.shapes.push_back(std::make_unique<btBoxShape>(btVector3(cube_half, cube_half, cube_half)));
    const double mass = cube_density * 8 * cube_half * cube_half * cube_half;
    btRigidBody* top = nullptr;
    for (int i = 0; i < pyramid_base; ++i)
        for (int j = i; j < pyramid_base; ++j) {
            const ctga::vec3<double> c = pyramid_cube(i, j);
            top = b.add(b.shapes.back().get(), mass, btVector3(c[0], c[1], c[2]), friction);
        }
    const btVector3 start = top->getWorldTransform().getOrigin();
    scene_result r = timed(pyramid_steps, [&](scene_result& out) {
        b.world.stepSimulation(h, 0, h);
        out.penetration = std::max(out.penetration, b.penetration());
    });
    r.drift = (top->getWorldTransform().getOrigin() - start).length();
    return r;
}

scene_result bullet_grid() {
    bullet_world b;
    b.shapes.push_back(std::make_unique<btSphereShape>(sphere_radius));
    const double mass = sphere_density * 4.0 / 3.0 * M_PI * sphere_radius * sphere_radius * sphere_radius;
    std::vector<btRigidBody*> s(grid_size * grid_size);
    for (int i = 0; i < grid_size; ++i)
        for (int k = 0; k < grid_size; ++k) s[i * grid_size + k] = b.add(b.shapes.back().get(), i == 0 ? 0.0 : mass, btVector3(k, -i, 0), 0.6, 1, 0);
    for (int i = 1; i < grid_size; ++i)
        for (int k = 0; k < grid_size; ++k) {
            b.joints.push_back(std::make_unique<btPoint2PointConstraint>(*s[i * grid_size + k], *s[(i - 1) * grid_size + k], btVector3(0, 0.5, 0),
                                                                         btVector3(0, -0.5, 0)));
            b.world.addConstraint(b.joints.back().get(), true);
            if (k == 0) continue;
            b.joints.push_back(std::make_unique<btPoint2PointConstraint>(*s[i * grid_size + k], *s[i * grid_size + k - 1], btVector3(-0.5, 0, 0),
                                                                         btVector3(0.5, 0, 0)));
            b.world.addConstraint(b.joints.back().get(), true);
        }
    return timed(grid_steps, [&](scene_result& out) {
        b.world.stepSimulation(h, 0, h);
        for (int i = 1; i < grid_size; ++i)
            for (int k = 0; k < grid_size; ++k) {
                const btVector3 p = s[i * grid_size + k]->getWorldTransform() * btVector3(0, 0.5, 0);
                const btVector3 q = s[(i - 1) * grid_size + k]->getWorldTransform() * btVector3(0, -0.5, 0);
                out.joint_error = std::max(out.joint_error, double((p - q).length()));
            }
    });
}
#endif

#ifdef CTGA_BENCH_MUJOCO
// room for the scenes' constraints (MuJoCo 2.2's defaults hold a few thousand)
constexpr const char* size_for_scenes = "<size njmax='400000' nconmax='200000' nstack='60000000'/>";

// MuJoCo 2.2.2 allocates its constraint Jacobian densely, njmax × nv numbers (mjdata.h: efc_J):
// the gigabytes a scene of nv degrees of freedom and `rows` constraint rows needs.
double mujoco_jacobian_gb(double nv, double rows) { return nv * rows * 8 / 1e9; }

struct mujoco_scene {
    mjModel* m = nullptr;
    mjData* d = nullptr;
    explicit mujoco_scene(const std::string& xml) {
        std::string error;
        m = bench::load_mjcf(xml, "ctga_contact.xml", error);
        if (!m) {
            std::fprintf(stderr, "ctga_contact_bench: MuJoCo refused the model: %s\n", error.c_str());
            std::exit(1);
        }
        d = mj_makeData(m);
    }
    ~mujoco_scene() {
        mj_deleteData(d);
        mj_deleteModel(m);
    }
    double penetration() const {
        double deepest = 0;
        for (int c = 0; c < d->ncon; ++c) deepest = std::max(deepest, -double(d->contact[c].dist));
        return deepest;
    }
};

// free cubes on a ground box; the geoms' friction 0.6 (MuJoCo takes the larger of two), density 100
scene_result mujoco_pyramid() {
    std::ostringstream x;
    x << "<mujoco><option timestep='" << h << "' gravity='0 " << -gravity << " 0'/>" << size_for_scenes
      << "<default><geom friction='" << friction << " 0.005 0.0001' density='" << cube_density << "'/></default><worldbody>"
      << "<geom type='box' size='400 1 400' pos='0 -1 0'/>";
    for (int i = 0; i < pyramid_base; ++i)
        for (int j = i; j < pyramid_base; ++j) {
            const ctga::vec3<double> c = pyramid_cube(i, j);
            x << "<body pos='" << c[0] << ' ' << c[1] << ' ' << c[2] << "'><freejoint/><geom type='box' size='" << cube_half << ' ' << cube_half
              << ' ' << cube_half << "'/></body>";
        }
    x << "</worldbody></mujoco>";
    mujoco_scene s(x.str());
    const int top = s.m->nbody - 1;
    mj_forward(s.m, s.d);
    const ctga::vec3<double> start{s.d->xpos[3 * top], s.d->xpos[3 * top + 1], s.d->xpos[3 * top + 2]};
    scene_result r = timed(pyramid_steps, [&](scene_result& out) {
        mj_step(s.m, s.d);
        out.penetration = std::max(out.penetration, s.penetration());
    });
    const ctga::vec3<double> end{s.d->xpos[3 * top], s.d->xpos[3 * top + 1], s.d->xpos[3 * top + 2]};
    const ctga::vec3<double> d = ctga::linear3::sub(end, start);
    r.drift = std::sqrt(ctga::linear3::dot(d, d));
    return r;
}

// free spheres that collide with nothing (contype 0), the joints as `connect` equalities, row 0 fixed
scene_result mujoco_grid() {
    std::ostringstream x;
    x << "<mujoco><option timestep='" << h << "' gravity='0 " << -gravity << " 0'/>" << size_for_scenes << "<worldbody>";
    const auto name = [](int i, int k) {  // (appended piece by piece: GCC 12 warns, -Wrestrict, on "literal" + std::string&&)
        std::string out(1, 'b');
        out += std::to_string(i);
        out += '_';
        out += std::to_string(k);
        return out;
    };
    for (int i = 1; i < grid_size; ++i)
        for (int k = 0; k < grid_size; ++k)
            x << "<body name='" << name(i, k) << "' pos='" << k << ' ' << -i << " 0'><freejoint/><geom type='sphere' size='" << sphere_radius
              << "' density='" << sphere_density << "' contype='0' conaffinity='0'/></body>";
    x << "</worldbody><equality>";
    for (int i = 1; i < grid_size; ++i)
        for (int k = 0; k < grid_size; ++k) {
            if (i == 1) x << "<connect body1='" << name(i, k) << "' anchor='0 0.5 0'/>";
            else x << "<connect body1='" << name(i, k) << "' body2='" << name(i - 1, k) << "' anchor='0 0.5 0'/>";
            if (k > 0) x << "<connect body1='" << name(i, k) << "' body2='" << name(i, k - 1) << "' anchor='-0.5 0 0'/>";
        }
    x << "</equality></mujoco>";
    mujoco_scene s(x.str());
    // a body's point p (its frame) in the world
    const auto at = [&](int body, const ctga::vec3<double>& p) {
        const double* R = s.d->xmat + 9 * body;
        const double* t = s.d->xpos + 3 * body;
        return ctga::vec3<double>{R[0] * p[0] + R[1] * p[1] + R[2] * p[2] + t[0], R[3] * p[0] + R[4] * p[1] + R[5] * p[2] + t[1],
                                  R[6] * p[0] + R[7] * p[1] + R[8] * p[2] + t[2]};
    };
    return timed(grid_steps, [&](scene_result& out) {
        mj_step(s.m, s.d);
        for (int i = 2; i < grid_size; ++i)
            for (int k = 0; k < grid_size; ++k) {
                const int b = (i - 1) * grid_size + k + 1, above = (i - 2) * grid_size + k + 1;
                const ctga::vec3<double> d = ctga::linear3::sub(at(b, {0.0, 0.5, 0.0}), at(above, {0.0, -0.5, 0.0}));
                out.joint_error = std::max(out.joint_error, std::sqrt(ctga::linear3::dot(d, d)));
            }
    });
}
#endif

template <class Scene>
void run(benchmark::State& state, Scene scene) {
    scene_result r;
    for (auto _ : state) r = scene();
    report(state, r);
}

#ifdef CTGA_BENCH_MUJOCO
// MuJoCo's rows when its Jacobian fits in 8 GB; else the row says why not
template <class Scene>
void run_mujoco(benchmark::State& state, double nv, double rows, Scene scene) {
    const double gb = mujoco_jacobian_gb(nv, rows);
    if (gb > 8) {
        const std::string why = "MuJoCo 2.2.2 allocates its constraint Jacobian densely (njmax x nv): " + std::to_string(int(gb)) + " GB";
        state.SkipWithError(why.c_str());
        for (auto _ : state) {}
        return;
    }
    run(state, scene);
}
#endif

void register_all() {
    const auto add = [](const std::string& name, auto scene) {
        benchmark::RegisterBenchmark(name.c_str(), [scene](benchmark::State& s) { run(s, scene); })
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1)
            ->UseRealTime();
    };
    add("large_pyramid/ctga", [] { return ctga_pyramid(100); });
    add("large_pyramid/ctga_2threads", [] { return ctga_pyramid(100, 2); });
    add("joint_grid/ctga", [] { return ctga_grid(100); });
    add("joint_grid/ctga_2threads", [] { return ctga_grid(100, 2); });
    for (const std::size_t sweeps : {4, 10, 30})
        add("joint_grid_work/ctga_" + std::to_string(sweeps), [sweeps] { return ctga_grid(sweeps); });
#ifdef CTGA_BENCH_BULLET
    add("large_pyramid/bullet", bullet_pyramid);
    add("joint_grid/bullet", bullet_grid);
#endif
#ifdef CTGA_BENCH_MUJOCO
    // (rows: the grid's 3 per joint; the pyramid's about 12 contact points per cube, 4 rows each with pyramidal cones)
    const auto add_mujoco = [](const std::string& name, double nv, double rows, auto scene) {
        benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& s) { run_mujoco(s, nv, rows, scene); })
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1)
            ->UseRealTime();
    };
    add_mujoco("large_pyramid/mujoco", 6.0 * pyramid_base * (pyramid_base + 1) / 2, 48.0 * pyramid_base * (pyramid_base + 1) / 2, mujoco_pyramid);
    add_mujoco("joint_grid/mujoco", 6.0 * (grid_size - 1) * grid_size, 6.0 * (grid_size - 1) * grid_size, mujoco_grid);
#endif
}

}  // namespace

int main(int argc, char** argv) {
    register_all();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
