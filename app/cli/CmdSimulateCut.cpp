// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli simulate-cut: a milling cut with regeneration on a simulated feed axis (core/sim/Milling
// coupled to the AxisSimulator through its load-torque input), written as a capture CSV (docs/machining.md);
// with --avoid, a chatter-avoidance controller changes the spindle speed during the cut
// (core/avoidance/AvoidanceCut, docs/chatter-avoidance.md) and a JSON summary goes to stdout.
#include "app/cli/CliCommand.h"
#include "core/avoidance/AvoidanceCut.h"
#include "core/io/CaptureCsv.h"
#include "core/machining/MachiningJson.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Units.h"
#include "core/sim/CutSimulation.h"
#include "core/sim/MachineDefinition.h"
#include "core/sim/Milling.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {
namespace {

struct SimulateCutArgs {
    std::string machine, axis, tool, cut, out, summaryOut;
    double rpm = 0.0, depthM = 0.0, durationS = 1.0, feedPerToothM = 0.1e-3, engageS = 0.2;
    std::uint64_t seed = 1;
    bool lostMotion = false;
    // avoidance (docs/chatter-avoidance.md); the options given override the method's table defaults
    std::string avoid = "none", sensor, weights, toolBand;
    double ts = 0, rv = 0, rw = 0, p0 = 0, sigma = 0, hold = 0, hp = 0, lp = 0, costTarget = 0;
    int nd = 0, maxSteps = 0, below = 0, above = 0;
    double escPc = 0, escDither = 0, escCurv = 0, escStart = 0, escMin = 0, escMax = 0;
    double dobMass = 0, dobViscous = 0, dobQ = 0, dobLow = 0, dobHigh = 0;
    std::map<std::string, CLI::Option*> opts;
    bool given(const std::string& name) const
    {
        auto it = opts.find(name);
        return it != opts.end() && it->second->count() > 0;
    }
};

std::string num(double v)
{
    return model::formatNumber(v, 17);
}

std::optional<std::vector<double>> parseList(const std::string& text)
{
    std::vector<double> out;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const auto comma = text.find(',', pos);
        const auto item = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
        auto v = model::parseNumber(item);
        if (!v)
            return std::nullopt;
        out.push_back(*v);
        if (comma == std::string::npos)
            break;
        pos = comma + 1;
    }
    return out;
}

