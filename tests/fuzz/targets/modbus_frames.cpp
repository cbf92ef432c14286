// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: (only the committed frames in tests/data/fuzz/modbus_frames/)
// The simulated drive's Modbus request handling (axistune-simdrive): raw bytes as one client's TCP
// stream (MBAP framing, the server's decoding and register engine), in-process. No crash, no sanitizer
// report, and the stream ends (no hang) whatever the bytes.
#include "core/device/SimDriveServer.h"

#include <cstdint>
#include <memory>

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(modbus_frames)
{
    static std::unique_ptr<device::SimDriveServer> server = [] {
        device::SimDriveServerOptions o;
        o.preset = "vmc";
        auto s = device::SimDriveServer::create(o);
        fuzz::require(s.ok(), "simdrive cannot start: " + (s.ok() ? "" : s.error().detail));
        return std::move(s).value();
    }();
    (void)server->serveBytes({reinterpret_cast<const std::uint8_t*>(input.data()), input.size()});
}
