// SPDX-License-Identifier: GPL-3.0-or-later
// Position PID design for an NC-closed position loop (core/tuning/PositionPid), on analytic plants.
#include "core/tuning/PositionPid.h"
#include "core/model/Number.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune;
using namespace axistune::tuning;
using cd = std::complex<double>;

namespace {

constexpr double kT = 1e-3; // 1 kHz servo thread

/// Rigid body 1/(J s²) + viscous b, held for a period (ZOH) and read one period later: the exact discrete response
/// of a double integrator under zero-order hold is T²(z+1)/(2J(z−1)²) without friction; with b the continuous
/// response is sampled on the unit circle through its exact ZOH form computed here from the state matrices.
cd rigidBody(double j, double b, double fHz)
{
    const cd z = std::polar(1.0, 2.0 * std::numbers::pi * fHz * kT);
    if (b == 0.0)
        return kT * kT * (z + 1.0) / (2.0 * j * (z - 1.0) * (z - 1.0)) / z;
    // x = (position, velocity), v' = (u − b v)/J: exact ZOH with a = b/J.
    const double a = b / j, e = std::exp(-a * kT);
    const double ad12 = (1.0 - e) / a, ad22 = e;
    const double bd1 = (kT - (1.0 - e) / a) / (j * a), bd2 = (1.0 - e) / (j * a);
    // H(z) = [1 0] (zI − Ad)⁻¹ Bd with Ad = [[1, ad12], [0, ad22]]
    const cd det = (z - 1.0) * (z - ad22);
    return ((z - ad22) * bd1 + ad12 * bd2) / det / z;
}

std::vector<double> lines(double f0, double f1, double df)
{
    std::vector<double> f;
    for (double x = f0; x <= f1 + 1e-9; x += df)
        f.push_back(x);
    return f;
}

} // namespace

TEST(PositionPid, DiscreteControllerMatchesLinuxCncsDifferenceEquation)
{
    // Run LinuxCNC's pid recurrence on a sine error and compare the steady output phasor with pidResponse.
    const PositionPid pid{2.0, 10.0, 0.047, 0.0, 0.0};
    const double f = 37.0, w = 2.0 * std::numbers::pi * f;
    double ei = 0.0, prev = 0.0;
    cd acc = 0.0;
    const int n0 = 2000, n = 27000; // 27 s: whole number of periods of 37 Hz at 1 kHz (999 cycles)
    for (int k = 0; k < n0 + n; ++k) {
        const double e = std::sin(w * k * kT);
        ei += e * kT;
        const double ed = (e - prev) / kT;
        prev = e;
        const double out = pid.p * e + pid.i * ei + pid.d * ed;
        if (k >= n0)
            acc += out * std::polar(1.0, -w * k * kT);
    }
    // The integrator's constant offset from the start adds nothing at 37 Hz over whole cycles.
    const cd measured = acc * 2.0 / static_cast<double>(n) * cd(0.0, 1.0); // sin → phasor −j
    const cd expected = pidResponse(pid, kT, f);
    EXPECT_NEAR(std::abs(measured / expected), 1.0, 1e-3);
    EXPECT_NEAR(std::arg(measured / expected), 0.0, 1e-3);
}

TEST(PositionPid, TorqueDriveMeetsItsMarginsAtTheCrossoverAndFindsTheInertia)
{
    const double j = 6e-4 * 2.0 * std::numbers::pi / 10.0; // N·m·s²/mm of a 6e-4 kg·m² axis, 10 mm lead
    const double b = 0.002;
    const auto f = lines(2.0, 450.0, 2.0);
    std::vector<cd> p(f.size());
    for (std::size_t k = 0; k < f.size(); ++k)
        p[k] = rigidBody(j, b, f[k]);
    auto input = driveInputFromSlope(f, p);
    ASSERT_TRUE(input) << input.error().detail;
    EXPECT_EQ(*input, DriveInput::Torque);

    PositionPidOptions o;
    o.phaseMarginDeg = 50.0;
    o.gainMarginDb = 8.0;
    auto d = designPositionPid(f, p, kT, o);
    ASSERT_TRUE(d) << d.error().detail;
    // At the chosen crossover |C P| = 1 and arg(C P) = −180° + PM (the definition the rule solves).
    const std::size_t c = static_cast<std::size_t>(std::lround((d->crossoverHz - 2.0) / 2.0));
    const cd l = pidResponse(d->gains, kT, f[c]) * p[c];
    EXPECT_NEAR(std::abs(l), 1.0, 1e-9);
    EXPECT_NEAR(std::arg(l) * 180.0 / std::numbers::pi, -180.0 + 50.0, 1e-6);
    EXPECT_GE(d->predicted.phaseMarginDeg, 49.5);
    EXPECT_GE(d->predicted.gainMarginDb, 8.0);
    EXPECT_GT(d->gains.d, 0.0);
    // The rigid-body fit returns J and b of the analytic plant; the loop's 1.5 periods of delay (ZOH and the
    // period of reading) enter only through the fit's first-order delay term: 2 % allowed on J, 5 % on b.
    EXPECT_NEAR(d->inertia / j, 1.0, 0.02);
    EXPECT_NEAR(d->viscous / b, 1.0, 0.05);
    EXPECT_DOUBLE_EQ(d->gains.ff2, d->inertia);
    EXPECT_EQ(d->rules.size(), 6u); // crossover, P, I, D, FF2, FF1: one rule per number
}

