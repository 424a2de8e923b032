// A half-space, for static surroundings (a floor, a wall): z ≤ 0 in its body's frame, so that its
// boundary is the body's xy plane and its outward normal the body's z axis. Posed by the body's
// motor like every shape (the ground: the identity). It has no mass.
#pragma once

namespace ctga::collision {

template <class T = double>
struct half_space {};

}  // namespace ctga::collision
