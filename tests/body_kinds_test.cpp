// Bodies that declare their subspace and inertia structure (include/ctga/scenes/body_kinds.hpp):
// the engine's price of one body step per combination (static_asserted), and the same trajectory
// as the general 3D code (a rigid_body_motion with the full 24-blade inertia and 6-blade screws)
// for every kind.
// PARTS: 3
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <ctga/ctga.hpp>
#include <ctga/scenes/body_kinds.hpp>

#include "support/catch.hpp"
#include "support/general_reference.hpp"
#include "support/published.hpp"
#include "support/parts.hpp"

namespace {

using namespace ctga;
using ctga::test::general_gravity;
using ctga::test::rel;
using ctga::test::published;
using ctga::test::published_mul;
namespace sub = ctga::subspace;
namespace kind = ctga::inertia_kind;

template <class S, class K, class W = wrench_model::none>
constexpr expr::cost step = body_step_cost<S, K, W>;
template <class S>
using gravity = wrench_model::uniform_field<double, S>;

// what one body step (ġ and ṡ of a free body, body frame) costs, by kind
static_assert(step<sub::full, kind::sphere>.mul < step<sub::full, kind::diagonal>.mul,
              "a sphere's Coriolis term ω × dω is structurally zero");
static_assert(step<sub::full, kind::diagonal>.mul < step<sub::full, kind::general>.mul);
static_assert(3 * step<sub::planar, kind::diagonal>.mul <= step<sub::full, kind::general>.mul,
              "a planar body's step works on 3 components: at most a third of the general body's");
static_assert(3 * step<sub::planar, kind::diagonal>.add <= step<sub::full, kind::general>.add);
static_assert(step<sub::rotation, kind::diagonal>.mul < step<sub::full, kind::diagonal>.mul);
static_assert(step<sub::translation, kind::sphere>.mul < step<sub::planar, kind::sphere>.mul);
static_assert(step<sub::full, kind::diagonal>.mul < step<sub::full, kind::diagonal, gravity<sub::full>>.mul,
              "a body without wrench has no wrench code");
static_assert(step<sub::planar, kind::diagonal>.mul < step<sub::planar, kind::diagonal, gravity<sub::planar>>.mul);

template <class S, class K, class W = wrench_model::none>
bool expect(const char* name, expr::cost printed) {
    constexpr expr::cost c = step<S, K, W>;
    std::printf("body step %-28s %3zum %3zua\n", name, static_cast<std::size_t>(c.mul), static_cast<std::size_t>(c.add));
    return c == printed;
}

// The kind's body and the same body as general mass properties (centre of mass at the origin,
// principal axes along the frame).
struct principal {
    double m, dx, dy, dz;
};
template <class K>
typename K::template data<double> data_of(const principal& p) {
    if constexpr (std::is_same_v<K, kind::sphere>) return {p.m, p.dx};
    else if constexpr (std::is_same_v<K, kind::axisymmetric>) return {p.m, p.dx, p.dz};
    else if constexpr (std::is_same_v<K, kind::diagonal>) return {p.m, p.dx, p.dy, p.dz};
    else return make_rigid_body(*make_principal_mass_properties(p.m, p.dx, p.dy, p.dz));
}

// Integrates the kind's model and the general model from the same state; the worst difference.
template <class S, class K, class Method>
double same_as_general(const Method& method, const principal& p, const screw<double>& s0, const motor<double>& g0) {
    using model_t = body_motion<double, S, K>;
    const model_t specific{data_of<K>(p)};
    const rigid_body_motion<double, frame::body> general{make_rigid_body(*make_principal_mass_properties(p.m, p.dx, p.dy, p.dz))};
    const auto a = integrate(method, specific, {project<typename model_t::motor_type>(g0), project<typename model_t::screw_type>(s0)},
                             0.01, 2000);
    const auto b = integrate(method, general, {g0, s0}, 0.01, 2000);
    REQUIRE(a);
    REQUIRE(b);
    return std::max(rel(motor<double>(a.state.g), b.state.g), rel(screw<double>(a.state.s), b.state.s));
}

}  // namespace

