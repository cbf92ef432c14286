// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The AxisTune store: one SQLite file (WAL, foreign keys, PRAGMA user_version with ordered
// migrations) holding machines, axes, parameter sets, models, sessions with captures and results,
// and the journal of parameter writes. Every logical save is one transaction, so a crash or kill
// during a save leaves the previous state intact. Layout and usage: docs/storage.md.
//
// Thread affinity: a Database is used from one thread at a time (one connection).

#include "core/io/Profile.h"
#include "core/model/Capture.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace SQLite {
class Database;
}

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

struct ModelRecord {
    std::int64_t id = 0;
    std::string axis;
    std::string kind;  ///< io::modelKinds()
    std::string time;  ///< empty: now
    nlohmann::json data;
};

struct JournalEntry {
    std::int64_t id = 0;
    std::string machine;  ///< filled when read back
    std::string axis;
    std::string key;
    std::optional<double> oldValue;  ///< none when the old value was unknown
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

/// After a failed open or a failed first save: removes a 0-byte "-wal" and a "-shm" smaller than one
/// wal-index page (what SQLite leaves when it cannot set up the log, e.g. on a full disk; no live
/// connection has such files), and with `created` the store file itself (one this process was creating).
void removeFailedOpenLeftovers(const std::string& path, bool created);

enum class OpenMode {
    CreateIfMissing,  ///< creates a new, empty store when the file does not exist
    MustExist,        ///< NotFound when the file does not exist (read-only commands)
};

class Database {
public:
    static constexpr int kSchemaVersion = 2;
    static constexpr std::int32_t kApplicationId = 0x41585455;  // "AXTU"

    /// Opens (and creates or migrates) a store. Refuses, with a message naming the file: a file that
    /// is not SQLite, a truncated or corrupt file, a file from a newer AxisTune, another program's
    /// SQLite file.
    static Result<Database> open(const std::string& path, OpenMode mode = OpenMode::CreateIfMissing);

    Database(Database&&) noexcept;
    Database& operator=(Database&&) noexcept;
    ~Database();

    const std::string& path() const { return m_path; }
    int schemaVersion() const;

    // Machines and axes.
    Result<std::vector<std::string>> listMachines() const;
    /// Creates the machine (and its axes, appended in order) if missing; one transaction.
    Status ensureMachine(const std::string& machine, const std::vector<std::string>& axes = {},
                         const std::string& description = {});

    // Parameters, models, journal (each call one transaction; prefer recordSession for a wizard).
    Result<std::int64_t> saveParameterSet(const std::string& machine, const ParameterSet& set,
                                          std::optional<std::int64_t> sessionId = std::nullopt);
    /// Current parameters: for every key the value of the newest non-proposed set holding it.
    Result<model::ParameterValues> currentParameters(const std::string& machine, const std::string& axis) const;
    Result<std::vector<ParameterSet>> parameterSets(const std::string& machine, const std::string& axis) const;
    Result<std::int64_t> saveModel(const std::string& machine, const ModelRecord& model,
                                   std::optional<std::int64_t> sessionId = std::nullopt);
    Result<std::vector<JournalEntry>> journal(const std::string& machine) const;

    // Profiles.
    /// The machine with its axes, current parameters and newest model of each kind.
    Result<io::MachineProfile> loadProfile(const std::string& machine) const;
    /// Saves a profile as an "imported" parameter set and models per axis, together with a session of
    /// kind "profile-import" whose inputs name `sourceName`; one transaction. Returns the session id.
    Result<std::int64_t> importProfile(const io::MachineProfile& profile, const std::string& sourceName,
                                       const std::string& note = {});

    // Sessions.
    /// `progress` (optional) is called with the fraction written, 0..1 by the samples of the captures, never
    /// falling, on the calling thread; 1 once the transaction is committed.
    Result<std::int64_t> recordSession(const SessionRecord& record, const std::function<void(double)>& progress = {});
    Result<std::vector<SessionInfo>> listSessions(const std::string& machine = {}) const;
    Result<SessionRecord> loadSession(std::int64_t id) const;

    /// Whether a save can succeed as far as can be known before one: the store is not opened
    /// read-only (file, folder or file system) and its write lock can be taken. Callers check this
    /// before measuring, so a test is never run for a session that cannot be saved. Io/Busy errors
    /// name the file.
    Status checkWritable() const;

    /// `PRAGMA integrity_check`: "ok" or the first problems found.
    Result<std::string> integrityCheck() const;

    /// For tests and tools: the underlying connection.
    SQLite::Database& connection() const { return *m_db; }

private:
    Database(std::string path, std::unique_ptr<SQLite::Database> db);
    Status migrate();

    std::string m_path;
    std::unique_ptr<SQLite::Database> m_db;
};

}  // namespace axistune::store
