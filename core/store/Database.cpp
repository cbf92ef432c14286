// SPDX-License-Identifier: GPL-3.0-or-later
// The SQLite store: opening with checks, migrations, machines, parameters, models, profiles
// (DESIGN.md "Storage", docs/storage.md).
#include "core/store/Database.h"

#include "core/io/Profile.h"
#include "core/store/DatabaseDetail.h"
#include "core/store/Schema.h"
#include "core/store/SessionRecord.h"

#include <SQLiteCpp/SQLiteCpp.h>
#include <array>
#include <bit>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sqlite3.h>
#include <nlohmann/json.hpp>

namespace axistune::store {

namespace fs = std::filesystem;

const char* toString(ParameterSource s)
{
    switch (s) {
    case ParameterSource::Read: return "read";
    case ParameterSource::Proposed: return "proposed";
    case ParameterSource::Applied: return "applied";
    case ParameterSource::Imported: return "imported";
    }
    return "read";
}

const char* toString(SessionStatus s)
{
    switch (s) {
    case SessionStatus::Completed: return "completed";
    case SessionStatus::Aborted: return "aborted";
    case SessionStatus::Failed: return "failed";
    }
    return "failed";
}

Result<ParameterSource> parameterSourceFrom(const std::string& s)
{
    for (auto v : {ParameterSource::Read, ParameterSource::Proposed, ParameterSource::Applied, ParameterSource::Imported}) {
        if (s == toString(v))
            return v;
    }
    return makeError(ErrorCode::BadInput, "unknown parameter source '" + s + "' (read, proposed, applied, imported)");
}

Result<SessionStatus> sessionStatusFrom(const std::string& s)
{
    for (auto v : {SessionStatus::Completed, SessionStatus::Aborted, SessionStatus::Failed}) {
        if (s == toString(v))
            return v;
    }
    return makeError(ErrorCode::BadInput, "unknown session status '" + s + "' (completed, aborted, failed)");
}

std::string nowIso8601()
{
    const auto now = std::chrono::system_clock::now();
    const auto t = std::chrono::system_clock::to_time_t(now);
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[96];
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday,
                  tm.tm_hour, tm.tm_min, tm.tm_sec, static_cast<int>(ms));
    return buf;
}

