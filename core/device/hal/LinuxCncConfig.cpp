// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/LinuxCncConfig.h"

#include "core/device/hal/HalText.h"
#include "core/io/AtomicFile.h"
#include "core/model/InputLimits.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace axistune::device::hal {
namespace {

bool isBlank(char c)
{
    return c == ' ' || c == '\t' || c == '\r';
}

std::string_view trim(std::string_view s)
{
    while (!s.empty() && isBlank(s.front()))
        s.remove_prefix(1);
    while (!s.empty() && isBlank(s.back()))
        s.remove_suffix(1);
    return s;
}

std::string where(const std::string& path, std::size_t line)
{
    return path + ":" + std::to_string(line);
}

/// "[SECTION]KEY" → (SECTION, KEY); empty when the word is not an INI reference.
std::pair<std::string, std::string> iniReference(std::string_view w)
{
    if (w.size() < 4 || w.front() != '[')
        return {};
    const auto close = w.find(']');
    if (close == std::string_view::npos || close < 2 || close + 1 >= w.size())
        return {};
    return {std::string(w.substr(1, close - 1)), std::string(w.substr(close + 1))};
}

/// Joint number of a section named JOINT_n.
int jointOfSection(std::string_view section)
{
    if (section.rfind("JOINT_", 0) != 0)
        return -1;
    const auto n = model::parseInteger(section.substr(6));
    return n && *n >= 0 && *n < 64 ? static_cast<int>(*n) : -1;
}

} // namespace

const IniEntry* IniFile::find(std::string_view section, std::string_view key) const
{
    for (const auto& e : entries)
        if (e.section == section && e.key == key)
            return &e;
    return nullptr;
}

std::vector<const IniEntry*> IniFile::findAll(std::string_view section, std::string_view key) const
{
    std::vector<const IniEntry*> out;
    for (const auto& e : entries)
        if (e.section == section && e.key == key)
            out.push_back(&e);
    return out;
}

Result<IniFile> parseIni(std::string path, std::string text)
{
    IniFile ini;
    ini.path = std::move(path);
    ini.text = std::move(text);
    std::string section;
    std::size_t pos = 0, lineNo = 0;
    const std::string_view all = ini.text;
    while (pos < all.size()) {
        const std::size_t nl = all.find('\n', pos);
        const std::size_t end = nl == std::string_view::npos ? all.size() : nl;
        ++lineNo;
        const std::string_view line = all.substr(pos, end - pos);
        const std::string_view t = trim(line);
        if (t.empty() || t.front() == '#' || t.front() == ';') {
            // blank or comment
        } else if (t.front() == '[') {
            const auto close = t.find(']');
            if (close == std::string_view::npos || close < 2)
                return makeError(ErrorCode::BadInput,
                                 where(ini.path, lineNo) + ": a section header needs a name in brackets");
            section = std::string(t.substr(1, close - 1));
        } else {
            const auto eq = line.find('=');
            if (eq == std::string_view::npos)
                return makeError(ErrorCode::BadInput,
                                 where(ini.path, lineNo) + ": expected KEY = VALUE, a [SECTION] or a comment");
            IniEntry e;
            e.section = section;
            e.key = std::string(trim(line.substr(0, eq)));
            if (e.key.empty())
                return makeError(ErrorCode::BadInput, where(ini.path, lineNo) + ": a value without a key");
            std::size_t vb = pos + eq + 1;
            while (vb < end && isBlank(all[vb]))
                ++vb;
            std::size_t ve = end;
            while (ve > vb && isBlank(all[ve - 1]))
                --ve;
            e.value = std::string(all.substr(vb, ve - vb));
            e.line = lineNo;
            e.valueBegin = vb;
            e.valueEnd = ve;
            ini.entries.push_back(std::move(e));
        }
        pos = nl == std::string_view::npos ? all.size() : nl + 1;
    }
    return ini;
}

Result<IniFile> readIni(const std::string& path)
{
    auto text = model::readInputFile(path);
    if (!text)
        return text.error();
    return parseIni(path, std::move(*text));
}

const PidInstance* LinuxCncConfig::findPid(std::string_view name) const
{
    for (const auto& p : pids)
        if (p.name == name)
            return &p;
    return nullptr;
}

