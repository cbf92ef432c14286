// SPDX-License-Identifier: GPL-3.0-or-later
// Checks C-C1 … C-C6 of spec/current-loop-and-multisweep-frf.md §4.3 (values from §3.4 and §3.6).
#include "core/dsp/DigitalFilter.h"
#include "core/dsp/Excitation.h"
#include "core/dsp/SineDemodulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace axistune;
using namespace axistune::dsp;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kFs = 4000.0;

// y_n[k] = B sin(2π fp k/fs + φ + ψ_n), k = 1..M (the spec's indexing).
std::vector<double> tone(double fp, double B, double phiDeg, double psiDeg, int M)
{
    std::vector<double> y;
    for (int k = 1; k <= M; ++k)
        y.push_back(B * std::sin(2 * kPi * fp * k / kFs + (phiDeg + psiDeg) * kPi / 180));
    return y;
}

Demodulated multi(double fp, double fj, double B, double phiDeg, int M)
{
    auto y0 = tone(fp, B, phiDeg, 0, M), y1 = tone(fp, B, phiDeg, 120, M), y2 = tone(fp, B, phiDeg, -120, M);
    const std::vector<SweepSamples> s{{0.0, 1, y0}, {120.0, 1, y1}, {-120.0, 1, y2}};
    auto d = demodulate(s, fj, kFs);
    EXPECT_TRUE(d.ok());
    return d.value();
}

Demodulated conventional(double fp, double fj, double B, double phiDeg, int M)
{
    auto y = tone(fp, B, phiDeg, 0, M);
    const std::vector<SweepSamples> s{{0.0, 1, y}};
    auto d = demodulate(s, fj, kFs);
    EXPECT_TRUE(d.ok());
    return d.value();
}

}  // namespace

TEST(SineDemodulation, CC1_MultiSweepExactForAnyM)
{
    for (double f : {100.0, 1100.0, 1900.0, 2900.0, 3300.0, 3900.0}) {
        for (int M : {1, 3, 40}) {
            const auto d = multi(f, f, 0.7, -40.0, M);
            EXPECT_NEAR(d.amplitude(), 0.7, 1e-12) << f << " Hz, M=" << M;
            EXPECT_NEAR(d.phaseRad() * 180 / kPi, -40.0, 1e-10) << f << " Hz, M=" << M;
            EXPECT_TRUE(d.valid);
            EXPECT_TRUE(d.multiSweep);
        }
    }
}

TEST(SineDemodulation, CC1_ConventionalErrorsOfTheSpecTable)
{
    // spec §3.4 table (B = 0.7, φ = -40°, normalisation 2/M), printed to 4 digits / 0.1°
    auto d = conventional(2900, 2900, 0.7, -40, 1);
    EXPECT_NEAR(d.amplitude(), 0.9185, 5e-5);
    EXPECT_NEAR(d.phaseRad() * 180 / kPi, 9.0, 0.05);
    EXPECT_FALSE(d.valid);  // 2900 Hz ≥ fs/2
    d = conventional(2900, 2900, 0.7, -40, 3);
    EXPECT_NEAR(d.amplitude(), 0.6365, 5e-5);
    EXPECT_NEAR(d.phaseRad() * 180 / kPi, -22.7, 0.05);
    EXPECT_NEAR(conventional(1100, 1100, 0.7, -40, 1).amplitude(), 1.2000, 5e-5);
    EXPECT_NEAR(conventional(3300, 3300, 0.7, -40, 1).amplitude(), 1.3641, 5e-5);
    EXPECT_TRUE(conventional(1100, 1100, 0.7, -40, 1).valid);
}

TEST(SineDemodulation, CC2_NoAliasAt1100HzForA2900HzSignal)
{
    const int M = 4000;
    EXPECT_NEAR(conventional(2900, 1100, 1.0, 0, M).amplitude(), 1.0, 1e-9);
    EXPECT_NEAR(multi(2900, 1100, 1.0, 0, M).amplitude(), 0.0, 1e-9);
    EXPECT_NEAR(conventional(2900, 2900, 1.0, 0, M).amplitude(), 1.0, 1e-9);
    EXPECT_NEAR(multi(2900, 2900, 1.0, 0, M).amplitude(), 1.0, 1e-9);
}

