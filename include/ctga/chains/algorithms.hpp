// The algorithms of a kinematic tree (tree.hpp), one header each, named as Featherstone (2008)
// names them:
//
//   forward_kinematics.hpp  forward_kinematics: every body's frame, velocity and acceleration     (§4.1)
//   rnea.hpp                rnea: inverse dynamics τ(q, q̇, q̈), recursive Newton–Euler            (§5.3)
//   crba.hpp                crba: the joint-space mass matrix H(q), composite rigid bodies        (§6.2)
//   aba.hpp                 aba: forward dynamics q̈(q, q̇, τ), articulated bodies                (§7.3)
//   energy.hpp              tree_kinetic_energy, tree_potential_energy
//   frame_jacobian.hpp      body_jacobian, world_jacobian: the geometric Jacobian of a body's frame
//   checked_call.hpp        checked_call: any of them on checked inputs, with its result checked
//
// What they share (configuration, joint vectors, kinematics, the forward pass) is passes.hpp.
#pragma once

#include "ctga/chains/aba.hpp"
#include "ctga/chains/checked_call.hpp"
#include "ctga/chains/crba.hpp"
#include "ctga/chains/energy.hpp"
#include "ctga/chains/forward_kinematics.hpp"
#include "ctga/chains/frame_jacobian.hpp"
#include "ctga/chains/passes.hpp"
#include "ctga/chains/rnea.hpp"
