// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Loop analysis on measured frequency responses: open loop from a closed-loop measurement, gain and
// phase margins, crossover frequencies and peak sensitivity, interpolated between measured points.
//
// Loop convention (negative feedback, open loop L = P·C):
//   Complementary:    the measurement is T = L/(1+L). This is the velocity-loop FRF of
//                     spec/current-loop-and-multisweep-frf.md §3.2, eq. (3.1): the disturbance d
//                     injected into the torque command and the response read as the torque T_m
//                     (d → T_m = PC/(1+PC)), equal to the command response ω* → ω. L = T/(1−T).
//   NegComplementary: the measurement is −T (e.g. d added after the controller and the
//                     controller output read back: u_c = −PC/(1+PC)·d). L = −M/(1+M).
//   Sensitivity:      the measurement is S = 1/(1+L) (total torque u_c + d read back). L = 1/S − 1.
// Interpolation between neighbouring valid points is linear in log10 f for log10|L| and for the
// unwrapped phase. Invalid points are not used, and no interpolation bridges an invalid point.

#include "core/dsp/FrequencyResponse.h"

#include <limits>
#include <vector>

namespace axistune::dsp {

enum class LoopMeasurement { Complementary, NegComplementary, Sensitivity };

/// Open loop L from a closed-loop measurement (see the conventions above). Points where the
/// conversion is singular (T = 1, M = −1, S = 0) are marked invalid. Coherence is carried over.
FrequencyResponse openLoopFromClosedLoop(const FrequencyResponse& measured, LoopMeasurement kind);

struct Crossover {
    double freqHz = 0.0;
    double marginDb = 0.0;   ///< gain margin −20log10|L| at a phase crossover (0 at a gain crossover)
    double marginDeg = 0.0;  ///< phase margin at a gain crossover, in (−180, 180] (0 at a phase crossover)
};

struct LoopMargins {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    std::vector<Crossover> gainCrossovers;   ///< |L| = 1, increasing frequency
    std::vector<Crossover> phaseCrossovers;  ///< ∠L = −180° (mod 360°), increasing frequency
    double phaseMarginDeg = kInf;            ///< smallest phase margin over the gain crossovers
    double phaseMarginFreqHz = 0.0;       ///< frequency where the smallest phase margin occurs
    double gainMarginDb = kInf;              ///< smallest gain margin over the phase crossovers
    double gainMarginFreqHz = 0.0;
    double peakSensitivity = 0.0;            ///< max |1/(1+L)| over the valid points
    double peakSensitivityDb = 0.0;
    double peakSensitivityFreqHz = 0.0;
};

/// Margins of an open loop L.
LoopMargins loopMargins(const FrequencyResponse& openLoop);

}  // namespace axistune::dsp
