// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli autotune: the one-button tuner (core/autotune/AutoTune.h; docs/tuning.md "One-button tuning"). A
// thin wrapper: connect, run the sequence, write the result JSON; a refusal writes the JSON too (with `reason`)
// and exits 4, or 3 when the drive failed (docs/cli.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/autotune/AmplitudeMap.h"
#include "core/autotune/AutoTune.h"
#include "core/autotune/TravelChoice.h"
#include "core/autotune/Undo.h"
#include "core/device/ModbusDrive.h"
#include "core/device/MoveTo.h"
#include "core/model/InputLimits.h"
#include "core/model/Number.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct AutotuneOptions {
    std::string connect;
    std::string axis;
    std::string style = "standard";
    std::string motorPath;
    double timeBudgetS = 30.0;
    double minBandwidthHz = 0.0;
    bool dryRun = false;
    std::vector<double> amplitudes;
    std::uint64_t seed = 1;
    std::string outPath;
    int positions = 1;
    std::string at; ///< --at: move there first (one position)
    bool budgetGiven = false;
    std::string undoPath; ///< --undo RESULT.json
    bool force = false;
    std::vector<std::string> tuneOptionsGiven; ///< options of a tune given with --undo
};

/// --undo RESULT.json: the parameters an applied run wrote go back to their values before it.
int runUndo(const AutotuneOptions& o)
{
    const std::string cmd = "autotune --undo";
    auto bad = [&](const std::string& what) { return reportError(cmd, makeError(ErrorCode::BadInput, what)); };
    if (!o.tuneOptionsGiven.empty())
        return bad(o.tuneOptionsGiven.front() + " is an option of a tune, not of --undo");
    auto j = model::readJsonFile(o.undoPath);
    if (!j)
        return reportError(cmd, j.error());
    auto tune = autotune::appliedTuneFromJson(*j);
    if (!tune)
        return bad(model::displayPath(o.undoPath) + ": " + tune.error().detail);
    if (!o.axis.empty() && o.axis != tune->axis)
        return bad("--axis " + o.axis + " but " + model::displayPath(o.undoPath) + " tuned axis " + tune->axis);
    auto drive = device::connectAny({o.connect, o.seed});
    if (!drive)
        return reportError(cmd, drive.error());
    auto undone = autotune::undoTune(**drive, *tune, o.force);
    if (!undone)
        return reportError(cmd, undone.error());
    return writeUndone(cmd, {{"axis", tune->axis}, {"connection", o.connect}, {"from", model::displayPath(o.undoPath)}},
                       *undone, o.outPath);
}

int runAutotune(const AutotuneOptions& o)
{
    if (!o.undoPath.empty())
        return runUndo(o);
    const std::string cmd = "autotune";
    auto bad = [&](const std::string& what) { return reportError(cmd, makeError(ErrorCode::BadInput, what)); };
    if (o.axis.empty())
        return bad("--axis is required (the axis to tune)");
    if (o.force)
        return bad("--force is an option of --undo");
    auto style = autotune::parseStyle(o.style);
    if (!style)
        return bad("--style: " + style.error().detail);
    if (o.positions > 1 && !o.at.empty())
        return bad("--at and --positions N > 1 exclude each other (--positions spreads the positions over the "
                   "travel window itself)");
    std::optional<double> at;
    if (!o.at.empty()) {
        at = model::parseNumber(o.at);
        if (!at || !std::isfinite(*at))
            return bad("--at: '" + o.at + "' is not a number");
    }
    autotune::Options opts;
    opts.amplitudeMapPct = o.amplitudes;
    opts.axis = o.axis;
    opts.style = *style;
    // The default budget is 30 s of motion per position.
    opts.timeBudgetS = o.budgetGiven ? o.timeBudgetS : o.timeBudgetS * o.positions;
    opts.positions = o.positions;
    opts.dryRun = o.dryRun;
    opts.minBandwidthHz = o.minBandwidthHz;
    if (!o.motorPath.empty()) {
        auto m = tuning::readMotorJsonFile(o.motorPath);
        if (!m)
            return reportError(cmd, m.error());
        opts.motor = *m;
    }
    // The wizard's checks (core), named by the options.
    if (auto st = autotune::checkChoices(
            opts, {"--positions", "--time-budget", "--min-bandwidth-hz", "--amplitudes", "--motor"});
        !st)
        return reportError(cmd, st.error());
    auto drive = device::connectAny({o.connect, o.seed});
    if (!drive)
        return reportError(cmd, drive.error());
    std::optional<device::MoveToResult> moved;
    if (at) {
        auto m = device::moveAxisTo(**drive, o.axis, *at);
        if (!m)
            return reportError(cmd, makeError(m.error().code, "--at: " + m.error().detail));
        moved = *m;
    }
    auto r = autotune::runAutoTune(**drive, opts);
    if (!r)
        return reportError(cmd, r.error());
    auto j = autotune::resultJson(*r, opts);
    j["connection"] = o.connect;
    j["positions"] = o.positions;
    if (moved)
        j["at"] = {{"position", moved->to}, {"from", moved->from}, {"motion_time_s", moved->motionTimeS}};
    if (j.contains("resonance_map")) {
        std::cerr << "resonance map (first resonance of the open velocity loop against position):\n";
        for (const auto& m : j["resonance_map"])
            std::cerr << "  " << model::formatNumber(m["position"].get<double>(), 4) << " : "
                      << (m.contains("frequency_Hz") && m["frequency_Hz"].is_number()
                              ? model::formatNumber(m["frequency_Hz"].get<double>(), 4) + " Hz, " +
                                    model::formatNumber(m["height_dB"].get<double>(), 3) + " dB"
                              : std::string("none in the band"))
                      << "\n";
    }
    const int written = writeJsonResult(cmd, j, o.outPath);
    if (written != 0)
        return written;
    if (r->outcome == autotune::Outcome::Refused) {
        std::cerr << "axistune-cli autotune: refused, nothing applied"
                  << (r->restored ? " (every parameter restored)" : "") << ": " << r->reason << "\n";
        return exitCodeFor(r->reasonCode);
    }
    return 0;
}

