// The tree algorithms on a scalar type that is not a floating-point number: forward-mode dual
// numbers (support/dual.hpp) through RNEA and ABA give their derivatives, checked against central
// differences of the double algorithms (∂τ/∂q, ∂τ/∂q̇) and against the mass matrix (∂q̈/∂τ = H⁻¹:
// H · ∂q̈/∂τ = 1, H from CRBA in double).
#include <array>
#include <cmath>
#include <cstddef>

#include <ctga/chains/algorithms.hpp>

#include "support/catch.hpp"
#include "support/dual.hpp"

namespace {
namespace ch = ctga::chains;
using D = ctga_test::dual<3>;
using tree = ch::tree<ch::link<-1, ch::revolute_z>, ch::link<0, ch::revolute_y>, ch::link<1, ch::revolute_x>>;

template <class T>
ch::model<tree, T> make_model() {
    ch::model<tree, T> m;
    m.gravity = {T(0.3), T(-0.2), T(-9.81)};
    const std::array<std::array<double, 3>, 3> c{{{0.1, 0.02, 0.2}, {0.05, -0.1, 0.25}, {-0.03, 0.04, 0.15}}};
    const auto link = [&]<class J>(std::size_t i, double x, double z) {
        const auto mass = ctga::make_mass_properties<T>(
            T(1.0 + 0.5 * static_cast<double>(i)), ctga::vec3<T>{T(c[i][0]), T(c[i][1]), T(c[i][2])},
            ctga::mat3<T>{{{T(0.02), T(0.001), T(0)}, {T(0.001), T(0.03), T(0)}, {T(0), T(0), T(0.04)}}});
        const ctga::motor<T> X(ctga::make_translator(T(x), T(0), T(z)));
        const auto L = ch::make_link<J>(X, mass);
        REQUIRE(L);
        return *L;
    };
    m.template link<0>() = link.template operator()<ch::revolute_z>(0, 0.0, 0.1);
    m.template link<1>() = link.template operator()<ch::revolute_y>(1, 0.05, 0.3);
    m.template link<2>() = link.template operator()<ch::revolute_x>(2, 0.0, 0.35);
    return m;
}

using vec = std::array<double, 3>;
const vec q0{0.3, -0.7, 1.1}, qd0{0.5, -0.2, 0.8}, qdd0{0.1, 0.2, -0.3};

// x as duals, seeded: component k varies along partial k
ch::joint_vector<tree, D> seeded(const vec& x) {
    return {D::variable(x[0], 0), D::variable(x[1], 1), D::variable(x[2], 2)};
}
ch::joint_vector<tree, D> constant(const vec& x) { return {D(x[0]), D(x[1]), D(x[2])}; }
}  // namespace

TEST_CASE("chains on dual numbers: ∂τ/∂q and ∂τ/∂q̇ of RNEA = central differences") {
    const ch::model<tree, D> md = make_model<D>();
    const ch::model<tree> m = make_model<double>();
    const double h = 1e-6;
    for (int wrt = 0; wrt < 2; ++wrt) {
        INFO((wrt == 0 ? "∂/∂q" : "∂/∂q̇"));
        const auto tau = wrt == 0 ? ch::rnea(md, seeded(q0), constant(qd0), constant(qdd0))
                                  : ch::rnea(md, constant(q0), seeded(qd0), constant(qdd0));
        double scale = 1;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) scale = std::max(scale, std::abs(ctga_test::derivative(tau[i], j)));
        for (std::size_t j = 0; j < 3; ++j) {
            vec xp = wrt == 0 ? q0 : qd0, xm = xp;
            xp[j] += h;
            xm[j] -= h;
            const auto tp = wrt == 0 ? ch::rnea(m, xp, qd0, qdd0) : ch::rnea(m, q0, xp, qdd0);
            const auto tm = wrt == 0 ? ch::rnea(m, xm, qd0, qdd0) : ch::rnea(m, q0, xm, qdd0);
            for (std::size_t i = 0; i < 3; ++i) {
                INFO("entry " << i << ", " << j);
                const double fd = (tp[i] - tm[i]) / (2 * h);
                CHECK(std::abs(ctga_test::derivative(tau[i], j) - fd) <= 1e-7 * scale);
            }
        }
        // the values are RNEA's in double
        const auto t = ch::rnea(m, q0, qd0, qdd0);
        for (std::size_t i = 0; i < 3; ++i) CHECK(std::abs(ctga_test::value(tau[i]) - t[i]) <= 1e-14 * scale);
    }
}

TEST_CASE("chains on dual numbers: ∂q̈/∂τ of ABA is the inverse of CRBA's mass matrix") {
    const ch::model<tree, D> md = make_model<D>();
    const ch::model<tree> m = make_model<double>();
    const vec tau0 = ch::rnea(m, q0, qd0, qdd0);
    const auto qdd = ch::aba(md, constant(q0), constant(qd0), seeded(tau0));
    const auto H = ch::crba(m, q0);
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(std::abs(ctga_test::value(qdd[i]) - qdd0[i]) <= 1e-12);  // ABA(RNEA(q̈)) = q̈
        for (std::size_t j = 0; j < 3; ++j) {
            double HM = 0;  // (H · ∂q̈/∂τ)(i, j)
            for (std::size_t k = 0; k < 3; ++k) HM += H[i][k] * ctga_test::derivative(qdd[k], j);
            INFO("entry " << i << ", " << j);
            CHECK(std::abs(HM - (i == j ? 1.0 : 0.0)) <= 1e-12);
        }
    }
}
