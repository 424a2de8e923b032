// A world of bodies that touch (include/ctga/scenes/world.hpp) against answers known in advance
// (../shared/reference/contact.md): a block on an incline, a bouncing ball, a stack with a mass
// ratio of 1:1000; and bad input.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include <ctga/collision/box.hpp>
#include <ctga/collision/half_space.hpp>
#include <ctga/collision/hull.hpp>
#include <ctga/collision/sphere.hpp>
#include <ctga/chains/algorithms.hpp>
#include <ctga/scenes/world.hpp>

#include "support/catch.hpp"

namespace {
using ctga::motor;
using ctga::screw;
namespace collision = ctga::collision;
using cube = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, collision::box<double>>;
using ball = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::sphere, collision::sphere<double>>;
using plane = collision::half_space<double>;
using spherical = ctga::spherical_joint<double>;
constexpr double g = 9.81, h = 1.0 / 60;

ctga::vec3<double> centre(const motor<double>& pose) { return ctga::map_of(pose).t; }
double speed(const screw<double>& s) { return std::sqrt(s[3] * s[3] + s[4] * s[4] + s[5] * s[5]); }

// A unit cube of density 100 resting on a plane tilted by θ about y, both with friction μ.
struct incline {
    ctga::physics_world<double, plane, cube> w{{1}, {.statics = 1, .contacts = 16, .pairs = 4}};
    double theta;
    explicit incline(double theta_, double mu) : theta(theta_) {
        w.settings().solver.tolerance = 1e-13;
        const motor<double> tilt(ctga::make_rotor(theta, 0.0, 1.0, 0.0));
        REQUIRE(w.add_static(plane{}, tilt, {mu, 0.0}));
        const auto R = ctga::map_of(tilt).R;
        const motor<double> pose = ctga::make_translator(0.5 * R[0][2], 0.5 * R[1][2], 0.5 * R[2][2]) * ctga::make_rotor(theta, 0.0, 1.0, 0.0);
        REQUIRE(w.add_body<0>(*collision::make_box(0.5, 0.5, 0.5), 100.0, pose, {mu, 0.0}));
    }
    double energy() const {
        const double m = w.body<0>(0).m();
        const double v = speed(w.velocity<0>(0));
        return 0.5 * m * v * v + m * g * centre(w.pose<0>(0))[2];
    }
};
}  // namespace

TEST_CASE("world: a block on an incline slides at g (sin θ − μ cos θ), losing μ m g cos θ per metre, or stays") {
    const double theta = 0.3;
    {
        const double mu = 0.2, a = g * (std::sin(theta) - mu * std::cos(theta));
        incline s(theta, mu);
        const ctga::vec3<double> start = centre(s.w.pose<0>(0));
        const double e0 = s.energy();
        double worst = 0, v_before = 0;
        for (int k = 0; k < 600; ++k) {
            const ctga::step_report<double> r = s.w.step(h);
            REQUIRE(r.error == ctga::error_code::none);
            REQUIRE(r.contacts == 4);
            CHECK(r.contact.converged);
            const double v = speed(s.w.velocity<0>(0));
            worst = std::max(worst, std::abs((v - v_before) / h - a) / a);
            v_before = v;
        }
        CHECK(worst <= 1e-11);  // each step (the solver's tolerance in velocity: 1e-13 N s / 100 kg)
        CHECK(std::abs(v_before / (600 * h) - a) / a <= 1e-12);
        const ctga::vec3<double> end = centre(s.w.pose<0>(0));
        const double slid = std::sqrt(ctga::linear3::dot(ctga::linear3::sub(end, start), ctga::linear3::sub(end, start)));
        const double m = s.w.body<0>(0).m();
        CHECK(std::abs((e0 - s.energy()) / (mu * m * g * std::cos(theta) * slid) - 1) <= 1e-9);
        CHECK(std::abs(slid - a * 10 * 10 / 2) <= 1e-9 * slid);  // the centre's motion is exact under a constant force
    }
    {
        incline s(theta, 0.4);  // μ ≥ tan θ = 0.309
        const ctga::vec3<double> start = centre(s.w.pose<0>(0));
        for (int k = 0; k < 600; ++k) REQUIRE(s.w.step(h).contact.converged);
        const ctga::vec3<double> d = ctga::linear3::sub(centre(s.w.pose<0>(0)), start);
        CHECK(std::sqrt(ctga::linear3::dot(d, d)) <= 1e-9);
    }
}

TEST_CASE("world: a ball bounces to e^(2k) h0, with e = 1 and no friction its energy is kept") {
    const double r = 0.1, h0 = 1.0;
    for (const double e : {1.0, 0.5}) {
        ctga::physics_world<double, plane, ball> w({1}, {.statics = 1, .contacts = 4, .pairs = 4});
        w.settings().solver.tolerance = 1e-12;
        REQUIRE(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {0.0, e}));
        REQUIRE(w.add_body<0>(*collision::make_sphere(r), 1000.0, motor<double>(ctga::make_translator(0.0, 0.0, r + h0)), {0.0, e}));
        const double m = w.body<0>(0).m(), e0 = m * g * h0;
        double v_before = 0, worst_energy = 0;
        int bounces = 0;
        for (int k = 0; k < 1200 && bounces < 3; ++k) {
            REQUIRE(w.step(h).error == ctga::error_code::none);
            const double z = centre(w.pose<0>(0))[2] - r, v = w.velocity<0>(0)[5];
            worst_energy = std::max(worst_energy, std::abs(0.5 * m * v * v + m * g * z - e0) / e0);
            if (v_before > 0 && v <= 0) {
                ++bounces;
                // the apex lies within the step: the parabola through this state
                const double apex = z + v * v / (2 * g);
                const double expected = h0 * std::pow(e, 2 * bounces);
                // the impact is taken at the start of the step that closes the gap, up to h |v| above
                // the ground, which the rebound scales by (1 − e²): the bound below
                const double impact_speed = std::sqrt(2 * g * expected / (e * e));
                CHECK(std::abs(apex - expected) <= (1 - e * e) * h * impact_speed + 1e-12);
            }
            v_before = v;
        }
        CHECK(bounces == 3);
        if (e == 1.0) CHECK(worst_energy <= 1e-12);
    }
}

TEST_CASE("world: a stack of ten boxes alternating 1 and 1000 kg/m^3 stands") {
    ctga::physics_world<double, plane, cube> w({10}, {.statics = 1, .contacts = 64, .pairs = 32});
    w.settings().solver.tolerance = 1e-10;
    REQUIRE(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {0.6, 0.0}));
    for (int i = 0; i < 10; ++i)
        REQUIRE(w.add_body<0>(*collision::make_box(0.5, 0.5, 0.5), i % 2 ? 100000.0 : 100.0,
                              motor<double>(ctga::make_translator(0.0, 0.0, 0.5 + i)), {0.6, 0.0}));
    double deepest = 0;
    for (int k = 0; k < 300; ++k) {
        const ctga::step_report<double> r = w.step(h);
        REQUIRE(r.error == ctga::error_code::none);
        CHECK(r.contact.converged);
        deepest = std::max(deepest, r.penetration);
    }
    const ctga::vec3<double> top = centre(w.pose<0>(9));
    CHECK(std::abs(top[0]) + std::abs(top[1]) + std::abs(top[2] - 9.5) <= 1e-9);
    CHECK(deepest <= 1e-8);  // the issue asks ≤ 1 % of the size
}

