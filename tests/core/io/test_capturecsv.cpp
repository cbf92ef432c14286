// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/CaptureCsv.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace axistune;

TEST(CaptureCsv, RoundTripKeepsMetadataColumnsAndFullPrecision)
{
    model::Capture c;
    c.metadata.set("fs_Hz", 4000.0);
    c.metadata.set("axis", "X");
    c.channels.push_back({"t_s", {0.0, 0.00025, 0.0005}});
    c.channels.push_back({"torque_cmd_Nm", {0.1, -1.0 / 3.0, 1e-300}});
    std::stringstream ss;
    ASSERT_TRUE(io::writeCaptureCsv(ss, c).ok());
    auto r = io::readCaptureCsv(ss, "mem.csv");
    ASSERT_TRUE(r.ok()) << r.error().detail;
    EXPECT_EQ(r->metadata, c.metadata);
    ASSERT_EQ(r->channels.size(), 2u);
    EXPECT_EQ(r->channels[1].name, "torque_cmd_Nm");
    EXPECT_EQ(r->channels[1].data, c.channels[1].data);  // bit-exact through the shortest round-trip form
}

TEST(CaptureCsv, ErrorsNameFileLineAndColumn)
{
    auto parse = [](const std::string& text) {
        std::stringstream ss(text);
        return io::readCaptureCsv(ss, "cap.csv");
    };
    auto r = parse("# fs_Hz=4000\nt_s,vel_rad_s\n0,1\n0.1,abc\n");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("cap.csv line 4, column 'vel_rad_s': not a number ('abc')"), std::string::npos)
        << r.error().detail;
    r = parse("t_s,vel_rad_s\n0,1,2\n");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("line 2"), std::string::npos);
    r = parse("t_s,vel_rad_s\n0\n");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("1 fields, the header has 2"), std::string::npos) << r.error().detail;
    r = parse("t_s,vel_rad_s\n0,nan\n");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("not"), std::string::npos);
    r = parse("");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("empty"), std::string::npos);
    r = parse("t_s,t_s\n0,0\n");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("appears twice"), std::string::npos);
    r = parse("t_s\n");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("no data rows"), std::string::npos);
    EXPECT_FALSE(io::readCaptureCsvFile("/nonexistent/x.csv").ok());
}