Status applyAvoidanceOptions(const SimulateCutArgs& a, avoidance::AvoidanceCutOptions& av)
{
    using avoidance::Method;
    using machining::AvoidanceSensor;
    const bool adaptiveLike = av.method == Method::Adaptive || av.method == Method::MultiMode;
    // Options that belong to another method are refused, not ignored.
    static const std::vector<std::string> adaptiveOnly = {"--ts-s",        "--nd",        "--rv",     "--rw",
                                                          "--p0",          "--sigma-th",  "--hold-s", "--max-steps",
                                                          "--highpass-hz", "--lowpass-hz"};
    static const std::vector<std::string> multiOnly = {"--weights", "--search-below", "--search-above",
                                                       "--cost-target"};
    static const std::vector<std::string> escOnly = {"--esc-pc",      "--esc-dither-rad-s", "--esc-curvature",
                                                     "--esc-start-s", "--esc-min-rpm",      "--esc-max-rpm"};
    static const std::vector<std::string> dobOnly = {"--dob-mass-kg", "--dob-viscous-ns-per-m", "--dob-q-hz",
                                                     "--dob-band-low-hz", "--dob-band-high-hz"};
    auto refuse = [&](const std::vector<std::string>& names, bool allowed, const std::string& why) -> Status {
        for (const auto& n : names)
            if (!allowed && a.given(n))
                return makeError(ErrorCode::BadInput, n + " " + why);
        return Status::success();
    };
    if (auto st = refuse(adaptiveOnly, adaptiveLike, "needs --avoid adaptive or multimode"); !st)
        return st;
    if (auto st = refuse(multiOnly, av.method == Method::MultiMode, "needs --avoid multimode"); !st)
        return st;
    if (auto st = refuse(escOnly, av.method == Method::Esc, "needs --avoid esc"); !st)
        return st;
    if (av.method == Method::None) {
        if (a.given("--sensor"))
            return makeError(ErrorCode::BadInput, "--sensor needs --avoid adaptive, multimode or esc");
        return refuse(dobOnly, false, "needs --sensor dob");
    }
    // The method's table defaults: adaptive Table 4 (DOB), with --sensor accel Table 3; multimode Table 5
    // (accelerometer); esc Table 6 (accelerometer cost a_y^2, or F_x^2 with --sensor dob).
    AvoidanceSensor sensor = av.method == Method::Adaptive ? AvoidanceSensor::Dob : AvoidanceSensor::Accelerometer;
    if (a.given("--sensor")) {
        if (a.sensor == "dob")
            sensor = AvoidanceSensor::Dob;
        else if (a.sensor == "accel")
            sensor = AvoidanceSensor::Accelerometer;
        else
            return makeError(ErrorCode::BadInput, "--sensor '" + a.sensor + "': must be dob or accel");
    }
    if (auto st = refuse(dobOnly, sensor == AvoidanceSensor::Dob, "needs --sensor dob"); !st)
        return st;
    if (auto st = refuse({"--tool-band"}, av.method == Method::Adaptive && sensor == AvoidanceSensor::Dob,
                         "needs --avoid adaptive with --sensor dob");
        !st)
        return st;
    avoidance::applyMethodDefaults(av, av.method, sensor);
    if (a.given("--tool-band")) {
        if (a.toolBand != "on" && a.toolBand != "off")
            return makeError(ErrorCode::BadInput, "--tool-band '" + a.toolBand + "': must be on or off");
        av.toolModeBand = a.toolBand == "on";
    }
    auto& o = av.adaptive;
    if (a.given("--ts-s"))
        o.samplePeriodS = a.ts;
    if (a.given("--nd"))
        o.kalman.order = a.nd;
    if (a.given("--rv"))
        o.kalman.rv = a.rv;
    if (a.given("--rw"))
        o.kalman.rw = a.rw;
    if (a.given("--p0"))
        o.kalman.p0 = a.p0;
    if (a.given("--sigma-th"))
        o.thresholdPower = a.sigma;
    if (a.given("--hold-s"))
        o.holdS = a.hold;
    if (a.given("--max-steps"))
        o.maxSteps = a.maxSteps;
    if (a.given("--highpass-hz"))
        o.highPassHz = a.hp;
    if (a.given("--lowpass-hz"))
        o.lowPassHz = a.lp;
    if (a.given("--weights")) {
        auto w = parseList(a.weights);
        if (!w)
            return makeError(ErrorCode::BadInput, "--weights '" + a.weights + "': a comma-separated list of numbers");
        o.weights = *w;
    }
    if (a.given("--search-below"))
        o.searchBelow = a.below;
    if (a.given("--search-above"))
        o.searchAbove = a.above;
    if (a.given("--cost-target"))
        o.costTarget = a.costTarget;
    if (av.method == Method::MultiMode && !a.given("--weights") && a.given("--nd")) {
        // default weights for another N_d: 1, 1/2, 1/3, ... (non-increasing)
        o.weights.clear();
        for (int j = 0; j < std::max(1, a.nd / 2); ++j)
            o.weights.push_back(1.0 / (j + 1));
    }
    auto& e = av.esc;
    if (a.given("--esc-pc"))
        e.pcRadS = a.escPc;
    if (a.given("--esc-dither-rad-s"))
        e.ditherRadS = a.escDither;
    if (a.given("--esc-curvature"))
        e.curvature = a.escCurv;
    if (a.given("--esc-start-s"))
        e.startS = a.escStart;
    if (av.method == Method::Esc) {
        if (!a.given("--esc-min-rpm") || !a.given("--esc-max-rpm"))
            return makeError(ErrorCode::BadInput,
                             "--avoid esc needs --esc-min-rpm and --esc-max-rpm (the speed bounds: without them the "
                             "thesis saw 1700 -> 700 rpm, spec §3.4.3)");
        e.minRpm = a.escMin;
        e.maxRpm = a.escMax;
        if (!(e.startS < a.durationS))
            return makeError(ErrorCode::OutOfRange, "--esc-start-s must be before the end of the cut (--duration-s)");
    }
    if (a.given("--dob-mass-kg"))
        av.dob.massKg = a.dobMass;
    if (a.given("--dob-viscous-ns-per-m"))
        av.dob.viscousNsPerM = a.dobViscous;
    if (a.given("--dob-q-hz"))
        av.dob.qCutoffHz = a.dobQ;
    if (a.given("--dob-band-low-hz"))
        av.dob.bandLowHz = a.dobLow;
    if (a.given("--dob-band-high-hz"))
        av.dob.bandHighHz = a.dobHigh;
    return Status::success();
}

