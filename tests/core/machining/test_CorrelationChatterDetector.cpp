// SPDX-License-Identifier: GPL-3.0-or-later
// V-004-01/02 of spec/cutting-force-observer-and-chatter-detection.md §3.9 (table of §2.4): 1-DOF ω_n = 1,
// ζ = 0.05, steady-state response computed here analytically, integer-period windows.
#include "core/machining/CorrelationChatterDetector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

using namespace axistune::machining;

namespace {
struct Tone {
    double w, amp;
};
CorrelationSample runWindow(const std::vector<Tone>& tones, double period)
{
    const std::size_t n = 20000;
    CorrelationChatterDetector det(n);
    CorrelationSample last;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = period * static_cast<double>(i) / n;
        double f = 0, x = 0, a = 0;
        for (const auto& tone : tones) {
            const std::complex<double> g = 1.0 / std::complex<double>(1.0 - tone.w * tone.w, 2.0 * 0.05 * tone.w);
            f += tone.amp * std::sin(tone.w * t);
            const double xi = tone.amp * std::abs(g) * std::sin(tone.w * t + std::arg(g));
            x += xi;
            a += -tone.w * tone.w * xi;
        }
        last = det.step(f, x, a);
    }
    return last;
}
}  // namespace

TEST(CorrelationChatterDetector, SingleToneTable)
{
    const double cases[][2] = {{0.30, 0.9995}, {0.90, 0.9037}, {0.95, 0.7162}, {1.05, -0.6985}, {1.50, -0.9929}};
    for (const auto& c : cases) {
        const auto s = runWindow({{c[0], 1.0}}, 2.0 * std::numbers::pi / c[0]);
        ASSERT_TRUE(s.valid);
        EXPECT_NEAR(s.rFx, c[1], 1e-3) << c[0];
        EXPECT_NEAR(s.rFa, -c[1], 1e-3) << c[0];
        EXPECT_EQ(s.chatter, c[0] > 1.0) << c[0];
    }
}

TEST(CorrelationChatterDetector, TwoTonesFlipBetween0p2And0p5)
{
    const double period = 20.0 * std::numbers::pi;  // 5 periods of 0.5, 11 of 1.1
    const double cases[][3] = {{0.05, 0.9773, -0.7637}, {0.20, 0.7332, -0.1379}, {0.50, 0.1411, 0.2775}, {1.00, -0.3852, 0.5792}};
    for (const auto& c : cases) {
        const auto s = runWindow({{0.5, 1.0}, {1.1, c[0]}}, period);
        EXPECT_NEAR(s.rFx, c[1], 1e-3) << c[0];
        EXPECT_NEAR(s.rFa, c[2], 1e-3) << c[0];
        EXPECT_EQ(s.chatter, c[0] >= 0.5) << c[0];
    }
}

TEST(CorrelationChatterDetector, ZeroEnergyIsInvalid)
{
    CorrelationChatterDetector det(10, 1e-12);
    CorrelationSample s;
    for (int i = 0; i < 30; ++i)
        s = det.step(0.0, 0.0, 0.0);
    EXPECT_FALSE(s.valid);
    EXPECT_FALSE(s.chatter);
}
