// SPDX-License-Identifier: GPL-3.0-or-later
// The scope end to end (docs/scope.md): axistune-simdrive started on a free loopback port, the Modbus client
// through the Drive seam, and axistune-cli scope. Expected values come from the known step (0 before, the
// amplitude from the step on), the requested pre-trigger share and the drive's clock (t_s = n · T_v).
#include "core/device/Drive.h"
#include "core/device/TestRunner.h"
#include "core/io/ScopeCsv.h"

#include <chrono>
#include <cmath>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/app/cli/CliRunner.h"
#include "tests/app/cli/SimDriveProcess.h"
#include "tests/core/device/ScopeTestUtil.h"

using namespace axistune;
using namespace axistune::device;
using axistune::testing::runCli;
using axistune::testing::SimDrive;

namespace {

constexpr double kStepRadS = 10.0;
constexpr double kTvS = 250e-6; ///< velocity period of the vmc preset (presets/vmc.json): 4 kHz

std::unique_ptr<Drive> connectTo(const SimDrive& srv)
{
    auto d = connect({"modbus://127.0.0.1:" + std::to_string(srv.port()) + "?timeout_ms=2000", 1});
    EXPECT_TRUE(d.ok()) << (d.ok() ? "" : d.error().detail);
    return d.ok() ? std::move(d).value() : nullptr;
}

ScopeState waitFor(Drive& d, std::initializer_list<ScopeState> states, double seconds)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<int>(seconds * 1000));
    ScopeState s = ScopeState::Idle;
    while (std::chrono::steady_clock::now() < end) {
        auto st = d.pollScope();
        EXPECT_TRUE(st.ok());
        if (!st.ok())
            return s;
        s = st->state;
        for (const auto w : states) {
            if (s == w)
                return s;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return s;
}

} // namespace

class ModbusScopeTrigger : public ::testing::TestWithParam<std::tuple<double, int>> {};

TEST_P(ModbusScopeTrigger, TriggerAtThePreTriggerRowOnAKnownStep)
{
    const auto [pct, divider] = GetParam();
    SimDrive srv("--preset vmc --seed 7");
    ASSERT_GT(srv.port(), 0);
    auto d = connectTo(srv);
    ASSERT_TRUE(d);
    auto caps = d->capabilities("X");
    ASSERT_TRUE(caps.ok());
    EXPECT_TRUE(caps->scope);
    ScopeRequest r;
    r.axis = "X";
    // Not in the drive's list order: the client must hand them back in this order.
    r.channels = {"motor_vel_rad_s", "t_s", "velocity_cmd_rad_s"};
    r.divider = divider;
    r.triggerChannel = "velocity_cmd_rad_s";
    r.triggerLevel = 0.5 * kStepRadS;
    r.edge = ScopeEdge::Rising;
    r.preTriggerPct = pct;
    r.lengthSamples = 1000;
    ASSERT_TRUE(d->armScope(r).ok());
    ASSERT_EQ(waitFor(*d, {ScopeState::Waiting}, 5.0), ScopeState::Waiting);
    TestRequest step;
    step.axis = "X";
    auto& s = step.test.emplace<StepTest>();
    s.velocityRadS = kStepRadS;
    s.recordS = 1.0;
    auto run = runTest(*d, step, {});
    ASSERT_TRUE(run.ok()) << run.error().detail;
    ASSERT_EQ(waitFor(*d, {ScopeState::Done}, 5.0), ScopeState::Done);
    auto c = d->readScopeCapture();
    ASSERT_TRUE(c.ok()) << c.error().detail;
    ASSERT_EQ(c->rows(), 1000u);
    const std::size_t pre = std::min<std::size_t>(static_cast<std::size_t>(std::llround(pct * 10.0)), 999);
    EXPECT_EQ(c->triggerRow(), pre);
    EXPECT_EQ(c->missingSamples(), 0u);
    ASSERT_EQ(c->channels.size(), 3u);
    EXPECT_EQ(c->channels[2].name, "velocity_cmd_rad_s");
    EXPECT_EQ(c->channels[2].unit, "rad/s");
    EXPECT_EQ(c->channels[1].unit, "s");
    const auto& v = c->columns[2];
    EXPECT_EQ(v[pre], kStepRadS);
    if (pre > 0) {
        EXPECT_EQ(v[pre - 1], 0.0);
    }
    // The step lies between the trigger sample and the one before: its time within one scope period.
    const double tTrigger = c->columns[1][pre];
    EXPECT_NEAR(tTrigger, static_cast<double>(c->triggerSample * divider) * kTvS, 1e-12);
    for (std::size_t i = 0; i < c->rows(); ++i)
        ASSERT_NEAR(c->columns[1][i], static_cast<double>(c->samples[i] * divider) * kTvS, 1e-12) << i;
}

