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
#pragma once

#include <array>
#include <cstddef>

#include "ctga/mechanics/coscrew.hpp"
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

}  // namespace ctga
