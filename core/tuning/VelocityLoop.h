// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Velocity PI and position P design (spec/lost-motion-and-two-inertia.md §2.8, TI-5 §4.12, §4.11):
//  * from a fitted inertia, chapter 5 rule in its corrected form (5.13 lost a k on the integral term):
//      K_v(s) = k J_m (√2 ω_l s + ω_l²)/s  →  K_P = k√2·ω_l·J_m,  K_I = k·ω_l²·J_m;
//  * from margins on a measured plant FRF: |C P| = 1 and arg(C P) = −180° + PM at the crossover;
//  * the position gain with the stability limit of the fitted two-inertia model (semi: y = y_m,
//    full: y = y_L), optionally with F_L in the loop.
// Velocity PI: C(s) = K_P + K_I/s, torque command in N·m per rad/s.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"
#include "core/tuning/TwoInertia.h"
#include "core/tuning/TwoInertiaFilter.h"

#include <complex>
#include <optional>
#include <vector>

namespace axistune::tuning {

struct VelocityPi {
    double kpNmsPerRad = 0.0;  ///< K_P [N·m/(rad/s)]
    double kiNmPerRad = 0.0;   ///< K_I [N·m/rad]
};

/// Corrected (5.13). ω_l [rad/s] is the closed-loop bandwidth for k = 1 (thesis: 2π·24, k = 10).
VelocityPi velocityPiFromInertia(double jmKgm2, double omegaLRadS, double k);
/// C(j2πf).
std::complex<double> piResponse(const VelocityPi& pi, double fHz);

struct LoopMargins {
    double crossoverHz = 0.0;       ///< highest gain crossover |L| = 1 (0 if none)
    double phaseMarginDeg = 0.0;    ///< at that crossover
    double gainMarginDb = 0.0;      ///< smallest over the −180° crossings (+inf if none)
    double phaseCrossoverHz = 0.0;  ///< where the gain margin is read (0 if none)
    double peakSensitivityDb = 0.0; ///< max |1/(1 + L)|
};

/// Margins of an open loop sampled at increasing frequencies (interpolated between samples).
LoopMargins loopMargins(const std::vector<double>& freqHz, const std::vector<std::complex<double>>& openLoop);

/// PI from a measured torque → velocity FRF: crossover at `crossoverHz` with `phaseMarginDeg`.
/// OutOfRange when the PI cannot provide the needed phase (it only lags, 0 … −90°).
Result<VelocityPi> velocityPiFromFrf(const dsp::FrequencyResponse& plant, double crossoverHz, double phaseMarginDeg);

enum class FeedbackMode { Semi, Full };

struct PositionGainDesign {
    double limitPerS = 0.0;        ///< stability limit of K_p (+inf if none below 1e5 s⁻¹)
    double limitFrequencyHz = 0.0; ///< phase crossing that sets the limit
    double recommendedPerS = 0.0;  ///< min(limit·10^(−GM/20), ω_c,vel/5) [ANALYST rule]
};

/// Position-loop gain limit on the fitted model with the velocity PI, delay included only when
/// `includeDelay` (the thesis's 1.1 ms is a measurement delay, §2.7). `filter` puts F_L in the
/// full-closed loop.
PositionGainDesign positionGain(const TwoInertiaParams& p, const VelocityPi& pi, FeedbackMode mode,
                                const std::optional<SuppressionFilter>& filter, bool includeDelay,
                                double gainMarginDb);

}  // namespace axistune::tuning