INSTANTIATE_TEST_SUITE_P(ModbusScope, ModbusScopeTrigger,
                         ::testing::Values(std::tuple{25.0, 1}, std::tuple{0.0, 1}, std::tuple{100.0, 2},
                                           std::tuple{60.0, 4}));

TEST(ModbusScope, RollModeEightChannelsNoMissingOrRepeatedSample)
{
    SimDrive srv("--preset vmc --seed 7");
    ASSERT_GT(srv.port(), 0);
    auto d = connectTo(srv);
    ASSERT_TRUE(d);
    ScopeRequest r;
    r.axis = "X";
    r.mode = ScopeMode::Roll;
    r.channels = {"t_s",       "velocity_cmd_rad_s", "motor_vel_rad_s", "torque_cmd_Nm",
                  "current_A", "position_cmd_m",     "table_pos_m",     "following_error_m"};
    const auto tArm = std::chrono::steady_clock::now();
    ASSERT_TRUE(d->armScope(r).ok());
    ScopeCapture all;
    all.triggered = false;
    all.columns.assign(r.channels.size(), {});
    std::uint64_t next = 0;
    bool started = false;
    std::uint64_t lost = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const double runS = 3.0;
    while (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < runS) {
        auto rows = d->readScopeRows(next, 4000);
        ASSERT_TRUE(rows.ok()) << rows.error().detail;
        if (rows->rows == 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
            continue;
        }
        if (started && rows->firstSample != next)
            lost += rows->firstSample - next;
        started = true;
        appendScopeRows(all, *rows);
        next = rows->firstSample + rows->rows;
    }
    const double wallS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double sinceArmS = std::chrono::duration<double>(std::chrono::steady_clock::now() - tArm).count();
    ASSERT_TRUE(d->stopScope().ok());
    std::printf("[ figures ] roll mode over Modbus, 8 channels: %zu rows in %.2f s of wall time, %llu lost\n",
                all.rows(), wallS, static_cast<unsigned long long>(lost));
    EXPECT_EQ(lost, 0u);
    EXPECT_EQ(all.missingSamples(), 0u);
    for (std::size_t i = 1; i < all.rows(); ++i)
        ASSERT_EQ(all.samples[i], all.samples[i - 1] + 1) << "row " << i;
    // The drive samples in real time at 4 kHz: at least 70 % of 3 s × 4000 (the server catches up at most
    // 0.1 s of machine time per turn when it is starved of CPU on a loaded machine), at most the wall time since
    // the scope was armed.
    EXPECT_GE(static_cast<double>(all.rows()), 0.7 * runS * 4000.0);
    EXPECT_LE(static_cast<double>(all.rows()), sinceArmS * 4000.0 + 1.0);
    // Each row's time is the drive's clock: t_s = n · T_v.
    for (std::size_t i = 0; i < all.rows(); ++i)
        ASSERT_NEAR(all.columns[0][i], static_cast<double>(all.samples[i]) * kTvS, 1e-12) << i;
}

TEST(ModbusScope, ClientAndServerRefuseWhatTheDriveDoesNotOffer)
{
    SimDrive srv("--preset vmc --seed 7");
    ASSERT_GT(srv.port(), 0);
    auto d = connectTo(srv);
    ASSERT_TRUE(d);
    ScopeRequest r;
    r.axis = "X";
    r.channels = {"t_s", "bogus"};
    auto st = d->armScope(r);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("scope channel 'bogus' is not traceable on axis X"), std::string::npos)
        << st.error().detail;
    auto caps = d->scopeCapabilities("X");
    ASSERT_TRUE(caps.ok());
    EXPECT_NEAR(caps->fastestRateHz, 4000.0, 1e-9);
    EXPECT_EQ(caps->channels.size(), 23u); // X's 15, then the positions and following error of Y and Z (4 each)
    EXPECT_EQ(caps->channels[3].unit, "N·m");
}

