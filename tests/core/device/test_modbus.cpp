// SPDX-License-Identifier: GPL-3.0-or-later
// The Modbus TCP drive against axistune-simdrive's server run in-process on a thread, over a real
// loopback socket. The embedded SimulatedDrive with the same seed is the independent reference.
#include "core/device/ModbusDrive.h"
#include "core/device/SimDriveServer.h"
#include "core/device/TestRunner.h"

#include <chrono>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <modbus/modbus.h>
#include <mutex>
#include <thread>

#include "tests/core/device/DriveTestUtil.h"
#include "tests/core/device/ServerThread.h"

using namespace axistune;
using namespace axistune::device;
using axistune::devtest::ServerThread;

namespace {

SimDriveServerOptions options(const std::string& preset = "vmc")
{
    SimDriveServerOptions o;
    o.preset = preset;
    o.seed = 7;
    return o;
}

std::unique_ptr<Drive> open(const std::string& uri)
{
    auto d = connectAny({uri, 7});
    EXPECT_TRUE(d.ok()) << (d.ok() ? "" : d.error().detail);
    return d.ok() ? std::move(d).value() : nullptr;
}

/// Polls until the test leaves Running; bounded in count and time.
Result<TestStatus> finish(Drive& d, double maxSeconds = 30.0)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(maxSeconds);
    for (int i = 0; i < 100000 && std::chrono::steady_clock::now() < end; ++i) {
        auto s = d.pollTest();
        if (!s || s->state != TestState::Running)
            return s;
    }
    return makeError(ErrorCode::Internal, "test did not finish in time");
}

TestRequest step(const std::string& axis, double amplitude, double duration)
{
    TestRequest r;
    r.axis = axis;
    auto& s = r.test.emplace<StepTest>();
    s.velocityRadS = amplitude;
    s.recordS = duration;
    return r;
}

/// A raw libmodbus client: the drive's answers without ModbusDrive in between.
struct RawClient {
    modbus_t* ctx;
    RawClient(int port, int unit) : ctx(modbus_new_tcp("127.0.0.1", port))
    {
        modbus_set_response_timeout(ctx, 1, 0);
        EXPECT_EQ(modbus_connect(ctx), 0);
        modbus_set_slave(ctx, unit);
    }
    ~RawClient() { modbus_close(ctx), modbus_free(ctx); }
};

} // namespace

TEST(ModbusDrive, IdentityAndParametersMatchTheEmbeddedDrive)
{
    ServerThread srv(options("dd-table"));
    auto remote = open(srv.uri());
    auto local = open("sim:dd-table");
    ASSERT_TRUE(remote && local);
    auto a = remote->identify(), b = local->identify();
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->axes, b->axes);
    EXPECT_EQ(a->machine, b->machine);
    for (const auto& axis : b->axes) {
        auto pr = remote->readParameters(axis, {});
        auto pl = local->readParameters(axis, {});
        ASSERT_TRUE(pr.ok() && pl.ok()) << (pr.ok() ? "" : pr.error().detail);
        ASSERT_EQ(pr->size(), pl->size()) << axis;
        for (const auto& [k, v] : *pl)
            EXPECT_EQ(pr->at(k), static_cast<double>(static_cast<float>(v))) << axis << " " << k; // float32 on the wire
    }
}

TEST(ModbusDrive, TraceOverModbusIsTheEmbeddedTraceBitForBit)
{
    ServerThread srv(options("vmc"));
    auto remote = open(srv.uri());
    auto local = open("sim:vmc");
    ASSERT_TRUE(remote && local);
    const auto traces = devtest::tracesOfEach({remote.get(), local.get()}, step("X", 20.0, 0.1));
    const auto& tr = traces[0];
    const auto& tl = traces[1];
    ASSERT_TRUE(tr && tl);
    ASSERT_EQ(tr->channels.size(), tl->channels.size());
    ASSERT_GT(tl->size(), 100u);
    EXPECT_EQ(tr->metadata, tl->metadata);
    for (std::size_t c = 0; c < tl->channels.size(); ++c) {
        EXPECT_EQ(tr->channels[c].name, tl->channels[c].name);
        EXPECT_EQ(tr->channels[c].data, tl->channels[c].data) << tl->channels[c].name; // float64 on the wire: exact
    }
}

