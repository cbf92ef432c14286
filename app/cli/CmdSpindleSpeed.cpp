// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli spindle-speed: lobe number and stable-pocket speed from a chatter frequency (or from a captured
// signal through the Kalman AR estimator), optionally with the SDM chapter-3 cost over the lobe (docs/machining.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/io/CaptureCsv.h"
#include "core/machining/ChatterFrequencyEstimator.h"
#include "core/machining/MachiningJson.h"
#include "core/machining/SpindleSpeed.h"
#include "core/model/Number.h"
#include "core/model/ResultJson.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {
namespace {

struct SpindleArgs {
    double chatterHz = 0.0;
    std::string in, signal;
    int order = 2;
    double rpm = 0.0;
    int teeth = 0;
    std::string tool, cut;
    double depthMm = 0.0;
    int steps = 40;
};

// Sample period from "# fs_Hz=" metadata, else from a t_s column.
Result<double> samplePeriod(const model::Capture& c, const std::string& src)
{
    if (const auto ts = c.metadata.samplePeriodS(); !ts)
        return makeError(ErrorCode::BadInput, src + ": " + ts.error().detail);
    else if (ts->has_value())
        return **ts;
    if (const auto* t = c.channel("t_s"); t && t->data.size() > 1) {
        const double ts = (t->data.back() - t->data.front()) / static_cast<double>(t->data.size() - 1);
        if (ts > 0.0)
            return ts;
    }
    return makeError(ErrorCode::BadInput, src + ": no '# fs_Hz=' metadata and no increasing t_s column");
}

Result<double> chatterFromCapture(const SpindleArgs& a, nlohmann::json& out)
{
    auto cap = io::readCaptureCsvFile(a.in);
    if (!cap)
        return cap.error();
    const auto* ch = cap->channel(a.signal);
    if (!ch)
        return makeError(ErrorCode::NotFound, a.in + ": no column '" + a.signal + "'");
    auto ts = samplePeriod(*cap, a.in);
    if (!ts)
        return ts.error();
    machining::KalmanAROptions opt;
    opt.order = a.order;
    opt.rv = 1e-6;
    opt.rw = 0.3;
    opt.p0 = 1e3;  // Table 4(a) settings, which converge from any signal scale
    auto f = machining::estimateChatterFrequencies(ch->data, *ts, opt);
    if (!f)
        return makeError(f.error().code, a.in + ", column '" + a.signal + "': " + f.error().detail);
    out["estimated_frequencies_Hz"] = *f;
    return f->front();
}

int runSpindle(const SpindleArgs& a)
{
    const std::string cmd = "spindle-speed";
    nlohmann::json out;
    double fchat = a.chatterHz;
    if (!a.in.empty()) {
        if (a.signal.empty())
            return reportError(cmd, makeError(ErrorCode::BadInput, "--in needs --signal COLUMN"));
        auto f = chatterFromCapture(a, out);
        if (!f)
            return reportError(cmd, f.error());
        fchat = *f;
    } else if (!(a.chatterHz > 0.0)) {
        return reportError(cmd, makeError(ErrorCode::BadInput, "give --chatter-hz F (> 0) or --in capture.csv --signal COLUMN"));
    }
    auto adv = machining::pocketAdvice(fchat, a.rpm, a.teeth);
    if (!adv)
        return reportError(cmd, adv.error());
    out["chatter_Hz"] = fchat;
    out["rpm"] = a.rpm;
    out["teeth"] = a.teeth;
    out["tooth_passing_Hz"] = adv->toothPassingHz;
    out["ratio"] = adv->ratio;
    out["lobe"] = adv->lobe;
    out["pocket_rpm"] = adv->rpm;
    out["notch_gain_now"] = adv->notchGainNow;
    for (const auto& c : adv->candidates)
        out["candidates"].push_back({{"lobe", c.lobe}, {"rpm", c.rpm}, {"notch_gain_at_chatter", c.notchGainAtChatter}});
    if (a.tool.empty() != a.cut.empty())
        return reportError(cmd, makeError(ErrorCode::BadInput, "--tool and --cut go together"));
    if (!a.tool.empty()) {
        auto tool = machining::readToolJsonFile(a.tool);
        if (!tool)
            return reportError(cmd, tool.error());
        auto cut = machining::readCutJsonFile(a.cut);
        if (!cut)
            return reportError(cmd, cut.error());
        if (cut->teeth != a.teeth)
            return reportError(cmd, makeError(ErrorCode::BadInput, a.cut + ": teeth (" + std::to_string(cut->teeth) +
                                                                       ") differs from --teeth " + std::to_string(a.teeth)));
        machining::CostOptions co;
        co.depthM = a.depthMm > 0.0 ? a.depthMm * 1e-3 : 1e-9;
        co.stepsPerPeriod = a.steps;
        auto c = machining::lobeCostAdvice(*tool, *cut, fchat, adv->lobe, co);
        if (!c)
            return reportError(cmd, c.error());
        nlohmann::json lobe{{"lobe", c->lobe},
                            {"rpm_search_min", c->rpmSearchMin},
                            {"rpm_search_max", c->rpmSearchMax},
                            {"peak_limit_rpm", c->peakLimitRpm},
                            {"peak_limit_depth_m", c->peakLimitDepthM}};
        if (a.depthMm > 0.0) {
            lobe["depth_m"] = co.depthM;
            if (c->bestRpm) {
                lobe["cost_optimal_rpm"] = *c->bestRpm;
                lobe["cost_dB"] = c->bestCostDb;
                lobe["gamma"] = c->gamma;
                lobe["lambda"] = c->lambdaAtBest;
                lobe["sigma"] = c->sigmaAtBest;
            } else {
                model::putUndefined(lobe, "cost_optimal_rpm", "unstable everywhere in this lobe at this depth");
            }
        }
        out["lobe_diagram"] = lobe;
    }
    return writeJsonResult(cmd, out, "");
}

const CliRegistrar kRegistrar{{
    "spindle-speed",
    "Lobe number and stable-pocket spindle speed from a chatter frequency (optionally with the SDM cost) → JSON",
    [](CLI::App& sub) -> std::function<int()> {
        auto a = std::make_shared<SpindleArgs>();
        sub.add_option("--chatter-hz", a->chatterHz, "measured chatter frequency [Hz]");
        sub.add_option("--in", a->in, "capture CSV to estimate the chatter frequency from (Kalman AR, spec §3.0.1)");
        sub.add_option("--signal", a->signal, "column of --in holding the vibration signal (e.g. accel_y_m_s2)");
        sub.add_option("--order", a->order, "AR order N_d for --in (2 per chatter frequency, default 2)");
        sub.add_option("--rpm", a->rpm, "current spindle speed [min^-1]")->required();
        sub.add_option("--teeth", a->teeth, "number of teeth")->required();
        sub.add_option("--tool", a->tool, "tool.json: adds the lobe diagram (pocket peak) of lobe rho");
        sub.add_option("--cut", a->cut, "cut.json (with --tool)");
        sub.add_option("--depth-mm", a->depthMm, "axial depth for the chapter-3 cost J (with --tool/--cut)");
        sub.add_option("--steps-per-period", a->steps, "SDM steps per tooth period (default 40)");
        return recordSessions(sub, [a] { return runSpindle(*a); });
    },
}};

}  // namespace
}  // namespace axistune::cli
