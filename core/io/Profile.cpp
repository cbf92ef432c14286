// SPDX-License-Identifier: GPL-3.0-or-later
// Machine profile JSON and the flat parameter CSV (schema: docs/formats-profile.md).
#include "core/io/Profile.h"

#include "core/io/TextFile.h"
#include "core/model/InputLimits.h"
#include "core/model/Number.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <nlohmann/json.hpp>

namespace axistune::io {
namespace {

Error bad(const std::string& source, const std::string& what)
{
    return makeError(ErrorCode::BadInput, source + ": " + what);
}

std::string trim(const std::string& s) { return std::string(trimBlanks(s)); }

std::vector<std::string> splitComma(const std::string& line)
{
    std::vector<std::string> out;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ','))
        out.push_back(trim(cell));
    if (!line.empty() && line.back() == ',')
        out.emplace_back();
    return out;
}

bool parseDouble(const std::string& s, double& v)
{
    const auto x = model::parseNumber(s);
    if (!x || model::isDenormal(*x))
        return false;
    v = *x;
    return true;
}

Result<AxisProfile> axisFromJson(const nlohmann::json& a, const std::string& where)
{
    AxisProfile axis;
    if (!a.is_object())
        return bad(where, "must be an object");
    if (!a.contains("name") || !a["name"].is_string() || a["name"].get<std::string>().empty())
        return bad(where, "field 'name' must be a non-empty string");
    axis.name = a["name"].get<std::string>();
    const std::string axisWhere = where + " (axis '" + axis.name + "')";
    for (const auto& [key, val] : a.items()) {
        if (key != "name" && key != "parameters" && key != "models")
            return bad(axisWhere, "unknown field '" + key + "'");
    }
    if (a.contains("parameters")) {
        if (!a["parameters"].is_object())
            return bad(axisWhere, "field 'parameters' must be an object of key: number");
        for (const auto& [key, val] : a["parameters"].items()) {
            if (key.empty())
                return bad(axisWhere, "parameters: empty key");
            if (!val.is_number() || !std::isfinite(val.get<double>()))
                return bad(axisWhere, "parameter '" + key + "' must be a finite number (SI)");
            axis.parameters[key] = val.get<double>();
        }
    }
    if (a.contains("models")) {
        if (!a["models"].is_object())
            return bad(axisWhere, "field 'models' must be an object of kind: object");
        for (const auto& [kind, val] : a["models"].items()) {
            if (!isModelKind(kind))
                return bad(axisWhere, "models: unknown kind '" + kind + "' (motor, two_inertia, lost_motion, modal)");
            if (!val.is_object())
                return bad(axisWhere, "model '" + kind + "' must be an object");
            axis.models[kind] = val;
        }
    }
    return axis;
}

}  // namespace

const std::vector<std::string>& modelKinds()
{
    static const std::vector<std::string> kinds{"motor", "two_inertia", "lost_motion", "modal"};
    return kinds;
}

bool isModelKind(const std::string& kind)
{
    for (const auto& k : modelKinds()) {
        if (k == kind)
            return true;
    }
    return false;
}

const AxisProfile* MachineProfile::axis(const std::string& axisName) const
{
    for (const auto& a : axes) {
        if (a.name == axisName)
            return &a;
    }
    return nullptr;
}

nlohmann::json profileToJson(const MachineProfile& profile)
{
    nlohmann::json j;
    j["format"] = kProfileFormat;
    j["version"] = kProfileVersion;
    j["machine"] = {{"name", profile.name}, {"description", profile.description}};
    nlohmann::json axes = nlohmann::json::array();
    for (const auto& a : profile.axes) {
        nlohmann::json ja;
        ja["name"] = a.name;
        ja["parameters"] = nlohmann::json::object();
        for (const auto& [k, v] : a.parameters)
            ja["parameters"][k] = v;
        ja["models"] = nlohmann::json::object();
        for (const auto& [k, v] : a.models)
            ja["models"][k] = v;
        axes.push_back(std::move(ja));
    }
    j["axes"] = std::move(axes);
    return j;
}

