// SPDX-License-Identifier: GPL-3.0-or-later
// The exponential window's damping removed from fitted modes (core/machining/ExponentialWindow).
#include "core/machining/ExponentialWindow.h"

#include <cmath>
#include <complex>
#include <gtest/gtest.h>

using namespace axistune;

TEST(ExponentialWindow, WindowedModeMapsBackExactly)
{
    // H_w(s) = H(s + σ): evaluate both at a few s to check the algebra of the header, then invert.
    const machining::ModalParameters m{0.4, 83.0, 30.1e6};
    const double sigma = 25.0;
    const machining::ModalParameters w{m.massKg, m.dampingNsPerM + 2.0 * m.massKg * sigma,
                                       m.stiffnessNPerM + m.dampingNsPerM * sigma + m.massKg * sigma * sigma};
    for (double omega : {100.0, 5000.0, 8700.0}) {
        const std::complex<double> s(0.0, omega);
        const auto hw = 1.0 / (w.massKg * s * s + w.dampingNsPerM * s + w.stiffnessNPerM);
        const auto sp = s + sigma;
        const auto h = 1.0 / (m.massKg * sp * sp + m.dampingNsPerM * sp + m.stiffnessNPerM);
        EXPECT_NEAR(std::abs(hw - h), 0.0, 1e-12 * std::abs(h));
    }
    auto back = machining::removeExponentialWindow(w, sigma);
    ASSERT_TRUE(back) << back.error().detail;
    EXPECT_NEAR(back->massKg, m.massKg, 1e-15);
    EXPECT_NEAR(back->dampingNsPerM, m.dampingNsPerM, 1e-9 * m.dampingNsPerM);
    EXPECT_NEAR(back->stiffnessNPerM, m.stiffnessNPerM, 1e-9 * m.stiffnessNPerM);
}

TEST(ExponentialWindow, MoreWindowDampingThanTheModeIsRefused)
{
    auto r = machining::removeExponentialWindow({0.4, 10.0, 3e7}, 20.0); // 2mσ = 16 > 10
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().detail.find("longer time constant"), std::string::npos);
    dsp::FrequencyResponse frf;
    frf.metadata.set("exp_window_decay_1_s", "abc");
    EXPECT_FALSE(machining::exponentialWindowDecay(frf));
    frf.metadata.set("exp_window_decay_1_s", "12.5");
    ASSERT_TRUE(machining::exponentialWindowDecay(frf));
    EXPECT_EQ(*machining::exponentialWindowDecay(frf), 12.5);
}
