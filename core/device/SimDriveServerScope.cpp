// SPDX-License-Identifier: GPL-3.0-or-later
// The scope of axistune-simdrive (docs/modbus.md "Scope", docs/scope.md): configuration and status
// registers, arm/stop commands, the roll ring and the last capture paged through scope.window. While the
// scope is armed and no test moves its axes, they run in wall-clock time (a real drive samples in real time);
// during a test the test's pace applies.
#include "core/device/SimDriveServer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <modbus/modbus.h>

namespace axistune::device {

bool SimDriveServer::scopeArmed() const
{
    const ScopeState s = m_drive->scopeStatus().state;
    return m_scopeUnit >= 0 && s != ScopeState::Idle && s != ScopeState::Done;
}

void SimDriveServer::stepScope()
{
    const auto now = Clock::now();
    if (!scopeArmed()) {
        m_scopeWall = now;
        return;
    }
    const bool testMovesIt =
        m_state == "running" &&
        ((m_testUnit >= 0 && m_drive->scopeSamplesAxis(m_axes[static_cast<std::size_t>(m_testUnit)].name)) ||
         (m_testSecondUnit >= 0 && m_drive->scopeSamplesAxis(m_axes[static_cast<std::size_t>(m_testSecondUnit)].name)));
    if (testMovesIt) {
        // The test's pace applies; the scope's other axes follow the one the test moves.
        m_drive->syncScopeAxes();
        m_scopeWall = now;
        return;
    }
    const sim::AxisSimulator& s = *m_axes[static_cast<std::size_t>(m_scopeUnit)].sim;
    const double rate = m_opt.pace > 0.0 ? m_opt.pace : 1.0;
    const double h = s.currentPeriod();
    const double due = std::chrono::duration<double>(now - m_scopeWall).count() * rate;
    // Whole velocity periods, ending on one (the scope samples there): a test started next begins on a velocity
    // period, as its record and the scope's rows then share their instants.
    const std::int64_t perVelocity = std::max<std::int64_t>(1, std::llround(s.velocityPeriod() / h));
    const std::int64_t at = s.currentTicks();
    auto target = [&](double seconds) {
        return (at + static_cast<std::int64_t>(std::floor(seconds / h))) / perVelocity * perVelocity;
    };
    auto ticks = std::max<std::int64_t>(0, target(due) - at);
    // At most 0.1 s of machine time per turn: after a stall the machine runs on from where it was (no samples
    // are dropped; the simulated machine falls behind the wall clock instead).
    if (due > 0.1) {
        ticks = std::max<std::int64_t>(0, target(0.1) - at);
        m_scopeWall = now;
    } else {
        m_scopeWall += std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(static_cast<double>(ticks) * h / rate));
    }
    m_drive->runScopeAxes(ticks);
}

int SimDriveServer::armScope(int ui)
{
    const Axis& ax = m_axes[static_cast<std::size_t>(ui)];
    const ScopeConfig& c = m_scopeConfig[static_cast<std::size_t>(ui)];
    auto caps = m_drive->scopeCapabilities(ax.name);
    if (!caps)
        return refuseError(caps.error());
    ScopeRequest r;
    r.axis = ax.name;
    const std::string mode = m_map.name("scope_mode", c.mode), edge = m_map.name("scope_edge", c.edge);
    r.mode = mode == "roll" ? ScopeMode::Roll : mode == "normal" ? ScopeMode::Normal : ScopeMode::Single;
    r.edge = edge == "falling" ? ScopeEdge::Falling : edge == "either" ? ScopeEdge::Either : ScopeEdge::Rising;
    for (std::size_t i = 0; i < 32; ++i) {
        if (!(c.mask >> i & 1u))
            continue;
        if (i >= caps->channels.size())
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE,
                          "scope.channel_mask bit " + std::to_string(i) + ": axis " + ax.name + " has " +
                              std::to_string(caps->channels.size()) + " scope channels");
        r.channels.push_back(caps->channels[i].name);
    }
    r.divider = c.divider;
    r.lengthSamples = c.length;
    r.triggerLevel = c.level;
    r.preTriggerPct = c.prePct;
    if (r.mode != ScopeMode::Roll) {
        if (c.triggerChannel >= caps->channels.size() || !(c.mask >> c.triggerChannel & 1u))
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "scope.trigger_channel " +
                                                                   std::to_string(c.triggerChannel) +
                                                                   " is not one of the channels of scope.channel_mask");
        r.triggerChannel = caps->channels[c.triggerChannel].name;
    }
    if (auto st = m_drive->armScope(r); !st)
        return refuseError(st.error());
    m_scopeUnit = ui;
    m_scopeWall = Clock::now();
    m_scopeCapture.reset();
    log("scope armed on axis " + ax.name + " (" + mode + ", " + std::to_string(r.channels.size()) + " channels)");
    return 0;
}

