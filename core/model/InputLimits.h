// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Guarded reading of input files (docs/robustness.md). Every parser reads its file through
// readInputFile (a regular file, not larger than kMaxInputFileBytes: no FIFO, device or /dev/zero) and
// every JSON input through parseJsonText (nesting depth, numbers that fit a double and are not
// denormal, any nlohmann exception turned into an error naming the file, the line and the key).
// CSV readers check kMaxLineBytes and kMaxCsvLines per line. Result JSON leaves the program through
// dumpResultJson, which refuses NaN, Inf and null: a value that is not defined is left out and named,
// with the reason, in its object's "undefined" member (putNumber, putUndefined; docs/formats.md
// "Undefined values").

#include "core/model/Result.h"

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

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

/// True, with the JSON pointer of the first value in `j` that is a NaN or infinite number or null.
bool findNonFinite(const nlohmann::json& j, std::string& pointer);

/// j.dump(indent) with invalid UTF-8 replaced; Internal error naming the JSON pointer when a number
/// is NaN or infinite (nlohmann would write it as null) or a value is null.
Result<std::string> dumpResultJson(const nlohmann::json& j, int indent = 2);

/// The result-JSON form of a value that is not defined (docs/formats.md "Undefined values"): `key` is
/// left out of the object `obj` and obj["undefined"][key] holds the reason, e.g.
/// {"gain_margin_dB": 12.1, "undefined": {"phase_margin_deg": "no gain crossover"}}.
void putUndefined(nlohmann::json& obj, const std::string& key, const std::string& reason);
/// obj[key] = v when v is finite, else putUndefined(obj, key, reason).
void putNumber(nlohmann::json& obj, const std::string& key, double v, const std::string& reason);
/// An array of numbers when every one is finite; else the key is left out (putUndefined) with the
/// reason and the index of the first value that is not finite.
void putNumbers(nlohmann::json& obj, const std::string& key, const std::vector<double>& v, const std::string& reason);

/// True for a subnormal double (non-zero, below 2.2e-308 in magnitude): refused wherever read.
bool isDenormal(double v);

/// Why a CSV or metadata cell is not accepted as a number: "not a number ('abc')", "'1e309' does not fit
/// a double", "'5e-324' is denormal (below 2.2e-308 in magnitude)".
std::string badNumberText(std::string_view cell);

/// A CSV line check: BadInput naming the source and line when `line` is longer than kMaxLineBytes or
/// `lineNo` exceeds kMaxCsvLines.
Status checkCsvLine(const std::string& source, std::size_t lineNo, std::size_t lineBytes);

} // namespace axistune::model
