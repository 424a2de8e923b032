// DART 6.12 (Debian's libdart-dev) as a third engine of ctga_chains_bench's contact steps:
// contact_step_<label>/dart (chains_dart.cpp), beside contact_step_<label>/ctga and /mujoco.
//
// Plain numbers only, as chains_mujoco.hpp: neither ctga's nor DART's headers, so that it costs
// the calling unit nothing to compile. Without CTGA_BENCH_DART (DART not found by CMake; defined
// only for the units that call it) add_dart_contact does nothing.
#pragma once

#include <vector>

#include "chains_mujoco.hpp"
#include "runner.hpp"

namespace bench::chains {

#ifdef CTGA_BENCH_DART
inline constexpr bool dart_enabled = true;
// The scenario in DART: its model checked against `reference` (ctga's numbers on states of the
// same robot in mujoco_case's coordinates: q, qd, qdd, and tau_ref, H_ref ctga's τ = H q̈ + C and H
// there; its bodies and gravity are the scenario's), the errors and its figures on stderr, and
// contact_step_<label>/dart. One tree without a held body (the quadruped); other scenarios are
// reported and skipped.
void add_dart_contact(std::vector<entry>& table, const contact_scenario& s, const mujoco_case& reference);
#else
inline constexpr bool dart_enabled = false;
inline void add_dart_contact(std::vector<entry>&, const contact_scenario&, const mujoco_case&) {}
#endif

}  // namespace bench::chains
