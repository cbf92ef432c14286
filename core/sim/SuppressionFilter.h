// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The drive-side runtime of the two-inertia vibration-suppression filters
// (spec/lost-motion-and-two-inertia.md §2.5–2.6, TI-3 §4.10, TI-4 §4.11), run at the position-loop
// period T:
//   F_m (semi-closed, suppression.mode 1) shapes the position command:
//       y_m* = y* + q/ω₀²,  v_m* = v* + q'/ω₀²,  q = LPF_{T₁}(a*),  T₁ = 2ζ/ω₀
//     (the decomposition F_m = 1 + (s²/ω₀²)/(1 + T₁s) of (5.7)); the lag is discretised
//     ramp-invariant (first-order hold on a*, exact for the piecewise-linear acceleration of a
//     rectangular-jerk profile), q' is the lag's derivative at the sample.
//   F_L (full-closed, suppression.mode 2) filters the load velocity command K_p(y* − y_L) + v*:
//       F_L(s) = (s² + 2ζω₀s + ω₀²)/((2ζω₀s + ω₀²)(τs + 1))      (5.9)
//     discretised by the Tustin transform without pre-warping (the spec's check values of §4.11).
// docs/simulator.md "Vibration-suppression filters" has the equations and the parameter rules.

#include "core/dsp/DigitalFilter.h"
#include "core/model/Result.h"
#include "core/sim/MotionProfile.h"

namespace axistune::sim {

enum class SuppressionFilterMode { Off = 0, SemiClosedFm = 1, FullClosedFl = 2 };

struct SuppressionSettings {
    SuppressionFilterMode mode = SuppressionFilterMode::Off;
    double f0Hz = 0.0;
    double zeta = 0.0;
    double tauS = 0.0;  ///< F_L only
};

/// Largest high-frequency gain 1/(2ζω₀τ) of F_L the drive accepts (+20 dB; the thesis's hand-tuned
/// 17 Hz / 0.14 / 13 ms has 2.57): above it the filter mostly amplifies encoder noise.
constexpr double kMaxFlHighFrequencyGain = 10.0;

/// Checks the settings against the feedback mode and the position-loop period. The messages name the
/// parameters (suppression.mode, position.feedback, suppression.f0, .zeta, .tau, position.period).
Status checkSuppressionSettings(const SuppressionSettings& s, bool fullClosed, double positionPeriodS);

/// F_L (5.9) by Tustin at period T (no pre-warping). BadInput for f₀ ≤ 0, ζ ≤ 0, τ ≤ 0 or T ≤ 0.
Result<dsp::Biquad> designFlTustin(double f0Hz, double zeta, double tauS, double periodS);

/// F_m on a command stream sampled every T (TI-3). Off (a pass-through) until configured.
class FmCommandShaper {
public:
    /// f₀ > 0, ζ ≥ 0 (ζ = 0: T₁ = 0, y_m* = y* + a*/ω₀² exactly, (5.8)), T > 0.
    Status configure(double f0Hz, double zeta, double periodS);
    void reset();
    /// y_m*, v_m* from y*, v*, a* at one sample; the acceleration is passed through unchanged.
    MotionState process(const MotionState& command);
    /// The lag's output q [axis units/s²] after the last sample (y_m* − y* = q/ω₀²).
    double lagOutput() const { return m_q; }

private:
    double m_w0sq = 0.0, m_t1 = 0.0, m_lambda = 0.0, m_period = 0.0;
    double m_q = 0.0, m_prevA = 0.0;
    bool m_on = false;
};

}  // namespace axistune::sim