namespace detail {

Error dbError(const std::string& path, const std::exception& e, const std::string& doing)
{
    if (const auto* se = dynamic_cast<const SQLite::Exception*>(&e)) {
        const int code = se->getErrorCode() & 0xff;
        if (code == SQLITE_NOTADB)
            return makeError(ErrorCode::BadInput, path + ": not an AxisTune store (not an SQLite database file)");
        if (code == SQLITE_CORRUPT)
            return makeError(ErrorCode::BadInput, path + ": the store is damaged (" + se->getErrorStr()
                                                      + ") while " + doing + "; restore a backup");
        if (code == SQLITE_BUSY || code == SQLITE_LOCKED)
            return makeError(ErrorCode::Busy, path + ": the store is locked by another program while " + doing);
        if (code == SQLITE_FULL)
            return makeError(ErrorCode::Io, path + ": disk full while " + doing + " (nothing was saved)");
        if (code == SQLITE_READONLY || code == SQLITE_CANTOPEN || code == SQLITE_PERM)
            return makeError(ErrorCode::Io, path + ": cannot write the store while " + doing + " (" + se->what() + ")");
    }
    return makeError(ErrorCode::Io, path + ": " + doing + " failed: " + e.what());
}

std::optional<std::int64_t> machineId(SQLite::Database& db, const std::string& machine)
{
    SQLite::Statement q(db, "SELECT id FROM machines WHERE name = ?");
    q.bind(1, machine);
    if (q.executeStep())
        return q.getColumn(0).getInt64();
    return std::nullopt;
}

std::int64_t ensureMachineId(SQLite::Database& db, const std::string& machine, const std::string& description)
{
    if (auto id = machineId(db, machine)) {
        if (!description.empty()) {
            SQLite::Statement u(db, "UPDATE machines SET description = ? WHERE id = ?");
            u.bind(1, description);
            u.bind(2, *id);
            u.exec();
        }
        return *id;
    }
    SQLite::Statement ins(db, "INSERT INTO machines(name, description, created) VALUES(?, ?, ?)");
    ins.bind(1, machine);
    ins.bind(2, description);
    ins.bind(3, nowIso8601());
    ins.exec();
    return db.getLastInsertRowid();
}

std::int64_t ensureAxisId(SQLite::Database& db, std::int64_t machine, const std::string& axis)
{
    SQLite::Statement q(db, "SELECT id FROM axes WHERE machine_id = ? AND name = ?");
    q.bind(1, machine);
    q.bind(2, axis);
    if (q.executeStep())
        return q.getColumn(0).getInt64();
    SQLite::Statement ins(db, "INSERT INTO axes(machine_id, name, position) "
                              "VALUES(?1, ?2, (SELECT coalesce(max(position), -1) + 1 FROM axes WHERE machine_id = ?1))");
    ins.bind(1, machine);
    ins.bind(2, axis);
    ins.exec();
    return db.getLastInsertRowid();
}

std::int64_t insertParameterSet(SQLite::Database& db, std::int64_t axisId, const std::string& source,
                                const std::string& time, const std::string& note,
                                const std::vector<std::pair<std::string, double>>& values,
                                std::optional<std::int64_t> sessionId)
{
    SQLite::Statement ins(db, "INSERT INTO parameter_sets(axis_id, source, time, note, session_id) VALUES(?, ?, ?, ?, ?)");
    ins.bind(1, axisId);
    ins.bind(2, source);
    ins.bind(3, time.empty() ? nowIso8601() : time);
    ins.bind(4, note);
    if (sessionId)
        ins.bind(5, *sessionId);
    else
        ins.bind(5);
    ins.exec();
    const auto setId = db.getLastInsertRowid();
    SQLite::Statement v(db, "INSERT INTO parameter_values(set_id, key, value) VALUES(?, ?, ?)");
    for (const auto& [key, value] : values) {
        v.bind(1, setId);
        v.bind(2, key);
        v.bind(3, value);
        v.exec();
        v.reset();
    }
    return setId;
}

std::int64_t insertModel(SQLite::Database& db, std::int64_t axisId, const std::string& kind, const std::string& time,
                         const std::string& json, std::optional<std::int64_t> sessionId)
{
    SQLite::Statement ins(db, "INSERT INTO models(axis_id, kind, time, data, session_id) VALUES(?, ?, ?, ?, ?)");
    ins.bind(1, axisId);
    ins.bind(2, kind);
    ins.bind(3, time.empty() ? nowIso8601() : time);
    ins.bind(4, json);
    if (sessionId)
        ins.bind(5, *sessionId);
    else
        ins.bind(5);
    ins.exec();
    return db.getLastInsertRowid();
}

void bindFloat64Blob(SQLite::Statement& st, int index, const std::vector<double>& values, std::vector<char>& scratch)
{
    const int bytes = static_cast<int>(values.size() * sizeof(double));
    if constexpr (std::endian::native == std::endian::little) {
        st.bindNoCopy(index, values.data(), bytes);
    } else {
        scratch.resize(values.size() * sizeof(double));
        for (std::size_t i = 0; i < values.size(); ++i) {
            const auto u = __builtin_bswap64(std::bit_cast<std::uint64_t>(values[i]));
            std::memcpy(scratch.data() + i * 8, &u, 8);
        }
        st.bindNoCopy(index, scratch.data(), bytes);
    }
}

bool readFloat64Blob(const SQLite::Column& col, std::vector<double>& out)
{
    const int bytes = col.getBytes();
    const void* p = col.getBlob();
    if (bytes % 8 != 0)
        return false;
    out.resize(static_cast<std::size_t>(bytes) / 8);
    if (bytes > 0)
        std::memcpy(out.data(), p, static_cast<std::size_t>(bytes));
    if constexpr (std::endian::native != std::endian::little) {
        for (auto& v : out)
            v = std::bit_cast<double>(__builtin_bswap64(std::bit_cast<std::uint64_t>(v)));
    }
    return true;
}

bool readFloat64BlobDirect(SQLite::Database& db, const char* table, std::int64_t rowid, std::int64_t bytes,
                           std::vector<double>& out)
{
    if (bytes < 0 || bytes % 8 != 0)
        return false;
    out.resize(static_cast<std::size_t>(bytes) / 8);
    if (bytes == 0)
        return true;
    sqlite3_blob* blob = nullptr;
    int rc = sqlite3_blob_open(db.getHandle(), "main", table, "data", rowid, 0, &blob);
    if (rc == SQLITE_OK) {
        if (sqlite3_blob_bytes(blob) != bytes)
            rc = SQLITE_CORRUPT;
        else
            rc = sqlite3_blob_read(blob, out.data(), static_cast<int>(bytes), 0);
    }
    sqlite3_blob_close(blob);
    if (rc != SQLITE_OK)
        throw SQLite::Exception(db.getHandle(), rc);
    if constexpr (std::endian::native != std::endian::little) {
        for (auto& v : out)
            v = std::bit_cast<double>(__builtin_bswap64(std::bit_cast<std::uint64_t>(v)));
    }
    return true;
}

}  // namespace detail

