// SPDX-License-Identifier: GPL-3.0-or-later
// Sampling rate of a time column with a jitter tolerance (core/io/SampleTime.h).
#include "core/io/SampleTime.h"

#include "core/model/Units.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace axistune::io {

Result<SampleTiming> sampleTiming(std::span<const double> t, const std::string& where, std::size_t firstDataLine)
{
    const std::size_t n = t.size();
    if (n < 2)
        return makeError(ErrorCode::BadInput, where + ": fewer than 2 time stamps, no sampling rate");
    auto lineOf = [&](std::size_t i) {
        return firstDataLine > 0 ? "line " + std::to_string(firstDataLine + i) : "data row " + std::to_string(i + 1);
    };
    for (std::size_t i = 1; i < n; ++i) {
        if (!(t[i] > t[i - 1]))
            return makeError(ErrorCode::BadInput, where + ", " + lineOf(i) + ": time does not increase (" +
                                                      model::formatNumber(t[i - 1], 17) + " s then " +
                                                      model::formatNumber(t[i], 17) + " s)");
    }
    SampleTiming s;
    s.intervalS = (t[n - 1] - t[0]) / static_cast<double>(n - 1);
    std::vector<double> d(n - 1);
    for (std::size_t i = 1; i < n; ++i)
        d[i - 1] = t[i] - t[i - 1];
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    s.medianIntervalS = d[d.size() / 2];
    const double tol = kTimeJitterTolerance * s.intervalS;
    for (std::size_t i = 0; i < n; ++i) {
        const double dev = std::abs(t[i] - (t[0] + static_cast<double>(i) * s.intervalS));
        s.maxDeviationS = std::max(s.maxDeviationS, dev);
        if (dev > tol) {
            return makeError(ErrorCode::BadInput,
                             where + ", " + lineOf(i) + ": not uniformly sampled: the time stamp " +
                                 model::formatNumber(t[i], 10) + " s is " + model::formatNumber(dev, 3) +
                                 " s off the uniform grid of interval " + model::formatNumber(s.intervalS, 10) +
                                 " s (tolerance " + model::formatNumber(100.0 * kTimeJitterTolerance, 3) +
                                 " % of the interval); give --fs to use the sample index instead");
        }
    }
    s.fsHz = 1.0 / s.intervalS;
    return s;
}

} // namespace axistune::io
