// Names of the previous release, kept for one more release. Each warns where it is used and
// names its replacement.
#pragma once

#include "ctga/mechanics/coscrew.hpp"
#include "ctga/mechanics/dynamics.hpp"
#include "ctga/mechanics/momentum.hpp"
#include "ctga/mechanics/screw.hpp"

namespace ctga::paper {
// The paper's formulas, lazily: each operation's .formula.
[[deprecated("use ctga::bracket.formula")]] inline constexpr const auto& bracket = ctga::bracket.formula;
[[deprecated("use ctga::evaluation.formula")]] inline constexpr const auto& evaluation = ctga::evaluation.formula;
[[deprecated("use ctga::momentum.formula")]] inline constexpr const auto& momentum = ctga::momentum.formula;
[[deprecated("use ctga::kinetic_energy.formula (twice the energy)")]] inline constexpr const auto& twice_kinetic_energy =
    ctga::kinetic_energy.formula;
[[deprecated("use ctga::coadjoint.formula")]] inline constexpr const auto& coadjoint = ctga::coadjoint.formula;
[[deprecated("use ctga::inertia_rate.formula")]] inline constexpr const auto& inertia_rate = ctga::inertia_rate.formula;
[[deprecated("use ctga::velocity.formula")]] inline constexpr const auto& velocity = ctga::velocity.formula;
[[deprecated("use ctga::motion_lhs")]] inline constexpr const auto& motion_lhs = ctga::motion_lhs;
}  // namespace ctga::paper
