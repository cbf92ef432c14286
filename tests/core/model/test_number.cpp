// SPDX-License-Identifier: GPL-3.0-or-later
// The locale-independent number module: expected texts are those of printf in the "C" locale (C11
// 7.21.6.1 %g/%f rules), written out here by hand; every check also runs with the C library under
// de_DE.UTF-8, where printf itself writes "0,5".
#include "core/model/Number.h"

#include <clocale>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <string>

namespace axistune::model {
namespace {

/// Switches the C library to de_DE.UTF-8 for one test and back; fails (never skips) without it.
class GermanLocale {
public:
    GermanLocale()
    {
        const char* old = std::setlocale(LC_ALL, nullptr);
        m_old = old ? old : "C";
        m_ok = std::setlocale(LC_ALL, "de_DE.UTF-8") != nullptr;
    }
    ~GermanLocale() { std::setlocale(LC_ALL, m_old.c_str()); }
    bool ok() const { return m_ok; }

private:
    std::string m_old;
    bool m_ok = false;
};

void expectFormats()
{
    EXPECT_EQ(formatShortest(0.5), "0.5");
    EXPECT_EQ(formatShortest(4000.0), "4000");
    EXPECT_EQ(formatShortest(-1.25e-7), "-1.25e-07");
    EXPECT_EQ(formatShortest(0.1), "0.1");
    EXPECT_EQ(formatNumber(0.1, 17), "0.10000000000000001");
    EXPECT_EQ(formatNumber(0.5, 6), "0.5");
    EXPECT_EQ(formatNumber(1e-6, 6), "1e-06");
    EXPECT_EQ(formatNumber(123456789.0, 4), "1.235e+08");
    EXPECT_EQ(formatNumber(0.61019, 4), "0.6102");
    EXPECT_EQ(formatFixed(0.5, 3), "0.500");
    EXPECT_EQ(formatFixed(-12.345, 1), "-12.3");
    EXPECT_EQ(formatFixed(2.5, 0), "2");                // round half to even, as printf
    EXPECT_EQ(formatFixed(1234567.0, 2), "1234567.00"); // no grouping
    EXPECT_EQ(formatScientific(0.0015, 9), "1.500000000e-03");
    EXPECT_EQ(formatScientific(-2.0e10, 2), "-2.00e+10");
    EXPECT_EQ(formatShortest(std::numeric_limits<double>::infinity()), "inf");
}

TEST(Number, FormatsLikePrintfInTheCLocale)
{
    expectFormats();
}

TEST(Number, FormatsTheSameUnderACommaLocale)
{
    GermanLocale de;
    ASSERT_TRUE(de.ok()) << "the de_DE.UTF-8 locale is not installed (scripts/deps generates it)";
    // The locale is really active: printf writes a comma here.
    char buf[16];
    std::snprintf(buf, sizeof buf, "%g", 0.5);
    ASSERT_STREQ(buf, "0,5");
    expectFormats();
    EXPECT_EQ(parseNumber("0.5"), 0.5);
    EXPECT_FALSE(parseNumber("0,5"));
}

TEST(Number, ParsesWholeTextsOnly)
{
    EXPECT_EQ(parseNumber("0.5"), 0.5);
    EXPECT_EQ(parseNumber("+1e3"), 1000.0);
    EXPECT_EQ(parseNumber("-2.5E-3"), -0.0025);
    EXPECT_EQ(parseNumber("4000"), 4000.0);
    for (const char* bad : {"", "+", "-", "+-1", "0,5", " 1", "1 ", "1x", "0x10", "1e400", "nan", "inf", ".", "e3"})
        EXPECT_FALSE(parseNumber(bad)) << "'" << bad << "'";
    EXPECT_TRUE(std::isinf(parseNumber("inf", true).value()));
    EXPECT_TRUE(std::isnan(parseNumber("nan", true).value()));
    EXPECT_EQ(parseInteger("42"), 42);
    EXPECT_EQ(parseInteger("-7"), -7);
    EXPECT_EQ(parseInteger("+7"), 7);
    for (const char* bad : {"", "4.0", "1e3", "12a", "99999999999999999999"})
        EXPECT_FALSE(parseInteger(bad)) << "'" << bad << "'";
}

TEST(Number, ShortestAndSeventeenDigitsRoundTrip)
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> mant(-1.0, 1.0);
    std::uniform_int_distribution<int> ex(-300, 300);
    for (int i = 0; i < 10000; ++i) {
        const double v = std::ldexp(mant(rng), ex(rng));
        EXPECT_EQ(parseNumber(formatShortest(v)), v);
        EXPECT_EQ(parseNumber(formatNumber(v, 17)), v);
    }
}

} // namespace
} // namespace axistune::model
