// mixed_pile: 1,000 shapes of four kinds dropped into a box, for ctga_contact_bench (contact.cpp
// has the other scenes and main; the definitions shared with them are in contact_scenes.hpp).
//   a ground box (6, 1, 6) at y = −1 and four walls (half thickness 0.5, half height 6) whose
//   inner faces are the planes x = ±5, z = ±5; body n of 1,000 at x = −4.5 + (n mod 10),
//   z = −4.5 + (⌊n / 10⌋ mod 10), y = 1 + 1.1 ⌊n / 100⌋, turned by 0.61 n rad about
//   (sin n, cos n, 1/2); its kind n mod 4: a sphere (radius 0.4), a capsule (radius 0.25, segment
//   0.4 along its z), a box (half extents 0.4, 0.3, 0.2), a rock (the convex hull of ten points
//   below, whose centre of mass is off its points' origin and whose axes are not principal: the
//   body is its hull moved to its principal frame, collision::on_principal_axes). Density 100,
//   friction 0.6, gravity 10 down, 60 Hz, 300 steps (5 s) from rest.
// ctga at tolerance 1e-6 and at most 100 sweeps a step; mixed_pile_work/ctga_<n> at n sweeps.
// Counters: ms_per_step; penetration, the largest seen; speed, the fastest body's speed at the end
// (the pile has come to rest when it is small).
// Peers, given ctga's masses and principal moments: Bullet (btSphereShape, btCapsuleShapeZ,
// btBoxShape, btConvexHullShape of the rock's moved points), ODE (sphere, capsule, box, and a
// convex geom of the moved rock's faces); MuJoCo with its own (its shapes at the density, the
// rock a mesh).
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <ctga/collision/box.hpp>
#include <ctga/collision/capsule.hpp>
#include <ctga/collision/hull.hpp>
#include <ctga/collision/sphere.hpp>
#include <ctga/scenes/world.hpp>

#include "contact_scenes.hpp"
#ifdef CTGA_BENCH_MUJOCO
#include <sstream>
#endif

