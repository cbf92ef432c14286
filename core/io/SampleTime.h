// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The sampling rate of a time column (docs/formats.md "Time columns").
// Loggers write time stamps rounded to a few significant digits (the impact record of
// shared/data/real: 7 digits, ±0.05 µs at 19.53 µs) or with clock jitter (EMPS: ±24 ns at 1 ms). Such a
// column is accepted when every stamp lies within kTimeJitterTolerance of the sampling interval from
// the uniform grid t0 + i·dt, dt = (t_last − t_first)/(n − 1). The interval is the mean over the whole
// record, not the median of the differences: the median of rounded differences is biased (1.95e-5 s
// instead of 1/51200 s = 1.953125e-5 s on the impact record, 0.16 % off in frequency) while the span is
// exact to the rounding of two stamps. A gap, a repeated stamp or a drifting clock moves later stamps by
// a whole interval and is refused with the row.

#include "core/model/Result.h"

#include <span>
#include <string>

namespace axistune::io {

/// Largest deviation of a time stamp from the uniform grid, as a fraction of the sampling interval.
inline constexpr double kTimeJitterTolerance = 0.01;

struct SampleTiming {
    double fsHz = 0.0;            ///< 1/dt
    double intervalS = 0.0;       ///< dt = span/(n − 1)
    double medianIntervalS = 0.0; ///< for the report
    double maxDeviationS = 0.0;   ///< largest |t_i − (t0 + i·dt)|
};

/// The timing of a time column. `where` names the file and column for messages ("f.csv, column 't_s'");
/// `firstDataLine` is the file line of the first sample (0 if unknown) so a refusal names the line.
/// Errors: fewer than 2 samples, non-increasing time, a stamp off the grid by more than the tolerance.
Result<SampleTiming> sampleTiming(std::span<const double> t, const std::string& where, std::size_t firstDataLine = 0);

} // namespace axistune::io
