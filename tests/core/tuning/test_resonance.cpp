// SPDX-License-Identifier: GPL-3.0-or-later
// Resonance detection: an analytic band-pass bump on a flat baseline (closed-form height and −3 dB
// width), and the dd-table-like velocity loop (spec/current-loop-and-multisweep-frf.md §3.8: modes at
// 600 Hz, 1 kHz, 3.3 kHz) sampled up to 3.9 kHz, clean and with noise and bad points.
#include "core/dsp/LoopAnalysis.h"
#include "core/tuning/Resonance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <numbers>
#include <random>

using namespace axistune;
using cd = std::complex<double>;

namespace {

constexpr double kPi = std::numbers::pi;

struct Mode {
    double fHz, zeta, inertia;
};
const Mode kModes[] = {{600.0, 0.03, 4.0}, {1000.0, 0.02, 2.5}, {3300.0, 0.015, 2.0}};

// Velocity loop like resources/machines/dd-table.json: PI 233 Nms/rad, 11700 Nm/rad on 1.238 kgm²,
// collocated modes s/(J_k(s²+2ζωs+ω²)), a 375 µs delay and a 1.6 kHz current-loop lag.
cd openLoop(double f, bool withModes = true)
{
    const cd s(0.0, 2.0 * kPi * f);
    cd p = 1.0 / (1.238 * s);
    if (withModes)
        for (const auto& m : kModes) {
            const double w = 2.0 * kPi * m.fHz;
            p += s / (m.inertia * (s * s + 2.0 * m.zeta * w * s + w * w));
        }
    return (233.0 + 11700.0 / s) * p * std::exp(-s * 375e-6) / (1.0 + s / (2.0 * kPi * 1600.0));
}

dsp::FrequencyResponse logGrid(int n, double f0, double f1, const std::function<cd(double)>& h)
{
    dsp::FrequencyResponse r;
    for (int i = 0; i < n; ++i) {
        const double f = f0 * std::pow(f1 / f0, static_cast<double>(i) / (n - 1));
        r.push(f, h(f), std::nan(""), true);
    }
    return r;
}

}  // namespace

// |1 + a·B(f)| with B = 1/(1 + jQ(f/fn − fn/f)): peak fn, height 20log10(1+a), −3 dB width
// 2ζ·fn·(1+a)/sqrt((1+a)² − 2) (from |1+a+ju|² /(1+u²) = (1+a)²/2).
TEST(Resonance, AnalyticBumpOnFlatBaseline)
{
    const double fn = 800.0, zeta = 0.005, a = 9.0, q = 1.0 / (2.0 * zeta);
    const auto frf = logGrid(3000, 10.0, 4000.0, [&](double f) { return 1.0 + a / cd(1.0, q * (f / fn - fn / f)); });
    auto r = tuning::findResonances(frf);
    ASSERT_TRUE(r.ok()) << r.error().detail;
    ASSERT_EQ(r->size(), 1U);
    const auto& p = r->front();
    EXPECT_NEAR(p.freqHz, fn, 0.001 * fn);
    // Tails of the bump raise the robust baseline slightly (≈ 0.4 dB here).
    EXPECT_NEAR(p.peakDb, 20.0 * std::log10(1.0 + a), 0.5);
    const double width = 2.0 * zeta * fn * (1.0 + a) / std::sqrt((1.0 + a) * (1.0 + a) - 2.0);
    EXPECT_NEAR(p.widthHz, width, 0.03 * width);
    EXPECT_FALSE(p.widthOneSided);
}

TEST(Resonance, DdTableLoopThreeModesWithinTwoPercent)
{
    const auto t = logGrid(800, 10.0, 3900.0, [](double f) { const cd l = openLoop(f); return l / (1.0 + l); });
    const auto l = dsp::openLoopFromClosedLoop(t, dsp::LoopMeasurement::Complementary);
    auto r = tuning::findResonances(l);
    ASSERT_TRUE(r.ok()) << r.error().detail;
    ASSERT_EQ(r->size(), 3U);
    for (std::size_t k = 0; k < 3; ++k) {
        const auto& p = (*r)[k];
        EXPECT_NEAR(p.freqHz, kModes[k].fHz, 0.02 * kModes[k].fHz) << k;
        EXPECT_GE(p.peakDb, 6.0);
        // Half-power width of a lightly damped mode ≈ 2ζ f (the baseline changes it a little).
        EXPECT_NEAR(p.widthHz, 2.0 * kModes[k].zeta * kModes[k].fHz, 0.3 * 2.0 * kModes[k].zeta * kModes[k].fHz) << k;
        EXPECT_NEAR(p.levelDb, 20.0 * std::log10(std::abs(openLoop(p.freqHz))), 0.5) << k;
    }
}

TEST(Resonance, NoiseBadPointsAndLowCoherenceIgnored)
{
    std::mt19937 rng(11);
    std::normal_distribution<double> nd(0.0, 0.01);
    auto t = logGrid(800, 10.0, 3900.0, [](double f) { const cd l = openLoop(f); return l / (1.0 + l); });
    for (std::size_t i = 0; i < t.size(); ++i) {
        t.h[i] *= cd(1.0 + nd(rng), nd(rng));
        t.coherence[i] = 0.98;
    }
    // Spikes that must not count: an invalid point at ~200 Hz, a low-coherence one at ~2 kHz.
    const auto near = [&](double f) {
        std::size_t best = 0;
        for (std::size_t i = 0; i < t.size(); ++i)
            if (std::abs(t.freqHz[i] - f) < std::abs(t.freqHz[best] - f))
                best = i;
        return best;
    };
    t.h[near(200.0)] *= 10.0;
    t.valid[near(200.0)] = false;
    t.h[near(2000.0)] *= 10.0;
    t.coherence[near(2000.0)] = 0.2;
    const auto l = dsp::openLoopFromClosedLoop(t, dsp::LoopMeasurement::Complementary);
    auto r = tuning::findResonances(l);
    ASSERT_TRUE(r.ok()) << r.error().detail;
    ASSERT_EQ(r->size(), 3U);
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR((*r)[k].freqHz, kModes[k].fHz, 0.02 * kModes[k].fHz) << k;

    // The same spike at a valid, coherent point IS a (one-point) peak: the filters above matter.
    t.valid[near(200.0)] = true;
    auto r2 = tuning::findResonances(dsp::openLoopFromClosedLoop(t, dsp::LoopMeasurement::Complementary));
    ASSERT_TRUE(r2.ok());
    EXPECT_EQ(r2->size(), 4U);
}

TEST(Resonance, RigidLoopHasNone)
{
    const auto l = logGrid(800, 10.0, 3900.0, [](double f) { return openLoop(f, false); });
    auto r = tuning::findResonances(l);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r->empty());
}

TEST(Resonance, TooFewUsablePointsIsAnError)
{
    auto l = logGrid(10, 10.0, 100.0, [](double f) { return openLoop(f); });
    for (std::size_t i = 0; i < 6; ++i)
        l.valid[i] = false;
    auto r = tuning::findResonances(l);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::BadInput);
    EXPECT_NE(r.error().detail.find("4 usable points"), std::string::npos) << r.error().detail;
}
