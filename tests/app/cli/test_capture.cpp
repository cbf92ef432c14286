// SPDX-License-Identifier: GPL-3.0-or-later
// End to end: axistune-cli capture writes a capture CSV that reads back with the documented columns.
#include "core/io/CaptureCsv.h"
#include "tests/app/cli/CliRunner.h"

#include <gtest/gtest.h>

using axistune::testing::makeTempDir;
using axistune::testing::runCli;

TEST(CliCapture, StepOnVmcWritesACaptureCsv)
{
    const auto dir = makeTempDir("capture");
    const auto out = (dir / "step.csv").string();
    const auto r = runCli("capture --connect sim:vmc --axis X --test step --amplitude 5 --duration 0.25 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto cap = axistune::io::readCaptureCsvFile(out);
    ASSERT_TRUE(cap.ok()) << cap.error().detail;
    EXPECT_EQ(cap->metadata.number("fs_Hz").value(), 4000.0);
    EXPECT_EQ(cap->metadata.text("axis"), "X");
    ASSERT_NE(cap->channel("t_s"), nullptr);
    ASSERT_NE(cap->channel("motor_vel_rad_s"), nullptr);
    ASSERT_NE(cap->channel("torque_cmd_Nm"), nullptr);
    EXPECT_EQ(cap->size(), 1000u);
    EXPECT_NEAR(cap->channel("motor_vel_rad_s")->data.back(), 5.0, 0.25);
    std::filesystem::remove_all(dir);
}

TEST(CliCapture, BadArgumentsGiveExitCode2WithAMessage)
{
    const auto dir = makeTempDir("capture-bad"); // nothing is written there, unless a refusal fails
    const std::string out = (dir / "x.csv").string();
    auto r = runCli("capture --connect sim:nosuch --axis X --out " + out);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("nosuch"), std::string::npos);
    r = runCli("capture --connect sim:vmc --axis W --out " + out);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("no axis 'W'"), std::string::npos);
    r = runCli("capture --connect sim:vmc --axis X --test step --amplitude 1e9 --out " + out);
    EXPECT_EQ(r.exitCode, 2);
    r = runCli("capture --connect sim:vmc --axis X --test dance --out " + out);
    EXPECT_EQ(r.exitCode, 2);
}
