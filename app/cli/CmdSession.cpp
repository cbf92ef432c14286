// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli session list|show|export: saved sessions in a store (docs/storage.md "Sessions").
#include "app/cli/CliCommand.h"
#include "core/store/Database.h"
#include "core/store/SessionExport.h"
#include "core/store/SessionRecord.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct SessionOptions {
    std::string db;
    std::string machine;
    std::int64_t id = 0;
    std::string out;
    CLI::App* list = nullptr;
    CLI::App* show = nullptr;
    CLI::App* exportCmd = nullptr;
};

int runSession(const SessionOptions& o)
{
    const std::string cmd = "session";
    auto db = store::Database::open(o.db, store::OpenMode::MustExist);
    if (!db)
        return reportError(cmd, db.error());
    if (o.list->parsed()) {
        auto sessions = db->listSessions(o.machine);
        if (!sessions)
            return reportError(cmd, sessions.error());
        nlohmann::json a = nlohmann::json::array();
        for (const auto& s : *sessions)
            a.push_back(store::sessionInfoJson(s));
        return writeJsonResult(cmd, a, "");
    }
    auto rec = db->loadSession(o.id);
    if (!rec)
        return reportError(cmd, rec.error());
    if (o.show->parsed()) {
        return writeJsonResult(cmd, store::sessionSummaryJson(*rec), "");
    }
    auto manifest = store::exportSessionFolder(*rec, o.out);
    if (!manifest)
        return reportError(cmd, manifest.error());
    return writeJsonResult(cmd, nlohmann::json{{"session", o.id}, {"folder", o.out}}, "");
}

const CliRegistrar kRegistrar{CliCommand{
    "session", "saved sessions: list, show one, export one to a folder of CSV files with a JSON manifest",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<SessionOptions>();
        sub.require_subcommand(1);
        o->list = sub.add_subcommand("list", "list sessions as JSON");
        o->list->add_option("--db", o->db, "store file")->required();
        o->list->add_option("--machine", o->machine, "only sessions of this machine");
        o->show = sub.add_subcommand("show", "one session as JSON (arrays by name and length)");
        o->show->add_option("--db", o->db, "store file")->required();
        o->show->add_option("--id", o->id, "session id")->required();
        o->exportCmd = sub.add_subcommand("export", "write one session to a folder: manifest.json and CSV files");
        o->exportCmd->add_option("--db", o->db, "store file")->required();
        o->exportCmd->add_option("--id", o->id, "session id")->required();
        o->exportCmd->add_option("--out", o->out, "folder (created if missing)")->required();
        return [o] { return runSession(*o); };
    }}};

}  // namespace

}  // namespace axistune::cli