TEST_CASE("world: a hull leaning over its base stands while its centre of mass is above the base, and tips when not") {
    // A parallelepiped: the unit square at z = 0, the same square shifted by s along x at z = 1;
    // volume 1, centre (1/2 + s/2, 1/2, 1/2), an xz product of inertia: its principal axes are
    // turned about y. On a plane it stands while the centre is over the base (s < 1), else tips.
    using rock = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, collision::convex_hull<double, 8>>;
    for (const double s : {0.8, 1.2}) {
        std::array<ctga::vec3<double>, 8> points{};
        for (int k = 0; k < 8; ++k) points[k] = {(k & 1) + (k & 4 ? s : 0.0), double((k >> 1) & 1), double((k >> 2) & 1)};
        const auto given = *collision::make_hull(points);
        const auto moved = *collision::on_principal_axes(given, 100.0);
        const auto frame = ctga::map_of(moved.frame);
        const auto p0 = *collision::mass_of(given, 100.0), p = *collision::mass_of(moved.shape, 100.0);
        CHECK(std::abs(p0.com[0] - (0.5 + s / 2)) + std::abs(p0.com[1] - 0.5) + std::abs(p0.com[2] - 0.5) <= 1e-14);
        CHECK(std::abs(p.mass - 100.0) <= 1e-12);
        CHECK(std::sqrt(ctga::linear3::dot(p.com, p.com)) <= 1e-15);
        const double trace = p.inertia_c[0][0] + p.inertia_c[1][1] + p.inertia_c[2][2];
        CHECK(std::abs(p0.inertia_c[0][2]) >= 1.0);  // (the given axes are not principal)
        CHECK(std::abs(p.inertia_c[0][1]) + std::abs(p.inertia_c[0][2]) + std::abs(p.inertia_c[1][2]) <= 1e-13 * trace);
        CHECK(std::abs(p.inertia_c[0][0] + p.inertia_c[1][1] + p.inertia_c[2][2] - (p0.inertia_c[0][0] + p0.inertia_c[1][1] + p0.inertia_c[2][2])) <= 1e-12 * trace);
        for (std::size_t i = 0; i < given.vertex_count; ++i) {  // the same solid: frame · moved vertex = given vertex
            const auto x = ctga::linear3::add(ctga::linear3::apply(frame.R, moved.shape.vertex[i]), frame.t);
            CHECK(std::abs(x[0] - given.vertex[i][0]) + std::abs(x[1] - given.vertex[i][1]) + std::abs(x[2] - given.vertex[i][2]) <= 1e-14);
        }
        ctga::physics_world<double, plane, rock> w({1}, {.statics = 1, .contacts = 16, .pairs = 4});
        w.settings().solver.tolerance = 1e-12;
        REQUIRE(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {0.8, 0.0}));
        CHECK(w.add_body<0>(given, 100.0, motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {0.8, 0.0}).error == ctga::error_code::not_aligned);
        REQUIRE(w.add_body<0>(moved.shape, 100.0, moved.frame, {0.8, 0.0}));
        const ctga::vec3<double> start = centre(w.pose<0>(0));
        double weight = 0;  // the normal impulses of the last step, against m g h
        for (int k = 0; k < 120; ++k) {
            const ctga::step_report<double> r = w.step(h);
            REQUIRE(r.error == ctga::error_code::none);
            weight = 0;
            for (std::size_t c = 0; c < r.contacts; ++c) weight += w.contact_impulse(c)[0];
        }
        const auto R = ctga::map_of(w.pose<0>(0)).R;
        double turned = 0;  // the angle between the start's and the end's axes: acos((tr(R0ᵀ R) − 1) / 2)
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) turned += frame.R[j][i] * R[j][i];
        turned = std::acos(std::clamp((turned - 1) / 2, -1.0, 1.0));
        const ctga::vec3<double> d = ctga::linear3::sub(centre(w.pose<0>(0)), start);
        if (s < 1) {
            CHECK(std::sqrt(ctga::linear3::dot(d, d)) <= 1e-9);
            CHECK(turned <= 1e-9);
            CHECK(std::abs(weight / (100.0 * g * h) - 1) <= 1e-9);
        } else {
            CHECK(turned >= 0.5);  // it fell over its edge x = 1
        }
    }
}

TEST_CASE("world: a free body on a spherical joint moves as the same pendulum built as a tree (ABA)") {
    namespace ch = ctga::chains;
    const double l = 0.7, r = 0.1, theta = 0.8;
    // the tree: a revolute joint about y at the origin, the bob's centre l below it
    using tree = ch::tree<ch::link<-1, ch::revolute_y>>;
    const auto bob = *collision::mass_of(*collision::make_sphere(r), 1000.0);
    ch::model<tree> m;
    m.gravity = {0.0, 0.0, -g};
    const auto link = ch::make_link<ch::revolute_y>(motor<double>(ctga::make_translator(0.0, 0.0, 0.0)),
                                                      ctga::make_mass_properties(bob.mass, ctga::vec3<double>{0.0, 0.0, -l}, bob.inertia_c));
    REQUIRE(link);
    m.link<0>() = *link;
    const ch::configuration<tree> q{theta};
    const ch::joint_vector<tree> zero{0.0};
    const double qdd = ch::aba(m, q, zero, zero)[0];
    // the bob's centre where the tree puts it, R_y(θ) (0, 0, −l), and its acceleration at rest, ω̇ × c
    const ctga::vec3<double> c{-l * std::sin(theta), 0.0, -l * std::cos(theta)};
    const ctga::vec3<double> expected{qdd * c[2], 0.0, -qdd * c[0]};
    for (const double step : {1.0 / 60, 1e-3}) {
        ctga::physics_world<double, plane, ball> w({1}, {.statics = 0, .contacts = 4, .pairs = 4, .joints = 1});
        w.settings().solver.tolerance = 1e-13;
        REQUIRE(w.add_body<0>(*collision::make_sphere(r), 1000.0, motor<double>(ctga::make_translator(c[0], c[1], c[2]))));
        REQUIRE(w.add_joint(spherical{ctga::body<0>(0), ctga::ground, {-c[0], -c[1], -c[2]}, {0.0, 0.0, 0.0}}));
        const ctga::step_report<double> rep = w.step(step);
        REQUIRE(rep.error == ctga::error_code::none);
        CHECK(rep.contact.converged);
        // from rest J v⁺ = 0 is J a = 0 (J̇ v = 0): v⁺ / h is the constrained acceleration exactly
        const screw<double> v = w.velocity<0>(0);
        for (std::size_t i = 0; i < 3; ++i) CHECK(std::abs(v[3 + i] / step - expected[i]) <= 1e-12 * g);
    }
}

