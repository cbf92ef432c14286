// SPDX-License-Identifier: GPL-3.0-or-later
// End to end over a real loopback socket: the axistune-simdrive binary on a free port, read and
// written by mbpoll (an independent Modbus client from Debian) and by axistune-cli params; the
// server killed in the middle of a test; injected faults.
#include "core/device/ModbusDrive.h"

#include <chrono>
#include <cstdio>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <thread>

#include "tests/NumberText.h"
#include "tests/app/cli/CliRunner.h"
#include "tests/app/cli/ModbusTestUtil.h"
#include "tests/app/cli/SimDriveProcess.h"

using namespace axistune;
using namespace axistune::testing;

namespace {

using Clock = std::chrono::steady_clock;
using axistune::testing::SimDrive;

double paramsValue(const std::string& uri, const std::string& key, const std::string& axis = "X")
{
    auto r = runCli("params --connect '" + uri + "' --axis " + axis + " --get " + key);
    if (r.exitCode != 0)
        return std::nan("");
    return nlohmann::json::parse(r.out)["parameters"][key].get<double>();
}

device::TestRequest step(double amplitude, double duration, int divider)
{
    device::TestRequest r;
    r.axis = "X";
    auto& s = r.test.emplace<device::StepTest>();
    s.velocityRadS = amplitude;
    s.recordS = duration;
    r.traceDivider = divider;
    return r;
}

} // namespace

TEST(ModbusCli, MbpollReadsIdentityAndParametersAtTheMapAddressesAndSeesParamsWrites)
{
    SimDrive srv("--preset vmc");
    ASSERT_GT(srv.port(), 0) << srv.log();
    const auto map = registerMap();
    const int magicAddr = map["fields"]["identity.magic"]["address"];
    const int axesAddr = map["fields"]["identity.axis_count"]["address"];
    auto out = mbpoll(srv.port(), "-a 1 -r " + std::to_string(magicAddr) + " -c " +
                                      std::to_string(axesAddr - magicAddr + 1) + " 127.0.0.1");
    EXPECT_EQ(mbpollValue(out, magicAddr), map["magic"].get<double>()) << out;
    EXPECT_EQ(mbpollValue(out, axesAddr), 3.0) << out; // vmc: X, Y, Z
    const int kp = parameterAddress("velocity.kp");
    ASSERT_GT(kp, 0);
    const std::string floatArgs = "-t 4:float -B -a 1 -r " + std::to_string(kp) + " 127.0.0.1";
    out = mbpoll(srv.port(), floatArgs);
    EXPECT_EQ(mbpollValue(out, kp), paramsValue(srv.uri(), "velocity.kp")) << out;
    // mbpoll writes, params reads.
    out = mbpoll(srv.port(), floatArgs + " 0.75");
    EXPECT_NE(out.find("Written 1 references"), std::string::npos) << out;
    EXPECT_EQ(paramsValue(srv.uri(), "velocity.kp"), 0.75);
    // params writes (with read-back), mbpoll reads.
    auto r = runCli("params --connect " + srv.uri() + " --axis X --set velocity.kp=0.625");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["written"][0], "velocity.kp");
    EXPECT_EQ(mbpollValue(mbpoll(srv.port(), floatArgs), kp), 0.625);
    EXPECT_NE(srv.log().find("connection 1 from 127.0.0.1"), std::string::npos) << srv.log();
    EXPECT_EQ(srv.stop(SIGTERM), 0);
    EXPECT_NE(srv.log().find("shut down cleanly"), std::string::npos) << srv.log();
}

TEST(ModbusCli, WriteOutsideLimitsIsRefusedByTheClientAndByTheDrive)
{
    SimDrive srv("--preset vmc");
    ASSERT_GT(srv.port(), 0);
    const double before = paramsValue(srv.uri(), "velocity.kp");
    auto r = runCli("params --connect " + srv.uri() + " --axis X --set velocity.kp=200000");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("outside its limits"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("not sent"), std::string::npos) << r.err;
    EXPECT_EQ(srv.log().find("refused"), std::string::npos) << srv.log(); // the drive never saw it
    const int kp = parameterAddress("velocity.kp");
    auto out = mbpoll(srv.port(), "-t 4:float -B -a 1 -r " + std::to_string(kp) + " 127.0.0.1 200000");
    EXPECT_NE(out.find("Illegal data value"), std::string::npos) << out;
    EXPECT_NE(srv.log().find("refused (exception 3)"), std::string::npos) << srv.log();
    EXPECT_EQ(paramsValue(srv.uri(), "velocity.kp"), before);
}

