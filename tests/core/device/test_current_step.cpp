// SPDX-License-Identifier: GPL-3.0-or-later
// The current-step test of the embedded simulated drive (TestType::CurrentStep, Drive.h): the trace at
// the current-loop rate with the step where the request puts it, the axis at rest and holding after
// the test, the parameters restored, and the refused requests naming their limit.
#include "core/device/SimulatedDrive.h"

#include <cmath>
#include <gtest/gtest.h>

#include "tests/core/device/DriveTestUtil.h"

using namespace axistune;
using namespace axistune::device;

namespace {

TestRequest currentStep(double amplitudeA, double durationS, const std::string& axis = "X")
{
    TestRequest r;
    r.axis = axis;
    auto& c = r.test.emplace<CurrentStepTest>();
    c.currentA = amplitudeA;
    c.recordS = durationS;
    return r;
}

TestStatus runToEnd(Drive& d)
{
    double progress = 0.0;
    for (int i = 0; i < 10000; ++i) {
        auto s = d.pollTest();
        EXPECT_TRUE(s.ok());
        EXPECT_GE(s->progress, progress);
        progress = s->progress;
        if (s->state != TestState::Running)
            return *s;
    }
    ADD_FAILURE() << "the test did not end";
    return {};
}

std::string refusal(Drive& d, const TestRequest& r)
{
    auto st = d.startTest(r);
    EXPECT_FALSE(st.ok());
    if (st.ok()) {
        (void)d.abortTest();
        return {};
    }
    EXPECT_EQ(st.error().code, ErrorCode::OutOfRange);
    return st.error().detail;
}

} // namespace

TEST(SimulatedDriveCurrentStep, TracesAtTheCurrentRateAndHoldsAfterwards)
{
    auto drive = devtest::makeDrive("vmc");
    drive->setSliceSeconds(0.001); // several polls inside the record and the hold
    auto* sim = drive->simulator("X");
    ASSERT_NE(sim, nullptr);
    const auto before = sim->parameters();
    ASSERT_TRUE(drive->startTest(currentStep(5.0, 0.004)).ok());
    EXPECT_FALSE(drive->writeParameters("X", {{"current.kp", 20.0}}).ok()); // no write while it runs
    const auto s = runToEnd(*drive);
    ASSERT_EQ(s.state, TestState::Completed) << s.detail;
    auto trace = drive->readTrace();
    ASSERT_TRUE(trace.ok());
    const auto& cap = *trace;
    // 4 ms at 62.5 µs: 64 samples, fs = 16 kHz; the step 10 % in, at sample 6 (0.4 ms / 62.5 µs = 6.4 → 6).
    ASSERT_EQ(cap.size(), 64u);
    EXPECT_DOUBLE_EQ(cap.metadata.number("fs_Hz").value(), 16000.0);
    EXPECT_EQ(cap.metadata.text("test"), "current_step");
    EXPECT_EQ(cap.metadata.number("step_amplitude_A").value(), 5.0);
    EXPECT_EQ(cap.metadata.number("voltage_clamped_ticks").value(), 0.0);
    const auto& t = cap.channel("t_s")->data;
    const auto& cmd = cap.channel("current_cmd_A")->data;
    EXPECT_DOUBLE_EQ(cap.metadata.number("step_start_s").value(), t[6]);
    EXPECT_EQ(cmd[5], 0.0);
    EXPECT_EQ(cmd[6], 5.0);
    EXPECT_EQ(cmd.back(), 5.0);
    // The current follows (α = 1, k_p 35.7 V/A: it is on the command within 2 % after 1 ms).
    const auto& i = cap.channel("current_A")->data;
    EXPECT_NEAR(i.back(), 5.0, 0.1);
    // After the hold the axis is at rest, the parameters are the ones from before.
    EXPECT_LT(std::abs(sim->motorVelocity()), 0.01);
    EXPECT_EQ(sim->parameters(), before);
    // A following velocity step sees the velocity trace again.
    ASSERT_TRUE(drive
                    ->startTest([] {
                        TestRequest r;
                        r.axis = "X";
                        auto& step = r.test.emplace<StepTest>();
                        step.velocityRadS = 1.0;
                        step.recordS = 0.01;
                        return r;
                    }())
                    .ok());
    ASSERT_EQ(runToEnd(*drive).state, TestState::Completed);
    auto vel = drive->readTrace();
    ASSERT_TRUE(vel.ok());
    EXPECT_EQ(vel->channels.size(), 14u);
    EXPECT_DOUBLE_EQ(vel->metadata.number("fs_Hz").value(), 4000.0);
}

