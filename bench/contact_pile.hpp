// mixed_pile's definition, shared by its ctga rows (contact_pile.cpp) and its peers' rows
// (contact_pile_peers.cpp, a unit of its own: compile time). The scene: contact_pile.cpp.
#pragma once

#include <array>
#include <cmath>
#include <span>

#include <ctga/collision/hull.hpp>
#include <ctga/mechanics/motor.hpp>

namespace bench::pile {
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
inline motor<double> pile_pose(int n) {
    const double x = -4.5 + n % 10, z = -4.5 + (n / 10) % 10, y = 1.0 + 1.1 * (n / 100);
    return ctga::make_translator(x, y, z) * ctga::make_rotor(0.61 * n, std::sin(double(n)), std::cos(double(n)), 0.5);
}

inline const collision::principal_hull<double, 16>& rock() {
    static const collision::principal_hull<double, 16> r = *collision::on_principal_axes(*collision::make_hull<16, double>(std::span<const ctga::vec3<double>>(rock_points)), pile_density);
    return r;
}

inline double linear_speed(const ctga::screw<double>& s) { return std::sqrt(s[3] * s[3] + s[4] * s[4] + s[5] * s[5]); }

}  // namespace bench::pile

namespace bench {
void register_pile_peers();  // contact_pile_peers.cpp: Bullet, ODE, MuJoCo
}  // namespace bench
