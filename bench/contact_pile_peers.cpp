// mixed_pile's peers (the scene: contact_pile.cpp), given ctga's masses and principal moments:
// Bullet (btSphereShape, btCapsuleShapeZ, btBoxShape, btConvexHullShape of the rock's moved
// points), ODE (sphere, capsule, box, and a convex geom of the moved rock's faces); MuJoCo with
// its own (its shapes at the density, the rock a mesh). A unit apart from ctga's rows: the
// heaviest scene unit's compile time is ctga's alone.
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

#include "contact_pile.hpp"
#include "contact_scenes.hpp"
#ifdef CTGA_BENCH_MUJOCO
#include <sstream>
#endif

namespace {

using namespace bench;
using namespace bench::pile;

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
void register_pile_peers() {
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
