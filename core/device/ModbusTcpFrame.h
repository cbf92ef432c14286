// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Modbus TCP requests as bytes, for a server (axistune-simdrive): framing by the MBAP header and
// decoding of the four function codes the drive serves (3, 6, 16, 23), every length and count checked
// before anything is handed on (Modbus Application Protocol V1.1b3 §6; Modbus Messaging on TCP/IP
// V1.0b §3.1.3). Pure functions on byte spans: no sockets, no state (docs/modbus.md "Under abuse").

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace axistune::device {

constexpr std::size_t kMbapHeaderBytes = 7; ///< transaction, protocol, length (2 bytes each), unit id
constexpr std::size_t kMaxPduBytes = 253;
constexpr std::size_t kMaxAduBytes = kMbapHeaderBytes + kMaxPduBytes; ///< 260

enum class FrameScan {
    NeedMore, ///< fewer bytes than the header announces
    Complete, ///< `length` bytes form one frame
    Invalid,  ///< not Modbus TCP (protocol id ≠ 0, length field outside 2..254): close the connection
};

struct FrameScanResult {
    FrameScan status = FrameScan::NeedMore;
    std::size_t length = 0; ///< the whole ADU (header + PDU) when Complete
    std::string why;        ///< when Invalid
};

/// Looks at the start of `buffered` (bytes received on one connection, not yet consumed).
FrameScanResult scanMbapFrame(std::span<const std::uint8_t> buffered);

/// One decoded request. `exception` ≠ 0: the frame is well framed but the request is refused before
/// it reaches the register engine (unknown function, counts out of range or not matching the byte
/// count or the frame length); `why` says which.
struct ModbusRequest {
    std::uint16_t transaction = 0;
    std::uint8_t unit = 0;
    std::uint8_t function = 0;
    int readAddress = 0, readCount = 0;   ///< 3 and 23
    int writeAddress = 0, writeCount = 0; ///< 6, 16 and 23
    std::vector<std::uint16_t> values;    ///< the registers to write, writeCount of them
    int exception = 0;
    std::string why;
};

/// Decodes one complete frame (as found by scanMbapFrame).
ModbusRequest decodeModbusRequest(std::span<const std::uint8_t> frame);

/// The answer to `request`: registers read (3, 23: `registers` holds readCount values), the echo of a
/// write (6, 16); or, with `exception` ≠ 0, the exception response.
std::vector<std::uint8_t> encodeModbusReply(const ModbusRequest& request, int exception,
                                            std::span<const std::uint16_t> registers);

} // namespace axistune::device
