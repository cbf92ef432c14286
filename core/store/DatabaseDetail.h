// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers shared by the store's .cpp files (not part of the public API).

#include "core/model/Result.h"

#include <SQLiteCpp/SQLiteCpp.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace axistune::store::detail {

/// Turns an SQLite exception into an error naming the file and what was being done.
Error dbError(const std::string& path, const std::exception& e, const std::string& doing);

/// Machine id by name (nullopt when missing).
std::optional<std::int64_t> machineId(SQLite::Database& db, const std::string& machine);
/// Creates the machine if missing (inside the caller's transaction) and returns its id.
std::int64_t ensureMachineId(SQLite::Database& db, const std::string& machine, const std::string& description);
/// Creates the axis if missing, appended after the machine's other axes.
std::int64_t ensureAxisId(SQLite::Database& db, std::int64_t machineId, const std::string& axis);

std::int64_t insertParameterSet(SQLite::Database& db, std::int64_t axisId, const std::string& source,
                                const std::string& time, const std::string& note,
                                const std::vector<std::pair<std::string, double>>& values,
                                std::optional<std::int64_t> sessionId);
std::int64_t insertModel(SQLite::Database& db, std::int64_t axisId, const std::string& kind, const std::string& time,
                         const std::string& json, std::optional<std::int64_t> sessionId);

/// Little-endian float64 BLOB codec.
void bindFloat64Blob(SQLite::Statement& st, int index, const std::vector<double>& values, std::vector<char>& scratch);
bool readFloat64Blob(const SQLite::Column& col, std::vector<double>& out);
/// Reads the BLOB column `data` of `table` row `rowid` straight into `out` (incremental BLOB I/O:
/// no intermediate copy of a multi-megabyte channel). Throws SQLite::Exception on failure.
bool readFloat64BlobDirect(SQLite::Database& db, const char* table, std::int64_t rowid, std::int64_t bytes,
                           std::vector<double>& out);

}  // namespace axistune::store::detail
