// A mixed scene (include/ctga/scenes/scene.hpp): bodies of five kinds, free and under gravity,
// plus a static and a kinematic body, stepped together by the single-body integrators on the
// product model; every moving body follows the general 3D code (rigid_body_motion with the full
// inertia and screws, gravity computed from map_of) to 1e-12, and the fixed bodies are untouched.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <ctga/ctga.hpp>
#include <ctga/scenes/body_kinds.hpp>
#include <ctga/scenes/scene.hpp>

#include "support/catch.hpp"
#include "support/general_reference.hpp"

namespace {

using namespace ctga;
using ctga::test::general_gravity;
using ctga::test::rel;
namespace sub = ctga::subspace;
namespace kind = ctga::inertia_kind;

template <class Method>
motion_state<motor<double>, screw<double>> general_run(const Method& method, double m, double dx, double dy, double dz,
                                                       const vec3<double>& a, const motor<double>& g0,
                                                       const screw<double>& s0, double h, long long n) {
    const rigid_body_motion<double, frame::body, general_gravity> model{
        make_rigid_body(*make_principal_mass_properties(m, dx, dy, dz)), {{m * a[0], m * a[1], m * a[2]}}};
    const auto run = integrate(method, model, {g0, s0}, h, n);
    REQUIRE(run);
    return run.state;
}

}  // namespace

TEST_CASE("a mixed scene steps every body as the general 3D code does, to 1e-12", "[scenes]") {
    const vec3<double> g_field{0.3, -9.81, 0.0}, no_field{0, 0, 0};
    const motor<double> tilted = rigid_motion(make_translator(0.5, -1.0, 2.0), make_rotor(0.7, 1.0 / 3, 2.0 / 3, 2.0 / 3));
    const motor<double> flat = rigid_motion(make_translator(-2.0, 1.0, 0.0), make_rotor(0.3, 0.0, 0.0, 1.0));
    const motor<double> origin{1, 0, 0, 0, 0, 0, 0, 0};
    const motor<double> shifted(make_translator(0.5, -1.0, 2.0));
    const screw<double> tumbling{0.3, 1.0, -0.4, 0.2, -0.1, 0.5}, in_plane{0, 0, 1.3, 0.2, -0.1, 0},
        spinning{0.3, 1.0, -0.4, 0, 0, 0}, sliding{0, 0, 0, 0.2, -0.1, 0.5};

    using falling_box = body_motion<double, sub::full, kind::general, wrench_model::uniform_field<double, sub::full>>;
    using free_box = body_motion<double, sub::full, kind::diagonal>;
    using puck = body_motion<double, sub::planar, kind::sphere, wrench_model::uniform_field<double, sub::planar>>;
    using top = body_motion<double, sub::rotation, kind::axisymmetric>;
    using slider = body_motion<double, sub::translation, kind::sphere>;
    const auto world = make_scene(
        falling_box{make_rigid_body(*make_principal_mass_properties(2.0, 2.0, 2.5, 3.0)), weight<sub::full>(2.0, g_field)},
        static_body<double>{tilted},
        free_box{{1.5, 1.2, 1.6, 0.9}},
        puck{{3.0, 1.1}, weight<sub::planar>(3.0, g_field)},
        kinematic_body<double>{origin, screw<double>{0, 0, 1, 1, 0, 0}},
        top{{1.0, 0.7, 1.3}},
        slider{{0.5, 0.2}});
    const auto x0 = world.initial_state(
        motion_state<motor<double>, screw<double>>{tilted, tumbling},
        motion_state<motor<double>, screw<double>>{tilted, tumbling},
        motion_state<typename puck::motor_type, typename puck::screw_type>{project<typename puck::motor_type>(flat),
                                                                           project<typename puck::screw_type>(in_plane)},
        motion_state<rotor<double>, typename top::screw_type>{project<rotor<double>>(origin), project<typename top::screw_type>(spinning)},
        motion_state<translator<double>, typename slider::screw_type>{project<translator<double>>(shifted),
                                                                      project<typename slider::screw_type>(sliding)});
    const double h = 0.01;
    const long long n = 1000;
    for (int which = 0; which < 2; ++which) {
        const auto check = [&](const auto& method, const char* name) {
            const auto run = integrate(method, world.model(), x0, h, n);
            REQUIRE(run);
            const auto& g = run.state.g;
            const auto& s = run.state.s;
            struct expected {
                const char* body;
                motion_state<motor<double>, screw<double>> ref;
                motor<double> g;
                screw<double> s;
            };
            const expected rows[] = {
                {"full, general, gravity", general_run(method, 2.0, 2.0, 2.5, 3.0, g_field, tilted, tumbling, h, n),
                 part<0>(g), part<0>(s)},
                {"full, diagonal", general_run(method, 1.5, 1.2, 1.6, 0.9, no_field, tilted, tumbling, h, n),
                 part<1>(g), part<1>(s)},
                {"planar, sphere, gravity", general_run(method, 3.0, 1.1, 1.1, 1.1, g_field, flat, in_plane, h, n),
                 motor<double>(part<2>(g)), screw<double>(part<2>(s))},
                {"rotation, axisymmetric", general_run(method, 1.0, 0.7, 0.7, 1.3, no_field, origin, spinning, h, n),
                 motor<double>(part<3>(g)), screw<double>(part<3>(s))},
                {"translation, sphere", general_run(method, 0.5, 0.2, 0.2, 0.2, no_field, shifted, sliding, h, n),
                 motor<double>(part<4>(g)), screw<double>(part<4>(s))},
            };
            for (const expected& r : rows) {
                const double e = std::max(rel(r.g, r.ref.g), rel(r.s, r.ref.s));
                std::printf("%-8s %-26s %.2e\n", name, r.body, e);
                CHECK(e <= 1e-12);
            }
        };
        if (which == 0) check(lie_rk4{}, "lie_rk4");
        else check(rk4{}, "rk4");
    }
    // the static and kinematic bodies are outside the integrated model
    CHECK(rel(boost::hana::at_c<0>(world.prescribed).pose, tilted) == 0);
    const motor<double> later = boost::hana::at_c<1>(world.prescribed).pose(2.0);
    CHECK(rel(later, ctga::exp(screw<double>{0, 0, 2, 2, 0, 0})) == 0);
}

