// The algebra and its operations without the mechanics: any Cl(p,q,r) up to 16 generators, the
// lazy products, formulas, evaluation and printing.
//
//   using G = ctga::algebra<"e1 e2 e3 e", -1, -1, -1, 0>;
//   G::mv<double, "1", "e2e3"> r = a * b;
#pragma once

#include "ctga/algebra/algebra.hpp"
#include "ctga/operations/evaluate.hpp"
#include "ctga/operations/formula.hpp"
#include "ctga/operations/io.hpp"
#include "ctga/operations/operators.hpp"
