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
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace axistune::sim {

/// What a spindle-speed controller sees at one of its sample instants (docs/chatter-avoidance.md).
struct CutProbe {
    double timeS = 0.0;      ///< machine time
    double toolAccelX = 0.0; ///< tool acceleration [m/s²] (an accelerometer on the spindle)
    double toolAccelY = 0.0;
    double tablePositionM = 0.0; ///< linear encoder (load side)
    double thrustCommandN = 0.0; ///< motor torque command / lead per radian
    double spindleRpm = 0.0;     ///< actual spindle speed
    double spindleCmdRpm = 0.0;  ///< spindle command in force
};

/// Called at every controller sample instant; returns the new spindle speed command [rpm] and may write its
/// diagnostics into `probes` (one value per name in CutSimulationOptions::probeChannels).
using SpindleController = std::function<double(const CutProbe&, std::span<double> probes)>;

struct CutSimulationOptions {
    MillingSetup milling;
    double durationS = 1.0; ///< traced machine time
    double engageS = 0.2;   ///< the tool enters the material
    /// The simulator's lost motion is quasi-static (table deflection ∝ the instantaneous motor torque): it
    /// turns current-loop noise into table accelerations a real table does not make, so it is off by default.
    bool lostMotion = false;
    std::uint64_t seed = 1;
    /// Optional spindle-speed controller, run every controllerPeriodS from the engagement on (the spindle
    /// turns at the setup speed until then). Its probes become trace channels with these names.
    SpindleController controller;
    double controllerPeriodS = 0.0;
    std::vector<std::string> probeChannels;
    /// Called every 50 ms of machine time with the time reached; returning false aborts the run
    /// (ErrorCode::Aborted).
    std::function<bool(double)> progress;
};

/// Runs the cut on `axis` (a linear axis of a machine definition). Errors name the option at fault.
Result<model::Capture> simulateCut(const AxisDefinition& axis, const CutSimulationOptions& options);

} // namespace axistune::sim
