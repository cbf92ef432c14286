// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/BallBarCsv.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>

using namespace axistune;
using namespace axistune::io;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

std::string rows(int n, double start = 0.0, double step = 10.0)
{
    std::ostringstream os;
    os << "angle_deg,deviation_um\n";
    for (int i = 0; i < n; ++i)
        os << start + step * i << ',' << 0.5 * i << '\n';
    return os.str();
}

const std::string kMeta = "# radius_mm=100\n# feed_mm_min=1000\n# direction=ccw\n";

Result<BallBarTrace> parse(const std::string& text)
{
    std::istringstream in(text);
    return readBallBarCsv(in, "t.csv");
}

} // namespace

TEST(BallBarCsv, ReadsMetadataInSiAndSamples)
{
    auto r = parse("# radius_mm=150\n# feed_mm_min=3000\n# direction=CW\n# plane=XY\n# center_x_mm=-20\n"
                   "# center_y_mm=400\n# dT_x_Nm=0.61\n# dT_y_Nm=0.6\n# operator=someone\n" +
                   rows(36));
    ASSERT_TRUE(r.ok()) << r.error().detail;
    EXPECT_DOUBLE_EQ(r->radiusM, 0.150);
    EXPECT_NEAR(r->feedMPerS, 0.05, 1e-15); // 3000 mm/min = 50 mm/s
    EXPECT_EQ(r->direction, CircleDirection::Cw);
    EXPECT_DOUBLE_EQ(r->directionSign(), -1.0);
    EXPECT_DOUBLE_EQ(r->centerXM, -0.020);
    EXPECT_DOUBLE_EQ(r->centerYM, 0.400);
    ASSERT_TRUE(r->dTxNm.has_value());
    EXPECT_DOUBLE_EQ(*r->dTxNm, 0.61);
    EXPECT_DOUBLE_EQ(*r->dTyNm, 0.6);
    EXPECT_EQ(r->metadata.text("operator"), "someone");
    ASSERT_EQ(r->size(), 36u);
    EXPECT_NEAR(r->angleRad[3], 30.0 * kDeg, 1e-15);
    EXPECT_NEAR(r->deviationM[3], 1.5e-6, 1e-18);
}

TEST(BallBarCsv, AcceptsDecreasingAnglesAndCrlf)
{
    std::string text = kMeta + rows(36, 360.0, -10.0);
    std::string crlf;
    for (char c : text) {
        if (c == '\n')
            crlf += '\r';
        crlf += c;
    }
    auto r = parse(crlf);
    ASSERT_TRUE(r.ok()) << r.error().detail;
    EXPECT_NEAR(r->angleRad.back(), 10.0 * kDeg, 1e-15);
    EXPECT_FALSE(r->dTxNm.has_value());
    EXPECT_EQ(r->plane, "XY");
}

TEST(BallBarCsv, RefusesMalformedTracesNamingLineAndField)
{
    struct Case {
        std::string text;
        std::string mustContain;
    };
    const Case cases[] = {
        {rows(36), "no metadata"},
        {"# feed_mm_min=1000\n# direction=ccw\n" + rows(36), "'radius_mm' missing"},
        {"# radius_mm=100\n# direction=ccw\n" + rows(36), "'feed_mm_min' missing"},
        {"# radius_mm=100\n# feed_mm_min=1000\n" + rows(36), "'direction' missing"},
        {"# radius_mm=abc\n# feed_mm_min=1000\n# direction=ccw\n" + rows(36),
         "line 1, metadata 'radius_mm': not a number"},
        {"# radius_mm=-5\n# feed_mm_min=1000\n# direction=ccw\n" + rows(36),
         "line 1, metadata 'radius_mm': must be greater"},
        {"# radius_mm=100\n# feed_mm_min=1000\n# direction=up\n" + rows(36), "line 3, metadata 'direction'"},
        {kMeta + "angle_deg,deviation_um\n0,1\n", "has 1 sample;"},
        {kMeta + "angle_deg,deviation_um\n0,1\n10,nan\n", "t.csv line 6, column 'deviation_um': not a finite number"},
        {kMeta + "angle_deg,deviation_um\n0,1\n10,x\n", "t.csv line 6, column 'deviation_um': not a number ('x')"},
        {kMeta + "angle_deg,deviation_um\n0,1\n20,1\n10,1\n30,1\n40,1\n50,1\n60,1\n70,1\n",
         "t.csv line 7, column 'angle_deg': angles must be strictly increasing"},
        {kMeta + "angle,dev\n0,1\n", "line 4: expected the header 'angle_deg,deviation_um'"},
        {kMeta + "angle_deg,deviation_um\n0,1,2\n", "line 5: expected 2 columns"},
        {kMeta, "no header"},
        {kMeta + "# radius_mm=50\n" + rows(36), "line 4, metadata 'radius_mm': given twice"},
    };
    for (const auto& c : cases) {
        auto r = parse(c.text);
        ASSERT_FALSE(r.ok()) << c.mustContain;
        EXPECT_EQ(r.error().code, ErrorCode::BadInput);
        EXPECT_NE(r.error().detail.find(c.mustContain), std::string::npos) << r.error().detail;
    }
}

TEST(BallBarCsv, WriterRoundTripsExactly)
{
    BallBarTrace t;
    t.source = "mem";
    t.radiusM = 0.1;
    t.feedMPerS = 1000.0e-3 / 60.0;
    t.direction = CircleDirection::Cw;
    t.centerXM = 0.25;
    t.centerYM = -0.125;
    t.dTyNm = 0.61;
    t.metadata.set("machine", "vmc");
    for (int i = 0; i < 3600; ++i) {
        t.angleRad.push_back((360.0 - 0.1 * i) * kDeg);
        t.deviationM.push_back(1e-6 * std::sin(0.01 * i) + 1e-9 * i);
    }
    std::stringstream ss;
    ASSERT_TRUE(writeBallBarCsv(ss, t).ok());
    auto r = readBallBarCsv(ss, "mem");
    ASSERT_TRUE(r.ok()) << r.error().detail;
    EXPECT_DOUBLE_EQ(r->radiusM, t.radiusM);
    EXPECT_NEAR(r->feedMPerS, t.feedMPerS, 1e-16);
    EXPECT_EQ(r->direction, CircleDirection::Cw);
    EXPECT_DOUBLE_EQ(r->centerXM, 0.25);
    EXPECT_DOUBLE_EQ(r->centerYM, -0.125);
    EXPECT_FALSE(r->dTxNm.has_value());
    EXPECT_DOUBLE_EQ(*r->dTyNm, 0.61);
    EXPECT_EQ(r->metadata.text("machine"), "vmc");
    ASSERT_EQ(r->size(), t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        EXPECT_NEAR(r->angleRad[i], t.angleRad[i], 1e-14);
        EXPECT_NEAR(r->deviationM[i], t.deviationM[i], 1e-20);
    }
}

TEST(BallBarCsv, WriterRefusesWhatTheReaderWouldRefuse)
{
    BallBarTrace t;
    t.radiusM = 0.1;
    t.feedMPerS = 0.01;
    for (int i = 0; i < 10; ++i) {
        t.angleRad.push_back(i * 0.1);
        t.deviationM.push_back(i == 4 ? std::nan("") : 0.0);
    }
    std::stringstream ss;
    auto s = writeBallBarCsv(ss, t);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().detail.find("sample 4, column 'deviation_um'"), std::string::npos) << s.error().detail;
    t.deviationM[4] = 0.0;
    t.radiusM = 0.0;
    EXPECT_FALSE(writeBallBarCsv(ss, t).ok());
}
