// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Capture CSV (DESIGN.md "File formats"): optional "# key=value" metadata lines, then a header of
// column names with units, then one row per sample. Errors name the file, the line and the column.

#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <istream>
#include <ostream>
#include <string>

namespace axistune::io {

/// Reads a capture. `sourceName` is used in error messages (usually the file path).
Result<model::Capture> readCaptureCsv(std::istream& in, const std::string& sourceName);
Result<model::Capture> readCaptureCsvFile(const std::string& path);

/// Writes metadata lines, the header and the rows (full double precision, '.' decimal point).
Status writeCaptureCsv(std::ostream& out, const model::Capture& capture);
Status writeCaptureCsvFile(const std::string& path, const model::Capture& capture);

}  // namespace axistune::io
