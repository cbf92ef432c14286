// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The AxisTune store: one SQLite file (WAL, foreign keys, PRAGMA user_version with ordered
// migrations) holding machines, axes, parameter sets, models, sessions with captures and results,
// and the journal of parameter writes. Every logical save is one transaction, so a crash or kill
// during a save leaves the previous state intact. Layout and usage: docs/storage.md.
//
// Thread affinity: a Database is used from one thread at a time (one connection).
// The records it saves and loads: StoreTypes.h (no JSON) and SessionRecord.h (with JSON data).

#include "core/model/Parameter.h"
#include "core/model/Result.h"
#include "core/store/StoreTypes.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace SQLite {
class Database;
}
namespace axistune::io {
struct MachineProfile;
}

namespace axistune::store {

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
    static constexpr int kSchemaVersion = 3;
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
