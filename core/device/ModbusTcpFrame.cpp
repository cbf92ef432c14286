// SPDX-License-Identifier: GPL-3.0-or-later
// Modbus TCP framing and request decoding for the simulated drive's server (Modbus Application
// Protocol V1.1b3 §6.3, §6.6, §6.12, §6.17 and §7; Modbus Messaging on TCP/IP V1.0b §3.1.3).
// A frame is delimited by its MBAP length field alone; the PDU inside must then agree with it
// exactly (byte count, quantity and frame length), so no request is ever executed with bytes that
// belong to another one.
#include "core/device/ModbusTcpFrame.h"

namespace axistune::device {
namespace {

constexpr int kIllegalFunction = 1, kIllegalAddress = 2, kIllegalValue = 3;

int be16(const std::uint8_t* p)
{
    return (p[0] << 8) | p[1];
}

void put16(std::vector<std::uint8_t>& out, int v)
{
    out.push_back(static_cast<std::uint8_t>((v >> 8) & 0xff));
    out.push_back(static_cast<std::uint8_t>(v & 0xff));
}

ModbusRequest refused(ModbusRequest r, int exception, std::string why)
{
    r.exception = exception;
    r.why = "function " + std::to_string(r.function) + ": " + std::move(why);
    return r;
}

std::string n(std::size_t v)
{
    return std::to_string(v);
}

} // namespace

FrameScanResult scanMbapFrame(std::span<const std::uint8_t> b)
{
    FrameScanResult r;
    if (b.size() >= 4 && be16(b.data() + 2) != 0) {
        r.status = FrameScan::Invalid;
        r.why = "protocol id " + std::to_string(be16(b.data() + 2)) + " is not Modbus (0)";
        return r;
    }
    if (b.size() < 6)
        return r;
    const std::size_t length = static_cast<std::size_t>(be16(b.data() + 4)); // unit id + PDU
    if (length < 2 || length > kMaxPduBytes + 1) {
        r.status = FrameScan::Invalid;
        r.why = "MBAP length " + n(length) + " outside 2.." + n(kMaxPduBytes + 1);
        return r;
    }
    if (b.size() < 6 + length)
        return r;
    r.status = FrameScan::Complete;
    r.length = 6 + length;
    return r;
}

ModbusRequest decodeModbusRequest(std::span<const std::uint8_t> frame)
{
    ModbusRequest r;
    r.transaction = static_cast<std::uint16_t>(be16(frame.data()));
    r.unit = frame[6];
    const std::uint8_t* q = frame.data() + kMbapHeaderBytes;
    const std::size_t pdu = frame.size() - kMbapHeaderBytes;
    r.function = q[0];
    auto addressRange = [&](int address, int count) { return address + count <= 65536; };
    switch (r.function) {
    case 0x03:
        if (pdu != 5)
            return refused(r, kIllegalValue, "request of " + n(pdu) + " bytes, expected 5");
        r.readAddress = be16(q + 1);
        r.readCount = be16(q + 3);
        if (r.readCount < 1 || r.readCount > 125)
            return refused(r, kIllegalValue, "quantity " + n(r.readCount) + " outside 1..125");
        if (!addressRange(r.readAddress, r.readCount))
            return refused(r, kIllegalAddress,
                           "registers " + n(r.readAddress) + "+" + n(r.readCount) + " beyond 65535");
        return r;
    case 0x06:
        if (pdu != 5)
            return refused(r, kIllegalValue, "request of " + n(pdu) + " bytes, expected 5");
        r.writeAddress = be16(q + 1);
        r.writeCount = 1;
        r.values = {static_cast<std::uint16_t>(be16(q + 3))};
        return r;
    case 0x10:
    case 0x17: {
        const bool rw = r.function == 0x17;
        const std::size_t head = rw ? 10 : 6; // function, [read address, read quantity,] address, quantity, byte count
        if (pdu < head)
            return refused(r, kIllegalValue,
                           "request of " + n(pdu) + " bytes, shorter than its " + n(head) + "-byte header");
        if (rw) {
            r.readAddress = be16(q + 1);
            r.readCount = be16(q + 3);
        }
        r.writeAddress = be16(q + (rw ? 5 : 1));
        r.writeCount = be16(q + (rw ? 7 : 3));
        const std::size_t byteCount = q[head - 1];
        const int maxWrite = rw ? 121 : 123;
        if (rw && (r.readCount < 1 || r.readCount > 125))
            return refused(r, kIllegalValue, "read quantity " + n(r.readCount) + " outside 1..125");
        if (r.writeCount < 1 || r.writeCount > maxWrite)
            return refused(r, kIllegalValue, "write quantity " + n(r.writeCount) + " outside 1.." + n(maxWrite));
        if (byteCount != 2 * static_cast<std::size_t>(r.writeCount))
            return refused(r, kIllegalValue,
                           "byte count " + n(byteCount) + " does not match " + n(r.writeCount) + " registers (" +
                               n(2 * r.writeCount) + " bytes)");
        if (pdu != head + byteCount)
            return refused(r, kIllegalValue,
                           "the frame carries " + n(pdu - head) + " data bytes, the byte count says " + n(byteCount));
        if (rw && !addressRange(r.readAddress, r.readCount))
            return refused(r, kIllegalAddress,
                           "registers " + n(r.readAddress) + "+" + n(r.readCount) + " beyond 65535");
        if (!addressRange(r.writeAddress, r.writeCount))
            return refused(r, kIllegalAddress,
                           "registers " + n(r.writeAddress) + "+" + n(r.writeCount) + " beyond 65535");
        r.values.resize(static_cast<std::size_t>(r.writeCount));
        for (std::size_t k = 0; k < r.values.size(); ++k)
            r.values[k] = static_cast<std::uint16_t>(be16(q + head + 2 * k));
        return r;
    }
    default:
        return refused(r, kIllegalFunction, "not served by this drive (3, 6, 16 and 23 are)");
    }
}

std::vector<std::uint8_t> encodeModbusReply(const ModbusRequest& request, int exception,
                                            std::span<const std::uint16_t> registers)
{
    std::vector<std::uint8_t> pdu;
    if (exception) {
        pdu = {static_cast<std::uint8_t>(request.function | 0x80), static_cast<std::uint8_t>(exception)};
    } else if (request.function == 0x03 || request.function == 0x17) {
        pdu.push_back(request.function);
        pdu.push_back(static_cast<std::uint8_t>(2 * registers.size()));
        for (const auto v : registers)
            put16(pdu, v);
    } else {
        pdu.push_back(request.function);
        put16(pdu, request.writeAddress);
        put16(pdu, request.function == 0x06 ? request.values.front() : request.writeCount);
    }
    std::vector<std::uint8_t> out;
    out.reserve(kMbapHeaderBytes + pdu.size());
    put16(out, request.transaction);
    put16(out, 0);
    put16(out, static_cast<int>(pdu.size() + 1));
    out.push_back(request.unit);
    out.insert(out.end(), pdu.begin(), pdu.end());
    return out;
}

} // namespace axistune::device
