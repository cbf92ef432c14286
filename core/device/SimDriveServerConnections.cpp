// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-simdrive's sockets (docs/modbus.md "Under abuse"): one thread, poll() over non-blocking
// sockets, each connection with its own input buffer, so a partial frame waits in its buffer and
// never holds up another client. A frame is taken only when complete (MBAP length), and only the
// bytes of that frame are decoded. Bounds: a bounded connection table (a new client takes the place
// of a silent or the longest-idle one), a deadline for a started frame, for a connection that never
// sends a request, and for answers a client does not read. Connection log lines are rate-limited;
// each refused request is logged once.
#include "core/device/ModbusTcpFrame.h"
#include "core/device/SimDriveServer.h"

#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

namespace axistune::device {
namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr std::size_t kMaxConnections = 32; ///< open at once; a new one displaces another
constexpr auto kFrameTimeout = 1000ms;      ///< a started frame must be complete within
constexpr auto kSilentTimeout = 10s;        ///< a connection must send its first request within
constexpr auto kSendTimeout = 2s;           ///< an answer the client does not read
constexpr int kFramesPerTurn = 8;           ///< per connection and loop turn (fairness)
constexpr int kAcceptsPerTurn = 256;
constexpr std::size_t kInputBytes = 4 * kMaxAduBytes; ///< buffered per connection
constexpr int kConnectionLinesPerSecond = 20;

struct Connection {
    int fd = -1;
    int id = 0;
    std::string peer;
    std::vector<std::uint8_t> in, out;
    Clock::time_point opened, lastRequest, frameStarted, outSince;
    int requests = 0;
};

/// At most kConnectionLinesPerSecond connection lines per second; the rest are counted and summed
/// up in one line, so 5,000 connects do not flood the log.
class ConnectionLog {
public:
    explicit ConnectionLog(std::function<void(const std::string&)> log) : m_log(std::move(log)) {}
    void operator()(const std::string& line)
    {
        roll();
        if (m_lines < kConnectionLinesPerSecond) {
            ++m_lines;
            m_log(line);
        } else {
            ++m_suppressed;
        }
    }
    void roll()
    {
        const auto now = Clock::now();
        if (now - m_window < 1s)
            return;
        if (m_suppressed > 0)
            m_log(std::to_string(m_suppressed) + " more connection lines in the last second not logged one by one");
        m_window = now;
        m_lines = m_suppressed = 0;
    }

private:
    std::function<void(const std::string&)> m_log;
    Clock::time_point m_window = Clock::now();
    int m_lines = 0, m_suppressed = 0;
};

/// Sends what the connection has pending; false when the connection is broken.
bool flush(Connection& c, Clock::time_point now)
{
    while (!c.out.empty()) {
        const auto n = send(c.fd, c.out.data(), c.out.size(), MSG_NOSIGNAL);
        if (n < 0)
            return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
        c.out.erase(c.out.begin(), c.out.begin() + n);
        c.outSince = now;
    }
    return true;
}

} // namespace

Status SimDriveServer::listen(int port)
{
    const int fd = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd < 0)
        return makeError(ErrorCode::Device, std::string("cannot create a socket: ") + std::strerror(errno));
    m_listenFd = fd;
    const int one = 1;
    setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK); // loopback only, whatever the caller asked
    if (bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(fd, SOMAXCONN) != 0)
        return makeError(ErrorCode::Device,
                         "cannot listen on 127.0.0.1:" + std::to_string(port) + ": " + std::strerror(errno));
    socklen_t len = sizeof addr;
    getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
    m_port = ntohs(addr.sin_port);
    return Status::success();
}

