// EXPECT: ctga: to_vector6 takes a screw
// to_vector6 reads the paper's 6-vectors (ω, v) and (l, p); a motor is not one.
#include <ctga/ctga.hpp>

auto wrong(const ctga::motor<double>& g) { return ctga::to_vector6(g); }
