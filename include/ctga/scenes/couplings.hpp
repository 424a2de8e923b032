// Elastic couplings of §7: a stiffness K and a damping D between two bodies (or a body and the
// ground), symmetric 6 × 6 elements of the same space as the inertia N, given in the coupling's
// frame. A frame is fixed in each body (frame_a, frame_b: motors in the body's frame, the world's
// for the ground); at rest they coincide. With A and B those frames in the world,
//     ξ = log(A⁻¹ B)                 the relative displacement, a screw in A's frame (motor.hpp's log)
//     s = (ω, v)                     B's velocity relative to A's, in A's axes, v that of B's origin
//                                    relative to the point of A there
//     W = −K ξ − D s                 the coupling's wrench on B, a co-screw (torque, force) at B's origin
// and A feels −W along the same line. K and D stay in the coupling's frame: the wrench moves,
// not the matrices (moving them as §7 says, K' = Ad*ᵀ K Ad*, gives the same wrench).
//
// The world applies W at the start of each step, with the applied wrenches: explicitly, so a
// coupling is stable while h ω < 2 for its stiffest mode, ω² = k / m (h d / m < 2 for its damping).
// A contact compliance (below) is taken implicitly, in the contact problem: stable at any step.
#pragma once

#include <array>
#include <cstddef>

#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/scenes/joints.hpp"

namespace ctga {

template <class T>
using matrix6 = std::array<std::array<T, 6>, 6>;

template <class T = double>
struct elastic_coupling {
    body_ref a, b;
    motor<T> frame_a, frame_b;  // the coupling's frame in each body's frame
    matrix6<T> stiffness{};     // K, in the coupling's frame: (rotation, translation) to (torque, force)
    matrix6<T> damping{};       // D, likewise
};

// −K ξ − D s.
template <class T>
[[nodiscard]] constexpr coscrew<T> coupling_wrench(const matrix6<T>& K, const matrix6<T>& D, const screw<T>& xi, const screw<T>& s) noexcept {
    coscrew<T> W{};
    for (std::size_t i = 0; i < 6; ++i) {
        T w = T(0);
        for (std::size_t j = 0; j < 6; ++j) w -= K[i][j] * xi[j] + D[i][j] * s[j];
        W[i] = w;
    }
    return W;
}

// A soft surface: the same elements as a contact compliance, a stiffness K and a damping D
// given in a static shape's frame. A contact point on it with unit normal n (in the shape's
// axes) and separation φ is a spring and a damper along n: k = nᵀ K_vv n and d = nᵀ D_vv n, the
// translation blocks moved to the point as §7 moves N (a translation leaves them, a rotation
// turns them), pressing with k (−φ) − d u_n. Taken implicitly, φ⁺ = φ + h u⁺, the normal row is
//     0 ≤ r_n ⊥ u_n + c r_n + b ≥ 0,   c = 1 / (h (h k + d)),   b = k φ / (h k + d)
// (at rest, r_n = −h k φ: the spring's force over the step), where a rigid contact has c = 0
// and b from its gap. Its tangential rows keep Coulomb's law.
template <class T = double>
struct contact_compliance {
    matrix6<T> stiffness{};  // K, in the shape's frame; its translation block positive definite
    matrix6<T> damping{};    // D, likewise; its translation block positive semi-definite
};
template <class T>
struct soft_row {
    T compliance;  // c, added to the normal entry of the contact's block
    T offset;      // b, the normal row's velocity offset
};
template <class T>
[[nodiscard]] constexpr soft_row<T> soften(const contact_compliance<T>& s, const vec3<T>& n, const T& separation, const T& h) noexcept {
    T k = T(0), d = T(0);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) k += n[i] * s.stiffness[3 + i][3 + j] * n[j], d += n[i] * s.damping[3 + i][3 + j] * n[j];
    const T z = h * k + d;
    return {T(1) / (h * z), k * separation / z};
}

}  // namespace ctga