#if CTGA_TEST_PART_HOLDS(0)
TEST_CASE("cost of one body step per subspace and inertia structure, as docs/mechanics.md §3 prints it", "[scenes][cost]") {
    CHECK(expect<sub::full, kind::general>("full, general", published<110, 76>));
    CHECK(expect<sub::full, kind::diagonal>("full, diagonal", published<74, 40>));
    CHECK(expect<sub::full, kind::axisymmetric>("full, axisymmetric", published<74, 40>));
    CHECK(expect<sub::full, kind::sphere>("full, sphere", published<59, 31>));
    CHECK(expect<sub::planar, kind::diagonal>("planar, diagonal", published<18, 4>));
    CHECK(expect<sub::planar, kind::axisymmetric>("planar, axisymmetric", published<18, 4>));
    CHECK(expect<sub::planar, kind::sphere>("planar, sphere", published<18, 4>));
    CHECK(expect<sub::rotation, kind::diagonal>("rotation, diagonal", published<28, 11>));
    CHECK(expect<sub::rotation, kind::axisymmetric>("rotation, axisymmetric", published<28, 11>));
    CHECK(expect<sub::rotation, kind::sphere>("rotation, sphere", published<16, 8>));
    CHECK(expect<sub::translation, kind::diagonal>("translation, diagonal", published<6, 0>));
    CHECK(expect<sub::translation, kind::sphere>("translation, sphere", published<6, 0>));
    CHECK(expect<sub::full, kind::general, gravity<sub::full>>("full, general, gravity", published<141, 99>));
    CHECK(expect<sub::full, kind::diagonal, gravity<sub::full>>("full, diagonal, gravity", published<105, 63>));
    CHECK(expect<sub::full, kind::axisymmetric, gravity<sub::full>>("full, axisymmetric, gravity", published<105, 63>));
    CHECK(expect<sub::full, kind::sphere, gravity<sub::full>>("full, sphere, gravity", published<90, 54>));
    CHECK(expect<sub::planar, kind::diagonal, gravity<sub::planar>>("planar, diagonal, gravity", published<30, 11>));
    CHECK(expect<sub::planar, kind::sphere, gravity<sub::planar>>("planar, sphere, gravity", published<30, 11>));
    CHECK(expect<sub::translation, kind::sphere, gravity<sub::translation>>("translation, sphere, gravity", published<17, 0>));
    // the general body's 110m: ½ g s (44m) and the typed acceleration (66m, tests/mechanics_cost_test.cpp)
    CHECK(cost_of<decltype(half * std::declval<const motor<>&>() * std::declval<const screw<>&>()), motor<>>.mul == published_mul<44>);
}

