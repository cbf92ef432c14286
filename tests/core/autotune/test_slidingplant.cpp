// SPDX-License-Identifier: GPL-3.0-or-later
// The plant in motion from the plant at standstill (core/autotune/SlidingPlant.h), against analytic plants: a rigid
// body with a damper, and two masses on a damped spring, whose 1/P is written out here term by term.
#include "core/autotune/SlidingPlant.h"

#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune;
using cd = std::complex<double>;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

dsp::FrequencyResponse sampled(double f0, double df, int n, const auto& plant)
{
    dsp::FrequencyResponse r;
    for (int i = 0; i < n; ++i) {
        const double f = f0 + df * i;
        r.push(f, plant(cd(0.0, kTwoPi * f)), std::nan(""), true);
    }
    return r;
}

} // namespace

TEST(SlidingPlant, RigidBodyWithADamperGivesItsDampingAndInertiaAndTheUndampedPlant)
{
    // P = 1/(J s + b): Re(1/P) = b and Im(1/P)/w = J on every line, exactly.
    const double j = 2.2e-3, b = 25.0;
    const auto p = sampled(20.0, 10.0, 40, [&](cd s) { return 1.0 / (j * s + b); });
    auto d = autotune::standstillDamping(p);
    ASSERT_TRUE(d.ok()) << d.error().detail;
    EXPECT_NEAR(d->bNmsPerRad, b, 1e-9 * b);
    EXPECT_NEAR(d->inertiaKgm2, j, 1e-9 * j);
    // Lines up to 3 x the lowest (20 Hz): 20, 30, ..., 60 Hz.
    EXPECT_EQ(d->lines, 5u);
    EXPECT_DOUBLE_EQ(d->upToHz, 60.0);
    // P/(1 - bP) = 1/(J s) on every line.
    for (std::size_t i = 0; i < p.size(); ++i) {
        const cd expected = 1.0 / (j * cd(0.0, kTwoPi * p.freqHz[i]));
        EXPECT_LT(std::abs(autotune::slidingPlant(p.h[i], d->bNmsPerRad) - expected), 1e-9 * std::abs(expected));
    }
}

TEST(SlidingPlant, TwoMassesOnADampedSpringGiveTheMotorSideDampingBelowTheirResonance)
{
    // vmc X's two masses (resources/machines/vmc.json: J_m 1.1818e-3, J_L 1.02133e-3, K 337.1 N m/rad,
    // c 0.043 N m s/rad) with a motor-side damper b. 1/P = J_m s + b + J_L s (c s + K)/(J_L s^2 + c s + K): the load's
    // term adds to Re(1/P) only through c, by c (J_L w^2)^2 / ((K - J_L w^2)^2 + (c w)^2) (its real part, written
    // out), which is 0.0244 N m s/rad at 60 Hz and less below (the resonance is at 124 Hz): b = 1.5 is read within 2 %.
    const double jm = 1.1818e-3, jl = 1.02133e-3, k = 337.1, c = 0.043, b = 1.5;
    const auto p = sampled(20.0, 10.0, 60,
                           [&](cd s) { return 1.0 / (jm * s + b + jl * s * (c * s + k) / (jl * s * s + c * s + k)); });
    auto d = autotune::standstillDamping(p);
    ASSERT_TRUE(d.ok()) << d.error().detail;
    const double w = kTwoPi * 60.0;
    const double loadRe = c * std::pow(jl * w * w, 2) / (std::pow(k - jl * w * w, 2) + std::pow(c * w, 2));
    EXPECT_LT(loadRe, 0.025);
    EXPECT_GE(d->bNmsPerRad, b);
    EXPECT_LE(d->bNmsPerRad, b + loadRe);
    // Below the resonance the two masses move together, the load's share raised by K/(K - J_L w^2) (1.76 at 60 Hz):
    // between J_m + J_L and J_m + 1.76 J_L.
    EXPECT_GE(d->inertiaKgm2, jm + jl);
    EXPECT_LE(d->inertiaKgm2, jm + 1.76 * jl);
}

TEST(SlidingPlant, TooFewLinesOrNoInertiaAreRefused)
{
    const auto two = sampled(20.0, 10.0, 2, [](cd s) { return 1.0 / (1e-3 * s + 1.0); });
    auto a = autotune::standstillDamping(two);
    ASSERT_FALSE(a.ok());
    EXPECT_NE(a.error().detail.find("fewer than 3 valid lines"), std::string::npos);
    // A spring (1/P = K/s: Im(1/P) < 0) is not the plant of an inertia.
    const auto spring = sampled(20.0, 10.0, 10, [](cd s) { return s / 100.0; });
    auto b = autotune::standstillDamping(spring);
    ASSERT_FALSE(b.ok());
    EXPECT_NE(b.error().detail.find("not those of an inertia"), std::string::npos);
    // Invalid lines are not read: the three valid ones of five.
    auto p = sampled(20.0, 10.0, 5, [](cd s) { return 1.0 / (1e-3 * s + 2.0); });
    p.valid[1] = false;
    p.h[1] = cd(std::nan(""), 0.0);
    auto d = autotune::standstillDamping(p);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->lines, 4u);
    EXPECT_NEAR(d->bNmsPerRad, 2.0, 1e-12);
}
