// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The headless velocity/position-loop design (issue 18 item 1; docs/tuning.md "Velocity loop"): every rule the
// velocity-loop wizard, the two-inertia wizard and `axistune-cli velocity-loop` apply, in one place:
//  * what a measured FRF is (`measurement` metadata: one parser for every caller);
//  * the torque → motor-velocity plant of a measurement (closed loop → plant with the running PI);
//  * the proposal: chapter 5 rule on J_m (spec/lost-motion-and-two-inertia.md §2.8, corrected 5.13) or
//    margins on the measured plant (TI-5 §4.12), with the sentence of the rule that chose it;
//  * the predicted open and closed loop with the margins before and after, the position gain with its
//    stability limit (§4.11), and the velocity step before and after on the model;
//  * the motor data the drive's parameters give (back-EMF constant k_e = k_t/1.5, amplitude-invariant dq).
// No Qt: the wizard pages only display this and collect the choices.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Capture.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"
#include "core/tuning/CurrentLoop.h"
#include "core/tuning/Notch.h"
#include "core/tuning/TwoInertia.h"
#include "core/tuning/TwoInertiaFilter.h"
#include "core/tuning/VelocityLoop.h"
#include "core/tuning/VelocityStep.h"

#include <complex>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace axistune::tuning {

/// The thesis's velocity-loop policy (spec §2.8): ω_l = 2π·24 rad/s for k = 1, static gain k = 10.
inline constexpr double kDefaultVelocityBandwidthHz = 24.0;
inline constexpr double kDefaultVelocityGainFactor = 10.0;
/// Gain margin kept below the position gain's stability limit (TI-5 §4.11, the ANALYST rule of positionGain).
inline constexpr double kPositionGainMarginDb = 6.0;
/// The loop's own delay on the model: sample and hold of the velocity loop, 1.5 periods.
inline constexpr double kVelocityLoopDelayPeriods = 1.5;

// ---------------------------------------------------------------------------------------------
// What a measured FRF is

enum class LoopMeasurementKind {
    Plant,            ///< torque → motor velocity P itself
    Open,             ///< the open loop L = C·P
    Complementary,    ///< T = L/(1 + L) (the drives' torque-injection FRF)
    NegComplementary, ///< −T
    Sensitivity,      ///< S = 1/(1 + L)
};

/// The names as they appear in the `measurement` key of an FRF CSV: plant, open, complementary,
/// neg-complementary, sensitivity.
std::string_view loopMeasurementName(LoopMeasurementKind kind);
/// BadInput naming the value and the accepted names when `name` is none of them.
Result<LoopMeasurementKind> parseLoopMeasurement(std::string_view name);
/// The FRF's `measurement` key; `absent` when it has none. BadInput for an unknown value.
Result<LoopMeasurementKind> loopMeasurementOf(const dsp::FrequencyResponse& frf, LoopMeasurementKind absent);
/// The notch analysis's form (Notch.h) of a closed or open loop measurement; BadInput for Plant.
Result<LoopForm> loopFormOf(LoopMeasurementKind kind);

/// The torque → motor-velocity plant of a measurement. Plant: a copy. Complementary: plantFromVelocityLoop (the
/// injection-hold correction when the file does not say it is corrected). Open, NegComplementary, Sensitivity:
/// the open loop L, then P = L/C(z) of the running PI. Lines where C = 0 are invalid.
Result<dsp::FrequencyResponse> plantFromMeasurement(const dsp::FrequencyResponse& measured, LoopMeasurementKind kind,
                                                    const VelocityPi& running, double velocityPeriodS,
                                                    double currentPeriodS);

// ---------------------------------------------------------------------------------------------
// The velocity-loop design

struct VelocityLoopRequest {
    enum class Method { Inertia, Frf };
    Method method = Method::Inertia;
    // Inertia rule.
    double jmKgm2 = 0.0;
    double omegaLHz = kDefaultVelocityBandwidthHz; ///< ω_l/2π for k = 1
    double k = kDefaultVelocityGainFactor;
    std::optional<TwoInertiaParams> model; ///< a fitted two-inertia model: the prediction uses it (J_m as entered)
    // Margins rule.
    double crossoverHz = 40.0;
    double phaseMarginDeg = 50.0;
    std::optional<dsp::FrequencyResponse> measured;              ///< needed for Method::Frf
    LoopMeasurementKind absentKind = LoopMeasurementKind::Plant; ///< what a measurement without `measurement` is
    // The loop as found on the drive.
    VelocityPi running{1.0, 50.0};
    double positionKpRunning = 0.0;
    double velocityPeriodS = 250e-6;
    double currentPeriodS = 62.5e-6;
    // Step prediction: a step of stepRadS at 1 % of stepDurationS.
    double stepRadS = 10.0;
    double stepDurationS = 0.2;
};

