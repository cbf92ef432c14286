// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Open imports of time series and FRF tables from other programs (docs/formats.md "Imports"):
//   - delimited text: separator auto (tab, ';', ',', blanks) or explicit, decimal point or comma,
//     a header line or none (names given, else col1..colN), '#' comment lines, a unit per column
//     converted to SI (core/model/Units);
//   - halscope's "Save Log" (LinuxCNC scope_files.c write_log_file): a line
//     "Sampling period is <ns> ns", then one row per sample of "<label> <value>" pairs;
//   - FRF columns of a table: f plus <name>_re/<name>_im (or <name>_mag_dB/<name>_phase_deg, or
//     <name>_mag/<name>_phase_deg), one of several FRFs in a file picked by name (--column H11).
// Numbers are parsed without the locale; every error names the file, the line and the column.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <istream>
#include <map>
#include <string>
#include <vector>

namespace axistune::io {

enum class HeaderMode { Auto, Present, Absent };
enum class DecimalMark { Auto, Point, Comma };

struct TableImportOptions {
    char separator = 0; ///< 0: auto; '\t', ';', ',', ' ' (any run of blanks)
    DecimalMark decimal =
        DecimalMark::Auto;                ///< Auto: comma when the separator is not ',' and a cell has ',' and no '.'
    HeaderMode header = HeaderMode::Auto; ///< Auto: the first line is a header when a cell is not a number
    std::vector<std::string> names;       ///< names of a headerless file's columns (default col1, col2, ...)
    std::map<std::string, std::string> units; ///< column → unit token of the file; values converted to SI
};

/// Reads a delimited table into a capture (channels in file order, values in SI after `units`).
/// The capture's metadata gets "# key=value" comment lines, `separator`, `decimal` and for each converted
/// column `unit.<name>=<SI token>` (`unit_in_file.<name>=<token>`).
Result<model::Capture> readTable(std::istream& in, const std::string& sourceName, const TableImportOptions& options);
Result<model::Capture> readTableFile(const std::string& path, const TableImportOptions& options);

/// Reads halscope's saved log. Channels are named by their labels; metadata fs_Hz and sample_period_ns.
Result<model::Capture> readHalscope(std::istream& in, const std::string& sourceName);
Result<model::Capture> readHalscopeFile(const std::string& path);
/// True when the text starts like a halscope log ("Sampling period is").
bool looksLikeHalscope(const std::string& firstLine);

/// The format of a file: "uff" for .unv/.uff, "halscope" when the first line is "Sampling period is", else "csv".
std::string detectImportFormat(const std::string& path);

/// A time series of any import format ("auto", "csv", "halscope", "uff") as a capture.
Result<model::Capture> readTimeSeriesFile(const std::string& path, const TableImportOptions& options,
                                          const std::string& format = "auto");

struct FrfColumnOptions {
    std::string frequencyColumn; ///< default: f_Hz, freq_Hz, f, freq, frequency (first present)
    std::string name;            ///< FRF name: columns <name>_re/<name>_im, ...; empty: re/im or the only FRF
    std::string units;           ///< unit of h in the file (m/N, um/N, ...); overrides a `units` metadata line
};

/// One FRF from the columns of an imported table, h converted to SI (units key of docs/formats.md).
Result<dsp::FrequencyResponse> frfFromTable(const model::Capture& table, const std::string& sourceName,
                                            const FrfColumnOptions& options);

} // namespace axistune::io
