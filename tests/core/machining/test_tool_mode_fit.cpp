// SPDX-License-Identifier: GPL-3.0-or-later
// Modal fit of a tool-tip receptance FRF (issue 10 item 1). The FRFs are evaluated analytically here
// from H(ω) = Σ 1/(k − mω² + jcω) (spec/chatter-stability-and-spindle-speed.md §1.3); the tool of
// Table 1 (seed 000): 0.40 kg, 83.0 N·s/m, 30.1 MN/m.
#include "core/machining/ToolModeFit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>

using namespace axistune;
using namespace axistune::machining;

namespace {

dsp::FrequencyResponse analyticFrf(const std::vector<ModalParameters>& modes, int n = 400, double f0 = 500.0, double f1 = 3000.0)
{
    dsp::FrequencyResponse frf;
    for (int i = 0; i < n; ++i) {
        const double f = f0 * std::pow(f1 / f0, static_cast<double>(i) / (n - 1));
        const double w = 2.0 * std::numbers::pi * f;
        std::complex<double> h = 0.0;
        for (const auto& m : modes)
            h += 1.0 / std::complex<double>(m.stiffnessNPerM - m.massKg * w * w, m.dampingNsPerM * w);
        frf.push(f, h, std::nan(""), true);
    }
    return frf;
}

void expectMode(const ModalParameters& got, const ModalParameters& want, double relTol)
{
    EXPECT_NEAR(got.massKg, want.massKg, relTol * want.massKg);
    EXPECT_NEAR(got.dampingNsPerM, want.dampingNsPerM, relTol * want.dampingNsPerM);
    EXPECT_NEAR(got.stiffnessNPerM, want.stiffnessNPerM, relTol * want.stiffnessNPerM);
}

const ModalParameters kTable1{0.40, 83.0, 30.1e6};
const ModalParameters kSecond{0.15, 60.0, 50e6};

}  // namespace

TEST(ToolModeFit, RecoversTable1ToolWithinHalfPercent)
{
    auto fit = fitToolModes(analyticFrf({kTable1}));
    ASSERT_TRUE(fit.ok()) << fit.error().detail;
    ASSERT_EQ(fit->modes.size(), 1u);
    expectMode(fit->modes[0], kTable1, 0.005);
    EXPECT_LT(fit->rmsRelativeError, 1e-6);
    // Automatic band: the half-power points of the one peak (f_n(1 ± ζ), ζ = 0.01196) widened by three
    // half-widths on each side, i.e. about f_n(1 ± 4ζ) = 1314.5 .. 1446.7 Hz.
    EXPECT_TRUE(fit->automaticBand);
    const double fn = naturalFrequencyHz(kTable1), z = dampingRatio(kTable1);
    EXPECT_NEAR(fit->bandMinHz, fn * (1.0 - 4.0 * z), 0.01 * fn);
    EXPECT_NEAR(fit->bandMaxHz, fn * (1.0 + 4.0 * z), 0.01 * fn);
    EXPECT_GT(fit->points, 20u);
    EXPECT_LT(fit->points, 40u); // 400 log-spaced points over 500–3000 Hz: 0.45 % apart
}

TEST(ToolModeFit, RecoversTwoModesWithinTwoPercent)
{
    auto fit = fitToolModes(analyticFrf({kTable1, kSecond}), {.modes = 2});
    ASSERT_TRUE(fit.ok()) << fit.error().detail;
    ASSERT_EQ(fit->modes.size(), 2u);
    expectMode(fit->modes[0], kTable1, 0.02);  // 1380 Hz
    expectMode(fit->modes[1], kSecond, 0.02);  // 2906 Hz
    EXPECT_LT(fit->rmsRelativeError, 1e-6);
}

TEST(ToolModeFit, OnePercentComplexNoiseWithinThreePercent)
{
    auto frf = analyticFrf({kTable1, kSecond});
    std::mt19937 rng(20261122);
    std::normal_distribution<double> n01(0.0, 0.01);
    for (auto& h : frf.h)
        h *= std::complex<double>(1.0 + n01(rng), n01(rng));
    auto fit = fitToolModes(frf, {.modes = 2});
    ASSERT_TRUE(fit.ok()) << fit.error().detail;
    ASSERT_EQ(fit->modes.size(), 2u);
    expectMode(fit->modes[0], kTable1, 0.03);
    expectMode(fit->modes[1], kSecond, 0.03);
    // rms of |noise| with 1 % per component is 1.41 % of |H| at every point, so also of the √|H|-weighted
    // norm; the fit cannot be better than the noise by much.
    EXPECT_GT(fit->residualRatio, 0.010);
    EXPECT_LT(fit->residualRatio, 0.018);
}

