// SPDX-License-Identifier: GPL-3.0-or-later
// Sessions in the store: one transaction per recorded session, captures and result arrays as
// little-endian float64 BLOBs (docs/storage.md "Sessions").
#include "core/io/Profile.h"
#include "core/model/MetadataJson.h"
#include "core/store/Database.h"
#include "core/store/DatabaseDetail.h"
#include "core/store/SessionRecord.h"

#include <SQLiteCpp/SQLiteCpp.h>
#include <nlohmann/json.hpp>

namespace axistune::store {

namespace {

Status checkRecord(const SessionRecord& r)
{
    if (r.info.kind.empty())
        return makeError(ErrorCode::BadInput, "session kind must not be empty");
    const bool needsMachine = !r.parameterSets.empty() || !r.models.empty() || !r.journal.empty();
    if (needsMachine && r.info.machine.empty())
        return makeError(ErrorCode::BadInput, "a session with parameters, models or journal entries needs a machine");
    for (const auto& c : r.captures) {
        for (const auto& ch : c.capture.channels) {
            if (ch.data.size() != c.capture.size())
                return makeError(ErrorCode::BadInput, "capture '" + c.name + "': channel '" + ch.name
                                                          + "' has " + std::to_string(ch.data.size()) + " samples, expected "
                                                          + std::to_string(c.capture.size()));
        }
    }
    for (const auto& m : r.models) {
        if (!io::isModelKind(m.kind))
            return makeError(ErrorCode::BadInput, "unknown model kind '" + m.kind + "'");
    }
    return Status::success();
}

std::int64_t insertSessionRow(SQLite::Database& db, const SessionInfo& info, std::optional<std::int64_t> machineId,
                              const nlohmann::json& inputs)
{
    SQLite::Statement ins(db, "INSERT INTO sessions(machine_id, axis, kind, started, finished, status, app_version, "
                              "inputs, operator, note) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    const std::string now = nowIso8601();
    if (machineId)
        ins.bind(1, *machineId);
    else
        ins.bind(1);
    ins.bind(2, info.axis);
    ins.bind(3, info.kind);
    ins.bind(4, info.started.empty() ? now : info.started);
    ins.bind(5, info.finished.empty() ? now : info.finished);
    ins.bind(6, toString(info.status));
    ins.bind(7, info.appVersion.empty() ? std::string(AXISTUNE_VERSION) : info.appVersion);
    ins.bind(8, inputs.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    ins.bind(9, info.operatorName);
    ins.bind(10, info.note);
    ins.exec();
    return db.getLastInsertRowid();
}

void insertCaptures(SQLite::Database& db, std::int64_t sessionId, const std::vector<NamedCapture>& captures,
                    const std::function<void(double)>& progress)
{
    double total = 1.0, written = 0.0; // samples of every channel, + 1 for the rest of the session
    for (const auto& c : captures)
        for (const auto& ch : c.capture.channels)
            total += static_cast<double>(ch.data.size());
    SQLite::Statement cap(db, "INSERT INTO captures(session_id, position, name, metadata, samples) VALUES(?, ?, ?, ?, ?)");
    SQLite::Statement ch(db, "INSERT INTO capture_channels(capture_id, position, name, data) VALUES(?, ?, ?, ?)");
    std::vector<char> scratch;
    for (std::size_t i = 0; i < captures.size(); ++i) {
        const auto& c = captures[i];
        nlohmann::json meta(c.capture.metadata);
        cap.bind(1, sessionId);
        cap.bind(2, static_cast<std::int64_t>(i));
        cap.bind(3, c.name);
        cap.bind(4, meta.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
        cap.bind(5, static_cast<std::int64_t>(c.capture.size()));
        cap.exec();
        cap.reset();
        const auto captureId = db.getLastInsertRowid();
        for (std::size_t k = 0; k < c.capture.channels.size(); ++k) {
            ch.bind(1, captureId);
            ch.bind(2, static_cast<std::int64_t>(k));
            ch.bind(3, c.capture.channels[k].name);
            detail::bindFloat64Blob(ch, 4, c.capture.channels[k].data, scratch);
            ch.exec();
            ch.reset();
            written += static_cast<double>(c.capture.channels[k].data.size());
            if (progress)
                progress(written / total);
        }
    }
}

void insertResults(SQLite::Database& db, std::int64_t sessionId, const std::vector<SessionResult>& results)
{
    SQLite::Statement res(db, "INSERT INTO results(session_id, position, name, data) VALUES(?, ?, ?, ?)");
    SQLite::Statement arr(db, "INSERT INTO result_arrays(result_id, position, name, data) VALUES(?, ?, ?, ?)");
    std::vector<char> scratch;
    for (std::size_t i = 0; i < results.size(); ++i) {
        res.bind(1, sessionId);
        res.bind(2, static_cast<std::int64_t>(i));
        res.bind(3, results[i].name);
        res.bind(4, results[i].data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
        res.exec();
        res.reset();
        const auto resultId = db.getLastInsertRowid();
        for (std::size_t k = 0; k < results[i].arrays.size(); ++k) {
            arr.bind(1, resultId);
            arr.bind(2, static_cast<std::int64_t>(k));
            arr.bind(3, results[i].arrays[k].name);
            detail::bindFloat64Blob(arr, 4, results[i].arrays[k].data, scratch);
            arr.exec();
            arr.reset();
        }
    }
}

void insertJournal(SQLite::Database& db, std::int64_t machineId, std::int64_t sessionId,
                   const std::vector<JournalEntry>& journal)
{
    SQLite::Statement ins(db, "INSERT INTO journal(axis_id, key, old_value, new_value, time, session_id) "
                              "VALUES(?, ?, ?, ?, ?, ?)");
    for (const auto& e : journal) {
        ins.bind(1, detail::ensureAxisId(db, machineId, e.axis));
        ins.bind(2, e.key);
        if (e.oldValue)
            ins.bind(3, *e.oldValue);
        else
            ins.bind(3);
        ins.bind(4, e.newValue);
        ins.bind(5, e.time.empty() ? nowIso8601() : e.time);
        ins.bind(6, sessionId);
        ins.exec();
        ins.reset();
    }
}

SessionInfo readInfo(SQLite::Statement& q)
{
    SessionInfo s;
    s.id = q.getColumn(0).getInt64();
    s.machine = q.getColumn(1).isNull() ? std::string() : q.getColumn(1).getString();
    s.axis = q.getColumn(2).getString();
    s.kind = q.getColumn(3).getString();
    s.started = q.getColumn(4).getString();
    s.finished = q.getColumn(5).getString();
    auto st = sessionStatusFrom(q.getColumn(6).getString());
    s.status = st ? *st : SessionStatus::Failed;
    s.appVersion = q.getColumn(7).getString();
    s.operatorName = q.getColumn(8).getString();
    s.note = q.getColumn(9).getString();
    s.captureCount = q.getColumn(10).getInt();
    s.resultCount = q.getColumn(11).getInt();
    return s;
}

const char* kSessionColumns =
    "SELECT s.id, m.name, s.axis, s.kind, s.started, s.finished, s.status, s.app_version, s.operator, s.note, "
    "(SELECT count(*) FROM captures c WHERE c.session_id = s.id), "
    "(SELECT count(*) FROM results r WHERE r.session_id = s.id), s.inputs "
    "FROM sessions s LEFT JOIN machines m ON m.id = s.machine_id ";

}  // namespace

Result<std::int64_t> Database::recordSession(const SessionRecord& r, const std::function<void(double)>& progress)
{
    if (auto st = checkRecord(r); !st)
        return st.error();
    try {
        SQLite::Transaction tx(*m_db, SQLite::TransactionBehavior::IMMEDIATE);
        std::optional<std::int64_t> mid;
        if (!r.info.machine.empty()) {
            mid = detail::ensureMachineId(*m_db, r.info.machine, r.machineDescription);
            for (const auto& a : r.machineAxes)
                detail::ensureAxisId(*m_db, *mid, a);
            if (!r.info.axis.empty())
                detail::ensureAxisId(*m_db, *mid, r.info.axis);
        }
        const auto sid = insertSessionRow(*m_db, r.info, mid, r.inputs);
        insertCaptures(*m_db, sid, r.captures, progress);
        insertResults(*m_db, sid, r.results);
        for (const auto& s : r.parameterSets) {
            detail::insertParameterSet(*m_db, detail::ensureAxisId(*m_db, *mid, s.axis), toString(s.source), s.time,
                                       s.note, {s.values.begin(), s.values.end()}, sid);
        }
        for (const auto& m : r.models)
            detail::insertModel(*m_db, detail::ensureAxisId(*m_db, *mid, m.axis), m.kind, m.time,
                                m.data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), sid);
        if (mid)
            insertJournal(*m_db, *mid, sid, r.journal);
        tx.commit();
        if (progress)
            progress(1.0);
        return sid;
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "saving a '" + r.info.kind + "' session");
    }
}

Result<std::vector<SessionInfo>> Database::listSessions(const std::string& machine) const
{
    try {
        std::vector<SessionInfo> out;
        SQLite::Statement q(*m_db, std::string(kSessionColumns) + (machine.empty() ? "" : "WHERE m.name = ? ") + "ORDER BY s.id");
        if (!machine.empty())
            q.bind(1, machine);
        while (q.executeStep())
            out.push_back(readInfo(q));
        return out;
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "listing sessions");
    }
}

Result<SessionRecord> Database::loadSession(std::int64_t id) const
{
    const std::string what = "session " + std::to_string(id);
    try {
        SessionRecord r;
        SQLite::Statement q(*m_db, std::string(kSessionColumns) + "WHERE s.id = ?");
        q.bind(1, id);
        if (!q.executeStep())
            return makeError(ErrorCode::NotFound, m_path + ": no session " + std::to_string(id));
        r.info = readInfo(q);
        r.inputs = nlohmann::json::parse(q.getColumn(12).getString());

        SQLite::Statement qc(*m_db, "SELECT id, name, metadata, samples FROM captures WHERE session_id = ? ORDER BY position");
        SQLite::Statement qch(*m_db, "SELECT name, id, length(data) FROM capture_channels WHERE capture_id = ? ORDER BY position");
        qc.bind(1, id);
        while (qc.executeStep()) {
            NamedCapture c;
            c.name = qc.getColumn(1).getString();
            auto meta = model::metadataFromJson(nlohmann::json::parse(qc.getColumn(2).getString()));
            if (!meta)
                return makeError(ErrorCode::BadInput,
                                 m_path + ": " + what + ", capture '" + c.name + "': " + meta.error().detail);
            c.capture.metadata = std::move(meta).value();
            const auto samples = static_cast<std::size_t>(qc.getColumn(3).getInt64());
            qch.bind(1, qc.getColumn(0).getInt64());
            while (qch.executeStep()) {
                model::Channel ch;
                ch.name = qch.getColumn(0).getString();
                if (!detail::readFloat64BlobDirect(*m_db, "capture_channels", qch.getColumn(1).getInt64(),
                                                   qch.getColumn(2).getInt64(), ch.data)
                    || ch.data.size() != samples) {
                    return makeError(ErrorCode::BadInput, m_path + ": " + what + ", capture '" + c.name + "', channel '"
                                                              + ch.name + "': stored data has the wrong length");
                }
                c.capture.channels.push_back(std::move(ch));
            }
            qch.reset();
            r.captures.push_back(std::move(c));
        }

        SQLite::Statement qr(*m_db, "SELECT id, name, data FROM results WHERE session_id = ? ORDER BY position");
        SQLite::Statement qa(*m_db, "SELECT name, data FROM result_arrays WHERE result_id = ? ORDER BY position");
        qr.bind(1, id);
        while (qr.executeStep()) {
            SessionResult res;
            res.name = qr.getColumn(1).getString();
            res.data = nlohmann::json::parse(qr.getColumn(2).getString());
            qa.bind(1, qr.getColumn(0).getInt64());
            while (qa.executeStep()) {
                model::Channel arr;
                arr.name = qa.getColumn(0).getString();
                if (!detail::readFloat64Blob(qa.getColumn(1), arr.data)) {
                    return makeError(ErrorCode::BadInput, m_path + ": " + what + ", result '" + res.name + "', array '"
                                                              + arr.name + "': stored data has the wrong length");
                }
                res.arrays.push_back(std::move(arr));
            }
            qa.reset();
            r.results.push_back(std::move(res));
        }

        SQLite::Statement qp(*m_db, "SELECT s.id, a.name, s.source, s.time, s.note FROM parameter_sets s "
                                    "JOIN axes a ON a.id = s.axis_id WHERE s.session_id = ? ORDER BY s.id");
        SQLite::Statement qv(*m_db, "SELECT key, value FROM parameter_values WHERE set_id = ?");
        qp.bind(1, id);
        while (qp.executeStep()) {
            ParameterSet s;
            s.id = qp.getColumn(0).getInt64();
            s.axis = qp.getColumn(1).getString();
            auto src = parameterSourceFrom(qp.getColumn(2).getString());
            s.source = src ? *src : ParameterSource::Read;
            s.time = qp.getColumn(3).getString();
            s.note = qp.getColumn(4).getString();
            qv.bind(1, s.id);
            while (qv.executeStep())
                s.values[qv.getColumn(0).getString()] = qv.getColumn(1).getDouble();
            qv.reset();
            r.parameterSets.push_back(std::move(s));
        }

        SQLite::Statement qm(*m_db, "SELECT m.id, a.name, m.kind, m.time, m.data FROM models m "
                                    "JOIN axes a ON a.id = m.axis_id WHERE m.session_id = ? ORDER BY m.id");
        qm.bind(1, id);
        while (qm.executeStep()) {
            r.models.push_back(ModelRecord{qm.getColumn(0).getInt64(), qm.getColumn(1).getString(),
                                           qm.getColumn(2).getString(), qm.getColumn(3).getString(),
                                           nlohmann::json::parse(qm.getColumn(4).getString())});
        }

        SQLite::Statement qj(*m_db, "SELECT j.id, a.name, j.key, j.old_value, j.new_value, j.time FROM journal j "
                                    "JOIN axes a ON a.id = j.axis_id WHERE j.session_id = ? ORDER BY j.id");
        qj.bind(1, id);
        while (qj.executeStep()) {
            JournalEntry e;
            e.id = qj.getColumn(0).getInt64();
            e.machine = r.info.machine;
            e.axis = qj.getColumn(1).getString();
            e.key = qj.getColumn(2).getString();
            if (!qj.getColumn(3).isNull())
                e.oldValue = qj.getColumn(3).getDouble();
            e.newValue = qj.getColumn(4).getDouble();
            e.time = qj.getColumn(5).getString();
            e.sessionId = id;
            r.journal.push_back(std::move(e));
        }
        return r;
    } catch (const nlohmann::json::exception& e) {
        return makeError(ErrorCode::BadInput, m_path + ": " + what + " holds invalid JSON (" + e.what() + ")");
    } catch (const std::exception& e) {
        return detail::dbError(m_path, e, "reading " + what);
    }
}

}  // namespace axistune::store