TEST(ModbusCli, EachInjectedFaultHasItsOwnMessageAndExitCode)
{
    auto timed = [](const std::string& args, double& seconds) {
        const auto t0 = Clock::now();
        auto r = runCli(args);
        seconds = std::chrono::duration<double>(Clock::now() - t0).count();
        return r;
    };
    double s = 0;
    {
        auto r = timed("params --connect modbus://127.0.0.1:1 --axis X", s); // nobody listens on port 1
        EXPECT_EQ(r.exitCode, 3);
        EXPECT_NE(r.err.find("cannot connect"), std::string::npos) << r.err;
    }
    {
        auto r = runCli("params --connect modbus://127.0.0.1:notaport --axis X");
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_NE(r.err.find("port must be a number"), std::string::npos) << r.err;
    }
    {
        SimDrive srv("--fault illegal-address");
        auto r = timed("params --connect " + srv.uri() + " --axis X", s);
        EXPECT_EQ(r.exitCode, 3);
        EXPECT_NE(r.err.find("ILLEGAL DATA ADDRESS"), std::string::npos) << r.err;
        EXPECT_NE(srv.log().find("fault illegal-address"), std::string::npos);
    }
    {
        SimDrive srv("--fault delay:1500");
        auto r = timed("params --connect '" + srv.uri("timeout_ms=300") + "' --axis X", s);
        EXPECT_EQ(r.exitCode, 3);
        EXPECT_NE(r.err.find("no answer within 300 ms"), std::string::npos) << r.err;
        EXPECT_LT(s, 8.0);
    }
    {
        SimDrive srv("--fault drop-after:1");
        auto r = timed("params --connect " + srv.uri() + " --axis X", s);
        EXPECT_EQ(r.exitCode, 3);
        EXPECT_NE(r.err.find("connection lost"), std::string::npos) << r.err;
        EXPECT_LT(s, 5.0);
        EXPECT_NE(srv.log().find("fault drop-after:1"), std::string::npos);
    }
    {
        SimDrive srv("--fault drive-fault:0.05");
        auto d = device::connectAny({srv.uri(), 1});
        ASSERT_TRUE(d.ok()) << d.error().detail;
        ASSERT_TRUE((*d)->startTest(step(5.0, 1.0, 0)).ok());
        Result<device::TestStatus> st = device::TestStatus{device::TestState::Running, 0.0, {}};
        for (int i = 0; i < 2000 && st.ok() && st->state == device::TestState::Running; ++i)
            st = (*d)->pollTest();
        ASSERT_TRUE(st.ok());
        EXPECT_EQ(st->state, device::TestState::Faulted);
        EXPECT_NE(st->detail.find("drive_fault"), std::string::npos) << st->detail;
        EXPECT_NE(srv.log().find("fault drive_fault"), std::string::npos);
    }
    auto bad = runCli("params --connect sim:vmc --axis X --set velocity.kp");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("KEY=VALUE"), std::string::npos);
}

device::TestRequest multiSweep(int divider)
{
    device::TestRequest r;
    r.axis = "C";
    auto& f = r.test.emplace<device::FrfTest>();
    f.method = device::FrfMethod::MultiSweep;
    f.fminHz = 20.0;
    f.fmaxHz = 900.0;
    f.points = 12;
    f.amplitudePct = 5.0;
    r.traceDivider = divider;
    return r;
}

