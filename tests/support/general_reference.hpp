// What the tests compare with: the relative difference of two elements (the error measure of
// exp_log_test, the representations and the scene tests), and gravity for the general 3D code
// written independently of the scenes' field wrench.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <ctga/ctga.hpp>

namespace ctga::test {

// max_i |x_i − y_i| / max(1, max_i |y_i|) over the components of two elements with the same
// components (y the reference), in long double.
template <class X, class Y>
double rel(const X& x, const Y& y) {
    long double d = 0, m = 1;
    for (std::size_t i = 0; i < y.size(); ++i) {
        d = std::max(d, std::fabs(static_cast<long double>(x[i]) - static_cast<long double>(y[i])));
        m = std::max(m, std::fabs(static_cast<long double>(y[i])));
    }
    return static_cast<double>(d / m);
}

// A uniform field on a body whose centre of mass is its origin, in the body frame: (0, Rᵀ m a),
// R the rotation of map_of(g).
struct general_gravity {
    vec3<double> weight;  // m a, fixed frame
    wrench<double> operator()(const motor<double>& g, const screw<double>&) const {
        const motor_map<double> G = map_of(g);
        const vec3<double> f = linear3::apply_transposed(G.R, weight);
        return wrench<double>{0, 0, 0, f[0], f[1], f[2]};
    }
};

}  // namespace ctga::test
