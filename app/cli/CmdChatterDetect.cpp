// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli chatter-detect: sensorless chatter detection of seed 004 (vibration-mode force and position,
// correlation rule r_Fx < r_Fa) on a captured full-closed trace → JSON intervals (docs/machining.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/io/CaptureCsv.h"
#include "core/machining/StageFromParameters.h"
#include "core/machining/StageJson.h"
#include "core/model/MetadataKeys.h"
#include "core/sim/MachineDefinition.h"

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

namespace axistune::cli {
namespace {

struct ChatterDetectArgs {
    std::string in, stage, out;
    std::optional<double> windowS, lowPassHz, highPassHz, minDurationS, mergeGapS, baselineS, baselineFactor;
};

/// The stage of the capture's simulated machine (metadata machine= and axis=) when no stage.json is given.
Result<machining::StageDescription> stageFromCapture(const model::Capture& cap, const std::string& src)
{
    const auto m = cap.metadata.text(model::meta::kMachine);
    const auto ax = cap.metadata.text(model::meta::kAxis);
    if (!m || !ax)
        return makeError(
            ErrorCode::BadInput,
            src + ": no --stage given and the capture names no machine/axis (metadata lines 'machine=' and 'axis=')");
    auto def = sim::loadPreset(*m);
    if (!def)
        return makeError(ErrorCode::BadInput,
                         src + ", metadata 'machine=" + *m + "': " + def.error().detail + " (give --stage)");
    const auto* a = def->axis(*ax);
    if (!a)
        return makeError(ErrorCode::BadInput, src + ", metadata 'axis=" + *ax + "': not an axis of " + *m);
    return machining::stageFromAxisParameters(a->values);
}

int runChatterDetect(const ChatterDetectArgs& a)
{
    const std::string cmd = "chatter-detect";
    auto cap = io::readCaptureCsvFile(a.in);
    if (!cap)
        return reportError(cmd, cap.error());
    auto stage = a.stage.empty() ? stageFromCapture(*cap, a.in) : machining::readStageJsonFile(a.stage);
    if (!stage)
        return reportError(cmd, stage.error());
    const std::string stageSrc =
        a.stage.empty() ? "machine " + cap->metadata.textOr(model::meta::kMachine, "?") : a.stage;
    if (!stage->hasCoupling)
        return reportError(
            cmd, makeError(ErrorCode::BadInput,
                           stageSrc + ": the chatter detection needs the 'coupling' (stiffness) of the stage"));
    auto mode = machining::vibrationModeOf(stage->twoMass());
    if (!mode)
        return reportError(cmd, makeError(mode.error().code, stageSrc + ": " + mode.error().detail));
    machining::ChatterDetectOptions opt = stage->chatter;
    if (a.windowS)
        opt.windowS = *a.windowS;
    if (a.lowPassHz)
        opt.lowPassHz = *a.lowPassHz;
    if (a.highPassHz)
        opt.highPassHz = *a.highPassHz;
    if (a.minDurationS)
        opt.minDurationS = *a.minDurationS;
    if (a.mergeGapS)
        opt.mergeGapS = *a.mergeGapS;
    if (a.baselineS)
        opt.baselineS = *a.baselineS;
    if (a.baselineFactor)
        opt.baselineFactor = *a.baselineFactor;

    const auto* t = cap->channel("t_s");
    const auto* current = cap->channel("current_cmd_A");
    const auto* torque = current ? nullptr : cap->channel("torque_cmd_Nm");
    const auto* xm = cap->channel("motor_pos_m");
    const auto* xt = cap->channel("table_pos_m");
    if (!t)
        return reportError(cmd, makeError(ErrorCode::BadInput, a.in + ": missing column 't_s'"));
    if (!current && !torque)
        return reportError(cmd, makeError(ErrorCode::BadInput,
                                          a.in + ": needs the current reference 'current_cmd_A' (or 'torque_cmd_Nm')"));
    if (!xm || !xt)
        return reportError(cmd, makeError(ErrorCode::BadInput,
                                          a.in + ": needs 'motor_pos_m' and 'table_pos_m' (full-closed signals)"));
    const std::size_t n = t->data.size();
    if (n < 2 || !(t->data.back() > t->data.front()))
        return reportError(
            cmd, makeError(ErrorCode::BadInput, a.in + ", column 't_s': fewer than 2 samples or time not increasing"));
    const double fs = static_cast<double>(n - 1) / (t->data.back() - t->data.front());
    const double r = stage->leadMPerRad();
    std::vector<double> fm(n);
    for (std::size_t i = 0; i < n; ++i)
        fm[i] = (current ? stage->torqueConstantNmPerA * current->data[i] : torque->data[i]) / r;
    auto res = machining::detectChatter(t->data, fm, xm->data, xt->data, fs, *mode, opt);
    if (!res)
        return reportError(cmd, makeError(res.error().code, a.in + ": " + res.error().detail));

    nlohmann::json j;
    j["input"] = a.in;
    j["stage"] = stageSrc;
    j["fs_Hz"] = fs;
    j["vibration_mode_Hz"] = res->vibrationModeHz;
    j["alpha"] = mode->alpha;
    j["window_s"] = opt.windowS;
    j["highpass_Hz"] = opt.highPassHz;
    j["lowpass"] = {{"cutoff_Hz", opt.lowPassHz}, {"applied", res->lowPassApplied}};
    if (!res->lowPassApplied)
        j["lowpass"]["note"] =
            "cutoff at or above the Nyquist frequency of the capture: nothing to remove, filter skipped";
    j["force_from"] = current ? "current_cmd_A x torque_constant / R" : "torque_cmd_Nm / R";
    j["flagged_fraction"] = res->flaggedFraction;
    j["baseline_s"] = opt.baselineS;
    j["force_floor_N"] = std::sqrt(res->forceFloorN2);
    j["chatter"] = !res->intervals.empty();
    j["intervals"] = nlohmann::json::array();
    for (const auto& iv : res->intervals)
        j["intervals"].push_back(
            {{"start_s", iv.startS}, {"end_s", iv.endS}, {"frequency_Hz", iv.frequencyHz}, {"score", iv.score}});
    return writeJsonResult(cmd, j, a.out);
}

const CliRegistrar kRegistrar{{
    "chatter-detect",
    "Sensorless chatter detection by force/position/acceleration correlation (seed 004) on a capture → JSON intervals",
    [](CLI::App& sub) -> std::function<int()> {
        auto a = std::make_shared<ChatterDetectArgs>();
        sub.add_option("--in", a->in, "capture CSV: t_s, current_cmd_A (or torque_cmd_Nm), motor_pos_m, table_pos_m")
            ->required();
        sub.add_option("--stage", a->stage, "stage.json with 'coupling' (default: the capture's simulated machine)");
        sub.add_option("--window-s", a->windowS, "correlation window T [s] (default 0.1)");
        sub.add_option("--lowpass-hz", a->lowPassHz,
                       "4th-order Butterworth low-pass [Hz] (default 2000; skipped at/above Nyquist)");
        sub.add_option("--highpass-hz", a->highPassHz, "4th-order Butterworth high-pass [Hz] (default 20)");
        sub.add_option("--min-duration-s", a->minDurationS,
                       "drop flagged runs shorter than this [s] (default 0, not in the paper)");
        sub.add_option("--merge-gap-s", a->mergeGapS,
                       "merge flagged runs closer than this [s] (default 0, not in the paper)");
        sub.add_option("--baseline-s", a->baselineS,
                       "air-cut baseline [s] from the start: force energy floor = factor x its largest window mean "
                       "square (default 0: off)");
        sub.add_option("--baseline-factor", a->baselineFactor, "floor factor on the baseline mean square (default 4)");
        sub.add_option("--out", a->out, "JSON file (default stdout)");
        return recordSessions(sub, [a] { return runChatterDetect(*a); });
    },
}};

} // namespace
} // namespace axistune::cli
