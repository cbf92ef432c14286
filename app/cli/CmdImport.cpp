// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli import: reads a profile JSON or a parameter CSV written by `export --format json|csv`
// into the store (docs/storage.md "Export and import").
#include "app/cli/CliCommand.h"
#include "core/io/Profile.h"
#include "core/model/InputLimits.h"
#include "core/store/Database.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct ImportOptions {
    std::string db;
    std::string in;
    std::string format;  // json | csv; empty: from the file extension
    std::string note;
};

std::string formatFromExtension(const std::string& path)
{
    const auto dot = path.rfind('.');
    return dot == std::string::npos ? std::string() : path.substr(dot + 1);
}

int runImport(const ImportOptions& o)
{
    const std::string cmd = "import";
    const std::string format = o.format.empty() ? formatFromExtension(o.in) : o.format;
    Result<io::MachineProfile> profile = makeError(ErrorCode::BadInput, "");
    if (format == "json") {
        profile = io::readProfileFile(o.in);
    } else if (format == "csv") {
        auto text = io::readTextFile(o.in);
        if (!text)
            return reportError(cmd, text.error());
        profile = io::parametersFromCsv(*text, o.in);
    } else {
        return reportError(cmd, makeError(ErrorCode::BadInput, o.in + ": cannot tell the format from the extension '"
                                                                   + format + "'; use --format json|csv"));
    }
    if (!profile)
        return reportError(cmd, profile.error());
    auto db = store::Database::open(o.db);
    if (!db)
        return reportError(cmd, db.error());
    auto sid = db.value().importProfile(*profile, o.in, o.note);
    if (!sid)
        return reportError(cmd, sid.error());
    std::size_t count = 0;
    for (const auto& a : profile->axes)
        count += a.parameters.size();
    return writeJsonResult(cmd,
                           {{"machine", profile->name},
                            {"format", format},
                            {"parameters", count},
                            {"session", *sid},
                            {"db", model::displayPath(o.db)}},
                           "");
}

const CliRegistrar kRegistrar{CliCommand{
    "import", "import a profile JSON or parameter CSV (as written by export) into the store",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<ImportOptions>();
        sub.add_option("--db", o->db, "store file (created if missing)")->required();
        sub.add_option("--in", o->in, "file to import")->required();
        sub.add_option("--format", o->format, "json or csv (default: from the extension)")
            ->check(CLI::IsMember({"json", "csv"}));
        sub.add_option("--note", o->note, "note stored with the import session");
        return [o] { return runImport(*o); };
    }}};

}  // namespace

}  // namespace axistune::cli
