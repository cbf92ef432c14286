// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Exports one stored session to a folder: manifest.json (session, inputs, results, parameter sets,
// models, journal, and the list of files) plus one capture CSV per capture and one CSV per result
// with arrays (docs/storage.md "Session export").

#include "core/model/Result.h"
#include "core/store/Database.h"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace axistune::store {

/// The session as JSON without array data (arrays are described by name and length).
nlohmann::json sessionSummaryJson(const SessionRecord& record);
nlohmann::json sessionInfoJson(const SessionInfo& info);

/// Writes the folder (created if missing; existing files of the same name are replaced).
/// Returns the manifest that was written.
Result<nlohmann::json> exportSessionFolder(const SessionRecord& record, const std::string& folder);

}  // namespace axistune::store
