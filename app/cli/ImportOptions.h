// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Options shared by the commands that read foreign files (frf, import-frf): the format, the CSV mapping
// (separator, decimal mark, header, column names, units per column) and the reading itself
// (docs/formats.md "Imports").

#include "core/io/TableImport.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace axistune::cli {

struct ImportCliOptions {
    std::string format = "auto"; ///< auto | csv | halscope | uff
    std::string separator = "auto";
    std::string decimal = "auto";
    bool noHeader = false;
    std::vector<std::string> names;
    std::vector<std::string> units; ///< COL=UNIT
};

/// Adds --format, --separator, --decimal, --no-header, --names, --unit to `sub`.
void addImportOptions(CLI::App& sub, ImportCliOptions& o, bool withUff = true);

/// The table options from the CLI options; BadInput for a malformed --unit.
Result<io::TableImportOptions> tableOptions(const ImportCliOptions& o);

/// The format of `path`: the option, else .unv/.uff → uff, a first line "Sampling period is" → halscope, else csv.
std::string detectFormat(const std::string& path, const ImportCliOptions& o);

/// Reads a time series (capture CSV, any delimited table, halscope log, UFF58 time records) as a capture.
Result<model::Capture> readTimeSeries(const std::string& path, const ImportCliOptions& o);

} // namespace axistune::cli
