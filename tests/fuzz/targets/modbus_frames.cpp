// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: (only the committed frames in tests/data/fuzz/modbus_frames/)
// The simulated drive's Modbus request handling (axistune-simdrive): raw bytes as one client's TCP
// stream (framing by libmodbus, then the server's decoding and register engine), in-process through a
// socketpair. No crash, no sanitizer report, and the stream ends (no hang) whatever the bytes.
#include "core/device/SimDriveServer.h"

#include <fcntl.h>
#include <memory>
#include <sys/socket.h>
#include <unistd.h>

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
    int fds[2];
    fuzz::require(::socketpair(AF_UNIX, SOCK_STREAM, 0, fds) == 0, "socketpair failed");
    // Answers go to fds[1], which nobody reads: a full buffer makes the send fail instead of blocking.
    ::fcntl(fds[0], F_SETFL, ::fcntl(fds[0], F_GETFL) | O_NONBLOCK);
    std::size_t sent = 0;
    while (sent < input.size()) {
        const ssize_t n = ::write(fds[1], input.data() + sent, input.size() - sent);
        if (n <= 0)
            break;
        sent += static_cast<std::size_t>(n);
    }
    ::shutdown(fds[1], SHUT_WR);
    server->serveStream(fds[0]);
    ::close(fds[0]);
    ::close(fds[1]);
}