// ---------------------------------------------------------------------------------------------
// axistune-cli scope

namespace {

struct CsvCheck {
    io::ScopeTable table;
    const model::Channel* cmd = nullptr;
};

} // namespace

TEST(CliScope, TriggeredCaptureOnTheSimulatorAndOverModbusReloads)
{
    const auto dir = axistune::testing::makeTempDir("scope");
    SimDrive srv("--preset vmc --seed 7");
    ASSERT_GT(srv.port(), 0);
    for (const auto& connect : {std::string("sim:vmc"), "modbus://127.0.0.1:" + std::to_string(srv.port())}) {
        const auto out = (dir / "trace.csv").string();
        const auto res = runCli("scope --connect " + connect +
                                " --axis X --channels velocity_cmd_rad_s,motor_vel_rad_s,following_error_m --trigger "
                                "velocity_cmd_rad_s:5:rising --pre 25 --length 0.1 --step 10 --out " +
                                out);
        ASSERT_EQ(res.exitCode, 0) << connect << ": " << res.err;
        auto t = io::readScopeCsvFile(out);
        ASSERT_TRUE(t.ok()) << t.error().detail;
        EXPECT_NEAR(t->fsHz, 4000.0, 1e-9);
        // 0.1 s at 4 kHz, trigger 25 % in: row 100.
        ASSERT_EQ(t->samples.size(), 400u) << connect;
        EXPECT_EQ(t->missingSamples, 0u);
        const auto* v = t->capture.channel("velocity_cmd_rad_s");
        ASSERT_TRUE(v);
        EXPECT_EQ(v->data[100], 10.0) << connect;
        EXPECT_EQ(v->data[99], 0.0) << connect;
        EXPECT_EQ(t->capture.metadata.number("trigger_row").value(), 100.0);
        EXPECT_EQ(t->capture.metadata.number("trigger_sample").value(), static_cast<double>(t->samples[100]));
        EXPECT_EQ(t->capture.metadata.text("unit.following_error_m"), "m");
        EXPECT_NE(res.out.find("\"trigger_row\": 100"), std::string::npos) << res.out;
    }
    std::filesystem::remove_all(dir);
}

TEST(CliScope, ContinuousOverModbusEveryRowOnce)
{
    const auto dir = axistune::testing::makeTempDir("scope");
    SimDrive srv("--preset vmc --seed 7");
    ASSERT_GT(srv.port(), 0);
    const auto out = (dir / "roll.csv").string();
    const auto res = runCli("scope --connect modbus://127.0.0.1:" + std::to_string(srv.port()) +
                            " --axis X --channels t_s,velocity_cmd_rad_s,motor_vel_rad_s,torque_cmd_Nm,current_A,"
                            "position_cmd_m,table_pos_m,following_error_m --continuous 1.5 --out " +
                            out);
    ASSERT_EQ(res.exitCode, 0) << res.err;
    auto t = io::readScopeCsvFile(out);
    ASSERT_TRUE(t.ok()) << t.error().detail;
    ASSERT_EQ(t->samples.size(), 6000u); // 1.5 s × 4000 Hz
    EXPECT_EQ(t->missingSamples, 0u);
    EXPECT_EQ(t->capture.metadata.text("scope_mode"), "roll");
    const auto* ts = t->capture.channel("t_s");
    ASSERT_TRUE(ts);
    for (std::size_t i = 0; i < t->samples.size(); ++i)
        ASSERT_NEAR(ts->data[i], static_cast<double>(t->samples[i]) * kTvS, 1e-12);
    std::filesystem::remove_all(dir);
}