namespace {

using namespace bench;
using ctga::motor;
namespace collision = ctga::collision;

constexpr int pile_bodies = 1000, pile_steps = 300;
constexpr double pile_density = 100.0, pile_friction = 0.6;
constexpr double ball_radius = 0.4, pill_radius = 0.25, pill_half = 0.2;
constexpr ctga::vec3<double> brick{0.4, 0.3, 0.2};
constexpr std::array<ctga::vec3<double>, 10> rock_points{{{-0.35, -0.3, -0.25},
                                                          {0.4, -0.3, -0.2},
                                                          {0.3, 0.25, -0.3},
                                                          {-0.3, 0.3, -0.2},
                                                          {-0.25, -0.2, 0.3},
                                                          {0.35, -0.25, 0.25},
                                                          {0.2, 0.35, 0.3},
                                                          {-0.35, 0.2, 0.25},
                                                          {0.45, 0.1, 0.0},
                                                          {0.0, 0.0, 0.42}}};
using rock_hull = collision::convex_hull<double, 16>;

// the container: the ground, then the walls at x = ±5.5 and z = ±5.5 (centre, half extents)
struct slab {
    ctga::vec3<double> at, half;
};
constexpr std::array<slab, 5> container{{{{0.0, -1.0, 0.0}, {6.0, 1.0, 6.0}},
                                         {{5.5, 6.0, 0.0}, {0.5, 6.0, 6.0}},
                                         {{-5.5, 6.0, 0.0}, {0.5, 6.0, 6.0}},
                                         {{0.0, 6.0, 5.5}, {6.0, 6.0, 0.5}},
                                         {{0.0, 6.0, -5.5}, {6.0, 6.0, 0.5}}}};

// body n's pose (of the shape as given: the rock's points' frame)
motor<double> pile_pose(int n) {
    const double x = -4.5 + n % 10, z = -4.5 + (n / 10) % 10, y = 1.0 + 1.1 * (n / 100);
    return ctga::make_translator(x, y, z) * ctga::make_rotor(0.61 * n, std::sin(double(n)), std::cos(double(n)), 0.5);
}

const collision::principal_hull<double, 16>& rock() {
    static const collision::principal_hull<double, 16> r = *collision::on_principal_axes(*collision::make_hull<16, double>(std::span<const ctga::vec3<double>>(rock_points)), pile_density);
    return r;
}

// ---- ctga ------------------------------------------------------------------------------------

using ball = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::sphere, collision::sphere<double>>;
using pill = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::axisymmetric, collision::capsule<double>>;
using cube = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, collision::box<double>>;
using stone = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, rock_hull>;
using pile_world = ctga::physics_world<double, collision::box<double>, ball, pill, cube, stone>;

double linear_speed(const ctga::screw<double>& s) { return std::sqrt(s[3] * s[3] + s[4] * s[4] + s[5] * s[5]); }

scene_result ctga_pile(std::size_t sweeps, std::size_t threads, std::size_t substeps = 0) {
    constexpr std::size_t quarter = pile_bodies / 4;
    auto w = std::make_unique<pile_world>(std::array<std::size_t, 4>{quarter, quarter, quarter, quarter},
                                          ctga::world_capacity{.statics = 5, .contacts = 24 * pile_bodies, .pairs = 16 * pile_bodies},
                                          ctga_settings(sweeps, threads, 1e-6, substeps));
    for (const slab& s : container)
        w->add_static(*collision::make_box(s.half[0], s.half[1], s.half[2]), motor<double>(ctga::make_translator(s.at[0], s.at[1], s.at[2])),
                      {pile_friction, 0.0});
    const ctga::material<double> m{pile_friction, 0.0};
    for (int n = 0; n < pile_bodies; ++n) {
        const motor<double> g = pile_pose(n);
        switch (n % 4) {
            case 0: w->add_body<0>(*collision::make_sphere(ball_radius), pile_density, g, m); break;
            case 1: w->add_body<1>(*collision::make_capsule(pill_radius, pill_half), pile_density, g, m); break;
            case 2: w->add_body<2>(*collision::make_box(brick[0], brick[1], brick[2]), pile_density, g, m); break;
            default: w->add_body<3>(rock().shape, pile_density, motor<double>(g * rock().frame), m); break;
        }
    }
    scene_result r = timed(pile_steps, [&](scene_result& out) {
        const ctga::step_report<double> s = w->step(h);
        note(out, s);
        out.penetration = std::max(out.penetration, s.penetration);
        out.residual = std::max(out.residual, s.contact.residual);
    });
    for (std::size_t i = 0; i < quarter; ++i)
        r.speed = std::max({r.speed, linear_speed(w->velocity<0>(i)), linear_speed(w->velocity<1>(i)), linear_speed(w->velocity<2>(i)),
                            linear_speed(w->velocity<3>(i))});
    return r;
}

// ---- Bullet ----------------------------------------------------------------------------------

#ifdef CTGA_BENCH_BULLET
btTransform bullet_pose(const motor<double>& g) {
    const ctga::motor_map<double> G = ctga::map_of(g);
    const auto& R = G.R;
    return btTransform(btMatrix3x3(R[0][0], R[0][1], R[0][2], R[1][0], R[1][1], R[1][2], R[2][0], R[2][1], R[2][2]), btVector3(G.t[0], G.t[1], G.t[2]));
}

scene_result bullet_pile() {
    bullet_world b;
    for (const slab& s : container) {
        b.shapes.push_back(std::make_unique<btBoxShape>(btVector3(s.half[0], s.half[1], s.half[2])));
        b.add(b.shapes.back().get(), 0.0, btVector3(s.at[0], s.at[1], s.at[2]), pile_friction);
    }
    b.shapes.push_back(std::make_unique<btSphereShape>(ball_radius));
    b.shapes.push_back(std::make_unique<btCapsuleShapeZ>(pill_radius, 2 * pill_half));
    b.shapes.push_back(std::make_unique<btBoxShape>(btVector3(brick[0], brick[1], brick[2])));
    auto hull = std::make_unique<btConvexHullShape>();
    for (std::size_t i = 0; i < rock().shape.vertex_count; ++i) {
        const ctga::vec3<double>& v = rock().shape.vertex[i];
        hull->addPoint(btVector3(v[0], v[1], v[2]), i + 1 == rock().shape.vertex_count);
    }
    b.shapes.push_back(std::move(hull));
    // the same masses and principal moments as ctga's bodies
    const std::array<ctga::mass_properties<double>, 4> props{*collision::mass_of(*collision::make_sphere(ball_radius), pile_density),
                                                             *collision::mass_of(*collision::make_capsule(pill_radius, pill_half), pile_density),
                                                             *collision::mass_of(*collision::make_box(brick[0], brick[1], brick[2]), pile_density),
                                                             *collision::mass_of(rock().shape, pile_density)};
    const std::size_t first = b.shapes.size() - 4, body0 = b.bodies.size();
    for (int n = 0; n < pile_bodies; ++n) {
        const ctga::mass_properties<double>& q = props[n % 4];
        const motor<double> g = n % 4 == 3 ? motor<double>(pile_pose(n) * rock().frame) : pile_pose(n);
        b.add(b.shapes[first + n % 4].get(), q.mass, btVector3(q.inertia_c[0][0], q.inertia_c[1][1], q.inertia_c[2][2]), bullet_pose(g), pile_friction);
    }
    scene_result r = timed(pile_steps, [&](scene_result& out) {
        b.world.stepSimulation(h, 0, h);
        out.penetration = std::max(out.penetration, b.penetration());
    });
    for (std::size_t i = body0; i < b.bodies.size(); ++i) r.speed = std::max(r.speed, double(b.bodies[i]->getLinearVelocity().length()));
    return r;
}
#endif

#ifdef CTGA_BENCH_ODE
// the rock as ODE's convex geom: its faces' planes (n, d), its points, its polygons (count, then
// the corners, counter-clockwise from outside), kept for the geoms' lifetime
struct ode_rock {
    std::vector<dReal> planes, points;
    std::vector<unsigned> polygons;
};
const ode_rock& rock_for_ode() {
    static const ode_rock r = [] {
        ode_rock out;
        const rock_hull& hull = rock().shape;
        for (std::size_t f = 0; f < hull.face_count; ++f) {
            for (std::size_t c = 0; c < 3; ++c) out.planes.push_back(hull.face[f].normal[c]);
            out.planes.push_back(hull.face[f].offset);
            out.polygons.push_back(hull.face[f].count);
            for (std::size_t k = 0; k < hull.face[f].count; ++k) out.polygons.push_back(hull.face_vertex[hull.face[f].first + k]);
        }
        for (std::size_t i = 0; i < hull.vertex_count; ++i)
            for (std::size_t c = 0; c < 3; ++c) out.points.push_back(hull.vertex[i][c]);
        return out;
    }();
    return r;
}

scene_result ode_pile() {
    ode_world o;
    o.mu = pile_friction;
    for (const slab& s : container) {
        dGeomID g = dCreateBox(o.space, 2 * s.half[0], 2 * s.half[1], 2 * s.half[2]);
        dGeomSetPosition(g, s.at[0], s.at[1], s.at[2]);
    }
    const std::array<ctga::mass_properties<double>, 4> props{*collision::mass_of(*collision::make_sphere(ball_radius), pile_density),
                                                             *collision::mass_of(*collision::make_capsule(pill_radius, pill_half), pile_density),
                                                             *collision::mass_of(*collision::make_box(brick[0], brick[1], brick[2]), pile_density),
                                                             *collision::mass_of(rock().shape, pile_density)};
    const ode_rock& r = rock_for_ode();
    std::vector<dBodyID> bodies;
    for (int n = 0; n < pile_bodies; ++n) {
        dGeomID g = nullptr;
        switch (n % 4) {
            case 0: g = dCreateSphere(o.space, ball_radius); break;
            case 1: g = dCreateCapsule(o.space, pill_radius, 2 * pill_half); break;
            case 2: g = dCreateBox(o.space, 2 * brick[0], 2 * brick[1], 2 * brick[2]); break;
            default:
                g = dCreateConvex(o.space, r.planes.data(), static_cast<unsigned>(r.planes.size() / 4), r.points.data(),
                                  static_cast<unsigned>(r.points.size() / 3), r.polygons.data());
                break;
        }
        const ctga::mass_properties<double>& q = props[n % 4];
        const motor<double> pose = n % 4 == 3 ? motor<double>(pile_pose(n) * rock().frame) : pile_pose(n);
        bodies.push_back(o.add(g, q.mass, {q.inertia_c[0][0], q.inertia_c[1][1], q.inertia_c[2][2]}, ctga::map_of(pose)));
    }
    scene_result out = timed(pile_steps, [&](scene_result&) { o.step(h); });
    for (dBodyID b : bodies) {
        const dReal* v = dBodyGetLinearVel(b);
        out.speed = std::max(out.speed, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    }
    out.penetration = o.deepest;
    return out;
}
#endif

#ifdef CTGA_BENCH_MUJOCO
// free bodies with MuJoCo's own shapes (a capsule along its z, as ctga's), the rock a mesh of its
// points as given (MuJoCo moves a mesh to its principal frame itself); its defaults otherwise.
// Buffers: 3,000 rows, 1,500 contacts and 200 million numbers of stack, about the most its
// mjData holds here (a 32-bit size: the dense Jacobian, njmax × nv numbers, twice, njmax² more,
// and a stack its Newton solver fills with nv² = 36 million numbers and more: 10,000 rows could
// not be allocated, 4,500 rows with 160 million numbers of stack overflowed it, measured); a run
// that fills the buffers says so.
scene_result mujoco_pile() {
    std::ostringstream x;
    x << "<mujoco><option timestep='" << h << "' gravity='0 " << -gravity << " 0'/>"
      << "<size njmax='3000' nconmax='1500' nstack='200000000'/>"
      << "<default><geom friction='" << pile_friction << " 0.005 0.0001' density='" << pile_density << "'/></default><asset><mesh name='rock' vertex='";
    for (const ctga::vec3<double>& p : rock_points) x << p[0] << ' ' << p[1] << ' ' << p[2] << ' ';
    x << "'/></asset><worldbody>";
    for (const slab& s : container)
        x << "<geom type='box' size='" << s.half[0] << ' ' << s.half[1] << ' ' << s.half[2] << "' pos='" << s.at[0] << ' ' << s.at[1] << ' ' << s.at[2] << "'/>";
    for (int n = 0; n < pile_bodies; ++n) {
        const motor<double> g = pile_pose(n);
        const ctga::vec3<double> t = ctga::map_of(g).t;
        x << "<body pos='" << t[0] << ' ' << t[1] << ' ' << t[2] << "' quat='" << g[0] << ' ' << g[1] << ' ' << g[2] << ' ' << g[3] << "'><freejoint/>";
        switch (n % 4) {
            case 0: x << "<geom type='sphere' size='" << ball_radius << "'/>"; break;
            case 1: x << "<geom type='capsule' size='" << pill_radius << ' ' << pill_half << "'/>"; break;
            case 2: x << "<geom type='box' size='" << brick[0] << ' ' << brick[1] << ' ' << brick[2] << "'/>"; break;
            default: x << "<geom type='mesh' mesh='rock'/>"; break;
        }
        x << "</body>";
    }
    x << "</worldbody></mujoco>";
    mujoco_scene s(x.str());
    scene_result r = timed(pile_steps, [&](scene_result& out) {
        mj_step(s.m, s.d);
        out.penetration = std::max(out.penetration, s.penetration());
    });
    for (int b = 0; b < pile_bodies; ++b) {  // (a free joint's linear velocity first)
        const double* v = s.d->qvel + 6 * b;
        r.speed = std::max(r.speed, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    }
    if (s.d->warning[mjWARN_CONTACTFULL].number > 0 || s.d->warning[mjWARN_CNSTRFULL].number > 0)
        r.failed = "MuJoCo 2.2.2 dropped contacts: its buffers (nconmax " + std::to_string(s.m->nconmax) + ", njmax " + std::to_string(s.m->njmax) +
                   ") filled, and larger ones do not fit its mjData beside its Newton solver's stack (a 32-bit size)";
    return r;
}
#endif

}  // namespace

namespace bench {
void register_pile() {
    add_scene("mixed_pile/ctga", [] { return ctga_pile(100, 1); });
    add_scene("mixed_pile/ctga_2threads", [] { return ctga_pile(100, 2); });
    for (const std::size_t sweeps : {10, 30})
        add_scene("mixed_pile_work/ctga_" + std::to_string(sweeps), [sweeps] { return ctga_pile(sweeps, 1); });
    add_scene("mixed_pile_work/ctga_soft_4", [] { return ctga_pile(0, 1, 4); });  // the soft step, 4 substeps
#ifdef CTGA_BENCH_BULLET
    add_scene("mixed_pile/bullet", bullet_pile);
#endif
#ifdef CTGA_BENCH_MUJOCO
    add_scene("mixed_pile/mujoco", mujoco_pile);
#endif
#ifdef CTGA_BENCH_ODE
    add_scene("mixed_pile/ode", ode_pile);
#endif
}
}  // namespace bench
