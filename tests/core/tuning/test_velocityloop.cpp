// SPDX-License-Identifier: GPL-3.0-or-later
// Velocity PI and position gain: spec/lost-motion-and-two-inertia.md §2.8 / §4.12 (K_P = 11.24,
// K_I = 1198, crossover ≈ 343 Hz, PM ≈ 88.5°, |L(22 Hz)| = +4.9 dB) and §2.11 (position limits).
#include "core/tuning/VelocityLoop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace axistune::tuning;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

TwoInertiaParams table51() { return TwoInertiaParams{0.00527, 0.0105, 200.0, 0.27, 1.1e-3}; }

axistune::dsp::FrequencyResponse plantFrf(const TwoInertiaParams& p)
{
    axistune::dsp::FrequencyResponse frf;
    for (int i = 0; i < 4000; ++i) {
        const double f = std::pow(10.0, 4.0 * i / 3999.0);
        frf.push(f, motorVelocityResponse(p, f), 1.0, true);
    }
    return frf;
}

}  // namespace

TEST(VelocityLoop, CorrectedThesisRule)
{
    const auto pi = velocityPiFromInertia(0.00527, kTwoPi * 24.0, 10.0);
    EXPECT_NEAR(pi.kpNmsPerRad, 11.24, 0.005);
    EXPECT_NEAR(pi.kiNmPerRad, 1198.0, 0.5);
}

TEST(VelocityLoop, MarginsOnTable51WithoutDelay)
{
    TwoInertiaParams p = table51();
    p.delayS = 0.0;  // §2.7: the 1.1 ms is a measurement delay, not in the loop
    const auto pi = velocityPiFromInertia(p.jmKgm2, kTwoPi * 24.0, 10.0);
    const auto frf = plantFrf(p);
    std::vector<std::complex<double>> L;
    for (std::size_t i = 0; i < frf.size(); ++i) {
        L.push_back(piResponse(pi, frf.freqHz[i]) * frf.h[i]);
    }
    const auto m = loopMargins(frf.freqHz, L);
    EXPECT_NEAR(m.crossoverHz, 343.0, 2.0);
    EXPECT_NEAR(m.phaseMarginDeg, 88.5, 0.3);
    EXPECT_NEAR(20.0 * std::log10(std::abs(piResponse(pi, 22.0) * motorVelocityResponse(p, 22.0))), 4.9, 0.1);
}

TEST(VelocityLoop, PiFromMarginsInvertsTheRule)
{
    TwoInertiaParams p = table51();
    p.delayS = 0.0;
    auto pi = velocityPiFromFrf(plantFrf(p), 343.0, 88.5);
    ASSERT_TRUE(pi.ok()) << pi.error().detail;
    EXPECT_NEAR(pi->kpNmsPerRad, 11.24, 0.01 * 11.24);
    EXPECT_NEAR(pi->kiNmPerRad, 1198.0, 0.05 * 1198.0);
    // A phase margin that needs phase lead is refused.
    EXPECT_FALSE(velocityPiFromFrf(plantFrf(p), 343.0, 120.0).ok());
    EXPECT_FALSE(velocityPiFromFrf(plantFrf(p), 50000.0, 60.0).ok());
}

TEST(VelocityLoop, PositionGainLimits)
{
    // §2.11 [DERIVED] linear-model limits (Table 5.1, K_v of corrected 5.13, no delay):
    // conventional full-closed ≈ 33 s⁻¹; with F_L(17 Hz, 0.14, 13 ms) > 500 s⁻¹; semi-closed no
    // finite limit up to 5000 s⁻¹.
    const auto p = table51();
    const auto pi = velocityPiFromInertia(p.jmKgm2, kTwoPi * 24.0, 10.0);
    const auto full = positionGain(p, pi, FeedbackMode::Full, std::nullopt, false, 6.0);
    EXPECT_NEAR(full.limitPerS, 33.0, 1.5);
    EXPECT_NEAR(full.recommendedPerS, full.limitPerS / 2.0, 0.01 * full.limitPerS);
    const SuppressionFilter fl{SuppressionMode::Full, 17.0, 0.14, 0.013};
    const auto withFl = positionGain(p, pi, FeedbackMode::Full, fl, false, 6.0);
    EXPECT_GT(withFl.limitPerS, 500.0);
    const auto semi = positionGain(p, pi, FeedbackMode::Semi, std::nullopt, false, 6.0);
    EXPECT_GT(semi.limitPerS, 5000.0);
}
