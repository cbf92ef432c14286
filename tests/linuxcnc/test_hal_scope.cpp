// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 20 on LinuxCNC: the scope of a hal: axis (core/device/hal/HalScope.h) on AxisTune's test machine
// (scripts/hal-testbed, a real HAL session per test). The scope is instance sampler.1 of LinuxCNC's sampler and the
// tests record through sampler.0 of the same load (HalSampler.h), so the scope runs while a test runs; it samples the
// pid's pins or any float pin; its trigger and ring are the host's (the same code as the embedded drive's).
#include "core/device/Drive.h"
#include "core/device/hal/HalAxis.h"
#include "core/device/hal/HalText.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <optional>
#include <thread>

#include "tests/linuxcnc/HalTestbed.h"

using namespace axistune;
using namespace axistune::device::hal;
using namespace axistune::testing;

namespace {

/// Polls the scope until it reaches `want` (10 s at most).
bool waitForScope(device::Drive& d, device::ScopeState want)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < end) {
        auto st = d.pollScope();
        if (st && st->state == want)
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

/// Reads every roll-mode row that is waiting into `all` (the first read takes what the ring holds).
void drainRows(device::Drive& d, device::ScopeCapture& all, std::uint64_t& next, bool& started)
{
    for (;;) {
        auto rows = d.readScopeRows(next, 100000);
        ASSERT_TRUE(rows) << rows.error().detail;
        if (rows->rows == 0)
            return;
        if (started) {
            ASSERT_EQ(rows->firstSample, next) << "scope rows lost";
        }
        started = true;
        device::appendScopeRows(all, *rows);
        next = rows->firstSample + rows->rows;
    }
}

/// A triggered capture on the command net: arms `r` (trigger channel, level rising, pre-trigger, length), sets the
/// command net to `command` once the pre-trigger rows are in (as the NC would write it), and reads the capture.
std::optional<device::ScopeCapture> captureOnCommand(device::Drive& d, device::ScopeRequest r,
                                                     const std::vector<std::string>& channels,
                                                     const std::string& trigger, double prePct, std::uint64_t rows,
                                                     const std::string& command)
{
    r.axis = "pid.x";
    r.channels = channels;
    r.triggerChannel = trigger;
    r.triggerLevel = 0.5;
    r.edge = device::ScopeEdge::Rising;
    r.preTriggerPct = prePct;
    r.lengthSamples = rows;
    const auto armed = d.armScope(r);
    EXPECT_TRUE(armed) << (armed ? "" : armed.error().detail);
    if (!armed || !waitForScope(d, device::ScopeState::Waiting))
        return std::nullopt;
    (void)halText({"sets", "x-pos-cmd", command}); // fails the test (EXPECT in halText) when halcmd refuses
    if (!waitForScope(d, device::ScopeState::Done))
        return std::nullopt;
    auto cap = d.readScopeCapture();
    EXPECT_TRUE(cap) << (cap ? "" : cap.error().detail);
    return cap ? std::optional<device::ScopeCapture>(*cap) : std::nullopt;
}

/// No sampler instance left in HAL.
bool samplerUnloaded()
{
    return halText({"-s", "show", "pin", "sampler."}).find_first_not_of(" \t\r\n") == std::string::npos;
}

} // namespace

// A step of the NC's command (halcmd sets on the command net, as the NC would write it) triggers a capture with the
// trigger exactly at the pre-trigger row, the step itself on that row; no sample is missing; after the scope stops
// the nets and functions are as before and the sampler is unloaded.
TEST_F(HalTestbed, ScopeTriggersOnACommandStep)
{
    startBed(1000000);
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    const std::string funBefore = halText({"-s", "show", "funct"});
    auto d = device::connect({"hal:", 1});
    ASSERT_TRUE(d) << d.error().detail;
    auto caps = (*d)->capabilities("pid.x");
    ASSERT_TRUE(caps);
    EXPECT_TRUE(caps->scope);
    auto cap = captureOnCommand(**d, {}, {"command", "feedback", "following_error"}, "command", 25.0, 400, "1.0");
    ASSERT_TRUE(cap);
    ASSERT_EQ(cap->rows(), 400u);
    ASSERT_EQ(cap->triggerRow(), 100u); // 25 % of 400
    EXPECT_EQ(cap->missingSamples(), 0u);
    EXPECT_EQ(cap->rateHz, 1000.0);
    ASSERT_EQ(cap->channels.size(), 3u);
    EXPECT_EQ(cap->channels[0].name, "command");
    EXPECT_EQ(cap->columns[0][99], 0.0);
    EXPECT_EQ(cap->columns[0][100], 1.0); // the step itself on the trigger row
    EXPECT_GT(cap->columns[1][399], 0.5); // the axis follows
    ASSERT_TRUE((*d)->stopScope());
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
    EXPECT_EQ(halText({"-s", "show", "funct"}), funBefore);
    EXPECT_TRUE(samplerUnloaded());
    (void)halText({"sets", "x-pos-cmd", "0"});
}