TEST(CliScope, BadOptionsExitTwoNamingTheOption)
{
    const auto dir = axistune::testing::makeTempDir("scope");
    const auto out = (dir / "x.csv").string();
    const std::string base = "scope --connect sim:vmc --axis X --out " + out + " ";
    const std::pair<std::string, std::string> cases[] = {
        {"--channels t_s --trigger t_s:abc:rising --length 0.1",
         "--trigger 't_s:abc:rising': expected CHANNEL:LEVEL:EDGE"},
        {"--channels t_s --trigger t_s:1:up --length 0.1", "EDGE rising, falling or either"},
        {"--channels t_s --trigger t_s:1:rising --pre 150 --length 0.1",
         "--pre 150: the pre-trigger share must lie in 0..100 %"},
        {"--channels t_s --length 0.1", "--length needs --trigger"},
        {"--channels t_s --length 0.1 --continuous 1 --trigger t_s:1:rising", "give either --length S"},
        {"--channels nope --continuous 0.1", "scope channel 'nope' is not traceable on axis X (channels: t_s"},
        {"--channels t_s --continuous 0.0001", "--continuous 0.0001 s is shorter than two samples at 4000 Hz"},
        {"--channels t_s --continuous 0.1 --divider 0", "scope divider 0 outside 1..1000"},
    };
    for (const auto& [args, words] : cases) {
        const auto res = runCli(base + args);
        EXPECT_EQ(res.exitCode, 2) << args << ": " << res.err;
        EXPECT_NE(res.err.find(words), std::string::npos) << args << ": " << res.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << args;
    }
    // A backend without a scope: the replay of a recorded step.
    const auto rec = (dir / "rec.csv").string();
    ASSERT_EQ(
        runCli("capture --connect sim:vmc --axis X --test step --amplitude 5 --duration 0.05 --out " + rec).exitCode,
        0);
    const auto res = runCli("scope --connect replay:" + rec + " --axis X --channels t_s --continuous 0.1 --out " + out);
    EXPECT_EQ(res.exitCode, 2) << res.err;
    EXPECT_NE(res.err.find("has no scope"), std::string::npos) << res.err;
    std::filesystem::remove_all(dir);
}

TEST(ScopeCsv, BadSampleColumnsAreRefusedNamingLineAndColumn)
{
    const auto dir = axistune::testing::makeTempDir("scope");
    auto check = [&](const std::string& text, const std::string& words) {
        const auto p = (dir / "bad.csv").string();
        std::ofstream(p) << text;
        auto t = io::readScopeCsvFile(p);
        ASSERT_FALSE(t.ok()) << words;
        EXPECT_NE(t.error().detail.find(words), std::string::npos) << t.error().detail;
    };
    check("# fs_Hz=4000\nsample,a\n5,1\n5,2\n", "bad.csv line 4, column 'sample': sample 5 repeats the row before");
    check("# fs_Hz=4000\nsample,a\n5,1\n\n4,2\n", "line 5, column 'sample': sample 4 is below the row before (5)");
    check("# fs_Hz=4000\nsample,a\n5.5,1\n", "line 3, column 'sample': 5.5 is not a sample number");
    check("# fs_Hz=4000\nsample,a\n-1,1\n", "-1 is not a sample number");
    check("sample,a\n1,1\n", "fs_Hz");
    check("# fs_Hz=-3\nsample,a\n1,1\n", "fs_Hz=-3 must be a positive sample rate");
    check("# fs_Hz=4000\nn,a\n1,1\n", "no column 'sample'");
    // A gap is not an error: it is counted.
    const auto p = (dir / "gap.csv").string();
    std::ofstream(p) << "# fs_Hz=4000\nsample,a\n5,1\n6,1\n9,1\n";
    auto t = io::readScopeCsvFile(p);
    ASSERT_TRUE(t.ok());
    EXPECT_EQ(t->missingSamples, 2u);
    std::filesystem::remove_all(dir);
}