TEST(ModbusDrive, OutOfLimitWriteIsRefusedByClientAndDrive)
{
    ServerThread srv(options());
    auto d = open(srv.uri());
    ASSERT_TRUE(d);
    auto* md = dynamic_cast<ModbusDrive*>(d.get());
    auto old = d->readParameters("X", std::vector<std::string>{"velocity.kp"});
    ASSERT_TRUE(old.ok());
    const auto before = md->requestCount();
    auto st = d->writeParameters("X", {{"velocity.kp", 2e5}}); // limit 1e5
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(st.error().detail.find("not sent"), std::string::npos) << st.error().detail;
    EXPECT_EQ(md->requestCount(), before); // nothing went out
    // The drive itself refuses the same value with ILLEGAL DATA VALUE.
    const auto* p = md->registerMap().parameter("velocity.kp");
    std::uint16_t w[2];
    encodeF32(2e5f, WordOrder::HighWordFirst, w);
    RawClient raw(srv.port(), 1);
    EXPECT_EQ(modbus_write_registers(raw.ctx, p->address, 2, w), -1);
    EXPECT_EQ(errno, EMBXILVAL);
    auto v = d->readParameters("X", std::vector<std::string>{"velocity.kp"});
    ASSERT_TRUE(v.ok());
    EXPECT_EQ(v->at("velocity.kp"), old->at("velocity.kp")); // unchanged
    // Half a float32 pair is refused too (ILLEGAL DATA ADDRESS), and so is an unknown unit id.
    EXPECT_EQ(modbus_write_register(raw.ctx, p->address, 0x3F80), -1);
    EXPECT_EQ(errno, EMBXILADD);
    modbus_set_slave(raw.ctx, 9);
    std::uint16_t r[1];
    EXPECT_EQ(modbus_read_registers(raw.ctx, 0, 1, r), -1);
    EXPECT_EQ(errno, EMBXGTAR);
}

TEST(ModbusDrive, WriteDuringTestIsRefusedAndCommandsAreNotRunTwice)
{
    auto o = options();
    o.pace = 1.0; // real time: the test lasts
    ServerThread srv(o);
    auto d = open(srv.uri());
    ASSERT_TRUE(d);
    ASSERT_TRUE(d->startTest(step("X", 5.0, 3.0)).ok());
    auto st = d->writeParameters("X", {{"velocity.kp", 0.5}});
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::Busy); // the client knows a test runs
    auto* md = dynamic_cast<ModbusDrive*>(d.get());
    RawClient raw(srv.port(), 1);
    std::uint16_t w[2];
    encodeF32(0.5f, WordOrder::HighWordFirst, w);
    EXPECT_EQ(modbus_write_registers(raw.ctx, md->registerMap().parameter("velocity.kp")->address, 2, w), -1);
    EXPECT_EQ(errno, EMBXSBUSY); // and so does the drive
    // A start command repeated with the token of the running test is answered, not executed again.
    std::uint16_t echo[1];
    const int tokenAddr = md->registerMap().field("status.command_token_echo").address;
    ASSERT_EQ(modbus_read_registers(raw.ctx, tokenAddr, 1, echo), 1);
    const std::uint16_t cmd[2] = {static_cast<std::uint16_t>(md->registerMap().code("command", "start_test")), echo[0]};
    EXPECT_EQ(modbus_write_registers(raw.ctx, md->registerMap().field("command.code").address, 2, cmd), 2);
    const std::uint16_t again[2] = {cmd[0], static_cast<std::uint16_t>(echo[0] + 1)};
    EXPECT_EQ(modbus_write_registers(raw.ctx, md->registerMap().field("command.code").address, 2, again), -1);
    EXPECT_EQ(errno, EMBXSBUSY); // a new token is a new command: refused while the test runs
    ASSERT_TRUE(d->abortTest().ok());
    auto s = d->pollTest();
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->state, TestState::Aborted);
}