// Any pin. Floats: the plant's velocity (an output on no net: a net of the scope's own carries it) and its position
// (on the feedback net) beside the pid's feedback; plant.x.position is the net the pid's feedback reads, so the two
// columns are equal sample for sample; the velocity integrated over the step response (trapezoids at the servo
// period) is the position change within 2 % (the plant integrates in substeps). Bit and s32: the pid's `saturated`
// and `saturated-count` during a step that drives its output into maxoutput (2, the test machine's INI), against
// the pid's documented meaning: saturated is TRUE exactly where |output| = maxoutput, and the count rises by one per
// saturated period and is 0 otherwise. An input pin on no net (pid.x.enable, set by setp) is not offered and is
// refused by name.
TEST_F(HalTestbed, ScopeSamplesAnyPin)
{
    startBed(1000000);
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    auto d = device::connect({"hal:", 1});
    ASSERT_TRUE(d) << d.error().detail;
    auto sc = (*d)->scopeCapabilities("pid.x");
    ASSERT_TRUE(sc) << sc.error().detail;
    bool velocity = false, enable = false, saturated = false;
    for (const auto& c : sc->channels) {
        velocity = velocity || c.name == "plant.x.velocity";
        enable = enable || c.name == "pid.x.enable";
        saturated = saturated || (c.name == "pid.x.saturated" && c.unit == "HAL bit");
    }
    EXPECT_TRUE(velocity);
    EXPECT_TRUE(saturated);
    EXPECT_FALSE(enable); // an input on no net: sampling it would change it
    EXPECT_EQ(sc->maxChannels, 20);

    auto cap = captureOnCommand(**d, {}, {"feedback", "plant.x.position", "plant.x.velocity", "command"}, "command",
                                10.0, 1000, "1.0");
    ASSERT_TRUE(cap);
    ASSERT_EQ(cap->rows(), 1000u);
    EXPECT_EQ(cap->missingSamples(), 0u);
    EXPECT_EQ(cap->channels[2].unit, "HAL units");
    for (std::size_t i = 0; i < cap->rows(); ++i)
        ASSERT_EQ(cap->columns[0][i], cap->columns[1][i]) << "row " << i;
    double integral = 0.0;
    for (std::size_t i = 1; i < cap->rows(); ++i)
        integral += 0.5 * (cap->columns[2][i] + cap->columns[2][i - 1]) * 1e-3;
    const double moved = cap->columns[1].back() - cap->columns[1].front();
    EXPECT_GT(moved, 0.5);
    EXPECT_NEAR(integral, moved, 0.02 * moved);
    ASSERT_TRUE((*d)->stopScope());
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore); // the scope's own net is gone

    // Far enough to saturate the output.
    auto sc2 = captureOnCommand(**d, {}, {"output", "pid.x.saturated", "pid.x.saturated-count"}, "pid.x.saturated",
                                10.0, 1000, "20.0");
    ASSERT_TRUE(sc2);
    ASSERT_EQ(sc2->rows(), 1000u);
    EXPECT_EQ(sc2->columns[1][sc2->triggerRow()], 1.0);
    const double maxOutput = getp("pid.x.maxoutput");
    std::size_t saturatedRows = 0;
    for (std::size_t i = 0; i < sc2->rows(); ++i) {
        const bool s = sc2->columns[1][i] != 0.0;
        ASSERT_EQ(s, std::abs(sc2->columns[0][i]) == maxOutput) << "row " << i;
        if (i > 0) {
            ASSERT_EQ(sc2->columns[2][i], s ? sc2->columns[2][i - 1] + 1.0 : 0.0) << "row " << i;
        }
        saturatedRows += s;
    }
    EXPECT_GT(saturatedRows, 10u);
    ASSERT_TRUE((*d)->stopScope());
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);

    device::ScopeRequest bit;
    bit.axis = "pid.x";
    bit.lengthSamples = 100;
    bit.channels = {"pid.x.enable"};
    bit.triggerChannel = "pid.x.enable";
    auto refused = (*d)->armScope(bit);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().detail.find("pid.x.enable"), std::string::npos) << refused.error().detail;
    (void)halText({"sets", "x-pos-cmd", "0"});
}

