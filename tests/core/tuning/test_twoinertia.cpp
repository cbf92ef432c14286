// SPDX-License-Identifier: GPL-3.0-or-later
// Two-inertia model, fit and suppression filters: checks of spec/lost-motion-and-two-inertia.md
// §2.7 (Table 5.1 consistency), §4.10 (F_m checks), §4.11 (F_L), §4.15, and §2.10 (load error).
#include "core/tuning/TwoInertia.h"
#include "core/tuning/TwoInertiaFilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace axistune::tuning;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

TwoInertiaParams table51(double delayS = 0.0) { return TwoInertiaParams{0.00527, 0.0105, 200.0, 0.27, delayS}; }

// Table 5.1 FRF, 1–1000 Hz, log-spaced, with multiplicative complex noise of 1 % (seeded).
axistune::dsp::FrequencyResponse syntheticFrf(const TwoInertiaParams& p, int n, double noise, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> nd(0.0, noise);
    axistune::dsp::FrequencyResponse frf;
    for (int i = 0; i < n; ++i) {
        const double f = std::pow(10.0, 3.0 * i / (n - 1.0));
        const std::complex<double> e(1.0 + nd(rng), nd(rng));
        frf.push(f, motorVelocityResponse(p, f) * e, 0.99, true);
    }
    return frf;
}

double db(std::complex<double> h) { return 20.0 * std::log10(std::abs(h)); }

}  // namespace

TEST(TwoInertia, Table51FrequenciesAndDampings)
{
    const auto p = table51();
    EXPECT_NEAR(antiresonanceRadS(p), 138.01, 0.01);
    EXPECT_NEAR(antiresonanceRadS(p) / kTwoPi, 21.97, 0.005);
    EXPECT_NEAR(resonanceRadS(p), 238.74, 0.02);
    EXPECT_NEAR(resonanceRadS(p) / kTwoPi, 38.00, 0.005);
    EXPECT_NEAR(zetaPole(p), 0.161, 0.0005);
    EXPECT_NEAR(zetaZero(p), 0.0932, 0.00005);
}

TEST(TwoInertia, StateSpaceMatchesTransferFunctions)
{
    // (5.11): x = [ω_m, spring torque, ω_L]; outputs x1, x3. Solve (sI − A) x = B at each frequency.
    const auto p = table51();
    const double Jm = p.jmKgm2, Jl = p.jlKgm2, K = p.kNmPerRad, C = p.cNmsPerRad;
    for (double f : {1.0, 10.0, 22.0, 38.0, 100.0, 700.0}) {
        const std::complex<double> s(0.0, kTwoPi * f);
        using c = std::complex<double>;
        // Rows of sI − A.
        c M[3][3] = {{s + C / Jm, 1.0 / Jm, -C / Jm}, {-K, s, K}, {-C / Jl, -1.0 / Jl, s + C / Jl}};
        c b[3] = {1.0 / Jm, 0.0, 0.0};
        // Gaussian elimination (3×3).
        for (int k = 0; k < 3; ++k) {
            for (int r = k + 1; r < 3; ++r) {
                const c q = M[r][k] / M[k][k];
                for (int cc = k; cc < 3; ++cc) M[r][cc] -= q * M[k][cc];
                b[r] -= q * b[k];
            }
        }
        c x[3];
        for (int k = 2; k >= 0; --k) {
            c acc = b[k];
            for (int cc = k + 1; cc < 3; ++cc) acc -= M[k][cc] * x[cc];
            x[k] = acc / M[k][k];
        }
        EXPECT_NEAR(std::abs(x[0] - motorVelocityResponse(p, f)), 0.0, 1e-9 * std::abs(x[0])) << f;
        EXPECT_NEAR(std::abs(x[2] - loadVelocityResponse(p, f)), 0.0, 1e-9 * std::abs(x[2])) << f;
    }
}

