// What the mechanics costs, in multiplications and additions of real numbers.
//
// The algebra's formulas are priced by the engine (cost_of, static_asserted against the counts
// the hand-written 6D spatial algebra pays, docs/benchmarks.md). The maps built once from a motor (motor_map) are plain structured
// arithmetic; their operations are counted by running them on a scalar type that counts
// (`counted`, below), against the hand-written spatial-algebra figures: Pinocchio's 24m 18a for a
// screw or co-screw transform and ≈ 38m 37a for an inertia transform, with a 2× allowance.
#include <cstdio>

#include <ctga/ctga.hpp>
#include <ctga/mechanics/dynamics.hpp>

#include "support/catch.hpp"
#include "support/published.hpp"

namespace scalars {

// A double that counts the arithmetic done on it. Negation is free (a sign flip), as in every
// operation count of this project.
struct counted {
    double v = 0;
    static inline long mul = 0, add = 0, div = 0;
    static void reset() { mul = add = div = 0; }

    constexpr counted() = default;
    constexpr counted(double x) : v(x) {}
    friend counted operator+(counted a, counted b) { ++add; return {a.v + b.v}; }
    friend counted operator-(counted a, counted b) { ++add; return {a.v - b.v}; }
    friend counted operator*(counted a, counted b) { ++mul; return {a.v * b.v}; }
    friend counted operator/(counted a, counted b) { ++div; return {a.v / b.v}; }
    friend constexpr counted operator-(counted a) { return {-a.v}; }
    counted& operator+=(counted b) { return *this = *this + b; }
    friend constexpr bool operator==(counted a, counted b) { return a.v == b.v; }
    friend constexpr auto operator<=>(counted a, counted b) { return a.v <=> b.v; }
};

}  // namespace scalars

