// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/FrfCsv.h"

#include <cmath>
#include <gtest/gtest.h>
#include <sstream>

#include "tests/NumberText.h"

using namespace axistune;

namespace {

dsp::FrequencyResponse sample()
{
    dsp::FrequencyResponse f;
    f.metadata.set("method", "multisweep");
    f.metadata.set("fs_Hz", 4000.0);
    f.push(10.0, {1.0, -0.1}, std::nan(""), true);
    f.push(100.5, {0.123456789012345678, 1e-300}, 0.987654321, true);
    f.push(3900.0, {-2.5, 3.25}, std::nan(""), false);
    return f;
}

Result<dsp::FrequencyResponse> parse(const std::string& text) { std::istringstream in(text); return io::readFrfCsv(in, "t.csv"); }

}  // namespace

TEST(FrfCsv, HeaderAndRowFormat)
{
    std::ostringstream out;
    ASSERT_TRUE(io::writeFrfCsv(out, sample()));
    const std::string s = out.str();
    EXPECT_NE(s.find("# fs_Hz=4000\n"), std::string::npos);
    EXPECT_NE(s.find("\nf_Hz,re,im,mag_dB,phase_deg,coherence,valid\n"), std::string::npos);
    // 10 Hz row: coherence empty, valid 1; mag = 20log10(sqrt(1.01)), phase = atan2(-0.1, 1)
    const auto row = s.substr(s.find("\n10,") + 1);
    const auto cells = io::detail::splitCsvLine(row.substr(0, row.find('\n')));
    ASSERT_EQ(cells.size(), 7u);
    EXPECT_EQ(cells[5], "");
    EXPECT_EQ(cells[6], "1");
    EXPECT_NEAR(axistune::testutil::stod(cells[3]), 10.0 * std::log10(1.01), 1e-12);
    EXPECT_NEAR(axistune::testutil::stod(cells[4]), -5.710593137499643, 1e-12);
}

TEST(FrfCsv, RoundTripIsExact)
{
    std::ostringstream out;
    const auto a = sample();
    ASSERT_TRUE(io::writeFrfCsv(out, a));
    auto r = parse(out.str());
    ASSERT_TRUE(r.ok()) << r.error().detail;
    const auto& b = r.value();
    ASSERT_EQ(b.size(), a.size());
    EXPECT_EQ(b.metadata, a.metadata);
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(b.freqHz[i], a.freqHz[i]);
        EXPECT_EQ(b.h[i], a.h[i]);
        EXPECT_EQ(std::isnan(b.coherence[i]), std::isnan(a.coherence[i]));
        if (!std::isnan(a.coherence[i])) {
            EXPECT_EQ(b.coherence[i], a.coherence[i]);
        }
        EXPECT_EQ(b.valid[i], a.valid[i]);
    }
}

TEST(FrfCsv, PolarOnlyFileAccepted)
{
    auto r = parse("f_Hz,mag_dB,phase_deg\r\n5,20,90\r\n");
    ASSERT_TRUE(r.ok()) << r.error().detail;
    EXPECT_NEAR(r->h[0].real(), 0.0, 1e-12);
    EXPECT_NEAR(r->h[0].imag(), 10.0, 1e-12);
    EXPECT_TRUE(r->valid[0]);
    EXPECT_TRUE(std::isnan(r->coherence[0]));
}

TEST(FrfCsv, ErrorsNameLineAndColumn)
{
    auto e1 = parse("# a=b\nf_Hz,re,im,mag_dB,phase_deg,coherence,valid\n1,1,0,0,0,,1\n2,abc,0,0,0,,1\n");
    ASSERT_FALSE(e1.ok());
    EXPECT_NE(e1.error().detail.find("t.csv line 4, column 're': not a number"), std::string::npos) << e1.error().detail;

    auto e2 = parse("f_Hz,re\n1,2\n");
    ASSERT_FALSE(e2.ok());
    EXPECT_NE(e2.error().detail.find("line 1"), std::string::npos);
    EXPECT_NE(e2.error().detail.find("'im'"), std::string::npos);

    auto e3 = parse("f_Hz,re,im,valid\n1,1,0,2\n");
    ASSERT_FALSE(e3.ok());
    EXPECT_NE(e3.error().detail.find("line 2, column 'valid'"), std::string::npos);

    auto e4 = parse("f_Hz,re,im\n2,1,0\n1,1,0\n");
    ASSERT_FALSE(e4.ok());
    EXPECT_NE(e4.error().detail.find("line 3, column 'f_Hz'"), std::string::npos);

    auto e5 = parse("f_Hz,re,im\n1,nan,0\n");
    ASSERT_FALSE(e5.ok());
    EXPECT_NE(e5.error().detail.find("line 2, column 're': not finite"), std::string::npos);

    auto e6 = parse("f_Hz,re,im\n1,1\n");
    ASSERT_FALSE(e6.ok());
    EXPECT_NE(e6.error().detail.find("line 2"), std::string::npos);

    auto e7 = parse("f_Hz,re,im,coherence\n1,1,0,1.5\n");
    ASSERT_FALSE(e7.ok());
    EXPECT_NE(e7.error().detail.find("column 'coherence'"), std::string::npos);

    EXPECT_FALSE(parse("").ok());
    EXPECT_FALSE(parse("f_Hz,re,im\n").ok());
    auto e8 = io::readFrfCsvFile("/nonexistent/x.csv");
    ASSERT_FALSE(e8.ok());
    EXPECT_EQ(e8.error().code, ErrorCode::NotFound);
}
