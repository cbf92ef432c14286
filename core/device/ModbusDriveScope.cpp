// SPDX-License-Identifier: GPL-3.0-or-later
// The scope over Modbus (docs/modbus.md "Scope"): configuration block and arm_scope, status block, and the
// roll ring, the last capture and the channel list paged through scope.window with function 23.
#include "core/device/ModbusDrive.h"

#include <algorithm>
#include <modbus/modbus.h>
#include <sstream>

namespace axistune::device {

Status ModbusDrive::readScopePage(int unit, const std::string& source, std::uint64_t from,
                                  std::vector<std::uint16_t>& page)
{
    const auto& src = m_map.field("scope.read_source");
    const auto& win = m_map.field("scope.window");
    const auto& off = m_map.field("scope.read_from");
    if (off.address != src.address + 1)
        return makeError(ErrorCode::Internal,
                         "register map " + m_map.family + ": scope.read_from must follow scope.read_source");
    std::uint16_t w[5];
    w[0] = static_cast<std::uint16_t>(std::max(0, m_map.code("scope_source", source)));
    encodeF64(static_cast<double>(from), m_map.wordOrder, w + 1);
    page.resize(static_cast<std::size_t>(win.count));
    return transact(unit, "reading the scope (" + source + ")", Retry::Idempotent, [&](modbus_t* c) {
        return modbus_write_and_read_registers(c, src.address, 5, w, win.address, win.count, page.data());
    });
}

Result<ScopeCapabilities> ModbusDrive::scopeCapabilities(const std::string& axis)
{
    auto a = axisInfo(axis);
    if (!a)
        return a.error();
    if (!m_map.fields.count("scope.window"))
        return makeError(ErrorCode::NotFound, "drive family " + m_map.family + " has no scope fields: " + m_uri.text +
                                                  " offers no scope (axis " + axis + ")");
    int lo = 0;
    auto r = readFields(a->unit,
                        {"scope.signal_count", "scope.max_channels", "scope.fastest_rate_hz", "scope.max_values",
                         "scope.ring_values", "scope.max_divider"},
                        lo, "the scope of axis " + axis);
    if (!r)
        return r.error();
    auto at = [&](const char* f) { return &(*r)[static_cast<std::size_t>(m_map.field(f).address - lo)]; };
    const int count = *at("scope.signal_count");
    if (count == 0)
        return makeError(ErrorCode::NotFound, m_uri.text + ": axis " + axis + " has no scope channels");
    ScopeCapabilities c;
    c.maxChannels = *at("scope.max_channels");
    c.maxDivider = *at("scope.max_divider");
    c.fastestRateHz = decodeF64(at("scope.fastest_rate_hz"), m_map.wordOrder);
    c.maxValues = decodeU32(at("scope.max_values"), m_map.wordOrder);
    c.ringValues = decodeU32(at("scope.ring_values"), m_map.wordOrder);
    // The channel list: "name TAB unit TAB description" lines, 248 bytes per page.
    std::string text;
    std::vector<std::uint16_t> page;
    const int winCount = m_map.field("scope.window").count;
    for (int p = 0; p < 256; ++p) {
        if (auto st = readScopePage(a->unit, "channels", text.size(), page); !st)
            return st.error();
        const std::string part = decodeString(page.data(), winCount);
        text += part;
        if (part.size() < 2 * static_cast<std::size_t>(winCount))
            break;
    }
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const auto t1 = line.find('\t'), t2 = t1 == std::string::npos ? t1 : line.find('\t', t1 + 1);
        if (t2 == std::string::npos)
            return makeError(ErrorCode::Device, m_uri.text + ": scope channel list line '" + line +
                                                    "' is not 'name TAB unit TAB description'");
        c.channels.push_back({line.substr(0, t1), line.substr(t1 + 1, t2 - t1 - 1), line.substr(t2 + 1)});
    }
    if (static_cast<int>(c.channels.size()) != count)
        return makeError(ErrorCode::Device, m_uri.text + ": scope lists " + std::to_string(c.channels.size()) +
                                                " channels, scope.signal_count says " + std::to_string(count));
    return c;
}

