// SPDX-License-Identifier: GPL-3.0-or-later
// Bounded roll history and the table → ScopeCapture conversion (docs/scope.md "The GUI scope").
#include "core/device/ScopeHistory.h"

#include "core/model/Metadata.h"
#include "core/model/MetadataKeys.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace axistune::device {

void ScopeHistory::reset(std::vector<ScopeChannelInfo> channels, double rateHz, std::size_t capacityRows)
{
    m_channels = std::move(channels);
    m_rateHz = rateHz;
    m_capacity = std::max<std::size_t>(1, capacityRows);
    m_values.assign(m_channels.size(), {});
    for (auto& v : m_values) {
        v.assign(m_capacity, 0.0);
        v.shrink_to_fit();
    }
    m_samples.assign(m_capacity, 0);
    m_samples.shrink_to_fit();
    m_head = m_count = 0;
    m_newest = 0;
    m_lost = m_repeated = m_dropped = 0;
}

void ScopeHistory::append(const ScopeRows& rows)
{
    const std::size_t width = m_channels.size();
    if (width == 0 || rows.values.size() < rows.rows * width)
        return;
    for (std::size_t i = 0; i < rows.rows; ++i) {
        const std::uint64_t n = rows.firstSample + i;
        if (m_count > 0) {
            if (n <= m_newest) {
                ++m_repeated;
                continue;
            }
            m_lost += n - m_newest - 1;
        }
        for (std::size_t k = 0; k < width; ++k)
            m_values[k][m_head] = rows.values[i * width + k];
        m_samples[m_head] = n;
        m_newest = n;
        m_head = (m_head + 1) % m_capacity;
        if (m_count < m_capacity)
            ++m_count;
        else
            ++m_dropped;
    }
}

std::size_t ScopeHistory::bytes() const
{
    return m_capacity * (m_values.size() * sizeof(double) + sizeof(std::uint64_t));
}

ScopeCapture ScopeHistory::snapshot(std::size_t rows) const
{
    ScopeCapture c;
    c.channels = m_channels;
    c.rateHz = m_rateHz;
    c.triggered = false;
    const std::size_t n = rows == 0 ? m_count : std::min(rows, m_count);
    const std::size_t start = (m_head + m_capacity - n) % m_capacity;
    c.samples.resize(n);
    c.columns.assign(m_channels.size(), std::vector<double>(n));
    // Two contiguous pieces: start..end of the buffer, then the wrapped part from 0.
    const std::size_t first = std::min(n, m_capacity - start);
    std::copy_n(m_samples.begin() + static_cast<std::ptrdiff_t>(start), first, c.samples.begin());
    std::copy_n(m_samples.begin(), n - first, c.samples.begin() + static_cast<std::ptrdiff_t>(first));
    for (std::size_t k = 0; k < m_channels.size(); ++k) {
        std::copy_n(m_values[k].begin() + static_cast<std::ptrdiff_t>(start), first, c.columns[k].begin());
        std::copy_n(m_values[k].begin(), n - first, c.columns[k].begin() + static_cast<std::ptrdiff_t>(first));
    }
    return c;
}

namespace {
Result<std::uint64_t> wholeNumber(const model::Metadata& m, const std::string& key)
{
    const auto* value = m.find(key);
    if (value == nullptr)
        return makeError(ErrorCode::BadInput, "scope table: metadata " + key + " is missing");
    const std::string text = value->text();
    const auto notWhole = [&] {
        return makeError(ErrorCode::BadInput,
                         "scope table: metadata " + key + " = '" + text + "' is not a whole number >= 0");
    };
    if (value->isNumber()) { // a number, also one a file wrote in exponent form ("2e+06")
        const double d = value->number().value_or(-1.0);
        if (!(d >= 0.0 && d == std::floor(d) && d < 18446744073709551616.0))
            return notWhole();
        return static_cast<std::uint64_t>(d);
    }
    std::uint64_t v = 0;
    const auto* end = text.data() + text.size();
    const auto [p, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc() || p != end)
        return notWhole();
    return v;
}
} // namespace

Result<ScopeCapture> scopeCaptureFromTable(const model::Capture& table)
{
    ScopeCapture c;
    auto fs = table.metadata.number(model::meta::kFsHz);
    if (!fs)
        return fs.error();
    if (!(std::isfinite(*fs) && *fs > 0.0))
        return makeError(ErrorCode::BadInput, "scope table: fs_Hz must be finite and > 0");
    c.rateHz = *fs;
    const auto* mode = table.metadata.find(model::meta::kScopeMode);
    c.triggered = mode != nullptr && mode->text() == "triggered";
    if (c.triggered) {
        auto t = wholeNumber(table.metadata, "trigger_sample");
        if (!t)
            return t.error();
        c.triggerSample = *t;
    }
    if (table.channels.empty() || table.channels.front().name != "sample")
        return makeError(ErrorCode::BadInput, "scope table: the first column must be 'sample'");
    const auto& s = table.channels.front().data;
    c.samples.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double v = s[i];
        if (!(v >= 0.0 && v == std::floor(v) && v < 18446744073709551616.0))
            return makeError(ErrorCode::BadInput,
                             "scope table: sample in row " + std::to_string(i + 1) + " is not a whole number >= 0");
        c.samples.push_back(static_cast<std::uint64_t>(v));
        if (i > 0 && c.samples[i] <= c.samples[i - 1])
            return makeError(ErrorCode::BadInput,
                             "scope table: sample numbers do not rise at row " + std::to_string(i + 1));
    }
    for (std::size_t k = 1; k < table.channels.size(); ++k) {
        const auto& ch = table.channels[k];
        if (ch.data.size() != s.size())
            return makeError(ErrorCode::BadInput, "scope table: column " + ch.name + " has " +
                                                      std::to_string(ch.data.size()) + " rows, 'sample' has " +
                                                      std::to_string(s.size()));
        c.channels.push_back({ch.name, table.metadata.textOr("unit." + ch.name, ""), {}});
        c.columns.push_back(ch.data);
    }
    return c;
}

} // namespace axistune::device
