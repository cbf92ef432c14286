// SPDX-License-Identifier: GPL-3.0-or-later
// Figures of a measured current step (core/tuning/CurrentStep.h) against closed forms: a first-order
// step 1 − e^{−t/τ} has the 10–90 % rise time τ·ln 9; the underdamped second-order step peaks at
// 1 + e^{−ζπ/√(1−ζ²)}. The capture parser finds the step sample and normalises by the signed amplitude.
#include "core/tuning/CurrentStep.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune;
using namespace axistune::tuning;

TEST(CurrentStepFigures, FirstOrderRiseTimeIsTauLn9)
{
    const double tau = 50e-6, h = 1e-7;
    std::vector<double> t, y;
    for (int k = 0; k < 20000; ++k) {
        t.push_back(k * h);
        y.push_back(1.0 - std::exp(-k * h / tau));
    }
    const auto f = stepFigures(t, y);
    EXPECT_NEAR(f.riseTimeS, tau * std::log(9.0), 1e-3 * tau); // interpolation error ≪ h
    EXPECT_EQ(f.overshoot, 0.0);
}

TEST(CurrentStepFigures, SecondOrderOvershootIsTheClosedForm)
{
    const double zeta = 0.3, wn = 2.0 * std::numbers::pi * 1000.0, wd = wn * std::sqrt(1.0 - zeta * zeta);
    std::vector<double> t, y;
    for (int k = 0; k < 50000; ++k) {
        const double s = k * 1e-7;
        t.push_back(s);
        y.push_back(1.0 - std::exp(-zeta * wn * s) * (std::cos(wd * s) + zeta * wn / wd * std::sin(wd * s)));
    }
    const auto f = stepFigures(t, y);
    EXPECT_NEAR(f.overshoot, std::exp(-zeta * std::numbers::pi / std::sqrt(1.0 - zeta * zeta)), 1e-6);
    // No 90 % crossing: NaN, never a number made up.
    EXPECT_TRUE(std::isnan(stepFigures({0.0, 1.0, 2.0}, {0.0, 0.5, 0.8}).riseTimeS));
}

TEST(CurrentStepFigures, CaptureParserFindsTheStepAndNormalises)
{
    model::Capture cap;
    std::vector<double> t, cmd, i;
    for (int k = 0; k < 10; ++k) {
        t.push_back(1.0 + k * 62.5e-6);
        cmd.push_back(k >= 4 ? -4.0 : 0.0);
        i.push_back(k >= 5 ? -2.0 * (k - 4) : 0.0);
    }
    cap.channels = {{"t_s", t}, {"current_cmd_A", cmd}, {"current_A", i}};
    auto m = currentStepFromCapture(cap);
    ASSERT_TRUE(m.ok()) << m.error().detail;
    EXPECT_EQ(m->amplitudeA, -4.0);
    EXPECT_DOUBLE_EQ(m->stepTimeS, t[4]);
    EXPECT_NEAR(m->periodS, 62.5e-6, 1e-12);
    ASSERT_EQ(m->tS.size(), 6u);
    EXPECT_EQ(m->tS[0], 0.0);
    EXPECT_DOUBLE_EQ(m->normalised[2], 1.0); // −4 A / −4 A
    const auto d = compareSteps(m->normalised, {0.0, 0.5, 1.0, 1.5, 2.0, 2.0, 9.0});
    EXPECT_EQ(d.samples, 6u);
    EXPECT_DOUBLE_EQ(d.maxAbs, 0.5);

    model::Capture noStep = cap;
    noStep.channels[1].data.assign(10, 0.0);
    auto e = currentStepFromCapture(noStep);
    ASSERT_FALSE(e.ok());
    EXPECT_NE(e.error().detail.find("never leaves 0"), std::string::npos);
    model::Capture noChannel;
    noChannel.channels = {{"t_s", t}, {"current_cmd_A", cmd}};
    e = currentStepFromCapture(noChannel);
    ASSERT_FALSE(e.ok());
    EXPECT_NE(e.error().detail.find("current_A"), std::string::npos);
}
