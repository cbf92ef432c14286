// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Simulated ball-bar circle test (docs/ballbar.md "Simulated circle tests"): the two axes of a plane
// run a circle together under their own servo loops; the table positions, with optional geometric
// errors, are read as a ball bar pivoted at the programmed centre would read them.
//
// Path: the commanded angle φ(t) starts at rest on the circle, accelerates along a lead-in arc, runs a
// full 360° data arc at the programmed feed, and decelerates along a lead-out arc. The data arc starts
// at `dataStartDeg` (default 45°) so that no reversal lies at its ends.

#include "core/model/BallBarTrace.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"
#include "core/sim/MachineDefinition.h"

#include <cstdint>
#include <string>

namespace axistune::sim {

struct CircleTestOptions {
    double radiusM = 0.05;
    double feedMPerS = 1000.0 / 60000.0; ///< 1000 mm/min
    model::CircleDirection direction = model::CircleDirection::Ccw;
    double centerXM = 0.0; ///< circle centre in machine coordinates
    double centerYM = 0.0;
    std::string axisX = "X"; ///< axes of the plane (first = "x" role)
    std::string axisY = "Y";
    double dataStartDeg = 45.0;  ///< geometric angle at which the 360° data arc begins
    double leadArcDeg = 90.0;    ///< lead-in and lead-out arc length (acceleration happens in its first half)
    /// Length of the data arc [deg]: 360 for a ball-bar test; shorter arcs (30..360) are for model runs that
    /// need only some reversals (tuning::tuneReversalCompensation). Drives always run 360.
    double dataArcDeg = 360.0;
    double dwellS = 0.1;         ///< hold at the start before moving
    double squarenessPerM = 0.0; ///< γ [rad]: Y leans toward +X by γ per unit of Y (angle X–Y below 90° → γ > 0)
    double scaleX = 0.0;         ///< relative scale error of X (ratio, 1e-6 = 1 ppm)
    double scaleY = 0.0;
    double torqueExcludeDeg = 5.0; ///< torque plateaus for ΔT: from this angle ...
    double torqueWindowDeg = 20.0; ///< ... to this angle either side of each reversal
    std::uint64_t seed = 1;
};

struct CircleTestResult {
    model::BallBarTrace ballbar; ///< angle and radial deviation over the data arc, metadata filled in
    model::Capture traceX;    ///< servo trace of the first axis over the whole run
    model::Capture traceY;
    double dTxNm = 0.0; ///< reversal torque change (peak-to-peak, mean over both reversals)
    double dTyNm = 0.0;
};

/// Runs the circle on the two axes (`opt.axisX`, `opt.axisY`) of `machine`, whose parameters already
/// hold any change to apply (lost-motion compensation, gains). Bad options give BadInput.
Result<CircleTestResult> runCircleTest(const MachineDefinition& machine, const CircleTestOptions& opt);

/// The ball bar's reading of a circle trace (layout in CircleRun.h, from CircleRun or a drive's Circle
/// test): radial deviation over the data arc with the geometric errors of `opt` applied to the table
/// positions, and ΔT of both axes. traceX/traceY stay empty. A missing channel, a trace shorter than
/// the data arc (an aborted circle) or bad options give BadInput.
Result<CircleTestResult> evaluateCircleTrace(const model::Capture& trace, const CircleTestOptions& opt);
/// evaluateCircleTrace with the options from the trace's own metadata (circleOptionsFromTrace).
Result<model::BallBarTrace> ballBarFromCircleTrace(const model::Capture& trace);

} // namespace axistune::sim
