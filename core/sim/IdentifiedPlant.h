// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An identified rigid-body model (core/ident, `axistune-cli identify`) as a simulated axis's plant:
// the total inertia, viscous and Coulomb friction referred to the motor (docs/identification.md
// "Using the result"). Linear axes: J = M·R², B = Fv·R², T_c = Fc·R with R = plant.screw_lead [m/rad].

#include "core/ident/IdentificationJson.h"
#include "core/model/Result.h"
#include "core/sim/MachineDefinition.h"

#include <string>

namespace axistune::sim {

/// Replaces plant.inertia_*, plant.viscous_* and plant.coulomb_* of `axis` so that their motor-side
/// totals equal the identified model; each is split between motor and load in the preset's own ratio
/// (all on the motor side where the preset has none), so a two-mass preset keeps its structure.
/// The offset has no simulator parameter and is not applied. Errors: linear model on a rotary axis
/// or the reverse, a value outside the parameter's limits (never clamped).
Status applyIdentifiedModel(AxisDefinition& axis, const ident::IdentifiedModel& model, const std::string& sourceName);

} // namespace axistune::sim
