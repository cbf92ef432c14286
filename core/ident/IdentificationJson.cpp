// SPDX-License-Identifier: GPL-3.0-or-later
// Identification result and controller JSON (docs/formats.md "Identification result").
#include "core/ident/IdentificationJson.h"

#include <cmath>
#include <fstream>

namespace axistune::ident {
namespace {

nlohmann::json finite(double v)
{
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

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
    return {{"value", finite(e.value)}, {"std", finite(e.std)}, {"std_pct", finite(e.stdPct())}};
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
    j["condition_number"] = finite(r.condition);
    j["condition_number_scaled"] = finite(r.scaledCondition);
    j["residual_rms"] = finite(r.residualRms);
    j["residual_rel_pct"] = finite(r.residualRelPct);
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
                           {"coulomb_negative", estimateJson(a.coulombNegative)},
                           {"residual_rms", finite(a.residualRms)},
                           {"condition_number_scaled", finite(a.scaledCondition)}};
    }
    return j;
}

nlohmann::json validationToJson(const ValidationResult& v)
{
    return {{"first_sample", v.firstSample},
            {"position_error_rms", finite(v.positionErrorRms)},
            {"position_error_max", finite(v.positionErrorMax)},
            {"position_error_pct_of_motion_rms", finite(v.positionErrorPctOfMotion)},
            {"benchmark_rel_err_position_pct", finite(v.benchmarkPositionPct)},
            {"benchmark_rel_err_force_pct", finite(v.benchmarkForcePct)}};
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
    if (!j.is_object() || j.value("format", std::string()) != kIdentificationFormat)
        return makeError(ErrorCode::BadInput,
                         src + ": not an identification result (format must be '" + kIdentificationFormat + "')");
    if (j.value("version", 0) != kIdentificationVersion)
        return makeError(ErrorCode::BadInput, src + ": unsupported identification version");
    IdentifiedModel m;
    const std::string axis = j.value("axis", std::string());
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
    std::ifstream f(path);
    if (!f)
        return makeError(ErrorCode::NotFound, path + ": cannot open the file");
    nlohmann::json j = nlohmann::json::parse(f, nullptr, false);
    if (j.is_discarded())
        return makeError(ErrorCode::BadInput, path + ": not valid JSON");
    return identifiedModelFromJson(j, path);
}

} // namespace axistune::ident
