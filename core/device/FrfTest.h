// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The frequency-response test of a drive (spec/current-loop-and-multisweep-frf.md §3.2, §3.5, §4.3):
// a torque disturbance d is added to the velocity-controller output inside the closed velocity loop
// (at the current-loop rate), the velocity-controller output T_c and the motor velocity are traced at
// the trace rate, and the FRF is the closed loop T = PC/(1+PC) (eq. 3.1 with ω* = 0): −T_c/d divided
// by the injection-hold factor G of dsp::injectionHoldFactor (d changes every current tick, T_c is held
// over the velocity period), metadata injection_hold_corrected=true; docs/frequency-response-sim.md.
//
// Sine streams are planned with a *continuous* excitation per frequency: one settle time, then three
// windows of M samples each spanning p + 1/3 periods (f = (p + 1/3)·fs/M exactly), so that the
// windows see the phase offsets 0, +120° and +240° ≡ −120° of one uninterrupted sine — the three
// sweeps of the multi-sweep method without a settle between them. The conventional method uses one
// window of p whole periods (f = p·fs/M). Settle time and minimum window come from the velocity
// loop's own dynamics (the slowest closed-loop time constant of the drive's PI and inertia setting);
// see docs/frequency-response-sim.md.

#include "core/device/Drive.h"
#include "core/dsp/FrequencyResponse.h"
#include "core/dsp/SineDemodulation.h"
#include "core/model/Capture.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace axistune::device {

/// Timing derived from the velocity loop's own dynamics.
struct LoopTiming {
    double timeConstantS = 0.0;  ///< slowest closed-loop time constant of J s² + k_p s + k_i
    double settleS = 0.0;        ///< settle time after each frequency change ...
    double settlePeriods = 0.0;  ///< ... and at least this many periods of the new frequency
    double maxSettleS = 0.5;     ///< cap of the period rule
    double minMeasureS = 0.0;    ///< minimum measured time per frequency (all windows together)
};

/// Slowest time constant 1/|Re s| of the rigid velocity loop J s² + k_p s + k_i = 0 (J = velocity.inertia),
/// settle = max(settleTimeConstants · τ, settlePeriods / f) (the period rule covers lightly damped
/// mechanical modes the PI setting does not show, capped at maxSettleS), minimum measured time =
/// measureTimeConstants · τ.
/// Errors when the drive's inertia setting or k_p is not positive.
Result<LoopTiming> loopTimingFromParameters(const model::ParameterValues& values, double settleTimeConstants = 5.0,
                                            double measureTimeConstants = 2.0, double settlePeriods = 8.0);

/// One window (k ≥ 0) of one frequency at one phase offset, with its settle samples before it.
struct FrfSegment {
    double freqHz = 0.0;
    double phaseOffsetDeg = 0.0;
    std::int64_t windowStart = 0;  ///< trace sample index of k = 0
    std::size_t settleSamples = 0; ///< samples before windowStart that belong to this segment
    std::size_t measureSamples = 0;
};

struct FrfPlan {
    FrfMethod method = FrfMethod::MultiSweep;
    double fsHz = 0.0;          ///< trace rate
    double amplitudeNm = 0.0;
    std::vector<FrfSegment> segments;  ///< sine streams, in time order
    std::vector<double> prbs;          ///< PRBS: one value per trace sample (after prbsStart)
    std::int64_t prbsStart = 0;        ///< PRBS: first sample of the analysed record (after settling)
    std::size_t nperseg = 0;           ///< PRBS: Welch segment length
    std::size_t totalSamples = 0;
    LoopTiming timing;
    double voltageLimitV = 0.0;  ///< points whose traced voltage reaches it are marked invalid (0: no check)
    double fminHz = 0.0, fmaxHz = 0.0;  ///< requested range (PRBS output is thinned to it)
    int points = 0;
    /// Current-loop period h (the injection's tick) and velocity-loop period (T_c's hold) for the
    /// injection-hold correction; 0: taken from the trace metadata current_period_s, velocity_period_s.
    double currentPeriodS = 0.0;
    double velocityPeriodS = 0.0;
    double durationS() const { return static_cast<double>(totalSamples) / fsHz; }
};

struct FrfPlanOptions {
    FrfMethod method = FrfMethod::MultiSweep;
    double fsHz = 4000.0;
    double fminHz = 10.0;
    double fmaxHz = 3900.0;
    int points = 60;
    double amplitudeNm = 0.0;
    LoopTiming timing;
    double voltageLimitV = 0.0;
};

/// Frequencies log-spaced from fmin to fmax (points ≥ 2, or one point when fmin = fmax), each moved
/// to the shortest window of the grid within 0.1 % of it (else the nearest within three times the
/// minimum window; up to about 1 % for short windows when f/fs is a simple fraction).
/// Errors name the option: fmin ≤ 0, fmax < fmin, fmax ≥ fs (multi-sweep) or ≥ fs/2 (PRBS), points < 1.
Result<FrfPlan> planFrfTest(const FrfPlanOptions& options);

/// The excitation at a (fractional) trace-sample position s (current-loop ticks between samples).
/// Zero outside the plan.
double frfExcitation(const FrfPlan& plan, double s);

/// The FRF of plan's excitation x and response y, both one value per trace sample (x[i], y[i] at sample i of the
/// plan): sine streams by dsp::sineStreamFrf on the plan's windows (the sweep recording names x and y with
/// excitationName and responseName), PRBS by Welch H1 over the record after prbsStart, thinned to the plan's points.
/// No hold correction and no drive metadata: the core of evaluateFrfTrace, shared with hal: (HalDrive.h), which
/// evaluates the plant and the open loop from its servo-rate record.
Result<FrfMeasurement> evaluateFrfSignals(const FrfPlan& plan, std::span<const double> x, std::span<const double> y,
                                          const std::string& excitationName, const std::string& responseName);

/// The sine-stream recording of a completed trace (channels injection_Nm and torque_cmd_Nm, the
/// response is −torque_cmd_Nm), and the FRF: sine streams by dsp::sineStreamFrf, PRBS by Welch H1.
/// The FRF is corrected for the injection hold (metadata injection_hold_corrected=true): sine streams
/// (d sampled every current tick h, T_c held N = velocity/current ticks) are divided by
/// dsp::injectionHoldFactor(f, h, N); PRBS (d held over one trace sample of D velocity periods) is
/// multiplied by dsp::injectionHoldFactor(f, T_v, D), i.e. left as it is for D = 1. The sweep recording
/// keeps the raw −T_c and d and carries injection_hold_period_s / injection_hold_ticks for a re-analysis.
/// BadInput when the periods are neither in the plan nor in the trace metadata, or not in integer ratio.
Result<FrfMeasurement> evaluateFrfTrace(const FrfPlan& plan, const model::Capture& trace);

}  // namespace axistune::device
