// SPDX-License-Identifier: GPL-3.0-or-later
// Margins on sampled data versus the analytic loop L(s) = K e^{-sθ} / (s (τs + 1)).
#include "core/dsp/LoopAnalysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace axistune::dsp;
using cd = std::complex<double>;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kK = 600.0, kTau = 1e-3, kTheta = 0.4e-3;

cd loop(double fHz)
{
    const cd s(0.0, 2 * kPi * fHz);
    return kK * std::exp(-s * kTheta) / (s * (kTau * s + 1.0));
}

FrequencyResponse sampled(int n = 600)
{
    FrequencyResponse f;
    for (int i = 0; i < n; ++i) {
        const double hz = std::pow(10.0, 3.3 * i / (n - 1));  // 1 Hz … 2 kHz
        f.push(hz, loop(hz), std::nan(""), true);
    }
    return f;
}

// analytic references
double gainCrossoverRad()
{
    // K² = ω²(1 + τ²ω²) → ω² = (−1 + √(1 + 4τ²K²)) / (2τ²)
    return std::sqrt((-1.0 + std::sqrt(1.0 + 4 * kTau * kTau * kK * kK)) / (2 * kTau * kTau));
}
double phaseCrossoverRad()
{
    // π/2 + atan(τω) + θω = π, by bisection
    double lo = 1.0, hi = 1e5;
    for (int i = 0; i < 200; ++i) {
        const double m = 0.5 * (lo + hi);
        (kPi / 2 + std::atan(kTau * m) + kTheta * m < kPi ? lo : hi) = m;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

TEST(LoopAnalysis, MarginsMatchAnalyticLoop)
{
    const auto m = loopMargins(sampled());
    const double wc = gainCrossoverRad();
    const double pm = 180.0 - 90.0 - (std::atan(kTau * wc) + kTheta * wc) * 180 / kPi;
    const double wpc = phaseCrossoverRad();
    const double gm = -20 * std::log10(std::abs(loop(wpc / (2 * kPi))));
    ASSERT_EQ(m.gainCrossovers.size(), 1u);
    ASSERT_EQ(m.phaseCrossovers.size(), 1u);
    // grid: 600 log points over 3.3 decades (1.3 % steps); linear interpolation in log f is
    // second-order accurate, so 0.05 % in frequency, 0.02° and 0.01 dB are ample.
    EXPECT_NEAR(m.phaseMarginFreqHz, wc / (2 * kPi), 5e-4 * wc / (2 * kPi));
    EXPECT_NEAR(m.phaseMarginDeg, pm, 0.02);
    EXPECT_NEAR(m.gainMarginFreqHz, wpc / (2 * kPi), 5e-4 * wpc / (2 * kPi));
    EXPECT_NEAR(m.gainMarginDb, gm, 0.01);
    // peak sensitivity: dense analytic maximum; the sampled maximum lies within 0.5 % below it
    double ms = 0, msF = 0;
    for (int i = 0; i < 200000; ++i) {
        const double hz = std::pow(10.0, 3.3 * i / 199999.0);
        const double s = std::abs(1.0 / (1.0 + loop(hz)));
        if (s > ms) {
            ms = s;
            msF = hz;
        }
    }
    EXPECT_LE(m.peakSensitivity, ms + 1e-12);
    EXPECT_GT(m.peakSensitivity, 0.995 * ms);
    EXPECT_NEAR(m.peakSensitivityFreqHz, msF, 0.02 * msF);
    EXPECT_NEAR(m.peakSensitivityDb, 20 * std::log10(m.peakSensitivity), 1e-12);
}

TEST(LoopAnalysis, OpenLoopFromEachClosedLoopForm)
{
    const auto L = sampled(50);
    for (auto kind : {LoopMeasurement::Complementary, LoopMeasurement::NegComplementary, LoopMeasurement::Sensitivity}) {
        FrequencyResponse meas;
        for (std::size_t i = 0; i < L.size(); ++i) {
            const cd l = L.h[i];
            const cd v = kind == LoopMeasurement::Complementary ? l / (1.0 + l)
                         : kind == LoopMeasurement::NegComplementary ? -l / (1.0 + l)
                                                                     : 1.0 / (1.0 + l);
            meas.push(L.freqHz[i], v, 0.9, true);
        }
        const auto back = openLoopFromClosedLoop(meas, kind);
        ASSERT_EQ(back.size(), L.size());
        for (std::size_t i = 0; i < L.size(); ++i) {
            EXPECT_LT(std::abs(back.h[i] - L.h[i]), 1e-10 * std::abs(L.h[i])) << i;
            EXPECT_TRUE(back.valid[i]);
            EXPECT_EQ(back.coherence[i], 0.9);
        }
    }
    FrequencyResponse singular;
    singular.push(10.0, {1.0, 0.0}, std::nan(""), true);
    EXPECT_FALSE(openLoopFromClosedLoop(singular, LoopMeasurement::Complementary).valid[0]);
}

TEST(LoopAnalysis, InvalidPointsAreNotBridged)
{
    auto L = sampled();
    const auto m0 = loopMargins(L);
    // invalidate everything around the gain crossover
    for (std::size_t i = 0; i < L.size(); ++i) {
        if (std::abs(L.freqHz[i] - m0.phaseMarginFreqHz) < 0.1 * m0.phaseMarginFreqHz)
            L.valid[i] = false;
    }
    const auto m = loopMargins(L);
    EXPECT_TRUE(m.gainCrossovers.empty());
    EXPECT_TRUE(std::isinf(m.phaseMarginDeg));
    EXPECT_EQ(m.phaseCrossovers.size(), 1u);
}

TEST(LoopAnalysis, SmallestMarginOfSeveralCrossovers)
{
    // integrator with a lightly damped resonance that lifts |L| above 1 again near 800 Hz
    FrequencyResponse f;
    const double wr = 2 * kPi * 800, z = 0.01;
    for (int i = 0; i < 3000; ++i) {
        const double hz = std::pow(10.0, 3.3 * i / 2999.0);
        const cd s(0.0, 2 * kPi * hz);
        const cd l = 2 * kPi * 50 / s * (wr * wr) / (s * s + 2 * z * wr * s + wr * wr);
        f.push(hz, l, std::nan(""), true);
    }
    const auto m = loopMargins(f);
    EXPECT_EQ(m.gainCrossovers.size(), 3u);  // 50 Hz, then up and down around the resonance
    EXPECT_NEAR(m.gainCrossovers[0].freqHz, 50.0, 0.5);
    EXPECT_NEAR(m.gainCrossovers[0].marginDeg, 90.0, 0.5);
    for (const auto& c : m.gainCrossovers)
        EXPECT_GE(std::abs(c.marginDeg), std::abs(m.phaseMarginDeg));
    EXPECT_LT(std::abs(m.phaseMarginDeg), 90.0);
}
