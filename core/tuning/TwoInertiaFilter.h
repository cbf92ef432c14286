// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Vibration-suppression filters of the two-inertia method (spec/lost-motion-and-two-inertia.md
// §2.5–2.6, algorithms TI-2..TI-4, TI-6):
//   F_m(s) = (s² + 2ζω_0 s + ω_0²)/(2ζω_0 s + ω_0²)          semi-closed, on the NC position command
//   F_L(s) = F_m(s)/(τ s + 1)                               full-closed, on the velocity command
// and the load error predicted for an S-curve acceleration profile with and without F_m.

#include "core/tuning/TwoInertia.h"

#include <complex>

namespace axistune::tuning {

enum class SuppressionMode { Semi, Full };

struct SuppressionFilter {
    SuppressionMode mode = SuppressionMode::Semi;
    double f0Hz = 0.0;
    double zeta = 0.0;
    double tauS = 0.0;  ///< F_L only (0 for F_m)
};

/// Model-derived start values (TI-2): f_0 = ω_0/2π, ζ = ζ_0 (zero damping, not ζ_p). For F_L a
/// τ ≤ 0 selects the default rule [ANALYST]: high-frequency gain 1/(2ζω_0τ) = 2.5 (the thesis's
/// hand-tuned 17 Hz/0.14/13 ms has 2.57).
SuppressionFilter suppressionFilterFromModel(const TwoInertiaParams& p, SuppressionMode mode, double tauS);

/// F_m or F_L at f [Hz].
std::complex<double> suppressionFilterResponse(const SuppressionFilter& f, double fHz);

/// Rest-to-rest S-curve (TI-6): accelerate with constant jerk to a_max, hold, reduce to reach v_max,
/// cruise, decelerate symmetrically. Angles in rad (or m).
struct MotionProfile {
    double vMax = 62.83;       ///< 10 rev/s
    double aMax = 1256.6;      ///< 200 rev/s²
    double jerk = 125660.0;    ///< 20 000 rev/s³ (not given in the thesis; a parameter)
    double cruiseS = 0.2;      ///< time at v_max
    double settleS = 0.5;      ///< time simulated after the end of the move
};

struct LoadErrorPrediction {
    double maxErrorWithoutFilter = 0.0;  ///< max |y_L − y*| with y_m = y* (ideal motor tracking)
    double maxErrorWithFilter = 0.0;     ///< max |y_L − y*| with y_m = F_m y*
};

/// Load error of the semi-closed axis under ideal motor tracking (y_L = (5.6)·y_m), with y_m = y*
/// and with y_m = F_m y* (the filter's own f_0/ζ, which may differ from the model's).
LoadErrorPrediction predictLoadError(const TwoInertiaParams& p, const SuppressionFilter& f, const MotionProfile& profile);

}  // namespace axistune::tuning
