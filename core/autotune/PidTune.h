// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tuning a position PID the NC closes (LinuxCNC's `pid` through hal: or linuxcnc:; docs/linuxcnc.md "Tuning"), the
// headless steps behind `axistune-cli pid-tune` and the velocity/position and notch wizards on such an axis:
//   1. measurePidLoop: the open loop measured with the running gains (multisine, FrfQuantity::OpenLoop) and the
//      effective plant P_eff = L / (C_running · N_running) (core/tuning/PositionPid.h; N_running: AxisTune's notch
//      when one runs after the pid, so that a second tune designs on the plant, not on plant × the first notch);
//   2. proposePidTune: P, I, D, FF1, FF2 for the margins asked and a biquad notch when it raises the crossover
//      (PidTuneScope::GainsAndNotch), or a notch alone for the running gains (PidTuneScope::NotchOnly), each number
//      with the rule that chose it; nothing moves;
//   3. applyPidTune: inserts the notch, writes the gains live, measures again and compares the margins; a loop that
//      misses them gets back what ran before (gains and notch).

#include "core/autotune/Undo.h"
#include "core/device/Drive.h"
#include "core/device/TestRunner.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"
#include "core/tuning/PositionPid.h"

#include <complex>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace axistune::autotune {

/// The pid's gain pins a tune writes (hal:'s parameter keys; linuxcnc: maps them to the INI's).
const std::vector<std::string>& pidGainKeys();

enum class PidTuneScope {
    GainsAndNotch, ///< P, I, D, FF1, FF2 and a notch when it lets the crossover rise (pid-tune, the velocity wizard)
    NotchOnly,     ///< a notch for the gains that run (the notch wizard); the gains are not changed. Rule: a notch at
                   ///< the strongest resonance above 1.5 × the running crossover when it raises the gain margin by
                   ///< 1 dB or more with the phase margin at least min(asked, running − 3°); Q with the largest GM
};

struct PidTuneRequest {
    std::string axis;
    double fminHz = 2.0;
    double fmaxHz = 0.0;                          ///< 0: 0.45 × the servo rate
    double amplitude = 0.0;                       ///< multisine peak in the PID output's units; 0: amplitudePct
    double amplitudePct = 0.0;                    ///< % of the pid's maxoutput; 0 with amplitude 0: 5 %
    int periods = 0;                              ///< averaged periods; 0: the drive's default
    std::optional<tuning::DriveInput> driveInput; ///< none: read from the measured plant's slope
    double phaseMarginDeg = 50.0;
    double gainMarginDb = 8.0;
    bool notch = true; ///< GainsAndNotch: consider a notch
    PidTuneScope scope = PidTuneScope::GainsAndNotch;
};

/// How checkPidTuneRequest names the fields (the CLI passes its option names).
struct PidTuneNames {
    std::string axis = "axis";
    std::string excitation = "the excitation";
    std::string phaseMargin = "the phase margin asked";
    std::string gainMargin = "the gain margin asked";
    std::string fmin = "fmin";
    std::string fmax = "fmax";
};

/// The request's own limits (margins asked 30..80° and 3..20 dB, a positive excitation, fmin below fmax); BadInput
/// naming the field as `names` says.
Status checkPidTuneRequest(const PidTuneRequest& request, const PidTuneNames& names = {});

/// The open loop as measured with the running gains.
struct PidLoopMeasurement {
    double servoRateHz = 0.0;
    double fmaxHz = 0.0;
    tuning::PositionPid running;
    model::ParameterValues runningValues;    ///< the gain pins as read before the measurement
    std::vector<double> freqHz;              ///< the valid lines
    std::vector<std::complex<double>> loop;  ///< L = −(PID output)/(drive input) at them
    std::vector<std::complex<double>> plant; ///< P_eff = L / (C_running · N_running): the plant without any notch
    /// AxisTune's notch that ran after the pid during the measurement (it is inside L: the injection enters before
    /// it); lines where it takes 60 dB or more out of L are left out of all three vectors.
    std::optional<tuning::BiquadNotch> runningNotch;
    double motionTimeS = 0.0;
    std::optional<device::FrfMeasurement> frf; ///< the whole measurement (for a session)
};

