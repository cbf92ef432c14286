// SPDX-License-Identifier: GPL-3.0-or-later
// The tool-mode fit on a real measured FRF (issue 19): H11 of ../shared/data/real/tooltip_frf_H11_H15.csv,
// the tool-tip point receptance of a tool holder (leekunhwee/Vibration-Signal-Processing,
// ExperimentalModalAnalysis). The data's author published (ExperimentalModalAnalysis/README.md, table of
// H11 peak values in µm/N, and the formulas ζ_k = (ω_2k − ω_1k)/(2ω_nk), k_k = −1/(2ζ_k H_k) there):
//   mode 1: f = 1074 Hz, real-part extremes 1031 / 1104 Hz → ζ = 0.03399, Im peak −0.6433 µm/N → k = 22.87 MN/m
//   mode 2: f = 1961 Hz, 1914 / 2092 Hz → ζ = 0.04539, Im −0.2138 µm/N → k = 51.53 MN/m
//   mode 3: f = 2617 Hz, 2546 / 2783 Hz → ζ = 0.04528, Im −0.2180 µm/N → k = 50.65 MN/m
// (Proj_3.m in the same folder computes ζ3 from the mode-2 frequencies, a copy slip; the README's table and
// formula are used here.) Tolerances from issue 19: frequencies 1.5 %, damping and stiffness 15 %.
#include "core/machining/StabilityLobes.h"
#include "core/machining/ToolModeFit.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <iostream>
#include <limits>
#include <numbers>

#include "tests/core/machining/RealToolFrf.h"
#include "tests/core/machining/ZeroOrderReference.h"

using namespace axistune;
using namespace axistune::machining;

namespace {

constexpr double kPi = std::numbers::pi;

struct Published {
    double hz, zeta, k;
};
Published published(double f, double f1, double f2, double imPeakUmPerN)
{
    const double zeta = (f2 - f1) / (2.0 * f);
    return {f, zeta, 1.0 / (2.0 * zeta * imPeakUmPerN * 1e-6)};
}
const Published kAuthor[3] = {published(1074, 1031, 1104, 0.6433), published(1961, 1914, 2092, 0.2138),
                              published(2617, 2546, 2783, 0.2180)};

void expectAuthorModes(const ToolModeFitResult& fit)
{
    ASSERT_EQ(fit.modes.size(), 3u);
    for (int j = 0; j < 3; ++j) {
        const auto& m = fit.modes[static_cast<std::size_t>(j)];
        const auto& a = kAuthor[j];
        EXPECT_NEAR(naturalFrequencyHz(m), a.hz, 0.015 * a.hz) << "mode " << j + 1;
        EXPECT_NEAR(dampingRatio(m), a.zeta, 0.15 * a.zeta) << "mode " << j + 1;
        EXPECT_NEAR(m.stiffnessNPerM, a.k, 0.15 * a.k) << "mode " << j + 1;
    }
}

} // namespace

TEST(ToolFitReal, H11AutomaticFitFindsTheAuthorsThreeModes)
{
    const auto frf = axistune::testing::readRealToolFrf(1);
    ASSERT_EQ(frf.size(), 5001u) << axistune::testing::kRealToolFrfCsv;
    auto fit = fitToolModes(frf);
    ASSERT_TRUE(fit.ok()) << fit.error().detail;
    EXPECT_TRUE(fit->automaticBand);
    expectAuthorModes(*fit);
    // The automatic band holds the three peaks and their flanks, not the low-frequency integration drift.
    EXPECT_GT(fit->bandMinHz, 500.0);
    EXPECT_LT(fit->bandMinHz, 1031.0);
    EXPECT_GT(fit->bandMaxHz, 2783.0);
    EXPECT_LT(fit->bandMaxHz, 3500.0);
    EXPECT_LT(fit->residualRatio, 0.30);
}

namespace {

// "Refused with a reason or right": a fit that is accepted must give the author's first mode (the one the
// requested mode count must contain) within the tolerances above.
void expectRefusedOrRight(const Result<ToolModeFitResult>& fit, const char* what)
{
    if (!fit.ok()) {
        EXPECT_NE(fit.error().detail.find("refused"), std::string::npos) << what << ": " << fit.error().detail;
        std::cout << what << ": " << fit.error().detail << "\n";
        return;
    }
    ASSERT_FALSE(fit->modes.empty()) << what;
    const auto& m = fit->modes.front();
    const auto& a = kAuthor[0];
    EXPECT_NEAR(naturalFrequencyHz(m), a.hz, 0.015 * a.hz) << what;
    EXPECT_NEAR(dampingRatio(m), a.zeta, 0.15 * a.zeta) << what;
    EXPECT_NEAR(m.stiffnessNPerM, a.k, 0.15 * a.k) << what;
}

} // namespace

