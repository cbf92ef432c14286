// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A simulated milling cut with chatter avoidance in the loop (docs/chatter-avoidance.md): the cut of
// core/sim/CutSimulation with its spindle-speed loop, and one of the controllers of
// core/machining/ChatterAvoidance closing the loop through the spindle command:
//   none      constant speed;
//   adaptive  Methods 2 (sensor DOB: feed-stage disturbance observer on the linear encoder and the thrust
//             command, Table 4) or the accelerometer version (Table 3): Kalman frequency, stable pocket;
//   multimode Method 3 (J_chat search over lobes, Table 5), repeated steps;
//   esc       Method 4 (extremum seeking on a_y² or F̂_x², Table 6, speed bounds).
// Shared by `axistune-cli simulate-cut --avoid` and the machining wizard's avoidance page.

#include "core/machining/ChatterAvoidance.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"
#include "core/sim/CutSimulation.h"

#include <string>
#include <vector>

namespace axistune::avoidance {

enum class Method { None, Adaptive, MultiMode, Esc };

/// "none", "adaptive", "multimode", "esc" (the CLI spelling).
const char* methodName(Method m);
Result<Method> parseMethod(const std::string& text);

struct AvoidanceCutOptions {
    sim::CutSimulationOptions cut;
    Method method = Method::None;
    machining::AvoidanceSensor sensor = machining::AvoidanceSensor::Dob;
    machining::AdaptiveOptions adaptive = machining::adaptiveTable4Dob();
    machining::EscOptions esc;
    machining::StageDobOptions dob;
    /// adaptive with the DOB: band-pass the observer force around the tool's y mode, one tooth-passing
    /// frequency wide, before the estimator (AdaptiveOptions::modeBand*; set from the tool and the initial speed
    /// unless given there). applyMethodDefaults sets it for adaptive + DOB.
    bool toolModeBand = false;
};

struct AvoidanceCutResult {
    model::Capture capture; ///< trace + process channels + avoidance channels (docs/chatter-avoidance.md)
    std::vector<machining::AvoidanceStep> steps;
    double triggerTimeS = -1.0;     ///< first a_u² > σ_th (adaptive, multimode), machine time
    machining::EscDesign escDesign; ///< esc only
    double escIntegratorGain = 0.0; ///< esc only
    std::uint64_t escBoundHits = 0; ///< esc only: controller samples held at a speed bound
};

/// Sets `o.method`, `o.sensor` and the method's table defaults (adaptive: Table 4 with the DOB, Table 3 with the
/// accelerometer; multimode: Table 5, with the DOB Table 4's t_s, σ_th and band; esc: Table 6, with the DOB the
/// Ch.6 observer (Q 2500 Hz, high-pass 1000 Hz)). The cut and the ESC bounds are left as they are.
void applyMethodDefaults(AvoidanceCutOptions& o, Method method, machining::AvoidanceSensor sensor);

/// The y mode of the largest peak compliance 1/(c ω_n) and f_TPE = N n/60: the band of `toolModeBand`.
struct ToolModeBand {
    double centreHz = 0.0, widthHz = 0.0;
};
Result<ToolModeBand> toolModeBand(const sim::MillingSetup& setup);

/// Errors name the option at fault (the controller's create() message).
Result<AvoidanceCutResult> runAvoidanceCut(const sim::AxisDefinition& axis, const AvoidanceCutOptions& options);

/// RMS of a channel over [t0, t1] of the capture's t_s; error when the channel or samples are missing.
Result<double> channelRms(const model::Capture& cap, const std::string& channel, double t0, double t1);

/// Largest moving RMS (window windowS) of `channel` from t0 on; 0 when there are too few samples.
double peakMovingRms(const model::Capture& cap, const std::string& channel, double t0, double windowS);

/// First time ≥ t0 from which the moving RMS of `channel` over `windowS` stays below `limit` to the end of the
/// capture (the "stable from" instant); empty when it never settles.
std::optional<double> settledFrom(const model::Capture& cap, const std::string& channel, double t0, double windowS,
                                  double limit);

} // namespace axistune::avoidance
