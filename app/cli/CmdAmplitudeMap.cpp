// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli amplitude-map: the closed velocity loop measured by multisine at three or more amplitudes, lines
// flagged non-linear where the response changes beyond its noise (core/autotune/AmplitudeMap.h; docs/tuning.md
// "Amplitude map and backlash"). A thin wrapper: connect, measure, write the map JSON.
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/autotune/AmplitudeMap.h"
#include "core/device/ModbusDrive.h"

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct AmplitudeMapCliOptions {
    std::string connect;
    std::string axis;
    std::vector<double> amplitudes;
    double fminHz = 20.0;
    double fmaxHz = 0.0;
    double spacingHz = 10.0;
    int periods = 4;
    double timeBudgetS = 0.0;
    std::uint64_t seed = 1;
    std::string outPath;
};

int runAmplitudeMap(const AmplitudeMapCliOptions& o)
{
    const std::string cmd = "amplitude-map";
    auto bad = [&](const std::string& what) { return reportError(cmd, makeError(ErrorCode::BadInput, what)); };
    if (auto st = autotune::checkAmplitudeList(o.amplitudes); !st)
        return bad("--amplitudes: " + st.error().detail);
    if (!(o.fminHz > 0.0) || !std::isfinite(o.fminHz) || !(o.spacingHz > 0.0) || !std::isfinite(o.spacingHz))
        return bad("--fmin and --spacing-hz must be > 0 Hz");
    if (!(o.fmaxHz >= 0.0) || !std::isfinite(o.fmaxHz) || (o.fmaxHz > 0.0 && !(o.fmaxHz > o.fminHz)))
        return bad("--fmax must be above --fmin (0: 0.975 x the drive's trace rate)");
    if (o.periods < 2 || o.periods > 64)
        return bad("--periods must lie in 2 ... 64");
    if (!(o.timeBudgetS >= 0.0) || !std::isfinite(o.timeBudgetS))
        return bad("--time-budget must be >= 0 s (0: no limit)");
    auto drive = device::connectAny({o.connect, o.seed});
    if (!drive)
        return reportError(cmd, drive.error());
    autotune::AmplitudeMapOptions ao;
    ao.axis = o.axis;
    ao.amplitudesPct = o.amplitudes;
    ao.fminHz = o.fminHz;
    ao.fmaxHz = o.fmaxHz;
    ao.spacingHz = o.spacingHz;
    ao.periods = o.periods;
    ao.timeBudgetS = o.timeBudgetS;
    auto m = autotune::measureAmplitudeMap(**drive, ao);
    if (!m)
        return reportError(cmd, m.error());
    auto j = autotune::amplitudeMapJson(*m);
    j["connection"] = o.connect;
    return writeJsonResult(cmd, j, o.outPath);
}

const CliRegistrar kRegistrar{CliCommand{
    "amplitude-map",
    "Amplitude dependence: the closed velocity loop by multisine at three or more amplitudes; lines whose response "
    "changes beyond the noise flagged non-linear (friction, backlash)",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<AmplitudeMapCliOptions>();
        sub.add_option("--connect", o->connect, connectOptionHelp())->required();
        sub.add_option("--axis", o->axis, "axis to measure")->required();
        sub.add_option("--amplitudes", o->amplitudes,
                       "A1,A2,A3[,...]: multisine peaks [% of rated torque], at least three, increasing")
            ->delimiter(',')
            ->required();
        sub.add_option("--fmin", o->fminHz, "lowest line [Hz] (default 20)");
        sub.add_option("--fmax", o->fmaxHz, "highest line [Hz] (default: 0.975 x the drive's trace rate)");
        sub.add_option("--spacing-hz", o->spacingHz, "line spacing [Hz] (default 10)");
        sub.add_option("--periods", o->periods, "averaged periods per amplitude, 2 ... 64 (default 4)");
        sub.add_option("--time-budget", o->timeBudgetS, "seconds of motion for all amplitudes (default 0: no limit)");
        sub.add_option("--seed", o->seed, "noise seed of an embedded simulated machine");
        sub.add_option("--out", o->outPath, "write the map JSON to this file instead of stdout");
        return recordSessions(sub, [o] { return runAmplitudeMap(*o); });
    }}};

} // namespace

} // namespace axistune::cli
