// ctga_contact_bench: scenes of many bodies that touch (scenes/world.hpp) beside Bullet 3.24
// (btDiscreteDynamicsWorld at its defaults, double precision), MuJoCo 2.2.2 (its defaults:
// Newton, pyramidal cones; free bodies, the grid's joints as `connect` equalities) and ODE 0.16
// (quickstep at its defaults; the grid's joints as ball joints), on the scenes of
// ../shared/reference/contact.md (Box3D's definitions, so that figures compare):
//   large_pyramid  5,050 unit cubes (half extent 0.5, density 100) in a pyramid of base 100 on a
//                  ground box (400, 1, 400) at y = −1, friction 0.6; gravity 10 down; 60 Hz; 200
//                  steps from rest
//   joint_grid     100 × 100 spheres of radius 0.4 (density 1) at (k, −i, 0), row 0 fixed;
//                  spherical joints to the neighbour above and to the left; the spheres do not
//                  collide; 100 steps
// <scene>/ctga_2threads splits the bodies in two parts swept at once (world_settings::partitions),
// which changes the order of the sweeps, not the problem. ctga_soft_<n>: the soft step
// (constraints/soft_step.hpp) with n substeps, to no tolerance (its _2threads: the same numbers). Each iteration runs the whole scene from its start. Counters: ms_per_step, and the scene's
// accuracy: the top cube's displacement at the end (drift, m), the largest penetration seen (m),
// the largest joint gap seen (m). ctga at its settings (world_settings: a tolerance on the
// natural-map residual and a budget of sweeps); the work–precision rows <scene>_work/ctga_<n>
// give it a budget of n sweeps.
//
// Work–precision (one figure, docs/img/contact_work_precision.svg), error against time per step:
//   pyramid_work   the same pyramid with a base of 20 (210 cubes) for 60 s (3,600 steps): the top
//                  cube's drift; ctga_tol_<t> at tolerance t (sweeps until it holds), ctga_<n> at
//                  n sweeps, bullet_<n> at n iterations, mujoco_<n> at n iterations (the pyramid:
//                  its default only)
//   pinch_work     a 10 cm cube (density 500) held between two fingers (4 × 10 × 10 cm, density
//                  1000) pressing with 10 N, μ = 0.5, no ground, gravity 10 along −z, 1 kHz, 2 s:
//                  the box's mean slip speed against the fingers (it must not slip: μF > mg/2)
// The peers' friction is set so that their rule of combining two gives μ (Bullet multiplies,
// MuJoCo takes the larger).
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

#include "contact_scenes.hpp"
#ifdef CTGA_BENCH_MUJOCO
#include <sstream>
#endif

namespace bench {
void register_pile();  // contact_pile.cpp
}