/// Measures the open loop of the request's axis with the gains that run. Refused when the drive does not measure the
/// open position loop (not a PID the NC closes), and with the drive's or the run's errors (Aborted on `run.abort`).
Result<PidLoopMeasurement> measurePidLoop(device::Drive& drive, const PidTuneRequest& request,
                                          const device::RunOptions& run);

struct PidTuneProposal {
    tuning::DriveInput input = tuning::DriveInput::Torque;
    std::string inputRule;
    tuning::PositionPid gains;                  ///< proposed (NotchOnly: the running gains)
    tuning::PositionLoopMargins runningMargins; ///< of the measured loop
    tuning::PositionLoopMargins predicted;      ///< of the proposed loop over the measured lines
    std::vector<std::complex<double>> predictedLoop;
    std::vector<std::string> rules;    ///< one sentence per gain (GainsAndNotch)
    std::optional<double> resonanceHz; ///< the plant's strongest resonance looked at for the notch
    std::optional<tuning::BiquadNotch> notch;        ///< the notch that runs after an apply (none: no notch)
    std::optional<tuning::BiquadNotch> runningNotch; ///< the one that ran during the measurement
    std::string notchRule;
    bool notchChanges() const;
    bool changesSomething() const { return notchChanges() || !rules.empty(); }
};

/// The proposal for a measurement (nothing moves). Errors: the drive input's slope read neither way (name it), no
/// crossover that meets the margins (designPositionPid's reason).
Result<PidTuneProposal> proposePidTune(const PidLoopMeasurement& measured, const PidTuneRequest& request);

/// The open loop predicted for `gains` and `notch` on the measured plant, C·N·P_eff at the measured lines.
std::vector<std::complex<double>> predictedPidLoop(const PidLoopMeasurement& measured, const tuning::PositionPid& gains,
                                                   const std::optional<tuning::BiquadNotch>& notch);

struct PidTuneApplied {
    bool applied = false;    ///< the proposal runs now and met the margins; false: what ran before is back
    std::string refusal;     ///< why not applied
    bool measuredOk = false; ///< the verifying measurement ran (margins below are measured)
    tuning::PositionLoopMargins measured;
    double motionTimeS = 0.0;
    model::ParameterValues before;             ///< the gain pins before
    model::ParameterValues written;            ///< what was written (empty for NotchOnly)
    std::optional<tuning::BiquadNotch> notchBefore; ///< AxisTune's notch after the pid before (read again at apply)
    std::optional<device::FrfMeasurement> frf; ///< the verifying measurement
};

/// Inserts (or retunes) the proposal's notch, or removes the running one when the proposal has none, writes the gains
/// (read back), measures the open loop again and checks the measured margins against the asked ones (3° and 1 dB
/// below them; NotchOnly: below the smaller of asked and predicted). A loop that misses them, a failed or aborted
/// verifying measurement: the gains and the notch from before (its f0 and Q) are put back and `applied` is false with
/// the reason. Errors (nothing left changed): the notch or the write refused, or HAL's notch no longer the one the
/// measurement ran with.
Result<PidTuneApplied> applyPidTune(device::Drive& drive, const PidTuneRequest& request,
                                    const PidLoopMeasurement& measured, const PidTuneProposal& proposal,
                                    const device::RunOptions& run);

/// The notch half of undoing an applied tune: the notch that ran before it and the one it applied (none: none).
struct PidTuneNotchUndo {
    std::string axis;
    std::optional<tuning::BiquadNotch> before;
    std::optional<tuning::BiquadNotch> applied;
    bool changes() const;
};

