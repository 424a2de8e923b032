// The derivatives of a frame's velocity and spatial acceleration (frames.hpp) with respect to q,
// q̇ and q̈, from the world-frame forward passes of rnea_derivatives.hpp, their kinematics only
// (Carpentier and Mansard's frame derivatives). Configuration derivatives are in the tangent
// space, as rnea_derivatives': moving dof k moves everything its body carries rigidly by the
// world screw S_k. For a dof k on the path from the frame's body b to the root (every other
// column is zero), with b's world velocity v and acceleration a, Ψ̇_k = v_λ × S_k, Ψ̈_k and Φ_k
// as in rnea_derivatives.hpp:
//
//   world:  ∂v/∂q_k = S_k × v + Ψ̇_k,          ∂v/∂q̇_k = S_k,
//           ∂a/∂q_k = S_k × a + Ψ̈_k + Ψ̇_k × v, ∂a/∂q̇_k = S_k × v + Φ_k,   ∂a/∂q̈_k = S_k
//   local:  the frame's coordinates X⁻¹ (X = W_b P, the frame's pose) move with it by S_k,
//           ∂(X⁻¹ y) = X⁻¹ (∂y − S_k × y) (for a: y without the world's −g), and X⁻¹ of the
//           world's q̇ and q̈ columns
//   local_world_aligned: local's numbers y turned by the frame's axes R, which turn with S_k's
//           angular part ω_k: ∂(R y)/∂q_k = ω_k × (R y) (each part) + R ∂y/∂q_k
//
// (a includes the world's −g in the passes: a constant, it cancels from the world's derivatives;
// the frame's coordinates move a − (−g), the spatial acceleration of frame_acceleration.) The
// derivative of the frame's placement is its Jacobian (frame_jacobian.hpp); ∂v/∂q̇ = ∂a/∂q̈ = J.
#pragma once

#include <cstddef>

#include "ctga/chains/arguments.hpp"
#include "ctga/chains/frame_jacobian.hpp"
#include "ctga/chains/frames.hpp"
#include "ctga/chains/mimic_expansion.hpp"
#include "ctga/chains/rnea_derivatives.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/chains/world_geometry.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/uninitialized.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
struct frame_motion_partials {
    jacobian_matrix<Tree, T> dv_dq, dv_dv;          // ∂v/∂q (tangent space), ∂v/∂q̇ = J
    jacobian_matrix<Tree, T> da_dq, da_dv, da_da;   // ∂a/∂q, ∂a/∂q̇, ∂a/∂q̈ = J
};

struct frame_motion_derivatives_t {
    template <class Tree, class T, class F>
    [[nodiscard]] constexpr frame_motion_partials<Tree, T> operator()(const model<Tree, T>& m, const configuration<Tree, T>& q,
                                                                      const joint_vector<Tree, T>& qd, const joint_vector<Tree, T>& qdd,
                                                                      F f, reference r) const noexcept {
        using namespace algorithm_detail;
        constexpr int b = frame_detail::frame_on<Tree, F>::body;
        frame_motion_partials<Tree, T> out{};
        if constexpr (Tree::has_mimic) {  // on the expanded tree, J_all G (mimic_expansion.hpp)
            const expansion<Tree, T> x(m);
            const auto all = (*this)(x.m, x.configuration_of(q), x.velocities_of(qd), x.velocities_of(qdd), f, r);
            return {x.reduce(all.dv_dq), x.reduce(all.dv_dv), x.reduce(all.da_dq), x.reduce(all.da_dv), x.reduce(all.da_da)};
        } else if constexpr (b >= 0) {
            derivative_pass<Tree, T> d{uninitialized};
            fill_world_geometry(d, m, q);
            const screw<T> a_world{T(0), T(0), T(0), -m.gravity[0], -m.gravity[1], -m.gravity[2]};
            for (std::size_t i = 0; i <= static_cast<std::size_t>(b); ++i) {
                derivative_velocities<false>(d, i, qd.data(), static_cast<const body_wrenches<Tree, T>*>(nullptr));
                derivative_accelerations<false>(d, i, a_world, qdd.data());
            }
            const screw<T>& v = d.v[b];
            const screw<T>& a = d.a[b];
            const motor_map<T> X = compose(d.pose[b], frame_detail::placement(m, f));
            // local: X⁻¹ y; local_world_aligned: R X⁻¹ y; world: y
            const auto seen = [&](const screw<T>& y) {
                if (r == reference::world) return y;
                const screw<T> local = transform_inverse(X, y);
                if (r == reference::local) return local;
                return frame_detail::rotate(X.R, frame_detail::angular(local), frame_detail::linear(local));
            };
            // local_world_aligned's turn of the axes by ω_k, on R X⁻¹ y
            const screw<T> v_aligned = r == reference::local_world_aligned ? seen(v) : screw<T>{};
            const screw<T> a_aligned = r == reference::local_world_aligned ? seen(a - a_world) : screw<T>{};
            const auto turned = [](const screw<T>& S, const screw<T>& y) {
                const vec3<T> w = frame_detail::angular(S);
                const vec3<T> p = linear3::cross(w, frame_detail::angular(y)), l = linear3::cross(w, frame_detail::linear(y));
                return screw<T>{p[0], p[1], p[2], l[0], l[1], l[2]};
            };
            const screw<T> a_true = a - a_world;
            for (std::size_t k = 0; k < Tree::nv; ++k) {
                if (!Tree::supports(Tree::body_of_dof[k], static_cast<std::size_t>(b))) continue;
                const screw<T>& S = d.S[k];
                // the world's columns, then the frame's coordinates moved by S: ∂(X⁻¹ y) = X⁻¹(∂y − S × y)
                const screw<T> dv = bracket(S, v) + d.Psi_d[k];
                const screw<T> da = bracket(S, a) + d.Psi_dd[k] + bracket(d.Psi_d[k], v);
                if (r == reference::world) {
                    out.dv_dq[k] = dv;
                    out.da_dq[k] = da;
                } else {
                    out.dv_dq[k] = seen(dv - bracket(S, v));
                    out.da_dq[k] = seen(da - bracket(S, a_true));
                }
                if (r == reference::local_world_aligned) {
                    out.dv_dq[k] = out.dv_dq[k] + turned(S, v_aligned);
                    out.da_dq[k] = out.da_dq[k] + turned(S, a_aligned);
                }
                out.dv_dv[k] = out.da_da[k] = seen(S);
                out.da_dv[k] = seen(bracket(S, v) + d.Phi[k]);
            }
        }
        return out;
    }
};
// ∂/∂(q, q̇, q̈) of frame_velocity and frame_acceleration of frame f (chains::body<I>,
// chains::frame<"name">, frame_at<K>) in reference r, at the state (q, q̇, q̈).
inline constexpr algorithm<frame_motion_derivatives_t, "frame_motion_derivatives"> frame_motion_derivatives{};

}  // namespace ctga::chains