TEST(PositionPid, VelocityDriveHasNoDerivativeAndFeedsForwardOneOverK)
{
    const double kv = 50.0; // mm/s per unit of command
    const auto f = lines(2.0, 450.0, 2.0);
    std::vector<cd> p(f.size());
    for (std::size_t k = 0; k < f.size(); ++k) {
        const cd z = std::polar(1.0, 2.0 * std::numbers::pi * f[k] * kT);
        p[k] = kv * kT / (z - 1.0); // exact ZOH integrator, y[k] from u[k−1]
    }
    auto input = driveInputFromSlope(f, p);
    ASSERT_TRUE(input) << input.error().detail;
    EXPECT_EQ(*input, DriveInput::Velocity);
    PositionPidOptions o;
    o.input = DriveInput::Velocity;
    auto d = designPositionPid(f, p, kT, o);
    ASSERT_TRUE(d) << d.error().detail;
    EXPECT_EQ(d->gains.d, 0.0);
    EXPECT_NEAR(d->gains.ff1 * kv, 1.0, 0.02);
    EXPECT_GE(d->predicted.phaseMarginDeg, 49.5);
}

// A velocity drive whose own velocity loop is a first-order lag (bandwidth 40 Hz, as the LinuxCNC test machine's
// velocity-mode drive) with one servo period of delay: P = K/(jω(1 + jω/ω_v))·e^{−jωT}. FF1 must be 1/K within 1 %
// (the fit models the lag and the delay); averaging |P|·ω up to the crossover would read K low by the lag's
// 1/√(1 + (ω/ω_v)²), several % at a crossover of a few Hz below ω_v.
TEST(PositionPid, VelocityDriveWithALaggingVelocityLoopFeedsForwardOneOverK)
{
    const double kv = 0.9967, wv = 2.0 * std::numbers::pi * 40.0;
    const auto f = lines(2.0, 450.0, 2.0);
    std::vector<cd> p(f.size());
    for (std::size_t k = 0; k < f.size(); ++k) {
        const double w = 2.0 * std::numbers::pi * f[k];
        p[k] = kv / (cd(0.0, w) * cd(1.0, w / wv)) * std::polar(1.0, -w * kT);
    }
    PositionPidOptions o;
    o.input = DriveInput::Velocity;
    auto d = designPositionPid(f, p, kT, o);
    ASSERT_TRUE(d) << d.error().detail;
    EXPECT_NEAR(d->gains.ff1 * kv, 1.0, 0.01);
    EXPECT_EQ(d->gains.ff2, 0.0);
    double averaged = 0.0;
    std::size_t n = 0;
    for (std::size_t k = 0; k < f.size() && f[k] <= d->crossoverHz; ++k, ++n)
        averaged += std::abs(p[k]) * 2.0 * std::numbers::pi * f[k];
    RecordProperty("crossover_Hz", model::formatShortest(d->crossoverHz));
    RecordProperty("ff1_times_K", model::formatShortest(d->gains.ff1 * kv));
    RecordProperty("averaged_K_over_K", model::formatShortest(averaged / static_cast<double>(n) / kv));
}

TEST(PositionPid, RefusesWhatItCannotTrust)
{
    const auto f = lines(2.0, 20.0, 2.0);
    std::vector<cd> p(f.size(), cd(1.0, 0.0));
    p[3] = cd(std::nan(""), 0.0);
    auto bad = designPositionPid(f, p, kT);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().detail.find("line 3"), std::string::npos) << bad.error().detail;
    // A flat plant is neither a torque nor a velocity drive.
    std::vector<cd> flat(f.size(), cd(1.0, 0.0));
    EXPECT_FALSE(driveInputFromSlope(f, flat));
    EXPECT_FALSE(designPositionPid({1.0, 2.0}, {cd(1, 0), cd(1, 0)}, kT));
}

