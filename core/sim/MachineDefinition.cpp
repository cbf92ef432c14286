// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/MachineDefinition.h"

#include "core/model/InputLimits.h"
#include "core/model/Units.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>

namespace axistune::sim {

using nlohmann::json;
namespace fs = std::filesystem;

const AxisDefinition* MachineDefinition::axis(const std::string& axisName) const
{
    for (const auto& a : axes) {
        if (a.name == axisName)
            return &a;
    }
    return nullptr;
}

std::string resourceDir()
{
    if (const char* env = std::getenv("AXISTUNE_RESOURCE_DIR"); env && *env)
        return env;
    return AXISTUNE_SOURCE_RESOURCE_DIR;
}

std::vector<std::string> presetNames()
{
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(fs::path(resourceDir()) / "machines", ec)) {
        if (e.path().extension() == ".json")
            names.push_back(e.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

Result<MachineDefinition> loadPreset(const std::string& name)
{
    const auto path = fs::path(resourceDir()) / "machines" / (name + ".json");
    if (!fs::exists(path)) {
        std::string known;
        for (const auto& n : presetNames())
            known += (known.empty() ? "" : ", ") + n;
        return makeError(ErrorCode::NotFound, "unknown machine preset '" + name + "' (known: " + known + ")");
    }
    return loadMachineDefinitionFile(path.string());
}

namespace {

Status applyParameters(const json& params, const std::string& where, AxisDefinition& axis)
{
    const auto& metas = axisParameterMetas(axis.kind);
    for (const auto& [key, entry] : params.items()) {
        const auto* meta = model::findParameter(metas, key);
        if (!meta)
            return makeError(ErrorCode::BadInput, where + ": unknown parameter '" + key + "'");
        if (!entry.is_object() || !entry.contains("value") || !entry["value"].is_number())
            return makeError(ErrorCode::BadInput, where + ", parameter '" + key + "': needs a numeric \"value\"");
        const std::string unit = entry.value("unit", meta->siUnit);
        auto si = model::convertUnit(entry["value"].get<double>(), unit, meta->siUnit);
        if (!si)
            return makeError(ErrorCode::BadInput, where + ", parameter '" + key + "': " + si.error().detail);
        if (auto st = model::checkParameterValue(*meta, *si); !st)
            return makeError(st.error().code, where + ": " + st.error().detail);
        axis.values[key] = *si;
        axis.sources[key] = entry.value("source", std::string("assumed"));
    }
    return Status::success();
}

Result<std::vector<ResonanceMode>> parseModes(const json& modes, const std::string& where)
{
    std::vector<ResonanceMode> out;
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const auto& m = modes[i];
        const std::string w = where + ", mode " + std::to_string(i + 1);
        for (const char* k : {"frequency_Hz", "damping", "modal_inertia_kgm2"}) {
            if (!m.contains(k) || !m[k].is_number())
                return makeError(ErrorCode::BadInput, w + ": needs a numeric \"" + std::string(k) + "\"");
        }
        ResonanceMode r{m["frequency_Hz"].get<double>(), m["damping"].get<double>(), m["modal_inertia_kgm2"].get<double>()};
        if (!(r.frequencyHz > 0) || !(r.damping > 0) || !(r.modalInertiaKgm2 > 0))
            return makeError(ErrorCode::OutOfRange, w + ": frequency, damping and modal inertia must be positive");
        out.push_back(r);
    }
    return out;
}

/// One entry {"value", "unit", "source"} of an axis ("travel_window") or its "screw" section (prefix "screw.") in
/// SI; the unit one of `units` (name, factor to SI).
Result<double> screwValue(const json& screw, const char* key,
                          std::initializer_list<std::pair<const char*, double>> units, const std::string& where,
                          AxisDefinition& axis, const std::string& prefix = "screw.")
{
    const std::string w = where + ", " + prefix + key;
    if (!screw.contains(key) || !screw[key].is_object() || !screw[key].contains("value") ||
        !screw[key]["value"].is_number())
        return makeError(ErrorCode::BadInput, w + ": needs an object with a numeric \"value\"");
    const auto& e = screw[key];
    const std::string unit = e.value("unit", std::string());
    std::string known;
    for (const auto& [name, factor] : units) {
        if (unit == name) {
            const double v = e["value"].get<double>() * factor;
            if (!(v > 0.0) || !std::isfinite(v))
                return makeError(ErrorCode::OutOfRange, w + ": must be > 0");
            axis.sources[prefix + key] = e.value("source", std::string("assumed"));
            return v;
        }
        known += (known.empty() ? "" : ", ") + std::string(name);
    }
    return makeError(ErrorCode::BadInput, w + ": unit '" + unit + "' is none of " + known);
}

Status parseScrew(const json& a, const std::string& where, AxisDefinition& axis)
{
    if (a.contains("travel_window")) {
        auto t = screwValue(a, "travel_window", {{"m", 1.0}, {"mm", 1e-3}}, where, axis, "");
        if (!t)
            return t.error();
        axis.travelWindowM = *t;
    }
    if (!a.contains("screw"))
        return Status::success();
    const json& s = a["screw"];
    if (!s.is_object())
        return makeError(ErrorCode::BadInput, where + ": \"screw\" must be an object");
    if (axis.kind != AxisKind::Linear)
        return makeError(ErrorCode::BadInput, where + ": a \"screw\" belongs to a linear axis");
    const std::initializer_list<std::pair<const char*, double>> length{{"m", 1.0}, {"mm", 1e-3}};
    const std::initializer_list<std::pair<const char*, double>> axial{{"N/m", 1.0}, {"N/um", 1e6}};
    ScrewStiffness k;
    struct Field {
        const char* key;
        std::initializer_list<std::pair<const char*, double>> units;
        double* out;
    };
    for (const Field& f :
         {Field{"root_diameter", length, &k.rootDiameterM},
          Field{"youngs_modulus", {{"Pa", 1.0}, {"GPa", 1e9}}, &k.youngsModulusPa},
          Field{"nut_distance_at_zero", length, &k.nutDistanceAtZeroM}, Field{"length", length, &k.lengthM},
          Field{"bearing_stiffness", axial, &k.bearingStiffnessNPerM},
          Field{"nut_stiffness", axial, &k.nutStiffnessNPerM},
          Field{"torsional_stiffness", {{"Nm/rad", 1.0}}, &k.torsionalStiffnessNmPerRad}}) {
        auto v = screwValue(s, f.key, f.units, where, axis);
        if (!v)
            return v.error();
        *f.out = *v;
    }
    if (k.nutDistanceAtZeroM >= k.lengthM)
        return makeError(ErrorCode::OutOfRange, where + ", screw.nut_distance_at_zero: must be less than screw.length");
    axis.screw = k;
    return Status::success();
}

Result<MachineDefinition> machineFromObject(const json& j, const std::string& path)
{
    MachineDefinition def;
    def.name = j.value("name", fs::path(path).stem().string());
    def.description = j.value("description", std::string());
    if (!j.contains("axes") || !j["axes"].is_array() || j["axes"].empty())
        return makeError(ErrorCode::BadInput, path + ": needs a non-empty \"axes\" array");
    const json common = j.value("common", json::object());
    for (const auto& a : j["axes"]) {
        AxisDefinition axis;
        axis.name = a.value("name", std::string());
        if (axis.name.empty())
            return makeError(ErrorCode::BadInput, path + ": an axis has no \"name\"");
        const std::string kind = a.value("kind", std::string("linear"));
        if (kind != "linear" && kind != "rotary")
            return makeError(ErrorCode::BadInput, path + ", axis " + axis.name + ": kind must be linear or rotary");
        axis.kind = kind == "linear" ? AxisKind::Linear : AxisKind::Rotary;
        axis.values = defaultAxisParameters(axis.kind);
        const std::string where = path + ", axis " + axis.name;
        if (common.contains("parameters")) {
            if (auto st = applyParameters(common["parameters"], where + " (common)", axis); !st)
                return st.error();
        }
        if (a.contains("parameters")) {
            if (auto st = applyParameters(a["parameters"], where, axis); !st)
                return st.error();
        }
        const json modes = a.contains("modes") ? a["modes"] : common.value("modes", json::array());
        auto m = parseModes(modes, where);
        if (!m)
            return m.error();
        axis.modes = *m;
        if (auto st = parseScrew(a, where, axis); !st)
            return st.error();
        def.axes.push_back(std::move(axis));
    }
    return def;
}

} // namespace

Result<MachineDefinition> loadMachineDefinitionFile(const std::string& path)
{
    auto parsed = model::readJsonFile(path);
    if (!parsed)
        return parsed.error();
    return machineDefinitionFromJson(*parsed, path);
}

Result<MachineDefinition> machineDefinitionFromJson(const json& j, const std::string& source)
{
    const std::string path = model::displayPath(source);
    if (!j.is_object())
        return makeError(ErrorCode::BadInput, path + ": the top level must be a JSON object");
    try {
        return machineFromObject(j, path);
    } catch (const json::exception& e) {
        return makeError(ErrorCode::BadInput, path + ": wrong type of a value (" + std::string(e.what()) + ")");
    }
}

}  // namespace axistune::sim
