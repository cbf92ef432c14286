// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli profile import|export: a machine profile between a JSON file and the store
// (docs/storage.md, schema in docs/formats-profile.md).
#include "app/cli/CliCommand.h"
#include "core/io/Profile.h"
#include "core/model/InputLimits.h"
#include "core/store/Database.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct ProfileOptions {
    std::string db;
    std::string in;
    std::string out;
    std::string machine;
    std::string note;
    CLI::App* importCmd = nullptr;
    CLI::App* exportCmd = nullptr;
};

int runImport(const ProfileOptions& o)
{
    const std::string cmd = "profile import";
    auto profile = io::readProfileFile(o.in);
    if (!profile)
        return reportError(cmd, profile.error());
    std::error_code ec;
    const bool existed = std::filesystem::exists(o.db, ec);
    std::optional<store::Database> db;
    {
        auto opened = store::Database::open(o.db);
        if (!opened)
            return reportError(cmd, opened.error());
        db.emplace(std::move(opened).value());
    }
    auto sid = db->importProfile(*profile, o.in, o.note);
    if (!sid) {
        // A failed import changes nothing: the transaction is rolled back; closing checkpoints and
        // removes the log; a store this import was creating is removed again.
        db.reset();
        store::removeFailedOpenLeftovers(o.db, !existed);
        return reportError(cmd, sid.error());
    }
    nlohmann::json j{{"machine", profile->name}, {"axes", profile->axes.size()}, {"session", *sid}, {"db", o.db}};
    return writeJsonResult(cmd, j, "");
}

int runExport(const ProfileOptions& o)
{
    const std::string cmd = "profile export";
    auto db = store::Database::open(o.db, store::OpenMode::MustExist);
    if (!db)
        return reportError(cmd, db.error());
    auto profile = db->loadProfile(o.machine);
    if (!profile)
        return reportError(cmd, profile.error());
    if (o.out.empty()) {
        std::cout << io::profileToText(*profile);
        return 0;
    }
    if (auto st = io::writeProfileFile(o.out, *profile); !st)
        return reportError(cmd, st.error());
    return writeJsonResult(cmd, nlohmann::json{{"machine", o.machine}, {"file", model::displayPath(o.out)}}, "");
}

const CliRegistrar kRegistrar{CliCommand{
    "profile", "machine profiles: import a profile JSON into the store, export one from it",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<ProfileOptions>();
        sub.require_subcommand(1);
        o->importCmd = sub.add_subcommand("import", "create or update a machine from a profile JSON (records a session)");
        o->importCmd->add_option("--db", o->db, "store file (created if missing)")->required();
        o->importCmd->add_option("--in", o->in, "profile JSON (docs/formats-profile.md)")->required();
        o->importCmd->add_option("--note", o->note, "note stored with the import session");
        o->exportCmd = sub.add_subcommand("export", "write a machine's profile (current parameters and models) as JSON");
        o->exportCmd->add_option("--db", o->db, "store file")->required();
        o->exportCmd->add_option("--machine", o->machine, "machine name")->required();
        o->exportCmd->add_option("--out", o->out, "write to this file instead of stdout");
        return [o] { return o->importCmd->parsed() ? runImport(*o) : runExport(*o); };
    }}};

}  // namespace

}  // namespace axistune::cli
