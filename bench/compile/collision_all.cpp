// Compile-cost unit (tools/compile-cost.sh, row (b7)): every shape kind of the collision layer
// and every pair a scene can meet, at -O2: the moving kinds (sphere, capsule, box, cylinder, a
// convex hull of 32 points) against each other and against the static ones (half-space, triangle
// mesh, height field), as collision/shape_set.hpp's variants, for separation_of and contact_of;
// the moving kinds' boxes and every kind's ray cast. The budget: ≤ 10 s, ≤ 1 GB.
#include <ctga/collision/shape_set.hpp>

namespace co = ctga::collision;
using moving = co::shape<co::sphere<double>, co::capsule<double>, co::box<double>, co::cylinder<double>, co::convex_hull<double, 32>>;
using fixed = co::shape<co::half_space<double>, co::triangle_mesh<double>, co::height_field<double>>;

co::separation<double> separation(const moving& a, const ctga::motor_map<double>& pa, const moving& b, const ctga::motor_map<double>& pb) {
    return co::separation_of(a, pa, b, pb);
}
co::separation<double> separation(const moving& a, const ctga::motor_map<double>& pa, const fixed& b, const ctga::motor_map<double>& pb) {
    return co::separation_of(a, pa, b, pb);
}
co::manifold<double> contact(const moving& a, const ctga::motor_map<double>& pa, const moving& b, const ctga::motor_map<double>& pb) {
    return co::contact_of(a, pa, b, pb, 0.01);
}
co::manifold<double> contact(const fixed& a, const ctga::motor_map<double>& pa, const moving& b, const ctga::motor_map<double>& pb) {
    return co::contact_of(a, pa, b, pb, 0.01);
}
co::aabb<double> bounds(const moving& a, const ctga::motor_map<double>& pa) { return co::bounds_of(a, pa); }
co::ray_hit<double> cast(const moving& a, const ctga::motor_map<double>& pa, const co::ray<double>& r) { return co::ray_cast(a, pa, r); }
co::ray_hit<double> cast(const fixed& a, const ctga::motor_map<double>& pa, const co::ray<double>& r) { return co::ray_cast(a, pa, r); }
