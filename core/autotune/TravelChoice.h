// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a front end asks before it starts the one-button tuner (issue 18 items 3 and 4; docs/tuning.md "The wizard"):
// whether the axis can be tuned over its travel and within which window, and whether a set of choices can run
// together. The rules are the sequence's own (device::checkCanMoveTo / travelWindow, checkAmplitudeList); the
// wizard's choice page only shows their answers. Nothing here moves the axis. No Qt.

#include "core/autotune/AutoTune.h"
#include "core/device/Drive.h"
#include "core/model/Result.h"

#include <string>
#include <string_view>
#include <vector>

namespace axistune::autotune {

/// Default motion budget of a tune: 30 s per position (the CLI's default).
inline constexpr double kDefaultBudgetPerPositionS = 30.0;
double defaultTimeBudgetS(int positions);

/// How far inside the travel window the positions over the travel stay [m or rad] (docs/tuning.md "Over the travel"):
/// the servo lag v/K_p of the move that reaches them, v the jog speed of device::moveAxisTo (kMoveToSpeedLinear or
/// kMoveToSpeedRotary) and K_p the position gain [1/s]. A position loop without feedforward trails its command by
/// v/K_p while it moves at v; the feedforward the drive adds removes most of that lag, so the overshoot at the end of
/// the move stays well inside it (sim:long-axis X at K_p = 30 1/s: 19 µm past the target against v/K_p = 16.7 mm),
/// and a drive that checks the measured position against its window (axistune-simdrive) does not see the axis leave
/// it. NaN when K_p is not finite and > 0.
double positionsInset(bool linear, double positionGainPerS);

/// N >= 2 positions evenly from −(window − inset) to +(window − inset); BadInput when the inset leaves no room
/// (inset >= window), naming both.
Result<std::vector<double>> positionsOverTravel(double window, double inset, int n);

struct TravelChoice {
    /// Empty: positions along the travel can be chosen; else why not (the reason runAutoTunePositions would refuse
    /// with: no jog or hold test, jog distances in command units, no finite travel window — the rotary presets).
    std::string refusal;
    double window = 0.0; ///< the travel window W: the positions lie in −W … +W [m or rad]
    /// "m" or "rad" when the drive names the unit of its position command (its scope channels) before any test;
    /// empty when it does not (the sequence then learns it from its first hold).
    std::string units;
    /// positionsInset at the drive's position gain now (the units' kind; linear when not named); NaN when the drive
    /// gives no position gain.
    double inset = 0.0;
};

/// Asks the drive (capabilities, limits, scope channels); no motion. Errors: the drive's (unknown axis, link).
Result<TravelChoice> travelChoice(device::Drive& drive, const std::string& axis);

/// How checkChoices names the choices in its messages: the wizard's words by default, the CLI's options there.
struct ChoiceNames {
    std::string positions = "positions";
    std::string timeBudget = "time budget";
    std::string minBandwidth = "required velocity crossover";
    std::string amplitudes = "amplitude map";
    std::string motor = "motor data";
};

/// The choices that cannot run together or are out of range, as the wizard and `axistune-cli autotune` refuse them:
/// positions < 1, a time budget <= 0, a required crossover < 0, an amplitude list that checkAmplitudeList refuses,
/// an amplitude map or motor data with positions >= 2 (both are for one position). BadInput naming the choice.
Status checkChoices(const Options& options, const ChoiceNames& names = {});

/// "5, 10, 20" (commas and/or blanks between the numbers; locale-free) → {5, 10, 20}; empty text → {}.
/// BadInput naming the item that is not a number. The list's rules are checkAmplitudeList's.
Result<std::vector<double>> parseAmplitudeList(std::string_view text);

} // namespace axistune::autotune
