// SPDX-License-Identifier: GPL-3.0-or-later
// One client's byte stream through the server's request handling, without the network loop (fuzzing).
#include "core/device/ModbusTcpFrame.h"
#include "core/device/SimDriveServer.h"

namespace axistune::device {

std::size_t SimDriveServer::serveBytes(std::span<const std::uint8_t> bytes)
{
    std::size_t at = 0;
    std::size_t frames = 0;
    while (at < bytes.size()) {
        const auto scan = scanMbapFrame(bytes.subspan(at));
        // NeedMore: the stream ended inside a frame; Invalid: serve() closes such a connection.
        if (scan.status != FrameScan::Complete)
            break;
        (void)answer(bytes.subspan(at, scan.length), "stream");
        step();
        at += scan.length;
        ++frames;
    }
    return frames;
}

} // namespace axistune::device
