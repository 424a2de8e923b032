// The algorithms as objects (chains/arguments.hpp): called correctly, an algorithm<Overloads,
// "name"> is its overload set, bit for bit, checked_call takes it, and RNEA gives a pendulum's
// τ = I θ̈ + m g l sin θ; called wrongly, it names the problem (problem_with, which the
// compile-fail tests see in the compiler's first lines).
#include <array>
#include <cmath>
#include <concepts>
#include <limits>
#include <type_traits>
#include <vector>

#include <ctga/chains/algorithms.hpp>

#include "support/catch.hpp"

namespace {

namespace ch = ctga::chains;

// a pendulum about y, its centre of mass l below the pivot, and a tool frame
using pendulum = ch::tree<ch::link<-1, ch::revolute_y>, ch::fixed_frame<"tool", 0>>;
// a floating base with one arm: nq = 9, nv = 7, 2 bodies
using based = ch::tree<ch::link<-1, ch::floating>, ch::link<0, ch::revolute_z>, ch::fixed_frame<"tool", 1>>;

constexpr double mass = 1.3, l = 0.7, Ic = 0.02, g = 9.81;

ch::model<pendulum> pendulum_model() {
    ch::model<pendulum> m;
    const auto link = ch::make_link<ch::revolute_y>(
        ctga::rigid_motion(ctga::make_translator(0.0, 0.0, 0.0), ctga::make_rotor(0.0, 0.0, 0.0, 1.0)),
        ctga::make_mass_properties(mass, ctga::vec3<double>{0.0, 0.0, -l},
                                   ctga::mat3<double>{{{Ic, 0.0, 0.0}, {0.0, Ic, 0.0}, {0.0, 0.0, Ic}}}));
    REQUIRE(link);
    m.link<0>() = *link;
    return m;
}

// What each algorithm object is: its overloads, and nothing more to store.
template <const auto& Algorithm>
using overloads_of = typename std::remove_cvref_t<decltype(Algorithm)>::overloads;
static_assert(std::is_base_of_v<ch::rnea_t, std::remove_cvref_t<decltype(ch::rnea)>>);
static_assert(std::is_empty_v<std::remove_cvref_t<decltype(ch::rnea)>>);
static_assert(std::is_same_v<overloads_of<ch::frame_velocity>, ch::frame_motion_t<false>>);

}  // namespace

TEST_CASE("arguments: an algorithm object computes what its overload set computes", "[chains][arguments]") {
    const ch::model<pendulum> m = pendulum_model();
    const ch::configuration<pendulum> q{0.4};
    const ch::joint_vector<pendulum> qd{-1.1}, qdd{0.7};
    const auto tau = ch::rnea(m, q, qd, qdd);
    CHECK(tau == overloads_of<ch::rnea>{}(m, q, qd, qdd));
    CHECK(ch::aba(m, q, qd, tau) == overloads_of<ch::aba>{}(m, q, qd, tau));
    CHECK(ch::crba(m, q) == overloads_of<ch::crba>{}(m, q));
    const auto k = ch::forward_kinematics(m, q, qd, qdd);
    const auto v = ch::frame_velocity(m, k, ch::frame<"tool">, ch::reference::world);
    const auto v_overloads = overloads_of<ch::frame_velocity>{}(m, k, ch::frame<"tool">, ch::reference::world);
    for (std::size_t i = 0; i < 6; ++i) CHECK(v[i] == v_overloads[i]);
    const ch::configuration<pendulum> q1{1.2};
    CHECK(ch::interpolate(m, q, q1, 0.25) == overloads_of<ch::interpolate>{}(m, q, q1, 0.25));
    CHECK(ch::integrate(m, q, ch::difference(m, q, q1))[0] == Approx(q1[0]));

    // the pendulum: τ = I_pivot θ̈ + m g l sin θ (the potential −m g l cos θ), q̇ adding nothing
    const double I_pivot = Ic + mass * l * l;
    CHECK(tau[0] == Approx(I_pivot * qdd[0] + mass * g * l * std::sin(q[0])).epsilon(1e-14));
}

