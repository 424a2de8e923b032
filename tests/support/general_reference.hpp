// What the scene tests compare against: the relative difference of two elements, and gravity for
// the general 3D code written independently of the scenes' field wrench.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <ctga/ctga.hpp>

namespace ctga::test {

// max_i |x_i − y_i| / max(1, max_i |y_i|) over the components of two elements of one type.
template <class X>
double rel(const X& x, const X& y) {
    double d = 0, s = 1;
    for (std::size_t i = 0; i < x.size(); ++i) d = std::max(d, double(std::abs(x[i] - y[i]))), s = std::max(s, double(std::abs(y[i])));
    return d / s;
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
