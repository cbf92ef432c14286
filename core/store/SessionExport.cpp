// SPDX-License-Identifier: GPL-3.0-or-later
// Session export to a folder of CSV files and a JSON manifest (docs/storage.md "Session export").
#include "core/store/SessionExport.h"

#include "core/io/CaptureCsv.h"
#include "core/io/Profile.h"
#include "core/model/MetadataJson.h"
#include "core/model/ResultJson.h"
#include "core/store/SessionRecord.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>

namespace axistune::store {

namespace fs = std::filesystem;

namespace {

/// A file-name-safe version of a capture or result name.
std::string safeName(const std::string& name)
{
    std::string out;
    for (char c : name)
        out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
    return out.empty() ? "unnamed" : out;
}

nlohmann::json channelsJson(const std::vector<model::Channel>& channels)
{
    nlohmann::json a = nlohmann::json::array();
    for (const auto& ch : channels)
        a.push_back({{"name", ch.name}, {"samples", ch.data.size()}});
    return a;
}

}  // namespace

nlohmann::json sessionInfoJson(const SessionInfo& info)
{
    return {{"id", info.id},           {"machine", info.machine},       {"axis", info.axis},
            {"kind", info.kind},       {"started", info.started},       {"finished", info.finished},
            {"status", toString(info.status)}, {"app_version", info.appVersion}, {"operator", info.operatorName},
            {"note", info.note},       {"captures", info.captureCount}, {"results", info.resultCount}};
}

namespace {

/// What the store holds, as result JSON without null (docs/formats.md "Undefined values"): a result
/// without data is an empty object; a null member, or an array member with a null element, recorded by
/// an earlier version is left out and named in "undefined".
nlohmann::json storedJson(const nlohmann::json& j)
{
    if (j.is_null())
        return nlohmann::json::object();
    nlohmann::json out = j;
    const std::function<void(nlohmann::json&)> fix = [&fix](nlohmann::json& o) {
        if (o.is_array()) {
            for (auto& e : o)
                fix(e);
            return;
        }
        if (!o.is_object())
            return;
        std::vector<std::string> undefined;
        for (auto it = o.begin(); it != o.end(); ++it) {
            const bool nullInArray =
                it->is_array() && std::any_of(it->begin(), it->end(), [](const auto& e) { return e.is_null(); });
            if (it->is_null() || nullInArray)
                undefined.push_back(it.key());
            else
                fix(*it);
        }
        for (const auto& k : undefined)
            model::putUndefined(o, k, "stored without a value");
    };
    fix(out);
    return out;
}

} // namespace

nlohmann::json sessionSummaryJson(const SessionRecord& r)
{
    nlohmann::json j;
    j["session"] = sessionInfoJson(r.info);
    j["inputs"] = storedJson(r.inputs);
    j["captures"] = nlohmann::json::array();
    for (const auto& c : r.captures) {
        j["captures"].push_back({{"name", c.name}, {"metadata", c.capture.metadata}, {"samples", c.capture.size()},
                                 {"channels", channelsJson(c.capture.channels)}});
    }
    j["results"] = nlohmann::json::array();
    for (const auto& res : r.results)
        j["results"].push_back(
            {{"name", res.name}, {"data", storedJson(res.data)}, {"arrays", channelsJson(res.arrays)}});
    j["parameter_sets"] = nlohmann::json::array();
    for (const auto& s : r.parameterSets) {
        j["parameter_sets"].push_back({{"axis", s.axis}, {"source", toString(s.source)}, {"time", s.time},
                                       {"note", s.note}, {"values", s.values}});
    }
    j["models"] = nlohmann::json::array();
    for (const auto& m : r.models)
        j["models"].push_back({{"axis", m.axis}, {"kind", m.kind}, {"time", m.time}, {"data", storedJson(m.data)}});
    j["journal"] = nlohmann::json::array();
    for (const auto& e : r.journal) {
        nlohmann::json je{{"axis", e.axis}, {"key", e.key}, {"new", e.newValue}, {"time", e.time}};
        // No null in result JSON (docs/formats.md "Undefined values"). The store cannot tell a value that was not read
        // before the write from a first write (StoreTypes.h): the reason says both.
        if (e.oldValue)
            je["old"] = *e.oldValue;
        else
            model::putUndefined(je, "old", "not recorded (not read before this write, or none before it)");
        j["journal"].push_back(je);
    }
    return j;
}

Result<nlohmann::json> exportSessionFolder(const SessionRecord& r, const std::string& folder)
{
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec)
        return makeError(ErrorCode::Io, folder + ": cannot create the folder (" + ec.message() + ")");
    nlohmann::json manifest = sessionSummaryJson(r);
    manifest["format"] = "axistune-session-export-1";
    for (std::size_t i = 0; i < r.captures.size(); ++i) {
        const std::string file = "capture_" + std::to_string(i + 1) + "_" + safeName(r.captures[i].name) + ".csv";
        if (auto st = io::writeCaptureCsvFile((fs::path(folder) / file).string(), r.captures[i].capture); !st)
            return st.error();
        manifest["captures"][i]["file"] = file;
    }
    for (std::size_t i = 0; i < r.results.size(); ++i) {
        const auto& res = r.results[i];
        if (res.arrays.empty())
            continue;
        // Arrays of one length form one table; otherwise each array gets its own one-column file.
        bool sameLength = true;
        for (const auto& a : res.arrays)
            sameLength = sameLength && a.data.size() == res.arrays.front().data.size();
        const std::string stem = "result_" + std::to_string(i + 1) + "_" + safeName(res.name);
        nlohmann::json files = nlohmann::json::array();
        std::vector<model::Capture> tables;
        if (sameLength) {
            tables.push_back(model::Capture{{}, res.arrays});
            files.push_back(stem + ".csv");
        } else {
            for (const auto& a : res.arrays) {
                tables.push_back(model::Capture{{}, {a}});
                files.push_back(stem + "_" + safeName(a.name) + ".csv");
            }
        }
        for (std::size_t k = 0; k < tables.size(); ++k) {
            if (auto st = io::writeCaptureCsvFile((fs::path(folder) / files[k].get<std::string>()).string(), tables[k]); !st)
                return st.error();
        }
        manifest["results"][i]["files"] = files;
    }
    if (auto st = io::writeTextFileAtomic((fs::path(folder) / "manifest.json").string(), manifest.dump(2) + "\n"); !st)
        return st.error();
    return manifest;
}

}  // namespace axistune::store