Result<MachineProfile> profileFromJson(const nlohmann::json& j, const std::string& sourceName)
{
    if (!j.is_object())
        return bad(sourceName, "a profile must be a JSON object");
    if (!j.contains("format") || j["format"] != kProfileFormat)
        return bad(sourceName, std::string("field 'format' must be \"") + kProfileFormat + "\"");
    if (!j.contains("version") || !j["version"].is_number_integer())
        return bad(sourceName, "field 'version' must be an integer");
    for (const auto& [key, val] : j.items()) {
        if (key != "format" && key != "version" && key != "machine" && key != "axes")
            return bad(sourceName, "unknown field '" + key + "' (format, version, machine, axes)");
    }
    if (j["version"].get<std::int64_t>() > kProfileVersion || j["version"].get<std::int64_t>() < 1) {
        return bad(sourceName, "profile version " + std::to_string(j["version"].get<std::int64_t>()) +
                                   " is not supported (this AxisTune reads version " + std::to_string(kProfileVersion) +
                                   ")");
    }
    MachineProfile p;
    if (!j.contains("machine") || !j["machine"].is_object())
        return bad(sourceName, "field 'machine' must be an object");
    const auto& m = j["machine"];
    if (!m.contains("name") || !m["name"].is_string() || m["name"].get<std::string>().empty())
        return bad(sourceName, "field 'machine.name' must be a non-empty string");
    p.name = m["name"].get<std::string>();
    for (const auto& [key, val] : m.items()) {
        if (key != "name" && key != "description")
            return bad(sourceName, "unknown field 'machine." + key + "' (name, description)");
    }
    if (m.contains("description")) {
        if (!m["description"].is_string())
            return bad(sourceName, "field 'machine.description' must be a string");
        p.description = m["description"].get<std::string>();
    }
    if (!j.contains("axes") || !j["axes"].is_array())
        return bad(sourceName, "field 'axes' must be an array");
    std::set<std::string> names;
    for (std::size_t i = 0; i < j["axes"].size(); ++i) {
        auto axis = axisFromJson(j["axes"][i], sourceName + " axes[" + std::to_string(i) + "]");
        if (!axis)
            return axis.error();
        if (!names.insert(axis->name).second)
            return bad(sourceName, "axes[" + std::to_string(i) + "]: duplicate axis name '" + axis->name + "'");
        p.axes.push_back(std::move(axis).value());
    }
    return p;
}

std::string profileToText(const MachineProfile& profile)
{
    return profileToJson(profile).dump(2) + "\n";
}

Result<std::string> readTextFile(const std::string& path)
{
    return model::readInputFile(path);
}

Result<MachineProfile> readProfileFile(const std::string& path)
{
    auto text = readTextFile(path);
    if (!text)
        return text.error();
    auto j = model::parseJsonText(*text, path);
    if (!j)
        return j.error();
    return profileFromJson(*j, path);
}

Status writeProfileFile(const std::string& path, const MachineProfile& profile)
{
    return writeTextFileAtomic(path, profileToText(profile));
}

std::string parametersToCsv(const MachineProfile& profile)
{
    std::ostringstream os;
    os << "# format=axistune-parameters\n";
    os << "# machine=" << profile.name << "\n";
    os << "machine,axis,key,value\n";
    for (const auto& a : profile.axes) {
        for (const auto& [k, v] : a.parameters) {
            os << profile.name << ',' << a.name << ',' << k << ',' << model::formatNumber(v, 17) << '\n';
        }
    }
    return os.str();
}

Result<MachineProfile> parametersFromCsv(const std::string& text, const std::string& sourceName)
{
    std::istringstream in(text);
    std::string line;
    std::size_t lineNo = 0;
    bool header = false;
    bool formatSeen = false;
    MachineProfile p;
    while (std::getline(in, line)) {
        ++lineNo;
        if (auto lim = model::checkCsvLine(sourceName, static_cast<std::size_t>(lineNo), line.size()); !lim)
            return lim.error();
        const std::string t = trim(line);
        const std::string where = sourceName + " line " + std::to_string(lineNo);
        if (t.empty())
            continue;
        if (t[0] == '#') {
            if (trim(t.substr(1)) == "format=axistune-parameters")
                formatSeen = true;
            continue;
        }
        const auto cells = splitComma(t);
        if (!header) {
            if (cells != std::vector<std::string>{"machine", "axis", "key", "value"})
                return bad(where, "expected the header 'machine,axis,key,value'");
            header = true;
            continue;
        }
        if (cells.size() != 4)
            return bad(where, "expected 4 columns, found " + std::to_string(cells.size()));
        if (cells[0].empty() || cells[1].empty() || cells[2].empty())
            return makeError(ErrorCode::BadInput, where + ", columns 'machine', 'axis' and 'key' must not be empty");
        if (p.name.empty())
            p.name = cells[0];
        else if (p.name != cells[0])
            return makeError(ErrorCode::BadInput, where + ", column 'machine': '" + cells[0] + "' differs from '" + p.name + "' (one machine per file)");
        double v = 0.0;
        if (!parseDouble(cells[3], v))
            return makeError(ErrorCode::BadInput, where + ", column 'value': " + model::badNumberText(cells[3]) +
                                                      " (a finite SI number is needed)");
        AxisProfile* axis = nullptr;
        for (auto& a : p.axes) {
            if (a.name == cells[1])
                axis = &a;
        }
        if (!axis) {
            p.axes.push_back(AxisProfile{cells[1], {}, {}});
            axis = &p.axes.back();
        }
        if (axis->parameters.count(cells[2]))
            return makeError(ErrorCode::BadInput, where + ", column 'key': '" + cells[2] + "' appears twice for axis " + cells[1]);
        axis->parameters[cells[2]] = v;
    }
    if (!formatSeen)
        return bad(sourceName, "missing the line '# format=axistune-parameters'");
    if (!header)
        return bad(sourceName, "no header 'machine,axis,key,value'");
    if (p.name.empty())
        return bad(sourceName, "no parameter rows");
    return p;
}

}  // namespace axistune::io
