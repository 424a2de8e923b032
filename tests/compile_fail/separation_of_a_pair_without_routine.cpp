// EXPECT: no narrowphase routine for this pair of shape kinds
// separation_of of two half-spaces (unbounded: no separation): no routine, a compile error that
// says so, not a run-time fallback.
#include <ctga/collision/narrowphase.hpp>

int main() {
    const ctga::motor_map<double> I{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
    const auto s = ctga::collision::separation_of(ctga::collision::half_space<double>{}, I, ctga::collision::half_space<double>{}, I);
    return s.distance > 0;
}