TEST(ToolModeFit, BandAndValidFlagSelectPoints)
{
    auto frf = analyticFrf({kTable1});
    // Garbage outside the band and at an invalid point must not matter.
    std::size_t expected = 0;
    for (std::size_t i = 0; i < frf.size(); ++i) {
        if (frf.freqHz[i] < 1000.0 || frf.freqHz[i] > 1800.0)
            frf.h[i] = {5e-6, -7e-6};
        else if (i % 17 == 0) {
            frf.valid[i] = false;
            frf.h[i] = {1.0, 1.0};
        } else {
            ++expected;
        }
    }
    auto fit = fitToolModes(frf, {.modes = 1, .minHz = 1000.0, .maxHz = 1800.0});
    ASSERT_TRUE(fit.ok()) << fit.error().detail;
    EXPECT_EQ(fit->points, expected);
    expectMode(fit->modes[0], kTable1, 0.005);
}

TEST(ToolModeFit, EmptyFrfIsNamedError)
{
    auto fit = fitToolModes(dsp::FrequencyResponse{});
    ASSERT_FALSE(fit.ok());
    EXPECT_EQ(fit.error().code, ErrorCode::BadInput);
    EXPECT_NE(fit.error().detail.find("valid points"), std::string::npos) << fit.error().detail;
}

TEST(ToolModeFit, TooFewPointsForModesIsNamedError)
{
    auto fit = fitToolModes(analyticFrf({kTable1}, 6), {.modes = 2});
    ASSERT_FALSE(fit.ok());
    EXPECT_EQ(fit.error().code, ErrorCode::BadInput);
    EXPECT_NE(fit.error().detail.find("7 needed for 2 mode(s)"), std::string::npos) << fit.error().detail;
}

TEST(ToolModeFit, PureSpringHasNoPeak)
{
    dsp::FrequencyResponse frf;
    for (int i = 0; i < 50; ++i)
        frf.push(100.0 + 10.0 * i, {1e-7, 0.0}, std::nan(""), true);
    auto fit = fitToolModes(frf);
    ASSERT_FALSE(fit.ok());
    EXPECT_EQ(fit.error().code, ErrorCode::BadInput);
    EXPECT_NE(fit.error().detail.find("no resonance peak"), std::string::npos) << fit.error().detail;
}

TEST(ToolModeFit, PeakOutsideBandHasNoPeak)
{
    // Only the rising flank below the 1380 Hz mode: -Im H increases monotonically, no interior maximum.
    auto fit = fitToolModes(analyticFrf({kTable1}), {.modes = 1, .maxHz = 1000.0});
    ASSERT_FALSE(fit.ok());
    EXPECT_NE(fit.error().detail.find("no resonance peak"), std::string::npos) << fit.error().detail;
}

TEST(ToolModeFit, SecondModeOfASingleModeFrfIsNamedError)
{
    // What the first start value leaves behind near 1380 Hz is not a second mode.
    auto fit = fitToolModes(analyticFrf({kTable1}), {.modes = 2});
    ASSERT_FALSE(fit.ok());
    EXPECT_EQ(fit.error().code, ErrorCode::BadInput);
    EXPECT_NE(fit.error().detail.find("no resonance peak for mode 2"), std::string::npos) << fit.error().detail;
}

TEST(ToolModeFit, AutomaticModeCountFindsBothModes)
{
    // The second mode's −Im peak (1/(c ω_n) = 0.913 µm/N) is 66 % of the first's (1.389 µm/N): significant.
    auto fit = fitToolModes(analyticFrf({kTable1, kSecond}));
    ASSERT_TRUE(fit.ok()) << fit.error().detail;
    ASSERT_EQ(fit->modes.size(), 2u);
    expectMode(fit->modes[0], kTable1, 0.005);
    expectMode(fit->modes[1], kSecond, 0.005);
}

TEST(ToolModeFit, NegativeModesIsOutOfRange)
{
    auto fit = fitToolModes(analyticFrf({kTable1}), {.modes = -1});
    ASSERT_FALSE(fit.ok());
    EXPECT_EQ(fit.error().code, ErrorCode::OutOfRange);
}
