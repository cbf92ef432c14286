// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// FRF CSV (DESIGN.md "File formats"): optional "# key=value" metadata lines, then the header
//   f_Hz,re,im,mag_dB,phase_deg,coherence,valid
// and one row per frequency. coherence is empty where not defined, valid is 0 or 1.
// Reading: re/im are authoritative; a file without re/im but with mag_dB and phase_deg is accepted
// too (the complex value is rebuilt from them). coherence and valid columns are optional (missing →
// undefined / 1). Frequencies must be finite, non-negative and strictly increasing.
// Errors name the source, the line and the column.
// A "# units=<token>" line (m/N, um/N, mm/N, m/s/N, m/s2/N, g/N, ... : docs/formats.md) gives the unit of h;
// the reader converts h to SI, sets units to the SI token and keeps the file's token in units_in_file. An
// unknown token is refused. Without the key h is taken as it is (files written before the key existed).

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"

#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace axistune::io {

/// The header written by writeFrfCsv.
inline constexpr const char* kFrfCsvHeader = "f_Hz,re,im,mag_dB,phase_deg,coherence,valid";

/// Reads an FRF. `sourceName` is used in error messages (usually the file path).
Result<dsp::FrequencyResponse> readFrfCsv(std::istream& in, const std::string& sourceName);
Result<dsp::FrequencyResponse> readFrfCsvFile(const std::string& path);

/// Converts h from `unit` to SI (metadata units=<SI token>, units_in_file=<unit> when they differ);
/// BadInput naming `sourceName` for an unknown unit.
Status convertFrfUnits(dsp::FrequencyResponse& frf, const std::string& unit, const std::string& sourceName);

/// Writes metadata lines, the header and the rows (17 significant digits, '.' decimal point).
Status writeFrfCsv(std::ostream& out, const dsp::FrequencyResponse& frf);
Status writeFrfCsvFile(const std::string& path, const dsp::FrequencyResponse& frf);

namespace detail {
// Small CSV helpers shared by the FRF and sine-stream CSV code (not a general CSV library: no quoting).
/// Splits a line at commas; trailing '\r' removed, cells trimmed of spaces.
std::vector<std::string> splitCsvLine(const std::string& line);
/// Parses a whole cell as a double ("nan"/"inf" accepted; the caller decides whether they are allowed).
bool parseDouble(const std::string& cell, double& value);
/// Shortest text that reads back to the same double.
std::string formatDouble(double v);
/// Parses "# key=value" into key/value; false for other comment lines.
bool parseMetadataLine(const std::string& line, std::string& key, std::string& value);
}  // namespace detail

}  // namespace axistune::io