namespace {

std::uint32_t be32(const unsigned char* p)
{
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | std::uint32_t(p[3]);
}

/// Checks the raw file before SQLite sees it: the magic string, and that the file is as long as its
/// header says (a truncated copy otherwise opens and fails later in a confusing place).
Status checkFileHeader(const std::string& path)
{
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec)
        return makeError(ErrorCode::Io, path + ": cannot read the file size (" + ec.message() + ")");
    if (size == 0)
        return Status::success();  // an empty file becomes a new store
    std::array<unsigned char, 100> h{};
    std::ifstream f(path, std::ios::binary);
    if (!f)
        return makeError(ErrorCode::Io, path + ": cannot be opened for reading");
    f.read(reinterpret_cast<char*>(h.data()), static_cast<std::streamsize>(h.size()));
    const auto got = static_cast<std::size_t>(f.gcount());
    static const char kMagic[] = "SQLite format 3";
    if (got < 16 || std::memcmp(h.data(), kMagic, 16) != 0)
        return makeError(ErrorCode::BadInput, path + ": not an AxisTune store (not an SQLite database file)");
    if (got < 100)
        return makeError(ErrorCode::BadInput, path + ": truncated store (" + std::to_string(size)
                                                  + " bytes, shorter than the 100-byte SQLite header); restore a backup");
    std::uint32_t pageSize = (std::uint32_t(h[16]) << 8) | h[17];
    if (pageSize == 1)
        pageSize = 65536;
    if (pageSize < 512 || (pageSize & (pageSize - 1)) != 0)
        return makeError(ErrorCode::BadInput, path + ": damaged store header (page size " + std::to_string(pageSize) + ")");
    // With a non-empty write-ahead log the log may legitimately hold pages beyond the main file's end
    // (e.g. after a kill during a checkpoint); SQLite recovers from it, so the length check is skipped.
    const auto wal = fs::path(path + "-wal");
    if (fs::exists(wal, ec) && fs::file_size(wal, ec) > 0)
        return Status::success();
    const std::uint32_t changeCounter = be32(h.data() + 24);
    const std::uint32_t pages = be32(h.data() + 28);
    const std::uint32_t validFor = be32(h.data() + 92);
    if (pages > 0 && changeCounter == validFor) {
        const std::uint64_t expected = std::uint64_t(pages) * pageSize;
        if (size < expected) {
            return makeError(ErrorCode::BadInput,
                             path + ": truncated store (the header announces " + std::to_string(pages) + " pages of "
                                 + std::to_string(pageSize) + " bytes = " + std::to_string(expected)
                                 + " bytes, the file has " + std::to_string(size) + " bytes); restore a backup");
        }
    }
    if (size % pageSize != 0) {
        return makeError(ErrorCode::BadInput, path + ": truncated store (" + std::to_string(size)
                                                  + " bytes is not a whole number of " + std::to_string(pageSize)
                                                  + "-byte pages); restore a backup");
    }
    return Status::success();
}

}  // namespace

void removeFailedOpenLeftovers(const std::string& path, bool created)
{
    std::error_code ec;
    const fs::path wal(path + "-wal"), shm(path + "-shm");
    // A live WAL connection has a wal-index of at least one 32 KiB page; a 0-byte log holds no frame.
    // Only such leftovers of a failed open are removed, never a log or index another connection uses.
    const bool emptyWal = !fs::exists(wal, ec) || fs::file_size(wal, ec) == 0;
    const bool deadShm = !fs::exists(shm, ec) || fs::file_size(shm, ec) < 32768;
    if (emptyWal && deadShm) {
        fs::remove(wal, ec);
        fs::remove(shm, ec);
    }
    if (created && emptyWal && deadShm)
        fs::remove(path, ec); // the store this call was creating
}

