// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reversal (quadrant-glitch) compensation tuned from circle tests (docs/ballbar.md "Reversal
// compensation"): the drive adds a pulse a·sgn(v_new)·exp(−t/τ) to the velocity command at each
// commanded reversal of an axis (reversal.amplitude a [m/s], reversal.time_constant τ [s];
// docs/simulator.md). The pulse gives the velocity integrator the torque step ΔT that the friction
// reversal demands, which otherwise only the following error builds up (the spike).
//
// Tuning: the spikes of a measured circle, then a search over (a, τ) per axis on a model of the machine
// (simulated circles that cover one reversal of each axis), then the compensated full circle predicted
// on the model before anything is written. The model must reproduce the measured spikes (within
// kModelSpikeTolerance) or the prediction is refused.

#include "core/model/BallBarTrace.h"
#include "core/model/Result.h"
#include "core/sim/CircleTest.h"
#include "core/sim/MachineDefinition.h"
#include "core/tuning/BallBarDiagnostics.h"

#include <array>
#include <string>
#include <vector>

namespace axistune::tuning {

/// Largest relative difference between the model's and the measured uncompensated spike for the
/// prediction to be trusted.
inline constexpr double kModelSpikeTolerance = 0.3;

/// The reversal spikes of one axis in a trace: the outward spike height at each reversal, 0 where no
/// spike passes the detection rule (BallBarDiagnostics); `worst` is the largest |height|.
struct AxisSpikes {
    std::vector<double> heightsM;
    double worstM = 0.0;
    double stepM = 0.0; ///< mean reversal step (the backlash) of the axis
};

/// Spikes of both plane axes of a trace (needs only the reversals the trace covers).
Result<std::array<AxisSpikes, 2>> reversalSpikes(const io::BallBarTrace& trace, const BallBarOptions& opt = {});

struct ReversalCompAxis {
    std::string axis;
    double amplitudeMPerS = 0.0;     ///< reversal.amplitude
    double timeConstantS = 0.0;      ///< reversal.time_constant
    double measuredSpikeM = 0.0;     ///< worst spike of the measured circle
    double modelSpikeM = 0.0;        ///< worst spike of the model's uncompensated full circle
    double predictedSpikeM = 0.0;    ///< worst spike of the model's compensated full circle
    double predictedReduction = 0.0; ///< 1 − predicted / model (fraction)
    double dTNm = 0.0;               ///< reversal torque change of the measured circle
    int evaluations = 0;             ///< simulated circles of the search
};

struct ReversalCompResult {
    std::array<ReversalCompAxis, 2> axes;
    io::BallBarTrace predicted; ///< the model's compensated full circle (the prediction)
    io::BallBarTrace modelUncompensated;
};

struct ReversalCompOptions {
    double searchDataArcDeg = 160.0; ///< data arc of the search circles (one reversal of each axis)
    double searchLeadArcDeg = 30.0;
    BallBarOptions ballbar;
};

/// Tunes the pulse of both plane axes of `circle` on `model` (whose parameters are those of the drive:
/// gains, filters, any compensation already written) against the measured circle `measured`.
/// Refused (BadInput) when the measured circle has no spike to compensate on either axis, when the model
/// does not reproduce the measured spikes within kModelSpikeTolerance, or when no candidate reduces a
/// spike (the reason names the axis and the numbers).
Result<ReversalCompResult> tuneReversalCompensation(const sim::MachineDefinition& model,
                                                    const sim::CircleTestOptions& circle,
                                                    const io::BallBarTrace& measured, double dTxNm, double dTyNm,
                                                    const ReversalCompOptions& opt = {});

} // namespace axistune::tuning