#endif
#if CTGA_TEST_PART_HOLDS(1)
TEST_CASE("every body kind follows the general 3D code's trajectory to 1e-12", "[scenes]") {
    const motor<double> g0 = rigid_motion(make_translator(0.5, -1.0, 0.0), make_rotor(0.7, 0.0, 0.0, 1.0));  // in the plane
    const motor<double> tilted = rigid_motion(make_translator(0.5, -1.0, 2.0), make_rotor(0.7, 1.0 / 3, 2.0 / 3, 2.0 / 3));
    const screw<double> tumbling{0.3, 1.0, -0.4, 0.2, -0.1, 0.5};
    const screw<double> in_plane{0, 0, 1.3, 0.2, -0.1, 0};
    const screw<double> spinning{0.3, 1.0, -0.4, 0, 0, 0};
    const screw<double> sliding{0, 0, 0, 0.2, -0.1, 0.5};
    const principal box{2.0, 2.0, 2.5, 3.0}, rod{1.5, 1.2, 1.2, 0.4}, ball{3.0, 1.1, 1.1, 1.1};
    double worst = 0;
    const auto check = [&](const char* name, double e) {
        std::printf("%-36s %.2e\n", name, e);
        CHECK(e <= 1e-12);
        worst = std::max(worst, e);
    };
    for (int method = 0; method < 2; ++method) {
        const auto run = [&]<class S, class K>(const char* name, const principal& p, const screw<double>& s0,
                                                const motor<double>& g) {
            const double e = method == 0 ? same_as_general<S, K>(lie_rk4{}, p, s0, g) : same_as_general<S, K>(rk4{}, p, s0, g);
            check(name, e);
        };
        run.template operator()<sub::full, kind::diagonal>("full, diagonal, tumbling", box, tumbling, tilted);
        run.template operator()<sub::full, kind::axisymmetric>("full, axisymmetric, tumbling", rod, tumbling, tilted);
        run.template operator()<sub::full, kind::sphere>("full, sphere, tumbling", ball, tumbling, tilted);
        run.template operator()<sub::planar, kind::diagonal>("planar, diagonal", box, in_plane, g0);
        run.template operator()<sub::planar, kind::sphere>("planar, sphere", ball, in_plane, g0);
        run.template operator()<sub::rotation, kind::diagonal>("rotation, diagonal", box, spinning, motor<double>{1, 0, 0, 0, 0, 0, 0, 0});
        run.template operator()<sub::translation, kind::sphere>("translation, sphere", ball, sliding, motor<double>(make_translator(0.5, -1.0, 2.0)));
    }
    std::printf("worst difference from the general code: %.2e\n", worst);
}

#endif
#if CTGA_TEST_PART_HOLDS(2)
TEST_CASE("under gravity, the body kinds follow the general 3D code to 1e-12", "[scenes]") {
    const vec3<double> a{0.3, -9.81, 0.0};  // in the e1, e2 plane, so the planar body feels all of it
    const principal box{2.0, 2.0, 2.5, 3.0};
    const motor<double> tilted = rigid_motion(make_translator(0.5, -1.0, 2.0), make_rotor(0.7, 1.0 / 3, 2.0 / 3, 2.0 / 3));
    const motor<double> flat = rigid_motion(make_translator(0.5, -1.0, 0.0), make_rotor(0.7, 0.0, 0.0, 1.0));
    const rigid_body_motion<double, frame::body, general_gravity> general{
        make_rigid_body(*make_principal_mass_properties(box.m, box.dx, box.dy, box.dz)), {{box.m * a[0], box.m * a[1], box.m * a[2]}}};
    const auto compare = [&]<class S, class K>(const char* name, const motor<double>& g0, const screw<double>& s0) {
        using model_t = body_motion<double, S, K, gravity<S>>;
        const model_t specific{data_of<K>(box), weight<S>(box.m, a)};
        const auto x = integrate(lie_rk4{}, specific,
                                 {project<typename model_t::motor_type>(g0), project<typename model_t::screw_type>(s0)}, 0.01, 2000);
        const auto y = integrate(lie_rk4{}, general, {g0, s0}, 0.01, 2000);
        REQUIRE(x);
        REQUIRE(y);
        const double e = std::max(rel(motor<double>(x.state.g), y.state.g), rel(screw<double>(x.state.s), y.state.s));
        std::printf("gravity, %-28s %.2e\n", name, e);
        CHECK(e <= 1e-12);
    };
    compare.template operator()<sub::full, kind::diagonal>("full, diagonal", tilted, screw<double>{0.3, 1.0, -0.4, 0.2, -0.1, 0.5});
    compare.template operator()<sub::full, kind::general>("full, general", tilted, screw<double>{0.3, 1.0, -0.4, 0.2, -0.1, 0.5});
    compare.template operator()<sub::planar, kind::diagonal>("planar, diagonal", flat, screw<double>{0, 0, 1.3, 0.2, -0.1, 0});
}
#endif