TEST_CASE("world: revolute, prismatic, fixed and distance joints move as ABA, the closed forms and the composite body say") {
    namespace ch = ctga::chains;
    using ctga::vec3;
    const vec3<double> y{0.0, 1.0, 0.0};
    const auto body_frame = [](const motor<double>& pose, const vec3<double>& x) { return ctga::linear3::apply_transposed(ctga::map_of(pose).R, x); };
    // revolute: a box bob turned by 0.5 rad about its rod, so that its inertia has products in the
    // hinge's frame (a spherical joint lets it tilt out of the plane of the swing); the same
    // pendulum as a tree with a revolute joint about y at the origin
    {
        const double l = 0.7, theta = 0.8;
        const auto shape = *collision::make_box(0.05, 0.1, 0.2);
        const auto props = *collision::mass_of(shape, 1000.0);
        const motor<double> twist(ctga::make_rotor(0.5, 0.0, 0.0, 1.0)), swing(ctga::make_rotor(theta, 0.0, 1.0, 0.0));
        using tree = ch::tree<ch::link<-1, ch::revolute_y>>;
        ch::model<tree> m;
        m.gravity = {0.0, 0.0, -g};
        const auto link = ch::make_link<ch::revolute_y>(
            motor<double>(ctga::make_translator(0.0, 0.0, 0.0)),
            ctga::make_mass_properties(props.mass, vec3<double>{0.0, 0.0, -l}, ctga::linear3::rotate_symmetric(ctga::map_of(twist).R, props.inertia_c)));
        REQUIRE(link);
        m.link<0>() = *link;
        const ch::joint_vector<tree> zero{0.0};
        const double qdd = ch::aba(m, ch::configuration<tree>{theta}, zero, zero)[0];
        const vec3<double> c = ctga::linear3::apply(ctga::map_of(swing).R, vec3<double>{0.0, 0.0, -l});
        REQUIRE(std::abs(c[0] + l * std::sin(theta)) < 1e-15);  // R_y(θ) as the tree turns
        const motor<double> pose = motor<double>(ctga::make_translator(c[0], c[1], c[2])) * swing * twist;
        for (const bool hinge : {true, false}) {
            ctga::physics_world<double, plane, cube> w({1}, {.statics = 0, .contacts = 4, .pairs = 4, .joints = 1});
            w.settings().gravity = {0.0, 0.0, -g};
            w.settings().solver.tolerance = 1e-13;
            REQUIRE(w.add_body<0>(shape, 1000.0, pose));
            const vec3<double> anchor = body_frame(pose, ctga::linear3::scale(-1.0, c));
            if (hinge) REQUIRE(w.add_joint(ctga::revolute_joint<double>{ctga::body<0>(0), ctga::ground, anchor, {}, body_frame(pose, y), y}));
            else REQUIRE(w.add_joint(spherical{ctga::body<0>(0), ctga::ground, anchor, {}}));
            REQUIRE(w.step(h).error == ctga::error_code::none);
            const screw<double> s = w.velocity<0>(0);
            if (hinge) {
                // from rest J v⁺ = 0 is J a = 0: v⁺ / h is the constrained acceleration exactly
                CHECK(std::abs(s[1] / h - qdd) <= 1e-12 * std::abs(qdd));
                CHECK(std::abs(s[0]) + std::abs(s[2]) <= 1e-13 * std::abs(qdd) * h);
                CHECK(std::abs(s[3] / h - qdd * c[2]) <= 1e-12 * g);
                CHECK(std::abs(s[5] / h + qdd * c[0]) <= 1e-12 * g);
            } else {
                CHECK(std::abs(s[0]) + std::abs(s[2]) > 1e-3 * std::abs(qdd) * h);  // the products of inertia tilt it
            }
        }
    }
    // prismatic: a turned box on a slide inclined by β, pushed across it and twisted; it slides
    // at g sin β along the slide (x = ½ g sin β t², exact for θ = ½ under a constant force) and
    // neither leaves the slide nor turns
    {
        const double beta = 0.4;
        const vec3<double> u{std::cos(beta), 0.0, -std::sin(beta)};
        const motor<double> pose = motor<double>(ctga::make_translator(0.3, -0.2, 1.0)) * motor<double>(ctga::make_rotor(0.3, 0.6, 0.0, 0.8));
        ctga::physics_world<double, plane, cube> w({1}, {.statics = 0, .contacts = 4, .pairs = 4, .joints = 1});
        w.settings().gravity = {0.0, 0.0, -g};
        w.settings().solver.tolerance = 1e-13;
        REQUIRE(w.add_body<0>(*collision::make_box(0.1, 0.2, 0.3), 700.0, pose));
        REQUIRE(w.add_joint(ctga::prismatic_joint<double>{ctga::body<0>(0), ctga::ground, {}, centre(pose), body_frame(pose, u)}));
        const int steps = 120;
        for (int k = 0; k < steps; ++k) {
            w.set_wrench<0>(0, {std::sin(beta), 3.0, std::cos(beta)}, {0.4, -0.3, 0.2});  // (a push normal to the slide)
            const ctga::step_report<double> r = w.step(h);
            REQUIRE(r.error == ctga::error_code::none);
            CHECK(r.joint_angle <= 1e-13);
        }
        const double t = steps * h;
        const vec3<double> moved = ctga::linear3::sub(centre(w.pose<0>(0)), centre(pose));
        CHECK(std::abs(ctga::linear3::dot(moved, u) - 0.5 * g * std::sin(beta) * t * t) <= 1e-12 * g * t * t);
        const vec3<double> across = ctga::linear3::add_scaled(moved, -ctga::linear3::dot(moved, u), u);
        CHECK(std::sqrt(ctga::linear3::dot(across, across)) <= 1e-12);
        const screw<double> s = w.velocity<0>(0);
        CHECK(std::abs(s[0]) + std::abs(s[1]) + std::abs(s[2]) <= 1e-12);
    }
    // fixed: two boxes welded, spinning in free fall, move as one body: the momentum grows by the
    // weight's impulse exactly; the angular momentum about the pair's centre of mass is kept to
    // the step's first order (the rows hold J(x_n) s_{n+1} = 0, positions then move on chords),
    // so that its drift halves with the step
    {
        const motor<double> p0(ctga::make_translator(0.0, 0.0, 1.0));
        const motor<double> p1 = motor<double>(ctga::make_translator(0.25, 0.1, 1.05)) * motor<double>(ctga::make_rotor(0.4, 0.0, 0.0, 1.0));
        const vec3<double> omega{0.3, 1.0, 0.2};
        const std::array<collision::box<double>, 2> shapes{*collision::make_box(0.1, 0.1, 0.1), *collision::make_box(0.15, 0.05, 0.1)};
        const std::array<ctga::mass_properties<double>, 2> props{*collision::mass_of(shapes[0], 1000.0), *collision::mass_of(shapes[1], 500.0)};
        const double mass = props[0].mass + props[1].mass, duration = 0.5;
        struct result {
            double momentum, turn, gap, angle;
        };
        const auto run = [&](double step) {
            ctga::physics_world<double, plane, cube> w({2}, {.statics = 0, .contacts = 4, .pairs = 4, .joints = 1});
            w.settings().gravity = {0.0, 0.0, -g};
            w.settings().solver.tolerance = 1e-13;
            REQUIRE(w.add_body<0>(shapes[0], 1000.0, p0, {}, screw<double>{omega[0], omega[1], omega[2], 0.0, 0.0, 0.0}));
            const vec3<double> v1 = ctga::linear3::cross(omega, ctga::linear3::sub(centre(p1), centre(p0)));
            REQUIRE(w.add_body<0>(shapes[1], 500.0, p1, {}, screw<double>{omega[0], omega[1], omega[2], v1[0], v1[1], v1[2]}));
            const vec3<double> joint = ctga::linear3::scale(0.5, ctga::linear3::add(centre(p0), centre(p1)));
            REQUIRE(w.add_joint(ctga::fixed_joint<double>{ctga::body<0>(0), ctga::body<0>(1), body_frame(p0, ctga::linear3::sub(joint, centre(p0))),
                                                          body_frame(p1, ctga::linear3::sub(joint, centre(p1)))}));
            // momentum, and angular momentum about the pair's centre of mass: Σ R I_c Rᵀ ω + m (c − c̄) × v
            const auto momenta = [&] {
                vec3<double> p{}, L{}, c{};
                for (std::size_t i = 0; i < 2; ++i) c = ctga::linear3::add_scaled(c, props[i].mass / mass, centre(w.pose<0>(i)));
                for (std::size_t i = 0; i < 2; ++i) {
                    const screw<double> s = w.velocity<0>(i);
                    const auto R = ctga::map_of(w.pose<0>(i)).R;
                    const vec3<double> wb = ctga::linear3::apply_transposed(R, vec3<double>{s[0], s[1], s[2]}), v{s[3], s[4], s[5]};
                    p = ctga::linear3::add_scaled(p, props[i].mass, v);
                    L = ctga::linear3::add(L, ctga::linear3::apply(R, ctga::linear3::apply(props[i].inertia_c, wb)));
                    L = ctga::linear3::add(L, ctga::linear3::scale(props[i].mass, ctga::linear3::cross(ctga::linear3::sub(centre(w.pose<0>(i)), c), v)));
                }
                return std::pair{p, L};
            };
            const auto [p_start, L_start] = momenta();
            result out{0, 0, 0, 0};
            for (int k = 0; k < static_cast<int>(std::lround(duration / step)); ++k) {
                const ctga::step_report<double> r = w.step(step);
                REQUIRE(r.error == ctga::error_code::none);
                out.gap = std::max(out.gap, r.joint_error), out.angle = std::max(out.angle, r.joint_angle);
            }
            const auto [p_end, L_end] = momenta();
            const vec3<double> dp = ctga::linear3::sub(p_end, ctga::linear3::add(p_start, vec3<double>{0.0, 0.0, -mass * g * duration}));
            const vec3<double> dL = ctga::linear3::sub(L_end, L_start);
            out.momentum = std::sqrt(ctga::linear3::dot(dp, dp)) / (mass * g * duration);
            out.turn = std::sqrt(ctga::linear3::dot(dL, dL) / ctga::linear3::dot(L_start, L_start));
            return out;
        };
        const result coarse = run(1e-3), fine = run(5e-4);
        CHECK(coarse.momentum <= 1e-12);
        CHECK(fine.momentum <= 1e-12);
        CHECK(fine.turn <= 0.55 * coarse.turn);  // (measured 1.04e-4 and 5.2e-5)
        CHECK(coarse.turn <= 2e-4);
        CHECK(fine.gap <= 0.3 * coarse.gap);  // the gap a step opens is second order (1.2e-7 and 3.0e-8 m)
        CHECK(coarse.gap <= 2e-7);
        // both bodies end a solved step with one ω and turn by the same exp(h ω̄): the weld's angle stays at rounding
        CHECK(coarse.angle <= 1e-14);
        CHECK(fine.angle <= 1e-14);
    }
    // distance: a ball held at a length from a point of the ground, from rest: its acceleration
    // is gravity without its part along the rod
    {
        const double L = 0.9, theta = 0.6;
        const vec3<double> n{std::sin(theta), 0.0, -std::cos(theta)};  // from the pivot to the ball
        ctga::physics_world<double, plane, ball> w({1}, {.statics = 0, .contacts = 4, .pairs = 4, .joints = 1});
        w.settings().gravity = {0.0, 0.0, -g};
        w.settings().solver.tolerance = 1e-13;
        const vec3<double> pivot{0.0, 0.0, 2.0}, at = ctga::linear3::add_scaled(pivot, L, n);
        REQUIRE(w.add_body<0>(*collision::make_sphere(0.1), 1000.0, motor<double>(ctga::make_translator(at[0], at[1], at[2]))));
        REQUIRE(w.add_joint(ctga::distance_joint<double>{ctga::body<0>(0), ctga::ground, {}, pivot, L}));
        REQUIRE(w.step(h).error == ctga::error_code::none);
        const screw<double> s = w.velocity<0>(0);
        const vec3<double> gravity{0.0, 0.0, -g}, expected = ctga::linear3::add_scaled(gravity, -ctga::linear3::dot(gravity, n), n);
        for (std::size_t i = 0; i < 3; ++i) CHECK(std::abs(s[3 + i] / h - expected[i]) <= 1e-12 * g);
    }
}