nlohmann::json summaryJson(const SimulateCutArgs& a, const avoidance::AvoidanceCutOptions& av,
                           const avoidance::AvoidanceCutResult& r, const model::Capture& cap)
{
    nlohmann::json j;
    j["avoid"] = avoidance::methodName(av.method);
    const auto* n = cap.channel("spindle_speed_rpm");
    const double end = a.durationS;
    j["final_spindle_rpm"] = n && !n->data.empty() ? n->data.back() : a.rpm;
    const double t0 = std::max(a.engageS, end - 0.3);
    if (auto rms = avoidance::channelRms(cap, "tool_accel_y_m_s2", t0, end))
        j["accel_y_rms_last_0p3s_m_s2"] = *rms;
    if (n) {
        double lo = n->data.front(), hi = lo;
        for (double v : n->data)
            lo = std::min(lo, v), hi = std::max(hi, v);
        j["spindle_rpm_min"] = lo;
        j["spindle_rpm_max"] = hi;
    }
    j["spindle_command_limited"] = cap.metadata.textOr(model::meta::kSpindleCommandLimited, "0");
    if (av.method == avoidance::Method::None)
        return j;
    j["sensor"] = av.sensor == machining::AvoidanceSensor::Dob ? "dob" : "accelerometer";
    // onset: the trigger (adaptive, multimode) or the ESC start. Stable: the vibration fell (the level over the
    // last 0.3 s is at most 40 % of the largest 50 ms RMS after the onset) and from `settled_s` on the 50 ms RMS
    // stays below twice that final level; otherwise `settled` is false and settled_s absent (no stable speed
    // reached). Never triggered: `triggered` false, onset_s absent (the result writer refuses null).
    const double onset = av.method == avoidance::Method::Esc ? av.esc.startS : r.triggerTimeS;
    j["triggered"] = onset >= 0.0;
    j["settled"] = false;
    if (onset >= 0.0) {
        j["onset_s"] = onset;
        const double peak = avoidance::peakMovingRms(cap, "tool_accel_y_m_s2", std::max(0.0, onset - 0.05), 0.05);
        j["peak_rms_after_onset_m_s2"] = peak;
        if (auto rms = avoidance::channelRms(cap, "tool_accel_y_m_s2", t0, end); rms && *rms <= 0.4 * peak) {
            if (auto settled = avoidance::settledFrom(cap, "tool_accel_y_m_s2", onset, 0.05, 2.0 * *rms)) {
                j["settled"] = true;
                j["settled_s"] = *settled;
                j["onset_to_settled_s"] = std::max(0.0, *settled - onset);
            }
        }
    }
    if (av.method == avoidance::Method::Esc) {
        j["esc"] = {{"h_c_rad_s", r.escDesign.hcRadS},
                    {"h_c_Hz", r.escDesign.hcRadS / model::kTwoPi},
                    {"k_c_per_s", r.escDesign.kcPerS},
                    {"omega_p_rad_s", r.escDesign.omegaPRadS},
                    {"dither_Hz", r.escDesign.omegaPRadS / model::kTwoPi},
                    {"k_int", r.escIntegratorGain},
                    {"bound_hits", static_cast<double>(r.escBoundHits)},
                    {"min_rpm", av.esc.minRpm},
                    {"max_rpm", av.esc.maxRpm}};
        return j;
    }
    nlohmann::json steps = nlohmann::json::array();
    for (const auto& s : r.steps)
        steps.push_back({{"t_s", s.timeS},
                         {"from_rpm", s.fromRpm},
                         {"to_rpm", s.toRpm},
                         {"chatter_Hz", s.chatterHz},
                         {"rho_new", s.rhoNew},
                         {"rho", s.rho},
                         {"J_chat", s.cost},
                         {"cost_met", s.costMet}});
    j["steps"] = steps;
    return j;
}

