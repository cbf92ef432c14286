// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/dsp/FrequencyResponse.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace axistune::dsp;

TEST(FrequencyResponse, MagnitudeAndPhaseOfKnownValues)
{
    EXPECT_NEAR(magnitudeDb({10.0, 0.0}), 20.0, 1e-12);
    EXPECT_NEAR(magnitudeDb({0.0, 0.1}), -20.0, 1e-12);
    EXPECT_TRUE(std::isinf(magnitudeDb({0.0, 0.0})));
    EXPECT_NEAR(phaseDeg({0.0, 1.0}), 90.0, 1e-12);
    EXPECT_NEAR(phaseDeg({-1.0, -1.0}), -135.0, 1e-12);
    EXPECT_NEAR(phaseDeg({-1.0, 0.0}), 180.0, 1e-12);
    EXPECT_NEAR(phaseDeg({-1.0, -0.0}), 180.0, 1e-12);  // (-180, 180]
}

TEST(FrequencyResponse, UnwrapRemovesWholeTurnsOnly)
{
    // A pure delay of 1 ms sampled every 100 Hz: true phase -36°·k.
    std::vector<double> wrapped, truth;
    for (int k = 0; k < 30; ++k) {
        const double p = -36.0 * k;
        truth.push_back(p);
        wrapped.push_back(phaseDeg(std::polar(1.0, p * M_PI / 180.0)));
    }
    const auto u = unwrapDeg(wrapped);
    ASSERT_EQ(u.size(), truth.size());
    for (std::size_t i = 0; i < u.size(); ++i)
        EXPECT_NEAR(u[i], truth[i], 1e-9) << i;
}

TEST(FrequencyResponse, PushKeepsArraysAligned)
{
    FrequencyResponse f;
    f.push(1.0, {1.0, 0.0}, std::nan(""), true);
    f.push(2.0, {0.0, 1.0}, 0.5, false);
    EXPECT_EQ(f.size(), 2u);
    EXPECT_EQ(f.h.size(), 2u);
    EXPECT_TRUE(std::isnan(f.coherence[0]));
    EXPECT_FALSE(f.valid[1]);
    const auto ph = unwrappedPhaseDeg(f);
    EXPECT_NEAR(ph[1], 90.0, 1e-12);
}
