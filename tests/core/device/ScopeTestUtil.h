// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers of the scope tests (tests/core/device/test_scope.cpp, tests/app/cli/test_scope.cpp).

#include "core/model/Capture.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace axistune::testing {

/// The scope row of a test trace's first sample, when the trace holds one row every `step` scope rows: the i0 at
/// which scopeX[i0 + k·step] == traceX[k] for every k (bit for bit: both read the same simulated state). nullopt
/// when there is none.
inline std::optional<std::size_t> traceRowInScope(const std::vector<double>& scopeX, const std::vector<double>& traceX,
                                                  std::size_t step)
{
    if (traceX.empty() || step == 0)
        return std::nullopt;
    for (std::size_t i0 = 0; i0 + step * (traceX.size() - 1) < scopeX.size(); ++i0) {
        bool all = true;
        for (std::size_t k = 0; k < traceX.size() && all; ++k)
            all = scopeX[i0 + k * step] == traceX[k];
        if (all)
            return i0;
    }
    return std::nullopt;
}

/// For a failure message: the i0 with the most matching trace samples, how many match, and the first that does not.
inline std::string traceRowReport(const std::vector<double>& scopeX, const std::vector<double>& traceX,
                                  std::size_t step)
{
    std::size_t bestI0 = 0, bestCount = 0;
    for (std::size_t i0 = 0; i0 < scopeX.size(); ++i0) {
        std::size_t count = 0;
        for (std::size_t k = 0; k < traceX.size() && i0 + k * step < scopeX.size(); ++k)
            count += scopeX[i0 + k * step] == traceX[k];
        if (count > bestCount) {
            bestCount = count;
            bestI0 = i0;
        }
    }
    std::size_t firstBad = traceX.size();
    for (std::size_t k = 0; k < traceX.size() && firstBad == traceX.size(); ++k)
        if (bestI0 + k * step >= scopeX.size() || scopeX[bestI0 + k * step] != traceX[k])
            firstBad = k;
    return "scope rows " + std::to_string(scopeX.size()) + ", trace rows " + std::to_string(traceX.size()) +
           "; best first row " + std::to_string(bestI0) + " matches " + std::to_string(bestCount) +
           "; first trace row not matched " + std::to_string(firstBad);
}

/// A two-axis scope (columns x, y at 4 kHz) against a circle test's trace (one row per position period, rate
/// traceHz): whether the trace's X samples are found in the scope (one every 4 kHz / traceHz rows, bit for bit), and
/// the largest difference of Y at those rows (0 when the scope samples both axes at one instant).
struct SameInstant {
    bool found = false;
    double worstY = 0.0;
    std::string report; ///< why not found
};
inline SameInstant sameInstant(const std::vector<double>& sx, const std::vector<double>& sy, const model::Channel& tx,
                               const model::Channel& ty, double traceHz)
{
    SameInstant out;
    const auto step = static_cast<std::size_t>(std::llround(4000.0 / traceHz));
    if (step == 0 || static_cast<double>(step) * traceHz != 4000.0) {
        out.report = "the trace's rate does not divide 4 kHz";
        return out;
    }
    const auto i0 = traceRowInScope(sx, tx.data, step);
    if (!i0) {
        out.report = "the trace's X positions are not in the scope, one every " + std::to_string(step) +
                     " rows: " + traceRowReport(sx, tx.data, step);
        return out;
    }
    out.found = true;
    for (std::size_t k = 0; k < ty.data.size(); ++k)
        out.worstY = std::max(out.worstY, std::abs(sy[*i0 + k * step] - ty.data[k]));
    return out;
}

} // namespace axistune::testing