TEST_CASE("world: a motor drives a joint at its effort up to its speed, limits stop a revolute and a prismatic joint") {
    using ctga::vec3;
    // a wheel (a box) on a revolute joint about z, gravity along the axis: the motor's torque τ
    // turns it at τ / I_z until it reaches the speed, then holds it there
    {
        const auto wheel = *collision::make_box(0.3, 0.1, 0.05);
        const double Iz = collision::mass_of(wheel, 500.0)->inertia_c[2][2], tau = 0.5, speed = 2.0;
        ctga::physics_world<double, plane, cube> w({1}, {.statics = 0, .contacts = 4, .pairs = 4, .joints = 1});
        w.settings().gravity = {0.0, 0.0, -g};
        w.settings().solver.tolerance = 1e-12;
        REQUIRE(w.add_body<0>(wheel, 500.0, motor<double>(ctga::make_translator(0.0, 0.0, 1.0))));
        const vec3<double> z{0.0, 0.0, 1.0};
        // (the joint's speed is b's relative to a's: the wheel is b)
        REQUIRE(w.add_joint(ctga::revolute_joint<double>{ctga::ground, ctga::body<0>(0), {0.0, 0.0, 1.0}, {}, z, z, {}, {speed, tau}}));
        for (int k = 1; k <= 120; ++k) {
            REQUIRE(w.step(h).error == ctga::error_code::none);
            const double t = k * h, reach = speed * Iz / tau;
            if (std::abs(t - reach) > h) CHECK(std::abs(w.velocity<0>(0)[2] - (t < reach ? tau * t / Iz : speed)) <= 1e-9 * speed);
        }
    }
    // a pendulum (a box 0.6 m from a hinge about y) let go level swings down until its angle
    // reaches the upper limit of 0.5 rad and rests there
    {
        const double l = 0.6, upper = 0.5;
        ctga::physics_world<double, plane, cube> w({1}, {.statics = 0, .contacts = 4, .pairs = 4, .joints = 1});
        w.settings().gravity = {0.0, 0.0, -g};
        w.settings().solver.tolerance = 1e-12;
        REQUIRE(w.add_body<0>(*collision::make_box(0.1, 0.1, 0.1), 800.0, motor<double>(ctga::make_translator(l, 0.0, 1.0))));
        const vec3<double> y{0.0, 1.0, 0.0};
        REQUIRE(w.add_joint(ctga::revolute_joint<double>{ctga::ground, ctga::body<0>(0), {0.0, 0.0, 1.0}, {-l, 0.0, 0.0}, y, y, {-1.0, upper}}));
        double furthest = 0, angle = 0;
        for (int k = 0; k < 180; ++k) {
            REQUIRE(w.step(h).error == ctga::error_code::none);
            const vec3<double> c = centre(w.pose<0>(0));
            angle = std::atan2(1.0 - c[2], c[0]);  // R_y(θ) takes x to (cos θ, 0, −sin θ)
            furthest = std::max(furthest, angle);
        }
        CHECK(furthest <= upper + 1e-9);
        CHECK(std::abs(angle - upper) <= 1e-6);
        CHECK(std::abs(w.velocity<0>(0)[1]) <= 1e-9);
    }
    // a box on a vertical slide given from the ground's side (the joint turned around inside):
    // it falls to the limit of 0.5 m and rests there
    {
        ctga::physics_world<double, plane, cube> w({1}, {.statics = 0, .contacts = 4, .pairs = 4, .joints = 1});
        w.settings().gravity = {0.0, 0.0, -g};
        w.settings().solver.tolerance = 1e-12;
        REQUIRE(w.add_body<0>(*collision::make_box(0.1, 0.1, 0.1), 800.0, motor<double>(ctga::make_translator(0.0, 0.0, 2.0))));
        REQUIRE(w.add_joint(ctga::prismatic_joint<double>{ctga::ground, ctga::body<0>(0), {0.0, 0.0, 2.0}, {}, {0.0, 0.0, -1.0}, {-1.0, 0.5}}));
        double lowest = 2.0;
        for (int k = 0; k < 120; ++k) {
            REQUIRE(w.step(h).error == ctga::error_code::none);
            lowest = std::min(lowest, centre(w.pose<0>(0))[2]);
        }
        CHECK(lowest >= 1.5 - 1e-9);
        CHECK(std::abs(centre(w.pose<0>(0))[2] - 1.5) <= 1e-6);
        CHECK(std::abs(w.velocity<0>(0)[5]) <= 1e-9);
    }
}

