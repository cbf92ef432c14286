// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/SimulatedDrive.h"
#include "core/device/TestRunner.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace axistune;
using namespace axistune::device;

TEST(SimulatedDrive, IdentifiesTheVmcAxes)
{
    auto d = connect({"sim:vmc", 1});
    ASSERT_TRUE(d.ok()) << d.error().detail;
    auto id = (*d)->identify();
    ASSERT_TRUE(id.ok());
    EXPECT_EQ(id->axes, (std::vector<std::string>{"X", "Y", "Z"}));
}

TEST(SimulatedDrive, UnknownPresetAndBadUriAreClearErrors)
{
    auto a = connect({"sim:nope", 1});
    ASSERT_FALSE(a.ok());
    EXPECT_NE(a.error().detail.find("nope"), std::string::npos);
    EXPECT_NE(a.error().detail.find("vmc"), std::string::npos);  // lists the known presets
    auto b = connect({"ftp://x", 1});
    ASSERT_FALSE(b.ok());
    EXPECT_EQ(b.error().code, ErrorCode::BadInput);
}

TEST(SimulatedDrive, ReadsAndWritesParametersWithRangeChecks)
{
    auto d = connect({"sim:vmc", 1});
    ASSERT_TRUE(d.ok());
    Drive& drive = **d;
    const std::vector<std::string> keys{"current.kp", "velocity.kp"};
    auto v = drive.readParameters("X", keys);
    ASSERT_TRUE(v.ok());
    EXPECT_DOUBLE_EQ(v->at("current.kp"), 35.7);  // preset value (spec §2.8)
    ASSERT_TRUE(drive.writeParameters("X", {{"velocity.kp", 0.7}}).ok());
    EXPECT_DOUBLE_EQ(drive.readParameters("X", keys)->at("velocity.kp"), 0.7);
    auto bad = drive.writeParameters("X", {{"velocity.kp", 0.5}, {"current.alpha", 2.0}});
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(bad.error().detail.find("current.alpha"), std::string::npos);
    EXPECT_NE(bad.error().detail.find("[0, 1]"), std::string::npos);
    // Nothing of a refused write is applied.
    EXPECT_DOUBLE_EQ(drive.readParameters("X", keys)->at("velocity.kp"), 0.7);
    // Read-only ratings and the plant are not writable.
    EXPECT_FALSE(drive.writeParameters("X", {{"motor.max_current", 10.0}}).ok());
    EXPECT_FALSE(drive.writeParameters("X", {{"plant.inertia_load", 1.0}}).ok());
    EXPECT_FALSE(drive.readParameters("Q", keys).ok());
}

TEST(SimulatedDrive, StepTestTracesAndRestoresAndRefusesWritesWhileRunning)
{
    auto d = connect({"sim:two-inertia", 1});
    ASSERT_TRUE(d.ok());
    Drive& drive = **d;
    TestRequest req;
    req.axis = "A";
    auto& step = req.test.emplace<StepTest>();
    step.velocityRadS = 1.0;
    step.recordS = 0.3;
    bool checkedBusy = false;
    RunOptions o;
    o.progress = [&](double, const std::string&) {
        if (!checkedBusy) { // while the test runs
            EXPECT_EQ(drive.writeParameters("A", {{"velocity.kp", 5.0}}).error().code, ErrorCode::Busy);
        }
        checkedBusy = true;
    };
    auto run = runTest(drive, req, o);
    ASSERT_TRUE(run.ok()) << run.error().detail;
    EXPECT_TRUE(checkedBusy);
    const auto& trace = run->trace;
    ASSERT_TRUE(trace);
    const auto* v = trace->channel("motor_vel_rad_s");
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(trace->size(), 1200u);  // 0.3 s at 4 kHz
    // The velocity loop has an integrator: the step settles at the command (1 rad/s) within 2 %.
    EXPECT_NEAR(v->data.back(), 1.0, 0.02);
}

TEST(SimulatedDrive, JogAboveTheMotorSpeedLimitIsRefused)
{
    // vmc X: screw lead R = 12 mm/2π per rad, so 1.26 m/s is 6000 min⁻¹ at the motor.
    auto d = connect({"sim:vmc", 1});
    ASSERT_TRUE(d.ok());
    TestRequest req;
    req.axis = "X";
    auto& jog = req.test.emplace<JogTest>();
    jog.distance = 0.01;
    jog.acceleration = 1.0;
    jog.dwellS = 0.05;
    jog.velocity = 62.83; // 10 rev/s read as metres per second
    auto st = (*d)->startTest(req);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(st.error().detail.find("above the limit of 628.3 rad/s"), std::string::npos) << st.error().detail;
    jog.velocity = 0.6; // 50 rev/s × 12 mm = 3000 min⁻¹: accepted
    EXPECT_TRUE((*d)->startTest(req).ok());
    EXPECT_TRUE((*d)->abortTest().ok());
}

TEST(SimulatedDrive, AbortStopsAndRestoresParameters)
{
    auto d = connect({"sim:vmc", 1});
    ASSERT_TRUE(d.ok());
    Drive& drive = **d;
    TestRequest req;
    req.axis = "Y";
    auto& jog = req.test.emplace<JogTest>();
    jog.distance = 0.01;
    jog.velocity = 0.01;
    jog.acceleration = 0.5;
    req.traceDivider = 4;
    ASSERT_TRUE(drive.startTest(req).ok());
    ASSERT_TRUE(drive.pollTest().ok());
    ASSERT_TRUE(drive.abortTest().ok());
    EXPECT_EQ(drive.pollTest()->state, TestState::Aborted);
    const std::vector<std::string> k{"trace.divider"};
    EXPECT_DOUBLE_EQ(drive.readParameters("Y", k)->at("trace.divider"), 1.0);
    EXPECT_FALSE(drive.readTrace().ok());
}
