// EXPECT: CTGA_LOOP_THRESHOLD is no longer read.*one-definition rule
// A loop threshold that differs between translation units would give the same inline functions
// different bodies and result types (an ODR violation no linker reports), so the threshold is not
// a macro: defining CTGA_LOOP_THRESHOLD is refused with the per-expression alternative.
#define CTGA_LOOP_THRESHOLD 256
#include <ctga/core.hpp>

int main() { return 0; }
