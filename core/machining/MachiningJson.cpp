// SPDX-License-Identifier: GPL-3.0-or-later
// Readers of the tool and cutting-condition JSON files (docs/machining.md "File formats").
#include "core/machining/MachiningJson.h"

#include "core/model/InputLimits.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace axistune::machining {

namespace {

using nlohmann::json;

Result<json> parseText(const std::string& text, const std::string& src)
{
    auto j = model::parseJsonText(text, src);
    if (!j)
        return j.error();
    if (!j->is_object())
        return makeError(ErrorCode::BadInput, src + ": the top level must be a JSON object");
    return j;
}

Result<double> number(const json& obj, const std::string& key, const std::string& where)
{
    if (!obj.contains(key))
        return makeError(ErrorCode::BadInput, where + ": missing key '" + key + "'");
    const auto& v = obj.at(key);
    if (!v.is_number())
        return makeError(ErrorCode::BadInput, where + ", key '" + key + "': not a number");
    const double d = v.get<double>();
    if (!std::isfinite(d))
        return makeError(ErrorCode::BadInput, where + ", key '" + key + "': not finite");
    return d;
}

Result<std::vector<ModalParameters>> modes(const json& j, const std::string& key, const std::string& src)
{
    if (!j.contains(key))
        return makeError(ErrorCode::BadInput, src + ": missing key '" + key + "'");
    const auto& arr = j.at(key);
    if (!arr.is_array())
        return makeError(ErrorCode::BadInput,
                         src + ", key '" + key + "': must be a list of modes ([] for a rigid direction)");
    std::vector<ModalParameters> out;
    for (std::size_t i = 0; i < arr.size(); ++i) {
        const std::string where = src + ", " + key + "[" + std::to_string(i) + "]";
        if (!arr[i].is_object())
            return makeError(ErrorCode::BadInput, where + ": must be an object");
        auto m = number(arr[i], "mass_kg", where);
        auto c = number(arr[i], "damping_Ns_per_m", where);
        auto k = number(arr[i], "stiffness_N_per_m", where);
        for (const auto* r : {&m, &c, &k})
            if (!*r)
                return r->error();
        out.push_back({*m, *c, *k});
    }
    return out;
}

Result<std::string> slurp(const std::string& path)
{
    return model::readInputFile(path);
}

} // namespace

Result<ToolModes> parseToolJson(const std::string& text, const std::string& src)
{
    auto j = parseText(text, src);
    if (!j)
        return j.error();
    auto mx = modes(*j, "modes_x", src);
    if (!mx)
        return mx.error();
    auto my = modes(*j, "modes_y", src);
    if (!my)
        return my.error();
    ToolModes t{*mx, *my};
    if (auto s = validateTool(t); !s)
        return makeError(s.error().code, src + ": " + s.error().detail);
    return t;
}

Result<CuttingConditions> parseCutJson(const std::string& text, const std::string& src)
{
    auto j = parseText(text, src);
    if (!j)
        return j.error();
    CuttingConditions c;
    auto teeth = number(*j, "teeth", src);
    if (!teeth)
        return teeth.error();
    if (*teeth != std::floor(*teeth))
        return makeError(ErrorCode::BadInput, src + ", key 'teeth': must be a whole number");
    c.teeth = static_cast<int>(std::clamp(*teeth, -1.0, 1e6));
    auto kt = number(*j, "Kt_N_per_m2", src);
    auto kr = number(*j, "Kr_N_per_m2", src);
    auto ri = number(*j, "radial_immersion", src);
    for (const auto* r : {&kt, &kr, &ri})
        if (!*r)
            return r->error();
    c.ktNPerM2 = *kt;
    c.krNPerM2 = *kr;
    c.radialImmersion = *ri;
    if (!j->contains("milling") || !j->at("milling").is_string())
        return makeError(ErrorCode::BadInput, src + ": missing key 'milling' (\"down\" or \"up\")");
    const auto mode = j->at("milling").get<std::string>();
    if (mode == "down")
        c.milling = MillingDirection::Down;
    else if (mode == "up")
        c.milling = MillingDirection::Up;
    else
        return makeError(ErrorCode::BadInput,
                         src + ", key 'milling': must be \"down\" or \"up\" (got \"" + mode + "\")");
    if (j->contains("spindle")) {
        const auto& sp = j->at("spindle");
        const std::string where = src + ", spindle";
        if (!sp.is_object())
            return makeError(ErrorCode::BadInput, where + ": must be an object {time_constant_s, min_rpm, max_rpm}");
        auto tc = number(sp, "time_constant_s", where);
        auto lo = number(sp, "min_rpm", where);
        auto hi = number(sp, "max_rpm", where);
        for (const auto* r : {&tc, &lo, &hi})
            if (!*r)
                return r->error();
        if (*tc < 0.0 || *tc > 10.0)
            return makeError(ErrorCode::OutOfRange, where + ", key 'time_constant_s': must be in [0, 10] s");
        if (!(*lo > 0.0) || !(*hi >= *lo))
            return makeError(ErrorCode::OutOfRange, where + ": need 0 < min_rpm <= max_rpm");
        c.spindleTimeConstantS = *tc;
        c.spindleMinRpm = *lo;
        c.spindleMaxRpm = *hi;
    }
    if (auto s = validateCut(c); !s)
        return makeError(s.error().code, src + ": " + s.error().detail);
    return c;
}

Result<ToolModes> readToolJsonFile(const std::string& path)
{
    auto t = slurp(path);
    if (!t)
        return t.error();
    return parseToolJson(*t, path);
}

Result<CuttingConditions> readCutJsonFile(const std::string& path)
{
    auto t = slurp(path);
    if (!t)
        return t.error();
    return parseCutJson(*t, path);
}

} // namespace axistune::machining