TEST_CASE("arguments: checked_call takes the algorithm objects", "[chains][arguments]") {
    const ch::model<pendulum> m = pendulum_model();
    const ch::configuration<pendulum> q{0.4};
    const ch::joint_vector<pendulum> qd{-1.1}, qdd{0.7};
    const auto tau = ch::checked_call(ch::rnea, m, q, qd, qdd);
    REQUIRE(tau);
    CHECK(*tau == ch::rnea(m, q, qd, qdd));
    const ch::joint_vector<pendulum> nan{std::numeric_limits<double>::quiet_NaN()};
    CHECK(ch::checked_call(ch::aba, m, q, qd, nan).error == ctga::error_code::non_finite);
    CHECK(ch::checked_call(ch::integrate, m, q, qd));
}

namespace {
// The problem each wrong call names: argument<k> counts from 1, the model first.
using M = ch::model<based>;
using q_t = ch::configuration<based>;   // 9 numbers
using v_t = ch::joint_vector<based>;    // 7
using f_t = ch::body_wrenches<based>;   // 2 wrenches
template <const auto& Algorithm, class... Args>
using problem = typename std::remove_cvref_t<decltype(Algorithm)>::template problem_with<Args...>;

static_assert(std::is_same_v<problem<ch::rnea, M, std::array<double, 8>, v_t, v_t>,
                             ch::configuration_has_the_wrong_length<ch::argument<2>, ch::expected<9>, ch::given<8>>>);
static_assert(std::is_same_v<problem<ch::aba, M, q_t, v_t, std::array<double, 9>>,
                             ch::joint_vector_has_the_wrong_length<ch::argument<4>, ch::expected<7>, ch::given<9>>>);
static_assert(std::is_same_v<problem<ch::rnea, M, q_t, v_t, v_t, std::array<ctga::chains::body_wrenches<based>::value_type, 3>>,
                             ch::body_wrenches_have_the_wrong_length<ch::argument<5>, ch::expected<2>, ch::given<3>>>);
static_assert(std::is_same_v<problem<ch::rnea, M, std::vector<double>, v_t, v_t>,
                             ch::state_array_is_not_a_std_array<ch::argument<2>, ch::expected_type<q_t>,
                                                                ch::given_type<std::vector<double>>>>);
static_assert(std::is_same_v<problem<ch::rnea, M, std::array<float, 9>, std::array<float, 7>, std::array<float, 7>>,
                             ch::state_array_has_another_scalar<ch::argument<2>, ch::expected_type<double>, ch::given_type<float>>>);
// two configurations: the second of difference's
static_assert(std::is_same_v<problem<ch::difference, M, q_t, v_t>,
                             ch::configuration_has_the_wrong_length<ch::argument<3>, ch::expected<9>, ch::given<7>>>);
// a frame function: the configuration before the frame
static_assert(std::is_same_v<problem<ch::frame_jacobian, M, std::array<double, 7>, ch::frame_name<"tool">, ch::reference>,
                             ch::configuration_has_the_wrong_length<ch::argument<2>, ch::expected<9>, ch::given<7>>>);
// where nq = nv, q and q̇ look alike: the state array of argument 3
using P = ch::model<pendulum>;
static_assert(std::is_same_v<problem<ch::rnea, P, std::array<double, 1>, std::array<double, 2>, std::array<double, 1>>,
                             ch::state_array_has_the_wrong_length<ch::argument<3>, ch::expected<1>, ch::given<2>>>);
// nothing to replace: another count of arguments, a first argument that is not a model
static_assert(std::is_same_v<problem<ch::rnea, M, q_t, v_t>,
                             ch::no_overload_takes_these_arguments<ch::algorithm_named<'r', 'n', 'e', 'a'>, M, q_t, v_t>>);
static_assert(std::is_same_v<problem<ch::crba, q_t, M>,
                             ch::no_overload_takes_these_arguments<ch::algorithm_named<'c', 'r', 'b', 'a'>, q_t, M>>);

// A call is well formed when the overload set takes it (the object takes anything, to report it).
static_assert(std::invocable<overloads_of<ch::rnea>, M, q_t, v_t, v_t>);
static_assert(!std::invocable<overloads_of<ch::rnea>, M, v_t, v_t, v_t>);
}  // namespace
