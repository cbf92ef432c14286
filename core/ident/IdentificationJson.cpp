// SPDX-License-Identifier: GPL-3.0-or-later
// Identification result and controller JSON (docs/formats.md "Identification result").
#include "core/ident/IdentificationJson.h"

#include "core/model/InputLimits.h"
#include "core/model/ResultJson.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune::ident {
namespace {

// A value that is not finite is left out and named with the reason (docs/formats.md "Undefined values").
constexpr const char* kSingular = "not defined: the regression is singular";

Result<double> number(const nlohmann::json& j, const std::string& key, const std::string& src)
{
    if (!j.is_object() || !j.contains(key))
        return makeError(ErrorCode::BadInput, src + ": missing key '" + key + "'");
    const auto& v = j.at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
        return makeError(ErrorCode::BadInput, src + ": '" + key + "' is not a finite number");
    return v.get<double>();
}

} // namespace

const char* axisMotionName(AxisMotion m)
{
    return m == AxisMotion::Linear ? "linear" : "rotary";
}

nlohmann::json unitsJson(AxisMotion m)
{
    if (m == AxisMotion::Linear)
        return {{"position", "m"},    {"velocity", "m/s"}, {"force", "N"}, {"inertia", "kg"},
                {"viscous", "N*s/m"}, {"coulomb", "N"},    {"offset", "N"}};
    return {{"position", "rad"},      {"velocity", "rad/s"}, {"force", "N*m"}, {"inertia", "kg*m^2"},
            {"viscous", "N*m*s/rad"}, {"coulomb", "N*m"},    {"offset", "N*m"}};
}

nlohmann::json estimateJson(const Estimate& e)
{
    nlohmann::json j = nlohmann::json::object();
    model::putNumber(j, "value", e.value, kSingular);
    model::putNumber(j, "std", e.std, "not defined: no residual degrees of freedom or a singular covariance");
    model::putNumber(j, "std_pct", e.stdPct(), "not defined: the value is 0 or has no standard deviation");
    return j;
}

nlohmann::json identificationToJson(const IdentificationResult& r, AxisMotion motion)
{
    nlohmann::json j;
    j["format"] = kIdentificationFormat;
    j["version"] = kIdentificationVersion;
    j["model"] = "force = inertia*a + viscous*v + coulomb*sign(v) + offset";
    j["axis"] = axisMotionName(motion);
    j["units"] = unitsJson(motion);
    j["inertia"] = estimateJson(r.inertia);
    j["viscous"] = estimateJson(r.viscous);
    j["coulomb"] = estimateJson(r.coulomb);
    j["offset"] = estimateJson(r.offset);
    model::putNumber(j, "condition_number", r.condition, kSingular);
    model::putNumber(j, "condition_number_scaled", r.scaledCondition, kSingular);
    model::putNumber(j, "residual_rms", r.residualRms, kSingular);
    model::putNumber(j, "residual_rel_pct", r.residualRelPct, "not defined: the force has no variation");
    j["method"] = {{"sample_rate_Hz", r.sampleRateHz},
                   {"decimation", r.decimation},
                   {"border_samples", r.borderSamples},
                   {"equations", r.rows},
                   {"min_speed", r.minSpeed},
                   {"moving_forward_pct", 100.0 * r.positiveFraction},
                   {"moving_backward_pct", 100.0 * r.negativeFraction}};
    if (r.asymmetric) {
        const auto& a = *r.asymmetric;
        j["asymmetric"] = {{"model", "force = inertia*a + viscous_positive*max(v,0) + viscous_negative*min(v,0) "
                                     "+ coulomb_positive*[v>0] - coulomb_negative*[v<0]"},
                           {"note", "the offset is not separable from per-direction Coulomb friction: "
                                    "(coulomb_positive - coulomb_negative)/2 contains it"},
                           {"inertia", estimateJson(a.inertia)},
                           {"viscous_positive", estimateJson(a.viscousPositive)},
                           {"viscous_negative", estimateJson(a.viscousNegative)},
                           {"coulomb_positive", estimateJson(a.coulombPositive)},
                           {"coulomb_negative", estimateJson(a.coulombNegative)}};
        model::putNumber(j["asymmetric"], "residual_rms", a.residualRms, kSingular);
        model::putNumber(j["asymmetric"], "condition_number_scaled", a.scaledCondition, kSingular);
    }
    return j;
}