TEST_CASE("two bodies coupled by a spring conserve energy and momentum, a damper dissipates", "[scenes][springs]") {
    using ball = body_motion<double, sub::full, kind::sphere>;
    using box = body_motion<double, sub::full, kind::diagonal>;
    const ball a{{2.0, 0.8}};
    const box b{{1.0, 0.3, 0.4, 0.5}};
    const auto kinetic = [](double m, double dx, double dy, double dz, const screw<double>& s) {
        return kinetic_energy(make_rigid_body(*make_principal_mass_properties(m, dx, dy, dz)).N, s);
    };
    const vec3<double> on_a{0.2, 0.0, 0.1}, on_b{-0.3, 0.1, 0.0};
    const motor<double> ga = rigid_motion(make_translator(-1.0, 0.0, 0.0), make_rotor(0.2, 0.0, 0.0, 1.0));
    const motor<double> gb = rigid_motion(make_translator(1.0, 0.5, 0.0), make_rotor(0.4, 1.0 / 3, 2.0 / 3, 2.0 / 3));
    const screw<double> sa{0.1, -0.2, 0.3, 0.0, 0.4, 0.0}, sb{-0.5, 0.2, 0.1, 0.1, -0.2, 0.3};
    const auto energy_and_momentum = [&](const auto& state, double k) {
        const screw<double>& s1 = part<0>(state.s);
        const screw<double>& s2 = part<1>(state.s);
        const auto p1 = ctga::scene_detail::point_of<double>(part<0>(state.g), s1, on_a);
        const auto p2 = ctga::scene_detail::point_of<double>(part<1>(state.g), s2, on_b);
        double stretch = 0;
        for (int i = 0; i < 3; ++i) stretch += (p2.p[i] - p1.p[i]) * (p2.p[i] - p1.p[i]);
        const double E = kinetic(2.0, 0.8, 0.8, 0.8, s1) + kinetic(1.0, 0.3, 0.4, 0.5, s2) + 0.5 * k * stretch;
        // fixed-frame linear momentum m R v_b of each body (centres of mass at the body origins)
        const auto R1 = map_of(motor<double>(part<0>(state.g))).R, R2 = map_of(motor<double>(part<1>(state.g))).R;
        const vec3<double> q1 = linear3::apply(R1, vec3<double>{2.0 * s1[3], 2.0 * s1[4], 2.0 * s1[5]});
        const vec3<double> q2 = linear3::apply(R2, vec3<double>{s2[3], s2[4], s2[5]});
        return std::array<double, 4>{E, q1[0] + q2[0], q1[1] + q2[1], q1[2] + q2[2]};
    };
    const double k = 20.0;
    {
        const auto world = make_scene(couple(spring_damper<0, 1>{on_a, on_b, k, 0.0}), a, b);
        const auto x0 = world.initial_state(motion_state<motor<double>, screw<double>>{ga, sa},
                                            motion_state<motor<double>, screw<double>>{gb, sb});
        const auto start = energy_and_momentum(x0, k);
        double worst_energy = 0, worst_momentum = 0;
        const auto run = integrate(lie_rk4{}, world.model(), x0, 1e-3, 10'000, [&](long long, const auto& x) {
            const auto now = energy_and_momentum(x, k);
            worst_energy = std::max(worst_energy, std::abs(now[0] - start[0]) / start[0]);
            for (int i = 1; i < 4; ++i) worst_momentum = std::max(worst_momentum, std::abs(now[i] - start[i]));
        });
        REQUIRE(run);
        std::printf("spring, lie_rk4 h = 1e-3, 10 s: relative energy error %.2e, linear momentum drift %.2e\n", worst_energy,
                    worst_momentum);
        CHECK(worst_energy <= 1e-9);
        // m R v_b is not linear in the state (motor, body-frame velocity), so RK keeps it only to
        // its truncation error, O(h⁴)
        CHECK(worst_momentum <= 1e-8);
    }
    {
        const auto damped = make_scene(
            couple(spring_damper<0, 1>{on_a, on_b, k, 2.0}, spring_damper<0, ctga::world>{on_a, {-1, 0, 0}, 5.0, 0.5}), a, b);
        const auto x0 = damped.initial_state(motion_state<motor<double>, screw<double>>{ga, sa},
                                             motion_state<motor<double>, screw<double>>{gb, sb});
        // total energy: both bodies, both springs; the dampers only remove it
        const auto total = [&](const auto& x) {
            const auto p = ctga::scene_detail::point_of<double>(part<0>(x.g), part<0>(x.s), on_a);
            double d2 = 0;
            for (int i = 0; i < 3; ++i) d2 += (p.p[i] - (i == 0 ? -1.0 : 0.0)) * (p.p[i] - (i == 0 ? -1.0 : 0.0));
            return energy_and_momentum(x, k)[0] + 0.5 * 5.0 * d2;
        };
        double previous = total(x0), rises = 0, first = previous;
        const auto run = integrate(lie_rk4{}, damped.model(), x0, 1e-3, 5'000, [&](long long, const auto& x) {
            const double e = total(x);
            rises = std::max(rises, e - previous);
            previous = e;
        });
        REQUIRE(run);
        std::printf("spring–damper, and a spring–damper to the world: energy %.4f -> %.4f over 5 s, largest rise %.1e\n",
                    first, previous, rises);
        CHECK(previous < 0.1 * first);
        CHECK(rises <= 1e-9 * first);
    }
}
