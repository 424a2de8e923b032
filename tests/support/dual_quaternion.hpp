// The exponential and the renormalisation of a motor written on its 8 dual-quaternion components
// (α0, α1, α2, α3, β0, β1, β2, β3), shared by the dense and 6×6 reference models. They are the
// closed forms of exp_log.hpp and motion.hpp, step for step, so those two operations agree with
// ctga's to the bit; everything else in the reference models is their own arithmetic.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include <ctga/mechanics/motor.hpp>

namespace ctga::test::dual_quaternion {

// e^{z/2} = cos φ + sinc φ a + ε(−sinc φ (a·b) + sinc φ b + c(φ)(a·b) a), a = ω/2, b = v/2, φ = |a|.
template <class T>
std::array<T, 8> exp(const std::array<T, 6>& z) {
    using std::cos;
    using std::sqrt;
    const T ax = z[0] / T(2), ay = z[1] / T(2), az = z[2] / T(2);
    const T bx = z[3] / T(2), by = z[4] / T(2), bz = z[5] / T(2);
    const T phi2 = ax * ax + ay * ay + az * az;
    const T phi = sqrt(phi2);
    const auto [sinc, c] = ctga::motor_detail::sinc_and_c(phi, phi2);
    const T ab = ax * bx + ay * by + az * bz;
    const T cab = c * ab;
    return {cos(phi), sinc * ax, sinc * ay, sinc * az, -sinc * ab, sinc * bx + cab * ax, sinc * by + cab * ay,
            sinc * bz + cab * az};
}

// g / √(g g*) = α̂ + ε(β − (α̂·β)α̂)/|α|, after scaling by the largest |αi|. A motor with α = 0 or
// a non-finite component gives NaNs, as ctga::renormalize does in release builds.
template <class T>
std::array<T, 8> renormalized(std::array<T, 8> x) {
    using std::sqrt;
    T m = T(0);
    for (std::size_t i = 0; i < 4; ++i) m = std::max(m, std::abs(x[i]));
    bool ok = m > T(0);
    for (const T& v : x) ok = ok && std::isfinite(v);
    if (!ok) {
        x.fill(std::numeric_limits<T>::quiet_NaN());
        return x;
    }
    for (T& v : x) v /= m;
    const T n = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    for (T& v : x) v /= n;
    const T d = x[0] * x[4] + x[1] * x[5] + x[2] * x[6] + x[3] * x[7];
    for (std::size_t i = 0; i < 4; ++i) x[4 + i] -= d * x[i];
    return x;
}

// Whether the eight numbers are a unit motor up to rounding: ctga::near_unit's test (the models'
// check of an integration's initial pose is the library's predicate, not an independent one).
template <class T>
bool near_unit(const std::array<T, 8>& x) {
    return ctga::near_unit(ctga::motor<T>{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]});
}

}  // namespace ctga::test::dual_quaternion