int runSimulateCut(const SimulateCutArgs& a)
{
    const std::string cmd = "simulate-cut";
    auto def = a.machine.size() > 5 && a.machine.substr(a.machine.size() - 5) == ".json"
                   ? sim::loadMachineDefinitionFile(a.machine)
                   : sim::loadPreset(a.machine);
    if (!def)
        return reportError(cmd, makeError(ErrorCode::BadInput, "--machine '" + a.machine + "': " + def.error().detail));
    const auto* axisDef = def->axis(a.axis);
    if (!axisDef)
        return reportError(
            cmd, makeError(ErrorCode::NotFound, "--axis '" + a.axis + "': machine " + def->name + " has no such axis"));
    if (axisDef->kind != sim::AxisKind::Linear)
        return reportError(cmd,
                           makeError(ErrorCode::BadInput, "--axis '" + a.axis + "': a cut needs a linear feed axis"));
    auto tool = machining::readToolJsonFile(a.tool);
    if (!tool)
        return reportError(cmd, tool.error());
    auto cut = machining::readCutJsonFile(a.cut);
    if (!cut)
        return reportError(cmd, cut.error());
    if (!(a.durationS > 0.0) || a.durationS > 60.0)
        return reportError(
            cmd, makeError(ErrorCode::OutOfRange, "--duration-s must be in (0, 60] (got " + num(a.durationS) + ")"));
    if (!(a.engageS >= 0.0) || a.engageS >= a.durationS)
        return reportError(cmd, makeError(ErrorCode::OutOfRange, "--engage-s must be in [0, duration)"));

    sim::MillingSetup ms;
    for (const auto& m : tool->modesX)
        ms.modesX.push_back({m.massKg, m.dampingNsPerM, m.stiffnessNPerM});
    for (const auto& m : tool->modesY)
        ms.modesY.push_back({m.massKg, m.dampingNsPerM, m.stiffnessNPerM});
    ms.teeth = cut->teeth;
    ms.ktNPerM2 = cut->ktNPerM2;
    ms.krNPerM2 = cut->krNPerM2;
    ms.radialImmersion = cut->radialImmersion;
    ms.upMilling = cut->milling == machining::MillingDirection::Up;
    ms.spindleRpm = a.rpm;
    ms.axialDepthM = a.depthM;
    ms.feedPerToothM = a.feedPerToothM;
    ms.spindleTimeConstantS = cut->spindleTimeConstantS;
    ms.spindleMinRpm = cut->spindleMinRpm;
    ms.spindleMaxRpm = cut->spindleMaxRpm;
    avoidance::AvoidanceCutOptions av;
    av.cut.milling = ms;
    av.cut.durationS = a.durationS;
    av.cut.engageS = a.engageS;
    av.cut.lostMotion = a.lostMotion;
    av.cut.seed = a.seed;
    auto method = avoidance::parseMethod(a.avoid);
    if (!method)
        return reportError(cmd, method.error());
    av.method = *method;
    if (auto st = applyAvoidanceOptions(a, av); !st)
        return reportError(cmd, st.error());
    auto simulated = avoidance::runAvoidanceCut(*axisDef, av);
    if (!simulated)
        return reportError(cmd, makeError(simulated.error().code, "--tool/--cut/--rpm/--depth-m/avoidance options: " +
                                                                      simulated.error().detail));
    model::Capture cap = std::move(simulated->capture);
    cap.metadata.set(model::meta::kMachine, def->name);
    cap.metadata.set(model::meta::kConnection, "sim:" + def->name);
    cap.metadata.set(model::meta::kSpindleRpm, a.rpm);
    cap.metadata.set(model::meta::kAxialDepthM, a.depthM);
    cap.metadata.set("feed_per_tooth_m", a.feedPerToothM);
    cap.metadata.set("tooth_frequency_Hz", a.rpm * ms.teeth / 60.0);
    cap.metadata.set(model::meta::kEngageS, a.engageS);
    cap.metadata.set("spindle_time_constant_s", ms.spindleTimeConstantS);
    cap.metadata.set("spindle_limits_rpm", num(ms.spindleMinRpm) + ":" + num(ms.spindleMaxRpm));
    if (auto st = io::writeCaptureCsvFile(a.out, cap); !st)
        return reportError(cmd, st.error());
    if (av.method == avoidance::Method::None && a.summaryOut.empty())
        return 0;
    return writeJsonResult(cmd, summaryJson(a, av, *simulated, cap), a.summaryOut);
}

