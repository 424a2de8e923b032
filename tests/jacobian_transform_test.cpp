// The Jacobian of a formula whose products loop (expr/looped.hpp): the inertia moved by a motor,
// N' = (g ḡ) N (g ḡ)* (§5), against dual numbers (tests/support/jacobian_check.hpp). Its own
// file: the two Jacobians (8 and 10 columns) are the heaviest compile of the Jacobian tests.
#include <tuple>
#include <type_traits>

#include <ctga/ctga.hpp>
#include <ctga/operations/jacobian.hpp>

#include "support/jacobian_check.hpp"

using namespace ctga;
using namespace ctga_test::jacobians;

TEST_CASE("the moved inertia (g ḡ) N (g ḡ)*: the Jacobian in the motor from shared, re-associated products", "[jacobian]") {
    // G = g ḡ has 64 blades, so the products G N and (G N) G* loop. Each column is
    //   ∂g (ḡ (N G*)) + (g ∂ḡ) (N G*) + (G N) (∂ḡ* g*) + ((G N) ḡ*) ∂g*
    // (expr/derivative.hpp): the products in brackets computed once for all eight columns
    // (expr/run.hpp, shared units), and the columns' own products accumulated together.
    constexpr auto moved_inertia = formula([](auto g, auto N) {
        const auto x = lift(g);
        const auto gg = x * bar(x);
        return gg * N * conj(gg);
    });
    using value = std::remove_cvref_t<decltype(eval(moved_inertia(motor<double>{}, body_inertia<double>{})))>;
    const auto motor_and_inertia = [](random_source& r) {
        return std::make_tuple(random_multivector<motor<double>>(r), body_inertia_of(random_body(r)));
    };
    CHECK(within("moved inertia d/d motor", check_formula<0, value>(moved_inertia, motor_and_inertia, pattern_check::covers),
                 dual_tolerance));
    CHECK(within("moved inertia d/d inertia", check_formula<1, value>(moved_inertia, motor_and_inertia, pattern_check::covers),
                 dual_tolerance));
}
