// SPDX-License-Identifier: GPL-3.0-or-later
// Math channels of the scope (core/device/ScopeMath.h) against analytic results: the difference is exact,
// the derivative of a sine is the cosine within the central difference's error, the amplitude spectrum of
// a sine on a bin reads its amplitude at its frequency.
#include "core/device/ScopeMath.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune;
using namespace axistune::device;

namespace {
constexpr double kFs = 4000.0;
/// a = A sin(2π f t) + 0.5, b = 0.25 (units m), rows from sample 100.
ScopeCapture sine(double amp, double f, std::size_t rows)
{
    ScopeCapture c;
    c.rateHz = kFs;
    c.triggered = false;
    c.channels = {{"a_m", "m", ""}, {"b_m", "m", ""}, {"v_rad_s", "rad/s", ""}};
    c.columns.assign(3, {});
    for (std::size_t i = 0; i < rows; ++i) {
        const std::uint64_t n = 100 + i;
        c.samples.push_back(n);
        const double t = static_cast<double>(n) / kFs;
        c.columns[0].push_back(amp * std::sin(2 * std::numbers::pi * f * t) + 0.5);
        c.columns[1].push_back(0.25);
        c.columns[2].push_back(1.0);
    }
    return c;
}
} // namespace

TEST(ScopeMath, DifferenceIsExactAndNeedsOneUnit)
{
    const auto c = sine(2.0, 50.0, 400);
    auto d = scopeDifference(c, "a_m", "b_m");
    ASSERT_TRUE(d.ok()) << d.error().detail;
    EXPECT_EQ(d->info.unit, "m");
    EXPECT_EQ(d->info.name, "a_m − b_m");
    for (std::size_t i = 0; i < c.rows(); ++i)
        EXPECT_EQ(d->values[i], c.columns[0][i] - 0.25);
    auto bad = scopeDifference(c, "a_m", "v_rad_s");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().detail.find("different units"), std::string::npos);
    EXPECT_FALSE(scopeDifference(c, "a_m", "nope").ok());
}

TEST(ScopeMath, DerivativeOfASineIsTheCosine)
{
    const double amp = 2.0, f = 50.0, w = 2 * std::numbers::pi * f, h = 1.0 / kFs;
    const auto c = sine(amp, f, 400);
    auto d = scopeDerivative(c, "a_m");
    ASSERT_TRUE(d.ok()) << d.error().detail;
    EXPECT_EQ(d->info.unit, "m/s");
    // Central difference: (sin(w(t+h)) − sin(w(t−h)))/(2h) = A w cos(wt) · sin(wh)/(wh): relative error
    // 1 − sin(wh)/(wh) ≈ (wh)²/6 = 2.6e-4 at 50 Hz and 4 kHz; the ends (one-sided) are O(wh) = 0.08.
    const double rel = 1.0 - std::sin(w * h) / (w * h);
    for (std::size_t i = 1; i + 1 < c.rows(); ++i) {
        const double t = static_cast<double>(c.samples[i]) / kFs;
        EXPECT_NEAR(d->values[i], amp * w * std::cos(w * t) * (1.0 - rel), 1e-9 * amp * w);
    }
}

TEST(ScopeMath, SpectrumOfASineOnABinReadsItsAmplitude)
{
    // 800 rows at 4 kHz: 5 Hz bins; 250 Hz is bin 50.
    const double amp = 0.003;
    const auto c = sine(amp, 250.0, 1000);
    auto s = scopeSpectrum(c, "a_m", 100, 800);
    ASSERT_TRUE(s.ok()) << s.error().detail;
    EXPECT_DOUBLE_EQ(s->resolutionHz, 5.0);
    ASSERT_EQ(s->freqHz.size(), 401u);
    const auto peak = std::max_element(s->amplitude.begin(), s->amplitude.end()) - s->amplitude.begin();
    EXPECT_EQ(s->freqHz[static_cast<std::size_t>(peak)], 250.0);
    // Hann window, coherent gain corrected: a sine on a bin reads A (within rounding), the mean is removed.
    EXPECT_NEAR(s->amplitude[static_cast<std::size_t>(peak)], amp, 1e-12);
    EXPECT_NEAR(s->amplitude[0], 0.0, 1e-12);
    // A gap in the window and a window too short are refused by name.
    auto gap = c;
    for (std::size_t i = 500; i < gap.samples.size(); ++i)
        gap.samples[i] += 3;
    auto g = scopeSpectrum(gap, "a_m", 100, 800);
    ASSERT_FALSE(g.ok());
    EXPECT_NE(g.error().detail.find("gap"), std::string::npos);
    EXPECT_FALSE(scopeSpectrum(c, "a_m", 0, 4).ok());
    EXPECT_FALSE(scopeSpectrum(c, "a_m", 900, 200).ok());
}