TEST(ModbusDrive, SilentClientMakesTheDriveStopAndRestoreByItself)
{
    auto o = options();
    o.pace = 1.0;
    o.safety.watchdogS = 0.5;
    ServerThread srv(o);
    auto d = open(srv.uri());
    ASSERT_TRUE(d);
    // With heartbeats (pollTest, every 200 ms) a 1.2 s test outlives the 0.5 s watchdog.
    ASSERT_TRUE(d->startTest(step("X", 5.0, 1.2)).ok());
    auto ok = finish(*d, 10.0);
    ASSERT_TRUE(ok.ok()) << ok.error().detail << "\n" << srv.log();
    EXPECT_EQ(ok->state, TestState::Completed) << ok->detail;
    // Silent: the drive stops the test and restores trace.divider (the test set it to 4).
    auto req = step("X", 5.0, 5.0);
    req.traceDivider = 4;
    ASSERT_TRUE(d->startTest(req).ok());
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    const std::string log = srv.log();
    EXPECT_NE(log.find("fault heartbeat_lost"), std::string::npos) << log;
    auto s = d->pollTest();
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->state, TestState::Aborted);
    EXPECT_NE(s->detail.find("heartbeat_lost"), std::string::npos) << s->detail;
    auto v = d->readParameters("X", std::vector<std::string>{"trace.divider"});
    ASSERT_TRUE(v.ok());
    EXPECT_EQ(v->at("trace.divider"), 1.0);
}

TEST(ModbusDrive, SafetyLimitsRefuseOrStopTests)
{
    auto o = options();
    o.safety.speedLimitRadS = 100.0;
    o.safety.amplitudeLimitPct = 1.0; // 1 % of rated torque: any real step trips
    ServerThread srv(o);
    auto d = open(srv.uri());
    ASSERT_TRUE(d);
    auto st = d->startTest(step("X", 150.0, 0.1));
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(st.error().detail.find("speed limit"), std::string::npos) << st.error().detail;
    TestRequest jog;
    jog.axis = "X";
    auto& jogTest = jog.test.emplace<JogTest>();
    jogTest.distance = 0.8; // beyond the ±0.5 m window
    jogTest.velocity = 0.01;
    jogTest.acceleration = 1.0;
    st = d->startTest(jog);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("travel window"), std::string::npos) << st.error().detail;
    auto req = step("X", 50.0, 0.5);
    req.traceDivider = 3;
    ASSERT_TRUE(d->startTest(req).ok());
    auto s = finish(*d);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->state, TestState::Faulted);
    EXPECT_NE(s->detail.find("amplitude_limit"), std::string::npos) << s->detail;
    auto v = d->readParameters("X", std::vector<std::string>{"trace.divider"});
    ASSERT_TRUE(v.ok());
    EXPECT_EQ(v->at("trace.divider"), 1.0); // pre-test value back
}

TEST(ModbusDrive, FollowingErrorTripsAJog)
{
    auto o = options();
    o.safety.followingErrorLimit = 1e-6; // 1 µm: a 50 mm/s jog lags more
    ServerThread srv(o);
    auto d = open(srv.uri());
    ASSERT_TRUE(d);
    TestRequest jog;
    jog.axis = "X";
    auto& jogTest = jog.test.emplace<JogTest>();
    jogTest.distance = 0.05;
    jogTest.velocity = 0.05;
    jogTest.acceleration = 1.0;
    jogTest.dwellS = 0.05;
    ASSERT_TRUE(d->startTest(jog).ok());
    auto s = finish(*d);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->state, TestState::Faulted);
    EXPECT_NE(s->detail.find("following_error"), std::string::npos) << s->detail;
}