const CliRegistrar kRegistrar{CliCommand{
    "autotune",
    "One-button tuning: envelope, current loop, adaptive FRF, notches, velocity PI, position gain, move, verify, "
    "apply or roll back",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<AutotuneOptions>();
        sub.add_option("--connect", o->connect, connectOptionHelp())->required();
        sub.add_option("--axis", o->axis, "axis to tune (with --undo: optional, must be the result's)");
        sub.add_option("--style", o->style,
                       "gentle (60 deg / 10 dB, 20 Hz), standard (50 deg / 8 dB, 40 Hz; default) or stiff "
                       "(45 deg / 6 dB, 80 Hz): design margins and required velocity crossover");
        sub.add_option("--time-budget", o->timeBudgetS,
                       "seconds of motion for the whole sequence (default 30 per position)");
        sub.add_option("--positions", o->positions,
                       "N >= 2: measure, design and verify at N positions spread over the drive's travel window "
                       "(the drive moves the axis between them by jogs); the gains must meet the margins at every "
                       "one; the result holds final.positions[] and the resonance map (default 1: where the axis "
                       "stands)");
        sub.add_option("--at", o->at,
                       "move the axis to this position [m or rad] first, then tune there (one position)");
        sub.add_option("--min-bandwidth-hz", o->minBandwidthHz,
                       "required velocity crossover [Hz] (default: the style's); a resonance within a factor 3 of "
                       "it is refused");
        sub.add_option("--motor", o->motorPath,
                       "motor JSON (R_a, L_q, delta; as current-loop --motor): the current loop is designed; without "
                       "it the running current PI is kept and verified");
        sub.add_option("--amplitudes", o->amplitudes,
                       "A1,A2,A3[,...]: measure the amplitude map (multisine peaks [% of rated torque], increasing) "
                       "in the FRF step; the FRF starts at the amplitude nearest the move's torque")
            ->delimiter(',');
        sub.add_flag("--dry-run", o->dryRun, "run every step, then restore every parameter (nothing applied)");
        sub.add_option("--seed", o->seed, "noise seed of an embedded simulated machine");
        sub.add_option("--out", o->outPath, "write the result JSON to this file instead of stdout");
        sub.add_option("--undo", o->undoPath,
                       "RESULT.json of an applied run: put the parameters it applied back to their values before it "
                       "(refused when the drive no longer holds what the run applied), read them back; no tuning");
        sub.add_flag("--force", o->force, "with --undo: undo even when the drive holds other values than applied");
        return recordSessions(sub, [o, &sub] {
            o->budgetGiven = sub.count("--time-budget") > 0;
            for (const char* t : {"--style", "--time-budget", "--positions", "--at", "--min-bandwidth-hz", "--motor",
                                  "--amplitudes", "--dry-run"})
                if (sub.count(t) > 0)
                    o->tuneOptionsGiven.push_back(t);
            return runAutotune(*o);
        });
    }}};

} // namespace

} // namespace axistune::cli