namespace {

// C-C3 bench: a notch run at 16 kHz on a sine stream generated at 16 kHz, the output traced at
// 4 kHz, demodulated by the multi-sweep method. Returns the FRF at the given frequencies.
FrequencyResponse measureNotchedPath(double notchHz, const std::vector<double>& freqs)
{
    const double fsFast = 16000.0;
    auto notch = designNotch({notchHz, 300.0, 0.0}, 1.0 / fsFast);
    EXPECT_TRUE(notch.ok());
    SweepRecording rec;
    rec.fsHz = kFs;
    rec.amplitude = 1.0;
    SineStreamOptions o;
    o.freqHz = freqs;
    o.fsHz = kFs;
    o.amplitude = 1.0;
    o.amplitudeLimit = 1.0;
    o.settleTimeS = 0.2;
    o.periods = 100;
    o.phaseOffsetsDeg = kMultiSweepOffsetsDeg;
    auto plan = planSineStream(o);
    EXPECT_TRUE(plan.ok());
    for (const auto& seg : plan.value()) {
        Biquad q = notch.value();  // each sweep starts from rest
        SweepBlock b;
        b.freqHz = seg.freqHz;
        b.phaseOffsetDeg = seg.phaseOffsetDeg;
        const auto start = -static_cast<std::int64_t>(seg.settleSamples);
        for (std::int64_t k = start; k < static_cast<std::int64_t>(seg.measureSamples); ++k) {
            double y = 0.0, x = 0.0;
            for (int sub = 0; sub < 4; ++sub) {  // four fast samples per traced sample
                const double t = (4.0 * static_cast<double>(k) + sub) / fsFast;
                x = std::sin(2 * kPi * seg.freqHz * t + seg.phaseOffsetDeg * kPi / 180);
                y = q.process(x);
                if (sub == 0) {
                    b.excitation.push_back(x);
                    b.response.push_back(y);
                    b.sample.push_back(k);
                }
            }
        }
        rec.blocks.push_back(std::move(b));
    }
    auto frf = sineStreamFrf(rec);
    EXPECT_TRUE(frf.ok()) << frf.error().detail;
    return frf.value();
}

}  // namespace

TEST(SineDemodulation, CC3_NotchDoesNotFoldInMultiSweep)
{
    const double h = 1.0 / 16000.0;
    for (double notchHz : {2900.0, 1100.0}) {
        auto notch = designNotch({notchHz, 300.0, 0.0}, h);
        ASSERT_TRUE(notch.ok());
        const auto frf = measureNotchedPath(notchHz, {1100.0, 2900.0});
        ASSERT_EQ(frf.size(), 2u);
        for (std::size_t i = 0; i < 2; ++i) {
            // measured = the notch's own response at the excitation frequency (within 1e-3),
            // i.e. a dip only at the notch, never at its fold 4000 - f.
            const auto truth = notch->response(frf.freqHz[i], h);
            EXPECT_LT(std::abs(frf.h[i] - truth), 1e-3) << notchHz << " notch, at " << frf.freqHz[i];
            EXPECT_TRUE(frf.valid[i]);
        }
        const std::size_t dip = notchHz == 1100.0 ? 0 : 1;
        EXPECT_LT(std::abs(frf.h[dip]), 1e-3);
        EXPECT_GT(std::abs(frf.h[1 - dip]), 0.9);
    }
}

