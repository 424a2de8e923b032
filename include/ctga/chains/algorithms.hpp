// The algorithms of a kinematic tree (tree.hpp), one header each, named as Featherstone (2008)
// names them:
//
//   forward_kinematics.hpp  forward_kinematics: every body's frame, velocity and acceleration     (§4.1)
//   rnea.hpp                rnea: inverse dynamics τ(q, q̇, q̈), recursive Newton–Euler            (§5.3)
//   crba.hpp                crba: the joint-space mass matrix H(q), composite rigid bodies        (§6.2)
//   aba.hpp                 aba: forward dynamics q̈(q, q̇, τ), articulated bodies                (§7.3)
//   minverse.hpp            minverse: H⁻¹(q) by the articulated-body recursion
//   rnea_derivatives.hpp    rnea_derivatives: ∂τ/∂q, ∂τ/∂q̇, H           (Carpentier and Mansard 2018)
//   aba_derivatives.hpp     aba_derivatives: ∂q̈/∂q, ∂q̈/∂q̇, ∂q̈/∂τ = H⁻¹
//   energy.hpp              tree_kinetic_energy, tree_potential_energy
//   frames.hpp              frame_pose, frame_velocity, frame_acceleration, frame_classical_acceleration
//   frame_jacobian.hpp      frame_jacobian, frame_jacobian_time_variation: J and J̇ of a frame
//   frame_derivatives.hpp   frame_motion_derivatives: ∂ of a frame's velocity and acceleration
//   center_of_mass.hpp      center_of_mass, subtree_centers_of_mass, center_of_mass_jacobian
//   centroidal.hpp          centroidal_momentum, centroidal_momentum_matrix   (Orin & Goswami 2008)
//   floating_base.hpp       a floating base's pose and velocity to and from ROS's / Pinocchio's numbers
//   checked_call.hpp        checked_call: any of them on checked inputs, with its result checked
//
// What they read (configuration, joint vectors, wrenches) and what a wrong call says is
// arguments.hpp: each is an object algorithm<overloads, "name">, called as a function. What they
// share (kinematics, the forward pass) is passes.hpp.
#pragma once

#include "ctga/chains/aba.hpp"
#include "ctga/chains/aba_derivatives.hpp"
#include "ctga/chains/center_of_mass.hpp"
#include "ctga/chains/centroidal.hpp"
#include "ctga/chains/checked_call.hpp"
#include "ctga/chains/configuration_space.hpp"
#include "ctga/chains/crba.hpp"
#include "ctga/chains/energy.hpp"
#include "ctga/chains/forward_kinematics.hpp"
#include "ctga/chains/floating_base.hpp"
#include "ctga/chains/frame_derivatives.hpp"
#include "ctga/chains/frame_jacobian.hpp"
#include "ctga/chains/frames.hpp"
#include "ctga/chains/joint_limits.hpp"
#include "ctga/chains/minverse.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/rnea.hpp"
#include "ctga/chains/rnea_derivatives.hpp"
