// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the two-inertia wizard needs beside the fit (spec/lost-motion-and-two-inertia.md §2.5, §4.8,
// §4.10, §4.13; docs/tuning.md "Two-inertia fit on the simulated drive's closed-loop FRF"):
//   * the plant P (torque → motor velocity) from a drive's closed velocity-loop FRF T = PC/(1+PC),
//     with the injection-hold correction when the drive did not apply it;
//   * the load error over time for an S-curve profile, with and without F_m (the maxima are
//     predictLoadError's);
//   * the load position predicted from a measured motor position and velocity through (5.6), to
//     compare with a measured load position.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"
#include "core/tuning/TwoInertia.h"
#include "core/tuning/TwoInertiaFilter.h"
#include "core/tuning/VelocityLoop.h"

#include <span>
#include <vector>

namespace axistune::tuning {

/// P = L/C with L = T/(1−T) and the drive's discrete PI C(z) = K_P + K_I·T_v/(1 − z⁻¹), z = e^{jωT_v}.
/// Unless the FRF's metadata says injection_hold_corrected=true, T is first divided by the hold factor
/// G = N/Σ_{m<N} e^{−jωmh}, N = T_v/h (dsp/InjectionHold.h). Points with T = 1 or C = 0 become invalid.
/// BadInput: metadata measurement other than "complementary", gains negative or both 0, T_v ≤ 0,
/// T_v not an integer multiple of h.
Result<dsp::FrequencyResponse> plantFromVelocityLoop(const dsp::FrequencyResponse& closedLoop, const VelocityPi& pi,
                                                     double velocityPeriodS, double currentPeriodS);

struct LoadErrorTraces {
    std::vector<double> tS;
    std::vector<double> accelCmd;       ///< commanded acceleration a* [rad/s² or m/s²]
    std::vector<double> withoutFilter;  ///< y_L − y* with y_m = y*
    std::vector<double> withFilter;     ///< y_L − y* with y_m = F_m y*
};

/// The load error of predictLoadError over time, sampled every `sampleS` (> 0), for the plot.
LoadErrorTraces loadErrorTraces(const TwoInertiaParams& p, const SuppressionFilter& f, const MotionProfile& profile,
                                double sampleS);

/// Load position through (5.6) driven by a measured motor position y_m and velocity v_m sampled at tS
/// (starting at rest: y_L = y_m, y_L' = v_m at the first sample); linear interpolation between
/// samples, RK4 with steps ≤ 1/200 of the anti-resonance period. Empty on mismatched lengths.
std::vector<double> predictLoadFromMotor(const TwoInertiaParams& p, std::span<const double> tS,
                                         std::span<const double> motorPos, std::span<const double> motorVel);

}  // namespace axistune::tuning
