// SPDX-License-Identifier: GPL-3.0-or-later
// NC parameter-file export from map files (docs/formats-profile.md "NC map files").
#include "core/io/NcExport.h"

#include "core/io/Profile.h"
#include "core/model/InputLimits.h"
#include "core/model/Number.h"
#include "core/model/Units.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <nlohmann/json.hpp>

namespace axistune::io {
namespace {

Error bad(const std::string& source, const std::string& what)
{
    return makeError(ErrorCode::BadInput, source + ": " + what);
}

std::string fill(std::string t, const std::map<std::string, std::string>& vars)
{
    std::string out;
    out.reserve(t.size() + 32);
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] == '{') {
            const auto close = t.find('}', i);
            if (close != std::string::npos) {
                const auto it = vars.find(t.substr(i + 1, close - i - 1));
                if (it != vars.end()) {
                    out += it->second;
                    i = close;
                    continue;
                }
            }
        }
        out += t[i];
    }
    return out;
}

Result<std::string> getString(const nlohmann::json& j, const std::string& field, const std::string& where, bool required)
{
    if (!j.contains(field)) {
        if (required)
            return bad(where, "missing field '" + field + "'");
        return std::string();
    }
    if (!j[field].is_string())
        return bad(where, "field '" + field + "' must be a string");
    return j[field].get<std::string>();
}

Result<std::vector<std::string>> getLines(const nlohmann::json& j, const std::string& field, const std::string& where)
{
    std::vector<std::string> out;
    if (!j.contains(field))
        return out;
    if (!j[field].is_array())
        return bad(where, "field '" + field + "' must be an array of strings");
    for (const auto& l : j[field]) {
        if (!l.is_string())
            return bad(where, "field '" + field + "' must be an array of strings");
        out.push_back(l.get<std::string>());
    }
    return out;
}

Result<NcMapEntry> entryFromJson(const nlohmann::json& e, const std::string& where)
{
    static const std::set<std::string> known{"key", "number", "si_unit", "unit", "scale", "decimals", "line", "description"};
    if (!e.is_object())
        return bad(where, "must be an object");
    for (const auto& [k, v] : e.items()) {
        if (!known.count(k))
            return bad(where, "unknown field '" + k + "'");
    }
    NcMapEntry out;
    for (auto [field, dest, required] : {std::tuple{"key", &out.key, true}, std::tuple{"number", &out.number, true},
                                         std::tuple{"si_unit", &out.siUnit, true}, std::tuple{"unit", &out.unit, true},
                                         std::tuple{"line", &out.line, false}, std::tuple{"description", &out.description, false}}) {
        auto s = getString(e, field, where, required);
        if (!s)
            return s.error();
        *dest = *s;
    }
    if (e.contains("scale")) {
        if (!e["scale"].is_number() || !std::isfinite(e["scale"].get<double>()) || e["scale"].get<double>() == 0.0)
            return bad(where + " (" + out.key + ")", "field 'scale' must be a finite non-zero number");
        out.scale = e["scale"].get<double>();
    }
    if (e.contains("decimals")) {
        if (!e["decimals"].is_number_integer() || e["decimals"].get<std::int64_t>() < 0 ||
            e["decimals"].get<std::int64_t>() > 12)
            return bad(where + " (" + out.key + ")", "field 'decimals' must be an integer 0..12");
        out.decimals = e["decimals"].get<int>();
    }
    if (out.key.empty() || out.number.empty())
        return bad(where, "fields 'key' and 'number' must not be empty");
    if (auto c = model::convertUnit(1.0, out.siUnit, out.unit); !c)
        return bad(where + " (" + out.key + ")", "units '" + out.siUnit + "' -> '" + out.unit + "': " + c.error().detail);
    return out;
}

std::string siText(double v)
{
    return model::formatNumber(v, 9);
}

}  // namespace

