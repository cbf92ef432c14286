// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Comparing two frequency responses of the same loop (the notch wizard's prediction against the
// verification measurement, docs/wizards/notch.md "Verify"):
//   deviation  |20log10|b(f)| − 20log10|a(f)|| at the frequencies of b, with a interpolated linearly
//              in (log10 f, dB) between its two neighbouring valid points; a point of b is compared
//              when it is valid, lies inside a's valid range and at least one of the two magnitudes
//              is at or above floorDb (far below the loop's unity level the two carry no information
//              about the margins, and the held torque command's images dominate there, docs/notch.md);
//   peak       the largest magnitude of the valid points within centre·(1 ± relHalfWidth).

#include "core/dsp/FrequencyResponse.h"

#include <cstddef>
#include <limits>

namespace axistune::tuning {

struct FrfDeviation {
    double maxAbsDb = std::numeric_limits<double>::quiet_NaN();  ///< largest |Δ| [dB]; NaN: no point compared
    double maxAtHz = std::numeric_limits<double>::quiet_NaN();   ///< frequency of the largest |Δ|
    double rmsDb = std::numeric_limits<double>::quiet_NaN();     ///< root mean square of Δ [dB]
    std::size_t points = 0;                                      ///< compared points
    double fminHz = 0.0, fmaxHz = 0.0;                           ///< range of the compared points
};

/// Magnitude deviation of `measured` from `reference` (see the file comment).
FrfDeviation compareMagnitudes(const dsp::FrequencyResponse& reference, const dsp::FrequencyResponse& measured,
                               double floorDb = -50.0);

/// Largest magnitude [dB] of the valid points within centerHz·(1 ± relHalfWidth); NaN when there is none.
double peakMagnitudeDb(const dsp::FrequencyResponse& frf, double centerHz, double relHalfWidth);

}  // namespace axistune::tuning
