// SPDX-License-Identifier: GPL-3.0-or-later
// Injection-hold factor G = N / Σ_{m<N} e^{−jωmh}, checked against an independent DFT of a held sine.
#include "core/dsp/InjectionHold.h"

#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune::dsp;

namespace {

/// 1/G by brute force: a sine sampled every N ticks and held, its DFT at ω over whole periods of
/// the fine grid divided by that of the sine sampled at every tick.
std::complex<double> heldFundamental(double fHz, double h, int n, int cycles)
{
    const double w = 2.0 * std::numbers::pi * fHz;
    // Length: a whole number of velocity periods spanning (close to) `cycles` periods of f.
    const long len = static_cast<long>(std::lround(cycles / (fHz * h * n))) * n;
    std::complex<double> held = 0.0, fine = 0.0;
    for (long k = 0; k < len; ++k) {
        const double t = static_cast<double>(k) * h;
        const double tHeld = static_cast<double>(k / n * n) * h;
        const std::complex<double> basis = std::polar(1.0, -w * t);
        held += std::sin(w * tHeld) * basis;
        fine += std::sin(w * t) * basis;
    }
    return held / fine;
}

} // namespace

TEST(InjectionHold, InverseIsTheFundamentalOfTheHeldSine)
{
    const double h = 62.5e-6;
    for (int n : {2, 4, 5}) {
        for (double f : {10.0, 300.0, 1000.0, 3300.0}) {
            if (f * h * n >= 1.0)
                continue;
            const auto g = injectionHoldFactor(f, h, n);
            const auto ref = heldFundamental(f, h, n, 4000);
            // Leakage of the finite record: ~1/cycles.
            EXPECT_NEAR(std::abs(1.0 / g), std::abs(ref), 2e-3) << n << " " << f;
            EXPECT_NEAR(std::arg(1.0 / g), std::arg(ref), 2e-3) << n << " " << f;
        }
    }
}

TEST(InjectionHold, DdTableValuesAndLimits)
{
    // N = 4, h = 62.5 µs: G ≈ e^{jω(N−1)h/2} (|G| slightly above 1): +33.75° at 1 kHz, +10.1° at 300 Hz.
    const double h = 62.5e-6;
    EXPECT_NEAR(std::arg(injectionHoldFactor(1000.0, h, 4)) * 180.0 / std::numbers::pi, 33.75, 1e-9);
    EXPECT_NEAR(std::arg(injectionHoldFactor(300.0, h, 4)) * 180.0 / std::numbers::pi, 10.125, 1e-9);
    // |Σ| = |sin(Nθ/2)/sin(θ/2)|: at 1 kHz θ = 2π/16, |G| = 4 sin(π/16)/sin(π/4).
    EXPECT_NEAR(std::abs(injectionHoldFactor(1000.0, h, 4)),
                4.0 * std::sin(std::numbers::pi / 16) / std::sin(std::numbers::pi / 4), 1e-12);
    EXPECT_EQ(injectionHoldFactor(1234.0, h, 1), std::complex<double>(1.0, 0.0));
    EXPECT_EQ(injectionHoldFactor(0.0, h, 4), std::complex<double>(1.0, 0.0));
    EXPECT_TRUE(std::isnan(injectionHoldFactor(4000.0, h, 4).real())); // the sum vanishes at 1/(N h)
    EXPECT_TRUE(std::isnan(injectionHoldFactor(100.0, h, 0).real()));
    EXPECT_TRUE(std::isnan(injectionHoldFactor(100.0, 0.0, 4).real()));
}

TEST(InjectionHold, CorrectsOnceAndRecordsIt)
{
    FrequencyResponse frf;
    frf.push(1000.0, {2.0, 0.0}, std::nan(""), true);
    frf.push(4000.0, {1.0, 0.0}, std::nan(""), true);
    ASSERT_TRUE(correctInjectionHold(frf, 62.5e-6, 4).ok());
    EXPECT_NEAR(std::abs(frf.h[0] * injectionHoldFactor(1000.0, 62.5e-6, 4) - 2.0), 0.0, 1e-12);
    EXPECT_TRUE(frf.valid[0]);
    EXPECT_FALSE(frf.valid[1]);
    EXPECT_TRUE(isInjectionHoldCorrected(frf));
    EXPECT_EQ(frf.metadata.number("injection_hold_ticks").value(), 4.0);
    EXPECT_FALSE(correctInjectionHold(frf, 62.5e-6, 4).ok()); // never twice
    FrequencyResponse other;
    EXPECT_FALSE(correctInjectionHold(other, 0.0, 4).ok());
    EXPECT_FALSE(correctInjectionHold(other, 62.5e-6, 0).ok());
}