TEST_CASE("world: an elastic coupling of §7 holds a body where K balances its weight and rings at √(k/m)") {
    using ctga::vec3;
    const auto shape = *collision::make_box(0.05, 0.1, 0.15);
    const auto props = *collision::mass_of(shape, 500.0);
    // hanging from the ground by a coupling whose frame is turned and sits at a corner of the body;
    // K with a rotation–translation term, D near critical: it settles where −K ξ balances gravity's
    // wrench about the frame's origin, computed here from the final pose
    {
        ctga::physics_world<double, plane, cube> w({1}, {.statics = 0, .contacts = 4, .pairs = 4, .couplings = 1});
        w.settings().gravity = {0.0, 0.0, -g};
        const motor<double> pose(ctga::make_translator(0.0, 0.0, 1.0));
        REQUIRE(w.add_body<0>(shape, 500.0, pose));
        const motor<double> frame = motor<double>(ctga::make_translator(0.05, 0.0, 1.15)) * motor<double>(ctga::make_rotor(0.3, 1.0, 1.0, 0.0));
        ctga::elastic_coupling<double> c{ctga::ground, ctga::body<0>(0), frame, motor<double>(ctga::conj(pose) * frame), {}, {}};
        for (std::size_t i = 0; i < 6; ++i) {
            c.stiffness[i][i] = i < 3 ? 125.0 : 3e4;
            c.damping[i][i] = i < 3 ? 2.5 : 600.0;
        }
        c.stiffness[0][4] = c.stiffness[4][0] = 100.0;
        REQUIRE(w.add_coupling(c));
        for (int k = 0; k < 3000; ++k) REQUIRE(w.step(1e-3).error == ctga::error_code::none);
        const motor<double> B = motor<double>(w.pose<0>(0) * c.frame_b);
        const screw<double> xi = ctga::log(motor<double>(ctga::conj(frame) * B));
        const auto A = ctga::map_of(frame);
        const vec3<double> p = ctga::map_of(B).t, weight{0.0, 0.0, -props.mass * g};
        const vec3<double> torque = ctga::linear3::apply_transposed(A.R, ctga::linear3::cross(ctga::linear3::sub(centre(w.pose<0>(0)), p), weight));
        const vec3<double> force = ctga::linear3::apply_transposed(A.R, weight);
        const std::array<double, 6> load{torque[0], torque[1], torque[2], force[0], force[1], force[2]};
        double scale = 0;
        for (const double x : load) scale = std::max(scale, std::abs(x));
        for (std::size_t i = 0; i < 6; ++i) {
            double Kxi = 0;
            for (std::size_t j = 0; j < 6; ++j) Kxi += c.stiffness[i][j] * xi[j];
            CHECK(std::abs(Kxi - load[i]) <= 1e-8 * scale);
        }
        CHECK(std::abs(xi[3]) + std::abs(xi[4]) + std::abs(xi[5]) > 1e-4);  // it did sag
    }
    // free of gravity, a spring along x at the centre, pulled 1 mm: x = x₀ cos(√(k/m) t); the
    // period between upward zero crossings, to about (ω h)² (the wrench is taken at the step's start)
    {
        const double k = 3e4, step = 1e-4;
        ctga::physics_world<double, plane, cube> w({1}, {.statics = 0, .contacts = 4, .pairs = 4, .couplings = 1});
        w.settings().gravity = {0.0, 0.0, 0.0};
        REQUIRE(w.add_body<0>(shape, 500.0, motor<double>(ctga::make_translator(0.001, 0.0, 1.0))));
        ctga::elastic_coupling<double> c{ctga::ground, ctga::body<0>(0), motor<double>(ctga::make_translator(0.0, 0.0, 1.0)), motor<double>{1, 0, 0, 0, 0, 0, 0, 0}, {}, {}};
        c.stiffness[3][3] = k;
        REQUIRE(w.add_coupling(c));
        const double omega = std::sqrt(k / props.mass);
        std::vector<double> crossings;
        double last = centre(w.pose<0>(0))[0];
        for (int n = 1; n <= 4000 && crossings.size() < 3; ++n) {
            REQUIRE(w.step(step).error == ctga::error_code::none);
            const double x = centre(w.pose<0>(0))[0];
            if (last < 0 && x >= 0) crossings.push_back((n - 1 + -last / (x - last)) * step);
            last = x;
        }
        REQUIRE(crossings.size() >= 2);
        const double period = 2 * M_PI / omega;
        CHECK(std::abs((crossings[1] - crossings[0]) - period) <= 1e-4 * period);  // (measured 1.1e-5)
    }
    CHECK(ctga::physics_world<double, plane, cube>({1}, {.couplings = 1})
              .add_coupling(ctga::elastic_coupling<double>{ctga::ground, ctga::ground, motor<double>{1, 0, 0, 0, 0, 0, 0, 0},
                                                           motor<double>{1, 0, 0, 0, 0, 0, 0, 0}, {}, {}})
              .error == ctga::error_code::joint_to_itself);
}