int SimDriveServer::writeScopeField(const RegisterField& f, int ui, const std::uint16_t* w)
{
    ScopeConfig& c = m_scopeConfig[static_cast<std::size_t>(ui)];
    const std::string& n = f.name;
    const WordOrder o = m_map.wordOrder;
    if (f.type == RegisterType::F64) {
        const double v = decodeF64(w, o);
        if (!std::isfinite(v))
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, n + " must be finite");
        if (n == "scope.trigger_level") {
            c.level = v;
        } else if (n == "scope.pre_trigger_pct") {
            c.prePct = v;
        } else if (n == "scope.read_from") {
            if (!(v >= 0.0) || v != std::floor(v) || v > 9007199254740992.0)
                return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "scope.read_from must be a whole number >= 0");
            m_scopeFrom = v;
        } else {
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, "field " + n + " is read-only");
        }
        return 0;
    }
    if (n == "scope.mode") {
        if (m_map.name("scope_mode", w[0]).empty())
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "unknown scope mode " + std::to_string(w[0]));
        c.mode = w[0];
    } else if (n == "scope.trigger_edge") {
        if (m_map.name("scope_edge", w[0]).empty())
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "unknown scope edge " + std::to_string(w[0]));
        c.edge = w[0];
    } else if (n == "scope.read_source") {
        if (m_map.name("scope_source", w[0]).empty())
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "unknown scope source " + std::to_string(w[0]));
        m_scopeSource = w[0];
    } else if (n == "scope.divider") {
        c.divider = w[0];
    } else if (n == "scope.trigger_channel") {
        c.triggerChannel = w[0];
    } else if (n == "scope.channel_mask") {
        c.mask = decodeU32(w, o);
    } else if (n == "scope.length") {
        c.length = decodeU32(w, o);
    } else {
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, "field " + n + " is read-only");
    }
    return 0;
}

bool SimDriveServer::encodeScopeField(const RegisterField& f, int ui, std::uint16_t* buf)
{
    const std::string& n = f.name;
    const WordOrder o = m_map.wordOrder;
    const ScopeConfig& c = m_scopeConfig[static_cast<std::size_t>(ui)];
    const bool mine = ui == m_scopeUnit;
    const ScopeStatus st = mine ? m_drive->scopeStatus() : ScopeStatus{};
    auto u16 = [&](int v) {
        buf[0] = static_cast<std::uint16_t>(v);
        return true;
    };
    auto f64 = [&](double v) {
        encodeF64(v, o, buf);
        return true;
    };
    auto u32 = [&](std::uint64_t v) {
        encodeU32(static_cast<std::uint32_t>(std::min<std::uint64_t>(v, 0xffffffffu)), o, buf);
        return true;
    };
    if (n == "scope.window") {
        encodeScopeWindow(f, ui, buf);
        return true;
    }
    if (n == "scope.mode")
        return u16(c.mode);
    if (n == "scope.divider")
        return u16(c.divider);
    if (n == "scope.channel_mask")
        return u32(c.mask);
    if (n == "scope.trigger_channel")
        return u16(c.triggerChannel);
    if (n == "scope.trigger_edge")
        return u16(c.edge);
    if (n == "scope.length")
        return u32(c.length);
    if (n == "scope.trigger_level")
        return f64(c.level);
    if (n == "scope.pre_trigger_pct")
        return f64(c.prePct);
    if (n == "scope.read_source")
        return u16(m_scopeSource);
    if (n == "scope.read_from")
        return f64(m_scopeFrom);
    if (n == "scope.state")
        return u16(m_map.code("scope_state", scopeStateName(st.state)));
    if (n == "scope.channel_count")
        return u16(mine ? static_cast<int>(m_drive->scopeChannelCount()) : 0);
    if (n == "scope.captures")
        return u32(st.captures);
    if (n == "scope.rate_hz")
        return f64(st.rateHz);
    if (n == "scope.next_sample")
        return f64(static_cast<double>(st.nextSample));
    if (n == "scope.oldest_sample")
        return f64(static_cast<double>(st.oldestSample));
    if (n == "scope.capture_first")
        return f64(static_cast<double>(st.captureFirstSample));
    if (n == "scope.capture_trigger")
        return f64(static_cast<double>(st.captureTriggerSample));
    if (n == "scope.capture_rows")
        return u32(st.captureRows);
    auto caps = m_drive->scopeCapabilities(m_axes[static_cast<std::size_t>(ui)].name);
    if (n == "scope.signal_count")
        return u16(caps ? static_cast<int>(caps->channels.size()) : 0);
    if (n == "scope.max_channels")
        return u16(caps ? caps->maxChannels : 0);
    if (n == "scope.fastest_rate_hz")
        return f64(caps ? caps->fastestRateHz : 0.0);
    if (n == "scope.max_values")
        return u32(caps ? caps->maxValues : 0);
    if (n == "scope.ring_values")
        return u32(caps ? caps->ringValues : 0);
    if (n == "scope.max_divider")
        return u16(caps ? caps->maxDivider : 0);
    return false;
}

