// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli autotune: the one-button tuner (core/autotune/AutoTune.h; docs/tuning.md "One-button tuning"). A
// thin wrapper: connect, run the sequence, write the result JSON; a refusal writes the JSON too (with `reason`)
// and exits 4, or 3 when the drive failed (docs/cli.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/autotune/AmplitudeMap.h"
#include "core/autotune/AutoTune.h"
#include "core/device/ModbusDrive.h"

#include <cmath>
#include <iostream>
#include <memory>

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
};

int runAutotune(const AutotuneOptions& o)
{
    const std::string cmd = "autotune";
    auto bad = [&](const std::string& what) { return reportError(cmd, makeError(ErrorCode::BadInput, what)); };
    auto style = autotune::parseStyle(o.style);
    if (!style)
        return bad("--style: " + style.error().detail);
    if (!(o.timeBudgetS > 0.0) || !std::isfinite(o.timeBudgetS))
        return bad("--time-budget must be > 0 s");
    if (!(o.minBandwidthHz >= 0.0) || !std::isfinite(o.minBandwidthHz))
        return bad("--min-bandwidth-hz must be >= 0 (0: the style's)");
    if (!o.amplitudes.empty()) {
        if (auto st = autotune::checkAmplitudeList(o.amplitudes); !st)
            return bad("--amplitudes: " + st.error().detail);
    }
    autotune::Options opts;
    opts.amplitudeMapPct = o.amplitudes;
    opts.axis = o.axis;
    opts.style = *style;
    opts.timeBudgetS = o.timeBudgetS;
    opts.dryRun = o.dryRun;
    opts.minBandwidthHz = o.minBandwidthHz;
    if (!o.motorPath.empty()) {
        auto m = tuning::readMotorJsonFile(o.motorPath);
        if (!m)
            return reportError(cmd, m.error());
        opts.motor = *m;
    }
    auto drive = device::connectAny({o.connect, o.seed});
    if (!drive)
        return reportError(cmd, drive.error());
    auto r = autotune::runAutoTune(**drive, opts);
    if (!r)
        return reportError(cmd, r.error());
    auto j = autotune::resultJson(*r, opts);
    j["connection"] = o.connect;
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
        sub.add_option("--axis", o->axis, "axis to tune")->required();
        sub.add_option("--style", o->style,
                       "gentle (60 deg / 10 dB, 20 Hz), standard (50 deg / 8 dB, 40 Hz; default) or stiff "
                       "(45 deg / 6 dB, 80 Hz): design margins and required velocity crossover");
        sub.add_option("--time-budget", o->timeBudgetS, "seconds of motion for the whole sequence (default 30)");
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
        return recordSessions(sub, [o] { return runAutotune(*o); });
    }}};

} // namespace

} // namespace axistune::cli