TEST(CliScope, DriveListsTheScopeChannelsWithUnits)
{
    const auto res = runCli("drive --connect sim:vmc --axis X");
    ASSERT_EQ(res.exitCode, 0) << res.err;
    const auto j = nlohmann::json::parse(res.out);
    EXPECT_EQ(j["axes"]["X"]["capabilities"]["scope"], true);
    const auto& s = j["axes"]["X"]["scope"];
    EXPECT_EQ(s["fastest_rate_Hz"].get<double>(), 4000.0);
    ASSERT_EQ(s["channels"].size(), 23u); // X's 15, then the positions and following error of Y and Z (4 each)
    EXPECT_EQ(s["channels"][14]["name"], "following_error_m");
    EXPECT_EQ(s["channels"][17]["name"], "Y.table_pos_m");
    EXPECT_EQ(s["channels"][17]["unit"], "m");
    EXPECT_EQ(s["channels"][14]["unit"], "m");
    EXPECT_EQ(s["channels"][3]["unit"], "N·m");
}

// Two axes in one scope over Modbus: X's and Y's table positions of a circle in one row. axistune-simdrive runs the
// circle at its own pace and keeps the scope's other axis with the one the test moves; the circle test's trace is
// the reference (the scope row holding a trace sample's X position holds its Y position; one velocity period of
// skew would be 4.2 µm at this feed).
TEST(ModbusScope, TwoAxesInOneScopeDrawTheCircleAtOneInstant)
{
    SimDrive srv("--preset vmc --seed 7");
    ASSERT_GT(srv.port(), 0);
    auto d = connectTo(srv);
    ASSERT_TRUE(d);
    auto caps = d->scopeCapabilities("X");
    ASSERT_TRUE(caps.ok());
    EXPECT_EQ(caps->channels.size(), 23u); // X's 15, then 4 of Y and 4 of Z
    EXPECT_EQ(caps->channels[17].name, "Y.table_pos_m");
    ScopeRequest r;
    r.axis = "X";
    r.mode = ScopeMode::Roll;
    r.channels = {"t_s", "table_pos_m", "Y.table_pos_m"};
    ASSERT_TRUE(d->armScope(r).ok());
    TestRequest t;
    auto& c = t.test.emplace<CircleTest>();
    t.axis = "X";
    c.secondAxis = "Y";
    c.radiusM = 0.05;
    c.feedMPerS = 1000.0 / 60000.0;
    c.centerYM = 0.1;
    c.dwellS = 0.1;
    ASSERT_TRUE(d->startTest(t).ok());
    ScopeCapture all;
    all.triggered = false;
    all.columns.assign(r.channels.size(), {});
    std::uint64_t next = 0;
    bool started = false, done = false;
    std::uint64_t lost = 0;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < end) {
        auto rows = d->readScopeRows(next, 20000);
        ASSERT_TRUE(rows.ok()) << rows.error().detail;
        if (started && rows->rows > 0 && rows->firstSample != next)
            lost += rows->firstSample - next;
        if (rows->rows > 0) {
            started = true;
            appendScopeRows(all, *rows);
            next = rows->firstSample + rows->rows;
        }
        if (done && rows->rows == 0)
            break;
        if (!done) {
            auto s = d->pollTest();
            ASSERT_TRUE(s.ok());
            if (s->state != TestState::Running) {
                ASSERT_EQ(s->state, TestState::Completed) << s->detail;
                done = true;
            }
        }
    }
    ASSERT_TRUE(done);
    auto trace = d->readTrace();
    ASSERT_TRUE(trace.ok()) << trace.error().detail;
    ASSERT_TRUE(d->stopScope().ok());
    EXPECT_EQ(lost, 0u);
    EXPECT_EQ(all.missingSamples(), 0u);
    const auto* tx = trace->channel("X.table_pos_m");
    const auto* ty = trace->channel("Y.table_pos_m");
    ASSERT_NE(tx, nullptr);
    ASSERT_NE(ty, nullptr);
    const auto& sx = all.columns[1];
    const auto& sy = all.columns[2];
    // The trace takes one row per position period (its fs_Hz), the scope one per velocity period (4 kHz).
    const auto fs = trace->metadata.number("fs_Hz");
    ASSERT_TRUE(fs.ok()) << fs.error().detail;
    const auto same = axistune::testing::sameInstant(sx, sy, *tx, *ty, *fs);
    ASSERT_TRUE(same.found) << same.report;
    EXPECT_EQ(same.worstY, 0.0) << "Y at the instant of X [m]";
}
