// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Guarded reading of input files (docs/robustness.md). Every parser reads its file through
// readInputFile (a regular file, not larger than kMaxInputFileBytes: no FIFO, device or /dev/zero) and
// every JSON input through parseJsonText (nesting depth, numbers that fit a double and are not
// denormal, any nlohmann exception turned into an error naming the file, the line and the key).
// CSV readers check kMaxLineBytes and kMaxCsvLines per line. Result JSON leaves the program through
// dumpResultJson, which refuses NaN and Inf instead of writing them as null.

#include "core/model/Result.h"

#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

namespace axistune::model {

/// Largest input file read (bytes). A 10^6-row ball-bar or FRF file is about 40 MB.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{256} << 20;
/// Longest line of a CSV file (bytes, without the newline).
inline constexpr std::size_t kMaxLineBytes = std::size_t{64} << 10;
/// Most lines a CSV file may have.
inline constexpr std::size_t kMaxCsvLines = 20'000'000;
/// Deepest nesting of JSON objects and arrays (the formats need 5 at most).
inline constexpr int kMaxJsonDepth = 32;

/// The path as it may be shown and written to UTF-8 JSON: bytes that are not valid UTF-8 become
/// "\xNN" so a file name from another system never aborts a JSON dump.
std::string displayPath(const std::string& path);

/// Reads a whole input file. NotFound when missing; BadInput when it is not a regular file (a FIFO,
/// a directory, a device) or larger than `maxBytes`; Io when it cannot be read. Errors name the path.
Result<std::string> readInputFile(const std::string& path, std::size_t maxBytes = kMaxInputFileBytes);

/// Parses JSON text with the limits above. Errors name `source`, the line and the last key.
Result<nlohmann::json> parseJsonText(const std::string& text, const std::string& source);

/// readInputFile + parseJsonText.
Result<nlohmann::json> readJsonFile(const std::string& path);

/// The JSON pointer of the first number in `j` that is NaN or infinite ("" when none).
bool findNonFinite(const nlohmann::json& j, std::string& pointer);

/// j.dump(indent) with invalid UTF-8 replaced; Internal error naming the JSON pointer when a number
/// is NaN or infinite (nlohmann would write it as null).
Result<std::string> dumpResultJson(const nlohmann::json& j, int indent = 2);

/// True for a subnormal double (non-zero, below 2.2e-308 in magnitude): refused wherever read.
bool isDenormal(double v);

/// Why a CSV or metadata cell is not accepted as a number: "not a number ('abc')", "'1e309' does not fit
/// a double", "'5e-324' is denormal (below 2.2e-308 in magnitude)".
std::string badNumberText(std::string_view cell);

/// A CSV line check: BadInput naming the source and line when `line` is longer than kMaxLineBytes or
/// `lineNo` exceeds kMaxCsvLines.
Status checkCsvLine(const std::string& source, std::size_t lineNo, std::size_t lineBytes);

} // namespace axistune::model
