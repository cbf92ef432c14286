// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-simdrive under abuse, end to end (issue 21 item 5, docs/modbus.md "Under abuse"): the
// binary on a free loopback port receives garbage, truncated frames, lying MBAP lengths, byte counts
// that do not match the quantity (functions 16 and 23), every unknown function code, reads and writes
// at and beyond every address edge of the committed map, out-of-range writes, 200 held connections,
// slow senders, 5,000 rapid connects and a refused test block followed by start_test. After each,
// libmodbus and mbpoll (independent client) read and write normally within a 1 s timeout, and what
// was refused is read back unchanged. Expected answers come from the Modbus specification (MODBUS
// Application Protocol V1.1b3 §6 and §7) and the committed map, not from the server's code.
#include <arpa/inet.h>
#include <chrono>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <optional>
#include <poll.h>
#include <random>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "tests/app/cli/ModbusTestUtil.h"
#include "tests/app/cli/SimDriveProcess.h"

using namespace axistune::testing;

namespace {

using Clock = std::chrono::steady_clock;
using Bytes = std::vector<std::uint8_t>;
using namespace std::chrono_literals;

double secondsSince(Clock::time_point t0)
{
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// A plain TCP connection to 127.0.0.1:port (blocking connect; reads bounded by poll()).
class Raw {
public:
    explicit Raw(int port)
    {
        m_fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_port = htons(static_cast<std::uint16_t>(port));
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        if (connect(m_fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
            close(m_fd);
            m_fd = -1;
        }
        const int one = 1;
        if (m_fd >= 0)
            setsockopt(m_fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    }
    ~Raw()
    {
        if (m_fd >= 0)
            close(m_fd);
    }
    Raw(const Raw&) = delete;
    Raw& operator=(const Raw&) = delete;
    bool ok() const { return m_fd >= 0; }
    bool send(const Bytes& b) const
    {
        return ::send(m_fd, b.data(), b.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(b.size());
    }
    /// Exactly n bytes within the timeout, else what came (shorter); `closed` when the peer closed.
    Bytes recvN(std::size_t n, std::chrono::milliseconds timeout, bool* closed = nullptr) const
    {
        Bytes out;
        const auto end = Clock::now() + timeout;
        while (out.size() < n) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - Clock::now()).count();
            pollfd p{m_fd, POLLIN, 0};
            if (left <= 0 || poll(&p, 1, static_cast<int>(left)) <= 0)
                break;
            std::uint8_t buf[512];
            const auto got = recv(m_fd, buf, std::min<std::size_t>(sizeof buf, n - out.size()), 0);
            if (got <= 0) {
                if (closed)
                    *closed = true;
                break;
            }
            out.insert(out.end(), buf, buf + got);
        }
        return out;
    }
    /// One Modbus TCP response (MBAP header + PDU), or nullopt.
    std::optional<Bytes> response(std::chrono::milliseconds timeout = 1000ms) const
    {
        Bytes h = recvN(7, timeout);
        if (h.size() < 7)
            return std::nullopt;
        const std::size_t len = (h[4] << 8) | h[5];
        if (len < 1)
            return std::nullopt;
        Bytes rest = recvN(len - 1, timeout);
        if (rest.size() != len - 1)
            return std::nullopt;
        h.insert(h.end(), rest.begin(), rest.end());
        return h;
    }
    /// True when the server closes the connection within the timeout (bytes it sends are counted).
    bool closedWithin(std::chrono::milliseconds timeout, std::size_t* bytesSeen = nullptr) const
    {
        bool closed = false;
        const Bytes b = recvN(1 << 20, timeout, &closed);
        if (bytesSeen)
            *bytesSeen = b.size();
        return closed;
    }

private:
    int m_fd = -1;
};

void put16(Bytes& b, int v)
{
    b.push_back(static_cast<std::uint8_t>((v >> 8) & 0xff));
    b.push_back(static_cast<std::uint8_t>(v & 0xff));
}

/// A Modbus TCP frame with an honest MBAP length.
Bytes frame(int tid, int unit, const Bytes& pdu)
{
    Bytes b;
    put16(b, tid);
    put16(b, 0);
    put16(b, static_cast<int>(pdu.size() + 1));
    b.push_back(static_cast<std::uint8_t>(unit));
    b.insert(b.end(), pdu.begin(), pdu.end());
    return b;
}

Bytes readPdu(int address, int count)
{
    Bytes p{0x03};
    put16(p, address);
    put16(p, count);
    return p;
}

/// Function 23 (or 16 without the read part) with `byteCount` and `data` as given (honest or not).
Bytes readWritePdu(int readAddress, int readCount, int address, int count, int byteCount,
                   const std::vector<std::uint16_t>& data, bool withRead = true)
{
    Bytes p{static_cast<std::uint8_t>(withRead ? 0x17 : 0x10)};
    if (withRead) {
        put16(p, readAddress);
        put16(p, readCount);
    }
    put16(p, address);
    put16(p, count);
    p.push_back(static_cast<std::uint8_t>(byteCount));
    for (auto v : data)
        put16(p, v);
    return p;
}

Bytes writePdu(int address, int count, int byteCount, const std::vector<std::uint16_t>& data)
{
    return readWritePdu(0, 0, address, count, byteCount, data, false);
}

/// The exception code of a response (0: a normal response); -1 when the function does not match.
int exceptionOf(const Bytes& r, int function)
{
    if (r.size() >= 9 && r[7] == (function | 0x80))
        return r[8];
    return r.size() >= 8 && r[7] == function ? 0 : -1;
}

/// IEEE 754 float32, high word first (the map's word_order).
std::vector<std::uint16_t> f32Words(float v)
{
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    return {static_cast<std::uint16_t>(u >> 16), static_cast<std::uint16_t>(u & 0xffff)};
}

std::vector<std::uint16_t> f64Words(double v)
{
    std::uint64_t u;
    std::memcpy(&u, &v, 8);
    return {static_cast<std::uint16_t>(u >> 48), static_cast<std::uint16_t>((u >> 32) & 0xffff),
            static_cast<std::uint16_t>((u >> 16) & 0xffff), static_cast<std::uint16_t>(u & 0xffff)};
}

int typeCount(const nlohmann::json& f)
{
    if (f.contains("count"))
        return f["count"].get<int>();
    const std::string t = f["type"];
    return t == "u16" ? 1 : t == "f64" ? 4 : 2;
}

int fieldAddress(const std::string& name)
{
    return registerMap()["fields"][name]["address"].get<int>();
}

/// A libmodbus client with a 1 s response timeout.
class Client {
public:
    explicit Client(int port)
    {
        m_ctx = modbus_new_tcp("127.0.0.1", port);
        modbus_set_response_timeout(m_ctx, 1, 0);
        m_connected = modbus_connect(m_ctx) == 0;
        modbus_set_slave(m_ctx, 1);
    }
    ~Client()
    {
        modbus_close(m_ctx);
        modbus_free(m_ctx);
    }
    bool connected() const { return m_connected; }
    std::optional<std::vector<std::uint16_t>> read(int address, int count)
    {
        std::vector<std::uint16_t> v(static_cast<std::size_t>(count));
        if (!m_connected || modbus_read_registers(m_ctx, address, count, v.data()) != count)
            return std::nullopt;
        return v;
    }
    bool write(int address, const std::vector<std::uint16_t>& v)
    {
        return m_connected && modbus_write_registers(m_ctx, address, static_cast<int>(v.size()), v.data()) ==
                                  static_cast<int>(v.size());
    }
    int lastErrno() const { return errno; }

private:
    modbus_t* m_ctx = nullptr;
    bool m_connected = false;
};

/// After the abuse: libmodbus reads the identity, writes velocity.kp and reads it back; mbpoll sees the
/// same value and writes another one that libmodbus reads. Every request within a 1 s timeout.
void expectNormalService(const SimDrive& srv, float kpValue)
{
    const auto map = registerMap();
    const int kp = parameterAddress("velocity.kp");
    Client c(srv.port());
    ASSERT_TRUE(c.connected());
    const auto id = c.read(0, 3);
    ASSERT_TRUE(id.has_value()) << modbus_strerror(c.lastErrno());
    EXPECT_EQ((*id)[0], map["magic"].get<int>());
    EXPECT_EQ((*id)[2], 3); // vmc: X, Y, Z
    ASSERT_TRUE(c.write(kp, f32Words(kpValue))) << modbus_strerror(c.lastErrno());
    const auto back = c.read(kp, 2);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(*back, f32Words(kpValue));
    const std::string floatArgs = "-t 4:float -B -a 1 -r " + std::to_string(kp) + " 127.0.0.1";
    EXPECT_EQ(mbpollValue(mbpoll(srv.port(), floatArgs), kp), kpValue);
    EXPECT_NE(mbpoll(srv.port(), floatArgs + " 0.5").find("Written 1 references"), std::string::npos);
    EXPECT_EQ(c.read(kp, 2), f32Words(0.5f));
}

/// status.message as text (two ASCII characters per register, high byte first); empty when the read fails.
std::string statusMessage(Client& c)
{
    std::string text;
    if (const auto msg = c.read(fieldAddress("status.message"), 64)) {
        for (auto w : *msg) {
            text += static_cast<char>(w >> 8);
            text += static_cast<char>(w & 0xff);
        }
    }
    return text;
}

std::size_t countLines(const std::string& log, const std::string& phrase)
{
    std::size_t n = 0;
    for (std::size_t at = log.find(phrase); at != std::string::npos; at = log.find(phrase, at + 1))
        ++n;
    return n;
}

} // namespace

TEST(ModbusAbuse, GarbageTruncatedAndLyingFramesChangeNothing)
{
    SimDrive srv("--preset vmc");
    ASSERT_GT(srv.port(), 0);
    const int kp = parameterAddress("velocity.kp");
    Client c(srv.port());
    const auto kpBefore = c.read(kp, 2);
    ASSERT_TRUE(kpBefore.has_value());

    // Garbage: 20 connections of 1000 random bytes whose protocol id is not 0 → each closed (one log line each).
    std::mt19937 rng(21);
    for (int k = 0; k < 20; ++k) {
        Raw r(srv.port());
        Bytes g(1000);
        for (auto& b : g)
            b = static_cast<std::uint8_t>(rng());
        g[2] = 0xA5; // protocol id high byte ≠ 0
        r.send(g);
        std::size_t seen = 0;
        EXPECT_TRUE(r.closedWithin(2000ms, &seen)) << "garbage connection " << k << " left open";
        EXPECT_EQ(seen, 0u) << "garbage was answered";
    }
    // Truncated frames: the first 1..11 bytes of a 12-byte read, all at once on 11 connections; each is
    // closed after the frame deadline (1 s), none answered.
    {
        const Bytes whole = frame(7, 1, readPdu(0, 3));
        std::vector<std::unique_ptr<Raw>> cut;
        for (std::size_t n = 1; n < whole.size(); ++n) {
            cut.push_back(std::make_unique<Raw>(srv.port()));
            cut.back()->send(Bytes(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(n)));
        }
        const auto t0 = Clock::now();
        for (auto& r : cut) {
            std::size_t seen = 0;
            EXPECT_TRUE(r->closedWithin(3000ms, &seen));
            EXPECT_EQ(seen, 0u);
        }
        EXPECT_LT(secondsSince(t0), 2.5); // 1 s deadline, polled every ≤ 20 ms
        // Meanwhile (and after) another client is served at once.
        EXPECT_TRUE(c.read(0, 1).has_value());
    }
    // Lying MBAP lengths: 0, 1 and 255..65535 are not Modbus TCP → closed; a length longer than what is
    // sent → incomplete → closed after 1 s; nothing executed either way.
    for (int len : {0, 1, 255, 300, 65535}) {
        Raw r(srv.port());
        Bytes b = frame(9, 1, writePdu(kp, 2, 4, f32Words(0.0f)));
        b[4] = static_cast<std::uint8_t>(len >> 8);
        b[5] = static_cast<std::uint8_t>(len & 0xff);
        r.send(b);
        std::size_t seen = 0;
        EXPECT_TRUE(r.closedWithin(2000ms, &seen)) << "MBAP length " << len;
        EXPECT_EQ(seen, 0u) << "MBAP length " << len;
    }
    {
        Raw r(srv.port());
        Bytes b = frame(10, 1, writePdu(kp, 2, 4, f32Words(0.0f)));
        b[5] = static_cast<std::uint8_t>(b[5] + 20); // claims 20 bytes more than it sends
        r.send(b);
        std::size_t seen = 0;
        EXPECT_TRUE(r.closedWithin(2500ms, &seen));
        EXPECT_EQ(seen, 0u);
    }
    // Byte count ≠ 2 × quantity (functions 16 and 23), with an honest MBAP length, after a valid write on
    // the same connection left bytes in every buffer: exception 3 (ILLEGAL DATA VALUE), nothing written.
    {
        Raw r(srv.port());
        r.send(frame(1, 1, writePdu(kp, 2, 4, *kpBefore)));
        ASSERT_TRUE(r.response().has_value());
        const std::vector<std::pair<Bytes, int>> bad = {
            {writePdu(kp, 2, 2, {0}), 0x10},                    // 2 registers, byte count 2, 2 bytes
            {writePdu(kp, 2, 6, {0, 0, 0}), 0x10},              // byte count 6
            {writePdu(kp, 2, 4, {0}), 0x10},                    // byte count 4, only 2 bytes follow
            {writePdu(kp, 2, 2, {0, 0}), 0x10},                 // byte count 2, 4 bytes follow
            {writePdu(kp, 0, 0, {}), 0x10},                     // quantity 0
            {writePdu(kp, 124, 248, {}), 0x10},                 // quantity 124 > 123
            {readWritePdu(0, 1, kp, 2, 2, {0}), 0x17},          // function 23, byte count 2
            {readWritePdu(0, 1, kp, 2, 4, {0}), 0x17},          // byte count 4, 2 bytes follow
            {readWritePdu(0, 1, kp, 2, 8, {0, 0, 0, 0}), 0x17}, // byte count 8
            {readWritePdu(0, 0, kp, 2, 4, {0, 0}), 0x17},       // read quantity 0
            {readWritePdu(0, 1, kp, 122, 244, {}), 0x17},       // write quantity 122 > 121
            {Bytes{0x10, 0x03}, 0x10},                          // shorter than its header
            {Bytes{0x03, 0x00, 0x00, 0x00, 0x01, 0x00}, 0x03},  // function 3 with a byte too many
            {Bytes{0x06, 0x03, 0xFC}, 0x06},                    // function 6, 2 bytes short
        };
        int tid = 100;
        for (const auto& [pdu, fc] : bad) {
            ASSERT_TRUE(r.send(frame(tid, 1, pdu)));
            const auto resp = r.response();
            ASSERT_TRUE(resp.has_value()) << "no answer to malformed function " << fc << " (tid " << tid << ")";
            EXPECT_EQ(((*resp)[0] << 8) | (*resp)[1], tid);
            EXPECT_EQ(exceptionOf(*resp, fc), 3) << "tid " << tid;
            ++tid;
        }
        EXPECT_EQ(c.read(kp, 2), kpBefore) << "a malformed write changed velocity.kp";
    }
    // Every function code the drive does not serve: exception 1 (ILLEGAL FUNCTION), in order, one connection.
    {
        Raw r(srv.port());
        int answered = 0;
        for (int fc = 0; fc < 256; ++fc) {
            if (fc == 3 || fc == 6 || fc == 16 || fc == 23)
                continue;
            ASSERT_TRUE(r.send(frame(fc, 1, Bytes{static_cast<std::uint8_t>(fc), 0, 0, 0, 1})));
            const auto resp = r.response();
            ASSERT_TRUE(resp.has_value()) << "function " << fc;
            ASSERT_EQ(resp->size(), 9u);
            EXPECT_EQ((*resp)[7], fc | 0x80);
            EXPECT_EQ((*resp)[8], 1) << "function " << fc;
            ++answered;
        }
        EXPECT_EQ(answered, 252);
    }
    EXPECT_EQ(c.read(kp, 2), kpBefore);
    const std::string log = srv.log();
    EXPECT_EQ(countLines(log, "is not Modbus (0)"), 20u) << "one line per garbage connection, not per byte";
    // Each refused request logged once: two function-16 and one function-23 request had byte count 2 for 2 registers.
    EXPECT_EQ(countLines(log, "byte count 2 does not match 2 registers"), 3u);
    EXPECT_GE(countLines(log, "not served by this drive"), 252u);
    expectNormalService(srv, 0.625f);
}

TEST(ModbusAbuse, EveryAddressEdgeAndOutOfRangeWrite)
{
    SimDrive srv("--preset vmc");
    ASSERT_GT(srv.port(), 0);
    const auto map = registerMap();
    // Owner of each register for unit 1 (X, linear): mapped or not.
    std::vector<bool> mapped(65536, false);
    std::vector<std::pair<int, int>> blocks;
    for (const auto& [name, f] : map["fields"].items()) {
        blocks.push_back({f["address"].get<int>(), typeCount(f)});
    }
    for (const auto& p : map["parameters"])
        blocks.push_back({p["address"].get<int>(), 2});
    for (const auto& [a, n] : blocks)
        for (int k = a; k < a + n; ++k)
            mapped[static_cast<std::size_t>(k)] = true;
    Raw r(srv.port());
    int tid = 0, requests = 0;
    auto ask = [&](const Bytes& pdu, int unit = 1) {
        ++requests;
        r.send(frame(++tid, unit, pdu));
        const auto resp = r.response();
        return resp ? exceptionOf(*resp, pdu[0]) : -2;
    };
    // Reads at every edge: the block itself answers; one register before or after, when that register is
    // not mapped, is ILLEGAL DATA ADDRESS (2).
    for (const auto& [a, n] : blocks) {
        EXPECT_EQ(ask(readPdu(a, n)), 0) << "block at " << a;
        if (a > 0 && !mapped[static_cast<std::size_t>(a - 1)]) {
            EXPECT_EQ(ask(readPdu(a - 1, n + 1)), 2) << "read from " << a - 1;
        }
        if (a + n < 65536 && !mapped[static_cast<std::size_t>(a + n)]) {
            EXPECT_EQ(ask(readPdu(a, n + 1)), 2) << "read past " << a + n;
        }
    }
    // The ends of the register space and of the quantity.
    EXPECT_EQ(ask(readPdu(65535, 1)), 2);
    EXPECT_EQ(ask(readPdu(65535, 2)), 2); // past 65535
    EXPECT_EQ(ask(readPdu(65500, 125)), 2);
    EXPECT_EQ(ask(readPdu(0, 0)), 3);
    EXPECT_EQ(ask(readPdu(0, 126)), 3);
    EXPECT_EQ(ask(writePdu(65535, 1, 2, {0})), 2);
    EXPECT_EQ(ask(writePdu(65535, 2, 4, {0, 0})), 2); // past 65535
    // Unit ids without an axis: GATEWAY TARGET (11).
    for (int unit : {0, 4, 100, 247, 255})
        EXPECT_EQ(ask(readPdu(0, 1), unit), 11) << "unit " << unit;

    // Parameters of unit 1, raw, before the writes.
    const int first = map["parameters"].front()["address"].get<int>();
    const int last = map["parameters"].back()["address"].get<int>() + 2;
    Client c(srv.port());
    std::vector<std::uint16_t> before;
    for (int a = first; a < last; a += 100) {
        auto v = c.read(a, std::min(100, last - a));
        ASSERT_TRUE(v.has_value());
        before.insert(before.end(), v->begin(), v->end());
    }
    // Writes: half a parameter, a write starting one register early, values beyond min/max and NaN.
    int outOfRange = 0;
    for (const auto& p : map["parameters"]) {
        const int a = p["address"].get<int>();
        const std::string key = p["key"];
        EXPECT_EQ(ask(writePdu(a, 1, 2, {0x3f80})), 2) << key << ": half a float pair";
        EXPECT_EQ(ask(writePdu(a + 1, 1, 2, {0})), 2) << key << ": second half";
        if (!mapped[static_cast<std::size_t>(a - 1)]) {
            EXPECT_EQ(ask(writePdu(a - 1, 3, 6, {0, 0x3f80, 0})), 2) << key;
        }
        const bool writable = p["writable"].get<bool>();
        const bool onX = !p.contains("axis_kinds") || p["axis_kinds"].dump().find("linear") != std::string::npos;
        const int expectRange = writable && onX ? 3 : 2; // read-only or absent: ILLEGAL DATA ADDRESS
        std::vector<float> bad = {std::nanf(""), std::numeric_limits<float>::infinity()};
        const double lo = p["min"].get<double>(), hi = p["max"].get<double>();
        if (std::isfinite(hi) && hi < 1e37)
            bad.push_back(static_cast<float>(hi + std::max(1.0, std::abs(hi))));
        if (std::isfinite(lo) && lo > -1e37)
            bad.push_back(static_cast<float>(lo - std::max(1.0, std::abs(lo))));
        for (float v : bad) {
            EXPECT_EQ(ask(writePdu(a, 2, 4, f32Words(v))), expectRange) << key << " = " << v;
            ++outOfRange;
        }
    }
    std::vector<std::uint16_t> after;
    for (int a = first; a < last; a += 100) {
        auto v = c.read(a, std::min(100, last - a));
        ASSERT_TRUE(v.has_value());
        after.insert(after.end(), v->begin(), v->end());
    }
    EXPECT_EQ(after, before) << "a refused write changed a parameter";
    EXPECT_GE(outOfRange, 4 * 30);
    std::cout << "[ figures ] " << requests << " requests at address edges, " << outOfRange
              << " out-of-range writes, all refused\n";
    expectNormalService(srv, 0.625f);
}

TEST(ModbusAbuse, HeldAndSlowConnectionsDoNotBlockOtherClients)
{
    SimDrive srv("--preset vmc");
    ASSERT_GT(srv.port(), 0);
    // 200 connections held open and silent.
    std::vector<std::unique_ptr<Raw>> held;
    for (int k = 0; k < 200; ++k) {
        held.push_back(std::make_unique<Raw>(srv.port()));
        ASSERT_TRUE(held.back()->ok()) << "connect " << k;
    }
    {
        Client c(srv.port());
        ASSERT_TRUE(c.connected());
        int ok = 0;
        for (int k = 0; k < 15; ++k)
            ok += c.read(0, 1).has_value() ? 1 : 0;
        EXPECT_EQ(ok, 15) << "with 200 idle connections held";
    }
    // Two slow senders: one byte every 0.4 s and one byte a second, for 3 s; meanwhile another client
    // reads as fast as it can with a 1 s timeout and never misses.
    std::atomic<int> slowClosed{0};
    auto slow = [&](std::chrono::milliseconds every) {
        Raw r(srv.port());
        const Bytes whole = frame(1, 1, readPdu(0, 1));
        const auto t0 = Clock::now();
        for (std::size_t i = 0; i < whole.size() && secondsSince(t0) < 3.0; ++i) {
            if (!r.send(Bytes{whole[i]})) {
                ++slowClosed;
                return;
            }
            bool closed = false;
            r.recvN(1, every, &closed);
            if (closed) {
                ++slowClosed;
                return;
            }
        }
    };
    std::thread s1(slow, 400ms), s2(slow, 1000ms);
    int reads = 0, failed = 0;
    {
        Client c(srv.port());
        const auto t0 = Clock::now();
        while (secondsSince(t0) < 3.0) {
            if (c.read(0, 1))
                ++reads;
            else
                ++failed;
            std::this_thread::sleep_for(20ms);
        }
    }
    s1.join();
    s2.join();
    EXPECT_EQ(failed, 0);
    EXPECT_GE(reads, 15);
    EXPECT_EQ(slowClosed.load(), 2) << "the slow senders are closed by the frame deadline (1 s)";
    std::cout << "[ figures ] 200 held connections; during 3 s of two slow senders: " << reads << " reads, " << failed
              << " failed\n";
    held.clear();
    expectNormalService(srv, 0.625f);
}

TEST(ModbusAbuse, FiveThousandRapidConnects)
{
    SimDrive srv("--preset vmc");
    ASSERT_GT(srv.port(), 0);
    const auto t0 = Clock::now();
    int connected = 0;
    for (int k = 0; k < 5000 && secondsSince(t0) < 30.0; ++k) {
        Raw r(srv.port());
        connected += r.ok() ? 1 : 0;
        if (k % 10 == 0)
            r.send(frame(k, 1, readPdu(0, 1))); // some ask and leave before the answer
    }
    const double s = secondsSince(t0);
    EXPECT_EQ(connected, 5000);
    EXPECT_LT(s, 30.0);
    std::cout << "[ figures ] 5000 connects in " << s << " s (" << 5000 / s << " per second)\n";
    expectNormalService(srv, 0.625f);
    // The log is not flooded: connection lines are rate-limited (20 per second plus one summary line,
    // written when the one-second window closes).
    std::this_thread::sleep_for(1200ms);
    const std::string log = srv.log();
    const auto lines = static_cast<double>(countLines(log, "\n"));
    EXPECT_LT(lines, 21.0 * (s + 3.0) + 50.0) << "log lines: " << lines;
    EXPECT_NE(log.find("not logged one by one"), std::string::npos);
}

TEST(ModbusAbuse, RefusedTestBlockNeverStarts)
{
    SimDrive srv("--preset vmc");
    ASSERT_GT(srv.port(), 0);
    const auto map = registerMap();
    const int type = fieldAddress("test.type"), amp = fieldAddress("test.step_velocity"),
              dur = fieldAddress("test.record"), code = fieldAddress("command.code"),
              state = fieldAddress("status.state"), echo = fieldAddress("status.command_token_echo");
    const int stepCode = map["enums"]["test_type"]["step"].get<int>();
    const int startCode = map["enums"]["command"]["start_test"].get<int>();
    const int clearCode = map["enums"]["command"]["clear"].get<int>();
    const int idle = map["enums"]["state"]["idle"].get<int>(), running = map["enums"]["state"]["running"].get<int>(),
              completed = map["enums"]["state"]["completed"].get<int>();
    Client c(srv.port());
    ASSERT_TRUE(c.connected());
    auto token = [&]() { return static_cast<std::uint16_t>((*c.read(echo, 1))[0] + 1); };
    auto command = [&](int what) { return c.write(code, {static_cast<std::uint16_t>(what), token()}); };
    auto waitIdleOrDone = [&]() {
        for (int k = 0; k < 200; ++k) {
            const int s = (*c.read(state, 1))[0];
            if (s != running)
                return s;
            std::this_thread::sleep_for(10ms);
        }
        return running;
    };
    // A valid 0.05 s velocity step of 1 rad/s starts and completes.
    ASSERT_TRUE(c.write(type, {static_cast<std::uint16_t>(stepCode)}));
    ASSERT_TRUE(c.write(amp, f64Words(1.0)));
    ASSERT_TRUE(c.write(dur, f64Words(0.05)));
    ASSERT_TRUE(command(startCode)) << modbus_strerror(c.lastErrno());
    EXPECT_EQ(waitIdleOrDone(), completed);
    ASSERT_TRUE(command(clearCode));
    // NaN, Inf and a byte-count mismatch on the amplitude are refused; start_test is refused after each
    // (exception 3), the drive stays idle, the amplitude reads back 1.0.
    Raw r(srv.port());
    const std::vector<std::pair<std::string, Bytes>> refusals = {
        {"NaN", writePdu(amp, 4, 8, f64Words(std::nan("")))},
        {"Inf", writePdu(amp, 4, 8, f64Words(std::numeric_limits<double>::infinity()))},
        {"-Inf", writePdu(amp, 4, 8, f64Words(-std::numeric_limits<double>::infinity()))},
        {"byte count 6 for 4 registers", writePdu(amp, 4, 6, {0x4000, 0, 0})},
    };
    int tid = 1;
    for (const auto& [what, pdu] : refusals) {
        r.send(frame(tid++, 1, pdu));
        const auto resp = r.response();
        ASSERT_TRUE(resp.has_value()) << what;
        EXPECT_EQ(exceptionOf(*resp, 0x10), 3) << what;
        const std::uint16_t t = token();
        r.send(frame(tid++, 1, writePdu(code, 2, 4, {static_cast<std::uint16_t>(startCode), t})));
        const auto start = r.response();
        ASSERT_TRUE(start.has_value()) << what;
        EXPECT_EQ(exceptionOf(*start, 0x10), 3) << "start_test after a refused amplitude (" << what << ")";
        EXPECT_EQ((*c.read(state, 1))[0], idle) << what;
        EXPECT_EQ(c.read(amp, 4), f64Words(1.0)) << what;
    }
    // The refusal is in status.message and the log.
    const std::string text = statusMessage(c);
    EXPECT_NE(text.find("refused earlier"), std::string::npos) << text;
    EXPECT_EQ(countLines(srv.log(), "test configuration refused earlier"), refusals.size());
    // A valid amplitude written again: the same start is accepted.
    ASSERT_TRUE(c.write(amp, f64Words(2.0)));
    ASSERT_TRUE(command(startCode)) << modbus_strerror(c.lastErrno());
    EXPECT_EQ(waitIdleOrDone(), completed);
    EXPECT_EQ(countLines(srv.log(), "test step started"), 2u);
    expectNormalService(srv, 0.625f);
}

// Map version 2 (docs/modbus.md "One quantity per register"): a raw client that knows only the JSON map writes a
// current step into test.current_step; the velocity-step register beside it, holding 7 rad/s, is not read as
// amperes. The server's refusal names the current it took from test.current_step.
TEST(ModbusAbuse, ACurrentStepIsReadFromItsOwnRegister)
{
    SimDrive srv("--preset vmc");
    ASSERT_GT(srv.port(), 0);
    const auto map = registerMap();
    const int type = fieldAddress("test.type"), velocity = fieldAddress("test.step_velocity"),
              current = fieldAddress("test.current_step"), dur = fieldAddress("test.record"),
              code = fieldAddress("command.code"), state = fieldAddress("status.state"),
              echo = fieldAddress("status.command_token_echo"), rate = fieldAddress("status.trace_rate_hz");
    EXPECT_NE(current, velocity);
    const int startCode = map["enums"]["command"]["start_test"].get<int>();
    const int completed = map["enums"]["state"]["completed"].get<int>(),
              running = map["enums"]["state"]["running"].get<int>();
    Client c(srv.port());
    ASSERT_TRUE(c.connected());
    auto start = [&]() {
        const auto t = static_cast<std::uint16_t>((*c.read(echo, 1))[0] + 1);
        return c.write(code, {static_cast<std::uint16_t>(startCode), t});
    };
    ASSERT_TRUE(c.write(type, {static_cast<std::uint16_t>(map["enums"]["test_type"]["current_step"].get<int>())}));
    ASSERT_TRUE(c.write(velocity, f64Words(7.0)));
    ASSERT_TRUE(c.write(current, f64Words(45.0)));
    ASSERT_TRUE(c.write(dur, f64Words(0.004)));
    EXPECT_FALSE(start()); // 45 A: above the drive's limit (the vmc motor's rated 15.3 A)
    const std::string text = statusMessage(c);
    EXPECT_NE(text.find("current step 45 A"), std::string::npos) << text;
    ASSERT_TRUE(c.write(current, f64Words(2.0)));
    ASSERT_TRUE(start()) << modbus_strerror(c.lastErrno());
    int s = running;
    for (int k = 0; k < 200 && s == running; ++k) {
        std::this_thread::sleep_for(10ms);
        s = (*c.read(state, 1))[0];
    }
    EXPECT_EQ(s, completed);
    // A current step traces at the current-loop rate (vmc: 16 kHz), a velocity step at 4 kHz.
    const auto r = c.read(rate, 4);
    ASSERT_TRUE(r.has_value());
    const auto sixteen = f64Words(16000.0);
    EXPECT_EQ(*r, sixteen);
    EXPECT_EQ(c.read(velocity, 4), f64Words(7.0));
    EXPECT_EQ(countLines(srv.log(), "test current_step started"), 1u);
}