TEST(ModbusDrive, InjectedFaultsGiveTheirOwnErrorsAndNeverHang)
{
    using Clock = std::chrono::steady_clock;
    {
        auto o = options();
        o.faults.illegalAddress = true;
        ServerThread srv(o);
        auto d = open(srv.uri());
        ASSERT_TRUE(d);
        auto v = d->readParameters("X", {});
        ASSERT_FALSE(v.ok());
        EXPECT_EQ(v.error().code, ErrorCode::Device);
        EXPECT_NE(v.error().detail.find("ILLEGAL DATA ADDRESS"), std::string::npos) << v.error().detail;
    }
    {
        auto o = options();
        o.faults.delayMs = 400;
        ServerThread srv(o);
        const auto t0 = Clock::now();
        auto d = connectAny({srv.uri(200), 7});
        const double s = std::chrono::duration<double>(Clock::now() - t0).count();
        ASSERT_FALSE(d.ok());
        EXPECT_EQ(d.error().code, ErrorCode::Device);
        EXPECT_NE(d.error().detail.find("no answer within 200 ms"), std::string::npos) << d.error().detail;
        EXPECT_LT(s, 3.0);
    }
    {
        auto o = options();
        o.faults.dropAfterRequests = 2; // every connection dies at its 2nd request: reconnects run out
        ServerThread srv(o);
        auto d = open(srv.uri());
        ASSERT_TRUE(d);
        Error last;
        int failures = 0;
        for (int i = 0; i < 20 && failures == 0; ++i) {
            auto v = d->readParameters("X", {});
            if (!v.ok())
                last = v.error(), ++failures;
        }
        ASSERT_EQ(failures, 1);
        EXPECT_EQ(last.code, ErrorCode::Device);
        EXPECT_NE(last.detail.find("connection lost"), std::string::npos) << last.detail;
        EXPECT_NE(last.detail.find("giving up"), std::string::npos) << last.detail;
        EXPECT_NE(srv.log().find("fault drop-after:2"), std::string::npos);
    }
    {
        auto o = options();
        o.faults.driveFaultAfterS = 0.05;
        ServerThread srv(o);
        auto d = open(srv.uri());
        ASSERT_TRUE(d);
        ASSERT_TRUE(d->startTest(step("X", 5.0, 0.5)).ok());
        auto s = finish(*d);
        ASSERT_TRUE(s.ok());
        EXPECT_EQ(s->state, TestState::Faulted);
        EXPECT_NE(s->detail.find("drive_fault"), std::string::npos) << s->detail;
    }
}

TEST(ModbusDrive, ReconnectsAndRetriesReadsWhenTheLinkDrops)
{
    auto o = options();
    o.faults.dropAfterRequests = 120; // a trace readout needs a few hundred requests: ~3 drops
    ServerThread srv(o);
    auto remote = open(srv.uri());
    auto local = open("sim:vmc");
    ASSERT_TRUE(remote && local);
    const auto traces = devtest::tracesOfEach({remote.get(), local.get()}, step("X", 20.0, 0.1));
    const auto& tr = traces[0];
    const auto& tl = traces[1];
    ASSERT_TRUE(tr && tl);
    for (std::size_t c = 0; c < tl->channels.size(); ++c)
        EXPECT_EQ(tr->channels[c].data, tl->channels[c].data) << tl->channels[c].name;
    EXPECT_NE(srv.log().find("fault drop-after:120"), std::string::npos);
}

