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
/// P = L/C_d in place, C_d(z) = K_P + K_I·T_v/(1 − z⁻¹) of the running discrete PI, z = e^{jωT_v}; lines that are
/// invalid or where C_d = 0 become invalid (h = 0).
void divideByVelocityPi(dsp::FrequencyResponse& openLoop, const VelocityPi& pi, double velocityPeriodS);

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

struct MeasuredLoadError {
    std::vector<double> tS;     ///< from the first sample (0)
    std::vector<double> error;  ///< y_L − y* minus its value at the first sample
    double maxAbs = 0.0;
};

/// The load error y_L − y* of a traced move. A drive renews its position command once per position
/// period and a trace sample between two renewals holds the old command while the load moves on, so
/// only samples where the command is fresh are used: where it differs from the previous sample, or
/// where it has not changed for `standstillSamples` samples on both sides (at rest). Empty on
/// mismatched or too short inputs.
MeasuredLoadError measuredLoadError(std::span<const double> tS, std::span<const double> command,
                                    std::span<const double> load, int standstillSamples = 16);

/// Duration of one rest-to-rest ramp (0 → v_max or back) of the S-curve of `profile`: 2·t_j + t_a.
double sCurveRampS(const MotionProfile& profile);

}  // namespace axistune::tuning