Status ModbusDrive::armScope(const ScopeRequest& request)
{
    auto a = axisInfo(request.axis);
    if (!a)
        return a.error();
    auto caps = scopeCapabilities(request.axis);
    if (!caps)
        return caps.error();
    // Checked here first with the drive's own figures: a refused request sends nothing.
    auto setup = checkScopeRequest(request, *caps);
    if (!setup)
        return setup.error();
    std::uint32_t mask = 0;
    for (const auto i : setup->channels) {
        if (i >= 32)
            return makeError(ErrorCode::OutOfRange, "scope channel '" + caps->channels[i].name +
                                                        "' is beyond the 32 channels scope.channel_mask can select");
        mask |= 1u << i;
    }
    std::vector<std::size_t> sorted = setup->channels;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::size_t> column;
    for (const auto i : setup->channels)
        column.push_back(static_cast<std::size_t>(std::find(sorted.begin(), sorted.end(), i) - sorted.begin()));
    // The configuration block scope.mode .. scope.pre_trigger_pct in one request.
    const auto& first = m_map.field("scope.mode");
    const auto& last = m_map.field("scope.pre_trigger_pct");
    const int n = last.address + last.count - first.address;
    if (n < 1 || n > 123)
        return makeError(ErrorCode::Internal, "register map " + m_map.family + ": the scope block must fit one write");
    std::vector<std::uint16_t> w(static_cast<std::size_t>(n), 0);
    auto at = [&](const char* f) { return &w[static_cast<std::size_t>(m_map.field(f).address - first.address)]; };
    const WordOrder o = m_map.wordOrder;
    *at("scope.mode") = static_cast<std::uint16_t>(std::max(0, m_map.code("scope_mode", scopeModeName(request.mode))));
    *at("scope.divider") = static_cast<std::uint16_t>(request.divider);
    encodeU32(mask, o, at("scope.channel_mask"));
    *at("scope.trigger_channel") =
        request.mode == ScopeMode::Roll ? 0 : static_cast<std::uint16_t>(setup->channels[setup->triggerColumn]);
    *at("scope.trigger_edge") =
        static_cast<std::uint16_t>(std::max(0, m_map.code("scope_edge", scopeEdgeName(request.edge))));
    encodeU32(static_cast<std::uint32_t>(std::min<std::uint64_t>(request.lengthSamples, 0xffffffffu)), o,
              at("scope.length"));
    encodeF64(request.mode == ScopeMode::Roll ? 0.0 : request.triggerLevel, o, at("scope.trigger_level"));
    encodeF64(request.mode == ScopeMode::Roll ? 0.0 : request.preTriggerPct, o, at("scope.pre_trigger_pct"));
    if (auto st = writeRegs(a->unit, first.address, w.data(), n, "writing the scope configuration"); !st)
        return st;
    if (auto st = command(a->unit, "arm_scope"); !st)
        return st;
    m_scopeUnit = a->unit;
    m_scopeChannels.clear();
    for (const auto i : setup->channels)
        m_scopeChannels.push_back(caps->channels[i]);
    m_scopeColumn = std::move(column);
    return Status::success();
}

Result<ScopeStatus> ModbusDrive::pollScope()
{
    if (m_scopeUnit < 0)
        return ScopeStatus{};
    int lo = 0;
    auto r = readFields(m_scopeUnit,
                        {"scope.state", "scope.captures", "scope.rate_hz", "scope.next_sample", "scope.oldest_sample",
                         "scope.capture_first", "scope.capture_trigger", "scope.capture_rows"},
                        lo, "the scope status");
    if (!r)
        return r.error();
    auto at = [&](const char* f) { return &(*r)[static_cast<std::size_t>(m_map.field(f).address - lo)]; };
    const WordOrder o = m_map.wordOrder;
    ScopeStatus s;
    const std::string state = m_map.name("scope_state", *at("scope.state"));
    const ScopeState states[] = {ScopeState::Idle,      ScopeState::Filling, ScopeState::Waiting,
                                 ScopeState::Triggered, ScopeState::Done,    ScopeState::Rolling};
    bool known = false;
    for (const auto st : states) {
        if (state == scopeStateName(st)) {
            s.state = st;
            known = true;
        }
    }
    if (!known)
        return makeError(ErrorCode::Device, m_uri.text + ": unknown scope state " + std::to_string(*at("scope.state")));
    s.captures = decodeU32(at("scope.captures"), o);
    s.rateHz = decodeF64(at("scope.rate_hz"), o);
    s.nextSample = static_cast<std::uint64_t>(decodeF64(at("scope.next_sample"), o));
    s.oldestSample = static_cast<std::uint64_t>(decodeF64(at("scope.oldest_sample"), o));
    s.captureFirstSample = static_cast<std::uint64_t>(decodeF64(at("scope.capture_first"), o));
    s.captureTriggerSample = static_cast<std::uint64_t>(decodeF64(at("scope.capture_trigger"), o));
    s.captureRows = decodeU32(at("scope.capture_rows"), o);
    return s;
}

