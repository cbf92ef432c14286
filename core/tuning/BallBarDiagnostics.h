// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Ball-bar diagnostics (docs/ballbar.md): least-squares centre and radius, circularity, per-axis
// reversal steps (backlash / lost motion) and reversal spikes, scale mismatch, squareness separated
// from servo mismatch (CW + CCW), cyclic error. All values SI; every finding carries the rule that
// decided it.
//
// Conventions (first-order geometry, derived in docs/ballbar.md):
//   θ  geometric angle of the bar, CCW from +X;  σ = +1 CCW, −1 CW;  R nominal radius;  v feed.
//   Δr(θ) = r0 + a cosθ + b sinθ                    radius deviation r0, centre offset (a, b)
//         + R(εx−εy)/2 · cos2θ                       scale mismatch εx − εy (X longer → positive)
//         + (γR/2 + σ v Δτ/2) · sin2θ                squareness γ (angle X–Y below 90° → positive),
//                                                    servo mismatch Δτ = τx − τy (X lags → positive)
//         + Σ_axes L_a · lm_a(θ)                     lost motion L_a (outward step at reversal → positive)
//   with lm_x = −½ sgn(ẋ) cosθ, lm_y = −½ sgn(ẏ) sinθ,  sgn(ẋ) = −σ sgn(sinθ), sgn(ẏ) = σ sgn(cosθ).

#include "core/io/BallBarCsv.h"
#include "core/model/Result.h"

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace axistune::tuning {

/// Smallest reversal step reported as a backlash and smallest reversal spike [m].
inline constexpr double kMinBacklashM = 0.3e-6;
inline constexpr double kMinSpikeM = 0.3e-6;

struct BallBarOptions {
    double excludeDeg = 4.0;    ///< half-window around a reversal left out of the smooth fits (spike zone)
    double fitWindowDeg = 20.0; ///< width of each side window of the local step fit, beyond excludeDeg
    double maxGapDeg = 5.0;     ///< largest angular gap a "full circle" may have
};

/// One reversal of one axis in one run (LM-1 of spec §4.3).
struct ReversalEvent {
    int axis = 0;             ///< 0 = first plane axis ("x"), 1 = second ("y")
    double angleRad = 0.0;    ///< reversal angle: x at 0 / π, y at π/2 / 3π/2
    double tableCoordM = 0.0; ///< axis coordinate of the event: centre ± R
    double stepM = 0.0;       ///< radial step across the reversal (lost motion; outward positive)
    double stepStdErrM = 0.0;
    double noiseRmsM = 0.0;       ///< rms residual of the local fit windows
    std::array<double, 4> poly{}; ///< local smooth part c0 + c1·d + c2·d² + c3·d³ (d = travel angle from reversal, rad)
    bool spike = false;           ///< a spike above the detection rule was found
    /// signed peak of the spike in the spike zone (outward positive): the residual against the step's
    /// monotonic transition from the level before the reversal to the level after it (docs/ballbar.md)
    double spikeHeightM = 0.0;
    double spikeAngleRad = 0.0; ///< angle of the peak
    double spikeWidthRad = 0.0; ///< full width at half height
};

struct CyclicFit {
    double amplitudeM = 0.0;
    double pitchM = 0.0;
    bool detected = false;
    double thresholdM = 0.0; ///< amplitude that noise alone exceeds with probability ≈ 1e-3
};

/// Diagnostics of one trace.
struct RunDiagnostics {
    std::string source;
    double sigma = 1.0; ///< +1 CCW, −1 CW
    double radiusM = 0.0;
    double feedMPerS = 0.0;
    std::vector<ReversalEvent> events; ///< every reversal whose windows the trace covers
    bool fullCircle = false;
    std::string refusal; ///< why the full-circle diagnostics were refused (empty when fullCircle)
    std::vector<std::string> refusalArgs; ///< arguments of the "full_circle" refusal key (see RuleText)
    // Full-circle diagnostics (valid when fullCircle):
    double radiusDeviationM = 0.0;
    double centerXM = 0.0; ///< machine circle centre relative to the ball-bar pivot
    double centerYM = 0.0;
    double circularityM = 0.0;           ///< max − min after removing the least-squares circle
    double cos2M = 0.0;                  ///< cos2θ coefficient
    double sin2M = 0.0;                  ///< sin2θ coefficient
    std::array<double, 2> lostMotionM{}; ///< global lost-motion amplitudes per axis (joint fit)
    double residualRmsM = 0.0;
    std::array<CyclicFit, 2> cyclic{};
};

/// Full-circle check: angular coverage with no gap above maxGapDeg. Error text names the coverage.
Status requireFullCircle(const io::BallBarTrace& trace, const BallBarOptions& opt, const std::string& what);

/// Step and spike at one reversal (needs only the two side windows to be covered).
Result<ReversalEvent> fitReversal(const io::BallBarTrace& trace, int axis, double reversalAngleRad,
                                  const BallBarOptions& opt);

/// All diagnostics of one trace; full-circle ones are left out with `refusal` set on partial arcs.
Result<RunDiagnostics> analyzeRun(const io::BallBarTrace& trace, const BallBarOptions& opt = {});

/// Radial circularity (max − min) of a deviation trace after removing its least-squares circle.
Result<double> circularityOf(std::span<const double> angleRad, std::span<const double> deviationM);

/// Lost-motion basis lm_a(θ) for travel direction σ (see the header comment).
double lostMotionBasis(int axis, double thetaRad, double sigma);

/// The rule behind a finding or a refusal as a stable key with its arguments (numbers already formatted
/// with '.' decimals), so a user interface can word it in its own language; `text` is the English wording.
/// Keys and argument order are listed in docs/ballbar.md "Rule keys".
struct RuleText {
    std::string id;
    std::vector<std::string> args;
    std::string text;
};

struct Finding {
    std::string name;
    double value = 0.0;
    std::string unit; ///< display unit of `value`
    std::string rule; ///< the rule that decided it, for people (English)
    std::string ruleId;                ///< key of `rule` (RuleText::id)
    std::vector<std::string> ruleArgs; ///< arguments of `rule` (RuleText::args)
};

struct ReversalSpike {
    int axis = 0;
    double angleRad = 0.0;
    double heightM = 0.0;
    double widthRad = 0.0;
    std::string source;
};

/// Combined diagnostics over one or more runs (CW and CCW separate squareness from servo mismatch).
struct BallBarReport {
    std::vector<RunDiagnostics> runs;
    std::optional<double> circularityM;
    std::optional<double> centerXM, centerYM;
    std::optional<double> radiusDeviationM;
    std::array<std::optional<double>, 2> backlashM;
    /// A backlash (reversal step) is reported when |backlashM| > backlashThresholdM (4× its standard error,
    /// at least kMinBacklashM); otherwise the step is noise or the tail of a spike.
    std::array<bool, 2> backlashDetected{};
    std::array<double, 2> backlashThresholdM{};
    std::vector<ReversalSpike> spikes;
    std::optional<double> scaleMismatch;  ///< εx − εy (ratio)
    std::optional<double> squarenessRad;  ///< γ
    std::optional<double> servoMismatchS; ///< τx − τy
    std::array<std::optional<CyclicFit>, 2> cyclic;
    std::vector<Finding> findings;
    std::vector<RuleText> refused; ///< diagnostics that could not be computed, with the reason
};

Result<BallBarReport> analyzeBallBar(std::span<const io::BallBarTrace> traces, const BallBarOptions& opt = {});

} // namespace axistune::tuning
