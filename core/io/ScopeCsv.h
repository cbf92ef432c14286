// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Scope CSV (docs/formats.md "Scope CSV"): a capture CSV (CaptureCsv.h) whose first column `sample` holds
// the drive's sample number of every row and whose metadata has fs_Hz. Written by `axistune-cli scope`
// and the GUI's scope; read back through the same capture reader and input limits.

#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace axistune::io {

struct ScopeTable {
    model::Capture capture; ///< as read: metadata and every column, `sample` first
    double fsHz = 0.0;
    std::vector<std::uint64_t> samples; ///< the `sample` column as integers
    std::uint64_t missingSamples = 0;   ///< gaps between consecutive sample numbers
};

/// Reads and checks a scope CSV: fs_Hz present, finite and positive; a `sample` column of whole numbers
/// >= 0 that rise from row to row (a gap is counted in missingSamples, a repeat or a fall is an error).
/// Errors name the source, the line and the column.
Result<ScopeTable> readScopeCsv(std::istream& in, const std::string& sourceName);
Result<ScopeTable> readScopeCsvFile(const std::string& path);

} // namespace axistune::io