Result<ScopeRows> ModbusDrive::readScopeRows(std::uint64_t from, std::size_t maxRows)
{
    if (m_scopeUnit < 0)
        return makeError(ErrorCode::NotFound, m_uri.text + ": the scope is not armed");
    const std::size_t width = m_scopeChannels.size();
    const WordOrder o = m_map.wordOrder;
    ScopeRows out;
    out.firstSample = from;
    std::vector<std::uint16_t> page;
    std::uint64_t next = from;
    while (out.rows < maxRows) {
        // A long readout during a test keeps the drive's watchdog fed (a read of many pages takes longer than its
        // timeout on a slow link or machine; the test would stop with "no heartbeat").
        if (m_testRunning && Clock::now() - m_lastHeartbeat >= kHeartbeatPeriod)
            if (auto st = heartbeat(); !st)
                return st.error();
        if (auto st = readScopePage(m_scopeUnit, "ring", next, page); !st)
            return st.error();
        const auto first = static_cast<std::uint64_t>(decodeF64(page.data(), o));
        const std::size_t rows = std::min<std::size_t>(page[4], maxRows - out.rows);
        if (rows == 0)
            break;
        if (out.rows == 0)
            out.firstSample = first;
        else if (first != next)
            break; // overwritten meanwhile: the caller sees the gap at its next read
        if (6 + rows * width * 4 > page.size())
            return makeError(ErrorCode::Device, m_uri.text + ": scope window claims " + std::to_string(rows) +
                                                    " rows of " + std::to_string(width) + " channels");
        for (std::size_t i = 0; i < rows; ++i) {
            for (std::size_t k = 0; k < width; ++k)
                out.values.push_back(decodeF64(&page[6 + 4 * (i * width + m_scopeColumn[k])], o));
        }
        out.rows += rows;
        next = first + rows;
    }
    return out;
}

Result<ScopeCapture> ModbusDrive::readScopeCapture()
{
    const std::size_t width = m_scopeChannels.size();
    const WordOrder o = m_map.wordOrder;
    for (int attempt = 0; attempt < 3; ++attempt) {
        auto s = pollScope();
        if (!s)
            return s.error();
        if (s->captures == 0)
            return makeError(ErrorCode::NotFound, m_uri.text + std::string(": no complete scope capture yet (scope ") +
                                                      scopeStateName(s->state) + ")");
        ScopeCapture c;
        c.channels = m_scopeChannels;
        c.rateHz = s->rateHz;
        c.triggerSample = s->captureTriggerSample;
        c.number = s->captures;
        c.columns.assign(width, {});
        std::vector<std::uint16_t> page;
        bool replaced = false;
        std::uint64_t next = s->captureFirstSample;
        const std::uint64_t end = s->captureFirstSample + s->captureRows;
        while (next < end) {
            if (auto st = readScopePage(m_scopeUnit, "capture", next, page); !st)
                return st.error();
            const auto first = static_cast<std::uint64_t>(decodeF64(page.data(), o));
            const std::size_t rows = page[4];
            if (page[5] != (s->captures & 0xffffu) || first != next || rows == 0) {
                replaced = true; // normal mode: a newer capture replaced it while it was read
                break;
            }
            for (std::size_t i = 0; i < rows; ++i) {
                c.samples.push_back(first + i);
                for (std::size_t k = 0; k < width; ++k)
                    c.columns[k].push_back(decodeF64(&page[6 + 4 * (i * width + m_scopeColumn[k])], o));
            }
            next = first + rows;
        }
        if (!replaced)
            return c;
    }
    return makeError(ErrorCode::Busy, m_uri.text + ": the scope replaced its capture three times while it was read");
}

Status ModbusDrive::stopScope()
{
    if (m_scopeUnit < 0)
        return Status::success();
    return command(m_scopeUnit, "stop_scope");
}

} // namespace axistune::device