struct VelocityLoopDesign {
    VelocityPi proposed;
    std::string rule;                            ///< the rule that chose the PI, with its numbers
    std::string modelNote;                       ///< what the prediction runs on
    bool rigidModel = true;                      ///< no two-inertia model: rigid J_m with the loop delay
    TwoInertiaParams model;                      ///< the prediction model (delay = 1.5 velocity periods)
    std::optional<dsp::FrequencyResponse> plant; ///< the measured plant (Method::Frf)
    /// The design grid: the plant's valid lines, else 300 log-spaced lines 1 Hz … 2 kHz on the model.
    std::vector<double> fHz;
    std::vector<std::complex<double>> plantH, openLoopBefore, openLoop, closedLoop;
    LoopMargins marginsBefore, marginsAfter;
    PositionGainDesign position; ///< with the proposed PI, semi-closed, 6 dB below the limit
    std::string positionRule;
    double stepTimeS = 0.0; ///< when the predicted steps start
    std::optional<VelocityStepPrediction> predictedBefore, predictedAfter;
};

/// The proposal with its prediction. Errors: bad numbers (named), Method::Frf without a measurement, a plant the
/// measurement cannot give, a crossover the PI cannot reach (velocityPiFromFrf's reason).
Result<VelocityLoopDesign> designVelocityLoop(const VelocityLoopRequest& request);

/// The drive parameters of a design: velocity.kp, velocity.ki, and position.kp when asked and finite and > 0.
model::ParameterValues velocityLoopParameters(const VelocityLoopDesign& design, bool withPositionGain);

// ---------------------------------------------------------------------------------------------
// The two-inertia proposal (spec §4.10, TI-3/TI-5): what the two-inertia wizard writes to the drive

struct TwoInertiaProposal {
    SuppressionFilter filter; ///< F_m (semi) or F_L (full) from the fitted model
    VelocityPi pi;            ///< chapter 5 rule on the fitted J_m
    /// velocity.kp/ki, suppression.mode (1 semi, 2 full), suppression.f0/zeta (and tau when full), the velocity
    /// and torque feedforward the method needs (position.velocity_ff = position.torque_ff = 1) and the torque
    /// feedforward inertia velocity.inertia = J_m + J_L.
    model::ParameterValues parameters;
};

/// The proposal for a fitted model. tauS: F_L's time constant (0: suppressionFilterFromModel's default).
TwoInertiaProposal twoInertiaProposal(const TwoInertiaParams& p, SuppressionMode mode, double tauS,
                                      double bandwidthHz = kDefaultVelocityBandwidthHz,
                                      double k = kDefaultVelocityGainFactor);

// ---------------------------------------------------------------------------------------------
// Velocity steps: measured or predicted, normalised to the step

struct NormalisedStep {
    std::vector<double> tMs; ///< from the step command
    std::vector<double> y;   ///< motor velocity / step
};

/// A step capture (t_s, velocity_cmd_rad_s, motor_vel_rad_s), from the first sample where the command reaches
/// half the step (one sample before it included); empty when a column is missing or the command never steps.
NormalisedStep normalisedStep(const model::Capture& capture, double stepRadS);
NormalisedStep normalisedStep(const VelocityStepPrediction& prediction, double stepRadS, double stepTimeS);
/// Overshoot [%] above 1 after t = 0 (0 when it never exceeds 1); nullopt for an empty trace.
std::optional<double> stepOvershootPct(const NormalisedStep& step);

// ---------------------------------------------------------------------------------------------
// Motor data from the drive

/// k_e [V·s/rad, q-axis peak] of the torque constant k_t [N·m/A, peak], amplitude-invariant dq: k_t = 1.5·k_e.
double backEmfFromTorqueConstant(double ktNmPerA);
/// Line-to-line rms volts per 1000 min⁻¹ per V·s/rad (q-axis peak): √(3/2)·1000·2π/60.
inline constexpr double kKeToVPerKrpm = 1.2247448713915890 * 1000.0 * 2.0 * std::numbers::pi / 60.0;

/// The drive parameters the current-loop design reads.
std::vector<std::string> motorParameterKeys();
/// `base` with what the drive states: motor.max_current, drive.max_voltage, motor.rated_current, the back-EMF
/// constant from motor.torque_constant (> 0). R_a, L_q and δ stay those of `base` (the drive does not offer them).
MotorData motorFromDriveParameters(const model::ParameterValues& values, MotorData base);

} // namespace axistune::tuning