void SimDriveServer::encodeScopeWindow(const RegisterField& f, int ui, std::uint16_t* buf)
{
    const WordOrder o = m_map.wordOrder;
    std::memset(buf, 0, sizeof(std::uint16_t) * static_cast<std::size_t>(f.count));
    const std::string source = m_map.name("scope_source", m_scopeSource);
    const auto from = static_cast<std::uint64_t>(m_scopeFrom);
    if (source == "channels") {
        auto caps = m_drive->scopeCapabilities(m_axes[static_cast<std::size_t>(ui)].name);
        std::string text;
        if (caps) {
            for (const auto& ch : caps->channels)
                text += ch.name + "\t" + ch.unit + "\t" + ch.description + "\n";
        }
        encodeString(from < text.size() ? text.substr(static_cast<std::size_t>(from)) : std::string(), f.count, buf);
        return;
    }
    if (ui != m_scopeUnit || f.count < 6)
        return;
    const std::size_t width = m_drive->scopeChannelCount();
    if (width == 0)
        return;
    const std::size_t perPage = static_cast<std::size_t>(f.count - 6) / (4 * width);
    std::uint64_t first = from, number = 0;
    std::size_t rows = 0;
    std::vector<double> values;
    if (source == "ring") {
        auto r = m_drive->readScopeRows(from, perPage);
        if (!r)
            return;
        first = r->firstSample;
        rows = r->rows;
        values = std::move(r->values);
    } else if (source == "capture") {
        const auto captures = m_drive->scopeStatus().captures;
        if (!m_scopeCapture || m_scopeCapture->number != captures) {
            auto c = m_drive->readScopeCapture();
            if (!c)
                return;
            m_scopeCapture = std::move(c).value();
        }
        const ScopeCapture& c = *m_scopeCapture;
        number = c.number;
        const std::uint64_t c0 = c.samples.empty() ? 0 : c.samples.front();
        first = std::max(from, c0);
        const std::uint64_t end = c0 + c.samples.size();
        rows = first < end ? static_cast<std::size_t>(std::min<std::uint64_t>(perPage, end - first)) : 0;
        values.resize(rows * width);
        for (std::size_t i = 0; i < rows; ++i) {
            for (std::size_t k = 0; k < width; ++k)
                values[i * width + k] = c.columns[k][static_cast<std::size_t>(first - c0) + i];
        }
    }
    encodeF64(static_cast<double>(first), o, buf);
    buf[4] = static_cast<std::uint16_t>(rows);
    buf[5] = static_cast<std::uint16_t>(number & 0xffffu);
    for (std::size_t i = 0; i < rows * width; ++i)
        encodeF64(values[i], o, buf + 6 + 4 * i);
}

} // namespace axistune::device
