// ctga: compile-time Clifford algebra for rigid-body dynamics
// (J. M. Selig, E. Bayro-Corrochano, "Rigid Body Dynamics Using Clifford Algebra", 2010).
// The umbrella header: the whole library.
#pragma once

#include "ctga/algebra/blade.hpp"
#include "ctga/algebra/fixed_string.hpp"
#include "ctga/algebra/io.hpp"
#include "ctga/algebra/layout.hpp"
#include "ctga/algebra/multivector.hpp"
#include "ctga/algebra/operations.hpp"
#include "ctga/algebra/products.hpp"
#include "ctga/algebra/signature.hpp"
#include "ctga/algebras.hpp"
#include "ctga/expr/expression.hpp"
#include "ctga/expr/nodes.hpp"
#include "ctga/expr/normal_form.hpp"
#include "ctga/expr/program.hpp"
#include "ctga/expr/rational.hpp"
#include "ctga/mechanics/motion.hpp"
#include "ctga/mechanics/checked.hpp"
#include "ctga/mechanics/convert.hpp"
#include "ctga/mechanics/dynamics.hpp"
#include "ctga/mechanics/inertia.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/spatial.hpp"
#include "ctga/mechanics/transform.hpp"
#include "ctga/mechanics/exp_log.hpp"
