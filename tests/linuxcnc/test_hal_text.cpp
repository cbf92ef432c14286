// SPDX-License-Identifier: GPL-3.0-or-later
// The readers of halcmd's script-mode output, on text copied from LinuxCNC 2.9 (Debian 12).
#include "core/device/hal/HalText.h"

#include <gtest/gtest.h>

using namespace axistune::device::hal;

TEST(HalText, PinsWithAndWithoutNets)
{
    const char* text = "pid float OUT 0 pid.x.output ==> x-torque-cmd\n"
                       "pid float IN 0 pid.x.feedback <== x-pos-fb\n"
                       "pid float IN 0 pid.x.feedback-deriv\n"
                       "\n"
                       "pid bit   IN TRUE pid.x.error-previous-target\n";
    auto pins = parsePins(text);
    ASSERT_TRUE(pins) << pins.error().detail;
    ASSERT_EQ(pins->size(), 4u);
    EXPECT_EQ((*pins)[0].name, "pid.x.output");
    EXPECT_EQ((*pins)[0].signal, "x-torque-cmd");
    EXPECT_EQ((*pins)[1].dir, "IN");
    EXPECT_EQ((*pins)[2].signal, "");
    EXPECT_EQ((*pins)[3].value, "TRUE");
    ASSERT_NE(findPin(*pins, "pid.x.feedback"), nullptr);
    EXPECT_EQ(findPin(*pins, "pid.x.feedback")->signal, "x-pos-fb");
    EXPECT_EQ(findPin(*pins, "pid.y.output"), nullptr);
}

TEST(HalText, SignalsWithWriterAndReaders)
{
    const char* text = "float  0  x-pos-cmd ==> pid.x.command\n"
                       "float  0.25  x-torque-cmd <== axistune-inject.out ==> plant.x.torque ==> sampler.0.pin.0\n";
    auto sigs = parseSignals(text);
    ASSERT_TRUE(sigs) << sigs.error().detail;
    ASSERT_EQ(sigs->size(), 2u);
    EXPECT_EQ((*sigs)[0].writer, "");
    EXPECT_EQ((*sigs)[0].readers, std::vector<std::string>{"pid.x.command"});
    EXPECT_EQ((*sigs)[1].value, "0.25");
    EXPECT_EQ((*sigs)[1].writer, "axistune-inject.out");
    EXPECT_EQ((*sigs)[1].readers, (std::vector<std::string>{"plant.x.torque", "sampler.0.pin.0"}));
}

TEST(HalText, ThreadsInExecutionOrder)
{
    auto th = parseThreads(
        "1000000 YES servo-thread     3094 13934518 streamer.0 pid.x.do-pid-calcs axistune-inject plant.x\n"
        "250000 YES fast      12 40 \n");
    ASSERT_TRUE(th) << th.error().detail;
    ASSERT_EQ(th->size(), 2u);
    EXPECT_EQ((*th)[0].periodNs, 1000000);
    EXPECT_EQ((*th)[0].name, "servo-thread");
    EXPECT_EQ((*th)[0].functions,
              (std::vector<std::string>{"streamer.0", "pid.x.do-pid-calcs", "axistune-inject", "plant.x"}));
    EXPECT_TRUE((*th)[1].functions.empty());
}

TEST(HalText, MalformedLinesAreRefusedWithTheLine)
{
    auto pins = parsePins("pid float OUT 0 pid.x.output --> x\n");
    ASSERT_FALSE(pins);
    EXPECT_NE(pins.error().detail.find("line 1"), std::string::npos) << pins.error().detail;
    auto th = parseThreads("fast YES servo 1 2 f\n");
    ASSERT_FALSE(th);
    EXPECT_NE(th.error().detail.find("show thread"), std::string::npos);
    EXPECT_FALSE(parseSignals("float 0 s <== a ==>\n"));
}