TEST(SimulatedDriveCurrentStep, RefusesBeyondItsLimitsAndNamesThem)
{
    auto drive = devtest::makeDrive("vmc");
    // vmc: motor.max_current 80 A → at most 40 A; at most 50 ms; k_t 0.50911 N·m/A, J_m 1.1818e-3 kg·m².
    EXPECT_NE(refusal(*drive, currentStep(40.5, 0.001)).find("50 % of motor.max_current (40 A)"), std::string::npos);
    EXPECT_NE(refusal(*drive, currentStep(-41.0, 0.001)).find("40 A"), std::string::npos);
    EXPECT_NE(refusal(*drive, currentStep(std::nan(""), 0.001)).find("finite"), std::string::npos);
    EXPECT_NE(refusal(*drive, currentStep(std::numeric_limits<double>::infinity(), 0.001)).find("finite"),
              std::string::npos);
    EXPECT_NE(refusal(*drive, currentStep(0.0, 0.001)).find("non-zero"), std::string::npos);
    EXPECT_NE(refusal(*drive, currentStep(1.0, 0.051)).find("(0, 0.05] s"), std::string::npos);
    EXPECT_NE(refusal(*drive, currentStep(1.0, 0.0001)).find("current periods"), std::string::npos);
    // 10 A for 45 ms: 0.50911·10·0.045/1.1818e-3 ≈ 194 rad/s, far above 20 rad/s.
    const std::string speed = refusal(*drive, currentStep(10.0, 0.05));
    EXPECT_NE(speed.find("20 rad/s"), std::string::npos) << speed;
    EXPECT_NE(speed.find("194 rad/s"), std::string::npos) << speed;
    // Just inside: 5 A for 9 ms → 0.50911·5·0.0081/1.1818e-3 ≈ 17.4 rad/s.
    ASSERT_TRUE(drive->startTest(currentStep(5.0, 0.009)).ok());
    EXPECT_EQ(runToEnd(*drive).state, TestState::Completed);
    // Nothing changed on a refusal: the trace divider is the preset's.
    auto v = drive->readParameters("X", std::vector<std::string>{"trace.divider"});
    ASSERT_TRUE(v.ok());
    EXPECT_EQ(v->at("trace.divider"), 1.0);
}

TEST(SimulatedDriveCurrentStep, AbortStopsTheStepAndRestoresTheParameters)
{
    auto drive = devtest::makeDrive("vmc");
    drive->setSliceSeconds(0.0005);
    auto* sim = drive->simulator("X");
    const auto before = sim->parameters();
    auto r = currentStep(5.0, 0.008);
    r.traceDivider = 2; // changes a parameter for the test
    ASSERT_TRUE(drive->startTest(r).ok());
    ASSERT_TRUE(drive->pollTest().ok());
    ASSERT_TRUE(drive->pollTest().ok());
    EXPECT_EQ(sim->parameter("trace.divider"), 2.0);
    ASSERT_TRUE(drive->abortTest().ok());
    auto s = drive->pollTest();
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->state, TestState::Aborted);
    EXPECT_EQ(sim->parameters(), before);
    // The current command is gone: the velocity loop holds the motor at rest again.
    sim->run(0.3);
    EXPECT_LT(std::abs(sim->motorVelocity()), 0.01);
    EXPECT_LT(std::abs(sim->torqueCommand()), 0.5);
    EXPECT_FALSE(drive->readTrace().ok()); // no completed test, no trace
}