TEST(ModbusDrive, UriErrorsNameThePart)
{
    for (const std::string u : {"modbus://127.0.0.1", "modbus://127.0.0.1:99999", "modbus://127.0.0.1:502?timeout_ms=1",
                                "modbus://127.0.0.1:502?colour=red"}) {
        auto r = parseModbusUri(u);
        ASSERT_FALSE(r.ok()) << u;
        EXPECT_EQ(r.error().code, ErrorCode::BadInput);
        EXPECT_NE(r.error().detail.find(u), std::string::npos);
    }
    auto ok = parseModbusUri("modbus://127.0.0.1:1502?timeout_ms=250");
    ASSERT_TRUE(ok.ok());
    EXPECT_EQ(ok->port, 1502);
    EXPECT_EQ(ok->timeoutMs, 250);
    EXPECT_EQ(modbusExceptionText(3).substr(0, 34), "exception 3 ILLEGAL DATA VALUE: va");
}

TEST(ModbusDrive, FrfOverModbusIsTheEmbeddedFrf)
{
    ServerThread srv(options("dd-table"));
    auto remote = open(srv.uri());
    auto local = open("sim:dd-table");
    ASSERT_TRUE(remote && local);
    TestRequest r;
    r.axis = local->identify()->axes.front();
    auto& frf = r.test.emplace<FrfTest>();
    frf.method = FrfMethod::MultiSweep;
    frf.fminHz = 100.0;
    frf.fmaxHz = 3000.0;
    frf.points = 6;
    frf.amplitudePct = 5.0;
    const std::vector<FrfMeasurement> m{devtest::runFrf(*remote, r), devtest::runFrf(*local, r)};
    const auto& a = m[0].frf;
    const auto& b = m[1].frf;
    ASSERT_EQ(a.size(), b.size());
    ASSERT_GE(b.size(), 5u);
    for (std::size_t i = 0; i < b.size(); ++i) {
        EXPECT_EQ(a.freqHz[i], b.freqHz[i]);
        EXPECT_LE(std::abs(a.h[i] - b.h[i]), 1e-9 * std::abs(b.h[i])) << b.freqHz[i];
        EXPECT_EQ(a.valid[i], b.valid[i]);
        EXPECT_EQ(std::isnan(a.coherence[i]), std::isnan(b.coherence[i]));
    }
    EXPECT_EQ(a.metadata, b.metadata);
    EXPECT_EQ(m[0].motionTimeS, m[1].motionTimeS);
    ASSERT_EQ(m[0].sweep.blocks.size(), m[1].sweep.blocks.size());
    for (std::size_t k = 0; k < m[1].sweep.blocks.size(); ++k) {
        EXPECT_EQ(m[0].sweep.blocks[k].sample, m[1].sweep.blocks[k].sample);
        EXPECT_EQ(m[0].sweep.blocks[k].response, m[1].sweep.blocks[k].response);
    }
    EXPECT_EQ(m[0].sweep.metadata, m[1].sweep.metadata);
}

TEST(ModbusDrive, FrfAmplitudeAboveTheDriveLimitIsRefused)
{
    auto o = options("dd-table");
    o.safety.amplitudeLimitPct = 2.0;
    ServerThread srv(o);
    auto d = open(srv.uri());
    ASSERT_TRUE(d);
    TestRequest r;
    r.axis = d->identify()->axes.front();
    auto& frf = r.test.emplace<FrfTest>();
    frf.amplitudePct = 5.0;
    auto st = d->startTest(r);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(st.error().detail.find("excitation amplitude 5 % of the rated torque above the drive's limit 2 %"),
              std::string::npos)
        << st.error().detail;
}