TEST(ModbusCli, ServerKilledMidMultiSweepIsALostConnectionAndTheRestartedDriveHasThePreTestParameters)
{
    const auto dir = makeTempDir("modbus-state");
    const std::string state = (dir / "state.json").string();
    const std::string args = "--preset dd-table --pace 1 --watchdog 5 --state " + state;
    {
        SimDrive srv(args);
        ASSERT_GT(srv.port(), 0) << srv.log();
        ASSERT_EQ(runCli("params --connect " + srv.uri() + " --axis C --set velocity.kp=250").exitCode, 0);
        auto d = device::connectAny({srv.uri("timeout_ms=500"), 1});
        ASSERT_TRUE(d.ok()) << d.error().detail;
        auto started = (*d)->startTest(multiSweep(2));
        ASSERT_TRUE(started.ok()) << started.error().detail;
        for (int i = 0; i < 5; ++i) {
            auto st = (*d)->pollTest();
            ASSERT_TRUE(st.ok());
            ASSERT_EQ(st->state, device::TestState::Running) << st->detail;
        }
        EXPECT_EQ(paramsValue(srv.uri(), "trace.divider", "C"), 2.0); // the test's setting
        srv.stop(SIGKILL);
        const auto t0 = Clock::now();
        auto st = (*d)->pollTest();
        const double s = std::chrono::duration<double>(Clock::now() - t0).count();
        ASSERT_FALSE(st.ok());
        EXPECT_EQ(exitCodeFor(st.error().code), 3);
        EXPECT_NE(st.error().detail.find("connection lost"), std::string::npos) << st.error().detail;
        EXPECT_NE(st.error().detail.find(srv.uri()), std::string::npos) << st.error().detail;
        EXPECT_LT(s, 2.0); // within the 500 ms timeout plus bounded reconnect attempts
    }
    SimDrive again(args);
    ASSERT_GT(again.port(), 0) << again.log();
    EXPECT_EQ(paramsValue(again.uri(), "velocity.kp", "C"), 250.0); // not the preset 233
    EXPECT_EQ(paramsValue(again.uri(), "trace.divider", "C"), 1.0); // not the test's 2
    std::filesystem::remove_all(dir);
}

TEST(ModbusCli, MultiSweepThroughTheSimdriveBinaryEqualsTheEmbeddedDriveWithTheSameSeed)
{
    SimDrive srv("--preset dd-table --seed 3");
    ASSERT_GT(srv.port(), 0) << srv.log();
    auto remote = device::connectAny({srv.uri(), 3});
    auto local = device::connectAny({"sim:dd-table", 3});
    ASSERT_TRUE(remote.ok() && local.ok());
    std::vector<device::FrfMeasurement> m;
    for (device::Drive* d : {remote->get(), local->get()}) {
        ASSERT_TRUE(d->startTest(multiSweep(0)).ok());
        Result<device::TestStatus> st = device::TestStatus{device::TestState::Running, 0.0, {}};
        const auto end = Clock::now() + std::chrono::seconds(60);
        while (st.ok() && st->state == device::TestState::Running && Clock::now() < end)
            st = d->pollTest();
        ASSERT_TRUE(st.ok());
        ASSERT_EQ(st->state, device::TestState::Completed) << st->detail;
        auto f = d->readFrequencyResponse();
        ASSERT_TRUE(f.ok()) << f.error().detail;
        m.push_back(std::move(f).value());
    }
    ASSERT_EQ(m[0].frf.size(), m[1].frf.size());
    ASSERT_GE(m[1].frf.size(), 10u);
    for (std::size_t i = 0; i < m[1].frf.size(); ++i) {
        EXPECT_EQ(m[0].frf.freqHz[i], m[1].frf.freqHz[i]);
        EXPECT_LE(std::abs(m[0].frf.h[i] - m[1].frf.h[i]), 1e-9 * std::abs(m[1].frf.h[i])) << m[1].frf.freqHz[i];
    }
}

TEST(ModbusCli, SilencedClientLetsTheDriveStopTheTestAndRestoreParameters)
{
    SimDrive srv("--preset vmc --pace 1 --watchdog 0.8");
    ASSERT_GT(srv.port(), 0);
    {
        auto d = device::connectAny({srv.uri(), 1});
        ASSERT_TRUE(d.ok()) << d.error().detail;
        ASSERT_TRUE((*d)->startTest(step(5.0, 10.0, 4)).ok());
        EXPECT_EQ(paramsValue(srv.uri(), "trace.divider"), 4.0);      // the test's setting while it runs
        std::this_thread::sleep_for(std::chrono::milliseconds(2000)); // no pollTest: no heartbeat
        EXPECT_NE(srv.log().find("fault heartbeat_lost"), std::string::npos) << srv.log();
    }
    EXPECT_EQ(paramsValue(srv.uri(), "trace.divider"), 1.0);
}
