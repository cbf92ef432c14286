// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Notch designs for a resonance that moves over the travel (internal to core/autotune; docs/tuning.md "Over the
// travel", "Notches for a moving resonance"). The tuner over positions measures the open loop at every position;
// the resonances there (above kResonanceSeparation x the required crossover) are the input here. Each design is a
// set of notches with the rule that sized them; the sequence (AutoTunePositionsNotches.cpp) predicts every
// position's plant with each design, runs the same PI search over every position's MEASURED plant the velocity-PI
// step runs (searchPi), and keeps the design with the widest worst-case closed-loop bandwidth. A design is never
// chosen for its own sake: a deep, wide notch costs phase at the crossover, a shallow or narrow one may leave a
// peak above the gain margin; the measured plants decide.
//
// The designs (resonance r at a position: frequency f_r, height H above its baseline [dB], -3 dB width w):
//   none          no new notch (a collocated mode whose peak keeps its phase away from -180 deg needs none);
//   band q, k     the lowest resonance of every position (the one that moves) covered by ONE notch at the
//                 geometric mean of its lowest and highest frequency, digital width k x their distance (k in
//                 kBandWidthFactors), depth 10^(-q H_min/20) with the smallest height of those resonances; the
//                 other resonances as in "peak q, zp";
//   peak q, zp    at each position a notch at f_r of depth d = 10^(-q H/20) (it takes the fraction q of the peak's
//                 height away) and digital width w/d clamped to w ... f_r (its zeros on the mode's poles: the
//                 peak drops by d without side lobes), q in kPeakFractions;
//   peak q, w     the same depth, digital width w (the peak's own -3 dB width: the least phase below it);
//   wizard        the notch wizard's proposal at each position (tuning::analyseNotches: depth to the baseline or to
//                 -20 dB open loop, width w/d clamped to w ... f_r), as the one-position sequence (the rule before);
// In the per-position designs, a notch whose resonance lies within kSameNotch of the centre of an earlier
// position's notch is left out (the earlier one notches it). A notch the execution rate cannot run is left out.

#include "core/tuning/Notch.h"
#include "core/tuning/Resonance.h"

#include <string>
#include <vector>

namespace axistune::autotune::detail {

/// Two positions' notches within this fraction of the centre are one notch (the earlier position's).
inline constexpr double kSameNotch = 0.05;
/// Fractions of a peak's height [dB] a peak-sized notch takes away, shallowest first.
inline constexpr double kPeakFractions[] = {0.25, 0.5, 0.75, 1.0};
/// Digital width of a band notch, in multiples of the distance between the moving resonance's extremes.
inline constexpr double kBandWidthFactors[] = {1.0, 1.5, 2.0};
/// A design must widen the worst-case bandwidth by more than this fraction to replace an earlier one in the list (the
/// list goes from no notch over one band notch to a notch per position): a notch sized on the resonance at the
/// measured positions does not follow it between them, where nothing is measured; it has to be worth it.
inline constexpr double kDesignBandwidthGain = 0.1;

/// One position's resonances to notch (on its open loop, above the separation from the required crossover) and the
/// notch wizard's proposal there.
struct PositionResonances {
    double x = 0.0;
    std::vector<tuning::Resonance> resonances;
    std::vector<tuning::ProposedNotch> wizard;
};

struct NotchDesign {
    std::string name; ///< "none", "wizard", "peak 0.5 zp", "peak 0.5 w", "band 0.5 x1.5"
    std::string rule; ///< how its notches were sized
    std::vector<tuning::ProposedNotch> notches;
};

/// Every design above, in the order of the list (none first). A notch width is clamped to min(f_r, 2 (f_N - f_r)),
/// f_N the execution Nyquist frequency; a resonance at or above f_N is not notched.
std::vector<NotchDesign> movingResonanceNotchDesigns(const std::vector<PositionResonances>& positions,
                                                     double execRateHz);

} // namespace axistune::autotune::detail