const CliRegistrar kRegistrar{{
    "simulate-cut",
    "Simulated milling cut with regeneration on a feed axis → capture CSV (feed-axis trace + cutting force)",
    [](CLI::App& sub) -> std::function<int()> {
        auto a = std::make_shared<SimulateCutArgs>();
        sub.add_option("--machine", a->machine, "machine preset (e.g. vmc) or machine .json file")->required();
        sub.add_option("--axis", a->axis, "linear feed axis (x = feed direction of the tool model)")->required();
        sub.add_option("--tool", a->tool, "tool.json (modes_x, modes_y)")->required();
        sub.add_option("--cut", a->cut, "cut.json (teeth, Kt_N_per_m2, Kr_N_per_m2, radial_immersion, milling)")
            ->required();
        sub.add_option("--rpm", a->rpm, "spindle speed [min^-1]")->required();
        sub.add_option("--depth-m", a->depthM, "axial depth of cut [m]")->required();
        sub.add_option("--duration-s", a->durationS, "traced machine time [s] (default 1)");
        sub.add_option("--engage-s", a->engageS, "time the tool enters the material [s] (default 0.2)");
        sub.add_option("--feed-per-tooth-m", a->feedPerToothM, "feed per tooth [m] (default 1e-4)");
        sub.add_option("--seed", a->seed, "simulator seed (default 1)");
        sub.add_flag("--lost-motion", a->lostMotion, "keep the quasi-static lost-motion deflection (default off)");
        sub.add_option("--out", a->out, "capture CSV to write")->required();
        auto& o = a->opts;
        sub.add_option("--avoid", a->avoid, "chatter avoidance: none (default), adaptive, multimode, esc");
        o["--sensor"] = sub.add_option("--sensor", a->sensor,
                                       "dob (feed-stage observer; adaptive default) or accel (tool accelerometer)");
        sub.add_option("--summary-out", a->summaryOut, "avoidance summary JSON (default stdout)");
        o["--ts-s"] = sub.add_option("--ts-s", a->ts, "estimator sample period t_s [s]");
        o["--nd"] = sub.add_option("--nd", a->nd, "AR order N_d (2 per chatter frequency)");
        o["--rv"] = sub.add_option("--rv", a->rv, "Kalman R_v (x I)");
        o["--rw"] = sub.add_option("--rw", a->rw, "Kalman R_w");
        o["--p0"] = sub.add_option("--p0", a->p0, "Kalman P[0] (x I)");
        o["--sigma-th"] = sub.add_option("--sigma-th", a->sigma, "trigger threshold on the filtered signal squared");
        o["--hold-s"] = sub.add_option("--hold-s", a->hold, "time between adaptation steps [s] (default 0.1)");
        o["--max-steps"] = sub.add_option("--max-steps", a->maxSteps, "adaptation step limit (default 5)");
        o["--highpass-hz"] = sub.add_option("--highpass-hz", a->hp, "pre-filter high-pass corner [Hz]");
        o["--lowpass-hz"] = sub.add_option("--lowpass-hz", a->lp, "pre-filter low-pass corner [Hz] (0: none)");
        o["--weights"] = sub.add_option("--weights", a->weights, "multimode weights w_j, e.g. 1,0.5");
        o["--search-below"] = sub.add_option("--search-below", a->below, "multimode search width below rho_new");
        o["--search-above"] = sub.add_option("--search-above", a->above, "multimode search width above rho_new");
        o["--cost-target"] = sub.add_option("--cost-target", a->costTarget, "multimode J_chat accepted (0.01)");
        o["--esc-pc"] = sub.add_option("--esc-pc", a->escPc, "ESC pole p_c [rad/s] (default 8*2*pi)");
        o["--esc-dither-rad-s"] = sub.add_option("--esc-dither-rad-s", a->escDither, "ESC dither a_c [rad/s] (1)");
        o["--esc-curvature"] = sub.add_option("--esc-curvature", a->escCurv, "ESC assumed curvature f'' (1e5)");
        o["--esc-start-s"] = sub.add_option("--esc-start-s", a->escStart, "ESC start [s] (default 5)");
        o["--esc-min-rpm"] = sub.add_option("--esc-min-rpm", a->escMin, "ESC lower speed bound [min^-1] (required)");
        o["--esc-max-rpm"] = sub.add_option("--esc-max-rpm", a->escMax, "ESC upper speed bound [min^-1] (required)");
        o["--dob-mass-kg"] = sub.add_option("--dob-mass-kg", a->dobMass, "DOB nominal stage mass M_tn [kg] (273)");
        o["--dob-viscous-ns-per-m"] = sub.add_option("--dob-viscous-ns-per-m", a->dobViscous, "DOB D_tn [N s/m] (1e4)");
        o["--dob-q-hz"] = sub.add_option("--dob-q-hz", a->dobQ, "DOB low-pass Q corner [Hz] (2000; esc 2500)");
        o["--dob-band-low-hz"] = sub.add_option("--dob-band-low-hz", a->dobLow, "DOB G_F lower corner [Hz] (1000)");
        o["--tool-band"] = sub.add_option("--tool-band", a->toolBand,
                                          "adaptive + dob: band-pass f_n +- f_TPE/2 before the estimator (on|off; on)");
        o["--dob-band-high-hz"] =
            sub.add_option("--dob-band-high-hz", a->dobHigh, "DOB G_F upper corner [Hz] (2000; 0 none)");
        return [a] { return runSimulateCut(*a); };
    },
}};

} // namespace
} // namespace axistune::cli
