// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A milling cut on one simulated feed axis (docs/machining.md "Simulated cuts"): the axis feeds at
// f_z·N·n/60 under position control, the milling process with regeneration (Milling.h) engages at
// `engageS`, and its force acts on the table as a load torque R·F. The trace gets the process signals
// at the trace instants: cutting_force_N (force of the process on the table along +axis) and tool_x_m.
// Shared by `axistune-cli simulate-cut` and the machining wizard.

#include "core/model/Capture.h"
#include "core/model/Result.h"
#include "core/sim/MachineDefinition.h"
#include "core/sim/Milling.h"

#include <cstdint>

namespace axistune::sim {

struct CutSimulationOptions {
    MillingSetup milling;
    double durationS = 1.0;  ///< traced machine time
    double engageS = 0.2;    ///< the tool enters the material
    /// The simulator's lost motion is quasi-static (table deflection ∝ the instantaneous motor torque): it
    /// turns current-loop noise into table accelerations a real table does not make, so it is off by default.
    bool lostMotion = false;
    std::uint64_t seed = 1;
};

/// Runs the cut on `axis` (a linear axis of a machine definition). Errors name the option at fault.
Result<model::Capture> simulateCut(const AxisDefinition& axis, const CutSimulationOptions& options);

}  // namespace axistune::sim
