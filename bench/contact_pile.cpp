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
// Peers: contact_pile_peers.cpp; the definitions both use: contact_pile.hpp.
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>

#include <ctga/collision/box.hpp>
#include <ctga/collision/capsule.hpp>
#include <ctga/collision/hull.hpp>
#include <ctga/collision/sphere.hpp>
#include <ctga/scenes/world.hpp>

#include "contact_pile.hpp"
#include "contact_scenes.hpp"

namespace {

using namespace bench;
using namespace bench::pile;

// ---- ctga ------------------------------------------------------------------------------------

using ball = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::sphere, collision::sphere<double>>;
using pill = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::axisymmetric, collision::capsule<double>>;
using cube = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, collision::box<double>>;
using stone = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, rock_hull>;
using pile_world = ctga::physics_world<double, collision::box<double>, ball, pill, cube, stone>;

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

}  // namespace

namespace bench {
void register_pile() {
    add_scene("mixed_pile/ctga", [] { return ctga_pile(100, 1); });
    add_scene("mixed_pile/ctga_2threads", [] { return ctga_pile(100, 2); });
    for (const std::size_t sweeps : {10, 30})
        add_scene("mixed_pile_work/ctga_" + std::to_string(sweeps), [sweeps] { return ctga_pile(sweeps, 1); });
    add_scene("mixed_pile_work/ctga_soft_4", [] { return ctga_pile(0, 1, 4); });  // the soft step, 4 substeps
    add_scene("mixed_pile_work/ctga_soft_4_2threads", [] { return ctga_pile(0, 2, 4); });
    register_pile_peers();
}
}  // namespace bench
