#include "collision_bench.hpp"

void bench::collision::register_pairs() {}
