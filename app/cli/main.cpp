// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli: every analysis and capture without the GUI. Results as JSON on stdout (or --out),
// errors on stderr with exit codes 2 (bad input), 3 (device error), 4 (safety stop).
#include "app/cli/CliCommand.h"
#include "core/autotune/Undo.h"
#include "core/device/DriveRegistry.h"
#include "core/io/AtomicFile.h"
#include "core/model/InputLimits.h"
#include "core/model/Number.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {

std::vector<CliCommand>& commandRegistry()
{
    static std::vector<CliCommand> registry;
    return registry;
}

std::string connectOptionHelp()
{
    return "drive to connect to: " + device::registeredUriForms() + " (axistune-cli drive --list-backends)";
}

int reportError(const std::string& command, const Error& error)
{
    std::cerr << "axistune-cli " << command << ": " << error.detail << '\n';
    return exitCodeFor(error.code);
}

int writeResult(const std::string& command, const std::string& text, const std::string& outPath)
{
    if (outPath.empty()) {
        if (!(std::cout << text).flush())
            return reportError(command, makeError(ErrorCode::Io, "stdout: write failed"));
        return 0;
    }
    // Atomic (core/io/AtomicFile.h): a full disk or a kill never leaves half a file with exit 0.
    if (auto st = io::writeFileAtomic(outPath, text); !st)
        return reportError(command, st.error());
    return 0;
}

int writeJsonResult(const std::string& command, const nlohmann::json& result, const std::string& outPath, int indent)
{
    auto text = model::dumpResultJson(result, indent);
    if (!text)
        return reportError(command, text.error());
    return writeResult(command, *text + "\n", outPath);
}

int writeUndone(const std::string& command, nlohmann::json out, const std::vector<autotune::UndoneParameter>& undone,
                const std::string& outPath)
{
    nlohmann::json list = nlohmann::json::array();
    for (const auto& u : undone) {
        list.push_back({{"key", u.key}, {"was", u.applied}, {"now", u.restored}});
        std::cerr << "  " << u.key << ": " << model::formatNumber(u.applied, 7) << " -> "
                  << model::formatNumber(u.restored, 7) << "\n";
    }
    out["undone"] = list;
    return writeJsonResult(command, out, outPath);
}

}  // namespace axistune::cli

int main(int argc, char** argv)
{
    using namespace axistune::cli;
    CLI::App app{"AxisTune command line: measure, analyse and tune NC feed axes without the GUI"};
    app.set_version_flag("--version", std::string(AXISTUNE_VERSION));
    app.require_subcommand(1);
    std::function<int()> runner;
    for (auto& cmd : commandRegistry()) {
        auto* sub = app.add_subcommand(cmd.name, cmd.description);
        auto run = std::make_shared<std::function<int()>>();
        *run = cmd.setup(*sub);
        sub->callback([run, &runner] { runner = *run; });
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int rc = app.exit(e);
        return rc == 0 ? 0 : 2;
    }
    return runner ? runner() : 2;
}