TEST_CASE("world: on a soft surface (§7's K and D as a contact compliance) a box sinks m g / (4 k), a ball stays π/ω") {
    // K and D in the ground's frame: a box turned so that its local y is the world's z; only
    // the translation block along the contact's normal in that frame acts, k = nᵀ K_vv n = K_yy.
    const auto compliance = [](const ctga::vec3<double>& k, const ctga::vec3<double>& d) {
        ctga::contact_compliance<double> c;
        for (std::size_t i = 0; i < 3; ++i) c.stiffness[3 + i][3 + i] = k[i], c.damping[3 + i][3 + i] = d[i];
        c.stiffness[0][0] = c.stiffness[1][1] = c.stiffness[2][2] = 1.0;  // (rotation blocks: a point contact has no rows for them)
        return c;
    };
    // (and in the soft step, constraints/soft_step.hpp: at rest c r_n + b = 0 there too)
    for (const std::size_t substeps : {0, 4}) {
        const double k = 1e5, m = 100.0, omega = std::sqrt(4 * k / m), d = m * omega / 2;  // critical for the four corners together
        ctga::physics_world<double, collision::box<double>, cube> w({1}, {.statics = 1, .contacts = 16, .pairs = 4});
        w.settings().solver.tolerance = 1e-13;
        w.settings().substeps = substeps;
        const motor<double> turned = ctga::make_translator(0.0, 0.0, -0.5) * ctga::make_rotor(std::acos(-1.0) / 2, 1.0, 0.0, 0.0);
        REQUIRE(w.add_static(*collision::make_box(5.0, 0.5, 5.0), turned, {0.6, 0.0}));
        REQUIRE(w.set_compliance(0, compliance({7 * k, k, 9 * k}, {7 * d, d, 9 * d})) == ctga::error_code::none);
        REQUIRE(w.add_body<0>(*collision::make_box(0.5, 0.5, 0.5), 100.0, motor<double>(ctga::make_translator(0.0, 0.0, 0.5)), {0.6, 0.0}));
        ctga::step_report<double> r;
        for (int step = 0; step < 300; ++step) REQUIRE((r = w.step(h)).error == ctga::error_code::none);
        const double sink = 0.5 - centre(w.pose<0>(0))[2], want = m * g / (4 * k);
        CHECK(r.contacts == 4);
        CHECK(std::abs(sink / want - 1) <= 1e-9);  // 2.45 mm
        CHECK(std::abs(r.penetration / want - 1) <= 1e-6);
        CHECK(speed(w.velocity<0>(0)) <= 1e-9);
    }
    {
        // a ball meets the surface at 1 m/s with no gravity and no damping: a half period of the
        // spring, π/ω, in contact, and it leaves at the speed it came (steps of h ω = 0.01)
        const double radius = 0.1, m = 1.0, omega = 100.0, k = m * omega * omega, step = 1e-4;
        ctga::physics_world<double, plane, ball> w({1}, {.statics = 1, .contacts = 4, .pairs = 2});
        w.settings().gravity = {0.0, 0.0, 0.0};
        w.settings().solver.tolerance = 1e-13;
        REQUIRE(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {0.0, 0.0}));
        REQUIRE(w.set_compliance(0, compliance({k, k, k}, {0.0, 0.0, 0.0})) == ctga::error_code::none);
        const double density = m / (4.0 / 3.0 * std::acos(-1.0) * radius * radius * radius);
        REQUIRE(w.add_body<0>(*collision::make_sphere(radius), density, motor<double>(ctga::make_translator(0.0, 0.0, radius)), {0.0, 0.0},
                              screw<double>{0, 0, 0, 0, 0, -1.0}));
        int pressed = 0;
        double deepest = 0;
        for (int n = 0; n < 600; ++n) {
            REQUIRE(w.step(step).error == ctga::error_code::none);
            pressed += w.contact_rows().size() > 0 && w.contact_impulse(0)[0] > 0;
            deepest = std::max(deepest, radius - centre(w.pose<0>(0))[2]);
        }
        const double half_period = std::acos(-1.0) / omega;
        CHECK(std::abs(pressed * step / half_period - 1) <= 0.01);
        CHECK(std::abs(deepest / (1.0 / omega) - 1) <= 0.03);  // v / ω = 1 cm
        const double out = w.velocity<0>(0)[5];  // (measured 0.992: the implicit spring loses a little, never gains)
        CHECK(out <= 1.0);
        CHECK(out >= 0.98);
    }
    // bad compliances
    ctga::physics_world<double, plane, ball> w({1}, {.statics = 1, .contacts = 4, .pairs = 2});
    REQUIRE(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {0.0, 0.0}));
    CHECK(w.set_compliance(1, compliance({1.0, 1.0, 1.0}, {})) == ctga::error_code::bad_index);
    CHECK(w.set_compliance(0, compliance({1.0, 0.0, 1.0}, {})) == ctga::error_code::not_positive_definite);
    CHECK(w.set_compliance(0, compliance({1.0, 1.0, 1.0}, {-1.0, 0.0, 0.0})) == ctga::error_code::not_positive_definite);
    CHECK(w.set_compliance(0, compliance({1.0, std::nan(""), 1.0}, {})) == ctga::error_code::non_finite);
    auto skew = compliance({1.0, 1.0, 1.0}, {});
    skew.stiffness[3][4] = 0.5;
    CHECK(w.set_compliance(0, skew) == ctga::error_code::not_symmetric);
}

TEST_CASE("world: a box dropped on a conveyor is carried up to the belt's speed at μ g") {
    // a unit cube at rest on a kinematic belt (a box shape moving at 2 m/s along x), μ = 0.5: friction
    // accelerates it at μ g until it moves with the belt, at t* = 2 / (μ g), then it rides along
    const double mu = 0.5, belt = 2.0;
    ctga::physics_world<double, collision::box<double>, cube> w({1}, {.statics = 1, .contacts = 16, .pairs = 4});
    w.settings().gravity = {0.0, 0.0, -g};
    w.settings().solver.tolerance = 1e-12;
    REQUIRE(w.add_kinematic(*collision::make_box(50.0, 5.0, 0.5), motor<double>(ctga::make_translator(0.0, 0.0, -0.5)), screw<double>{0, 0, 0, belt, 0, 0},
                            {mu, 0.0}));
    REQUIRE(w.add_body<0>(*collision::make_box(0.5, 0.5, 0.5), 100.0, motor<double>(ctga::make_translator(0.0, 0.0, 0.5)), {mu, 0.0}));
    const double ride = belt / (mu * g);
    for (int k = 1; k <= 60; ++k) {
        REQUIRE(w.step(h).error == ctga::error_code::none);
        const double t = k * h, expected = t < ride ? mu * g * t : belt;
        if (std::abs(t - ride) > h) CHECK(std::abs(w.velocity<0>(0)[3] - expected) <= 1e-9 * belt);
        CHECK(std::abs(w.velocity<0>(0)[5]) <= 1e-9);
    }
    CHECK(w.set_kinematic_velocity(1, screw<double>{}) == ctga::error_code::bad_index);
    CHECK(w.set_kinematic_velocity(0, screw<double>{0, 0, 0, std::numeric_limits<double>::quiet_NaN(), 0, 0}) == ctga::error_code::non_finite);
}

TEST_CASE("world: a fast ball does not pass through a thin wall") {
    // a 10 cm ball (e = 0, no gravity) thrown at a 2 cm static wall from 3 m: at 1,000 m/s a step
    // is 16.7 m; the speculative reach finds the wall, the impact stops the ball, and the position
    // correction removes what its last half step would have carried it in
    for (const double speed : {10.0, 100.0, 1000.0}) {
        ctga::physics_world<double, collision::box<double>, ball> w({1}, {.statics = 1, .contacts = 8, .pairs = 4});
        w.settings().gravity = {0.0, 0.0, 0.0};
        REQUIRE(w.add_static(*collision::make_box(0.01, 1.0, 1.0), motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {0.0, 0.0}));
        REQUIRE(w.add_body<0>(*collision::make_sphere(0.05), 1000.0, motor<double>(ctga::make_translator(-3.0, 0.0, 0.0)), {0.0, 0.0},
                              screw<double>{0, 0, 0, speed, 0, 0}));
        double furthest = -3.0;
        for (int k = 0; k < 30; ++k) {
            REQUIRE(w.step(h).error == ctga::error_code::none);
            furthest = std::max(furthest, centre(w.pose<0>(0))[0]);
        }
        CHECK(furthest <= -0.06 + w.settings().slop + 1e-12);  // the ball's front at most the slop into the wall's face
        CHECK(std::abs(w.velocity<0>(0)[3]) <= 1e-9);
    }
}

