// ctga: compile-time Clifford algebra for rigid-body dynamics
// (J. M. Selig, E. Bayro-Corrochano, "Rigid Body Dynamics Using Clifford Algebra", 2010).
// The umbrella header: every public header of the library.
//
//   support/      inline.hpp, math.hpp, checked.hpp           no dependencies
//   algebra/      blades, layouts, the algebra type, rules, multivector storage
//   expr/         the expression engine: normal forms, staging, programs, running them
//   operations/   the user-facing operations: operators, evaluation, formulas, printing
//   geometry/     ready-made Cl(3,0,1) (namespace ctga::pga): points, lines, planes, motors
//   mechanics/    the paper: algebras, screw, coscrew, motor, the inertias (mass properties,
//                 representations, 6×6 matrices, momentum and energy, transforms), dynamics, convert
//   collision/    shapes posed by their bodies' motors and their mass; separations, contact
//                 manifolds, ray casts, time of impact (shape_set.hpp), the broadphase, a contact
//                 force as a co-screw
//   integrators/  the motion-model interface, methods stepping any model, ctga's rigid-body model
//   scenes/       body kinds, scenes of many bodies, batches
//   chains/       kinematic trees: joints, the tree type, FK, RNEA, CRBA, ABA, Jacobians (one header
//                 each, algorithms.hpp), the tree as an integrator model (motion.hpp)
#pragma once

#include "ctga/chains/algorithms.hpp"
#include "ctga/chains/motion.hpp"
#include "ctga/collision/broadphase.hpp"
#include "ctga/collision/line_of_action.hpp"
#include "ctga/collision/shape_set.hpp"
#include "ctga/collision/time_of_impact.hpp"
#include "ctga/core.hpp"
#include "ctga/geometry/pga.hpp"
#include "ctga/integrators/integrate.hpp"
#include "ctga/integrators/methods.hpp"
#include "ctga/integrators/model.hpp"
#include "ctga/integrators/rigid_body_motion.hpp"
#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/body_inertia.hpp"
#include "ctga/mechanics/convert.hpp"
#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/dynamics.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/inertia_matrix.hpp"
#include "ctga/mechanics/inertia_transform.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/rigid_body.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/scenes/batch.hpp"
#include "ctga/scenes/body_kinds.hpp"
#include "ctga/scenes/scene.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/unit_direction.hpp"
