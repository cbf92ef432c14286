// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli reversal-comp: reversal (quadrant-glitch) compensation tuned from circle tests through
// the drive (docs/ballbar.md "Reversal compensation"): measure a circle, tune the pulse on the model of
// the machine with the drive's own parameters, predict the compensated circle, write the pulse, verify
// with a new circle.
#include "app/cli/CircleCommand.h"
#include "app/cli/CliCommand.h"
#include "core/device/Drive.h"
#include "core/device/DriveRegistry.h"
#include "core/io/BallBarCsv.h"
#include "core/model/ResultJson.h"
#include "core/sim/AxisParameters.h"
#include "core/sim/MachineDefinition.h"
#include "core/tuning/ReversalCompensation.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {
namespace {

struct ReversalCompCliOptions {
    CircleCliOptions circle;
    std::string model;
    bool dryRun = false;
    std::string measuredOut, predictedOut, verifiedOut, out;
};

/// The model of the machine: --model FILE, else the preset the drive names; its plane axes take every
/// drive parameter the drive reports (gains, filters, compensation), so the model runs as the drive does.
Result<sim::MachineDefinition> driveModel(device::Drive& drive, const ReversalCompCliOptions& o,
                                          const sim::CircleTestOptions& c)
{
    Result<sim::MachineDefinition> m = makeError(ErrorCode::BadInput, "");
    if (!o.model.empty()) {
        m = sim::loadMachineDefinitionFile(o.model);
    } else {
        auto id = drive.identify();
        if (!id)
            return id.error();
        m = sim::loadPreset(id->machine);
        if (!m)
            return makeError(ErrorCode::BadInput, "no model of the drive's machine '" + id->machine + "' (" +
                                                      m.error().detail + "): give one with --model FILE");
    }
    if (!m)
        return makeError(ErrorCode::BadInput, "--model '" + o.model + "': " + m.error().detail);
    sim::MachineDefinition machine = *m;
    for (const std::string& axis : {c.axisX, c.axisY}) {
        sim::AxisDefinition* def = nullptr;
        for (auto& a : machine.axes)
            if (a.name == axis)
                def = &a;
        if (!def)
            return makeError(ErrorCode::BadInput, "the model '" + machine.name + "' has no axis '" + axis + "'");
        auto metas = drive.parameterMetadata(axis);
        if (!metas)
            return metas.error();
        std::vector<std::string> keys;
        for (const auto& meta : *metas)
            if (!sim::isPlantParameter(meta.key) && def->values.count(meta.key))
                keys.push_back(meta.key);
        auto values = drive.readParameters(axis, keys);
        if (!values)
            return values.error();
        for (const auto& [k, v] : *values)
            def->values[k] = v;
    }
    return machine;
}

nlohmann::json axisJson(const tuning::ReversalCompAxis& a)
{
    return {{"axis", a.axis},
            {"amplitude_m_per_s", a.amplitudeMPerS},
            {"amplitude_mm_min", a.amplitudeMPerS * 60000.0},
            {"time_constant_ms", a.timeConstantS * 1e3},
            {"dT_Nm", a.dTNm},
            {"measured_spike_um", a.measuredSpikeM * 1e6},
            {"model_spike_um", a.modelSpikeM * 1e6},
            {"predicted_spike_um", a.predictedSpikeM * 1e6},
            {"predicted_reduction_pct", a.predictedReduction * 100.0},
            {"search_circles", a.evaluations}};
}

Status writeBallBar(const std::string& path, io::BallBarTrace bb, const std::string& what)
{
    if (path.empty())
        return Status::success();
    bb.metadata.set("reversal_comp", what);
    return io::writeBallBarCsvFile(path, bb);
}

int runReversalComp(const ReversalCompCliOptions& o)
{
    const std::string cmd = "reversal-comp";
    if (o.circle.plane.size() != 2)
        return reportError(
            cmd, makeError(ErrorCode::BadInput, "--plane '" + o.circle.plane + "': two axis letters, e.g. XY"));
    if (!device::findBackend(o.circle.connect))
        return reportError(cmd, makeError(ErrorCode::BadInput, "--connect '" + o.circle.connect + "': expected " +
                                                                   device::registeredUriForms()));
    const sim::CircleTestOptions c = circleOptions(o.circle);
    auto drive = device::connect({o.circle.connect, o.circle.seed});
    if (!drive)
        return reportError(cmd, drive.error());
    device::Drive& d = **drive;
    // 1. The circle as the drive is now.
    auto before = measureCircleOnDrive(d, c);
    if (!before)
        return reportError(cmd, before.error());
    if (auto st = writeBallBar(o.measuredOut, before->result.ballbar, "measured"); !st)
        return reportError(cmd, st.error());
    // 2. Tune and predict on the model with the drive's parameters.
    auto model = driveModel(d, o, c);
    if (!model)
        return reportError(cmd, model.error());
    auto tuned =
        tuning::tuneReversalCompensation(*model, c, before->result.ballbar, before->result.dTxNm, before->result.dTyNm);
    if (!tuned)
        return reportError(cmd, tuned.error());
    if (auto st = writeBallBar(o.predictedOut, tuned->predicted, "predicted"); !st)
        return reportError(cmd, st.error());
    nlohmann::json j;
    j["connection"] = o.circle.connect;
    j["model"] = model->name;
    j["axes"] = nlohmann::json::array();
    for (const auto& a : tuned->axes)
        j["axes"].push_back(axisJson(a));
    j["written"] = false;
    if (o.dryRun)
        return writeJsonResult(cmd, j, o.out);
    // 3. Write the pulse (range-checked and read back by the drive).
    for (const auto& a : tuned->axes) {
        const model::ParameterValues v{{"reversal.amplitude", a.amplitudeMPerS},
                                       {"reversal.time_constant", a.timeConstantS}};
        if (auto st = d.writeParameters(a.axis, v); !st)
            return reportError(cmd,
                               makeError(st.error().code, "writing the pulse of " + a.axis + ": " + st.error().detail));
    }
    j["written"] = true;
    // 4. Verify with a new circle.
    auto after = measureCircleOnDrive(d, c);
    if (!after)
        return reportError(cmd, after.error());
    if (auto st = writeBallBar(o.verifiedOut, after->result.ballbar, "verified"); !st)
        return reportError(cmd, st.error());
    auto spikes = tuning::reversalSpikes(after->result.ballbar);
    if (!spikes)
        return reportError(cmd, spikes.error());
    for (std::size_t k = 0; k < 2; ++k) {
        const auto& a = tuned->axes[k];
        const double verified = (*spikes)[k].worstM;
        auto& ja = j["axes"][k];
        ja["verified_spike_um"] = verified * 1e6;
        if (a.measuredSpikeM > 0.0)
            ja["measured_reduction_pct"] = (1.0 - verified / a.measuredSpikeM) * 100.0;
        else
            model::putUndefined(ja, "measured_reduction_pct", "no reversal spike measured before the compensation");
    }
    return writeJsonResult(cmd, j, o.out);
}

const CliRegistrar kRegistrar{
    {"reversal-comp",
     "Reversal (quadrant-glitch) compensation tuned from circle tests through a drive: measure, tune on the model, "
     "predict, write, verify",
     [](CLI::App& sub) {
         auto o = std::make_shared<ReversalCompCliOptions>();
         auto& c = o->circle;
         sub.add_option("--connect", c.connect, connectOptionHelp())->capture_default_str();
         sub.add_option("--plane", c.plane, "the two axes, first = x role")->capture_default_str();
         sub.add_option("--radius-mm", c.radiusMm, "circle radius [mm]")
             ->capture_default_str()
             ->check(CLI::PositiveNumber);
         sub.add_option("--feed-mm-min", c.feedMmMin, "feed [mm/min]")
             ->capture_default_str()
             ->check(CLI::PositiveNumber);
         sub.add_option("--direction", c.direction, "ccw | cw")
             ->capture_default_str()
             ->check(CLI::IsMember({"ccw", "cw"}));
         sub.add_option("--center-x-mm", c.centerXMm, "circle centre, first axis [mm]")->capture_default_str();
         sub.add_option("--center-y-mm", c.centerYMm, "circle centre, second axis [mm]")->capture_default_str();
         sub.add_option("--seed", c.seed, "noise seed of a sim: drive and of the model")->capture_default_str();
         sub.add_option("--model", o->model, "machine definition JSON of the model (default: the drive's preset)");
         sub.add_flag("--dry-run", o->dryRun, "tune and predict only: write nothing, no verification circle");
         sub.add_option("--measured-out", o->measuredOut, "ball-bar CSV of the circle before");
         sub.add_option("--predicted-out", o->predictedOut, "ball-bar CSV of the model's compensated circle");
         sub.add_option("--verified-out", o->verifiedOut, "ball-bar CSV of the verification circle");
         sub.add_option("--out", o->out, "result JSON (default stdout)");
         return [o] { return runReversalComp(*o); };
     }}};

} // namespace
} // namespace axistune::cli
