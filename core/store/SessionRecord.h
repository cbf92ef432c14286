// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The records of the AxisTune store that hold JSON data: a model, a session's result, a whole session
// as it is saved and loaded (Database::recordSession, Database::loadSession; docs/storage.md).

#include "core/store/StoreTypes.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace axistune::store {

struct ModelRecord {
    std::int64_t id = 0;
    std::string axis;
    std::string kind;  ///< io::modelKinds()
    std::string time;  ///< empty: now
    nlohmann::json data;
};

struct SessionResult {
    std::string name;
    nlohmann::json data;
    std::vector<model::Channel> arrays;  ///< named arrays, e.g. "f_Hz", "mag_dB"
};

/// Everything one session recorded. Parameter sets, models and journal entries listed here are saved
/// in the same transaction and linked to the session (the store never changes a profile without a
/// session saying why).
struct SessionRecord {
    SessionInfo info;
    std::vector<std::string> machineAxes;  ///< axes to create (in order) if the machine lacks them
    std::string machineDescription;        ///< when not empty, replaces the machine's description
    nlohmann::json inputs = nlohmann::json::object();
    std::vector<NamedCapture> captures;
    std::vector<SessionResult> results;
    std::vector<ParameterSet> parameterSets;
    std::vector<ModelRecord> models;
    std::vector<JournalEntry> journal;

    /// The data of the first result of this name, or nullptr.
    const nlohmann::json* result(const std::string& name) const
    {
        for (const auto& r : results)
            if (r.name == name)
                return &r.data;
        return nullptr;
    }
};

}  // namespace axistune::store