// Current step (TestType::CurrentStep) over Modbus: the trace at the current-loop rate, read back at
// the rate the drive reports (status.trace_rate_hz), equal to the embedded drive's trace bit for bit.
TEST(ModbusDrive, CurrentStepOverModbusIsTheEmbeddedTrace)
{
    ServerThread srv(options("vmc"));
    auto remote = open(srv.uri());
    auto local = open("sim:vmc");
    ASSERT_TRUE(remote && local);
    TestRequest r;
    r.axis = "Y";
    auto& current = r.test.emplace<CurrentStepTest>();
    current.currentA = 4.0;
    current.recordS = 0.005;
    const auto traces = devtest::tracesOfEach({remote.get(), local.get()}, r);
    const auto& tr = traces[0];
    const auto& tl = traces[1];
    ASSERT_TRUE(tr && tl);
    EXPECT_EQ(tl->size(), 80u); // 5 ms at 62.5 µs
    EXPECT_EQ(tl->metadata.number("fs_Hz").value(), 16000.0);
    EXPECT_EQ(tr->metadata, tl->metadata);
    ASSERT_EQ(tr->channels.size(), tl->channels.size());
    for (std::size_t c = 0; c < tl->channels.size(); ++c) {
        EXPECT_EQ(tr->channels[c].name, tl->channels[c].name);
        EXPECT_EQ(tr->channels[c].data, tl->channels[c].data) << tl->channels[c].name;
    }
    // The raw status register says the same rate.
    RawClient raw(srv.port(), 2);
    std::uint16_t w[4];
    ASSERT_EQ(modbus_read_registers(raw.ctx, 116, 4, w), 4);
    std::uint64_t bits = 0;
    for (int k = 0; k < 4; ++k)
        bits = (bits << 16) | w[k];
    double rate;
    std::memcpy(&rate, &bits, sizeof rate);
    EXPECT_EQ(rate, 16000.0);
}

TEST(ModbusDrive, CurrentStepRefusedByTheDriveAndByTheServer)
{
    auto o = options("vmc");
    o.safety.amplitudeLimitPct = 20.0; // 20 % of 15.3 A · 0.50911 N·m/A = 1.558 N·m → at most 3.06 A
    ServerThread srv(o);
    auto d = open(srv.uri());
    ASSERT_TRUE(d);
    TestRequest r;
    r.axis = "X";
    auto& current = r.test.emplace<CurrentStepTest>();
    current.currentA = 4.0;
    current.recordS = 0.002;
    auto st = d->startTest(r);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(st.error().detail.find("current step 4 A means 2.036 Nm, above the drive's limit 20 %"), std::string::npos)
        << st.error().detail;
    // Inside the server's limit but beyond the record length of the drive: the drive's own message.
    current.currentA = 3.0;
    current.recordS = 0.06;
    st = d->startTest(r);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("(0, 0.05] s"), std::string::npos) << st.error().detail;
    current.recordS = 0.001; // short: the velocity loop brakes the motor afterwards below the 20 % too
    ASSERT_TRUE(d->startTest(r).ok());
    auto s = finish(*d);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->state, TestState::Completed) << s->detail;
}

// A second client after a first one (a new CLI process, a reconnect of the GUI) continues the drive's
// command-token sequence: its start_test runs a new test instead of being answered as a retry of the
// first client's command (which left the first test's trace in place).
TEST(ModbusDrive, ANewClientRunsItsOwnTestNotTheLastClientsRetry)
{
    ServerThread srv(options("vmc"));
    {
        auto first = open(srv.uri());
        ASSERT_TRUE(first);
        ASSERT_TRUE(first->startTest(step("X", 5.0, 0.02)).ok());
        auto s = finish(*first);
        ASSERT_TRUE(s.ok() && s->state == TestState::Completed);
    }
    auto second = open(srv.uri());
    ASSERT_TRUE(second);
    TestRequest r;
    r.axis = "X";
    auto& current = r.test.emplace<CurrentStepTest>();
    current.currentA = 3.0;
    current.recordS = 0.002;
    ASSERT_TRUE(second->startTest(r).ok());
    auto s = finish(*second);
    ASSERT_TRUE(s.ok() && s->state == TestState::Completed);
    auto t = second->readTrace();
    ASSERT_TRUE(t.ok()) << t.error().detail;
    EXPECT_EQ(t->metadata.number("fs_Hz").value(), 16000.0); // the current step's trace, not the velocity step's (4000)
    EXPECT_EQ(t->size(), 32u);
    // And a refusal reaches the second client too.
    current.currentA = 45.0;
    auto st = second->startTest(r);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("40 A"), std::string::npos) << st.error().detail;
}

