// The sandwich R x R̃ (ctga::sandwich) in Cl(3,0,1): rotors, translators and motors acting on
// points and planes keep the type (the terms that cancel between R's two appearances are
// found), and the values equal the dense reference's R x R̃.
#include <cmath>
#include <random>

#include <ctga/ctga.hpp>
#include <ctga/reference/dense.hpp>

#include "support/catch.hpp"

namespace {

using pga = ctga::algebra<"e0 e1 e2 e3", 0, 1, 1, 1>;
using point = pga::mv<double, "e0e3e2", "e0e1e3", "e0e2e1", "e1e2e3">;
using plane = pga::mv<double, "e0", "e1", "e2", "e3">;
using rotor = pga::mv<double, "1", "e1e2">;
using translator = pga::mv<double, "1", "e0e1", "e0e2", "e0e3">;
using motor = pga::mv<double, "1", "e1e2", "e2e3", "e3e1", "e0e1", "e0e2", "e0e3", "e0e1e2e3">;

template <class X>
double max_difference(const X& x, const ctga::dense::multivector<pga, double>& expected) {
    const auto got = ctga::dense::to_dense(x);
    return static_cast<double>(ctga::dense::max_abs_diff(got, expected));
}

template <class R, class X>
void check_sandwich(const R& r, const X& x) {
    const X q = ctga::sandwich(r, x);  // stays in X's type
    const auto dr = ctga::dense::to_dense(r);
    const auto expected = ctga::dense::gp(ctga::dense::gp(dr, ctga::dense::to_dense(x)), ctga::dense::reverse(dr));
    CHECK(max_difference(q, expected) <= 1e-12);
}

TEST_CASE("sandwich: rotors, translators and motors map points to points and planes to planes", "[sandwich]") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double angle = 0.7;
    const rotor R{std::cos(angle / 2), std::sin(angle / 2)};
    const translator T{1.0, 0.3, -0.2, 0.5};
    const motor M = ctga::project<motor>(T * R);  // a screw motion: T R
    const point p{u(rng), u(rng), u(rng), 1.0};
    const plane e{u(rng), u(rng), u(rng), u(rng)};
    check_sandwich(R, p);
    check_sandwich(T, p);
    check_sandwich(M, p);
    check_sandwich(R, e);
    check_sandwich(M, e);
    // a unit rotor keeps the point's weight (e1e2e3), and the translator moves, not rotates
    const point q = ctga::sandwich(R, p);
    CHECK(std::abs(q.get<"e1e2e3">() - 1.0) <= 1e-15);
    const point t = ctga::sandwich(T, p);
    CHECK(std::abs(t.get<"e1e2e3">() - 1.0) <= 1e-15);
    CHECK(std::abs(std::abs(t.get<"e0e3e2">() - p.get<"e0e3e2">()) - 2 * 0.3) <= 1e-12);
}

}  // namespace
