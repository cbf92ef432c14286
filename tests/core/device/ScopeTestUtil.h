// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers of the scope tests (tests/core/device/test_scope.cpp, tests/app/cli/test_scope.cpp).

#include <cstddef>
#include <optional>
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

} // namespace axistune::testing
