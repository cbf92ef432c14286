// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli export: a machine's current parameters as an NC parameter file (map files in
// resources/nc/, to verify against the NC's manual) or as AxisTune JSON/CSV (docs/storage.md).
#include "app/cli/CliCommand.h"
#include "core/io/NcExport.h"
#include "core/io/Profile.h"
#include "core/model/InputLimits.h"
#include "core/store/Database.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct ExportOptions {
    std::string db;
    std::string machine;
    std::string format;
    std::string out;
    std::string map;  // NC map file; default resources/nc/<format>.json
};

int runExport(const ExportOptions& o)
{
    const std::string cmd = "export";
    auto db = store::Database::open(o.db, store::OpenMode::MustExist);
    if (!db)
        return reportError(cmd, db.error());
    auto profile = db->loadProfile(o.machine);
    if (!profile)
        return reportError(cmd, profile.error());
    std::string text;
    std::vector<std::string> unmapped;
    if (o.format == "json") {
        text = io::profileToText(*profile);
    } else if (o.format == "csv") {
        text = io::parametersToCsv(*profile);
    } else {
        const std::string mapPath = o.map.empty() ? io::defaultNcMapPath(o.format) : o.map;
        auto map = io::readNcMapFile(mapPath);
        if (!map)
            return reportError(cmd, map.error());
        auto nc = io::exportNc(*profile, *map);
        if (!nc)
            return reportError(cmd, nc.error());
        text = std::move(nc->text);
        unmapped = nc->unmapped;
        std::cerr << "axistune-cli export: " << mapPath << " is a template map: verify every parameter number, unit "
                  << "and scaling against the NC's parameter manual before loading the file\n";
        if (!unmapped.empty()) {
            std::cerr << "axistune-cli export: " << unmapped.size() << " parameters have no " << o.format
                      << " mapping and are NOT in the file (listed there as comments):";
            for (const auto& k : unmapped)
                std::cerr << ' ' << k;
            std::cerr << '\n';
        }
    }
    if (o.out.empty()) {
        std::cout << text;
        return 0;
    }
    if (auto st = io::writeTextFileAtomic(o.out, text); !st)
        return reportError(cmd, st.error());
    return writeJsonResult(
        cmd,
        {{"machine", o.machine}, {"format", o.format}, {"file", model::displayPath(o.out)}, {"unmapped", unmapped}},
        "");
}

const CliRegistrar kRegistrar{CliCommand{
    "export", "write a machine's parameters as an NC parameter file (fanuc, siemens, heidenhain) or JSON/CSV",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<ExportOptions>();
        sub.add_option("--db", o->db, "store file")->required();
        sub.add_option("--machine", o->machine, "machine name")->required();
        sub.add_option("--format", o->format,
                       "fanuc, siemens, heidenhain (NC map files), json (profile) or csv (parameter list); "
                       "another NC family works when resources/nc/<format>.json or --map exists")
            ->required();
        sub.add_option("--out", o->out, "output file (default: stdout)");
        sub.add_option("--map", o->map, "NC map file instead of resources/nc/<format>.json");
        return [o] { return runExport(*o); };
    }}};

}  // namespace

}  // namespace axistune::cli