namespace {

using namespace bench;
using ctga::motor;
namespace collision = ctga::collision;
constexpr int pyramid_base = 100, pyramid_steps = 200;
constexpr int grid_size = 100, grid_steps = 100;
constexpr double cube_half = 0.5, cube_density = 100.0, friction = 0.6;
constexpr double sphere_radius = 0.4, sphere_density = 1.0;
constexpr int small_base = 20, small_steps = 3600;
// the pinch: the box's and a finger's half extents, where the fingers are, their push, the steps
constexpr double pinch_box = 0.05, pinch_finger = 0.02, pinch_at = 0.07, pinch_force = 10.0, pinch_mu = 0.5;
constexpr double pinch_box_density = 500.0, pinch_finger_density = 1000.0;
constexpr double pinch_h = 1e-3;  // a grasp's step, as robotics users run MuJoCo (60 Hz: every peer flew apart)
constexpr int pinch_steps = 2000;


// cube j of row i of a pyramid of the given base
ctga::vec3<double> pyramid_cube(int i, int j, int base = pyramid_base) {
    return {(i + 1) * cube_half + 2 * (j - i) * cube_half - base * cube_half, (2 * i + 1) * cube_half, 0.0};
}

// the fingers' push and the torque that holds each level against the friction at its face, for
// the box's weight shared by the two: a finger of side s (−1, +1) at a, the other at b
struct pinch_push {
    ctga::vec3<double> force, torque;
};
pinch_push pinch_wrench(double side, const ctga::vec3<double>& a, const ctga::vec3<double>& b, double box_mass, double finger_mass) {
    ctga::vec3<double> d = ctga::linear3::sub(b, a);
    d = ctga::linear3::scale(pinch_force / std::sqrt(ctga::linear3::dot(d, d)), d);
    return {{d[0], d[1], d[2] + (finger_mass + box_mass / 2) * gravity}, {0.0, side * pinch_finger * box_mass * gravity / 2, 0.0}};
}


// ---- ctga ------------------------------------------------------------------------------------

using cube = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, collision::box<double>>;
using ball = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::sphere, collision::sphere<double>>;
using spherical = ctga::spherical_joint<double>;


scene_result ctga_pyramid(std::size_t sweeps, std::size_t threads = 1, int base = pyramid_base, int steps = pyramid_steps,
                          double tolerance = 1e-6, std::size_t substeps = 0) {
    const std::size_t n = static_cast<std::size_t>(base * (base + 1) / 2);
    auto w = std::make_unique<ctga::physics_world<double, collision::box<double>, cube>>(
        std::array<std::size_t, 1>{n}, ctga::world_capacity{.statics = 1, .contacts = 16 * n, .pairs = 8 * n},
        ctga_settings(sweeps, threads, tolerance, substeps));
    w->add_static(*collision::make_box(400.0, 1.0, 400.0), motor<double>(ctga::make_translator(0.0, -1.0, 0.0)), {friction, 0.0});
    const auto box = *collision::make_box(cube_half, cube_half, cube_half);
    for (int i = 0; i < base; ++i)
        for (int j = i; j < base; ++j) {
            const ctga::vec3<double> c = pyramid_cube(i, j, base);
            w->add_body<0>(box, cube_density, motor<double>(ctga::make_translator(c[0], c[1], c[2])), {friction, 0.0});
        }
    const ctga::vec3<double> top = pyramid_cube(base - 1, base - 1, base);
    scene_result r = timed(steps, [&](scene_result& out) {
        const ctga::step_report<double> s = w->step(h);
        note(out, s);
        out.penetration = std::max(out.penetration, s.penetration);
        out.residual = std::max(out.residual, s.contact.residual);
    });
    const ctga::vec3<double> d = ctga::linear3::sub(ctga::map_of(w->pose<0>(n - 1)).t, top);
    r.drift = std::sqrt(ctga::linear3::dot(d, d));
    return r;
}

scene_result ctga_grid(std::size_t sweeps, std::size_t threads = 1, std::size_t substeps = 0) {
    constexpr std::size_t n = (grid_size - 1) * grid_size;
    auto w = std::make_unique<ctga::physics_world<double, collision::half_space<double>, ball>>(
        std::array<std::size_t, 1>{n}, ctga::world_capacity{.statics = 0, .contacts = 16, .pairs = 16, .joints = 2 * n},
        ctga_settings(sweeps, threads, 1e-6, substeps));
    collision::filter none;
    none.group = -1;  // the spheres do not collide
    const auto sphere = *collision::make_sphere(sphere_radius);
    const auto id = [](int i, int k) { return static_cast<std::size_t>((i - 1) * grid_size + k); };
    for (int i = 1; i < grid_size; ++i)
        for (int k = 0; k < grid_size; ++k)
            w->add_body<0>(sphere, sphere_density, motor<double>(ctga::make_translator(double(k), double(-i), 0.0)), {}, {}, none);
    for (int i = 1; i < grid_size; ++i)
        for (int k = 0; k < grid_size; ++k) {
            if (i == 1) w->add_joint(spherical{ctga::body<0>(id(i, k)), ctga::ground, {0.0, 0.5, 0.0}, {double(k), -0.5, 0.0}});
            else w->add_joint(spherical{ctga::body<0>(id(i, k)), ctga::body<0>(id(i - 1, k)), {0.0, 0.5, 0.0}, {0.0, -0.5, 0.0}});
            if (k > 0) w->add_joint(spherical{ctga::body<0>(id(i, k)), ctga::body<0>(id(i, k - 1)), {-0.5, 0.0, 0.0}, {0.5, 0.0, 0.0}});
        }
    return timed(grid_steps, [&](scene_result& out) {
        const ctga::step_report<double> s = w->step(h);
        note(out, s);
        out.joint_error = std::max(out.joint_error, s.joint_error);
    });
}

// the box (body 0) between the fingers (1 and 2), with no ground
scene_result ctga_pinch(double tolerance, std::size_t substeps = 0) {
    ctga::world_settings<double> set;
    set.substeps = substeps;
    set.gravity = {0.0, 0.0, -gravity};
    set.solver.tolerance = tolerance;
    set.solver.max_sweeps = 100000;
    ctga::physics_world<double, collision::box<double>, cube> w({3}, {.statics = 0, .contacts = 32, .pairs = 8}, set);
    w.add_body<0>(*collision::make_box(pinch_box, pinch_box, pinch_box), pinch_box_density, motor<double>(ctga::make_translator(0.0, 0.0, 1.0)),
                  {pinch_mu, 0.0});
    for (const double side : {-1.0, 1.0})
        w.add_body<0>(*collision::make_box(pinch_finger, pinch_box, pinch_box), pinch_finger_density,
                      motor<double>(ctga::make_translator(side * pinch_at, 0.0, 1.0)), {pinch_mu, 0.0});
    const double mb = w.body<0>(0).m(), mf = w.body<0>(1).m();
    double slip = 0;
    scene_result r = timed(pinch_steps, [&](scene_result& out) {
        const ctga::vec3<double> a = ctga::map_of(w.pose<0>(1)).t, b = ctga::map_of(w.pose<0>(2)).t;
        const pinch_push left = pinch_wrench(-1.0, a, b, mb, mf), right = pinch_wrench(1.0, b, a, mb, mf);
        w.set_wrench<0>(1, left.force, left.torque);
        w.set_wrench<0>(2, right.force, right.torque);
        const ctga::step_report<double> s = w.step(pinch_h);
        note(out, s);
        out.residual = std::max(out.residual, s.contact.residual);
        out.penetration = std::max(out.penetration, s.penetration);
        slip += std::abs(w.velocity<0>(0)[5] - (w.velocity<0>(1)[5] + w.velocity<0>(2)[5]) / 2);
    });
    r.slip = slip / pinch_steps;
    return r;
}

// ---- Bullet ----------------------------------------------------------------------------------

#ifdef CTGA_BENCH_BULLET

scene_result bullet_pyramid(int base = pyramid_base, int steps = pyramid_steps, int iterations = 10) {
    bullet_world b(iterations);
    b.shapes.push_back(std::make_unique<btBoxShape>(btVector3(400, 1, 400)));
    b.add(b.shapes.back().get(), 0.0, btVector3(0, -1, 0), friction);
    b.shapes.push_back(std::make_unique<btBoxShape>(btVector3(cube_half, cube_half, cube_half)));
    const double mass = cube_density * 8 * cube_half * cube_half * cube_half;
    btRigidBody* top = nullptr;
    for (int i = 0; i < base; ++i)
        for (int j = i; j < base; ++j) {
            const ctga::vec3<double> c = pyramid_cube(i, j, base);
            top = b.add(b.shapes.back().get(), mass, btVector3(c[0], c[1], c[2]), friction);
        }
    const btVector3 start = top->getWorldTransform().getOrigin();
    scene_result r = timed(steps, [&](scene_result& out) {
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

scene_result bullet_pinch(int iterations) {
    bullet_world b(iterations, btVector3(0, 0, -gravity));
    b.shapes.push_back(std::make_unique<btBoxShape>(btVector3(pinch_box, pinch_box, pinch_box)));
    b.shapes.push_back(std::make_unique<btBoxShape>(btVector3(pinch_finger, pinch_box, pinch_box)));
    for (auto& shape : b.shapes) shape->setMargin(0.001);  // (its default, 4 cm, is more than a finger's half width)
    const double mb = pinch_box_density * 8 * pinch_box * pinch_box * pinch_box, mf = pinch_finger_density * 8 * pinch_finger * pinch_box * pinch_box;
    btRigidBody* box = b.add(b.shapes[0].get(), mb, btVector3(0, 0, 1), pinch_mu);
    btRigidBody* left = b.add(b.shapes[1].get(), mf, btVector3(-pinch_at, 0, 1), pinch_mu);
    btRigidBody* right = b.add(b.shapes[1].get(), mf, btVector3(pinch_at, 0, 1), pinch_mu);
    const auto at = [](btRigidBody* x) {
        const btVector3 p = x->getWorldTransform().getOrigin();
        return ctga::vec3<double>{p.x(), p.y(), p.z()};
    };
    const auto push = [](btRigidBody* x, const pinch_push& p) {
        x->applyCentralForce(btVector3(p.force[0], p.force[1], p.force[2]));
        x->applyTorque(btVector3(p.torque[0], p.torque[1], p.torque[2]));
    };
    double slip = 0;
    scene_result r = timed(pinch_steps, [&](scene_result& out) {
        push(left, pinch_wrench(-1.0, at(left), at(right), mb, mf));
        push(right, pinch_wrench(1.0, at(right), at(left), mb, mf));
        b.world.stepSimulation(pinch_h, 0, pinch_h);  // (which clears the forces)
        out.penetration = std::max(out.penetration, b.penetration());
        slip += std::abs(box->getLinearVelocity().z() - (left->getLinearVelocity().z() + right->getLinearVelocity().z()) / 2);
    });
    r.slip = slip / pinch_steps;
    return r;
}
#endif

#ifdef CTGA_BENCH_ODE
scene_result ode_pyramid() {
    ode_world o;
    o.mu = friction;
    dGeomID ground = dCreateBox(o.space, 800, 2, 800);
    dGeomSetPosition(ground, 0, -1, 0);
    const ctga::mass_properties<double> p = *collision::mass_of(*collision::make_box(cube_half, cube_half, cube_half), cube_density);
    dBodyID top = nullptr;
    for (int i = 0; i < pyramid_base; ++i)
        for (int j = i; j < pyramid_base; ++j) {
            const ctga::vec3<double> c = pyramid_cube(i, j);
            top = o.add(dCreateBox(o.space, 2 * cube_half, 2 * cube_half, 2 * cube_half), p.mass,
                        {p.inertia_c[0][0], p.inertia_c[1][1], p.inertia_c[2][2]}, ctga::map_of(motor<double>(ctga::make_translator(c[0], c[1], c[2]))));
        }
    const dReal* start = dBodyGetPosition(top);
    const ctga::vec3<double> top0{start[0], start[1], start[2]};
    scene_result r = timed(pyramid_steps, [&](scene_result&) { o.step(h); });
    const dReal* end = dBodyGetPosition(top);
    const ctga::vec3<double> d{end[0] - top0[0], end[1] - top0[1], end[2] - top0[2]};
    r.drift = std::sqrt(ctga::linear3::dot(d, d)), r.penetration = o.deepest;
    return r;
}

// the spheres without geoms (they collide with nothing), ball joints at the anchors' midpoints
scene_result ode_grid() {
    ode_world o;
    const ctga::mass_properties<double> p = *collision::mass_of(*collision::make_sphere(sphere_radius), sphere_density);
    std::vector<dBodyID> b(grid_size * grid_size, nullptr);
    for (int i = 1; i < grid_size; ++i)
        for (int k = 0; k < grid_size; ++k)
            b[i * grid_size + k] = o.add(nullptr, p.mass, {p.inertia_c[0][0], p.inertia_c[1][1], p.inertia_c[2][2]},
                                         ctga::map_of(motor<double>(ctga::make_translator(double(k), double(-i), 0.0))));
    std::vector<dJointID> joints;
    const auto ball = [&](dBodyID x, dBodyID y, double ax, double ay) {
        joints.push_back(dJointCreateBall(o.world, nullptr));
        dJointAttach(joints.back(), x, y);
        dJointSetBallAnchor(joints.back(), ax, ay, 0);
    };
    for (int i = 1; i < grid_size; ++i)
        for (int k = 0; k < grid_size; ++k) {
            ball(b[i * grid_size + k], b[(i - 1) * grid_size + k], double(k), -i + 0.5);  // (row 0: the world, a null body)
            if (k > 0) ball(b[i * grid_size + k], b[i * grid_size + k - 1], k - 0.5, double(-i));
        }
    return timed(grid_steps, [&](scene_result& out) {
        o.step(h);
        for (dJointID j : joints) {
            dVector3 x, y;
            dJointGetBallAnchor(j, x), dJointGetBallAnchor2(j, y);
            const ctga::vec3<double> d{x[0] - y[0], x[1] - y[1], x[2] - y[2]};
            out.joint_error = std::max(out.joint_error, std::sqrt(ctga::linear3::dot(d, d)));
        }
    });
}
#endif

#ifdef CTGA_BENCH_MUJOCO
// room for the scenes' constraints (MuJoCo 2.2's defaults hold a few thousand)
constexpr const char* size_for_scenes = "<size njmax='400000' nconmax='200000' nstack='60000000'/>";
// room for a pyramid of n cubes: 13 contact points a cube (the 210-cube pyramid had at most
// 12.1, and 7,088 rows, measured), 48 rows a cube, a stack for the dense Jacobian (rows × nv
// numbers). MuJoCo 2.2 also holds njmax² numbers (efc_AR) and sizes mjData in a 32-bit int:
// with 60 rows a cube it could not be allocated.
std::string size_for_pyramid(int n) {
    const long contacts = 13L * n, rows = 48L * n, nv = 6L * n;
    return "<size njmax='" + std::to_string(rows) + "' nconmax='" + std::to_string(contacts) + "' nstack='" + std::to_string(4 * rows * nv) + "'/>";
}

// MuJoCo 2.2.2 allocates its constraint Jacobian densely, njmax × nv numbers (mjdata.h: efc_J):
// the gigabytes a scene of nv degrees of freedom and `rows` constraint rows needs.
double mujoco_jacobian_gb(double nv, double rows) { return nv * rows * 8 / 1e9; }


// free cubes on a ground box; the geoms' friction 0.6 (MuJoCo takes the larger of two), density 100
scene_result mujoco_pyramid(int base = pyramid_base, int steps = pyramid_steps, int iterations = 100) {
    std::ostringstream x;
    x << "<mujoco><option timestep='" << h << "' iterations='" << iterations << "' gravity='0 " << -gravity << " 0'/>" << size_for_pyramid(base * (base + 1) / 2)
      << "<default><geom friction='" << friction << " 0.005 0.0001' density='" << cube_density << "'/></default><worldbody>"
      << "<geom type='box' size='400 1 400' pos='0 -1 0'/>";
    for (int i = 0; i < base; ++i)
        for (int j = i; j < base; ++j) {
            const ctga::vec3<double> c = pyramid_cube(i, j, base);
            x << "<body pos='" << c[0] << ' ' << c[1] << ' ' << c[2] << "'><freejoint/><geom type='box' size='" << cube_half << ' ' << cube_half
              << ' ' << cube_half << "'/></body>";
        }
    x << "</worldbody></mujoco>";
    mujoco_scene s(x.str());
    const int top = s.m->nbody - 1;
    mj_forward(s.m, s.d);
    const ctga::vec3<double> start{s.d->xpos[3 * top], s.d->xpos[3 * top + 1], s.d->xpos[3 * top + 2]};
    scene_result r = timed(steps, [&](scene_result& out) {
        mj_step(s.m, s.d);
        out.penetration = std::max(out.penetration, s.penetration());
    });
    const ctga::vec3<double> end{s.d->xpos[3 * top], s.d->xpos[3 * top + 1], s.d->xpos[3 * top + 2]};
    const ctga::vec3<double> d = ctga::linear3::sub(end, start);
    r.drift = std::sqrt(ctga::linear3::dot(d, d));
    if (s.d->warning[mjWARN_CONTACTFULL].number > 0 || s.d->warning[mjWARN_CNSTRFULL].number > 0)
        r.failed = "MuJoCo 2.2.2 dropped contacts: its buffers (nconmax " + std::to_string(s.m->nconmax) + ", njmax " + std::to_string(s.m->njmax) +
                   ") filled, and larger ones do not fit its mjData (njmax x njmax numbers, a 32-bit size)";
    return r;
}

// the box (body 1) and the fingers (2, 3) free, no ground; the push as xfrc_applied
scene_result mujoco_pinch(int iterations) {
    std::ostringstream x;
    x << "<mujoco><option timestep='" << pinch_h << "' iterations='" << iterations << "' gravity='0 0 " << -gravity << "'/><default><geom friction='"
      << pinch_mu << " 0.005 0.0001'/></default><worldbody>"
      << "<body pos='0 0 1'><freejoint/><geom type='box' density='" << pinch_box_density << "' size='" << pinch_box << ' ' << pinch_box << ' '
      << pinch_box << "'/></body>";
    for (const double side : {-1.0, 1.0})
        x << "<body pos='" << side * pinch_at << " 0 1'><freejoint/><geom type='box' density='" << pinch_finger_density << "' size='"
          << pinch_finger << ' ' << pinch_box << ' ' << pinch_box << "'/></body>";
    x << "</worldbody></mujoco>";
    mujoco_scene s(x.str());
    const double mb = s.m->body_mass[1], mf = s.m->body_mass[2];
    const auto at = [&](int body) { return ctga::vec3<double>{s.d->xpos[3 * body], s.d->xpos[3 * body + 1], s.d->xpos[3 * body + 2]}; };
    const auto push = [&](int body, const pinch_push& p) {
        for (int k = 0; k < 3; ++k) s.d->xfrc_applied[6 * body + k] = p.force[k], s.d->xfrc_applied[6 * body + 3 + k] = p.torque[k];
    };
    mj_forward(s.m, s.d);
    double slip = 0;
    scene_result r = timed(pinch_steps, [&](scene_result& out) {
        push(2, pinch_wrench(-1.0, at(2), at(3), mb, mf));
        push(3, pinch_wrench(1.0, at(3), at(2), mb, mf));
        mj_step(s.m, s.d);
        out.penetration = std::max(out.penetration, s.penetration());
        slip += std::abs(s.d->qvel[2] - (s.d->qvel[8] + s.d->qvel[14]) / 2);  // (a free joint's linear velocity first)
    });
    r.slip = slip / pinch_steps;
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
    const auto add = [](const std::string& name, auto scene) { add_scene(name, scene); };
    add("large_pyramid/ctga", [] { return ctga_pyramid(100); });
    add("large_pyramid/ctga_2threads", [] { return ctga_pyramid(100, 2); });
    add("joint_grid/ctga", [] { return ctga_grid(100); });
    add("joint_grid/ctga_2threads", [] { return ctga_grid(100, 2); });
    for (const std::size_t sweeps : {4, 10, 30})
        add("joint_grid_work/ctga_" + std::to_string(sweeps), [sweeps] { return ctga_grid(sweeps); });
    // work–precision (tolerances as the residual's exponent: ctga_tol_3 is 1e-3)
    for (const int e : {2, 3, 4})
        add("pyramid_work/ctga_tol_" + std::to_string(e), [e] { return ctga_pyramid(100000, 1, small_base, small_steps, std::pow(10.0, -e)); });
    for (const std::size_t sweeps : {10, 100})
        add("pyramid_work/ctga_" + std::to_string(sweeps), [sweeps] { return ctga_pyramid(sweeps, 1, small_base, small_steps); });
    for (const int e : {2, 4, 6, 10})
        add("pinch_work/ctga_tol_" + std::to_string(e), [e] { return ctga_pinch(std::pow(10.0, -e)); });
    // the soft step (constraints/soft_step.hpp): n substeps of two sweeps, no tolerance
    for (const std::size_t n : {4, 8})
        add("large_pyramid_work/ctga_soft_" + std::to_string(n), [n] { return ctga_pyramid(0, 1, pyramid_base, pyramid_steps, 1e-6, n); });
    add("large_pyramid_work/ctga_soft_4_2threads", [] { return ctga_pyramid(0, 2, pyramid_base, pyramid_steps, 1e-6, 4); });
    add("joint_grid_work/ctga_soft_4", [] { return ctga_grid(0, 1, 4); });
    add("joint_grid_work/ctga_soft_4_2threads", [] { return ctga_grid(0, 2, 4); });
    for (const std::size_t n : {4, 8, 16, 32})
        add("pyramid_work/ctga_soft_" + std::to_string(n), [n] { return ctga_pyramid(0, 1, small_base, small_steps, 1e-6, n); });
    for (const std::size_t n : {4, 16})
        add("pinch_work/ctga_soft_" + std::to_string(n), [n] { return ctga_pinch(1e-6, n); });
#ifdef CTGA_BENCH_BULLET
    add("large_pyramid/bullet", [] { return bullet_pyramid(); });
    add("joint_grid/bullet", bullet_grid);
    for (const int n : {10, 30, 100}) {
        add("pyramid_work/bullet_" + std::to_string(n), [n] { return bullet_pyramid(small_base, small_steps, n); });
        add("pinch_work/bullet_" + std::to_string(n), [n] { return bullet_pinch(n); });
    }
#endif
#ifdef CTGA_BENCH_ODE
    add("large_pyramid/ode", ode_pyramid);
    add("joint_grid/ode", ode_grid);
#endif
#ifdef CTGA_BENCH_MUJOCO
    // (rows: the grid's 3 per joint; the pyramid's about 12 contact points per cube, 4 rows each with pyramidal cones)
    const auto add_mujoco = [](const std::string& name, double nv, double rows, auto scene) {
        benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& s) { run_mujoco(s, nv, rows, scene); })
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1)
            ->UseRealTime();
    };
    add_mujoco("large_pyramid/mujoco", 6.0 * pyramid_base * (pyramid_base + 1) / 2, 48.0 * pyramid_base * (pyramid_base + 1) / 2,
               [] { return mujoco_pyramid(); });
    add_mujoco("joint_grid/mujoco", 6.0 * (grid_size - 1) * grid_size, 6.0 * (grid_size - 1) * grid_size, mujoco_grid);
    // (100: its default; the pyramid at 1 iteration took MuJoCo nine minutes, 147 ms a step, and fell)
    add("pyramid_work/mujoco_100", [] { return mujoco_pyramid(small_base, small_steps, 100); });
    for (const int n : {1, 100}) add("pinch_work/mujoco_" + std::to_string(n), [n] { return mujoco_pinch(n); });
#endif
}

}  // namespace

int main(int argc, char** argv) {
    register_all();
    bench::register_pile();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
