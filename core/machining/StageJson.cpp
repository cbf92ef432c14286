// SPDX-License-Identifier: GPL-3.0-or-later
// Reader of stage.json (docs/machining.md): stage parameters and the options of the cutting force observer
// and the chatter detection.
#include "core/machining/StageJson.h"

#include "core/model/InputLimits.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

namespace axistune::machining {
namespace {

using nlohmann::json;

Status onlyKeys(const json& obj, const std::set<std::string>& allowed, const std::string& where)
{
    for (const auto& [k, v] : obj.items()) {
        if (!allowed.count(k) && k.rfind("_comment", 0) != 0)
            return makeError(ErrorCode::BadInput, where + ": unknown key '" + k + "'");
    }
    return Status::success();
}

/// Reads obj[key] into out; `required` false keeps out when absent. min/max: allowed range (inclusive).
Status num(const json& obj, const std::string& key, const std::string& where, double& out, bool required,
           double lo = -INFINITY, double hi = INFINITY, bool loOpen = false)
{
    if (!obj.contains(key)) {
        if (required)
            return makeError(ErrorCode::BadInput, where + ": missing key '" + key + "'");
        return Status::success();
    }
    const auto& v = obj.at(key);
    if (!v.is_number())
        return makeError(ErrorCode::BadInput, where + ", key '" + key + "': not a number");
    const double d = v.get<double>();
    if (!std::isfinite(d) || d < lo || d > hi || (loOpen && d <= lo))
        return makeError(ErrorCode::OutOfRange, where + ", key '" + key + "': " + std::to_string(d) + " is outside " +
                                                    (loOpen ? "(" : "[") + std::to_string(lo) + ", " +
                                                    std::to_string(hi) + "]");
    out = d;
    return Status::success();
}

Status flag(const json& obj, const std::string& key, const std::string& where, bool& out)
{
    if (!obj.contains(key))
        return Status::success();
    if (!obj.at(key).is_boolean())
        return makeError(ErrorCode::BadInput, where + ", key '" + key + "': must be true or false");
    out = obj.at(key).get<bool>();
    return Status::success();
}

Result<const json*> object(const json& j, const std::string& key, const std::string& src, bool required)
{
    if (!j.contains(key)) {
        if (required)
            return makeError(ErrorCode::BadInput, src + ": missing key '" + key + "'");
        return static_cast<const json*>(nullptr);
    }
    if (!j.at(key).is_object())
        return makeError(ErrorCode::BadInput, src + ", key '" + key + "': must be an object");
    return &j.at(key);
}

#define AXT_TRY(expr)                                                                                                  \
    do {                                                                                                               \
        if (auto st_ = (expr); !st_)                                                                                   \
            return st_.error();                                                                                        \
    } while (0)

Status readSide(const json& o, const std::string& where, double& j, double& b, double& c)
{
    AXT_TRY(onlyKeys(o, {"inertia_kgm2", "viscous_Nms_per_rad", "coulomb_Nm"}, where));
    AXT_TRY(num(o, "inertia_kgm2", where, j, true, 0.0, INFINITY, true));
    AXT_TRY(num(o, "viscous_Nms_per_rad", where, b, false, 0.0));
    AXT_TRY(num(o, "coulomb_Nm", where, c, false, 0.0));
    return Status::success();
}

Status readRls(const json& o, const std::string& w, SwitchingRlsOptions& r)
{
    AXT_TRY(onlyKeys(o,
                     {"method", "q_rls_cutoff_Hz", "window_L", "lambda", "p0", "trace_max", "accel_threshold_rad_s2",
                      "match_q", "handover", "commit_at_end", "repair_covariance"},
                     w));
    if (o.contains("method")) {
        const auto m = o.at("method").is_string() ? o.at("method").get<std::string>() : std::string("?");
        if (m == "switching")
            r.method = RlsMethod::Switching;
        else if (m == "conventional")
            r.method = RlsMethod::Conventional;
        else if (m == "fixed")
            r.method = RlsMethod::Fixed;
        else
            return makeError(ErrorCode::BadInput,
                             w + ", key 'method': must be \"switching\", \"conventional\" or \"fixed\"");
    }
    if (o.contains("handover")) {
        const auto m = o.at("handover").is_string() ? o.at("handover").get<std::string>() : std::string("?");
        if (m == "shadow")
            r.handover = Handover::Shadow;
        else if (m == "substitute")
            r.handover = Handover::Substitute;
        else
            return makeError(ErrorCode::BadInput, w + ", key 'handover': must be \"shadow\" or \"substitute\"");
    }
    double windowL = r.windowL;
    AXT_TRY(num(o, "q_rls_cutoff_Hz", w, r.qRlsCutoffHz, false, 0.0, INFINITY, true));
    AXT_TRY(num(o, "window_L", w, windowL, false, 1.0, 1e7));
    if (windowL != std::floor(windowL))
        return makeError(ErrorCode::BadInput, w + ", key 'window_L': must be a whole number");
    r.windowL = static_cast<int>(windowL);
    AXT_TRY(num(o, "lambda", w, r.lambda, false, 0.0, 1.0, true));
    AXT_TRY(num(o, "p0", w, r.p0, false, 0.0, INFINITY, true));
    AXT_TRY(num(o, "trace_max", w, r.traceMax, false, 0.0));
    AXT_TRY(num(o, "accel_threshold_rad_s2", w, r.accelThreshold, false, 0.0));
    AXT_TRY(flag(o, "match_q", w, r.matchQ));
    AXT_TRY(flag(o, "commit_at_end", w, r.commitAtEnd));
    AXT_TRY(flag(o, "repair_covariance", w, r.repairCovariance));
    return Status::success();
}

Status readChatter(const json& o, const std::string& w, ChatterDetectOptions& c)
{
    AXT_TRY(onlyKeys(o,
                     {"lowpass_Hz", "highpass_Hz", "window_s", "inertial_scale_w", "energy_floor", "min_duration_s",
                      "merge_gap_s", "baseline_s", "baseline_factor"},
                     w));
    AXT_TRY(num(o, "lowpass_Hz", w, c.lowPassHz, false, 0.0, INFINITY, true));
    AXT_TRY(num(o, "highpass_Hz", w, c.highPassHz, false, 0.0, INFINITY, true));
    AXT_TRY(num(o, "window_s", w, c.windowS, false, 0.0, INFINITY, true));
    AXT_TRY(num(o, "inertial_scale_w", w, c.inertialScale, false, 0.0));
    AXT_TRY(num(o, "energy_floor", w, c.energyFloor, false, 0.0));
    AXT_TRY(num(o, "min_duration_s", w, c.minDurationS, false, 0.0));
    AXT_TRY(num(o, "merge_gap_s", w, c.mergeGapS, false, 0.0));
    AXT_TRY(num(o, "baseline_s", w, c.baselineS, false, 0.0));
    AXT_TRY(num(o, "baseline_factor", w, c.baselineFactor, false, 0.0, INFINITY, true));
    return Status::success();
}

} // namespace

double StageDescription::leadMPerRad() const
{
    return leadMPerRev / (2.0 * std::numbers::pi);
}

TwoMassStage StageDescription::twoMass() const
{
    const double r = leadMPerRad(), r2 = r * r;
    return {motor.inertia / r2, load.inertia / r2, couplingStiffnessNmPerRad / r2, couplingDampingNmsPerRad / r2};
}

Result<StageDescription> parseStageJson(const std::string& text, const std::string& src)
{
    auto parsed = model::parseJsonText(text, src);
    if (!parsed)
        return parsed.error();
    const json& j = *parsed;
    if (!j.is_object())
        return makeError(ErrorCode::BadInput, src + ": the top level must be a JSON object");
    AXT_TRY(onlyKeys(
        j,
        {"screw_lead_m_per_rev", "torque_constant_Nm_per_A", "motor", "load", "coupling", "observer", "rls", "chatter"},
        src));
    StageDescription d;
    AXT_TRY(num(j, "screw_lead_m_per_rev", src, d.leadMPerRev, true, 0.0, 10.0, true));
    AXT_TRY(num(j, "torque_constant_Nm_per_A", src, d.torqueConstantNmPerA, true, 0.0, 1e4, true));
    auto motor = object(j, "motor", src, true);
    if (!motor)
        return motor.error();
    AXT_TRY(readSide(**motor, src + ", motor", d.motor.inertia, d.motor.viscous, d.motor.coulomb));
    auto load = object(j, "load", src, true);
    if (!load)
        return load.error();
    AXT_TRY(readSide(**load, src + ", load", d.load.inertia, d.load.viscous, d.load.coulomb));
    auto coupling = object(j, "coupling", src, false);
    if (!coupling)
        return coupling.error();
    if (*coupling) {
        const std::string w = src + ", coupling";
        AXT_TRY(onlyKeys(**coupling, {"stiffness_Nm_per_rad", "damping_Nms_per_rad"}, w));
        AXT_TRY(num(**coupling, "stiffness_Nm_per_rad", w, d.couplingStiffnessNmPerRad, true, 0.0, INFINITY, true));
        AXT_TRY(num(**coupling, "damping_Nms_per_rad", w, d.couplingDampingNmsPerRad, false, 0.0));
        d.hasCoupling = true;
    }
    auto obs = object(j, "observer", src, false);
    if (!obs)
        return obs.error();
    if (*obs) {
        const std::string w = src + ", observer";
        AXT_TRY(onlyKeys(**obs, {"q_cutoff_Hz", "sign_deadband_rad_s"}, w));
        AXT_TRY(num(**obs, "q_cutoff_Hz", w, d.observer.qCutoffHz, false, 0.0, INFINITY, true));
        AXT_TRY(num(**obs, "sign_deadband_rad_s", w, d.observer.signDeadbandRadS, false, 0.0));
    }
    d.rls.qCutoffHz = d.observer.qCutoffHz;
    d.rls.signDeadbandRadS = d.observer.signDeadbandRadS;
    auto rls = object(j, "rls", src, false);
    if (!rls)
        return rls.error();
    if (*rls)
        AXT_TRY(readRls(**rls, src + ", rls", d.rls));
    auto ch = object(j, "chatter", src, false);
    if (!ch)
        return ch.error();
    if (*ch)
        AXT_TRY(readChatter(**ch, src + ", chatter", d.chatter));
    return d;
}

Result<StageDescription> readStageJsonFile(const std::string& path)
{
    auto text = model::readInputFile(path);
    if (!text)
        return text.error();
    return parseStageJson(*text, path);
}

} // namespace axistune::machining