Status SimDriveServer::serve()
{
    std::vector<Connection> conns;
    int nextId = 1;
    ConnectionLog connLog([this](const std::string& l) { log(l); });
    auto drop = [&](std::size_t i, const std::string& why) {
        connLog("connection " + std::to_string(conns[i].id) + " from " + conns[i].peer + " closed (" + why + ", " +
                std::to_string(conns[i].requests) + " requests)");
        close(conns[i].fd);
        conns.erase(conns.begin() + static_cast<std::ptrdiff_t>(i));
    };
    // The connection a new client displaces: one that never sent a request first, else the one idle
    // longest; a client that keeps talking is displaced only by kMaxConnections talking clients.
    auto displaced = [&]() {
        std::size_t best = 0;
        for (std::size_t i = 1; i < conns.size(); ++i) {
            const bool silentI = conns[i].requests == 0, silentB = conns[best].requests == 0;
            if (silentI != silentB ? silentI : conns[i].lastRequest < conns[best].lastRequest)
                best = i;
        }
        return best;
    };
    std::vector<pollfd> fds;
    bool pending = false; // complete frames left in a buffer by the per-turn limit
    while (!m_stop.load()) {
        fds.assign(1, pollfd{m_listenFd, POLLIN, 0});
        for (const auto& c : conns) {
            short ev = 0;
            if (c.out.empty() && c.in.size() < kInputBytes)
                ev |= POLLIN; // back-pressure: no more input while an answer waits to be read
            if (!c.out.empty())
                ev |= POLLOUT;
            fds.push_back(pollfd{c.fd, ev, 0});
        }
        const int n = poll(fds.data(), fds.size(), pending ? 0 : m_state == "running" || scopeArmed() ? 1 : 20);
        if (n < 0 && errno != EINTR)
            return makeError(ErrorCode::Device, std::string("poll failed: ") + std::strerror(errno));
        auto now = Clock::now();
        // Read and send first (indices of fds match conns until the table changes).
        std::vector<std::string> broken(conns.size());
        for (std::size_t i = 0; n > 0 && i < conns.size(); ++i) {
            Connection& c = conns[i];
            const short re = fds[i + 1].revents;
            if ((re & POLLOUT) && !flush(c, now))
                broken[i] = "connection lost while answering";
            if (re & (POLLIN | POLLHUP | POLLERR)) {
                std::uint8_t buf[kInputBytes];
                const auto got = recv(c.fd, buf, kInputBytes - c.in.size(), 0);
                if (got == 0)
                    broken[i] = "by the client";
                else if (got < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
                    broken[i] = std::strerror(errno);
                else if (got > 0) {
                    if (c.in.empty())
                        c.frameStarted = now;
                    c.in.insert(c.in.end(), buf, buf + got);
                }
            }
        }
        // Answer complete frames, a few per connection per turn.
        pending = false;
        for (std::size_t i = 0; i < conns.size(); ++i) {
            Connection& c = conns[i];
            for (int k = 0; k < kFramesPerTurn && broken[i].empty() && c.out.empty(); ++k) {
                const auto scan = scanMbapFrame(c.in);
                if (scan.status == FrameScan::Invalid) {
                    m_message = "connection " + std::to_string(c.id) + " from " + c.peer + ": " + scan.why;
                    log("refused: " + m_message + "; connection closed, nothing changed");
                    broken[i] = "not Modbus TCP";
                    break;
                }
                if (scan.status == FrameScan::NeedMore)
                    break;
                ++c.requests;
                c.lastRequest = now;
                if (m_opt.faults.dropAfterRequests > 0 && c.requests >= m_opt.faults.dropAfterRequests) {
                    log("fault drop-after:" + std::to_string(m_opt.faults.dropAfterRequests) +
                        ": dropping connection " + std::to_string(c.id));
                    broken[i] = "fault injected";
                    break;
                }
                if (m_opt.faults.delayMs > 0) {
                    log("fault delay:" + std::to_string(m_opt.faults.delayMs) + ": answering late");
                    std::this_thread::sleep_for(std::chrono::milliseconds(m_opt.faults.delayMs));
                }
                c.out = answer(std::span<const std::uint8_t>(c.in.data(), scan.length),
                               "connection " + std::to_string(c.id));
                c.outSince = now;
                c.in.erase(c.in.begin(), c.in.begin() + static_cast<std::ptrdiff_t>(scan.length));
                c.frameStarted = now;
                if (!flush(c, now))
                    broken[i] = "connection lost while answering";
            }
            if (broken[i].empty() && c.out.empty() && scanMbapFrame(c.in).status == FrameScan::Complete)
                pending = true;
        }
        // Deadlines.
        now = Clock::now();
        for (std::size_t i = 0; i < conns.size(); ++i) {
            const Connection& c = conns[i];
            if (!broken[i].empty())
                continue;
            if (!c.in.empty() && scanMbapFrame(c.in).status == FrameScan::NeedMore &&
                now - c.frameStarted > kFrameTimeout)
                broken[i] = "a request left incomplete for more than 1 s (" + std::to_string(c.in.size()) + " bytes)";
            else if (c.requests == 0 && c.in.empty() && now - c.opened > kSilentTimeout)
                broken[i] = "no request within 10 s of connecting";
            else if (!c.out.empty() && now - c.outSince > kSendTimeout)
                broken[i] = "the client does not read its answers";
        }
        for (std::size_t i = conns.size(); i-- > 0;) {
            if (!broken[i].empty())
                drop(i, broken[i]);
        }
        // New clients last, so the table indices above stayed valid.
        if (n > 0 && (fds[0].revents & POLLIN)) {
            for (int k = 0; k < kAcceptsPerTurn; ++k) {
                sockaddr_in peer{};
                socklen_t len = sizeof peer;
                const int fd =
                    accept4(m_listenFd, reinterpret_cast<sockaddr*>(&peer), &len, SOCK_NONBLOCK | SOCK_CLOEXEC);
                if (fd < 0)
                    break; // EAGAIN: none left; EMFILE and the like: retried next turn
                if (conns.size() >= kMaxConnections)
                    drop(displaced(),
                         "displaced by a new client: " + std::to_string(kMaxConnections) + " connections open");
                char ip[INET_ADDRSTRLEN] = "?";
                inet_ntop(AF_INET, &peer.sin_addr, ip, sizeof ip);
                Connection c;
                c.fd = fd;
                c.id = nextId++;
                c.peer = std::string(ip) + ":" + std::to_string(ntohs(peer.sin_port));
                c.opened = c.lastRequest = c.frameStarted = Clock::now();
                conns.push_back(std::move(c));
                connLog("connection " + std::to_string(conns.back().id) + " from " + conns.back().peer);
            }
        }
        connLog.roll();
        step();
    }
    while (!conns.empty())
        drop(0, "server shutting down");
    if (m_state == "running") {
        (void)m_drive->abortTest();
        log("shutdown during a test: test stopped, parameters restored");
    }
    return Status::success();
}

} // namespace axistune::device
