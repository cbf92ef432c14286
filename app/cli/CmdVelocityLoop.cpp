// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli velocity-loop: the velocity PI (chapter 5 rule on J_m, or margins on a measured FRF), the predicted
// open loop with its margins before and after, the position gain with its stability limit and the predicted
// velocity step: the rules of the velocity-loop wizard (core/tuning/VelocityLoopDesign.h; docs/tuning.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/device/ModbusDrive.h"
#include "core/io/FrfCsv.h"
#include "core/model/InputLimits.h"
#include "core/model/MetadataKeys.h"
#include "core/model/ResultJson.h"
#include "core/tuning/VelocityLoopDesign.h"
#include "core/tuning/VelocityLoopDesignJson.h"

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct VelocityLoopOptions {
    std::string method = "auto";
    std::string frfPath;
    std::string measurement;
    std::string modelPath;
    std::string connect;
    std::string axis;
    std::uint64_t seed = 1;
    double jm = 0.0;
    double bandwidthHz = tuning::kDefaultVelocityBandwidthHz;
    double k = tuning::kDefaultVelocityGainFactor;
    double crossoverHz = 40.0;
    double phaseMarginDeg = 50.0;
    std::vector<double> loopPi;
    double velocityPeriodS = 0.0;
    double currentPeriodS = 0.0;
    double positionKp = -1.0;
    double stepRadS = 10.0;
    double stepDurationS = 0.2;
    bool withPositionGain = false;
    std::string outPath;
};

/// A fitted two-inertia model: the JSON of `axistune-cli two-inertia` (Jm_kgm2, JL_kgm2, K_Nm_per_rad,
/// C_Nms_per_rad, delay_s).
Result<tuning::TwoInertiaParams> readModel(const std::string& path)
{
    auto parsed = model::readJsonFile(path);
    if (!parsed)
        return parsed.error();
    const nlohmann::json& j = *parsed;
    if (!j.is_object())
        return makeError(ErrorCode::BadInput, path + ": expected the JSON object of axistune-cli two-inertia");
    tuning::TwoInertiaParams p;
    for (const auto& [key, dst, positive] : {std::tuple<const char*, double*, bool>{"Jm_kgm2", &p.jmKgm2, true},
                                             {"JL_kgm2", &p.jlKgm2, true},
                                             {"K_Nm_per_rad", &p.kNmPerRad, true},
                                             {"C_Nms_per_rad", &p.cNmsPerRad, false},
                                             {"delay_s", &p.delayS, false}}) {
        if (!j.contains(key) || !j[key].is_number())
            return makeError(ErrorCode::BadInput, path + ": field '" + key + "' missing or not a number");
        const double v = j[key].get<double>();
        if (!std::isfinite(v) || (positive ? !(v > 0.0) : v < 0.0))
            return makeError(ErrorCode::BadInput,
                             path + ": field '" + key + "' must be " + (positive ? "> 0" : ">= 0"));
        *dst = v;
    }
    return p;
}

