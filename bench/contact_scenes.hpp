// The pieces every scene of ctga_contact_bench shares (contact.cpp, contact_pile.cpp): the
// step and gravity, a row's figures and its counters, the timing, ctga's settings, Bullet's world
// and MuJoCo's scene, and a row's registration.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <ctga/scenes/world.hpp>

#ifdef CTGA_BENCH_BULLET
#include <btBulletDynamicsCommon.h>
#endif
#ifdef CTGA_BENCH_ODE
#include <ode/ode.h>
#endif
#ifdef CTGA_BENCH_MUJOCO
#include <cstdio>

#include "mujoco_xml.hpp"
#endif

namespace bench {

inline constexpr double h = 1.0 / 60, gravity = 10.0;

struct scene_result {
    double ms_per_step = 0, drift = 0, penetration = 0, joint_error = 0, slip = 0, residual = 0, speed = 0;
    std::string failed;  // why the row's figures do not count (a peer dropped contacts)
};

inline void report(benchmark::State& state, const scene_result& r) {
    state.counters["ms_per_step"] = r.ms_per_step;
    state.counters["drift"] = r.drift;
    state.counters["penetration"] = r.penetration;
    state.counters["joint_error"] = r.joint_error;
    state.counters["slip"] = r.slip;
    state.counters["residual"] = r.residual;
    state.counters["speed"] = r.speed;
}

// a ctga step's error fails the row (its figures would not be the scene's)
inline void note(scene_result& out, const ctga::step_report<double>& s) {
    if (s.error != ctga::error_code::none && out.failed.empty()) out.failed = std::string("ctga's step failed: ") + ctga::describe(s.error);
}

template <class Run>
scene_result timed(int steps, Run&& run) {
    scene_result r;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) run(r);
    r.ms_per_step = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / steps;
    return r;
}

// substeps > 0: the soft step (constraints/soft_step.hpp) with that many substeps, sweeps unused
inline ctga::world_settings<double> ctga_settings(std::size_t sweeps, std::size_t threads = 1, double tolerance = 1e-6, std::size_t substeps = 0) {
    ctga::world_settings<double> s;
    s.threads = threads;
    s.partitions = threads;  // one part per thread (one thread and two parts give the same numbers as two threads)
    s.gravity = {0.0, -gravity, 0.0};
    s.solver.tolerance = tolerance;
    s.solver.max_sweeps = sweeps;
    s.solver.check_every = 4;
    s.substeps = substeps;
    return s;
}

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

    explicit bullet_world(int iterations = 10, const btVector3& g = btVector3(0, -gravity, 0)) {
        world.setGravity(g);
        world.getSolverInfo().m_numIterations = iterations;
    }
    ~bullet_world() {
        for (auto& j : joints) world.removeConstraint(j.get());
        for (auto& b : bodies) world.removeRigidBody(b.get());
    }
    // (Bullet's friction between two bodies is the product of theirs: each is given √μ)
    btRigidBody* add(btCollisionShape* shape, double mass, const btVector3& at, double mu, int group = 1, int mask = -1) {
        btTransform p;
        p.setIdentity();
        p.setOrigin(at);
        btVector3 inertia(0, 0, 0);
        if (mass > 0) shape->calculateLocalInertia(mass, inertia);
        return add(shape, mass, inertia, p, mu, group, mask);
    }
    // at a pose, with the principal moments given (Bullet's own for a hull are its box's)
    btRigidBody* add(btCollisionShape* shape, double mass, const btVector3& inertia, const btTransform& p, double mu, int group = 1, int mask = -1) {
        states.push_back(std::make_unique<btDefaultMotionState>(p));
        btRigidBody::btRigidBodyConstructionInfo info(mass, states.back().get(), shape, inertia);
        info.m_friction = std::sqrt(mu);
        bodies.push_back(std::make_unique<btRigidBody>(info));
        bodies.back()->setActivationState(DISABLE_DEACTIVATION);
        if (mass == 0 && group == 1 && mask == -1)  // (as Bullet's own default: static bodies do not meet each other)
            group = btBroadphaseProxy::StaticFilter, mask = btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter;
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
#endif

#ifdef CTGA_BENCH_ODE
// ODE 0.16 (double precision) at its defaults: dWorldQuickStep (20 iterations, ERP 0.2, CFM 1e-5),
// a hash space, up to 8 contact points a pair, each a contact joint with Coulomb friction μ
// scaled by the normal force (dContactApprox1: ODE's friction pyramid).
struct ode_world {
    dWorldID world;
    dSpaceID space;
    dJointGroupID contacts;
    double mu = 0.6, deepest = 0;
    explicit ode_world(double gx = 0, double gy = -gravity, double gz = 0) {
        dInitODE2(0);
        world = dWorldCreate();
        space = dHashSpaceCreate(nullptr);
        contacts = dJointGroupCreate(0);
        dWorldSetGravity(world, gx, gy, gz);
    }
    ode_world(const ode_world&) = delete;
    ode_world& operator=(const ode_world&) = delete;
    ~ode_world() {
        dJointGroupDestroy(contacts);
        dSpaceDestroy(space);
        dWorldDestroy(world);
        dCloseODE();
    }
    // a body of mass m and principal moments at a pose, its geom (if any) attached
    dBodyID add(dGeomID geom, double m, const ctga::vec3<double>& moments, const ctga::motor_map<double>& at) {
        dBodyID b = dBodyCreate(world);
        dMass mass;
        dMassSetParameters(&mass, m, 0, 0, 0, moments[0], moments[1], moments[2], 0, 0, 0);
        dBodySetMass(b, &mass);
        dMatrix3 R;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j) R[4 * i + j] = j < 3 ? at.R[i][j] : 0.0;
        dBodySetRotation(b, R);
        dBodySetPosition(b, at.t[0], at.t[1], at.t[2]);
        if (geom) dGeomSetBody(geom, b);
        return b;
    }
    static void near(void* self, dGeomID a, dGeomID b) {
        auto& w = *static_cast<ode_world*>(self);
        dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
        if (!ba && !bb) return;
        dContact c[8];
        const int n = dCollide(a, b, 8, &c[0].geom, sizeof(dContact));
        for (int i = 0; i < n; ++i) {
            c[i].surface.mode = dContactApprox1;
            c[i].surface.mu = w.mu;
            w.deepest = std::max(w.deepest, double(c[i].geom.depth));
            dJointAttach(dJointCreateContact(w.world, w.contacts, &c[i]), ba, bb);
        }
    }
    void step(double dt) {
        dSpaceCollide(space, this, &near);
        dWorldQuickStep(world, dt);
        dJointGroupEmpty(contacts);
    }
};
#endif

#ifdef CTGA_BENCH_MUJOCO
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
#endif

template <class Scene>
void run(benchmark::State& state, Scene scene) {
    scene_result r;
    for (auto _ : state) r = scene();
    if (!r.failed.empty()) state.SkipWithError(r.failed.c_str());
    report(state, r);
}

// a row: one run of the scene, its time per step in milliseconds
template <class Scene>
void add_scene(const std::string& name, Scene scene) {
    benchmark::RegisterBenchmark(name.c_str(), [scene](benchmark::State& s) { run(s, scene); })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1)
        ->UseRealTime();
}

}  // namespace bench
