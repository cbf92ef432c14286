// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/dsp/Excitation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace axistune;
using namespace axistune::dsp;

TEST(Excitation, SineStreamPlanSettleAndWholePeriods)
{
    SineStreamOptions o;
    o.freqHz = {10.0, 400.0, 3300.0};
    o.fsHz = 4000.0;
    o.amplitude = 0.5;
    o.amplitudeLimit = 1.0;
    o.settleTimeS = 0.05;
    o.settlePeriods = 3;
    o.periods = 4;
    o.minMeasureTimeS = 0.02;
    o.phaseOffsetsDeg = kMultiSweepOffsetsDeg;
    auto p = planSineStream(o);
    ASSERT_TRUE(p.ok());
    ASSERT_EQ(p->size(), 9u);
    // 10 Hz: settle max(0.05 s, 0.3 s) = 1200 samples; 4 periods = 1600 samples
    EXPECT_EQ((*p)[0].settleSamples, 1200u);
    EXPECT_EQ((*p)[0].measureSamples, 1600u);
    EXPECT_EQ((*p)[1].phaseOffsetDeg, 120.0);
    EXPECT_EQ((*p)[2].phaseOffsetDeg, -120.0);
    // 400 Hz: settle 0.05 s = 200 samples; max(4, ceil(0.02·400)=8) periods = 80 samples
    EXPECT_EQ((*p)[3].settleSamples, 200u);
    EXPECT_EQ((*p)[3].periods, 8u);
    EXPECT_EQ((*p)[3].measureSamples, 80u);
    // 3300 Hz: 66 periods (≥ 0.02 s) → round(66·4000/3300) = 80 samples
    EXPECT_EQ((*p)[6].periods, 66u);
    EXPECT_EQ((*p)[6].measureSamples, 80u);
    EXPECT_EQ(sineStreamLength(p.value()), 3u * (1200 + 1600 + 200 + 80 + 200 + 80));
    // value: 0.5 sin(2π·400·k/4000 + 120°)
    EXPECT_NEAR(sineStreamValue((*p)[4], 0.5, 3, 4000.0), 0.5 * std::sin(2 * std::numbers::pi * 0.3 + 2 * std::numbers::pi / 3), 1e-14);
}

TEST(Excitation, AmplitudeAboveLimitIsAnErrorNotAClamp)
{
    SineStreamOptions o;
    o.freqHz = {100.0};
    o.amplitude = 1.5;
    o.amplitudeLimit = 1.0;
    auto p = planSineStream(o);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(p.error().detail.find("exceeds"), std::string::npos);
    PrbsOptions pr;
    pr.amplitude = 2.0;
    pr.amplitudeLimit = 1.0;
    EXPECT_FALSE(makePrbs(pr).ok());
    ChirpOptions c{ChirpKind::Linear, 1.0, 100.0, 1.0, 1000.0, 2.0, 1.0};
    EXPECT_FALSE(makeChirp(c).ok());
    o.amplitude = 0.5;
    o.freqHz = {4000.0};
    EXPECT_FALSE(planSineStream(o).ok());  // f ≥ fs
    o.freqHz = {};
    EXPECT_FALSE(planSineStream(o).ok());
}

TEST(Excitation, PrbsIsMaximalLength)
{
    for (unsigned n : {3u, 7u, 10u, 12u}) {
        PrbsOptions o;
        o.order = n;
        o.amplitude = 1.0;
        o.amplitudeLimit = 1.0;
        auto s = makePrbs(o);
        ASSERT_TRUE(s.ok());
        const std::size_t N = (std::size_t{1} << n) - 1;
        ASSERT_EQ(s->size(), N);
        // an m-sequence has 2^(n-1) ones and circular autocorrelation N at lag 0, -1 elsewhere
        double sum = 0;
        for (double v : *s)
            sum += v;
        EXPECT_EQ(sum, 1.0) << n;
        for (std::size_t lag = 1; lag < N; lag += (N > 200 ? 37 : 1)) {
            double r = 0;
            for (std::size_t i = 0; i < N; ++i)
                r += (*s)[i] * (*s)[(i + lag) % N];
            EXPECT_EQ(r, -1.0) << "order " << n << " lag " << lag;
        }
    }
    PrbsOptions o;
    o.order = 4;
    o.holdSamples = 3;
    o.periods = 2;
    o.amplitude = 0.2;
    o.amplitudeLimit = 0.2;
    auto s = makePrbs(o);
    ASSERT_TRUE(s.ok());
    ASSERT_EQ(s->size(), 15u * 3 * 2);
    for (std::size_t i = 0; i < 45; ++i)
        EXPECT_EQ((*s)[i], (*s)[i + 45]);
    EXPECT_EQ((*s)[0], (*s)[2]);
}

TEST(Excitation, ChirpInstantaneousFrequency)
{
    const double fs = 10000.0, T = 2.0;
    for (auto kind : {ChirpKind::Linear, ChirpKind::Exponential}) {
        ChirpOptions o{kind, 10.0, 1000.0, T, fs, 1.0, 1.0};
        auto s = makeChirp(o);
        ASSERT_TRUE(s.ok());
        ASSERT_EQ(s->size(), 20000u);
        EXPECT_EQ((*s)[0], 0.0);
        // analytic value at t: sin(2π·cycles(t))
        for (std::size_t k : {1000u, 7777u, 19999u}) {
            const double t = k / fs;
            const double cycles = kind == ChirpKind::Linear
                                      ? 10.0 * t + 0.5 * 990.0 * t * t / T
                                      : 10.0 * T / std::log(100.0) * (std::pow(100.0, t / T) - 1.0);
            EXPECT_NEAR((*s)[k], std::sin(2 * std::numbers::pi * cycles), 1e-9);
        }
    }
    ChirpOptions bad{ChirpKind::Linear, 10.0, 6000.0, 1.0, 10000.0, 1.0, 1.0};
    EXPECT_FALSE(makeChirp(bad).ok());  // above fs/2
    ChirpOptions badExp{ChirpKind::Exponential, 0.0, 100.0, 1.0, 10000.0, 1.0, 1.0};
    EXPECT_FALSE(makeChirp(badExp).ok());
}
