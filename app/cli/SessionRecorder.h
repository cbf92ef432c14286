// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sessions from the CLI (issue 5 item 3, docs/storage.md "Sessions from the CLI"): adds
// `--db FILE --machine NAME [--operator NAME] [--note TEXT]` to a subcommand and wraps its runner so
// that, when --db is given, the run is recorded as one session in the store (one transaction):
//   kind     = the subcommand's name
//   status   = completed (exit 0), aborted (exit 4, safety stop) or failed (any other exit code)
//   inputs   = the options given and their defaults, and every input file (path, bytes, SHA-256;
//              small JSON files also by content)
//   captures = every capture / FRF / sine-stream CSV the command wrote (output options, "--out...")
//   results  = the JSON printed on stdout and every JSON file written, or the text; on failure the
//              exit code and the error message.
// The machine must already be in the store (exit 2 naming it and `profile import` otherwise); the
// check happens before the command runs, so nothing is measured for a session that cannot be saved.
// Not a subcommand: it registers nothing.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace axistune::cli {

/// Adds the session options to `sub` and returns `run` wrapped so that it records a session when
/// --db is given (and behaves exactly as `run` otherwise). Use in a CliCommand setup:
///   return recordSessions(sub, [o] { return runFoo(*o); });
std::function<int()> recordSessions(CLI::App& sub, std::function<int()> run);

/// SHA-256 of a byte string as 64 lowercase hex digits (FIPS 180-4).
std::string sha256Hex(const std::string& bytes);

}  // namespace axistune::cli
