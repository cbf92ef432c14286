// SPDX-License-Identifier: GPL-3.0-or-later
// Paged readout of the Modbus drive: trace channels, texts and the FRF through the trace window
// (function code 23: select and read in one round trip); format in docs/modbus.md.
#include "core/device/ModbusDrive.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <modbus/modbus.h>
#include <sstream>

namespace axistune::device {

Result<std::string> ModbusDrive::readText(int unit, std::uint16_t channel)
{
    const auto& sel = m_map.field("trace.select_offset");
    const auto& win = m_map.field("trace.window");
    std::string text;
    std::vector<std::uint16_t> buf(static_cast<std::size_t>(win.count));
    for (int page = 0; page < 64; ++page) { // texts are short: at most 64 windows
        std::uint16_t w[3];
        encodeU32(static_cast<std::uint32_t>(text.size()), m_map.wordOrder, w);
        w[2] = channel;
        auto st = transact(unit, "reading trace text", Retry::Idempotent, [&](modbus_t* c) {
            return modbus_write_and_read_registers(c, sel.address, 3, w, win.address, win.count, buf.data());
        });
        if (!st)
            return st.error();
        const std::string part = decodeString(buf.data(), win.count);
        text += part;
        if (part.size() < 2 * static_cast<std::size_t>(win.count))
            return text;
    }
    return text;
}

Result<model::Capture> ModbusDrive::readTrace()
{
    const int unit = m_testUnit >= 0 ? m_testUnit : m_map.unitIdBase;
    // Samples, channels and rate in one read (status.trace_samples .. status.trace_rate_hz).
    const auto& fs = m_map.field("status.trace_samples");
    const auto& fc = m_map.field("status.trace_channels");
    const auto& fr = m_map.field("status.trace_rate_hz");
    const int lo = std::min({fs.address, fc.address, fr.address});
    const int hi = std::max({fs.address + fs.count, fc.address + fc.count, fr.address + fr.count});
    std::vector<std::uint16_t> r(static_cast<std::size_t>(hi - lo));
    if (auto st = readRegs(unit, lo, hi - lo, r.data(), "reading the trace size"); !st)
        return st.error();
    const std::uint32_t samples = decodeU32(&r[static_cast<std::size_t>(fs.address - lo)], m_map.wordOrder);
    const int channels = r[static_cast<std::size_t>(fc.address - lo)];
    const double rateHz = decodeF64(&r[static_cast<std::size_t>(fr.address - lo)], m_map.wordOrder);
    if (samples == 0 || channels == 0)
        return makeError(ErrorCode::NotFound, m_uri.text + ": no trace: no test has completed");
    model::Capture cap;
    auto names = readText(unit, static_cast<std::uint16_t>(m_map.code("trace_channel", "names")));
    if (!names)
        return names.error();
    auto meta = readText(unit, static_cast<std::uint16_t>(m_map.code("trace_channel", "metadata")));
    if (!meta)
        return meta.error();
    std::stringstream ns(*names), ms(*meta);
    for (std::string line; std::getline(ns, line);)
        cap.channels.push_back({line, {}});
    for (std::string line; std::getline(ms, line);) {
        if (auto eq = line.find('='); eq != std::string::npos)
            cap.metadata.setFromText(line.substr(0, eq), line.substr(eq + 1));
    }
    // The trace's rate: the velocity-loop divider or, for a current step, the current-loop rate.
    if (!cap.metadata.contains(model::meta::kFsHz) && rateHz > 0.0) {
        cap.metadata.set(model::meta::kFsHz, rateHz);
    } else if (cap.metadata.contains(model::meta::kFsHz)) {
        const auto fsHz = cap.metadata.number(model::meta::kFsHz);
        if (!fsHz)
            return makeError(ErrorCode::Device, m_uri.text + ": trace " + fsHz.error().detail);
        if (!(std::abs(*fsHz - rateHz) <= 1e-9 * std::abs(rateHz)))
            return makeError(ErrorCode::Device,
                             m_uri.text + ": trace metadata says fs_Hz=" + *cap.metadata.text(model::meta::kFsHz) +
                                 " but status.trace_rate_hz is " + model::formatNumber(rateHz, 17) + " Hz");
    }
    if (static_cast<int>(cap.channels.size()) != channels)
        return makeError(ErrorCode::Device, m_uri.text + ": trace lists " + std::to_string(cap.channels.size()) +
                                                " channel names for " + std::to_string(channels) + " channels");
    const auto& sel = m_map.field("trace.select_offset");
    const auto& win = m_map.field("trace.window");
    const int perPage = win.count / 4;
    std::vector<std::uint16_t> buf(static_cast<std::size_t>(win.count));
    for (int c = 0; c < channels; ++c) {
        auto& data = cap.channels[static_cast<std::size_t>(c)].data;
        data.reserve(samples);
        for (std::uint32_t off = 0; off < samples; off += static_cast<std::uint32_t>(perPage)) {
            std::uint16_t w[3];
            encodeU32(off, m_map.wordOrder, w);
            w[2] = static_cast<std::uint16_t>(c);
            // Select the page and read it in one request (function code 23); repeating it is harmless.
            auto st = transact(unit, "reading trace channel " + cap.channels[static_cast<std::size_t>(c)].name,
                               Retry::Idempotent, [&](modbus_t* ctx) {
                                   return modbus_write_and_read_registers(ctx, sel.address, 3, w, win.address,
                                                                          win.count, buf.data());
                               });
            if (!st)
                return st.error();
            const std::uint32_t n = std::min<std::uint32_t>(static_cast<std::uint32_t>(perPage), samples - off);
            for (std::uint32_t k = 0; k < n; ++k)
                data.push_back(decodeF64(&buf[4 * k], m_map.wordOrder));
        }
    }
    return cap;
}

Result<std::vector<double>> ModbusDrive::readBlob(int unit, std::uint16_t channel)
{
    const auto& sel = m_map.field("trace.select_offset");
    const auto& win = m_map.field("trace.window");
    const std::uint32_t perPage = static_cast<std::uint32_t>(win.count / 4);
    std::vector<std::uint16_t> buf(static_cast<std::size_t>(win.count));
    std::vector<double> blob;
    std::size_t length = 1; // known after the first page: element 0 is the length
    constexpr std::size_t kMaxLength = 50'000'000;
    for (std::uint32_t off = 0; off < length; off += perPage) {
        std::uint16_t w[3];
        encodeU32(off, m_map.wordOrder, w);
        w[2] = channel;
        auto st = transact(unit, "reading the frequency response", Retry::Idempotent, [&](modbus_t* c) {
            return modbus_write_and_read_registers(c, sel.address, 3, w, win.address, win.count, buf.data());
        });
        if (!st)
            return st.error();
        for (std::uint32_t k = 0; k < perPage && off + k < length; ++k) {
            blob.push_back(decodeF64(&buf[4 * k], m_map.wordOrder));
            if (off + k == 0) {
                if (!(blob[0] >= 3.0 && blob[0] <= static_cast<double>(kMaxLength)))
                    return makeError(ErrorCode::NotFound,
                                     m_uri.text + ": no frequency response: no FRF test has completed");
                length = static_cast<std::size_t>(blob[0]);
            }
        }
    }
    return blob;
}

Result<FrfMeasurement> ModbusDrive::readFrequencyResponse()
{
    const int unit = m_testUnit >= 0 ? m_testUnit : m_map.unitIdBase;
    const int dataSel = m_map.code("trace_channel", "frf_data"), metaSel = m_map.code("trace_channel", "frf_metadata");
    if (dataSel < 0 || metaSel < 0)
        return makeError(ErrorCode::NotFound, "drive family " + m_map.family + " does not serve frequency responses");
    auto blob = readBlob(unit, static_cast<std::uint16_t>(dataSel));
    if (!blob)
        return blob.error();
    auto meta = readText(unit, static_cast<std::uint16_t>(metaSel));
    if (!meta)
        return meta.error();
    const std::vector<double>& b = *blob;
    std::size_t i = 1;
    auto malformed = [&] {
        return makeError(ErrorCode::Device, m_uri.text + ": malformed frequency response from the drive");
    };
    auto take = [&](std::size_t n) { return i + n <= b.size(); };
    FrfMeasurement m;
    if (!take(2))
        return malformed();
    m.motionTimeS = b[i++];
    const auto points = static_cast<std::size_t>(b[i++]);
    if (!take(5 * points + 3))
        return malformed();
    for (std::size_t p = 0; p < points; ++p, i += 5)
        m.frf.push(b[i], {b[i + 1], b[i + 2]}, b[i + 3], b[i + 4] != 0.0);
    m.sweep.fsHz = b[i++];
    m.sweep.amplitude = b[i++];
    const auto blocks = static_cast<std::size_t>(b[i++]);
    for (std::size_t k = 0; k < blocks; ++k) {
        if (!take(3))
            return malformed();
        dsp::SweepBlock blk;
        blk.freqHz = b[i];
        blk.phaseOffsetDeg = b[i + 1];
        const auto n = static_cast<std::size_t>(b[i + 2]);
        i += 3;
        if (!take(3 * n))
            return malformed();
        for (std::size_t s = 0; s < n; ++s)
            blk.sample.push_back(static_cast<std::int64_t>(b[i + s]));
        blk.excitation.assign(b.begin() + static_cast<std::ptrdiff_t>(i + n),
                              b.begin() + static_cast<std::ptrdiff_t>(i + 2 * n));
        blk.response.assign(b.begin() + static_cast<std::ptrdiff_t>(i + 2 * n),
                            b.begin() + static_cast<std::ptrdiff_t>(i + 3 * n));
        i += 3 * n;
        m.sweep.blocks.push_back(std::move(blk));
    }
    std::stringstream ms(*meta);
    for (std::string line; std::getline(ms, line);) {
        const auto eq = line.find('=');
        if (eq == std::string::npos)
            continue;
        const std::string k = line.substr(0, eq), v = line.substr(eq + 1);
        if (k.rfind("frf.", 0) == 0)
            m.frf.metadata.setFromText(k.substr(4), v);
        else if (k.rfind("sweep.", 0) == 0)
            m.sweep.metadata.setFromText(k.substr(6), v);
    }
    return m;
}

} // namespace axistune::device
