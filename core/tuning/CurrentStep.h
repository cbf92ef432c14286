// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A measured q-axis current step (TestType::CurrentStep, docs/simulator.md "Current-step test") made
// comparable with the predictions of CurrentLoop.h: time from the step, current normalised by the step
// amplitude, the 10–90 % rise time and the overshoot, and the difference of two responses on one grid.

#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <cstddef>
#include <vector>

namespace axistune::tuning {

struct MeasuredCurrentStep {
    std::vector<double> tS;         ///< time since the step [s]; sample 0 is the first with the step commanded
    std::vector<double> normalised; ///< current_A / amplitude
    double amplitudeA = 0.0;        ///< the commanded step (signed)
    double stepTimeS = 0.0;         ///< t_s of the step sample in the capture
    double periodS = 0.0;           ///< sample period
};

/// The step in a trace with channels t_s, current_cmd_A and current_A: the first sample whose command
/// reaches half the largest |command| is the step. Errors name what is missing (a channel, a step, samples).
Result<MeasuredCurrentStep> currentStepFromCapture(const model::Capture& capture);

struct StepFigures {
    double riseTimeS = 0.0; ///< 10 %→90 % of the final value 1 by linear interpolation; NaN if 90 % is not reached
    double overshoot = 0.0; ///< max(y) − 1, at least 0
};

/// Rise time and overshoot of a step normalised to 1.
StepFigures stepFigures(const std::vector<double>& tS, const std::vector<double>& y);

struct StepDifference {
    double maxAbs = 0.0;     ///< largest |a − b|
    double rms = 0.0;        ///< root mean square of a − b
    std::size_t samples = 0; ///< samples compared (the shorter length)
};

/// a − b sample by sample over the common length (both on the same time grid).
StepDifference compareSteps(const std::vector<double>& a, const std::vector<double>& b);

} // namespace axistune::tuning