// LinuxCNC's biquad notch (type 2) equals the analog notch prototype (s² + 1)/(s² + s/Q + 1) under the bilinear
// transform prewarped at f0, s = (1 − z⁻¹)/((1 + z⁻¹)·tan(w0/2)) — an independent derivation of the same filter:
// within 1e-12 everywhere; zero at f0; unity at DC and at half the sampling rate.
TEST(BiquadNotch, EqualsThePrewarpedBilinearAnalogNotch)
{
    const double T = 1e-3;
    for (const double q : {0.5, 1.0, 2.0}) {
        const tuning::BiquadNotch n{104.0, q};
        const double w0 = 2.0 * M_PI * n.f0Hz * T;
        for (double f = 1.0; f < 500.0; f += 7.3) {
            const std::complex<double> z1 = std::polar(1.0, -2.0 * M_PI * f * T);
            const std::complex<double> s = (1.0 - z1) / ((1.0 + z1) * std::tan(w0 / 2.0));
            const std::complex<double> analog = (s * s + 1.0) / (s * s + s / q + 1.0);
            EXPECT_LT(std::abs(tuning::biquadNotchResponse(n, T, f) - analog), 1e-12) << f << " Hz, Q " << q;
        }
        EXPECT_LT(std::abs(tuning::biquadNotchResponse(n, T, n.f0Hz)), 1e-12);
        EXPECT_NEAR(std::abs(tuning::biquadNotchResponse(n, T, 0.0)), 1.0, 1e-12);
        EXPECT_NEAR(std::abs(tuning::biquadNotchResponse(n, T, 500.0)), 1.0, 1e-12);
    }
}

// The resonance finder: a rigid body 1/(J s²) with one mode at 120 Hz (ζ 0.02) and an anti-resonance at 80 Hz;
// |P|·ω² peaks at the mode (within one 1 Hz line); a rigid body alone has no resonance.
TEST(PlantResonance, FindsTheModeOfATwoMassPlantAndNoneOnARigidBody)
{
    std::vector<double> f;
    std::vector<std::complex<double>> twoMass, rigid;
    const double J = 1e-3, wa = 2 * M_PI * 80.0, wr = 2 * M_PI * 120.0, za = 0.02, zr = 0.02;
    for (double x = 2.0; x <= 450.0; x += 1.0) {
        const std::complex<double> s(0.0, 2 * M_PI * x);
        f.push_back(x);
        rigid.push_back(1.0 / (J * s * s));
        twoMass.push_back(rigid.back() * (wr * wr / (wa * wa)) * (s * s + 2.0 * za * wa * s + wa * wa) /
                          (s * s + 2.0 * zr * wr * s + wr * wr));
    }
    const auto r = tuning::plantResonanceHz(f, twoMass, tuning::DriveInput::Torque, 20.0);
    ASSERT_TRUE(r.has_value());
    EXPECT_NEAR(*r, 120.0, 1.0);
    EXPECT_FALSE(tuning::plantResonanceHz(f, rigid, tuning::DriveInput::Torque, 20.0).has_value());
    // With what the GUI's resonance table shows: the −3 dB width of a lightly damped mode is its half-power bandwidth
    // 2ζ·f_r = 4.8 Hz (within 0.5 Hz: the lines are 1 Hz apart, interpolated linearly); the rise above the median of
    // the lines, which lie at or above the high-frequency asymptote, is at most the peak over that asymptote,
    // (1 − (f_a/f_r)²)/(2ζ) = 13.9 (22.85 dB).
    const auto full = tuning::plantResonance(f, twoMass, tuning::DriveInput::Torque, 20.0);
    ASSERT_TRUE(full.has_value());
    EXPECT_EQ(full->freqHz, *r);
    EXPECT_NEAR(full->widthHz, 2.0 * zr * 120.0, 0.5);
    EXPECT_FALSE(full->widthOneSided);
    EXPECT_GT(full->peakDb, 6.0);
    EXPECT_LE(full->peakDb, 20.0 * std::log10((1.0 - std::pow(80.0 / 120.0, 2)) / (2.0 * zr)) + 0.01);
    EXPECT_NEAR(full->levelDb - full->baselineDb, full->peakDb, 1e-12);
    EXPECT_FALSE(tuning::plantResonance(f, rigid, tuning::DriveInput::Torque, 20.0).has_value());
}
