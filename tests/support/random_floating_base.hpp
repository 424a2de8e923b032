// One random state drawn for ctga and for the Featherstone reference (tests/support/featherstone.hpp)
// at once: a placement as ctga's motor, and a floating base's configuration in both layouts.
#pragma once

#include <cstddef>
#include <random>

#include <Eigen/Geometry>

#include <ctga/mechanics/motor.hpp>

#include "support/random_tree.hpp"

namespace ctga::test {

// The placement (R, t) (x ↦ R x + t) as a motor: the translator after the rotor of R's quaternion.
inline ctga::motor<double> motor_of(const featherstone::mat3& R, const featherstone::vec3& t) {
    const Eigen::Quaterniond qr(R);
    const ctga::rotor<double> r{qr.w(), qr.x(), qr.y(), qr.z()};
    return ctga::rigid_motion(ctga::make_translator(t[0], t[1], t[2]), r);
}

// A random base pose (uniform rotation, translation in [−reach, reach]³) written as ctga's floating
// joint stores it, the motor's 8 coefficients at q[qo …], and as the reference does, (t, quaternion
// w x y z) at q_ref[qr …].
template <class Q, class QRef>
void random_floating_base(std::mt19937_64& rng, double reach, Q& q, std::size_t qo, QRef& q_ref, Eigen::Index qr) {
    const featherstone::mat3 R = featherstone::random_rotation(rng);
    const featherstone::vec3 t = featherstone::uniform_vec3(rng, reach);
    const Eigen::Quaterniond quat(R);
    const ctga::motor<double> g = motor_of(R, t);
    for (std::size_t k = 0; k < 8; ++k) q[qo + k] = g[k];
    q_ref.template segment<3>(qr) = t;
    q_ref.template segment<4>(qr + 3) << quat.w(), quat.x(), quat.y(), quat.z();
}

}  // namespace ctga::test
