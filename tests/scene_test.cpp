// A mixed scene (include/ctga/scenes/scene.hpp): bodies of five kinds, free and under gravity,
// plus a static and a kinematic body, stepped together by the single-body integrators on the
// product model; every moving body follows the general 3D code (rigid_body_motion with the full
// inertia and screws, gravity computed from map_of) to 1e-12, and the fixed bodies are untouched.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <ctga/ctga.hpp>
#include <ctga/scenes/body_kinds.hpp>
#include <ctga/scenes/scene.hpp>

#include "support/catch.hpp"

namespace {

using namespace ctga;
namespace sub = ctga::subspace;
namespace kind = ctga::inertia_kind;

double rel(const motor<double>& a, const motor<double>& b) {
    double d = 0, s = 1;
    for (std::size_t i = 0; i < 8; ++i) d = std::max(d, std::abs(a[i] - b[i])), s = std::max(s, std::abs(b[i]));
    return d / s;
}
double rel(const screw<double>& a, const screw<double>& b) {
    double d = 0, s = 1;
    for (std::size_t i = 0; i < 6; ++i) d = std::max(d, std::abs(a[i] - b[i])), s = std::max(s, std::abs(b[i]));
    return d / s;
}

struct general_gravity {  // (0, Rᵀ m a), written independently of the scene's field wrench
    vec3<double> weight;
    wrench<double> operator()(const motor<double>& g, const screw<double>&) const {
        const motor_map<double> G = map_of(g);
        vec3<double> f{};
        for (int i = 0; i < 3; ++i) f[i] = G.R[0][i] * weight[0] + G.R[1][i] * weight[1] + G.R[2][i] * weight[2];
        return wrench<double>{0, 0, 0, f[0], f[1], f[2]};
    }
};

template <class Method, class Body>
motion_state<motor<double>, screw<double>> general_run(const Method& method, double m, double dx, double dy, double dz,
                                                       const vec3<double>& a, const motor<double>& g0,
                                                       const screw<double>& s0, double h, long long n) {
    (void)sizeof(Body);
    const rigid_body_motion<double, frame::body, general_gravity> model{
        make_rigid_body(*make_principal_mass_properties(m, dx, dy, dz)), {{m * a[0], m * a[1], m * a[2]}}};
    const auto run = integrate(method, model, {g0, s0}, h, n);
    REQUIRE(run);
    return run.state;
}

}  // namespace

TEST_CASE("a mixed scene steps every body as the general 3D code does, to 1e-12", "[scenes]") {
    const vec3<double> g_field{0.3, -9.81, 0.0}, no_field{0, 0, 0};
    const motor<double> tilted = rigid_motion(translation(0.5, -1.0, 2.0), rotation(1.0 / 3, 2.0 / 3, 2.0 / 3, 0.7));
    const motor<double> flat = rigid_motion(translation(-2.0, 1.0, 0.0), rotation(0.0, 0.0, 1.0, 0.3));
    const motor<double> origin{1, 0, 0, 0, 0, 0, 0, 0};
    const motor<double> shifted(translation(0.5, -1.0, 2.0));
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
                {"full, general, gravity", general_run<decltype(method), int>(method, 2.0, 2.0, 2.5, 3.0, g_field, tilted, tumbling, h, n),
                 part<0>(g), part<0>(s)},
                {"full, diagonal", general_run<decltype(method), int>(method, 1.5, 1.2, 1.6, 0.9, no_field, tilted, tumbling, h, n),
                 part<1>(g), part<1>(s)},
                {"planar, sphere, gravity", general_run<decltype(method), int>(method, 3.0, 1.1, 1.1, 1.1, g_field, flat, in_plane, h, n),
                 motor<double>(part<2>(g)), screw<double>(part<2>(s))},
                {"rotation, axisymmetric", general_run<decltype(method), int>(method, 1.0, 0.7, 0.7, 1.3, no_field, origin, spinning, h, n),
                 motor<double>(part<3>(g)), screw<double>(part<3>(s))},
                {"translation, sphere", general_run<decltype(method), int>(method, 0.5, 0.2, 0.2, 0.2, no_field, shifted, sliding, h, n),
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
    CHECK(rel(boost::hana::at_c<0>(world.fixed).pose, tilted) == 0);
    const motor<double> later = boost::hana::at_c<1>(world.fixed).pose(2.0);
    CHECK(rel(later, ctga::exp(screw<double>{0, 0, 2, 2, 0, 0})) == 0);
}