Result<NcMap> ncMapFromJson(const nlohmann::json& j, const std::string& sourceName)
{
    static const std::set<std::string> known{"format", "family", "title", "verify", "comment", "comment_forbidden",
                                             "header", "footer", "layout", "line", "axis_item", "axis_separator",
                                             "axis_header", "parameters"};
    if (!j.is_object())
        return bad(sourceName, "an NC map must be a JSON object");
    for (const auto& [k, v] : j.items()) {
        if (!known.count(k))
            return bad(sourceName, "unknown field '" + k + "'");
    }
    if (!j.contains("format") || j["format"] != "axistune-nc-map-1")
        return bad(sourceName, "field 'format' must be \"axistune-nc-map-1\"");
    NcMap m;
    for (auto [field, dest, required] :
         {std::tuple{"family", &m.family, true}, std::tuple{"title", &m.title, true}, std::tuple{"verify", &m.verify, true},
          std::tuple{"comment", &m.comment, true}, std::tuple{"line", &m.line, true},
          std::tuple{"axis_item", &m.axisItem, false}, std::tuple{"axis_separator", &m.axisSeparator, false},
          std::tuple{"axis_header", &m.axisHeader, false}}) {
        auto s = getString(j, field, sourceName, required);
        if (!s)
            return s.error();
        *dest = *s;
    }
    if (m.verify.empty())
        return bad(sourceName, "field 'verify' must say what to check against the NC's parameter manual");
    for (auto [field, dest] : {std::pair{"header", &m.header}, std::pair{"footer", &m.footer},
                               std::pair{"comment_forbidden", &m.commentForbidden}}) {
        auto l = getLines(j, field, sourceName);
        if (!l)
            return l.error();
        *dest = *l;
    }
    auto layout = getString(j, "layout", sourceName, true);
    if (!layout)
        return layout.error();
    if (*layout == "by_parameter")
        m.layout = NcLayout::ByParameter;
    else if (*layout == "by_parameter_per_axis")
        m.layout = NcLayout::ByParameterPerAxis;
    else if (*layout == "by_axis")
        m.layout = NcLayout::ByAxis;
    else
        return bad(sourceName, "field 'layout': '" + *layout + "' (by_parameter, by_parameter_per_axis, by_axis)");
    if (m.layout == NcLayout::ByParameter && m.axisItem.empty())
        return bad(sourceName, "layout by_parameter needs 'axis_item'");
    // Templates that would drop the notice or the values from the file are refused (docs/formats-profile.md).
    if (m.comment.find("{text}") == std::string::npos)
        return bad(sourceName, "field 'comment' must contain {text} (else the VERIFY notice would be dropped)");
    for (const auto& f : m.commentForbidden) {
        if (f.empty() || f.find_first_of(" \t\r\n") != std::string::npos)
            return bad(sourceName, "field 'comment_forbidden': entries must be non-empty and hold no blank");
        for (const char c : f)
            if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == ':')
                return bad(sourceName, "field 'comment_forbidden': '" + f +
                                           "' holds a letter, digit or ':' (it would garble the VERIFY notice)");
    }
    // The notice is written as the map states it, or the map is refused: a forbidden string in it would be blanked.
    for (const auto& f : m.commentForbidden)
        if (m.verify.find(f) != std::string::npos)
            return bad(sourceName, "field 'verify' holds '" + f +
                                       "', which 'comment_forbidden' blanks in comments: the VERIFY notice would not "
                                       "be written as given");
    for (const auto* t : {&m.comment, &m.line, &m.axisItem, &m.axisSeparator, &m.axisHeader})
        if (t->find_first_of("\r\n") != std::string::npos)
            return bad(sourceName, "templates must be single lines (no line break)");
    if (m.layout == NcLayout::ByParameter) {
        if (m.line.find("{axes}") == std::string::npos)
            return bad(sourceName,
                       "field 'line' must contain {axes} for layout by_parameter (else no value is written)");
        if (m.axisItem.find("{value}") == std::string::npos)
            return bad(sourceName, "field 'axis_item' must contain {value} (else no value is written)");
    } else if (m.line.find("{value}") == std::string::npos) {
        return bad(sourceName, "field 'line' must contain {value} (else no value is written)");
    }
    if (!j.contains("parameters") || !j["parameters"].is_array())
        return bad(sourceName, "field 'parameters' must be an array");
    for (std::size_t i = 0; i < j["parameters"].size(); ++i) {
        auto e = entryFromJson(j["parameters"][i], sourceName + " parameters[" + std::to_string(i) + "]");
        if (!e)
            return e.error();
        const std::string& line = e->line;
        const char* needed = m.layout == NcLayout::ByParameter ? "{axes}" : "{value}";
        if (!line.empty() &&
            (line.find(needed) == std::string::npos || line.find_first_of("\r\n") != std::string::npos))
            return bad(sourceName + " parameters[" + std::to_string(i) + "] (" + e->key + ")",
                       std::string("field 'line' must be one line containing ") + needed);
        m.entries.push_back(std::move(e).value());
    }
    return m;
}

Result<NcMap> readNcMapFile(const std::string& path)
{
    auto text = readTextFile(path);
    if (!text)
        return text.error();
    auto j = model::parseJsonText(*text, path);
    if (!j)
        return j.error();
    return ncMapFromJson(*j, path);
}

Result<std::string> formatNcValue(const NcMapEntry& entry, double valueSi)
{
    auto converted = model::convertUnit(valueSi, entry.siUnit, entry.unit);
    if (!converted)
        return converted.error();
    const double v = *converted * entry.scale;
    if (!std::isfinite(v))
        return makeError(ErrorCode::OutOfRange, "parameter '" + entry.key + "': NC value is not finite");
    if (entry.decimals == 0) {
        const double r = std::round(v);
        if (std::fabs(r) > 2147483647.0)
            return makeError(ErrorCode::OutOfRange, "parameter '" + entry.key + "' = " + siText(valueSi) + " " + entry.siUnit
                                                        + " gives NC value " + siText(v) + ", outside a 32-bit integer");
        return std::to_string(static_cast<long long>(r)); // an integer: no decimal point, no grouping
    }
    // "-0.000" is not a value an NC operator expects to read.
    std::string s = model::formatFixed(v, entry.decimals);
    if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos)
        return s.substr(1);
    return s;
}