// The scope runs while a test runs: rolled from before a multisine FRF test to after it, every servo period is a row
// (no gap in the sampler's numbers), the injection shows in the pid's output net during the test, and the test's own
// record (sampler.0) is complete. While a second test runs the scope is not armed anew (refused, naming why) and its
// stop waits for the test's end; then the nets and functions are as before and the sampler is unloaded, and the scope
// arms again.
TEST_F(HalTestbed, ScopeRunsWhileATestRuns)
{
    startBed(1000000);
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    const std::string funBefore = halText({"-s", "show", "funct"});
    auto d = device::connect({"hal:", 1});
    ASSERT_TRUE(d) << d.error().detail;
    device::ScopeRequest r;
    r.axis = "pid.x";
    r.mode = device::ScopeMode::Roll;
    r.channels = {"output", "feedback"};
    ASSERT_TRUE((*d)->armScope(r)) << "arm";
    device::ScopeCapture all;
    all.triggered = false;
    all.columns.assign(2, {});
    std::uint64_t next = 0;
    bool started = false;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    drainRows(**d, all, next, started);
    const std::size_t before = all.rows();
    ASSERT_GT(before, 100u);

    device::TestRequest t;
    t.axis = "pid.x";
    auto& f = t.test.emplace<device::FrfTest>();
    f.method = device::FrfMethod::Multisine;
    f.fminHz = 5.0;
    f.fmaxHz = 200.0;
    f.amplitudePeak = 0.2;
    f.multisinePeriods = 2;
    {
        auto st = (*d)->startTest(t);
        ASSERT_TRUE(st) << st.error().detail;
    }
    const std::size_t atStart = all.rows();
    auto runTestToEnd = [&] {
        for (;;) {
            auto s = (*d)->pollTest();
            ASSERT_TRUE(s) << s.error().detail;
            drainRows(**d, all, next, started);
            if (s->state != device::TestState::Running) {
                ASSERT_EQ(s->state, device::TestState::Completed) << s->detail;
                return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    };
    runTestToEnd();
    auto frf = (*d)->readFrequencyResponse();
    ASSERT_TRUE(frf) << frf.error().detail;
    EXPECT_GT(frf->frf.freqHz.size(), 10u);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    drainRows(**d, all, next, started);
    EXPECT_EQ(all.missingSamples(), 0u);
    for (std::size_t i = 1; i < all.rows(); ++i)
        ASSERT_EQ(all.samples[i], all.samples[i - 1] + 1) << "row " << i;
    // The injection in the output net: the largest output during the test far above the one while the axis held
    // still before it.
    double peakBefore = 0.0, peakDuring = 0.0;
    for (std::size_t i = 0; i < all.rows(); ++i)
        (i < atStart ? peakBefore : peakDuring) =
            std::max(i < atStart ? peakBefore : peakDuring, std::abs(all.columns[0][i]));
    EXPECT_GT(peakDuring, 0.1); // the multisine's peak is 0.2 in output units
    EXPECT_LT(peakBefore, 0.05);

    // During a second test the scope is not armed anew (the test rewires HAL's nets), and a stop waits for the
    // test's end to take the scope's pins out of HAL; the test completes either way.
    ASSERT_TRUE((*d)->startTest(t)) << "second test";
    auto refused = (*d)->armScope(r);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().detail.find("while a test runs"), std::string::npos) << refused.error().detail;
    ASSERT_TRUE((*d)->stopScope());
    runTestToEnd();
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
    EXPECT_EQ(halText({"-s", "show", "funct"}), funBefore);
    EXPECT_TRUE(samplerUnloaded());
    // Armed again after the test: it rolls.
    ASSERT_TRUE((*d)->armScope(r)) << "arm after the test";
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    started = false;
    next = 0;
    all = {};
    all.triggered = false;
    all.columns.assign(2, {});
    drainRows(**d, all, next, started);
    EXPECT_GT(all.rows(), 50u);
    ASSERT_TRUE((*d)->stopScope());
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
    EXPECT_EQ(halText({"-s", "show", "funct"}), funBefore);
    EXPECT_TRUE(samplerUnloaded());
}
