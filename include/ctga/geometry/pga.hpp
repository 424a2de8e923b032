// Projective geometric algebra Cl(3,0,1), ready-made: points, lines, planes, directions, rotors,
// translators and motors in klein's conventions (https://jeremyong.com/klein/), computed by
// ctga's engine. Everything is in namespace ctga::pga (it shares names with ctga's Cl(0,3,1)
// mechanics: write pga::motor, not `using namespace` both):
//
//   namespace pga = ctga::pga;
//   pga::point<> p = pga::make_point(1, 0, 0);
//   pga::rotor<> R = pga::make_rotor(pi / 2, 0, 0, 1);   // +90° about the z axis
//   pga::point<> q = pga::sandwich(R, p);                // (0, 1, 0): y e013 + w e123, a point again
//   pga::line<>  l = pga::join(p, q);                    // the line from p to q
//
// The scalar type is a template argument, double by default (point<> is point<double>), as for
// ctga's other element types.
//
//   pga_types.hpp         the algebra and the element types (their blades)
//   pga_operations.hpp    sandwich, join, meet, norms
//   pga_constructors.hpp  make_point, make_plane, make_rotor, make_translator, make_line, ...
//   (and operations/io.hpp: `std::cout << p` prints p in its type's blade words)
//
// Conventions. The algebra is algebra<"e0 e1 e2 e3", 0, 1, 1, 1>; eijk is the word ei ej ek
// (e032 = e0e3e2 = −e0e2e3). Each line below is checked by tests/pga_test.cpp against an
// independent reference (hand-written matrices, Rodrigues' formula, solved linear systems).
//
//   plane       a e1 + b e2 + c e3 + d e0, stored (a, b, c, d): the plane a x + b y + c z + d = 0,
//               normal n = (a, b, c).
//   point       x e032 + y e013 + z e021 + w e123, stored (x, y, z, w): the point (x, y, z)/w.
//   direction   x e032 + y e013 + z e021: the point at infinity in direction (x, y, z) (w = 0).
//   line        m_x e01 + m_y e02 + m_z e03 + v_x e23 + v_y e31 + v_z e12, stored in that order:
//               direction v, moment m = p × v for any point p of the line (Plücker coordinates).
//   rotor       make_rotor(θ, u) = cos(θ/2) − sin(θ/2)(u_x e23 + u_y e31 + u_z e12), u unit:
//               turns by +θ about the axis u through the origin, right-handed (counter-clockwise
//               seen from the tip of u): (1, 0, 0) by +90° about z goes to (0, 1, 0). Points,
//               directions, lines and planes turn alike.
//   translator  make_translator(d) = 1 − ½(d_x e01 + d_y e02 + d_z e03): moves points by +d.
//   motor       s + (e23, e31, e12) + (e01, e02, e03) + p e0123: any product of the above.
//   sandwich    sandwich(M, x) = M x M̃, in x's type. Composition: M2 * M1 applies M1 first
//               (sandwich(M2 * M1, x) = sandwich(M2, sandwich(M1, x))); a motor T * R rotates
//               about the origin, then translates.
//   join        (∨, `&`) join(p, q) of two points: the line directed from p to q, v = w_p q − w_q p
//               (q − p when normalised), m = p × q.
//               join(l, r) = join(r, l) of a line (v, through p) and a point r (normalised): the
//               plane through both with normal v × (r − p); so join(p, q, r) of three points has
//               normal (q − p) × (r − p): p, q, r run counter-clockwise seen from where n points.
//               join(e, r) of a plane and a point: the number a x + b y + c z + d w (the signed
//               distance when both are normalised); join(r, e) is its negative.
//   meet        (∧, `^`) meet(e, f) of two planes: the line with direction n_e × n_f.
//               meet(e, f, g) of three planes: the point with w = det[n_e; n_f; n_g], at their
//               intersection (normalized() divides by w).
//               meet(e, l) = meet(l, e) of a plane and a line: the point with w = n · v, at the
//               intersection.
//               meet(e, r) of a plane and a point: the coefficient of e0123, a x + b y + c z + d w;
//               meet(r, e) is its negative.
//   incidence   a point r lies on a plane e iff join(r, e) = 0; on a line l iff join(r, l) = 0 (the
//               plane's four numbers); two lines meet iff join(l1, l2) = 0.
//   norms       norm(plane) = |n|, norm(line) = |v|, norm(rotor) = √(R R̃), norm(direction) its
//               length; normalized(x) divides by the norm, normalized(point) by w.
#pragma once

#include "ctga/geometry/pga_constructors.hpp"
#include "ctga/geometry/pga_operations.hpp"
#include "ctga/geometry/pga_types.hpp"
#include "ctga/operations/io.hpp"