Database::Database(std::string path, std::unique_ptr<SQLite::Database> db) : m_path(std::move(path)), m_db(std::move(db)) {}
Database::Database(Database&&) noexcept = default;
Database& Database::operator=(Database&&) noexcept = default;
Database::~Database() = default;

Result<Database> Database::open(const std::string& path, OpenMode mode)
{
    std::error_code ec;
    const bool exists = fs::exists(path, ec);
    if (!exists && mode == OpenMode::MustExist)
        return makeError(ErrorCode::NotFound, path + ": no such store");
    if (exists) {
        if (!fs::is_regular_file(path, ec))
            return makeError(ErrorCode::BadInput, path + ": not a regular file");
        if (auto st = checkFileHeader(path); !st)
            return st.error();
    }
    std::unique_ptr<SQLite::Database> db;
    // A failed open leaves nothing behind: no new empty store, no -wal/-shm that SQLite made and could
    // not use (e.g. a -shm it could not grow on a full disk).
    auto failed = [&](Error e) {
        const int sysErr = db ? sqlite3_system_errno(db->getHandle()) : 0;
        db.reset();
        removeFailedOpenLeftovers(path, !exists);
        if (sysErr == ENOSPC)
            return makeError(ErrorCode::Io, path + ": disk full while opening the store (nothing was saved)");
        if (sysErr == EROFS || sysErr == EACCES || sysErr == EPERM)
            return makeError(ErrorCode::Io, path +
                                                ": the store is read-only (file, folder or file system not writable; " +
                                                std::strerror(sysErr) + "); nothing can be saved in it");
        return e;
    };
    try {
        db = std::make_unique<SQLite::Database>(path, SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
        db->setBusyTimeout(5000);
        db->exec("PRAGMA foreign_keys = ON");
        // Reading the schema makes SQLite parse page 1 and the schema table: a foreign or damaged
        // file fails here, before anything is written.
        const int tables = db->execAndGet("SELECT count(*) FROM sqlite_master").getInt();
        const int userVersion = db->execAndGet("PRAGMA user_version").getInt();
        const int appId = db->execAndGet("PRAGMA application_id").getInt();
        if (userVersion > kSchemaVersion) {
            return makeError(ErrorCode::BadInput, path + ": written by a newer AxisTune (store schema version "
                                                      + std::to_string(userVersion) + ", this version reads up to "
                                                      + std::to_string(kSchemaVersion) + "); refusing to open it");
        }
        if (appId != kApplicationId && (tables > 0 || userVersion > 0))
            return makeError(ErrorCode::BadInput, path + ": an SQLite database of another program, not an AxisTune store");
        if (tables == 0)
            db->exec("PRAGMA page_size = 65536");  // large BLOB channels: fewer overflow pages
        const std::string journal = db->execAndGet("PRAGMA journal_mode = WAL").getString();
        if (journal != "wal")
            return makeError(ErrorCode::Io, path + ": cannot switch the store to WAL mode (journal mode '" + journal + "')");
        db->exec("PRAGMA synchronous = FULL");
    } catch (const std::exception& e) {
        return failed(detail::dbError(path, e, "opening the store"));
    }
    Database result(path, std::move(db));
    if (auto st = result.migrate(); !st) {
        result.m_db.reset();
        removeFailedOpenLeftovers(path, !exists);
        return st.error();
    }
    return result;
}

int Database::schemaVersion() const
{
    return m_db->execAndGet("PRAGMA user_version").getInt();
}

Status Database::migrate()
{
    try {
        int version = schemaVersion();
        for (const auto& m : migrations()) {
            if (m.version <= version)
                continue;
            SQLite::Transaction tx(*m_db, SQLite::TransactionBehavior::IMMEDIATE);
            // Re-read inside the write lock: another process may have migrated meanwhile.
            version = schemaVersion();
            if (m.version <= version)
                continue;
            m_db->exec(m.sql);
            m_db->exec("PRAGMA user_version = " + std::to_string(m.version));
            m_db->exec("PRAGMA application_id = " + std::to_string(kApplicationId));
            tx.commit();
            version = m.version;
        }
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "migrating the store schema");
    }
    return Status::success();
}

Result<std::vector<std::string>> Database::listMachines() const
{
    try {
        std::vector<std::string> out;
        SQLite::Statement q(*m_db, "SELECT name FROM machines ORDER BY name");
        while (q.executeStep())
            out.push_back(q.getColumn(0).getString());
        return out;
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "listing machines");
    }
}

