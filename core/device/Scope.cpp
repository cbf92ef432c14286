// SPDX-License-Identifier: GPL-3.0-or-later
// The drive's scope: request checks and the trigger / ring-buffer recorder (docs/scope.md).
#include "core/device/Scope.h"

#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>

namespace axistune::device {

const char* scopeModeName(ScopeMode m)
{
    switch (m) {
    case ScopeMode::Single:
        return "single";
    case ScopeMode::Normal:
        return "normal";
    case ScopeMode::Roll:
        return "roll";
    }
    return "?";
}

const char* scopeEdgeName(ScopeEdge e)
{
    switch (e) {
    case ScopeEdge::Rising:
        return "rising";
    case ScopeEdge::Falling:
        return "falling";
    case ScopeEdge::Either:
        return "either";
    }
    return "?";
}

const char* scopeStateName(ScopeState s)
{
    switch (s) {
    case ScopeState::Idle:
        return "idle";
    case ScopeState::Filling:
        return "filling";
    case ScopeState::Waiting:
        return "waiting";
    case ScopeState::Triggered:
        return "triggered";
    case ScopeState::Done:
        return "done";
    case ScopeState::Rolling:
        return "rolling";
    }
    return "?";
}

std::size_t ScopeCapture::triggerRow() const
{
    if (!triggered)
        return rows();
    const auto it = std::lower_bound(samples.begin(), samples.end(), triggerSample);
    return it != samples.end() && *it == triggerSample ? static_cast<std::size_t>(it - samples.begin()) : rows();
}

std::uint64_t ScopeCapture::missingSamples() const
{
    if (samples.size() < 2)
        return 0;
    return samples.back() - samples.front() + 1 - samples.size();
}

std::uint64_t scopePreTriggerSamples(double pct, std::uint64_t length)
{
    if (length == 0)
        return 0;
    const auto pre = static_cast<std::uint64_t>(std::llround(pct / 100.0 * static_cast<double>(length)));
    return std::min(pre, length - 1);
}

Result<ScopeSetup> checkScopeRequest(const ScopeRequest& r, const ScopeCapabilities& caps)
{
    auto known = [&] {
        std::string s;
        for (const auto& c : caps.channels)
            s += (s.empty() ? "" : ", ") + c.name;
        return s;
    };
    if (caps.channels.empty() || !(caps.fastestRateHz > 0.0))
        return makeError(ErrorCode::NotFound, "axis " + r.axis + " has no scope channels");
    ScopeSetup s;
    if (r.channels.empty())
        return makeError(ErrorCode::BadInput,
                         "scope channels: none given (channels of axis " + r.axis + ": " + known() + ")");
    if (static_cast<int>(r.channels.size()) > caps.maxChannels)
        return makeError(ErrorCode::OutOfRange, "scope channels: " + std::to_string(r.channels.size()) +
                                                    " given, the drive traces at most " +
                                                    std::to_string(caps.maxChannels) + " at once");
    for (const auto& name : r.channels) {
        const auto it = std::find_if(caps.channels.begin(), caps.channels.end(),
                                     [&](const ScopeChannelInfo& c) { return c.name == name; });
        if (it == caps.channels.end())
            return makeError(ErrorCode::NotFound, "scope channel '" + name + "' is not traceable on axis " + r.axis +
                                                      " (channels: " + known() + ")");
        const auto idx = static_cast<std::size_t>(it - caps.channels.begin());
        if (std::find(s.channels.begin(), s.channels.end(), idx) != s.channels.end())
            return makeError(ErrorCode::BadInput, "scope channel '" + name + "' is given twice");
        s.channels.push_back(idx);
    }
    if (r.divider < 1 || r.divider > caps.maxDivider)
        return makeError(ErrorCode::OutOfRange, "scope divider " + std::to_string(r.divider) + " outside 1.." +
                                                    std::to_string(caps.maxDivider));
    s.divider = r.divider;
    s.mode = r.mode;
    s.rateHz = caps.fastestRateHz / r.divider;
    if (r.mode == ScopeMode::Roll)
        return s;
    const auto trig = std::find(r.channels.begin(), r.channels.end(), r.triggerChannel);
    if (trig == r.channels.end())
        return makeError(ErrorCode::BadInput,
                         "scope trigger channel '" + r.triggerChannel + "' is not one of the traced channels");
    s.triggerColumn = static_cast<std::size_t>(trig - r.channels.begin());
    if (!std::isfinite(r.triggerLevel))
        return makeError(ErrorCode::OutOfRange, "scope trigger level must be finite");
    s.triggerLevel = r.triggerLevel;
    s.edge = r.edge;
    if (!(r.preTriggerPct >= 0.0 && r.preTriggerPct <= 100.0))
        return makeError(ErrorCode::OutOfRange,
                         "scope pre-trigger " + model::formatNumber(r.preTriggerPct, 6) + " % outside 0..100 %");
    const std::uint64_t maxRows = caps.maxValues / r.channels.size();
    if (r.lengthSamples < 2 || r.lengthSamples > maxRows)
        return makeError(ErrorCode::OutOfRange, "scope length " + std::to_string(r.lengthSamples) +
                                                    " samples outside 2.." + std::to_string(maxRows) + " for " +
                                                    std::to_string(r.channels.size()) + " channels (" +
                                                    model::formatNumber(static_cast<double>(maxRows) / s.rateHz, 4) +
                                                    " s at " + model::formatNumber(s.rateHz, 6) + " Hz)");
    s.length = r.lengthSamples;
    s.preSamples = scopePreTriggerSamples(r.preTriggerPct, r.lengthSamples);
    return s;
}

// ---------------------------------------------------------------------------------------------

void ScopeRecorder::arm(const ScopeSetup& setup, std::uint64_t ringRows)
{
    m_setup = setup;
    m_width = setup.channels.size();
    m_capacity = setup.mode == ScopeMode::Roll ? std::max<std::uint64_t>(ringRows, 1) : setup.length;
    m_ring.assign(static_cast<std::size_t>(m_capacity * m_width), 0.0);
    m_count = 0;
    m_sinceArm = 0;
    m_havePrevious = false;
    m_captures = 0;
    m_haveCapture = false;
    m_capture = {};
    m_state = setup.mode == ScopeMode::Roll ? ScopeState::Rolling
              : setup.preSamples > 0        ? ScopeState::Filling
                                            : ScopeState::Waiting;
}

void ScopeRecorder::stop()
{
    if (m_state != ScopeState::Done)
        m_state = ScopeState::Idle;
}

void ScopeRecorder::appendToRing(std::uint64_t sample, std::span<const double> row)
{
    if (m_count == 0 || sample != m_next) { // the first row, or a stream that restarted: start again
        m_count = 0;
        m_oldest = sample;
    }
    const std::uint64_t slot = sample % m_capacity;
    std::copy(row.begin(), row.begin() + static_cast<std::ptrdiff_t>(m_width),
              m_ring.begin() + static_cast<std::ptrdiff_t>(slot * m_width));
    m_next = sample + 1;
    if (m_count < m_capacity)
        ++m_count;
    else
        ++m_oldest;
}

void ScopeRecorder::push(std::uint64_t sample, std::span<const double> row)
{
    if (m_state == ScopeState::Idle || m_state == ScopeState::Done || row.size() < m_width)
        return;
    if (m_state == ScopeState::Rolling) {
        appendToRing(sample, row);
        return;
    }
    const double v = row[m_setup.triggerColumn];
    if (m_state == ScopeState::Filling || m_state == ScopeState::Waiting) {
        // A trigger needs the pre-trigger rows taken since arming and a previous value to cross from.
        if (m_sinceArm >= m_setup.preSamples && m_havePrevious) {
            const double l = m_setup.triggerLevel, p = m_previous;
            const bool rising = p < l && v >= l, falling = p > l && v <= l;
            const bool hit = m_setup.edge == ScopeEdge::Rising    ? rising
                             : m_setup.edge == ScopeEdge::Falling ? falling
                                                                  : rising || falling;
            if (hit) {
                m_state = ScopeState::Triggered;
                m_trigger = sample;
                m_remaining = m_setup.length - m_setup.preSamples;
            }
        }
    }
    m_previous = v;
    m_havePrevious = true;
    appendToRing(sample, row);
    ++m_sinceArm;
    if (m_state == ScopeState::Filling && m_sinceArm >= m_setup.preSamples)
        m_state = ScopeState::Waiting;
    if (m_state == ScopeState::Triggered && --m_remaining == 0)
        finishCapture();
}

void ScopeRecorder::finishCapture()
{
    ScopeCapture c;
    c.rateHz = m_setup.rateHz;
    c.triggered = true;
    c.triggerSample = m_trigger;
    c.number = ++m_captures;
    const std::uint64_t first = m_trigger - m_setup.preSamples;
    c.columns.assign(m_width, std::vector<double>(static_cast<std::size_t>(m_setup.length)));
    c.samples.resize(static_cast<std::size_t>(m_setup.length));
    for (std::uint64_t i = 0; i < m_setup.length; ++i) {
        const std::uint64_t slot = (first + i) % m_capacity;
        c.samples[static_cast<std::size_t>(i)] = first + i;
        for (std::size_t k = 0; k < m_width; ++k)
            c.columns[k][static_cast<std::size_t>(i)] = m_ring[static_cast<std::size_t>(slot * m_width + k)];
    }
    m_capture = std::move(c);
    m_haveCapture = true;
    if (m_setup.mode == ScopeMode::Single) {
        m_state = ScopeState::Done;
        return;
    }
    // Normal: arm again; the next capture takes its own pre-trigger rows.
    m_sinceArm = 0;
    m_havePrevious = false;
    m_state = m_setup.preSamples > 0 ? ScopeState::Filling : ScopeState::Waiting;
}

ScopeStatus ScopeRecorder::status() const
{
    ScopeStatus s;
    s.state = m_state;
    s.rateHz = m_setup.rateHz;
    s.nextSample = m_next;
    s.oldestSample = m_count ? m_oldest : m_next;
    s.captures = m_captures;
    if (m_haveCapture) {
        s.captureFirstSample = m_capture.samples.front();
        s.captureTriggerSample = m_capture.triggerSample;
        s.captureRows = m_capture.samples.size();
    }
    return s;
}

ScopeRows ScopeRecorder::rows(std::uint64_t from, std::size_t maxRows) const
{
    ScopeRows out;
    const std::uint64_t oldest = m_count ? m_oldest : m_next;
    out.firstSample = std::max(from, oldest);
    if (m_setup.mode != ScopeMode::Roll || out.firstSample >= m_next)
        return out;
    out.rows = static_cast<std::size_t>(std::min<std::uint64_t>(maxRows, m_next - out.firstSample));
    out.values.resize(out.rows * m_width);
    for (std::size_t i = 0; i < out.rows; ++i) {
        const std::uint64_t slot = (out.firstSample + i) % m_capacity;
        std::copy_n(m_ring.begin() + static_cast<std::ptrdiff_t>(slot * m_width), m_width,
                    out.values.begin() + static_cast<std::ptrdiff_t>(i * m_width));
    }
    return out;
}

Result<ScopeCapture> ScopeRecorder::capture() const
{
    if (!m_haveCapture)
        return makeError(ErrorCode::NotFound,
                         std::string("no complete scope capture yet (scope ") + scopeStateName(m_state) + ")");
    return m_capture;
}

model::Capture scopeCaptureToTable(const ScopeCapture& c, const std::string& axis, const model::Metadata& extra)
{
    model::Capture t;
    t.metadata = extra;
    t.metadata.set(model::meta::kFsHz, c.rateHz);
    t.metadata.set(model::meta::kAxis, axis);
    t.metadata.set(model::meta::kScopeMode, c.triggered ? "triggered" : "roll");
    if (c.triggered) {
        // A number while a double holds it exactly; larger sample numbers stay their exact digits.
        t.metadata.set("trigger_sample", c.triggerSample <= (std::uint64_t{1} << 53)
                                             ? model::MetadataValue(static_cast<double>(c.triggerSample))
                                             : model::MetadataValue(std::to_string(c.triggerSample)));
        t.metadata.set("trigger_row", static_cast<double>(c.triggerRow()));
    }
    t.metadata.set("missing_samples", static_cast<double>(c.missingSamples()));
    model::Channel sample{"sample", {}};
    sample.data.reserve(c.samples.size());
    for (const auto n : c.samples)
        sample.data.push_back(static_cast<double>(n));
    t.channels.push_back(std::move(sample));
    for (std::size_t k = 0; k < c.channels.size() && k < c.columns.size(); ++k) {
        t.metadata.set("unit." + c.channels[k].name, c.channels[k].unit);
        t.channels.push_back({c.channels[k].name, c.columns[k]});
    }
    return t;
}

void appendScopeRows(ScopeCapture& capture, const ScopeRows& rows)
{
    const std::size_t width = capture.columns.size();
    for (std::size_t i = 0; i < rows.rows; ++i) {
        capture.samples.push_back(rows.firstSample + i);
        for (std::size_t k = 0; k < width; ++k)
            capture.columns[k].push_back(rows.values[i * width + k]);
    }
}

} // namespace axistune::device
