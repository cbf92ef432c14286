// SPDX-License-Identifier: GPL-3.0-or-later
// Velocity-step prediction (core/tuning/VelocityStep.h) against the analytic continuous step of a PI
// on a rigid inertia, T(s) = (K_P s + K_I)/(J s² + K_P s + K_I) = 1 − L⁻¹[s/(s² + b s + c)],
// b = K_P/J, c = K_I/J (σ = b/2): under-damped y = 1 − e^{−σt}(cos ω_d t − σ/ω_d sin ω_d t),
// over-damped with cosh/sinh and λ = √(σ² − c). A short period approaches the continuous loop.
#include "core/tuning/VelocityStep.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace axistune::tuning;

namespace {

double analytic(double b, double c, double t)
{
    const double s = b / 2.0;
    if (s * s < c) {
        const double wd = std::sqrt(c - s * s);
        return 1.0 - std::exp(-s * t) * (std::cos(wd * t) - s / wd * std::sin(wd * t));
    }
    const double l = std::sqrt(s * s - c);
    return 1.0 - std::exp(-s * t) * (std::cosh(l * t) - s / l * std::sinh(l * t));
}

void compareRigid(double j, VelocityPi pi, double tol)
{
    TwoInertiaParams p;
    p.jmKgm2 = j; // K = 0: rigid
    const double period = 2e-6;
    auto r = predictVelocityStep(p, pi, period, 1.0, 0.0, 0.1);
    ASSERT_TRUE(r.ok()) << r.error().detail;
    const double b = pi.kpNmsPerRad / j, c = pi.kiNmPerRad / j;
    double worst = 0.0;
    for (std::size_t k = 0; k < r->tS.size(); k += 50)
        // The sampled loop lags the continuous one by about one period.
        worst = std::max(worst, std::abs(r->motorVelRadS[k] - analytic(b, c, r->tS[k] - period)));
    EXPECT_LT(worst, tol);
}

} // namespace

TEST(VelocityStep, RigidUnderDampedMatchesAnalytic)
{
    // b = 100 1/s, c = 1e4 1/s²: ζ = 0.5, overshoot 16 %.
    compareRigid(2e-3, {0.2, 20.0}, 2e-3);
}

TEST(VelocityStep, RigidChapter5RuleMatchesAnalytic)
{
    // K_P = k√2 ω_l J, K_I = k ω_l² J with k = 10, ω_l = 2π·24: over-damped (σ² = 50 ω_l² > 10 ω_l²).
    const double j = 5.27e-3, wl = 2.0 * M_PI * 24.0;
    compareRigid(j, velocityPiFromInertia(j, wl, 10.0), 5e-3);
}

TEST(VelocityStep, TwoInertiaSettlesToTheCommandOnBothSides)
{
    TwoInertiaParams p{5.27e-3, 1.05e-2, 200.0, 0.27, 0.0};
    const auto pi = velocityPiFromInertia(p.jmKgm2, 2.0 * M_PI * 24.0, 10.0);
    auto r = predictVelocityStep(p, pi, 250e-6, 2.0, 0.01, 1.0);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->tS.size(), 4001U);
    EXPECT_NEAR(r->motorVelRadS.back(), 2.0, 1e-3);
    EXPECT_NEAR(r->loadVelRadS.back(), 2.0, 1e-3);
    EXPECT_DOUBLE_EQ(r->motorVelRadS[39], 0.0); // before the step at 10 ms
}

TEST(VelocityStep, RefusesBadInput)
{
    TwoInertiaParams p;
    EXPECT_FALSE(predictVelocityStep(p, {1.0, 1.0}, 1e-3, 1.0, 0.0, 0.1).ok()); // J_m = 0
    p.jmKgm2 = 1e-3;
    EXPECT_FALSE(predictVelocityStep(p, {1.0, 1.0}, 0.0, 1.0, 0.0, 0.1).ok());
    EXPECT_FALSE(predictVelocityStep(p, {NAN, 1.0}, 1e-3, 1.0, 0.0, 0.1).ok());
}