int runVelocityLoop(const VelocityLoopOptions& o)
{
    const std::string cmd = "velocity-loop";
    auto bad = [&](const std::string& what) { return reportError(cmd, makeError(ErrorCode::BadInput, what)); };
    tuning::VelocityLoopRequest req;
    std::string method = o.method;
    if (method == "auto")
        method = o.frfPath.empty() ? "inertia" : "margins";
    if (method != "inertia" && method != "margins")
        return bad("--method must be inertia, margins or auto (got '" + o.method + "')");
    req.method =
        method == "margins" ? tuning::VelocityLoopRequest::Method::Frf : tuning::VelocityLoopRequest::Method::Inertia;
    if (req.method == tuning::VelocityLoopRequest::Method::Frf && o.frfPath.empty())
        return bad("--method margins needs --frf FILE (a measured velocity-loop or plant FRF)");
    if (req.method == tuning::VelocityLoopRequest::Method::Inertia && !o.frfPath.empty())
        return bad("--frf is for --method margins; the inertia rule takes --jm or --model");
    if (!o.loopPi.empty() && o.loopPi.size() != 2)
        return bad("--loop-pi needs KP,KI");
    // The loop as it runs: from the drive, or from the options.
    double jmDrive = 0.0;
    bool haveRunning = false;
    req.velocityPeriodS = 250e-6;
    req.currentPeriodS = 62.5e-6;
    nlohmann::json source = nlohmann::json::object();
    if (!o.connect.empty()) {
        if (o.axis.empty())
            return bad("--connect needs --axis");
        auto drive = device::connectAny({o.connect, o.seed});
        if (!drive)
            return reportError(cmd, drive.error());
        const std::vector<std::string> keys{"velocity.kp",    "velocity.ki", "velocity.period",
                                            "current.period", "position.kp", "velocity.inertia"};
        auto values = (*drive)->readParameters(o.axis, keys);
        if (!values)
            return reportError(cmd, values.error());
        auto get = [&](const char* key) -> Result<double> {
            const auto it = values->find(key);
            if (it == values->end() || !std::isfinite(it->second))
                return makeError(ErrorCode::Device, o.connect + " axis " + o.axis + ": the drive did not give " + key);
            return it->second;
        };
        for (const auto& [key, dst] : {std::pair<const char*, double*>{"velocity.kp", &req.running.kpNmsPerRad},
                                       {"velocity.ki", &req.running.kiNmPerRad},
                                       {"velocity.period", &req.velocityPeriodS},
                                       {"current.period", &req.currentPeriodS},
                                       {"position.kp", &req.positionKpRunning}}) {
            auto v = get(key);
            if (!v)
                return reportError(cmd, v.error());
            *dst = *v;
        }
        if (auto v = get("velocity.inertia"))
            jmDrive = *v;
        haveRunning = true;
        source = {{"connection", o.connect}, {"axis", o.axis}};
    }
    if (!o.loopPi.empty()) {
        req.running = {o.loopPi[0], o.loopPi[1]};
        haveRunning = true;
    }
    if (o.velocityPeriodS > 0.0)
        req.velocityPeriodS = o.velocityPeriodS;
    if (o.currentPeriodS > 0.0)
        req.currentPeriodS = o.currentPeriodS;
    if (o.velocityPeriodS < 0.0 || o.currentPeriodS < 0.0 || !std::isfinite(o.velocityPeriodS) ||
        !std::isfinite(o.currentPeriodS))
        return bad("--velocity-period-s and --current-period-s must be > 0");
    if (o.positionKp >= 0.0)
        req.positionKpRunning = o.positionKp;
    if (!haveRunning)
        return bad("the running velocity PI is needed for the margins before and for a closed-loop FRF: "
                   "--connect C --axis A, or --loop-pi KP,KI");
    // The model and J_m.
    if (!o.modelPath.empty()) {
        auto m = readModel(o.modelPath);
        if (!m)
            return reportError(cmd, m.error());
        req.model = *m;
    }
    req.jmKgm2 = o.jm > 0.0 ? o.jm : req.model ? req.model->jmKgm2 : jmDrive;
    if (!(o.jm >= 0.0) || !std::isfinite(o.jm))
        return bad("--jm must be > 0");
    if (!(req.jmKgm2 > 0.0))
        return bad("the motor-side inertia J_m is needed (the rule and the prediction model): --jm, --model "
                   "two-inertia.json, or a drive whose velocity.inertia is > 0");
    req.omegaLHz = o.bandwidthHz;
    req.k = o.k;
    req.crossoverHz = o.crossoverHz;
    req.phaseMarginDeg = o.phaseMarginDeg;
    req.stepRadS = o.stepRadS;
    req.stepDurationS = o.stepDurationS;
    nlohmann::json frfJson;
    if (!o.frfPath.empty()) {
        auto read = io::readFrfCsvFile(o.frfPath);
        if (!read)
            return reportError(cmd, read.error());
        dsp::FrequencyResponse frf = std::move(read).value();
        if (!o.measurement.empty()) {
            auto kind = tuning::parseLoopMeasurement(o.measurement);
            if (!kind)
                return bad("--measurement: " + kind.error().detail);
            frf.metadata.set(model::meta::kMeasurement, std::string(tuning::loopMeasurementName(*kind)));
        } else if (!frf.metadata.contains(model::meta::kMeasurement)) {
            return bad(o.frfPath + ": no 'measurement' key says what the FRF is; give --measurement plant|open|"
                                   "complementary|neg-complementary|sensitivity");
        } else if (auto kind = tuning::loopMeasurementOf(frf, tuning::LoopMeasurementKind::Plant); !kind) {
            return bad(o.frfPath + ": " + kind.error().detail);
        }
        frfJson = {{"file", o.frfPath}, {"measurement", *frf.metadata.text(model::meta::kMeasurement)}};
        req.measured = std::move(frf);
    }
    auto design = tuning::designVelocityLoop(req);
    if (!design) {
        const std::string where = o.frfPath.empty() ? "" : o.frfPath + ": ";
        return reportError(cmd, Error{design.error().code, where + design.error().detail});
    }
    const auto& d = *design;
    nlohmann::json j;
    j["method"] = method;
    j["proposal"] = tuning::velocityLoopProposalJson(d);
    j["running"] = {{"velocity_kp_Nms_per_rad", req.running.kpNmsPerRad},
                    {"velocity_ki_Nm_per_rad", req.running.kiNmPerRad},
                    {"position_kp_per_s", req.positionKpRunning},
                    {"velocity_period_s", req.velocityPeriodS},
                    {"current_period_s", req.currentPeriodS}};
    if (!source.empty())
        j["drive"] = source;
    if (method == "inertia")
        j["inertia_rule"] = {{"Jm_kgm2", req.jmKgm2}, {"bandwidth_Hz", req.omegaLHz}, {"k", req.k}};
    else
        j["margins_rule"] = {{"crossover_Hz", req.crossoverHz},
                             {"phase_margin_deg", req.phaseMarginDeg},
                             {"frf", frfJson},
                             {"lines_used", d.fHz.size()}};
    j["model"] = {{"kind", d.rigidModel ? "rigid" : "two-inertia"},
                  {"Jm_kgm2", d.model.jmKgm2},
                  {"delay_s", d.model.delayS},
                  {"note", d.modelNote}};
    if (!d.rigidModel) {
        j["model"]["JL_kgm2"] = d.model.jlKgm2;
        j["model"]["K_Nm_per_rad"] = d.model.kNmPerRad;
        j["model"]["C_Nms_per_rad"] = d.model.cNmsPerRad;
    }
    j["position_gain_rule"] = d.positionRule;
    nlohmann::json step{{"step_rad_s", req.stepRadS}, {"duration_s", req.stepDurationS}};
    const char* noPrediction = "the step could not be predicted on the model";
    model::putOptional(step, "overshoot_before_pct",
                       d.predictedBefore ? tuning::stepOvershootPct(
                                               tuning::normalisedStep(*d.predictedBefore, req.stepRadS, d.stepTimeS))
                                         : std::nullopt,
                       1.0, noPrediction);
    model::putOptional(step, "overshoot_after_pct",
                       d.predictedAfter ? tuning::stepOvershootPct(
                                              tuning::normalisedStep(*d.predictedAfter, req.stepRadS, d.stepTimeS))
                                        : std::nullopt,
                       1.0, noPrediction);
    j["step_prediction"] = step;
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [key, v] : tuning::velocityLoopParameters(d, o.withPositionGain))
        params[key] = v;
    j["parameters"] = params;
    return writeJsonResult(cmd, j, o.outPath);
}