nlohmann::json validationToJson(const ValidationResult& v)
{
    nlohmann::json j{{"first_sample", v.firstSample}};
    const char* diverged = "not defined: the simulation did not give finite positions";
    model::putNumber(j, "position_error_rms", v.positionErrorRms, diverged);
    model::putNumber(j, "position_error_max", v.positionErrorMax, diverged);
    model::putNumber(j, "position_error_pct_of_motion_rms", v.positionErrorPctOfMotion,
                     "not defined: the record has no motion");
    model::putNumber(j, "benchmark_rel_err_position_pct", v.benchmarkPositionPct,
                     "not defined: the measured position has no energy");
    model::putNumber(j, "benchmark_rel_err_force_pct", v.benchmarkForcePct,
                     "not defined: the measured force has no energy");
    return j;
}

nlohmann::json controllerToJson(const PositionController& c)
{
    return {{"kp_per_s", c.kpPerS},
            {"kv", c.kv},
            {"saturation", c.saturation},
            {"delay_samples", c.delaySamples},
            {"force_scale", c.forceScale}};
}

Result<PositionController> controllerFromJson(const nlohmann::json& j, const std::string& src)
{
    PositionController c;
    for (const auto& [key, dst] : {std::pair{"kp_per_s", &c.kpPerS}, std::pair{"kv", &c.kv},
                                   std::pair{"saturation", &c.saturation}, std::pair{"force_scale", &c.forceScale}}) {
        auto v = number(j, key, src);
        if (!v)
            return v.error();
        *dst = *v;
    }
    auto d = number(j, "delay_samples", src);
    if (!d)
        return d.error();
    if (*d < 0.0 || *d > 100.0 || std::floor(*d) != *d)
        return makeError(ErrorCode::OutOfRange, src + ": 'delay_samples' must be an integer in 0..100");
    c.delaySamples = static_cast<int>(*d);
    if (!(c.saturation > 0.0))
        return makeError(ErrorCode::OutOfRange, src + ": 'saturation' must be > 0");
    if (!(c.forceScale > 0.0))
        return makeError(ErrorCode::OutOfRange, src + ": 'force_scale' must be > 0");
    return c;
}

Result<IdentifiedModel> identifiedModelFromJson(const nlohmann::json& j, const std::string& src)
{
    // Typed look-ups only: json::value() throws when the key holds another type.
    const auto text = [&j](const char* key) {
        return j.contains(key) && j.at(key).is_string() ? j.at(key).get<std::string>() : std::string();
    };
    if (!j.is_object() || text("format") != kIdentificationFormat)
        return makeError(ErrorCode::BadInput,
                         src + ": not an identification result (format must be '" + kIdentificationFormat + "')");
    if (!j.contains("version") || !j.at("version").is_number_integer() ||
        j.at("version").get<long long>() != kIdentificationVersion)
        return makeError(ErrorCode::BadInput, src + ": unsupported identification version");
    IdentifiedModel m;
    const std::string axis = text("axis");
    if (axis != "linear" && axis != "rotary")
        return makeError(ErrorCode::BadInput, src + ": 'axis' must be linear or rotary");
    m.motion = axis == "linear" ? AxisMotion::Linear : AxisMotion::Rotary;
    double vals[4] = {};
    const char* keys[4] = {"inertia", "viscous", "coulomb", "offset"};
    for (int i = 0; i < 4; ++i) {
        if (!j.contains(keys[i]))
            return makeError(ErrorCode::BadInput, src + ": missing '" + keys[i] + "'");
        auto v = number(j.at(keys[i]), "value", src + ", '" + keys[i] + "'");
        if (!v)
            return v.error();
        vals[i] = *v;
    }
    if (!(vals[0] > 0.0) || vals[1] < 0.0 || vals[2] < 0.0)
        return makeError(ErrorCode::OutOfRange, src + ": inertia must be > 0 and viscous and Coulomb friction >= 0");
    m.model = RigidBodyModel::symmetric(vals[0], vals[1], vals[2], vals[3]);
    return m;
}

Result<IdentifiedModel> readIdentifiedModelFile(const std::string& path)
{
    // Regular file, size, depth and number limits (docs/robustness.md).
    auto j = model::readJsonFile(path);
    if (!j)
        return j.error();
    return identifiedModelFromJson(*j, model::displayPath(path));
}

} // namespace axistune::ident
