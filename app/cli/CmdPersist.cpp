// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli persist: writes pid gains into the INI keys of a LinuxCNC configuration that feed them (Persist,
// docs/linuxcnc.md "Configurations and Persist"): every other byte of the INI unchanged, a backup next to it, the
// edits printed as JSON first. Gains from --set, or the values the running HAL holds now (--from-hal).
#include "app/cli/CliCommand.h"
#include "core/device/hal/HalDrive.h"
#include "core/device/hal/LinuxCncConfig.h"
#include "core/device/hal/LinuxCncDrive.h"
#include "core/model/Number.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {
namespace {

using namespace device::hal;

struct PersistOptions {
    std::string ini;
    std::string axis;
    std::vector<std::string> set;
    bool fromHal = false;
    bool dryRun = false;
};

int runPersist(const PersistOptions& o)
{
    const std::string cmd = "persist";
    if (o.set.empty() == !o.fromHal)
        return reportError(cmd,
                           makeError(ErrorCode::BadInput, "give either --set KEY=VALUE (repeatable) or --from-hal"));
    auto cfg = readLinuxCncConfig(o.ini);
    if (!cfg)
        return reportError(cmd, cfg.error());
    const PidInstance* pid = nullptr;
    std::string axes;
    for (const auto& p : cfg->pids) {
        axes += (axes.empty() ? "" : ", ") + linuxCncAxisName(p);
        if (linuxCncAxisName(p) == o.axis || p.name == o.axis)
            pid = &p;
    }
    if (!pid)
        return reportError(cmd, makeError(ErrorCode::BadInput, "--axis " + o.axis + ": not an axis of " + o.ini + " (" +
                                                                   (axes.empty() ? std::string("none") : axes) + ")"));
    std::vector<GainChange> changes;
    const auto metas = pidParameterMetadata();
    for (const auto& s : o.set) {
        const auto eq = s.find('=');
        const auto v = eq == std::string::npos ? std::nullopt : model::parseNumber(std::string_view(s).substr(eq + 1));
        if (eq == std::string::npos || !v)
            return reportError(
                cmd, makeError(ErrorCode::BadInput, "--set '" + s + "': expected GAIN=VALUE, e.g. Pgain=2.5"));
        const std::string key = s.substr(0, eq);
        const auto* meta = model::findParameter(metas, key);
        if (!meta)
            return reportError(cmd,
                               makeError(ErrorCode::BadInput, "--set '" + s + "': '" + key +
                                                                  "' is not a pid gain (Pgain, Igain, Dgain, FF0…FF3, "
                                                                  "bias, deadband, maxerror…, maxoutput)"));
        if (auto st = model::checkParameterValue(*meta, *v); !st)
            return reportError(cmd, st.error());
        changes.push_back({pid->name, key, *v});
    }
    if (o.fromHal) {
        // Every gain the INI feeds, as the running HAL holds it now (halcmd shows seven significant digits).
        auto session = halSessionFromEnvironment();
        if (!session)
            return reportError(cmd, session.error());
        auto hal = HalDrive::open(*session);
        if (!hal)
            return reportError(cmd, hal.error());
        std::vector<std::string> keys;
        for (const auto& [gain, source] : pid->gains)
            if (!source.key.empty() && model::findParameter(metas, gain))
                keys.push_back(gain);
        auto values = (*hal)->readParameters(pid->name, keys);
        if (!values)
            return reportError(cmd, values.error());
        for (const auto& [k, v] : *values)
            changes.push_back({pid->name, k, v});
    }
    auto plan = planPersist(*cfg, changes);
    if (!plan)
        return reportError(cmd, plan.error());
    nlohmann::ordered_json out;
    out["ini"] = o.ini;
    out["axis"] = o.axis;
    out["pid"] = pid->name;
    out["dry_run"] = o.dryRun;
    auto& edits = out["edits"] = nlohmann::ordered_json::array();
    for (const auto& e : plan->second)
        edits.push_back(
            {{"section", e.section}, {"key", e.key}, {"line", e.line}, {"old", e.oldValue}, {"new", e.newValue}});
    if (!o.dryRun && !plan->second.empty()) {
        auto written = persistGains(*cfg, changes);
        if (!written)
            return reportError(cmd, written.error());
        out["backup"] = o.ini + ".axistune-backup";
    }
    out["written"] = !o.dryRun && !plan->second.empty();
    std::cout << out.dump(2) << "\n";
    return 0;
}

const CliRegistrar kRegistrar{
    {"persist", "Write pid gains into the INI keys of a LinuxCNC configuration that feed them (backup kept)",
     [](CLI::App& sub) {
         auto o = std::make_shared<PersistOptions>();
         sub.add_option("--ini", o->ini, "the configuration's INI file")->required();
         sub.add_option("--axis", o->axis, "axis letter (X), jointN or pid name")->required();
         sub.add_option("--set", o->set, "GAIN=VALUE, pid pin names (Pgain, FF1 …), repeatable");
         sub.add_flag("--from-hal", o->fromHal,
                      "the values of every INI-fed gain as the running HAL holds them (AXISTUNE_HALCMD for halcmd)");
         sub.add_flag("--dry-run", o->dryRun, "print the edits, write nothing");
         return [o] { return runPersist(*o); };
     }}};

} // namespace
} // namespace axistune::cli
