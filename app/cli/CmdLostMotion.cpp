// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli lost-motion: A and B of Δx = (A + B·x)·ΔT from ball-bar traces, with residuals and the
// predicted proposed and conventional compensation (docs/ballbar.md; spec/lost-motion-and-two-inertia.md §4.3–4.5).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/io/AtomicFile.h"
#include "core/io/BallBarCsv.h"
#include "core/model/Constants.h"
#include "core/model/Number.h"
#include "core/model/ResultJson.h"
#include "core/tuning/LostMotion.h"

#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

namespace axistune::cli {
namespace {

using model::kRadPerDeg;

struct LostMotionCliOptions {
    std::vector<std::string> paths;
    std::string axis;
    double screwOffsetM = 0.0;
    double screwSign = 1.0;
    bool bFree = false;
    std::optional<double> conventionalUm;
    double excludeDeg = 4.0;
    double windowDeg = 20.0;
    std::string compensatedOut;
    std::optional<double> leadMm, rootDiameterMm;
    double shearModulusGpa = 79.0;
    std::string outPath;
};

Status writeCompensated(const std::string& path, const std::vector<tuning::CompensationPrediction>& preds)
{
    std::ostringstream f;
    const auto g = [](double v) { return model::formatNumber(v, 12); };
    f << "file_index,angle_deg,measured_um,proposed_um,conventional_um\n";
    for (std::size_t k = 0; k < preds.size(); ++k) {
        const auto& p = preds[k];
        for (std::size_t i = 0; i < p.angleRad.size(); ++i)
            f << k << ',' << g(p.angleRad[i] / kRadPerDeg) << ',' << g(p.measuredM[i] * 1e6) << ','
              << g(p.proposedM[i] * 1e6) << ',' << g(p.conventionalM[i] * 1e6) << '\n';
    }
    return io::writeFileAtomic(path, f.view());
}

constexpr const char* kNoFullCircle = "the trace is not a full circle";

/// A, B, the points with residuals, the guards and the optional material-model comparison.
nlohmann::json fitJson(const LostMotionCliOptions& o, const tuning::LostMotionFit& fitv,
                       const std::vector<tuning::LostMotionPoint>& points)
{
    const auto* fit = &fitv;
    nlohmann::json j;
    j["axis"] = o.axis;
    j["method"] = tuning::lostMotionMethodName(fit->method);
    j["A_m_per_Nm"] = fit->aMPerNm;
    j["B_per_Nm"] = fit->bPerNm;
    j["A_um_per_Nm"] = fit->aMPerNm * 1e6;
    j["B_um_per_Nm_m"] = fit->bPerNm * 1e6;
    // Left out and named when not defined (docs/formats.md "Undefined values").
    const char* noStdErr = "no standard error: the fit has no more points than unknowns";
    model::putOptional(j, "A_stderr_m_per_Nm", fit->aStdErr, 1.0, noStdErr);
    model::putOptional(j, "B_stderr_per_Nm", fit->bStdErr, 1.0, noStdErr);
    if (fit->printedA)
        j["printed_two_point"] = {{"A_m_per_Nm", *fit->printedA}, {"B_per_Nm", *fit->printedB}};
    nlohmann::json pts = nlohmann::json::array();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto& p = points[i];
        pts.push_back({{"x_m", p.xM},
                       {"dT_Nm", p.dTNm},
                       {"dx_m", p.dxM},
                       {"residual_m", fit->residualsM[i]},
                       {"file", p.source},
                       {"angle_deg", p.angleRad / kRadPerDeg}});
    }
    j["points"] = pts;
    j["residual_rms_m"] = fit->residualRmsM;
    if (o.leadMm && o.rootDiameterMm) {
        // Spec §4.4 guard: the measured compliance is expected ~10× the textbook torsion of the screw.
        const double slope =
            tuning::materialComplianceSlope(*o.leadMm * 1e-3, *o.rootDiameterMm * 1e-3, o.shearModulusGpa * 1e9);
        j["material_B_per_Nm"] = slope;
        if (fit->bPerNm != 0.0)
            j["material_ratio_m"] = slope / fit->bPerNm;
        else
            model::putUndefined(j, "material_ratio_m", "the fitted B is 0");
    }
    j["warnings"] = fit->warnings;
    return j;
}

int runLostMotion(const LostMotionCliOptions& o)
{
    const char* cmd = "lost-motion";
    tuning::LostMotionSetup setup;
    setup.axis = o.axis == "y" ? 1 : 0;
    setup.screwOffsetM = o.screwOffsetM;
    setup.screwSign = o.screwSign;
    tuning::BallBarOptions bo;
    bo.excludeDeg = o.excludeDeg;
    bo.fitWindowDeg = o.windowDeg;

    std::vector<io::BallBarTrace> traces;
    std::vector<tuning::LostMotionPoint> points;
    for (const auto& p : o.paths) {
        auto t = io::readBallBarCsvFile(p);
        if (!t)
            return reportError(cmd, t.error());
        auto pts = tuning::extractLostMotionPoints(*t, setup, bo);
        if (!pts)
            return reportError(cmd, pts.error());
        points.insert(points.end(), pts->begin(), pts->end());
        traces.push_back(std::move(t).value());
    }
    auto fit = tuning::fitLostMotion(points, o.bFree);
    if (!fit)
        return reportError(cmd, fit.error());
    double xbl = 0.0;
    for (const auto& p : points)
        xbl += p.dxM / static_cast<double>(points.size());
    if (o.conventionalUm)
        xbl = *o.conventionalUm * 1e-6;

    nlohmann::json j = fitJson(o, *fit, points);
    std::vector<tuning::CompensationPrediction> preds;
    nlohmann::json pj = nlohmann::json::array();
    std::optional<double> worst;
    for (const auto& t : traces) {
        auto p = tuning::predictCompensation(t, setup, *fit, xbl, bo);
        if (!p)
            return reportError(cmd, p.error());
        nlohmann::json e{{"file", t.source},
                         {"measured_cut_in_um", p->measuredCutInM * 1e6},
                         {"proposed_cut_in_um", p->proposedCutInM * 1e6},
                         {"conventional_cut_in_um", p->conventionalCutInM * 1e6}};
        model::putOptional(e, "measured_circularity_um", p->measuredCircularityM, 1e6, kNoFullCircle);
        model::putOptional(e, "proposed_circularity_um", p->proposedCircularityM, 1e6, kNoFullCircle);
        model::putOptional(e, "conventional_circularity_um", p->conventionalCircularityM, 1e6, kNoFullCircle);
        pj.push_back(e);
        if (p->proposedCircularityM)
            worst = std::max(worst.value_or(0.0), *p->proposedCircularityM);
        preds.push_back(std::move(p).value());
    }
    model::putOptional(j, "predicted_circularity_um", worst, 1e6, "no trace is a full circle");
    j["conventional_backlash_um"] = xbl * 1e6;
    j["predictions"] = pj;
    if (!o.compensatedOut.empty()) {
        if (auto s = writeCompensated(o.compensatedOut, preds); !s)
            return reportError(cmd, s.error());
    }
    return writeJsonResult(cmd, j, o.outPath);
}

const CliRegistrar kRegistrar{CliCommand{
    "lost-motion", "Lost-motion A/B of dx = (A + B x) dT from ball-bar traces, residuals and predicted compensation",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<LostMotionCliOptions>();
        sub.add_option("--ballbar", o->paths,
                       "ball-bar CSV files (each needs '# dT_x_Nm=' or '# dT_y_Nm=' for the axis, and the circle "
                       "centre '# center_x_mm=', '# center_y_mm=')")
            ->required();
        sub.add_option("--axis", o->axis, "axis to identify: x or y")->required()->check(CLI::IsMember({"x", "y"}));
        sub.add_option("--screw-offset-m", o->screwOffsetM,
                       "x0: spring length (coupling to load point) at table coordinate 0, in m (default 0)");
        sub.add_option("--screw-sign", o->screwSign,
                       "+1 if the spring length grows with the table coordinate, -1 if it shrinks (default +1)")
            ->check(CLI::IsMember({-1.0, 1.0}));
        sub.add_flag("--b-free", o->bFree, "fix B = 0 (A = mean dx/dT), for axes without position dependence");
        sub.add_option("--conventional-backlash-um", o->conventionalUm,
                       "backlash x_bl of the conventional step compensation for the prediction (default: the mean "
                       "measured lost motion)");
        sub.add_option("--lead-mm", o->leadMm,
                       "screw lead [mm/rev], with --root-diameter-mm: material-model comparison")
            ->check(CLI::PositiveNumber);
        sub.add_option("--root-diameter-mm", o->rootDiameterMm, "screw root diameter [mm]")->check(CLI::PositiveNumber);
        sub.add_option("--shear-modulus-gpa", o->shearModulusGpa, "screw shear modulus [GPa] (default 79)")
            ->check(CLI::PositiveNumber);
        sub.add_option("--exclude-deg", o->excludeDeg, "reversal zone half-width (default 4)")
            ->check(CLI::Range(0.2, 30.0));
        sub.add_option("--window-deg", o->windowDeg, "step-fit window beyond the zone (default 20)")
            ->check(CLI::Range(2.0, 60.0));
        sub.add_option("--compensated-out", o->compensatedOut,
                       "write measured, proposed and conventional traces here "
                       "(file_index,angle_deg,measured_um,proposed_um,conventional_um)");
        sub.add_option("--out", o->outPath, "write the JSON to this file instead of stdout");
        return recordSessions(sub, [o] { return runLostMotion(*o); });
    }}};

} // namespace
} // namespace axistune::cli