/// Refused (Safety, naming both) when HAL's notch after the axis is no longer the one the tune applied (f0 and Q
/// within 1e-5 relative: halcmd prints seven digits), unless `force`: putting the old one back would undo a later
/// change. Nothing to check when the tune left the notch as it was. Call it before the gains are undone.
Status checkPidTuneNotchUndo(device::Drive& drive, const PidTuneNotchUndo& undo, bool force);

/// What undoPidTuneNotch found and left.
struct PidTuneNotchUndone {
    bool changed = false;                        ///< false: the tune left the notch as it was; nothing read or written
    std::optional<tuning::BiquadNotch> held;     ///< HAL's notch just before the undo wrote over it (read; none: none)
    std::optional<tuning::BiquadNotch> restored; ///< the notch now: the one from before the tune (none: removed)
};

/// Puts the notch from before back (inserted with its f0 and Q, or removed when there was none) and says what HAL
/// held just before (read first: after a forced undo, a later change the journal records as overwritten); nothing
/// when the tune left the notch as it was. Errors: the read or the restore refused.
Result<PidTuneNotchUndone> undoPidTuneNotch(device::Drive& drive, const PidTuneNotchUndo& undo);

/// One write of a tune or of its undo as a session's journal records it (store::JournalEntry's key, old and new
/// value; docs/storage.md "Journal"): the gains by their keys (pidGainKeys), AxisTune's notch by the HAL names of
/// the biquad's parameters, `axistune-notch.f0` [Hz] and `axistune-notch.Q`, and by `axistune-notch` for whether
/// it runs after the axis's pid (1) or not (0).
struct PidTuneWrite {
    std::string key;
    std::optional<double> from; ///< none: nothing before (f0 and Q of a notch inserted)
    double to = 0.0;
    friend bool operator==(const PidTuneWrite&, const PidTuneWrite&) = default;
};

/// The notch's change from `from` to `to`: inserted: `axistune-notch` 0 → 1, f0 and Q with nothing before; retuned:
/// f0 and Q, before → after (both: the component is loaded again with both); removed: `axistune-notch` 1 → 0 only
/// (f0 and Q have no value after it; the session's result keeps the notch removed); nothing when they are the same.
std::vector<PidTuneWrite> pidTuneNotchWrites(const std::optional<tuning::BiquadNotch>& from,
                                             const std::optional<tuning::BiquadNotch>& to);

/// The journal of an apply: each gain written (`before` → `written`, in key order), then the notch's change
/// (`notchBefore` → the proposal's notch); empty when the tune was not kept (what ran before is back).
std::vector<PidTuneWrite> pidTuneAppliedWrites(const PidTuneApplied& applied, const PidTuneProposal& proposal);

/// The journal of an undo: each gain from what the drive held just before the undo (UndoneParameter::applied; after
/// a forced undo the later change, not the value the tune applied) to the one read back, then the notch from the one
/// HAL held just before to the one put back.
std::vector<PidTuneWrite> pidTuneUndoWrites(const std::vector<UndoneParameter>& gains, const PidTuneNotchUndone& notch);

/// The writes as JSON: [{"key", "old" (absent: nothing before), "new"}].
nlohmann::json pidTuneWritesJson(const std::vector<PidTuneWrite>& writes);

/// The result JSON of a tune (docs/linuxcnc.md "Tuning from the command line", pid-tune's --out; the wizards' session
/// result): axis, scope, servo_rate_Hz, band_Hz, drive_input (+ _rule), running {gains, margins, motion_time_s},
/// proposed {gains, predicted, rules, notch_rule, notch {f0_Hz, Q}}, applied, and with `applied`: verified
/// {measured, motion_time_s} and refused, or, when it was kept, journal (pidTuneWritesJson of pidTuneAppliedWrites).
nlohmann::json pidTuneJson(const PidTuneRequest& request, const PidLoopMeasurement& measured,
                           const PidTuneProposal& proposal, const PidTuneApplied* applied = nullptr);

} // namespace axistune::autotune
