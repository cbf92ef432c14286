// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The following error of a move predicted from a measured loop (docs/linuxcnc.md "Following error of a move"):
// the PID the NC closes (PositionPid.h, LinuxCNC's discrete pid with FF1 and FF2) around the effective plant P_eff
// measured as lines of a frequency response, and a position command sampled once per servo period.
//
// LinuxCNC's pid (2.9) computes, each period, with the command r and the feedback y:
//   e = r[n−1] − y[n] when its pin error-previous-target is TRUE (the default), else r[n] − y[n]  (the error pin)
//   out = P·e + I·Σe·T + D·((r[n] − r[n−1]) − (y[n] − y[n−1]))/T + FF1·ṙ + FF2·r̈   (backward differences)
// so with C = P + I·T/(1 − z⁻¹) + D·(1 − z⁻¹)/T on the feedback, the command enters through
// C_r = (P + I·T/(1 − z⁻¹))·z⁻¹ + D·(1 − z⁻¹)/T (C_r = C without error-previous-target) and
// F = FF1·(1 − z⁻¹)/T + FF2·((1 − z⁻¹)/T)². With an optional notch N after the PID:
//   Y = P_eff·N·(C_r + F)·R / (1 + P_eff·N·C),   error pin E = z⁻¹·R − Y (or R − Y)
// evaluated on the DFT bins of the command padded with rest at its end (the move is one period of a periodic
// command), and transformed back. P_eff between measured lines is interpolated (log-magnitude and unwrapped phase,
// linear in log frequency); outside the measured band it is extrapolated as a rigid body (|P| ∝ f⁻² for a torque
// input, f⁻¹ for a velocity input, phase held). When a notable share of the predicted error lies below the measured
// lines, the prediction is refused unless the measured plant over its lowest decade falls as that rigid body does.

#include "core/model/Result.h"
#include "core/tuning/PositionPid.h"

#include <complex>
#include <optional>
#include <span>
#include <vector>

namespace axistune::tuning {

struct MovePredictionOptions {
    DriveInput input = DriveInput::Torque;
    std::optional<BiquadNotch> notch;
    bool errorPreviousTarget = true; ///< the pid's error-previous-target pin (TRUE in LinuxCNC 2.9 by default)
    double restAfterS = 1.0;         ///< rest appended to the command before the transform (the error decays in it)
    /// A prediction with more than this share of its error energy below the measured lines is refused unless the plant
    /// over its lowest measured decade falls as the rigid body does (within maxOrderDeviation of f⁻² or f⁻¹).
    double maxExtrapolatedShare = 0.05;
    double maxOrderDeviation = 0.25;
};

struct MovePrediction {
    std::vector<double> error;      ///< the pid's error pin, one value per servo period of the command
    std::vector<double> output;     ///< PID output (the drive input), same samples
    double peakError = 0.0;         ///< max |error|
    double peakOutput = 0.0;        ///< max |output|
    double extrapolatedShare = 0.0; ///< of Σ|E_k|², from bins outside the measured lines
    double lowDecadeOrder = 0.0;    ///< −slope of log|P| against log f over the lowest measured decade
};

/// Predicts the following error and PID output of `command` (one sample per servo period `periodS`, starting at
/// rest). Errors: fewer than 3 lines, lines not ascending or not finite, an empty or non-finite command, a command
/// that does not start and end at rest, or a prediction that leans on the extrapolated bins.
Result<MovePrediction> predictMove(const std::vector<double>& freqHz, const std::vector<std::complex<double>>& plant,
                                   const PositionPid& pid, double periodS, std::span<const double> command,
                                   const MovePredictionOptions& options = {});

} // namespace axistune::tuning