// The vibration-suppression parameters (suppression.*, docs/modbus.md) and a jog's jerk limit (carried
// in test.jog_jerk, a register of its own since map version 2) reach the served drive: the filtered rectangular-jerk jog on the two-inertia
// bench is the embedded drive's bit for bit (values chosen exact in float32), and a filter mode that
// does not match the feedback is refused over the wire with a message naming both parameters.
TEST(ModbusDrive, SuppressionFilterAndJerkLimitedJogAreTheEmbeddedOnes)
{
    auto o = options("two-inertia");
    // 0.01 (axis units) is 10 mm on a linear axis but only 0.6° here: the bench's motor lags its command
    // by a few degrees at 200 rev/s² (the thesis's Fig. 5.12 shows 3°), so allow 0.2 rad.
    o.safety.followingErrorLimit = 0.2;
    ServerThread srv(o);
    auto remote = open(srv.uri());
    auto local = open("sim:two-inertia");
    ASSERT_TRUE(remote && local);
    const model::ParameterValues filter{{"suppression.mode", 1}, {"suppression.f0", 22.0}, {"suppression.zeta", 0.09375}};
    TestRequest jog;
    jog.axis = "A";
    auto& jogTest = jog.test.emplace<JogTest>();
    jogTest.distance = 16.0;
    jogTest.velocity = 62.5;
    jogTest.acceleration = 1250.0;
    jogTest.jerk = 125000.0;
    jogTest.dwellS = 0.05;
    for (Drive* d : {remote.get(), local.get()}) {
        auto bad = d->writeParameters("A", {{"suppression.mode", 2}, {"suppression.tau", 0.015625}});
        ASSERT_FALSE(bad.ok());
        EXPECT_NE(bad.error().detail.find("suppression.mode"), std::string::npos) << bad.error().detail;
        EXPECT_NE(bad.error().detail.find("position.feedback"), std::string::npos) << bad.error().detail;
        ASSERT_TRUE(d->writeParameters("A", filter).ok());
        auto back = d->readParameters("A", std::vector<std::string>{"suppression.mode", "suppression.f0", "suppression.zeta"});
        ASSERT_TRUE(back.ok());
        EXPECT_EQ(*back, filter);
        ASSERT_TRUE(d->startTest(jog).ok());
        auto s = finish(*d);
        ASSERT_TRUE(s.ok()) << s.error().detail;
        ASSERT_EQ(s->state, TestState::Completed) << s->detail;
    }
    auto tr = remote->readTrace();
    auto tl = local->readTrace();
    ASSERT_TRUE(tr.ok() && tl.ok());
    const auto* cmd = tl->channel("position_cmd_rad");
    ASSERT_TRUE(cmd);
    // The jerk-limited move: from 0 to 16 rad (the command holds the end after the move).
    EXPECT_NEAR(cmd->data.back() - cmd->data.front(), 16.0, 1e-9);
    for (const char* name : {"position_cmd_rad", "motor_pos_rad", "table_pos_rad"})
        EXPECT_EQ(tr->channel(name)->data, tl->channel(name)->data) << name;
}

