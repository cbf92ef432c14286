// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli ballbar: ball-bar diagnostics of one or more circle traces (docs/ballbar.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/io/BallBarCsv.h"
#include "core/model/CircleDirectionName.h"
#include "core/model/Constants.h"
#include "core/model/ResultJson.h"
#include "core/tuning/BallBarDiagnostics.h"

#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>

namespace axistune::cli {
namespace {

using model::kRadPerDeg;

struct BallBarCliOptions {
    std::vector<std::string> inPaths;
    double excludeDeg = 4.0;
    double windowDeg = 20.0;
    std::string outPath;
};

constexpr const char* kNoFullCircle = "no full-circle run among the traces";
constexpr const char* kNoBothDirections = "needs full-circle runs in both directions (CW and CCW)";

const char* axisKey(int axis)
{
    return axis == 0 ? "x" : "y";
}

nlohmann::json runJson(const tuning::RunDiagnostics& r)
{
    nlohmann::json j;
    j["file"] = r.source;
    j["direction"] = model::circleDirectionName(r.sigma > 0 ? model::CircleDirection::Ccw : model::CircleDirection::Cw);
    j["radius_mm"] = r.radiusM * 1e3;
    j["feed_mm_min"] = r.feedMPerS * 60e3;
    j["full_circle"] = r.fullCircle;
    if (r.fullCircle) {
        j["circularity_um"] = r.circularityM * 1e6;
        j["center_um"] = {{"x", r.centerXM * 1e6}, {"y", r.centerYM * 1e6}};
        j["radius_deviation_um"] = r.radiusDeviationM * 1e6;
        j["cos2_um"] = r.cos2M * 1e6;
        j["sin2_um"] = r.sin2M * 1e6;
        j["residual_rms_um"] = r.residualRmsM * 1e6;
    } else {
        j["refused"] = r.refusal;
    }
    nlohmann::json ev = nlohmann::json::array();
    for (const auto& e : r.events) {
        ev.push_back({{"axis", axisKey(e.axis)},
                      {"angle_deg", e.angleRad / kRadPerDeg},
                      {"table_mm", e.tableCoordM * 1e3},
                      {"step_um", e.stepM * 1e6},
                      {"step_stderr_um", e.stepStdErrM * 1e6},
                      {"noise_rms_um", e.noiseRmsM * 1e6}});
    }
    j["reversals"] = ev;
    return j;
}

nlohmann::json reportJson(const tuning::BallBarReport& rep)
{
    nlohmann::json j;
    model::putOptional(j, "circularity_um", rep.circularityM, 1e6, kNoFullCircle);
    if (rep.centerXM)
        j["center_um"] = {{"x", *rep.centerXM * 1e6}, {"y", *rep.centerYM * 1e6}};
    else
        model::putUndefined(j, "center_um", kNoFullCircle);
    model::putOptional(j, "radius_deviation_um", rep.radiusDeviationM, 1e6, kNoFullCircle);
    for (int axis = 0; axis < 2; ++axis) {
        const std::string a = axisKey(axis);
        const std::string noReversal = "no " + std::string(axis == 0 ? "X" : "Y") + " reversal in the trace(s)";
        model::putOptional(j, "backlash_" + a + "_um", rep.backlashM[axis], 1e6, noReversal);
        if (rep.backlashM[axis]) {
            j["backlash_detected_" + a] = rep.backlashDetected[axis];
            j["backlash_threshold_" + a + "_um"] = rep.backlashThresholdM[axis] * 1e6;
        } else {
            model::putUndefined(j, "backlash_detected_" + a, noReversal);
            model::putUndefined(j, "backlash_threshold_" + a + "_um", noReversal);
        }
    }
    nlohmann::json spikes = nlohmann::json::array();
    for (const auto& s : rep.spikes) {
        spikes.push_back({{"axis", axisKey(s.axis)},
                          {"angle_deg", s.angleRad / kRadPerDeg},
                          {"height_um", s.heightM * 1e6},
                          {"width_deg", s.widthRad / kRadPerDeg},
                          {"file", s.source}});
    }
    j["reversal_spikes"] = spikes;
    model::putOptional(j, "scale_mismatch_ppm", rep.scaleMismatch, 1e6, kNoFullCircle);
    model::putOptional(j, "squareness_um_per_m", rep.squarenessRad, 1e6, kNoFullCircle);
    model::putOptional(j, "servo_mismatch_ms", rep.servoMismatchS, 1e3, kNoBothDirections);
    if (rep.cyclic[0]) {
        nlohmann::json c;
        for (int axis = 0; axis < 2; ++axis) {
            const auto& f = *rep.cyclic[axis];
            c[axisKey(axis)] = f.amplitudeM * 1e6;
            c[std::string("pitch_") + axisKey(axis) + "_mm"] = f.pitchM * 1e3;
            c[std::string("detected_") + axisKey(axis)] = f.detected;
            c[std::string("threshold_") + axisKey(axis) + "_um"] = f.thresholdM * 1e6;
        }
        j["cyclic_error_um"] = c;
    } else {
        model::putUndefined(j, "cyclic_error_um", kNoFullCircle);
    }
    nlohmann::json findings = nlohmann::json::array();
    for (const auto& f : rep.findings)
        findings.push_back({{"name", f.name},
                            {"value", f.value},
                            {"unit", f.unit},
                            {"rule", f.rule},
                            {"rule_id", f.ruleId},
                            {"rule_args", f.ruleArgs}});
    j["findings"] = findings;
    nlohmann::json refused = nlohmann::json::array();
    for (const auto& r : rep.refused)
        refused.push_back(r.text);
    j["refused"] = refused;
    nlohmann::json runs = nlohmann::json::array();
    for (const auto& r : rep.runs)
        runs.push_back(runJson(r));
    j["runs"] = runs;
    return j;
}

int runBallBar(const BallBarCliOptions& o)
{
    if (o.inPaths.empty())
        return reportError("ballbar", makeError(ErrorCode::BadInput, "give at least one trace with --in FILE"));
    std::vector<io::BallBarTrace> traces;
    for (const auto& p : o.inPaths) {
        auto t = io::readBallBarCsvFile(p);
        if (!t)
            return reportError("ballbar", t.error());
        traces.push_back(std::move(t).value());
    }
    tuning::BallBarOptions bo;
    bo.excludeDeg = o.excludeDeg;
    bo.fitWindowDeg = o.windowDeg;
    auto rep = tuning::analyzeBallBar(traces, bo);
    if (!rep)
        return reportError("ballbar", rep.error());
    if (!rep->circularityM && !rep->backlashM[0] && !rep->backlashM[1]) {
        std::string why;
        for (const auto& r : rep->refused)
            why += (why.empty() ? "" : "; ") + r.text;
        return reportError("ballbar", makeError(ErrorCode::BadInput, "no diagnostic could be computed: " + why));
    }
    return writeJsonResult("ballbar", reportJson(*rep), o.outPath);
}

const CliRegistrar kRegistrar{CliCommand{
    "ballbar",
    "Ball-bar diagnostics: centre, radius, circularity, backlash, reversal spikes, scale mismatch, squareness, "
    "servo mismatch, cyclic error",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<BallBarCliOptions>();
        sub.add_option("--in", o->inPaths,
                       "ball-bar CSV (angle_deg,deviation_um with '# radius_mm=', '# feed_mm_min=', "
                       "'# direction=ccw|cw'); repeat for CW and CCW runs to separate squareness from servo mismatch")
            ->required();
        sub.add_option("--exclude-deg", o->excludeDeg,
                       "half-width of the zone around each reversal left out of the smooth fits and searched for "
                       "spikes (default 4)")
            ->check(CLI::Range(0.2, 30.0));
        sub.add_option("--window-deg", o->windowDeg,
                       "width of the fit window on each side of a reversal, beyond the excluded zone (default 20)")
            ->check(CLI::Range(2.0, 60.0));
        sub.add_option("--out", o->outPath, "write the JSON to this file instead of stdout");
        return recordSessions(sub, [o] { return runBallBar(*o); });
    }}};

} // namespace
} // namespace axistune::cli
