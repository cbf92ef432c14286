// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/SweepCsv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

using namespace axistune;

namespace {

Result<dsp::SweepRecording> parse(const std::string& t) { std::istringstream in(t); return io::readSweepCsv(in, "s.csv"); }

}  // namespace

TEST(SweepCsv, RoundTripAndDemodulation)
{
    // y = 0.7 sin(θ - 40°) for excitation sin(θ), three offsets at 2900 Hz, fs = 4 kHz, M = 1
    dsp::SweepRecording rec;
    rec.fsHz = 4000.0;
    rec.amplitude = 1.0;
    rec.metadata.set("axis", "X");
    for (double psi : {0.0, 120.0, -120.0}) {
        dsp::SweepBlock b;
        b.freqHz = 2900.0;
        b.phaseOffsetDeg = psi;
        for (std::int64_t k = -2; k <= 1; ++k) {
            const double th = 2 * std::numbers::pi * 2900.0 * k / 4000.0 + psi * std::numbers::pi / 180;
            b.sample.push_back(k);
            b.excitation.push_back(std::sin(th));
            b.response.push_back(0.7 * std::sin(th - 40 * std::numbers::pi / 180));
        }
        rec.blocks.push_back(b);
    }
    std::ostringstream out;
    ASSERT_TRUE(io::writeSweepCsv(out, rec));
    EXPECT_NE(out.str().find("# fs_Hz=4000\n# amplitude=1\n"), std::string::npos);
    EXPECT_NE(out.str().find("\nfreq_Hz,phase_offset_deg,sample,excitation,response\n2900,0,-2,"), std::string::npos);
    auto back = parse(out.str());
    ASSERT_TRUE(back.ok()) << back.error().detail;
    EXPECT_EQ(back->fsHz, 4000.0);
    EXPECT_EQ(back->metadata.text("axis"), "X");
    ASSERT_EQ(back->blocks.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(back->blocks[i].sample, rec.blocks[i].sample);
        EXPECT_EQ(back->blocks[i].excitation, rec.blocks[i].excitation);
        EXPECT_EQ(back->blocks[i].response, rec.blocks[i].response);
        EXPECT_EQ(back->blocks[i].phaseOffsetDeg, rec.blocks[i].phaseOffsetDeg);
    }
    auto frf = dsp::sineStreamFrf(back.value());
    ASSERT_TRUE(frf.ok()) << frf.error().detail;
    EXPECT_NEAR(std::abs(frf->h[0]), 0.7, 1e-12);
    EXPECT_NEAR(std::arg(frf->h[0]) * 180 / std::numbers::pi, -40.0, 1e-9);
}

TEST(SweepCsv, ErrorsNameLineAndColumn)
{
    const std::string head = "# fs_Hz=4000\nfreq_Hz,phase_offset_deg,sample,excitation,response\n";
    auto e1 = parse(head + "100,0,0,1,2\n100,0,1,x,2\n");
    ASSERT_FALSE(e1.ok());
    EXPECT_NE(e1.error().detail.find("s.csv line 4, column 'excitation': not a number"), std::string::npos) << e1.error().detail;
    auto e2 = parse(head + "100,0,0,1,2\n100,0,2,1,2\n");
    ASSERT_FALSE(e2.ok());
    EXPECT_NE(e2.error().detail.find("line 4, column 'sample'"), std::string::npos);
    auto e3 = parse(head + "100,0,0.5,1,2\n");
    ASSERT_FALSE(e3.ok());
    EXPECT_NE(e3.error().detail.find("not an integer"), std::string::npos);
    auto e4 = parse("freq_Hz,phase_offset_deg,sample,excitation,response\n100,0,0,1,2\n");
    ASSERT_FALSE(e4.ok());
    EXPECT_NE(e4.error().detail.find("fs_Hz"), std::string::npos);
    auto e5 = parse("# fs_Hz=4000\nfreq_Hz,sample,excitation,response\n");
    ASSERT_FALSE(e5.ok());
    EXPECT_NE(e5.error().detail.find("missing column 'phase_offset_deg'"), std::string::npos);
    auto e6 = parse(head + "100,0,0,nan,2\n");
    ASSERT_FALSE(e6.ok());
    EXPECT_NE(e6.error().detail.find("line 3, column 'excitation': not finite"), std::string::npos);
}