std::string defaultNcMapPath(const std::string& family)
{
    std::string dir = AXISTUNE_SOURCE_RESOURCE_DIR;
    if (const char* env = std::getenv("AXISTUNE_RESOURCE_DIR"); env && *env)
        dir = env;
    return dir + "/nc/" + family + ".json";
}

Result<NcExport> exportNc(const MachineProfile& profile, const NcMap& map)
{
    NcExport out;
    std::map<std::string, std::string> base{{"machine", profile.name}, {"family", map.family}, {"title", map.title}};
    auto comment = [&](const std::string& text) {
        std::string t = text;
        for (const auto& f : map.commentForbidden) {
            for (std::size_t p = t.find(f); !f.empty() && p != std::string::npos; p = t.find(f, p + 1))
                t.replace(p, f.size(), " ");
        }
        auto vars = base;
        vars["text"] = t;
        return fill(map.comment, vars) + "\n";
    };
    auto axisVars = [&](std::map<std::string, std::string> v, std::size_t i) {
        v["axis"] = profile.axes[i].name;
        v["axis_index"] = std::to_string(i + 1);
        v["axis_index0"] = std::to_string(i);
        return v;
    };
    auto entryVars = [&](const NcMapEntry& e) {
        auto v = base;
        v["number"] = e.number;
        v["key"] = e.key;
        v["unit"] = e.unit;
        return v;
    };

    std::string& t = out.text;
    for (const auto& h : map.header)
        t += fill(h, base) + "\n";
    t += comment("AxisTune " + map.title + " - machine " + profile.name);
    t += comment("VERIFY: " + map.verify);

    std::set<std::string> mappedKeys;
    for (const auto& e : map.entries)
        mappedKeys.insert(e.key);

    auto valueLine = [&](const NcMapEntry& e, std::size_t axis, const std::string& value) {
        auto v = axisVars(entryVars(e), axis);
        v["value"] = value;
        return fill(e.line.empty() ? map.line : e.line, v) + "\n";
    };

    if (map.layout == NcLayout::ByAxis) {
        for (std::size_t i = 0; i < profile.axes.size(); ++i) {
            if (!map.axisHeader.empty())
                t += fill(map.axisHeader, axisVars(base, i)) + "\n";
            for (const auto& e : map.entries) {
                const auto it = profile.axes[i].parameters.find(e.key);
                if (it == profile.axes[i].parameters.end())
                    continue;
                auto value = formatNcValue(e, it->second);
                if (!value)
                    return makeError(value.error().code, "axis " + profile.axes[i].name + ": " + value.error().detail);
                t += valueLine(e, i, *value);
            }
        }
    } else {
        for (const auto& e : map.entries) {
            std::string items;
            bool any = false;
            for (std::size_t i = 0; i < profile.axes.size(); ++i) {
                const auto it = profile.axes[i].parameters.find(e.key);
                if (it == profile.axes[i].parameters.end())
                    continue;
                auto value = formatNcValue(e, it->second);
                if (!value)
                    return makeError(value.error().code, "axis " + profile.axes[i].name + ": " + value.error().detail);
                if (map.layout == NcLayout::ByParameterPerAxis) {
                    t += valueLine(e, i, *value);
                } else {
                    auto v = axisVars(entryVars(e), i);
                    v["value"] = *value;
                    if (any)
                        items += map.axisSeparator;
                    items += fill(map.axisItem, v);
                }
                any = true;
            }
            if (map.layout == NcLayout::ByParameter && any) {
                auto v = entryVars(e);
                v["axes"] = items;
                t += fill(e.line.empty() ? map.line : e.line, v) + "\n";
            }
        }
    }

    // Keys the map does not know: listed with their values so that nobody assumes they were set.
    std::map<std::string, std::string> unmapped;
    for (const auto& a : profile.axes) {
        for (const auto& [key, value] : a.parameters) {
            if (mappedKeys.count(key))
                continue;
            auto& s = unmapped[key];
            s += (s.empty() ? "" : ", ") + a.name + "=" + siText(value);
        }
    }
    if (!unmapped.empty()) {
        t += comment("UNMAPPED: " + std::to_string(unmapped.size()) + " AxisTune parameters have no " + map.family
                     + " mapping and are NOT in this file; set them by hand if the NC has them (SI values):");
        for (const auto& [key, values] : unmapped) {
            t += comment("UNMAPPED " + key + ": " + values);
            out.unmapped.push_back(key);
        }
    }
    for (const auto& f : map.footer)
        t += fill(f, base) + "\n";
    return out;
}

}  // namespace axistune::io
