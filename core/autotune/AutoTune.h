// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one-button axis tuner (issue 18 items 5 and 6; docs/tuning.md "One-button tuning"): the wizards' hand
// sequence as one headless run through the drive seam, every step saying what it measured, what it chose and
// the rule that chose it:
//   safety envelope → current loop → adaptive FRF → notches → velocity PI → position gain and feedforward →
//   move evaluation → verify (re-measured FRF, margins against the prediction) → apply (read back) or roll back.
// The rules are those of core/tuning (VelocityLoopDesign, Notch, CurrentLoop); this file only sequences them.
// Refusals (item 6) stop the run with a reason and restore every parameter the run wrote: lines not valid
// (coherence), non-linear lines, a resonance at the required bandwidth, a drive fault, margins not met.
// Its own library (core/autotune) because it sits above both core/device (the seam) and core/tuning (the rules).
// No Qt.

#include "core/device/Drive.h"
#include "core/device/TestRunner.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"
#include "core/tuning/CurrentLoop.h"

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace axistune::autotune {

enum class Style { Gentle, Standard, Stiff };

/// What a style asks of the velocity loop (docs/tuning.md "Styles").
struct StyleTargets {
    double phaseMarginDeg = 50.0;       ///< the design's predicted phase margin at least
    double gainMarginDb = 8.0;          ///< the design's predicted gain margin at least
    double minBandwidthHz = 40.0;       ///< the required velocity crossover: the velocity wizard's default 40 Hz
    double frfAmplitudePct = 10.0;      ///< first FRF peak [% rated torque]
    double acceptPhaseMarginDeg = 45.0; ///< the re-measured loop must keep at least this (else roll back)
    double acceptGainMarginDb = 6.0;
};
StyleTargets styleTargets(Style s);
const char* styleName(Style s);
/// gentle, standard, stiff; BadInput naming the value otherwise.
Result<Style> parseStyle(std::string_view name);

struct Step {
    std::string name;
    nlohmann::json measured = nlohmann::json::object();
    nlohmann::json chosen = nlohmann::json::object();
    std::string rule;
    double motionTimeS = 0.0;
};

struct Options {
    std::string axis;
    Style style = Style::Standard;
    double timeBudgetS = 30.0;   ///< motion time of the whole sequence [s]; a step that would exceed it refuses
    bool dryRun = false;         ///< run every measurement, then restore the parameters (nothing applied)
    double minBandwidthHz = 0.0; ///< required velocity crossover [Hz]; 0: the style's
    /// R_a, L_q, δ of the motor (the drive does not state them): with it the current loop is designed
    /// (motorFromDriveParameters + designCurrentLoop), without it the running current PI is kept and only verified.
    std::optional<tuning::MotorData> motor;
    /// Amplitude map in the FRF step (AmplitudeMap.h, docs/tuning.md "Amplitude map and backlash"): empty, none; else
    /// at least three increasing multisine peaks [% rated torque]. The FRF then starts at the map's amplitude nearest
    /// the torque of the move evaluation's move (run once with the running gains); the map is recorded in the frf
    /// step's measured.amplitude_map (the strong-non-linearity refusal stays the adaptive FRF's).
    std::vector<double> amplitudeMapPct;
    device::RunOptions run; ///< abort token and progress of each test
    /// Called on the running thread when a step begins (its name as in steps[]; velocity-pi to verify begin
    /// again on a second design attempt) and when it ends (the Step as it goes into steps[]). The abort token
    /// is also checked before each step: set between two tests, the run stops there (Refused, Aborted).
    std::function<void(const std::string& name)> stepStarted;
    std::function<void(const Step&)> stepFinished;
    /// N >= 2: measure, design and verify at N positions spread over the drive's travel window
    /// (AutoTunePositions.cpp, docs/tuning.md "Over the travel"); 1: where the axis stands (the sequence above).
    int positions = 1;
};

/// One position of a tune over the travel: the re-measured margins and bandwidths there, and the first resonance
/// of the open loop measured there before the tuning (the resonance map).
struct PositionFinal {
    double position = 0.0;                ///< [m or rad], where the drive stood (its position command)
    double phaseMarginDeg = 0.0;          ///< re-measured
    double gainMarginDb = 0.0;            ///< re-measured
    double velocityBandwidthHz = 0.0;     ///< re-measured
    double positionBandwidthHz = 0.0;     ///< from the re-measured closed velocity loop
    double predictedPhaseMarginDeg = 0.0; ///< the design's on the FRF measured there
    double predictedGainMarginDb = 0.0;
    std::optional<double> firstResonanceHz;       ///< lowest resonance of the open loop before tuning (nullopt: none)
    std::optional<double> firstResonanceHeightDb; ///< its height above the baseline
};

struct Final {
    double phaseMarginDeg = 0.0;      ///< re-measured open velocity loop (smallest over its gain crossovers)
    double gainMarginDb = 0.0;        ///< re-measured (smallest over the −180° crossings)
    double velocityBandwidthHz = 0.0; ///< −3 dB of the re-measured closed velocity loop
    double positionBandwidthHz = 0.0; ///< −3 dB of K_p·T_v/s closed (position feedback only, on the re-measured T_v)
    std::optional<double> settlingTimeS;  ///< move evaluation; nullopt when it never settled in the record
    double peakFollowingError = 0.0;      ///< [m or rad]
    double motionTimeS = 0.0;             ///< machine time of the whole sequence
    model::ParameterValues parameters;    ///< what was (or, dry run, would be) applied
    std::vector<PositionFinal> positions; ///< --positions N >= 2: every position (the figures above: the worst)
};

enum class Outcome {
    Applied, ///< parameters written and read back
    DryRun,  ///< every step ran; the parameters were restored
    Refused, ///< stopped with a reason; every parameter restored
};

struct AutoTuneResult {
    Outcome outcome = Outcome::Refused;
    std::string reason;                       ///< why it refused (empty otherwise)
    ErrorCode reasonCode = ErrorCode::Safety; ///< the refusal's class (Safety: the loop cannot be tuned safely)
    std::vector<Step> steps;
    std::optional<Final> final;
    double motionTimeS = 0.0;
    bool restored = false;         ///< the parameters were written back and read back equal
    model::ParameterValues before; ///< every writable parameter as found
};

/// Runs the sequence on `drive`. Errors (nothing changed yet): bad options, an axis the drive does not have, a
/// drive that cannot run the tests the sequence needs. Everything later is an AutoTuneResult (Refused with the reason
/// and the parameters restored, or Applied/DryRun).
Result<AutoTuneResult> runAutoTune(device::Drive& drive, const Options& options);

/// The names of the nine steps in their order (steps[].name): safety-envelope, current-loop, frf, notches,
/// velocity-pi, position, move, verify, apply.
const std::vector<std::string>& stepNames();

/// The result JSON of docs/formats.md "autotune result": outcome, reason, steps[] {name, measured, chosen, rule},
/// final {phase_margin_deg, gain_margin_dB, velocity_bandwidth_Hz, position_bandwidth_Hz, settling_time_s,
/// peak_following_error, motion_time_s, parameters}.
nlohmann::json resultJson(const AutoTuneResult& r, const Options& options);

/// Options::positions >= 2 (AutoTunePositions.cpp); runAutoTune calls it. Errors as runAutoTune's, and BadInput
/// when the drive cannot move the axis between the measurements (no jog or hold test, no travel window).
Result<AutoTuneResult> runAutoTunePositions(device::Drive& drive, const Options& options);
/// Adds positions[] to `final` and the resonance_map[] (docs/formats.md "autotune result") for a tune over positions.
void addPositionsJson(const AutoTuneResult& r, nlohmann::json& j);

/// −3 dB frequency of a closed loop |T| relative to its first valid line (linear interpolation in log f between
/// the two lines around it); nullopt when it never falls 3 dB within the valid lines.
std::optional<double> closedLoopBandwidthHz(const std::vector<double>& fHz, const std::vector<std::complex<double>>& t);

} // namespace axistune::autotune
