// EXPECT: no narrowphase routine for this pair of shape kinds
// A scene's moving kinds (collision/shape_set.hpp) that hold a half-space, queried against its
// static kinds (another half-space): the variants' visit meets a pair without a routine, a
// compile error naming the problem rather than a run-time failure.
#include <ctga/collision/shape_set.hpp>

int main() {
    namespace co = ctga::collision;
    const ctga::motor_map<double> I{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
    const co::shape<co::sphere<double>, co::half_space<double>> moving = co::sphere<double>{1.0};
    const co::shape<co::half_space<double>> fixed = co::half_space<double>{};
    return co::separation_of(moving, I, fixed, I).distance > 0;
}
