// SPDX-License-Identifier: GPL-3.0-or-later
// Math channels of the scope (ScopeMath.h).
#include "core/device/ScopeMath.h"

#include "core/dsp/Fft.h"

#include <cmath>
#include <numbers>

namespace axistune::device {

namespace {
Result<std::size_t> columnOf(const ScopeCapture& c, const std::string& name)
{
    for (std::size_t k = 0; k < c.channels.size() && k < c.columns.size(); ++k)
        if (c.channels[k].name == name)
            return k;
    return makeError(ErrorCode::BadInput, "math channel: '" + name + "' is not in the capture");
}
} // namespace

Result<ScopeMathChannel> scopeDifference(const ScopeCapture& c, const std::string& a, const std::string& b)
{
    auto ka = columnOf(c, a);
    if (!ka)
        return ka.error();
    auto kb = columnOf(c, b);
    if (!kb)
        return kb.error();
    if (c.channels[*ka].unit != c.channels[*kb].unit)
        return makeError(ErrorCode::BadInput, "math channel: " + a + " [" + c.channels[*ka].unit + "] and " + b + " [" +
                                                  c.channels[*kb].unit + "] have different units");
    ScopeMathChannel m;
    m.info = {a + " − " + b, c.channels[*ka].unit, "difference"};
    const auto& x = c.columns[*ka];
    const auto& y = c.columns[*kb];
    m.values.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        m.values[i] = x[i] - y[i];
    return m;
}

Result<ScopeMathChannel> scopeDerivative(const ScopeCapture& c, const std::string& a)
{
    auto ka = columnOf(c, a);
    if (!ka)
        return ka.error();
    const auto& y = c.columns[*ka];
    const std::size_t n = y.size();
    if (n < 2 || c.samples.size() != n)
        return makeError(ErrorCode::BadInput, "math channel: d/dt " + a + " needs at least 2 rows");
    ScopeMathChannel m;
    m.info = {"d/dt " + a, c.channels[*ka].unit.empty() ? "1/s" : c.channels[*ka].unit + "/s", "derivative"};
    m.values.resize(n);
    auto t = [&](std::size_t i) { return static_cast<double>(c.samples[i]) / c.rateHz; };
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t lo = i == 0 ? 0 : i - 1;
        const std::size_t hi = i + 1 == n ? n - 1 : i + 1;
        m.values[i] = (y[hi] - y[lo]) / (t(hi) - t(lo));
    }
    return m;
}

Result<ScopeSpectrum> scopeSpectrum(const ScopeCapture& c, const std::string& channel, std::size_t first,
                                    std::size_t count)
{
    auto k = columnOf(c, channel);
    if (!k)
        return k.error();
    if (first >= c.rows() || count > c.rows() - first || count < 8)
        return makeError(ErrorCode::BadInput,
                         "spectrum of " + channel + ": the window holds " +
                             std::to_string(first < c.rows() ? std::min(count, c.rows() - first) : 0) +
                             " rows; at least 8 are needed");
    if (c.samples[first + count - 1] - c.samples[first] + 1 != count)
        return makeError(ErrorCode::BadInput,
                         "spectrum of " + channel + ": the window has a gap in the sample numbers (samples lost)");
    const auto& y = c.columns[*k];
    double mean = 0.0;
    for (std::size_t i = 0; i < count; ++i)
        mean += y[first + i];
    mean /= static_cast<double>(count);
    dsp::RealFft fft(count);
    auto in = fft.input();
    double gain = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const double w =
            0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(count));
        gain += w;
        in[i] = (y[first + i] - mean) * w;
    }
    fft.execute();
    ScopeSpectrum s;
    s.resolutionHz = c.rateHz / static_cast<double>(count);
    const auto out = fft.output();
    for (std::size_t b = 0; b < out.size(); ++b) {
        s.freqHz.push_back(static_cast<double>(b) * s.resolutionHz);
        const bool edge = b == 0 || (count % 2 == 0 && b == out.size() - 1);
        s.amplitude.push_back(std::abs(out[b]) * (edge ? 1.0 : 2.0) / gain);
    }
    return s;
}

} // namespace axistune::device
