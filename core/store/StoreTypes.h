// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The records of the AxisTune store (Database.h) that hold no JSON: parameter sets, the journal,
// session headers. The records with JSON data (models, results, whole sessions) are in SessionRecord.h,
// so that the many files that only name a session or read the journal do not parse the JSON library.

#include "core/model/Capture.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace axistune::store {

enum class ParameterSource { Read, Proposed, Applied, Imported };
enum class SessionStatus { Completed, Aborted, Failed };

const char* toString(ParameterSource s);
const char* toString(SessionStatus s);
Result<ParameterSource> parameterSourceFrom(const std::string& s);
Result<SessionStatus> sessionStatusFrom(const std::string& s);

/// UTC time as ISO 8601 with milliseconds, "2026-11-22T05:33:33.120Z".
std::string nowIso8601();

struct ParameterSet {
    std::int64_t id = 0;  ///< assigned by the store
    std::string axis;
    ParameterSource source = ParameterSource::Read;
    std::string time;  ///< empty: now
    std::string note;
    model::ParameterValues values;
};

struct JournalEntry {
    std::int64_t id = 0;
    std::string machine;  ///< filled when read back
    std::string axis;
    std::string key;
    std::optional<double> oldValue; ///< none when not recorded: not read before the write, or none before it
    double newValue = 0.0;
    std::string time;  ///< empty: now
    std::optional<std::int64_t> sessionId;
};

struct SessionInfo {
    std::int64_t id = 0;
    std::string machine;  ///< may be empty (analysis of files without a machine)
    std::string axis;
    std::string kind;     ///< "frf", "current-loop", "profile-import", ...
    std::string started;  ///< empty: now
    std::string finished; ///< empty: now
    SessionStatus status = SessionStatus::Completed;
    std::string appVersion;  ///< empty: this build's version
    std::string operatorName;
    std::string note;
    int captureCount = 0;  ///< filled by listSessions/loadSession
    int resultCount = 0;
};

struct NamedCapture {
    std::string name;
    model::Capture capture;
};

// With JSON data: SessionRecord.h.
struct ModelRecord;
struct SessionResult;
struct SessionRecord;

}  // namespace axistune::store