Status Database::ensureMachine(const std::string& machine, const std::vector<std::string>& axes,
                               const std::string& description)
{
    if (machine.empty())
        return makeError(ErrorCode::BadInput, "machine name must not be empty");
    try {
        SQLite::Transaction tx(*m_db, SQLite::TransactionBehavior::IMMEDIATE);
        const auto id = detail::ensureMachineId(*m_db, machine, description);
        for (const auto& a : axes)
            detail::ensureAxisId(*m_db, id, a);
        tx.commit();
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "saving machine '" + machine + "'");
    }
    return Status::success();
}

Result<std::int64_t> Database::saveParameterSet(const std::string& machine, const ParameterSet& set,
                                                std::optional<std::int64_t> sessionId)
{
    try {
        SQLite::Transaction tx(*m_db, SQLite::TransactionBehavior::IMMEDIATE);
        const auto mid = detail::ensureMachineId(*m_db, machine, {});
        const auto aid = detail::ensureAxisId(*m_db, mid, set.axis);
        const auto id = detail::insertParameterSet(*m_db, aid, toString(set.source), set.time, set.note,
                                                   {set.values.begin(), set.values.end()}, sessionId);
        tx.commit();
        return id;
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "saving parameters of " + machine + "/" + set.axis);
    }
}

Result<model::ParameterValues> Database::currentParameters(const std::string& machine, const std::string& axis) const
{
    try {
        model::ParameterValues out;
        SQLite::Statement q(*m_db, "SELECT v.key, v.value FROM parameter_values v "
                                   "JOIN parameter_sets s ON s.id = v.set_id JOIN axes a ON a.id = s.axis_id "
                                   "JOIN machines m ON m.id = a.machine_id "
                                   "WHERE m.name = ? AND a.name = ? AND s.source != 'proposed' ORDER BY s.id");
        q.bind(1, machine);
        q.bind(2, axis);
        while (q.executeStep())
            out[q.getColumn(0).getString()] = q.getColumn(1).getDouble();
        return out;
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "reading parameters of " + machine + "/" + axis);
    }
}

Result<std::vector<ParameterSet>> Database::parameterSets(const std::string& machine, const std::string& axis) const
{
    try {
        std::vector<ParameterSet> out;
        SQLite::Statement q(*m_db, "SELECT s.id, s.source, s.time, s.note FROM parameter_sets s "
                                   "JOIN axes a ON a.id = s.axis_id JOIN machines m ON m.id = a.machine_id "
                                   "WHERE m.name = ? AND a.name = ? ORDER BY s.id");
        q.bind(1, machine);
        q.bind(2, axis);
        SQLite::Statement v(*m_db, "SELECT key, value FROM parameter_values WHERE set_id = ?");
        while (q.executeStep()) {
            ParameterSet s;
            s.id = q.getColumn(0).getInt64();
            s.axis = axis;
            auto src = parameterSourceFrom(q.getColumn(1).getString());
            s.source = src ? *src : ParameterSource::Read;
            s.time = q.getColumn(2).getString();
            s.note = q.getColumn(3).getString();
            v.bind(1, s.id);
            while (v.executeStep())
                s.values[v.getColumn(0).getString()] = v.getColumn(1).getDouble();
            v.reset();
            out.push_back(std::move(s));
        }
        return out;
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "reading parameter sets of " + machine + "/" + axis);
    }
}

Result<std::int64_t> Database::saveModel(const std::string& machine, const ModelRecord& model,
                                         std::optional<std::int64_t> sessionId)
{
    if (!io::isModelKind(model.kind))
        return makeError(ErrorCode::BadInput, "unknown model kind '" + model.kind + "'");
    try {
        SQLite::Transaction tx(*m_db, SQLite::TransactionBehavior::IMMEDIATE);
        const auto mid = detail::ensureMachineId(*m_db, machine, {});
        const auto aid = detail::ensureAxisId(*m_db, mid, model.axis);
        const auto id =
            detail::insertModel(*m_db, aid, model.kind, model.time,
                                model.data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), sessionId);
        tx.commit();
        return id;
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "saving the " + model.kind + " model of " + machine + "/" + model.axis);
    }
}

