// body_inertia: a rigid body's N by its ten parameters (m, h = m c, I_o), against the 24-blade
// rigid_inertia of inertia_of (blade by blade), and momentum, energy and the transform by a
// motor map against the same operations on rigid_inertia, on random bodies, poses and velocities.
#include <algorithm>
#include <cmath>
#include <random>

#include <ctga/ctga.hpp>

#include "support/catch.hpp"
#include "support/general_reference.hpp"

namespace {
using namespace ctga;

using test::rel;  // support/general_reference.hpp
}  // namespace

static_assert(cost_of<decltype(momentum.formula(std::declval<const body_inertia<>&>(), std::declval<const screw<>&>())),
                      coscrew<>> == expr::cost{24, 18},
              "ten parameters, the same 24m 18a as the 24 stored blades");

TEST_CASE("body_inertia is the element N of inertia_of, and its operations agree", "[mechanics][inertia]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1), pos(0.5, 2.0);
    double worst_element = 0, worst_momentum = 0, worst_energy = 0, worst_transform = 0, worst_rate = 0;
    for (int n = 0; n < 500; ++n) {
        const double a = pos(rng), b = pos(rng), c = pos(rng), m = pos(rng);
        const motor_map<double> Q = map_of(ctga::exp(screw<double>{2 * u(rng), 2 * u(rng), 2 * u(rng), 0, 0, 0}));
        const auto props = make_mass_properties(
            m, vec3<double>{u(rng), u(rng), u(rng)},
            linear3::rotate_symmetric(Q.R, mat3<double>{{{m * (b * b + c * c) / 12, 0, 0}, {0, m * (a * a + c * c) / 12, 0},
                                                          {0, 0, m * (a * a + b * b) / 12}}}));
        REQUIRE(props);
        const body_inertia<double> N10 = body_inertia_of(*props);
        const rigid_inertia<double> N24 = inertia_of(*props);
        worst_element = std::max(worst_element, rel(to_rigid_inertia(N10), N24));
        const screw<double> s{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
        worst_momentum = std::max(worst_momentum, rel(momentum(N10, s), momentum(N24, s)));
        worst_energy = std::max(worst_energy, std::abs(kinetic_energy(N10, s) - kinetic_energy(N24, s)) /
                                                  std::max(1.0, std::abs(kinetic_energy(N24, s))));
        const motor_map<double> G =
            map_of(ctga::exp(screw<double>{2 * u(rng), 2 * u(rng), 2 * u(rng), 5 * u(rng), 5 * u(rng), 5 * u(rng)}));
        worst_transform = std::max(worst_transform, rel(to_rigid_inertia(transform(G, N10)), transform(G, N24)));
        // the rate of a moving body's inertia by its ten parameters = the formula of §6 on the element
        worst_rate = std::max(worst_rate, rel(inertia<double>(to_rigid_inertia(inertia_rate(N10, s))), inertia_rate(N24, s)));
    }
    std::printf("body_inertia vs rigid_inertia: element %.1e, momentum %.1e, energy %.1e, transform %.1e, rate %.1e\n",
                worst_element, worst_momentum, worst_energy, worst_transform, worst_rate);
    CHECK(worst_element <= 1e-15);
    CHECK(worst_momentum <= 1e-14);
    CHECK(worst_energy <= 1e-14);
    CHECK(worst_transform <= 1e-14);
    CHECK(worst_rate <= 1e-14);
}