TEST(TwoInertia, FitRecoversTable51WithNoiseAndDelay)
{
    const auto truth = table51(1.1e-3);
    const auto frf = syntheticFrf(truth, 2000, 0.01, 12345);
    auto fit = fitTwoInertia(frf, TwoInertiaFitOptions{});
    ASSERT_TRUE(fit.ok()) << fit.error().detail;
    const auto& q = fit->params;
    EXPECT_NEAR(q.jmKgm2, truth.jmKgm2, 0.03 * truth.jmKgm2);
    EXPECT_NEAR(q.jlKgm2, truth.jlKgm2, 0.03 * truth.jlKgm2);
    EXPECT_NEAR(q.kNmPerRad, truth.kNmPerRad, 0.03 * truth.kNmPerRad);
    EXPECT_NEAR(q.cNmsPerRad, truth.cNmsPerRad, 0.15 * truth.cNmsPerRad);
    EXPECT_NEAR(q.delayS, 1.1e-3, 0.05e-3);
    EXPECT_NEAR(antiresonanceRadS(q) / kTwoPi, 21.97, 0.3);
    EXPECT_NEAR(resonanceRadS(q) / kTwoPi, 38.00, 0.3);
    EXPECT_NEAR(zetaZero(q), 0.0932, 0.015);
    EXPECT_NEAR(zetaPole(q), 0.161, 0.02);
    // The noise is 1 % per component, so the relative complex error of a good fit is ≈ 1.4 %.
    EXPECT_LT(fit->fitError, 0.02);
    EXPECT_GT(fit->fitError, 0.005);
    // Start values come from the data's dip and peak of |H|·ω.
    EXPECT_NEAR(fit->dataAntiresonanceHz, 22.0, 1.5);
    EXPECT_NEAR(fit->dataResonanceHz, 38.0, 2.5);
}

TEST(TwoInertia, FitWithoutResonanceIsAnError)
{
    // A rigid body 1/(J s): no dip and no peak.
    axistune::dsp::FrequencyResponse frf;
    for (int i = 0; i < 500; ++i) {
        const double f = std::pow(10.0, 3.0 * i / 499.0);
        frf.push(f, 1.0 / (0.0157 * std::complex<double>(0.0, kTwoPi * f)), 1.0, true);
    }
    auto fit = fitTwoInertia(frf, TwoInertiaFitOptions{});
    ASSERT_FALSE(fit.ok());
    EXPECT_NE(fit.error().detail.find("anti-resonance"), std::string::npos);
    // A band that cuts the resonance off is refused too.
    auto cut = fitTwoInertia(syntheticFrf(table51(), 2000, 0.0, 1), TwoInertiaFitOptions{5.0, 30.0, 0.0});
    EXPECT_FALSE(cut.ok());
    auto bad = fitTwoInertia(syntheticFrf(table51(), 2000, 0.0, 1), TwoInertiaFitOptions{300.0, 5.0, 0.0});
    EXPECT_FALSE(bad.ok());
}

TEST(TwoInertia, FmMagnitudesFor17Hz007)
{
    const SuppressionFilter f{SuppressionMode::Semi, 17.0, 0.07, 0.0};
    const double freq[] = {5, 10, 15, 17, 20, 22, 30, 50, 100};
    const double dB[] = {-0.78, -3.65, -11.98, -17.16, -7.69, -3.26, 6.30, 17.01, 28.28};
    for (int i = 0; i < 9; ++i) {
        EXPECT_NEAR(db(suppressionFilterResponse(f, freq[i])), dB[i], 0.01) << freq[i];
    }
    // |F_m(j2π·17)| = 2ζ/√(1 + 4ζ²) = 0.1386.
    EXPECT_NEAR(std::abs(suppressionFilterResponse(f, 17.0)), 0.1386, 0.0001);
    // F_m cascaded with (5.6) of identical parameters is 1 at every frequency.
    const TwoInertiaParams p{0.005, 0.01, 0.01 * std::pow(kTwoPi * 17.0, 2), 2 * 0.07 * 0.01 * kTwoPi * 17.0, 0.0};
    for (double fr : {1.0, 17.0, 80.0, 500.0}) {
        EXPECT_NEAR(std::abs(suppressionFilterResponse(f, fr) * motorToLoadResponse(p, fr) - 1.0), 0.0, 1e-12);
    }
}