namespace axistune::device {
namespace {

// The drive describes itself over Modbus (docs/modbus.md "Capabilities, limits and plans"): the limits
// are the server's own (its safety limits narrow the embedded drive's), read from registers, not the
// client's copy of the simulator's constants.
TEST(ModbusDescribe, LimitsAreTheServersOwn)
{
    auto o = options("vmc");
    o.safety.amplitudeLimitPct = 20.0;
    o.safety.speedLimitRadS = 300.0;
    o.safety.travelLimit = 0.25;
    devtest::ServerThread server(o);
    auto d = open(server.uri());
    ASSERT_TRUE(d);
    auto local = connect({"sim:vmc", 7});
    ASSERT_TRUE(local.ok());
    const auto embedded = (*local)->limits("X").value();
    auto lim = d->limits("X");
    ASSERT_TRUE(lim.ok()) << lim.error().detail;
    EXPECT_EQ(lim->frfAmplitudeMaxPct, 20.0); // below the embedded drive's
    EXPECT_EQ(lim->motorSpeedMaxRadS, 300.0);
    EXPECT_EQ(lim->travelWindow, 0.25);
    // 20 % of the rated torque as a current is 20 % of the rated current (torque = k_t · I).
    const double ratedA =
        d->readParameters("X", std::vector<std::string>{"motor.rated_current"}).value().at("motor.rated_current");
    EXPECT_NEAR(lim->currentStepMaxA, std::min(embedded.currentStepMaxA, 0.2 * ratedA),
                1e-6 * ratedA); // float32 rating
    EXPECT_EQ(lim->currentStepMaxS, embedded.currentStepMaxS);
    EXPECT_EQ(lim->testDurationMaxS, embedded.testDurationMaxS);
    auto caps = d->capabilities("X");
    ASSERT_TRUE(caps.ok()) << caps.error().detail;
    EXPECT_EQ(caps->testTypes, (*local)->capabilities("X")->testTypes);
    EXPECT_EQ(caps->frfMethods.size(), 4u);
    EXPECT_TRUE(caps->evaluatesFrf && caps->writesParameters && caps->hasLink);
    EXPECT_EQ(caps->traceRateHz, (*local)->capabilities("X")->traceRateHz);
    // A plan beyond the server's limit is refused with the server's words; within it, the plan is the
    // embedded drive's plan of the same request (the server asks its embedded drive).
    TestRequest r;
    r.axis = "X";
    auto& frf = r.test.emplace<FrfTest>();
    frf.fminHz = 50.0;
    frf.fmaxHz = 400.0;
    frf.points = 6;
    frf.amplitudePct = 30.0;
    auto refused = d->planTest(r);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(refused.error().detail.find("above the drive's limit 20 %"), std::string::npos) << refused.error().detail;
    frf.amplitudePct = 5.0;
    auto plan = d->planTest(r);
    ASSERT_TRUE(plan.ok()) << plan.error().detail;
    auto same = (*local)->planTest(r);
    ASSERT_TRUE(same.ok());
    EXPECT_EQ(plan->motionTimeS, same->motionTimeS); // f64 on the wire
    EXPECT_EQ(plan->recordSamples, same->recordSamples);
    EXPECT_EQ(plan->traceRateHz, same->traceRateHz);
    // Planning moved nothing: the drive is idle and takes the test.
    EXPECT_EQ(d->pollTest()->state, TestState::Idle);
}

TEST(ModbusDescribe, AMapWithoutTheDescriptionIsReportedByField)
{
    devtest::ServerThread server(options("vmc"));
    auto uri = parseModbusUri(server.uri());
    ASSERT_TRUE(uri.ok());
    auto loaded = loadRegisterMap("axistune-sim");
    ASSERT_TRUE(loaded.ok());
    RegisterMap map = *loaded;
    map.fields.erase("limits.travel_window");
    map.fields.erase("describe.flags");
    map.enums["command"].erase("plan_test");
    auto d = ModbusDrive::open(*uri, map);
    ASSERT_TRUE(d.ok()) << d.error().detail;
    auto caps = (*d)->capabilities("X");
    ASSERT_FALSE(caps.ok());
    EXPECT_NE(caps.error().detail.find("has no field describe.flags"), std::string::npos) << caps.error().detail;
    auto lim = (*d)->limits("X");
    ASSERT_FALSE(lim.ok());
    EXPECT_NE(lim.error().detail.find("has no field limits.travel_window"), std::string::npos);
    TestRequest r;
    r.axis = "X";
    r.test = HoldTest{};
    auto plan = (*d)->planTest(r);
    ASSERT_FALSE(plan.ok());
    EXPECT_NE(plan.error().detail.find("has no command plan_test"), std::string::npos);
}

} // namespace
} // namespace axistune::device