TEST(SineDemodulation, CC4_ParkTransformOfBalancedSet)
{
    const double Vp = 1.7, phip = 0.4, wp = 2 * kPi * 2900, wj = 2 * kPi * 1100;
    for (double t = 0.0; t < 0.01; t += 1.37e-4) {
        const double u = Vp * std::sin(wp * t + phip);
        const double v = Vp * std::sin(wp * t + phip - 2 * kPi / 3);
        const double w = Vp * std::sin(wp * t + phip + 2 * kPi / 3);
        const auto dq = parkTransform(u, v, w, wj * t);
        const double arg = (wp - wj) * t + phip;
        EXPECT_NEAR(dq[0], std::sqrt(1.5) * Vp * std::sin(arg), 1e-12);
        EXPECT_NEAR(dq[1], -std::sqrt(1.5) * Vp * std::cos(arg), 1e-12);
    }
}

TEST(SineDemodulation, CC5_PhaseIsAtan2OfAandB)
{
    for (double phi : {-170.0, -100.0, -40.0, 0.0, 95.0, 130.0, 179.0}) {
        const auto d = multi(700, 700, 2.0, phi, 7);
        EXPECT_NEAR(d.phaseRad() * 180 / kPi, phi, 1e-9);
        EXPECT_NEAR(d.a, 2.0 * std::sin(phi * kPi / 180), 1e-12);
        EXPECT_NEAR(d.b, 2.0 * std::cos(phi * kPi / 180), 1e-12);
    }
}

TEST(SineDemodulation, CC6_ValidityRanges)
{
    EXPECT_TRUE(multi(3999, 3999, 1, 0, 5).valid);
    EXPECT_FALSE(multi(4000, 4000, 1, 0, 5).valid);
    EXPECT_FALSE(multi(4100, 4100, 1, 0, 5).valid);
    EXPECT_TRUE(conventional(1999, 1999, 1, 0, 5).valid);
    EXPECT_FALSE(conventional(2000, 2000, 1, 0, 5).valid);
}

TEST(SineDemodulation, BadSweepSetsAreErrors)
{
    std::vector<double> y(10, 1.0), y9(9, 1.0);
    const std::vector<SweepSamples> two{{0.0, 0, y}, {120.0, 0, y}};
    EXPECT_FALSE(demodulate(two, 100, kFs).ok());
    const std::vector<SweepSamples> wrongOffsets{{0.0, 0, y}, {90.0, 0, y}, {-120.0, 0, y}};
    EXPECT_FALSE(demodulate(wrongOffsets, 100, kFs).ok());
    const std::vector<SweepSamples> unequal{{0.0, 0, y}, {120.0, 0, y9}, {-120.0, 0, y}};
    EXPECT_FALSE(demodulate(unequal, 100, kFs).ok());
    const std::vector<SweepSamples> one{{0.0, 0, y}};
    EXPECT_FALSE(demodulate(one, 0.0, kFs).ok());
    EXPECT_FALSE(demodulate(one, 100, 0.0).ok());
}

TEST(SineDemodulation, RecordingFrfIsResponseOverExcitation)
{
    // response = 0.5·excitation delayed by 90° at every frequency; excitation amplitude 3
    SweepRecording rec;
    rec.fsHz = kFs;
    for (double f : {50.0, 2500.0}) {
        for (double psi : {0.0, 120.0, -120.0}) {
            SweepBlock b;
            b.freqHz = f;
            b.phaseOffsetDeg = psi;
            for (std::int64_t k = -5; k < 17; ++k) {
                const double th = 2 * kPi * f * k / kFs + psi * kPi / 180;
                b.sample.push_back(k);
                b.excitation.push_back(3.0 * std::sin(th));
                b.response.push_back(k < 0 ? 99.0 : 1.5 * std::sin(th - kPi / 2));  // settle rows ignored
            }
            rec.blocks.push_back(b);
        }
    }
    auto frf = sineStreamFrf(rec);
    ASSERT_TRUE(frf.ok()) << frf.error().detail;
    ASSERT_EQ(frf->size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(std::abs(frf->h[i] - std::complex<double>(0.0, -0.5)), 0.0, 1e-12);
        EXPECT_TRUE(frf->valid[i]);
        EXPECT_TRUE(std::isnan(frf->coherence[i]));
    }
    EXPECT_EQ(frf->metadata.text("method"), "multisweep");
}
