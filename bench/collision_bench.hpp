// ctga_collision_bench: the collision layer's queries (include/ctga/collision/) beside FCL 0.7 and
// Bullet 3.24 when CMake finds them (CTGA_BENCH_FCL, CTGA_BENCH_BULLET), as Google Benchmarks named
//   collision_<pair>/<implementation>   distance and contact of one pair kind (collision_pairs.cpp)
//   broadphase_10k/<implementation>     10,000 moving boxes, update and pair query per step
//                                       (collision_broadphase.cpp)
//   clip_segment/<vec3|pga>             a manifold's clipping step in 3-vectors and in ctga::pga
//                                       (collision_algebra.cpp)
// Each source registers its rows; collision.cpp runs them.
#pragma once

namespace bench::collision {
void register_pairs();
void register_broadphase();
void register_algebra();
}  // namespace bench::collision
