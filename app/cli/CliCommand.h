// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Subcommand registry of axistune-cli. Each Cmd*.cpp defines one subcommand and registers it with a
// static CliRegistrar, so adding a command never touches main.cpp.

#include "core/model/Result.h"

#include <CLI/CLI.hpp>
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace axistune::autotune {
struct UndoneParameter;
}

namespace axistune::cli {

struct CliCommand {
    std::string name;
    std::string description;
    /// Adds the subcommand's options to `sub` and returns the function that runs it (exit code).
    std::function<std::function<int()>(CLI::App& sub)> setup;
};

std::vector<CliCommand>& commandRegistry();

struct CliRegistrar {
    explicit CliRegistrar(CliCommand c) { commandRegistry().push_back(std::move(c)); }
};

/// Prints "axistune-cli <command>: <detail>" to stderr and returns the exit code for the error.
int reportError(const std::string& command, const Error& error);

/// Writes a command's text result to `outPath`, or to stdout when it is empty; returns the exit code.
int writeResult(const std::string& command, const std::string& text, const std::string& outPath);

/// The output boundary for JSON results: refuses (Internal error, nothing written) a result holding NaN
/// or Inf, which JSON would show as null; otherwise writes the dump (indent < 0: one line) and a newline.
int writeJsonResult(const std::string& command, const nlohmann::json& result, const std::string& outPath,
                    int indent = 2);

/// The result of an undo (autotune --undo, pid-tune --undo): `out` with `undone[]` (key, was, now) added, written
/// as writeJsonResult does, and "  key: was -> now" per parameter on stderr.
int writeUndone(const std::string& command, nlohmann::json out, const std::vector<autotune::UndoneParameter>& undone,
                const std::string& outPath);

/// Help text of --connect: "drive to use: " and the registered URI forms (core/device/DriveRegistry.h).
std::string connectOptionHelp();

}  // namespace axistune::cli