namespace {

using namespace ctga;
using scalars::counted;
using ctga::test::published;
using ctga::test::published_mul;

struct ops {
    long mul, add;
};
template <class F>
ops count(F f) {
    counted::reset();
    f();
    return {counted::mul, counted::add};
}

template <class T>
motor<T> some_motor() {
    const auto g = rigid_motion(make_translator(0.3, -1.2, 2.0), make_rotor(1.3, 0.48, 0.6, 0.64));
    motor<T> out;
    for (std::size_t i = 0; i < g.size(); ++i) out[i] = T(g[i]);
    return out;
}

template <class T>
mass_properties<T> some_body() {
    return {T(2.5), {T(0.1), T(-0.2), T(0.3)}, {{{T(1.1), T(0.1), T(0.05)}, {T(0.1), T(1.4), T(-0.1)}, {T(0.05), T(-0.1), T(1.9)}}}};
}

constexpr bool operator==(const ops& o, const expr::cost& c) {
    return o.mul == static_cast<long>(c.mul) && o.add == static_cast<long>(c.add);
}

TEST_CASE("costs of the maps built once from a motor and of the typed calls (counted), as docs/mechanics.md prints them",
          "[mechanics][cost]") {
    const motor<counted> g = some_motor<counted>();
    motor_map<counted> G;
    counted::reset();
    G = map_of(g);
    const ops build{counted::mul, counted::add};
    CHECK(build == published<31, 24>);
    CHECK(counted::div == 1);  // map_of: 31m 24a 1d
    const screw<counted> s{0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    const coscrew<counted> P{0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    const mass_properties<counted> body = some_body<counted>();
    const rigid_inertia<counted> N = inertia_of(body);
    const mobility<counted> M = mobility_of(body);
    const body_inertia<counted> Nb = body_inertia_of(body);
    const rigid_body<counted> rb = make_rigid_body(body);

    CHECK(count([&] { (void)transform(G, s); }) == published<24, 18>);
    CHECK(count([&] { (void)transform(G, P); }) == published<24, 18>);
    CHECK(count([&] { (void)transform(G, N); }) == published<54, 50>);
    CHECK(count([&] { (void)transform(G, Nb); }) == published<54, 50>);
    CHECK(count([&] { (void)transform(G, body); }) == published<54, 39>);
    CHECK(count([&] { (void)transform(G, M); }) == published<288, 216>);
    // velocity_from(body_mobility, P): the form about the centre of mass, Featherstone's §2.13
    CHECK(count([&] { (void)velocity_from(rb.Mb, P); }) == published<24, 18>);
    // ṡ: momentum + coadjoint + W − · + velocity, with the ten-parameter mobility or the 36 blades
    const wrench<counted> W{0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    CHECK(count([&] { (void)acceleration(rb, s, W); }) == published<66, 54>);
    CHECK(count([&] { (void)acceleration(N, M, s, W); }) == published<78, 66>);
    // a revolute joint about a coordinate axis turns two columns of the placement's R: 12m 6a
    CHECK(count([&] { (void)chains::joint_detail::rotate_about_axis<2>(G, counted(0.6), counted(0.8)); }) == published<12, 6>);
    // an aligned joint's map (chains::aligned: placement a translation) is R_z(q) itself, built
    // with no flops; its shape's zeros and ones are skipped: a screw or co-screw crosses it in
    // 14m 10a, a body inertia in 34m 33a (3 halvings), a pose composes in 21m 15a
    constexpr linear3::shape Sz = chains::joint_detail::axis_rotation_shape<2>;
    static_assert(linear3::apply_cost(Sz) == 6 && linear3::apply_cost(linear3::dense) == 15 &&
                  linear3::apply_cost(linear3::identity) == 0);
    counted::reset();
    const motor_map<counted> Gz{chains::joint_detail::axis_rotation<2>(counted(0.6), counted(0.8)), G.t};  // c, s of q
    CHECK((counted::mul == 0 && counted::add == 0));
    CHECK(count([&] { (void)transform<Sz>(Gz, s); }) == published<14, 10>);
    CHECK(count([&] { (void)transform_inverse<Sz>(Gz, s); }) == published<14, 10>);
    CHECK(count([&] { (void)transform<Sz>(Gz, P); }) == published<14, 10>);
    CHECK(count([&] { (void)transform<Sz>(Gz, Nb); }) == published<34, 33>);
    CHECK(count([&] { (void)compose<Sz>(G, Gz); }) == published<21, 15>);
    // … with the same results as the dense products on the same map
    const screw<counted> ds = transform(Gz, s), ss = transform<Sz>(Gz, s);
    const body_inertia<counted> dN = transform(Gz, Nb), sN = transform<Sz>(Gz, Nb);
    for (std::size_t k = 0; k < 6; ++k) CHECK(std::abs(ds[k].v - ss[k].v) <= 1e-15);
    CHECK(std::abs(dN.ixy[0].v - sN.ixy[0].v) <= 1e-15);
    CHECK(std::abs(dN.hx[0].v - sN.hx[0].v) <= 1e-15);
}

// The hand-written spatial algebra's figures beside ctga's in docs/mechanics.md §1 and
// docs/engine.md §4, counted on the textbook formulas (Featherstone 2008, §2.9–2.13), written
// here from the formulas, not from ctga: ω, v, l, p 3-vectors.
namespace spatial_reference {
using v3 = std::array<counted, 3>;
v3 cross(const v3& a, const v3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
v3 plus(const v3& a, const v3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
counted dot(const v3& a, const v3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
}  // namespace spatial_reference

TEST_CASE("the hand-written spatial algebra's counts that the docs compare with (textbook formulas, counted)",
          "[mechanics][cost]") {
    using namespace spatial_reference;
    const v3 w{0.1, 0.2, 0.3}, v{0.4, 0.5, 0.6}, w2{0.7, 0.8, 0.9}, v2{1.0, 1.1, 1.2};
    // [s1, s2] = (ω1 × ω2, ω1 × v2 + v1 × ω2)
    CHECK(count([&] {
              (void)cross(w, w2);
              (void)plus(cross(w, v2), cross(v, w2));
          }) == published<18, 12>);
    // {s, P} = (ω × l + v × p, ω × p)
    CHECK(count([&] {
              (void)plus(cross(w, w2), cross(v, v2));
              (void)cross(w, v2);
          }) == published<18, 12>);
    // P(s) = ω·l + v·p
    CHECK(count([&] { (void)(dot(w, w2) + dot(v, v2)); }) == published<6, 5>);
    // g1 g2 as dual quaternions (α1 + ε β1)(α2 + ε β2) = α1 α2 + ε (α1 β2 + β1 α2), a quaternion
    // product 16m 12a
    using quaternion = std::array<counted, 4>;
    const auto times = [](const quaternion& a, const quaternion& b) {
        return quaternion{a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
                          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
    };
    const quaternion a1{0.1, 0.2, 0.3, 0.4}, b1{0.5, 0.6, 0.7, 0.8}, a2{0.9, 1.0, 1.1, 1.2}, b2{1.3, 1.4, 1.5, 1.6};
    CHECK(count([&] {
              (void)times(a1, a2);
              const quaternion x = times(a1, b2), y = times(b1, a2);
              (void)quaternion{x[0] + y[0], x[1] + y[1], x[2] + y[2], x[3] + y[3]};
          }) == published<48, 40>);
    // a general 6×6 inertia times a 6-vector: 36m 30a
    std::array<std::array<counted, 6>, 6> N6{};
    const std::array<counted, 6> x{0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    CHECK(count([&] {
              for (const auto& row : N6) (void)(row[0] * x[0] + row[1] * x[1] + row[2] * x[2] + row[3] * x[3] + row[4] * x[4] + row[5] * x[5]);
          }) == published<36, 30>);
}
// Figures quoted from elsewhere, beside ctga's in docs/mechanics.md §1 and docs/engine.md §3, that
// no code of ours runs (so they are cited, not asserted):
namespace quoted {
// Pinocchio (spatial/inertia.hpp): a rigid inertia times a motion, ½ vᵀ I v, and the inertia
// moved by an SE(3) action (InertiaTpl::se3Action, about)
[[maybe_unused]] constexpr auto pinocchio_momentum = ctga::test::cited<24, 18>;
[[maybe_unused]] constexpr auto pinocchio_energy = ctga::test::cited<30>;
[[maybe_unused]] constexpr auto pinocchio_inertia_transform = ctga::test::cited<38, 37>;
// Featherstone (2008), the operation counts of his Table 2.5: the inertia transform; and §2.13's
// solve of a rigid body's ṡ: momentum + coadjoint + velocity from momentum
[[maybe_unused]] constexpr auto featherstone_inertia_transform = ctga::test::cited<47, 48>;
[[maybe_unused]] constexpr auto featherstone_momentum = ctga::test::cited<24>;
[[maybe_unused]] constexpr auto featherstone_coadjoint = ctga::test::cited<18>;
// the Coriolis term of a rigid body by hand: its momentum, then the coadjoint action
[[maybe_unused]] constexpr auto spatial_coriolis = ctga::test::cited<42>;
}  // namespace quoted

// The algebra's formulas on concrete types, priced by the engine for generic inputs.
template <class F, class... A>
using result = decltype(std::declval<F>()(std::declval<const A&>()...));

using s6 = lifted_screw<double>;
using P6 = coscrew<double>;
using N6 = rigid_inertia<double>;
using Ng = inertia<double>;
using M6 = mobility<double>;

static_assert(cost_of<result<decltype(bracket.formula), screw<>, screw<>>> == published<18, 12>);
static_assert(cost_of<result<decltype(coadjoint.formula), s6, P6>> == published<18, 12>);
static_assert(cost_of<result<decltype(pairing.formula), P6, s6>> == published<6, 5>);
static_assert(cost_of<result<decltype(momentum.formula), N6, s6>> == published<24, 18>,
              "a rigid body's inertia has 24 blades: the momentum at Pinocchio's 24m 18a");
static_assert(cost_of<result<decltype(momentum.formula), Ng, s6>> == published<36, 30>);
static_assert(cost_of<result<decltype(momentum.formula), body_inertia<>, s6>> == published<24, 18>,
              "ten parameters, one leaf each: the same count as the 24 blades");
static_assert(cost_of<result<decltype(velocity_from.formula), M6, P6>> == published<36, 30>);
static_assert(cost_of<result<decltype(kinetic_energy.formula), N6, s6>> == published<30, 23>);
static_assert(cost_of<result<decltype(inertia_rate.formula), N6, s6>> == published<96, 99>);
static_assert(cost_of<decltype(std::declval<const motor<>&>() * std::declval<const motor<>&>())> == published<48, 40>);
static_assert(cost_of<result<decltype(adjoint), motor<>, screw<>>> == published<72, 58>);
// an axis joint's S q̇ is one blade: the bracket v × S q̇ of the acceleration recursion (chains/)
static_assert(cost_of<result<decltype(bracket.formula), screw<>, cl031::mv<double, "e1e2">>> == published<4, 0>);

template <class E>
void report(const char* name) {
    std::printf("cost_of %-28s %zum %zua\n", name, static_cast<std::size_t>(cost_of<E>.mul), static_cast<std::size_t>(cost_of<E>.add));
}

TEST_CASE("engine costs of the paper's formulas on the mechanics types", "[mechanics][cost]") {
    // the static_asserts above are the test; this records the figures for the docs
    report<result<decltype(bracket.formula), screw<>, screw<>>>("bracket [s1, s2]");
    report<result<decltype(coadjoint.formula), s6, P6>>("coadjoint {s, P}");
    report<result<decltype(pairing.formula), P6, s6>>("pairing P(s)");
    report<result<decltype(momentum.formula), N6, s6>>("momentum (rigid N)");
    report<result<decltype(momentum.formula), Ng, s6>>("momentum (general N)");
    report<result<decltype(velocity_from.formula), M6, P6>>("velocity E v (M ^ P)");
    report<result<decltype(kinetic_energy.formula), N6, s6>>("2 E_k (rigid N)");
    report<result<decltype(inertia_rate.formula), N6, s6>>("dN/dt (rigid N)");
    report<decltype(std::declval<const motor<>&>() * std::declval<const motor<>&>())>("motor product g1 g2");
    report<result<decltype(adjoint), motor<>, screw<>>>("adjoint g s g*");
    CHECK(cost_of<result<decltype(momentum.formula), N6, s6>>.mul == 24);
}

}  // namespace