const CliRegistrar kRegistrar{CliCommand{
    "velocity-loop",
    "Velocity PI from J_m (chapter 5 rule) or from margins on a measured FRF, margins before/after, position gain",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<VelocityLoopOptions>();
        sub.add_option("--method", o->method,
                       "inertia (K_P = k*sqrt2*omega_l*J_m, K_I = k*omega_l^2*J_m), margins (crossover and phase "
                       "margin on --frf) or auto (margins when --frf is given; default)");
        sub.add_option("--frf", o->frfPath, "measured FRF CSV for --method margins");
        sub.add_option("--measurement", o->measurement,
                       "what --frf is when its file does not say (measurement= key): plant, open, complementary, "
                       "neg-complementary, sensitivity; overrides the file");
        sub.add_option("--model", o->modelPath,
                       "JSON of axistune-cli two-inertia: the prediction model (and J_m unless --jm)");
        sub.add_option("--connect", o->connect,
                       connectOptionHelp() + "; reads the running loop (velocity.kp/ki, "
                                             "periods, position.kp, velocity.inertia)");
        sub.add_option("--axis", o->axis, "axis of --connect");
        sub.add_option("--seed", o->seed, "noise seed of an embedded simulated machine");
        sub.add_option("--jm", o->jm,
                       "motor-side inertia J_m [kg*m^2] (default: --model, else the drive's "
                       "velocity.inertia)");
        sub.add_option("--bandwidth-hz", o->bandwidthHz, "inertia rule: omega_l/2pi for k = 1 (default 24)");
        sub.add_option("--k", o->k, "inertia rule: gain factor k (default 10)");
        sub.add_option("--crossover-hz", o->crossoverHz, "margins rule: gain crossover [Hz] (default 40)");
        sub.add_option("--phase-margin-deg", o->phaseMarginDeg, "margins rule: phase margin [deg] (default 50)");
        sub.add_option("--loop-pi", o->loopPi,
                       "KP,KI of the running velocity PI [Nm*s/rad, Nm/rad] (overrides "
                       "the drive's)")
            ->delimiter(',')
            ->expected(2);
        sub.add_option("--velocity-period-s", o->velocityPeriodS,
                       "velocity-loop period (default: the drive's, "
                       "else 250e-6)");
        sub.add_option("--current-period-s", o->currentPeriodS,
                       "current-loop period (default: the drive's, "
                       "else 62.5e-6)");
        sub.add_option("--position-kp", o->positionKp, "running position gain [1/s] (default: the drive's, else 0)");
        sub.add_option("--step", o->stepRadS, "predicted velocity step [rad/s] (default 10)");
        sub.add_option("--step-duration", o->stepDurationS, "predicted step record [s] (default 0.2)");
        sub.add_flag("--with-position-gain", o->withPositionGain,
                     "put the recommended position.kp into \"parameters\" too");
        sub.add_option("--out", o->outPath, "write the JSON to this file instead of stdout");
        return recordSessions(sub, [o] { return runVelocityLoop(*o); });
    }}};

} // namespace

} // namespace axistune::cli
