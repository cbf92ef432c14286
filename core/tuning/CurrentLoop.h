// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// q-axis current-loop design with a PI ratio α (spec/current-loop-and-multisweep-frf.md chapter 2):
//   v* = k_i ∫(i* − i) dt + k_p (α i* − i),   plant e^{−τs} / (L_q s + R_a).
// Four constraints: dead-time stability with a gain margin (2.3)–(2.5), no voltage saturation for a
// sinusoidal ripple of r_I·I_max at any frequency (envelope 2.10, τ = 0), step overshoot ≤ OS_max
// (2.14)–(2.15, delay-free), and the magnetic-saturation gain schedule (2.16). The optimum per α
// minimises the 10–90 % rise time of the delay-free closed loop; α* minimises over α.
// Only the ratio V_max / I_q enters the voltage constraint: max current and max voltage must use the
// same convention (both rms or both peak).

#include "core/model/Result.h"

#include <string>
#include <vector>

namespace axistune::tuning {

struct MotorData {
    double resistanceOhm = 0.0;        ///< R_a per phase
    double inductanceQH = 0.0;         ///< nominal L_q
    double maxCurrentA = 0.0;          ///< I_max (same convention as maxVoltageV)
    double maxVoltageV = 0.0;          ///< V_max
    double inductanceDropAtMax = 0.0;  ///< δ = 1 − L_q(I_max)/L_q,nom, 0 ≤ δ < 1
    double ratedCurrentA = 0.0;        ///< optional (0 = not given)
    int polePairs = 0;                 ///< optional (0 = not given)
    double backEmfVPerKrpm = 0.0;      ///< optional line-to-line V(rms) per 1000 min⁻¹ (0 = not given)
    double contouringSpeedRpm = 300.0; ///< speed for the back-EMF check (chapter 2: 300 min⁻¹)
};

/// Parses motor JSON text (keys in docs/tuning.md). `source` names the file in error messages.
/// Checks: required keys present and numeric, R ≥ 0, L > 0, I_max > 0, V_max > 0, 0 ≤ δ < 1, and, if a
/// back-EMF constant is given, V_max above the back-EMF at the contouring speed.
Result<MotorData> parseMotorJson(const std::string& text, const std::string& source);
Result<MotorData> readMotorJsonFile(const std::string& path);
/// Checks a MotorData value (the same checks as the parser).
Status validateMotor(const MotorData& motor, const std::string& source);
/// Back-EMF [V] at `speedRpm` from a constant in V per 1000 min⁻¹ (check C-A1).
double backEmfV(double backEmfVPerKrpm, double speedRpm);

/// 20·log10(√2): the paper's "3 dB" gain margin, |G| < 1/√2 (2.3).
inline constexpr double kPaperGainMarginDb = 3.0102999566398120;

struct CurrentLoopSettings {
    double deadTimeS = 62.5e-6;      ///< τ (paper: the current-control period)
    /// |G(jω_pc)| < 10^(−GM/20). The paper's "3 dB" is the factor √2 (|G| < 1/√2), i.e. 3.0103 dB.
    double gainMarginDb = kPaperGainMarginDb;
    double overshootMax = 0.10;      ///< step overshoot limit (fraction)
    double rippleFraction = 0.05;    ///< I_q / I_max of the voltage constraint (paper 1/20)
    double alphaStep = 0.1;          ///< α grid 0, step, …, 1
};

Status validateSettings(const CurrentLoopSettings& s);

struct PiGains {
    double kiVPerAs = 0.0;
    double kpVPerA = 0.0;
};

// ---- individual constraints (usable for plots and tests) ----

/// Smallest phase-crossover frequency [rad/s] of G(s) = (k_p s + k_i)/(L s² + R s)·e^{−τs}, robust
/// phase formula of §2.4; negative when none is found.
double phaseCrossoverRadS(const MotorData& m, double deadTimeS, PiGains g);
/// |G(jω)| of the open loop.
double openLoopMagnitude(const MotorData& m, PiGains g, double omegaRadS);
/// Dead-time stability with gain margin: |G(jω_pc)| < 10^(−GM/20) at the smallest phase crossover.
bool isStableWithMargin(const MotorData& m, double deadTimeS, double gainMarginDb, PiGains g);
/// Largest k_p for k_i → 0⁺ that keeps the margin.
double maxStableKp(const MotorData& m, double deadTimeS, double gainMarginDb);
/// Largest stable k_i for a given k_p (0 when k_p ≥ maxStableKp); region assumed k_i ∈ (0, k_i,max].
double maxStableKi(const MotorData& m, double deadTimeS, double gainMarginDb, double kp);

/// No saturation at any frequency (τ = 0): a ≥ 0 and (b ≥ 0 or b² ≤ 4ac), §2.5.
/// `currentPerVolt` = I_q / V_max.
bool isVoltageOk(const MotorData& m, double alpha, double currentPerVolt, PiGains g);
/// Largest k_i with isVoltageOk for a given k_p and α (0 when none).
double maxVoltageKi(const MotorData& m, double alpha, double currentPerVolt, double kp, double kiUpper);

/// Region type of (2.9) at ripple frequency ω_q (Fig. 2.6, Appendix C).
enum class VoltageRegion { OutsideEllipse, LeftOfParabola, InsideHyperbola, AboveParabola, InsideEllipse };
VoltageRegion voltageRegionAt(const MotorData& m, double alpha, double currentPerVolt, double omegaQRadS);
/// ω_q where S = 0, i.e. V_max/(I_q L_q).
double omegaSZero(const MotorData& m, double currentPerVolt);
/// ω_q where T = 0, i.e. V_max/(α I_q L_q); +inf for α = 0.
double omegaTZero(const MotorData& m, double alpha, double currentPerVolt);

/// Peak step overshoot (fraction, ≥ 0) of (α k_p s + k_i)/(L s² + (R + k_p)s + k_i), (2.14)–(2.15).
double stepOvershoot(const MotorData& m, double alpha, PiGains g);
/// k_i where the overshoot reaches `overshootMax` for a given k_p (bisection; overshoot grows with k_i).
double overshootBoundaryKi(const MotorData& m, double alpha, double overshootMax, double kp, double kiUpper);

/// Delay-free closed-loop step response at time t [s] (analytic).
double delayFreeStep(const MotorData& m, double alpha, PiGains g, double tS);
/// 10–90 % rise time [s] of the delay-free closed loop; negative if 90 % is never reached.
double riseTime1090(const MotorData& m, double alpha, PiGains g);

/// Gain factor (I_max − δ|i|)/I_max of (2.16).
double scheduleFactor(const MotorData& m, double currentA);

// ---- the design ----

struct AlphaOptimum {
    double alpha = 0.0;
    PiGains gains;
    double riseTimeS = 0.0;
    double overshoot = 0.0;
    std::vector<std::string> activeConstraints;  ///< "stability", "voltage", "overshoot"
    bool feasible = false;
};

struct SchedulePoint {
    double currentA = 0.0;
    double factor = 1.0;
    PiGains gains;
};

struct CurrentLoopDesign {
    double alpha = 0.0;
    PiGains gains;
    double riseTimeS = 0.0;
    std::vector<AlphaOptimum> table;
    std::vector<SchedulePoint> schedule;
};

/// The optimum for one α (grid search over the stability region, then local refinement).
AlphaOptimum optimiseAlpha(const MotorData& m, const CurrentLoopSettings& s, double alpha);
/// The sweep over α, the optimum and the schedule at 0, 0.1, …, 1.0 × I_max (plus rated current).
Result<CurrentLoopDesign> designCurrentLoop(const MotorData& m, const CurrentLoopSettings& s);

// ---- plot data ----

struct BoundaryCurve {
    std::vector<double> kpVPerA;
    std::vector<double> kiVPerAs;  ///< largest admissible k_i at each k_p (0 where none)
};

/// Dead-time stability boundary k_i,max(k_p) on `points` k_p values in (0, k_p,max).
BoundaryCurve stabilityBoundary(const MotorData& m, const CurrentLoopSettings& s, int points);
/// Voltage envelope for one α on the same k_p range.
BoundaryCurve voltageEnvelope(const MotorData& m, const CurrentLoopSettings& s, double alpha, int points);
/// Overshoot = OS_max curve for one α.
BoundaryCurve overshootCurve(const MotorData& m, const CurrentLoopSettings& s, double alpha, int points);

struct StepResponse {
    std::vector<double> timeS;
    std::vector<double> delayFree;  ///< continuous, τ = 0 (the design model)
    std::vector<double> discrete;   ///< ZOH at the current period plus dead time τ
};

/// Normalised step responses (command 1) at the current period `periodS` over `durationS`.
StepResponse stepResponses(const MotorData& m, double alpha, PiGains g, double deadTimeS, double periodS,
                           double durationS);

}  // namespace axistune::tuning
