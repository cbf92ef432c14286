// SPDX-License-Identifier: GPL-3.0-or-later
// The replay: backend (core/device/replay/, docs/drive-seam.md "The replay: backend"): what it
// plays, what it refuses and how a bad capture is reported. The rules every backend follows are in
// tests/conformance/.
#include "core/device/Drive.h"
#include "core/io/CaptureCsv.h"
#include "tests/ScopedTempDir.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

namespace axistune::device {
namespace {

std::string writeFile(const std::string& name, const std::string& text)
{
    // One directory per test, in one directory per process (ctest runs the tests of this file as parallel
    // processes), removed when the process ends — also after a failed test.
    static const axistune::testing::ScopedTempDir base("replay-test");
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const auto dir = base / info->name();
    std::filesystem::create_directories(dir);
    const auto path = (dir / name).string();
    std::ofstream(path) << text;
    return path;
}

/// 5 samples at 100 Hz of a step on axis X, as `axistune-cli capture` writes it.
std::string stepCapture(const std::string& extraMetadata = "# motion_time_s=0.25\n")
{
    return writeFile("step.csv", "# test=step\n# axis=X\n# fs_Hz=100\n# machine=vmc\n# seed=7\n" + extraMetadata +
                                     "t_s,motor_vel_rad_s\n0,0\n0.01,1\n0.02,2\n0.03,2.5\n0.04,2.6\n");
}

TEST(ReplayDrive, PlaysTheRecordedTestWithItsPlan)
{
    auto d = connect({"replay:" + stepCapture(), 1});
    ASSERT_TRUE(d.ok()) << d.error().detail;
    auto id = (*d)->identify();
    EXPECT_EQ(id->model, "replay");
    EXPECT_EQ(id->machine, "vmc");
    EXPECT_EQ(id->axes, std::vector<std::string>{"X"});
    auto caps = (*d)->capabilities("X");
    ASSERT_TRUE(caps.ok());
    EXPECT_EQ(caps->testTypes, std::vector<TestType>{TestType::Step});
    EXPECT_TRUE(caps->frfMethods.empty());
    EXPECT_EQ(caps->traceRateHz, 100.0);
    EXPECT_FALSE(caps->writesParameters || caps->evaluatesFrf || caps->hasLink);
    // Numeric metadata as read-only parameters, text metadata left out.
    auto meta = (*d)->parameterMetadata("X");
    ASSERT_TRUE(meta.ok());
    ASSERT_EQ(meta->size(), 3u); // fs_Hz, motion_time_s, seed
    EXPECT_EQ((*meta)[0].key, "capture.fs_Hz");
    EXPECT_EQ((*meta)[0].siUnit, "Hz");
    EXPECT_FALSE((*meta)[0].writable);
    EXPECT_EQ((*d)->readParameters("X", {}).value().at("capture.seed"), 7.0);
    TestRequest r;
    r.axis = "X";
    r.test = StepTest{};
    auto plan = (*d)->planTest(r);
    ASSERT_TRUE(plan.ok());
    EXPECT_EQ(plan->motionTimeS, 0.25); // the recorded motion time
    EXPECT_EQ(plan->recordSamples, 5u);
    EXPECT_EQ(plan->traceRateHz, 100.0);
    EXPECT_FALSE((*d)->readTrace().ok()); // nothing played yet
    ASSERT_TRUE((*d)->startTest(r).ok());
    // 0.05 s of recorded time per poll: 0.2, 0.4, 0.6, 0.8, 1.0.
    std::vector<double> progress;
    for (auto s = (*d)->pollTest(); s.ok(); s = (*d)->pollTest()) {
        progress.push_back(s->progress);
        if (s->state != TestState::Running) {
            EXPECT_EQ(s->state, TestState::Completed);
            break;
        }
    }
    ASSERT_EQ(progress.size(), 5u);
    EXPECT_NEAR(progress[0], 0.2, 1e-12);
    EXPECT_EQ(progress.back(), 1.0);
    auto trace = (*d)->readTrace();
    ASSERT_TRUE(trace.ok());
    EXPECT_EQ(trace->size(), 5u);
    EXPECT_EQ(trace->channel("motor_vel_rad_s")->data[3], 2.5);
    EXPECT_EQ(trace->metadata.text("connection").value().rfind("replay:", 0), 0u);
}

TEST(ReplayDrive, RefusesWhatItCannotReplay)
{
    auto d = connect({"replay:" + stepCapture(""), 1});
    ASSERT_TRUE(d.ok()) << d.error().detail;
    TestRequest r;
    r.axis = "X";
    r.test = StepTest{};
    // Without motion_time_s the motion is the record: 5 samples at 100 Hz.
    EXPECT_EQ((*d)->planTest(r)->motionTimeS, 0.05);
    r.test = FrfTest{};
    auto frf = (*d)->startTest(r);
    ASSERT_FALSE(frf.ok());
    EXPECT_NE(frf.error().detail.find("recorded a step test; it cannot run a frf test"), std::string::npos);
    r.test = StepTest{};
    r.axis = "Y";
    auto y = (*d)->planTest(r);
    ASSERT_FALSE(y.ok());
    EXPECT_NE(y.error().detail.find("no axis 'Y'"), std::string::npos);
    auto w = (*d)->writeParameters("X", {{"capture.fs_Hz", 200.0}});
    ASSERT_FALSE(w.ok());
    EXPECT_NE(w.error().detail.find("'capture.fs_Hz' is read-only"), std::string::npos) << w.error().detail;
    EXPECT_FALSE((*d)->readFrequencyResponse().ok());
    // Abort mid-replay (0.25 s recorded: five polls).
    auto longer = connect({"replay:" + stepCapture(), 1});
    ASSERT_TRUE(longer.ok());
    r.axis = "X";
    ASSERT_TRUE((*longer)->startTest(r).ok());
    ASSERT_EQ((*longer)->pollTest()->state, TestState::Running);
    ASSERT_TRUE((*longer)->abortTest().ok());
    EXPECT_EQ((*longer)->pollTest()->state, TestState::Aborted);
    EXPECT_FALSE((*longer)->readTrace().ok());
}

TEST(ReplayDrive, ABadCaptureIsNamedWithItsKey)
{
    const auto noTest = writeFile("notest.csv", "# axis=X\n# fs_Hz=100\nt_s,v\n0,0\n0.01,1\n");
    auto a = connect({"replay:" + noTest, 1});
    ASSERT_FALSE(a.ok());
    EXPECT_EQ(a.error().detail, "connection 'replay:" + noTest + "': " + noTest +
                                    ": metadata 'test' is missing: a replayed capture needs test, axis and fs_Hz");
    const auto frf = writeFile("frf.csv", "# test=frf\n# axis=X\n# fs_Hz=100\nt_s,v\n0,0\n0.01,1\n");
    auto b = connect({"replay:" + frf, 1});
    ASSERT_FALSE(b.ok());
    EXPECT_NE(b.error().detail.find("metadata test=frf cannot be replayed"), std::string::npos) << b.error().detail;
    const auto badFs = writeFile("badfs.csv", "# test=hold\n# axis=X\n# fs_Hz=-1\nt_s,v\n0,0\n0.01,1\n");
    auto c = connect({"replay:" + badFs, 1});
    ASSERT_FALSE(c.ok());
    EXPECT_NE(c.error().detail.find("metadata 'fs_Hz' must be a positive number"), std::string::npos);
    auto empty = connect({"replay:", 1});
    ASSERT_FALSE(empty.ok());
    EXPECT_NE(empty.error().detail.find("expected replay:FILE.csv"), std::string::npos);
}

} // namespace
} // namespace axistune::device