TEST(ToolFitReal, H11WholeFileOneModeIsRefusedOrRight)
{
    const auto frf = axistune::testing::readRealToolFrf(1);
    ASSERT_EQ(frf.size(), 5001u);
    auto fit = fitToolModes(frf, {.modes = 1, .minHz = 0.0, .maxHz = 5000.0});
    expectRefusedOrRight(fit, "whole file, one mode");
}

TEST(ToolFitReal, H11WholeFileTwoModesIsRefusedOrRight)
{
    const auto frf = axistune::testing::readRealToolFrf(1);
    ASSERT_EQ(frf.size(), 5001u);
    auto fit = fitToolModes(frf, {.modes = 2, .minHz = 0.0, .maxHz = 5000.0});
    expectRefusedOrRight(fit, "whole file, two modes");
}

TEST(ToolFitReal, H11OneModeAutomaticBandIsRight)
{
    const auto frf = axistune::testing::readRealToolFrf(1);
    auto fit = fitToolModes(frf, {.modes = 1});
    ASSERT_TRUE(fit.ok()) << fit.error().detail;
    expectRefusedOrRight(fit, "one mode, automatic band");
    EXPECT_LT(fit->bandMaxHz, 1500.0); // the band of the strongest peak only
}

// The lobes of the machining wizard's default cut (4 teeth, K_t = 0.980 GPa, K_r = 0.294 GPa, a_e/D = 7/12,
// down milling; 2000–6000 min⁻¹ in 25 min⁻¹ steps, 80 steps per tooth period) with the automatically fitted
// H11 modes in x and y, against the zero-order limit computed directly on the measured H11 (the same
// receptance in x and y, no fit involved): the smallest limit depth agrees within 10 % (issue 19).
TEST(ToolFitReal, H11DefaultCutMinimumLimitAgreesWithZeroOrderOnTheMeasuredFrf)
{
    const auto frf = axistune::testing::readRealToolFrf(1);
    ASSERT_EQ(frf.size(), 5001u);
    auto fit = fitToolModes(frf);
    ASSERT_TRUE(fit.ok()) << fit.error().detail;
    CuttingConditions cut;
    cut.teeth = 4;
    cut.ktNPerM2 = 0.980e9;
    cut.krNPerM2 = 0.294e9;
    cut.radialImmersion = 7.0 / 12.0;
    cut.milling = MillingDirection::Down;
    const double st = std::acos(2.0 * cut.radialImmersion - 1.0);
    const auto k0 = axistune::testing::meanCuttingMatrix(cut.teeth, cut.ktNPerM2, cut.krNPerM2, st, kPi);
    // The measured receptance between 500 and 3500 Hz (the author's plots use 101–3500 Hz; below 500 Hz
    // the accelerometer's double integration dominates, and the ZOA minimum lies at the first mode).
    const auto zoa = axistune::testing::zoaMinimum(
        [&](const auto& visit) {
            for (std::size_t i = 0; i < frf.size(); ++i)
                if (frf.freqHz[i] >= 500.0 && frf.freqHz[i] <= 3500.0)
                    visit(2.0 * kPi * frf.freqHz[i], frf.h[i]);
        },
        k0);
    ASSERT_LT(zoa.depthM, 1.0);
    const ToolModes tool{fit->modes, fit->modes};
    auto grid = rpmGrid(2000.0, 6000.0, 25.0);
    ASSERT_TRUE(grid.ok());
    LobeOptions opt;
    opt.stepsPerPeriod = 80;
    auto lobes = stabilityLobes(tool, cut, *grid, opt);
    ASSERT_TRUE(lobes.ok()) << lobes.error().detail;
    double minDepth = std::numeric_limits<double>::infinity();
    for (const auto& p : *lobes)
        minDepth = std::min(minDepth, p.limitDepthM);
    std::cout << "ZOA on measured H11: " << zoa.depthM * 1e3 << " mm at " << zoa.omegaC / (2.0 * kPi)
              << " Hz; SDM minimum " << minDepth * 1e3 << " mm\n";
    EXPECT_NEAR(minDepth, zoa.depthM, 0.10 * zoa.depthM);
}
