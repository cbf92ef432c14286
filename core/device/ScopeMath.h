// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Math channels of the scope (docs/scope.md "The GUI scope"): the difference of two channels, the time
// derivative of one (by the drive's sample numbers, so a gap does not fake a slope), and the amplitude
// spectrum of a window of samples.

#include "core/device/Scope.h"
#include "core/model/Result.h"

#include <string>
#include <vector>

namespace axistune::device {

struct ScopeMathChannel {
    ScopeChannelInfo info; ///< name "a − b" / "d/dt a", unit of a (derivative: unit of a per s)
    std::vector<double> values;
};

/// a − b, row by row. Errors: a channel not in the capture; units that differ.
Result<ScopeMathChannel> scopeDifference(const ScopeCapture& c, const std::string& a, const std::string& b);
/// d a / d t: central differences inside, one-sided at both ends, t = sample number / rate. Errors: the
/// channel is not in the capture, fewer than 2 rows.
Result<ScopeMathChannel> scopeDerivative(const ScopeCapture& c, const std::string& a);

struct ScopeSpectrum {
    std::vector<double> freqHz;
    std::vector<double>
        amplitude; ///< single-sided peak amplitude in the channel's unit (Hann, coherent gain corrected)
    double resolutionHz = 0.0;
};
/// Amplitude spectrum of rows [first, first + count) of a channel: mean removed, Hann window, peak
/// amplitude (a sine of amplitude A on a bin reads A). Errors: fewer than 8 rows, a gap in the sample
/// numbers inside the window (the spectrum needs equally spaced samples), an unknown channel.
Result<ScopeSpectrum> scopeSpectrum(const ScopeCapture& c, const std::string& channel, std::size_t first,
                                    std::size_t count);

} // namespace axistune::device
