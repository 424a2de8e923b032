// The benchmarked operations, one non-inlined function per operation and implementation
// (kernel_<operation>_<implementation>), so that every implementation is timed and its
// instructions counted the same way: a call on inputs in memory, a result returned.
//
// Implementations: ctga (the library), spatial (hand-written 6D spatial algebra, spatial.hpp),
// eigen (Eigen 6-vectors and 6×6 matrices: the formalism of §2 of the paper), dense (the naive
// dense 256-component reference of Cl(0,6,2)). Every input set holds the same physical values:
// a rigid body (mass, centre of mass, inertia tensor), poses, velocities, co-screws, wrenches.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <ctga/ctga.hpp>
#include <ctga/reference/dense.hpp>

#include "spatial.hpp"

namespace bench {

using vec6 = Eigen::Matrix<double, 6, 1>;
using mat6 = Eigen::Matrix<double, 6, 6>;
using dense_mv = ctga::dense::multivector<ctga::cl062>;

// One RK4 step of one free body, state (pose, body-frame velocity), body-frame wrench, step h.
inline constexpr double step_size = 1e-3;

struct ctga_inputs {
    ctga::rigid_body<> body;
    ctga::body_inertia<> N;  // the body's N by its ten parameters (m, m c, I_o)
    ctga::motor<> g, g2;
    ctga::motor_map<> G;  // the sandwich by g, built once
    ctga::screw<> s, s2;
    ctga::coscrew<> P;
    ctga::wrench<> W;
};
struct spatial_inputs {
    spatial::inertia Y;
    spatial::inverse_inertia Z;
    spatial::dual_quaternion g, g2;
    spatial::se3 X;
    spatial::motion s, s2;
    spatial::force P, W;
};
struct eigen_inputs {
    mat6 N, N_inverse, H, H_inverse_transpose;
    Eigen::Quaterniond g_real, g_dual, g2_real, g2_dual;
    vec6 s, s2, P, W;
};
struct dense_inputs {
    dense_mv N, M, g, g2, g_bar, s, s2, P, W;
};

// A 14-number state: the motor's 8 components, then the body-frame velocity (ω, v).
using state = std::array<double, 14>;

struct input_batches {
    std::vector<ctga_inputs> ctga;
    std::vector<spatial_inputs> spatial;
    std::vector<eigen_inputs> eigen;
    std::vector<dense_inputs> dense;
};
// n input sets from one random stream (bench/inputs.cpp).
input_batches make_inputs(std::size_t n, unsigned seed);

// ---- the kernels (kernels_<implementation>.cpp) ----------------------------------------------
// Each returns its result in the implementation's own types.

struct eigen_dual_quaternion {
    Eigen::Quaterniond real, dual;
};

ctga::coscrew<> momentum(const ctga_inputs&);  // A ∨ (N ∧ s)
spatial::force momentum(const spatial_inputs&);
vec6 momentum(const eigen_inputs&);
dense_mv momentum(const dense_inputs&);

double energy(const ctga_inputs&);  // ½ s̄ ∨ (N ∧ s)
double energy(const spatial_inputs&);
double energy(const eigen_inputs&);
double energy(const dense_inputs&);

ctga::screw<> bracket(const ctga_inputs&);  // ½(s1 s2 − s2 s1)
spatial::motion bracket(const spatial_inputs&);
vec6 bracket(const eigen_inputs&);
dense_mv bracket(const dense_inputs&);

ctga::coscrew<> coadjoint(const ctga_inputs&);  // ½(s̄ P − P s̄)
spatial::force coadjoint(const spatial_inputs&);
vec6 coadjoint(const eigen_inputs&);
dense_mv coadjoint(const dense_inputs&);

ctga::motor<> motor_product(const ctga_inputs&);  // g1 g2
spatial::dual_quaternion motor_product(const spatial_inputs&);
eigen_dual_quaternion motor_product(const eigen_inputs&);
dense_mv motor_product(const dense_inputs&);

ctga::screw<> screw_transform(const ctga_inputs&);  // g s g* (the map built once)
spatial::motion screw_transform(const spatial_inputs&);
vec6 screw_transform(const eigen_inputs&);
dense_mv screw_transform(const dense_inputs&);

ctga::coscrew<> coscrew_transform(const ctga_inputs&);  // ḡ P ḡ*
spatial::force coscrew_transform(const spatial_inputs&);
vec6 coscrew_transform(const eigen_inputs&);
dense_mv coscrew_transform(const dense_inputs&);

ctga::body_inertia<> inertia_transform(const ctga_inputs&);  // (g ḡ) N (g ḡ)*
spatial::inertia inertia_transform(const spatial_inputs&);
mat6 inertia_transform(const eigen_inputs&);
dense_mv inertia_transform(const dense_inputs&);

ctga::screw<> eom(const ctga_inputs&);  // ṡ of N ∧ ṡ + ½((s̄N − Ns̄) ∧ s) = W E
spatial::motion eom(const spatial_inputs&);
vec6 eom(const eigen_inputs&);
dense_mv eom(const dense_inputs&);

state step(const ctga_inputs&);  // one RK4 step of (g, s), body frame
state step(const spatial_inputs&);
state step(const eigen_inputs&);
state step(const dense_inputs&);

// The classical RK4 step of x' = f(x) on the flat state, shared by every implementation:
// each supplies only f.
template <class F>
state rk4(const state& x, double h, F f) {
    const auto axpy = [](const state& a, double c, const state& b) {
        state out;
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = a[i] + c * b[i];
        return out;
    };
    const state k1 = f(x), k2 = f(axpy(x, h / 2, k1)), k3 = f(axpy(x, h / 2, k2)), k4 = f(axpy(x, h, k3));
    state out;
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = x[i] + h / 6 * (k1[i] + 2 * (k2[i] + k3[i]) + k4[i]);
    return out;
}

}  // namespace bench
