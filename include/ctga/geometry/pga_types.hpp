// The projective geometric algebra Cl(3,0,1) and its element types, in klein's conventions
// (https://jeremyong.com/klein/). Each type names its blades in the words below, so that a value
// prints in them (operations/io.hpp: a point prints e0e3e2, e0e1e3, e0e2e1, e1e2e3) and its
// constructor takes the coefficients in the order listed:
//
//   plane       a e1 + b e2 + c e3 + d e0                 the plane a x + b y + c z + d = 0
//   line        m_x e01 + m_y e02 + m_z e03               the moment m = p × v (p any point on the line)
//               + v_x e23 + v_y e31 + v_z e12             and the direction v (Plücker coordinates)
//   point       x e032 + y e013 + z e021 + w e123         the point (x, y, z)/w; w = 1 when normalised
//   direction   x e032 + y e013 + z e021                  the point at infinity in direction (x, y, z)
//   rotor       s + r_x e23 + r_y e31 + r_z e12           a rotation about an axis through the origin
//   translator  s + t_x e01 + t_y e02 + t_z e03           a translation
//   motor       s + (e23, e31, e12) + (e01, e02, e03) + p e0123   any rigid motion (the even subalgebra)
//
// (e032 is the word e0e3e2, and so on.) What each coefficient means under rotations,
// translations, joins and meets: pga.hpp.
#pragma once

#include "ctga/algebra/algebra.hpp"

namespace ctga::pga {

// e0² = 0, e1² = e2² = e3² = +1, in this order (the basis order of the shuffle product ∨: the
// orientation of join, pga.hpp).
using algebra = ctga::algebra<"e0 e1 e2 e3", 0, 1, 1, 1>;

template <class T = double>
using plane = algebra::mv<T, "e1", "e2", "e3", "e0">;
template <class T = double>
using line = algebra::mv<T, "e0e1", "e0e2", "e0e3", "e2e3", "e3e1", "e1e2">;
template <class T = double>
using point = algebra::mv<T, "e0e3e2", "e0e1e3", "e0e2e1", "e1e2e3">;
template <class T = double>
using direction = algebra::mv<T, "e0e3e2", "e0e1e3", "e0e2e1">;
template <class T = double>
using rotor = algebra::mv<T, "1", "e2e3", "e3e1", "e1e2">;
template <class T = double>
using translator = algebra::mv<T, "1", "e0e1", "e0e2", "e0e3">;
template <class T = double>
using motor = algebra::mv<T, "1", "e2e3", "e3e1", "e1e2", "e0e1", "e0e2", "e0e3", "e0e1e2e3">;

}  // namespace ctga::pga