TEST(TwoInertia, FlMagnitudesFor17Hz014Tau13ms)
{
    const SuppressionFilter f{SuppressionMode::Full, 17.0, 0.14, 0.013};
    EXPECT_NEAR(db(suppressionFilterResponse(f, 17.0)), -16.05, 0.01);
    const double freq[] = {5, 10, 22, 38, 100, 300};
    const double dB[] = {-1.45, -5.76, -9.12, 0.44, 6.53, 8.0};
    for (int i = 0; i < 6; ++i) {
        EXPECT_NEAR(db(suppressionFilterResponse(f, freq[i])), dB[i], 0.05) << freq[i];
    }
    EXPECT_NEAR(std::abs(suppressionFilterResponse(f, 1e6)), 2.572, 0.005);
}

TEST(TwoInertia, FilterFromModelUsesZeroDamping)
{
    const auto semi = suppressionFilterFromModel(table51(), SuppressionMode::Semi, 0.0);
    EXPECT_NEAR(semi.f0Hz, 21.97, 0.005);
    EXPECT_NEAR(semi.zeta, 0.0932, 0.00005);
    EXPECT_EQ(semi.tauS, 0.0);
    const auto full = suppressionFilterFromModel(table51(), SuppressionMode::Full, 0.0);
    // Default rule: high-frequency gain 1/(2ζω_0τ) = 2.5.
    EXPECT_NEAR(1.0 / (2.0 * full.zeta * kTwoPi * full.f0Hz * full.tauS), 2.5, 1e-9);
    EXPECT_NEAR(suppressionFilterFromModel(table51(), SuppressionMode::Full, 0.013).tauS, 0.013, 0);
}

TEST(TwoInertia, LoadErrorForAccelerationStep)
{
    // §2.10: with ideal motor tracking and no F_m, an acceleration step α gives a load error peak
    // ≈ (α/ω_0²)(1 + e^{−πζ/√(1−ζ²)}) = 6.6° at 22 Hz / ζ 0.093 (α = 200 rev/s²). A long constant
    // acceleration (v_max reached after 1 s) and a cruise isolate the first peak.
    const auto p = table51();
    MotionProfile prof;
    prof.aMax = 1256.6;
    prof.vMax = 1256.6;
    prof.jerk = 1e9;
    prof.cruiseS = 0.5;  // lets the ringing decay before the deceleration
    prof.settleS = 0.3;
    const double w0 = antiresonanceRadS(p);
    const double z = zetaZero(p);
    const double expected = prof.aMax / (w0 * w0) * (1.0 + std::exp(-std::numbers::pi * z / std::sqrt(1 - z * z)));
    EXPECT_NEAR(expected * 180.0 / std::numbers::pi, 6.6, 0.05);
    const auto matched = suppressionFilterFromModel(p, SuppressionMode::Semi, 0.0);
    const auto e = predictLoadError(p, matched, prof);
    EXPECT_NEAR(e.maxErrorWithoutFilter, expected, 0.005 * expected);
    // The matched filter cancels (5.6): the load follows the command.
    EXPECT_LT(e.maxErrorWithFilter, 1e-4 * expected);
    // A mistuned filter (17 Hz / 0.07 on a 22 Hz plant) still helps, but does not cancel.
    const auto mistuned = predictLoadError(p, SuppressionFilter{SuppressionMode::Semi, 17.0, 0.07, 0.0}, prof);
    EXPECT_GT(mistuned.maxErrorWithFilter, 0.05 * expected);
}