Result<std::vector<JournalEntry>> Database::journal(const std::string& machine) const
{
    try {
        std::vector<JournalEntry> out;
        SQLite::Statement q(*m_db, "SELECT j.id, a.name, j.key, j.old_value, j.new_value, j.time, j.session_id "
                                   "FROM journal j JOIN axes a ON a.id = j.axis_id JOIN machines m ON m.id = a.machine_id "
                                   "WHERE m.name = ? ORDER BY j.id");
        q.bind(1, machine);
        while (q.executeStep()) {
            JournalEntry e;
            e.id = q.getColumn(0).getInt64();
            e.machine = machine;
            e.axis = q.getColumn(1).getString();
            e.key = q.getColumn(2).getString();
            if (!q.getColumn(3).isNull())
                e.oldValue = q.getColumn(3).getDouble();
            e.newValue = q.getColumn(4).getDouble();
            e.time = q.getColumn(5).getString();
            if (!q.getColumn(6).isNull())
                e.sessionId = q.getColumn(6).getInt64();
            out.push_back(std::move(e));
        }
        return out;
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "reading the journal of " + machine);
    }
}

Result<io::MachineProfile> Database::loadProfile(const std::string& machine) const
{
    try {
        io::MachineProfile p;
        SQLite::Statement qm(*m_db, "SELECT id, description FROM machines WHERE name = ?");
        qm.bind(1, machine);
        if (!qm.executeStep())
            return makeError(ErrorCode::NotFound, m_path + ": no machine '" + machine + "' in the store");
        const auto mid = qm.getColumn(0).getInt64();
        p.name = machine;
        p.description = qm.getColumn(1).getString();
        SQLite::Statement qa(*m_db, "SELECT id, name FROM axes WHERE machine_id = ? ORDER BY position");
        qa.bind(1, mid);
        SQLite::Statement qmod(*m_db, "SELECT kind, data FROM models WHERE axis_id = ? ORDER BY id");
        while (qa.executeStep()) {
            io::AxisProfile a;
            a.name = qa.getColumn(1).getString();
            auto params = currentParameters(machine, a.name);
            if (!params)
                return params.error();
            a.parameters = *params;
            qmod.bind(1, qa.getColumn(0).getInt64());
            while (qmod.executeStep())
                a.models[qmod.getColumn(0).getString()] = nlohmann::json::parse(qmod.getColumn(1).getString());
            qmod.reset();
            p.axes.push_back(std::move(a));
        }
        return p;
    } catch (const nlohmann::json::exception& e) {
        return makeError(ErrorCode::BadInput, m_path + ": a stored model of '" + machine + "' is not valid JSON (" + e.what() + ")");
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "reading the profile of " + machine);
    }
}

Result<std::int64_t> Database::importProfile(const io::MachineProfile& profile, const std::string& sourceName,
                                             const std::string& note)
{
    SessionRecord rec;
    rec.info.machine = profile.name;
    rec.info.kind = "profile-import";
    rec.info.note = note;
    rec.inputs = {{"source", sourceName}, {"description", profile.description}};
    rec.machineDescription = profile.description;
    for (const auto& a : profile.axes) {
        rec.machineAxes.push_back(a.name);
        ParameterSet s;
        s.axis = a.name;
        s.source = ParameterSource::Imported;
        s.note = "imported from " + sourceName;
        s.values = a.parameters;
        if (!s.values.empty())
            rec.parameterSets.push_back(std::move(s));
        for (const auto& [kind, data] : a.models)
            rec.models.push_back(ModelRecord{0, a.name, kind, {}, data});
    }
    rec.inputs["axes"] = rec.machineAxes;
    return recordSession(rec);
}

Status Database::checkWritable() const
{
    // SQLite silently opens a store it may not write (permissions, read-only file system) read-only.
    if (sqlite3_db_readonly(m_db->getHandle(), "main") == 1)
        return makeError(ErrorCode::Io, m_path + ": the store is read-only (file, folder or file system not writable); "
                                                 "nothing can be saved in it");
    try {
        m_db->exec("BEGIN IMMEDIATE"); // takes the write lock, writes nothing
        m_db->exec("ROLLBACK");
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "checking that the store can be written");
    }
    return Status::success();
}

Result<std::string> Database::integrityCheck() const
{
    try {
        std::string out;
        SQLite::Statement q(*m_db, "PRAGMA integrity_check");
        while (q.executeStep()) {
            if (!out.empty())
                out += "; ";
            out += q.getColumn(0).getString();
        }
        return out;
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "checking integrity");
    }
}

}  // namespace axistune::store