TEST_CASE("world: a box pinched between two fingers holds when μF > mg/2 and slides at the Coulomb rate when not") {
    // fingers 4 x 10 x 10 cm (density 1000) either side of a 10 cm cube (density 500), μ = 0.5, no
    // ground: each finger carries its weight and half the box's, presses with F towards the other
    // along the line between them (an internal pair) and is held level by the torque that balances
    // the friction at its face; the box hangs by friction alone
    for (const double F : {10.0, 4.0}) {
        const double mu = 0.5;
        ctga::physics_world<double, plane, cube> w({3}, {.statics = 0, .contacts = 32, .pairs = 8});
        w.settings().solver.tolerance = 1e-12;
        REQUIRE(w.add_body<0>(*collision::make_box(0.05, 0.05, 0.05), 500.0, motor<double>(ctga::make_translator(0.0, 0.0, 1.0)), {mu, 0.0}));
        for (const double side : {-1.0, 1.0})
            REQUIRE(w.add_body<0>(*collision::make_box(0.02, 0.05, 0.05), 1000.0, motor<double>(ctga::make_translator(0.07 * side, 0.0, 1.0)),
                                  {mu, 0.0}));
        const double mb = w.body<0>(0).m(), mf = w.body<0>(1).m();
        double worst = 0, slip = 0;
        for (int k = 0; k < 600; ++k) {
            const ctga::vec3<double> a = centre(w.pose<0>(1)), b = centre(w.pose<0>(2));
            ctga::vec3<double> d = ctga::linear3::sub(b, a);
            d = ctga::linear3::scale(1 / std::sqrt(ctga::linear3::dot(d, d)), d);
            w.set_wrench<0>(1, {F * d[0], F * d[1], F * d[2] + (mf + mb / 2) * g}, {0.0, -0.01 * mb * g, 0.0});
            w.set_wrench<0>(2, {-F * d[0], -F * d[1], -F * d[2] + (mf + mb / 2) * g}, {0.0, 0.01 * mb * g, 0.0});
            const ctga::step_report<double> r = w.step(h);
            REQUIRE(r.error == ctga::error_code::none);
            CHECK(r.contact.converged);
            slip = w.velocity<0>(0)[5] - (w.velocity<0>(1)[5] + w.velocity<0>(2)[5]) / 2;
            worst = std::max(worst, std::abs(slip));
            if (F < mb * g / (2 * mu)) break;  // the weak grip: one step of sliding is the test
        }
        if (mu * F > mb * g / 2) CHECK(worst <= 1e-6);  // the issue asks < 1 µm/s (MuJoCo users measure 50-155 µm/s)
        else {
            // sliding: the box falls at (2μF − m_b g)/m_b, each finger at (m_b g/2 − μF)/m_f, from rest
            const double relative = (2 * mu * F - mb * g) / mb - (mb * g / 2 - mu * F) / mf;
            CHECK(std::abs(slip / h - relative) <= 1e-9 * std::abs(relative));
        }
    }
}

TEST_CASE("world: the soft step: a box rests g/ω² deep, a hanging box stretches its joint as much, a block slides at g (sin θ − μ cos θ)") {
    // (constraints/soft_step.hpp: at rest u = 0 and Δr = 0 give m_eff σ β C = −τ r with r = m g h_s
    // shared by points of equal gaps; τ h_s / (σ β) = 1/ω², so C = −g/ω² whatever the mass, for
    // a box on its four corners (W_nn r_i = g h_s: the corner's arm × n meets I⁻¹ as 3/m does) and a
    // body hanging under its joint (arm ∥ r: A r = r / m); contacts and joints both at a quarter of
    // the substeps' rate, the most either may be)
    constexpr std::size_t n = 4;
    const double omega = 2 * std::numbers::pi * 0.25 * n / h;  // a quarter of the substeps' rate
    {
        ctga::physics_world<double, plane, cube> w({2}, {.statics = 1, .contacts = 16, .pairs = 4, .joints = 1});
        w.settings().substeps = n;
        REQUIRE(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {0.6, 0.0}));
        const auto box = *collision::make_box(0.5, 0.5, 0.5);
        REQUIRE(w.add_body<0>(box, 100.0, motor<double>(ctga::make_translator(0.0, 0.0, 0.5))));
        REQUIRE(w.add_body<0>(box, 300.0, motor<double>(ctga::make_translator(5.0, 0.0, 3.0))));  // hanging from (5, 0, 4)
        REQUIRE(w.add_joint(spherical{ctga::body<0>(1), ctga::ground, {0.0, 0.0, 1.0}, {5.0, 0.0, 4.0}}));
        ctga::step_report<double> r;
        for (int k = 0; k < 300; ++k) REQUIRE((r = w.step(h)).error == ctga::error_code::none);
        CHECK(r.contacts == 4);
        CHECK(std::isnan(r.contact.residual));  // the soft step measures none
        CHECK(std::abs(r.penetration * omega * omega / g - 1) <= 1e-9);
        CHECK(std::abs(centre(w.pose<0>(0))[2] - (0.5 - g / (omega * omega))) <= 1e-12);
        CHECK(std::abs((4.0 - centre(w.pose<0>(1))[2] - 1.0) * omega * omega / g - 1) <= 1e-9);
        CHECK(std::abs(r.joint_error * omega * omega / g - 1) <= 1e-9);
        // the weight over the step, on the ground (side b): the body (side a) is held up by its opposite
        CHECK(std::abs(w.joint_impulse(0)[2] + w.body<0>(1).m() * g * h) <= 1e-9 * w.body<0>(1).m() * g * h);
    }
    {
        const double theta = 0.3, mu = 0.2, a = g * (std::sin(theta) - mu * std::cos(theta));
        incline s(theta, mu);
        s.w.settings().substeps = n;
        for (int k = 0; k < 60; ++k) REQUIRE(s.w.step(h).error == ctga::error_code::none);  // (settled on its springs)
        double v_before = speed(s.w.velocity<0>(0)), worst = 0;
        for (int k = 0; k < 540; ++k) {
            REQUIRE(s.w.step(h).error == ctga::error_code::none);
            const double v = speed(s.w.velocity<0>(0));
            worst = std::max(worst, std::abs((v - v_before) / h - a) / a);
            v_before = v;
        }
        CHECK(worst <= 1e-9);
    }
    {
        ctga::physics_world<double, plane, cube> w({1}, {.statics = 1, .contacts = 16, .pairs = 4});
        w.settings().substeps = n;
        REQUIRE(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0))));
        REQUIRE(w.add_body<0>(*collision::make_box(0.5, 0.5, 0.5), 100.0, motor<double>(ctga::make_translator(0.0, 0.0, 0.5))));
        w.settings().contact_hertz = std::numeric_limits<double>::quiet_NaN();
        CHECK(w.step(h).error == ctga::error_code::non_finite);
        w.settings().contact_hertz = 0, w.settings().push_speed = 0;
        CHECK(w.step(h).error == ctga::error_code::negative_limit);
        w.settings().push_speed = 3, w.settings().contact_damping = -1;
        CHECK(w.step(h).error == ctga::error_code::negative_limit);
    }
}

