// Rigid motions of §3 against the 6×6 formalism of §2: rotors rotate by the right-hand rule,
// g g* = 1 holds as the two relations of §3, and g s g* = H s with H = [[R, 0], [T R, R]].
#include <array>
#include <cmath>
#include <random>

#include <ctga/ctga.hpp>
#include <ctga/mechanics/motor.hpp>

#include "support/catch.hpp"

namespace {

using namespace ctga;
using vec3 = std::array<double, 3>;
using mat3 = std::array<vec3, 3>;

vec3 apply(const mat3& m, const vec3& x) {
    return {m[0][0] * x[0] + m[0][1] * x[1] + m[0][2] * x[2], m[1][0] * x[0] + m[1][1] * x[1] + m[1][2] * x[2],
            m[2][0] * x[0] + m[2][1] * x[1] + m[2][2] * x[2]};
}
vec3 cross(const vec3& a, const vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// Rodrigues: the rotation matrix of angle θ about the unit axis u.
mat3 rotation_matrix(const vec3& u, double theta) {
    const double c = std::cos(theta), s = std::sin(theta), k = 1 - c;
    return {{{c + u[0] * u[0] * k, u[0] * u[1] * k - u[2] * s, u[0] * u[2] * k + u[1] * s},
             {u[1] * u[0] * k + u[2] * s, c + u[1] * u[1] * k, u[1] * u[2] * k - u[0] * s},
             {u[2] * u[0] * k - u[1] * s, u[2] * u[1] * k + u[0] * s, c + u[2] * u[2] * k}}};
}

TEST_CASE("a rotor rotates by +θ about its axis (right-hand rule)", "[mechanics][motion]") {
    // a quarter turn about z takes x to y
    const auto r = make_rotor(std::acos(-1.0) / 2, 0.0, 0.0, 1.0);
    const screw<> along_x{0, 0, 0, 1, 0, 0};
    const screw<> s = adjoint(motor<>(r), along_x);
    CHECK(get<"e1e">(s) == Approx(0).margin(1e-15));
    CHECK(get<"e2e">(s) == Approx(1));
}

TEST_CASE("make_rotor makes a unit rotor from any non-zero axis, and refuses the zero axis", "[mechanics][motion]") {
    // (0, 0, 5) is the z axis: the same rotation as (0, 0, 1), a unit rotor, not |α| = 2.5
    const rotor<> r5 = make_rotor(1.0, 0.0, 0.0, 5.0), r1 = make_rotor(1.0, 0.0, 0.0, 1.0);
    for (std::size_t k = 0; k < 4; ++k) CHECK(r5[k] == Approx(r1[k]).margin(1e-16));
    CHECK(r1[0] == Approx(std::cos(0.5)).margin(1e-16));
    CHECK(r1[3] == Approx(std::sin(0.5)).margin(1e-16));
    CHECK(near_unit(motor<>(make_rotor(0.3, 1e-300, 2e-300, -2e-300))));
    CHECK(near_unit(motor<>(make_rotor(0.3, 1e300, 2e300, -2e300))));
    CHECK(make_rotor_checked(1.0, 0.0, 0.0, 0.0).error == error_code::zero_direction);
    CHECK(make_rotor_checked(std::nan(""), 0.0, 0.0, 1.0).error == error_code::non_finite);
    CHECK(make_rotor_checked(1.0, 0.0, HUGE_VAL, 1.0).error == error_code::non_finite);
}

TEST_CASE("g g* = 1 and g s g* = H s for random motors, against the 6×6 formalism", "[mechanics][motion]") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 200; ++trial) {
        vec3 axis{u(rng), u(rng), u(rng)};
        const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        for (double& a : axis) a /= n;
        const double theta = 3 * u(rng);
        const vec3 t{10 * u(rng), 10 * u(rng), 10 * u(rng)};
        const motor<> g = rigid_motion(make_translator(t[0], t[1], t[2]), make_rotor(theta, axis[0], axis[1], axis[2]));

        // §3: g g* = 1 is α·α = 1 and α0β0 + α·β = 0
        const auto unit = eval(g * conj(g));
        CHECK(scalar_part(unit) == Approx(1).epsilon(1e-14));
        CHECK(get<"e1e2e3e">(unit) == Approx(0).margin(1e-14));
        const double alpha_beta = g[0] * g[4] + g[1] * g[5] + g[2] * g[6] + g[3] * g[7];
        CHECK(alpha_beta == Approx(0).margin(1e-14));

        // g s g* = H s, H = [[R, 0], [T R, R]]
        const screw<> s{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
        const mat3 R = rotation_matrix(axis, theta);
        const vec3 w = apply(R, {s[0], s[1], s[2]});
        const vec3 Rv = apply(R, {s[3], s[4], s[5]});
        const vec3 tw = cross(t, w);
        const screw<> moved = adjoint(g, s);
        for (int i = 0; i < 3; ++i) {
            CHECK(moved[i] == Approx(w[i]).margin(1e-12));
            CHECK(moved[3 + i] == Approx(Rv[i] + tw[i]).margin(1e-11));
        }
    }
}

TEST_CASE("the adjoint action is a screw at 72 multiplications", "[mechanics][motion]") {
    using moved = decltype(adjoint(motor<>{}, screw<>{}));
    static_assert(moved::size() == 6);
    static_assert(cost_of<moved>.mul <= 72);
    CHECK(cost_of<moved>.mul <= 72);
}

}  // namespace

TEST_CASE("map_of is homogeneous: a drifted motor gives the map of the rigid motion it encodes", "[mechanics][motion]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1), scale(0.5, 2.0);
    double worst = 0;
    for (int n = 0; n < 200; ++n) {
        const motor<double> g = ctga::exp(screw<double>{2 * u(rng), 2 * u(rng), 2 * u(rng), 5 * u(rng), 5 * u(rng), 5 * u(rng)});
        // off g g* = 1: scaled, and every component perturbed (|α|² − 1 and α·β both non-zero)
        const double lambda = scale(rng);
        motor<double> drifted;
        for (std::size_t i = 0; i < 8; ++i) drifted[i] = lambda * g[i] + 1e-3 * u(rng);
        const motor_map<double> a = map_of(drifted), b = map_of(renormalize(drifted));
        for (int i = 0; i < 3; ++i) {
            worst = std::max(worst, std::abs(a.t[i] - b.t[i]) / std::max(1.0, std::abs(b.t[i])));
            for (int j = 0; j < 3; ++j) worst = std::max(worst, std::abs(a.R[i][j] - b.R[i][j]));
        }
    }
    CHECK(worst <= 1e-14);
}
