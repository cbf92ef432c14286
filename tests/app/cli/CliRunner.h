// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs the real axistune-cli binary from end-to-end tests and captures exit code, stdout and stderr.

#include "tests/ScopedTempDir.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace axistune::testing {

struct CliResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

inline std::string readFileText(const std::filesystem::path& p)
{
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

/// A fresh temporary directory for one test, removed with its contents when the returned object goes out of scope.
inline ScopedTempDir makeTempDir(const std::string& tag)
{
    return ScopedTempDir(tag);
}

/// Runs `AXISTUNE_CLI args` through the shell (args are passed as written).
inline CliResult runCli(const std::string& args)
{
    const auto dir = makeTempDir("cli");
    const auto outPath = dir / "stdout.txt";
    const auto errPath = dir / "stderr.txt";
    const std::string cmd = std::string(AXISTUNE_CLI) + " " + args + " >" + outPath.string() + " 2>" + errPath.string();
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readFileText(outPath);
    r.err = readFileText(errPath);
    return r;
}

}  // namespace axistune::testing