TEST_CASE("world: the same state, bit for bit, with one thread and with two, run after run") {
    // (300 steps: 1,000 took 22 s of this unit at -Og with two threads, for no more of the code)
    // a pyramid of 21 cubes and a chain of 6 spheres on spherical joints swinging into it: two body
    // kinds, contacts and joints in one problem, more rows than Newton's limit (the sweeps run)
    // (and the soft step: constraints/soft_step.hpp)
    const auto run = [](std::size_t threads, std::size_t substeps = 0) {
        ctga::world_settings<double> set;
        set.threads = threads;
        set.substeps = substeps;
        set.partitions = 2;
        set.parallel_rows = 0;  // the team sweeps however few rows there are
        set.solver.tolerance = 1e-9;
        set.solver.max_sweeps = 30;
        ctga::physics_world<double, plane, cube, ball> w({21, 6}, {.statics = 1, .contacts = 512, .pairs = 256, .joints = 6}, set);
        REQUIRE(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {0.6, 0.0}));
        const auto box = *collision::make_box(0.5, 0.5, 0.5);
        for (int i = 0; i < 6; ++i)
            for (int j = i; j < 6; ++j)
                REQUIRE(w.add_body<0>(box, 100.0, motor<double>(ctga::make_translator(i * 0.5 + (j - i) * 1.0 - 3.0, 0.0, 0.5 + i)), {0.6, 0.0}));
        for (int k = 0; k < 6; ++k) {
            REQUIRE(w.add_body<1>(*collision::make_sphere(0.25), 500.0, motor<double>(ctga::make_translator(-6.0 + 0.5 * k, 0.0, 6.0))));
            if (k == 0) REQUIRE(w.add_joint(spherical{ctga::body<1>(0), ctga::ground, {-0.25, 0.0, 0.0}, {-6.25, 0.0, 6.0}}));
            else REQUIRE(w.add_joint(spherical{ctga::body<1>(k), ctga::body<1>(k - 1), {-0.25, 0.0, 0.0}, {0.25, 0.0, 0.0}}));
        }
        std::size_t rows = 0;
        for (int k = 0; k < 300; ++k) {
            const ctga::step_report<double> r = w.step(h);
            REQUIRE(r.error == ctga::error_code::none);
            rows = std::max(rows, r.contacts);
        }
        CHECK(rows > 64);
        std::uint64_t hash = 1469598103934665603ull;  // FNV-1a over the poses' and velocities' bytes
        const auto mix = [&](const auto& x) {
            const auto* bytes = reinterpret_cast<const unsigned char*>(&x);
            for (std::size_t i = 0; i < sizeof(x); ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
        };
        for (std::size_t i = 0; i < 21; ++i) mix(w.pose<0>(i)), mix(w.velocity<0>(i));
        for (std::size_t i = 0; i < 6; ++i) mix(w.pose<1>(i)), mix(w.velocity<1>(i));
        return hash;
    };
    const std::uint64_t one = run(1);
    CHECK(run(2) == one);
    CHECK(run(1) == one);
    CHECK(run(2) == one);
    const std::uint64_t soft = run(1, 4);
    CHECK(soft != one);
    CHECK(run(2, 4) == soft);
}

TEST_CASE("world: bad input is refused, a step that goes non-finite keeps the last good state") {
    ctga::physics_world<double, plane, cube> w({1}, {.statics = 1, .contacts = 16, .pairs = 4});
    const auto box = *collision::make_box(0.5, 0.5, 0.5);
    const motor<double> pose(ctga::make_translator(0.0, 0.0, 0.5));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(w.add_body<0>(box, 0.0, pose).error == ctga::error_code::non_positive_mass);
    CHECK(w.add_body<0>(box, nan, pose).error == ctga::error_code::non_finite);
    CHECK(w.add_body<0>(box, 100.0, pose, {-0.1, 0.0}).error == ctga::error_code::negative_friction);
    CHECK(w.add_body<0>(box, 100.0, motor<double>{2, 0, 0, 0, 0, 0, 0, 0}).error == ctga::error_code::not_a_motor);
    CHECK(w.add_body<0>(box, 100.0, pose, {}, screw<double>{0, 0, nan, 0, 0, 0}).error == ctga::error_code::non_finite);
    CHECK(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0)), {nan, 0.0}).error == ctga::error_code::non_finite);
    REQUIRE(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0))));
    CHECK(w.add_static(plane{}, motor<double>(ctga::make_translator(0.0, 0.0, 0.0))).error == ctga::error_code::capacity_exceeded);
    REQUIRE(w.add_body<0>(box, 100.0, pose));
    CHECK(w.add_body<0>(box, 100.0, pose).error == ctga::error_code::capacity_exceeded);
    {
        ctga::physics_world<double, plane, cube> jw({2}, {.statics = 0, .contacts = 4, .pairs = 4, .joints = 2});
        REQUIRE(jw.add_body<0>(box, 100.0, pose));
        CHECK(jw.add_joint(spherical{ctga::body<0>(0), ctga::body<0>(0), {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}).error == ctga::error_code::joint_to_itself);
        CHECK(jw.add_joint(spherical{ctga::ground, ctga::ground, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}).error == ctga::error_code::joint_to_itself);
        CHECK(jw.add_joint(spherical{ctga::body<0>(0), ctga::body<0>(1), {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}).error == ctga::error_code::bad_index);
        CHECK(jw.add_joint(spherical{ctga::body<0>(0), ctga::ground, {nan, 0.0, 0.0}, {0.0, 0.0, 0.0}}).error == ctga::error_code::non_finite);
        const ctga::vec3<double> o{}, x{1.0, 0.0, 0.0};
        CHECK(jw.add_joint(ctga::revolute_joint<double>{ctga::body<0>(0), ctga::ground, o, o, x, o}).error == ctga::error_code::zero_direction);
        CHECK(jw.add_joint(ctga::prismatic_joint<double>{ctga::body<0>(0), ctga::ground, o, o, {nan, 0.0, 0.0}}).error == ctga::error_code::non_finite);
        CHECK(jw.add_joint(ctga::distance_joint<double>{ctga::body<0>(0), ctga::ground, o, x, 0.0}).error == ctga::error_code::non_positive_size);
        CHECK(jw.add_joint(ctga::revolute_joint<double>{ctga::body<0>(0), ctga::ground, o, o, x, x, {1.0, -1.0}}).error == ctga::error_code::limits_reversed);
        CHECK(jw.add_joint(ctga::prismatic_joint<double>{ctga::body<0>(0), ctga::ground, o, o, x, {}, {1.0, -2.0}}).error == ctga::error_code::negative_limit);
        CHECK(jw.add_joint(ctga::prismatic_joint<double>{ctga::body<0>(0), ctga::ground, o, o, x, {nan, 0.0}}).error == ctga::error_code::non_finite);
        // capacity: two joints are six blocks; a spherical joint and two fixed ones fill five, a
        // third fixed one finds one left
        REQUIRE(jw.add_joint(spherical{ctga::body<0>(0), ctga::ground, o, o}));
        REQUIRE(jw.add_joint(ctga::fixed_joint<double>{ctga::body<0>(0), ctga::ground, o, o}));
        REQUIRE(jw.add_joint(ctga::fixed_joint<double>{ctga::body<0>(0), ctga::ground, o, o}));
        CHECK(jw.add_joint(ctga::fixed_joint<double>{ctga::body<0>(0), ctga::ground, o, o}).error == ctga::error_code::capacity_exceeded);
    }
    CHECK(w.add_joint(spherical{ctga::body<0>(0), ctga::ground, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}).error == ctga::error_code::capacity_exceeded);
    CHECK(w.step(nan).error == ctga::error_code::non_finite);
    CHECK(w.step(-h).error == ctga::error_code::non_finite);
    REQUIRE(w.step(h).error == ctga::error_code::none);
    const motor<double> good = w.pose<0>(0);
    w.set_velocity<0>(0, screw<double>{0, 0, 0, std::numeric_limits<double>::infinity(), 0, 0});
    CHECK(w.step(h).error == ctga::error_code::non_finite);
    for (std::size_t c = 0; c < 8; ++c) CHECK(w.pose<0>(0)[c] == good[c]);
}