Status addHalText(LinuxCncConfig& cfg, const std::string& halPath, std::string_view text, std::string_view letters)
{
    std::size_t pos = 0, lineNo = 0;
    const std::string_view all = text;
    while (pos < all.size()) {
        const std::size_t nl = all.find('\n', pos);
        const std::size_t end = nl == std::string_view::npos ? all.size() : nl;
        ++lineNo;
        std::string_view line = all.substr(pos, end - pos);
        pos = nl == std::string_view::npos ? all.size() : nl + 1;
        if (const auto hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        const auto w = splitWords(line);
        if (w.size() >= 2 && w[0] == "loadrt" && w[1] == "pid") {
            std::vector<std::string> names;
            long long count = 0;
            for (std::size_t i = 2; i < w.size(); ++i) {
                if (w[i].rfind("names=", 0) == 0) {
                    std::string_view list = std::string_view(w[i]).substr(6);
                    while (!list.empty()) {
                        const auto comma = list.find(',');
                        if (comma == 0)
                            return makeError(ErrorCode::BadInput,
                                             where(halPath, lineNo) + ": loadrt pid names=: an empty name in the list");
                        names.emplace_back(list.substr(0, comma));
                        list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
                    }
                } else if (w[i].rfind("count=", 0) == 0 || w[i].rfind("num_chan=", 0) == 0) {
                    const auto n = model::parseInteger(std::string_view(w[i]).substr(w[i].find('=') + 1));
                    if (!n || *n < 1 || *n > 64)
                        return makeError(ErrorCode::BadInput, where(halPath, lineNo) + ": pid count must be 1 to 64");
                    count = *n;
                }
            }
            if (names.empty()) {
                for (long long i = 0; i < std::max(count, 1LL); ++i)
                    names.push_back("pid." + std::to_string(i));
            }
            for (auto& n : names)
                if (!cfg.findPid(n))
                    cfg.pids.push_back(PidInstance{n, -1, {}, {}});
        } else if (w.size() >= 3 && w[0] == "setp") {
            const std::string& pin = w[1];
            const auto dot = pin.rfind('.');
            if (dot == std::string::npos || dot == 0 || dot + 1 == pin.size())
                continue;
            const std::string owner = pin.substr(0, dot);
            auto it =
                std::find_if(cfg.pids.begin(), cfg.pids.end(), [&](const PidInstance& p) { return p.name == owner; });
            if (it == cfg.pids.end())
                continue;
            GainSource g;
            g.pin = pin;
            g.halFile = halPath;
            g.halLine = lineNo;
            const auto [section, key] = iniReference(w[2]);
            if (!section.empty()) {
                g.section = section;
                g.key = key;
                if (const int j = jointOfSection(section); j >= 0 && it->joint < 0) {
                    it->joint = j;
                    if (static_cast<std::size_t>(j) < letters.size())
                        it->axisLetter = std::string(1, letters[static_cast<std::size_t>(j)]);
                }
            } else {
                g.literal = w[2];
            }
            it->gains[pin.substr(dot + 1)] = std::move(g);
        }
    }
    return Status::success();
}

Result<LinuxCncConfig> readLinuxCncConfig(const std::string& iniPath, const std::string& hallibDir)
{
    namespace fs = std::filesystem;
    auto ini = readIni(iniPath);
    if (!ini)
        return ini.error();
    LinuxCncConfig cfg;
    cfg.ini = std::move(*ini);
    const fs::path iniDir = fs::path(iniPath).parent_path();

    std::vector<const IniEntry*> halEntries = cfg.ini.findAll("HAL", "HALFILE");
    for (const IniEntry* e : cfg.ini.findAll("HAL", "POSTGUI_HALFILE"))
        halEntries.push_back(e);
    if (halEntries.empty())
        return makeError(ErrorCode::BadInput, iniPath + ": no [HAL]HALFILE: this INI names no HAL file");

    // Coordinates of trivial kinematics: joint n is the n-th letter.
    std::string letters;
    const IniEntry* kins = cfg.ini.find("KINS", "KINEMATICS");
    const bool trivial = !kins || kins->value.find("trivkins") != std::string::npos;
    if (const IniEntry* c = cfg.ini.find("TRAJ", "COORDINATES"); c && trivial)
        for (char ch : c->value)
            if (!isBlank(ch))
                letters += ch;

    for (const IniEntry* e : halEntries) {
        std::string name = e->value;
        fs::path resolved;
        if (name.rfind("LIB:", 0) == 0) {
            resolved = fs::path(hallibDir) / name.substr(4);
        } else if (fs::path(name).is_absolute()) {
            resolved = name;
        } else if (fs::exists(iniDir / name)) {
            resolved = iniDir / name;
        } else {
            resolved = fs::path(hallibDir) / name;
        }
        if (resolved.extension() == ".tcl") {
            cfg.notes.push_back(where(iniPath, e->line) + ": " + name +
                                " is a Tcl HAL file; AxisTune reads only .hal files, gains set there are not found");
            continue;
        }
        auto text = model::readInputFile(resolved.string());
        if (!text)
            return makeError(text.error().code,
                             where(iniPath, e->line) + ": HAL file " + name + ": " + text.error().detail);
        const std::string halPath = resolved.string();
        cfg.halFiles.push_back(halPath);

        if (auto added = addHalText(cfg, halPath, *text, letters); !added.ok())
            return added.error();
    }
    if (cfg.pids.empty())
        cfg.notes.push_back(iniPath + ": its HAL files load no pid component");
    return cfg;
}

Result<std::pair<std::string, std::vector<IniEdit>>> planPersist(const LinuxCncConfig& config,
                                                                 const std::vector<GainChange>& changes)
{
    struct Pending {
        const IniEntry* entry;
        std::string value;
    };
    std::vector<Pending> pending;
    for (const auto& c : changes) {
        const PidInstance* pid = config.findPid(c.pid);
        if (!pid)
            return makeError(ErrorCode::NotFound,
                             config.ini.path + ": its HAL files load no pid named '" + c.pid + "'");
        if (!std::isfinite(c.value))
            return makeError(ErrorCode::BadInput, c.pid + "." + c.gain + ": the new value is not a finite number");
        const auto g = pid->gains.find(c.gain);
        if (g == pid->gains.end())
            return makeError(ErrorCode::NotFound, c.pid + "." + c.gain +
                                                      " is set by no setp line in the HAL files; "
                                                      "add 'setp " +
                                                      c.pid + "." + c.gain + " [JOINT_n]KEY' there first");
        if (!g->second.literal.empty())
            return makeError(ErrorCode::BadInput,
                             c.pid + "." + c.gain + " is written as the literal " + g->second.literal + " in " +
                                 where(g->second.halFile, g->second.halLine) +
                                 "; AxisTune does not edit HAL files: change it there or feed it from the INI");
        const IniEntry* e = config.ini.find(g->second.section, g->second.key);
        if (!e)
            return makeError(ErrorCode::NotFound, c.pid + "." + c.gain + " is fed by [" + g->second.section + "]" +
                                                      g->second.key + ", which " + config.ini.path + " does not have");
        // A gain that keeps its value keeps its text ("4.0" stays "4.0").
        if (const auto current = model::parseNumber(e->value); current && *current == c.value)
            continue;
        const std::string v = model::formatShortest(c.value);
        auto same = std::find_if(pending.begin(), pending.end(), [&](const Pending& p) { return p.entry == e; });
        if (same != pending.end()) {
            if (same->value != v)
                return makeError(ErrorCode::BadInput,
                                 "[" + e->section + "]" + e->key + " feeds two gains that are to get different values");
            continue;
        }
        pending.push_back({e, v});
    }
    std::sort(pending.begin(), pending.end(),
              [](const Pending& a, const Pending& b) { return a.entry->valueBegin < b.entry->valueBegin; });
    std::string out;
    std::vector<IniEdit> edits;
    std::size_t at = 0;
    for (const auto& p : pending) {
        out.append(config.ini.text, at, p.entry->valueBegin - at);
        out += p.value;
        at = p.entry->valueEnd;
        if (p.entry->value != p.value)
            edits.push_back({p.entry->section, p.entry->key, p.entry->line, p.entry->value, p.value});
    }
    out.append(config.ini.text, at, std::string::npos);
    return std::pair{std::move(out), std::move(edits)};
}

Result<std::vector<IniEdit>> persistGains(const LinuxCncConfig& config, const std::vector<GainChange>& changes)
{
    auto plan = planPersist(config, changes);
    if (!plan)
        return plan.error();
    if (plan->second.empty())
        return plan->second;
    if (auto st = io::writeFileAtomic(config.ini.path + ".axistune-backup", config.ini.text); !st)
        return makeError(st.error().code, "no backup, nothing changed: " + st.error().detail);
    if (auto st = io::writeFileAtomic(config.ini.path, plan->first); !st)
        return st.error();
    return std::move(plan->second);
}

} // namespace axistune::device::hal
