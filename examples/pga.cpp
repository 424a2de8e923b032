// Projective geometric algebra Cl(3,0,1), ready-made (ctga::pga, klein's conventions): a point
// rotated and translated, the line through two points, the point where three planes meet.
// The sign conventions are listed at the top of <ctga/geometry/pga.hpp>.
#include <cstdio>
#include <iostream>

#include <ctga/ctga.hpp>

namespace pga = ctga::pga;

int main() {
    constexpr double pi = 3.14159265358979323846;
    const pga::point<> p = pga::make_point(1, 0, 0);

    // +90° about the z axis (right-hand rule), then +2 along z: the motor T * R applies R first
    const pga::rotor<> R = pga::make_rotor(pi / 2, 0, 0, 1);
    const pga::translator<> T = pga::make_translator(0, 0, 2);
    const pga::motor<> M = T * R;
    const pga::point<> q = pga::sandwich(M, p);  // R p R̃ then T: (0, 1, 2), a point again
    std::cout << "p        = " << p << "\n";
    std::cout << "R p R~   = " << pga::sandwich(R, p) << "\n";
    std::cout << "M p M~   = " << q << "\n";

    // the line from p to q: direction q - p, moment p x q; both points lie on it
    const pga::line<> l = pga::join(p, q);
    std::cout << "p v q    = " << l << "\n";
    std::cout << "p v l    = " << pga::join(p, l) << "   (zero: p lies on l)\n";

    // three planes x = 1, y = 2, z = 3 meet at (1, 2, 3)
    const pga::plane<> ex = pga::make_plane(1, 0, 0, -1), ey = pga::make_plane(0, 1, 0, -2),
                       ez = pga::make_plane(0, 0, 1, -3);
    const pga::point<> x = pga::meet(ex, ey, ez);
    std::cout << "meet     = " << x << "\n";
    std::cout << "x on ex? " << pga::join(ex, x) << "   (a x + b y + c z + d w: zero)\n";

    // the plane through p, q and x; and where the line l pierces the plane z = 3
    std::cout << "plane    = " << pga::join(p, q, x) << "\n";
    std::cout << "l ^ ez   = " << pga::normalized(pga::meet(l, ez)) << "\n";

    // a rotor about a zero axis is reported (error_code::zero_direction), not made
    const auto bad = pga::make_rotor_checked(1.0, 0, 0, 0);
    std::printf("make_rotor_checked(1, 0, 0, 0) %s\n", bad ? "made a rotor" : "refused the zero axis");
    return bad ? 1 : 0;
}
