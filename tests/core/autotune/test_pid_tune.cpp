// SPDX-License-Identifier: GPL-3.0-or-later
// The proposal step of tuning a position PID the NC closes (core/autotune/PidTune.h), on an analytic plant: a rigid
// body under zero-order hold times a two-mass resonance / anti-resonance pair, with the open loop of known gains.
// Nothing here needs a drive; measuring and applying run on the HAL test machine (tests/linuxcnc, tests/gui/hal).
#include "core/autotune/PidTune.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune;
using namespace axistune::autotune;
using cd = std::complex<double>;

namespace {

constexpr double kRateHz = 1000.0;
constexpr double kT = 1.0 / kRateHz;
constexpr double kJ = 3.77e-4; // N·m·s²/mm (6e-4 kg·m², 10 mm lead)

/// T²(z+1)/(2J(z−1)²)·z⁻¹: the exact ZOH response of 1/(J s²), read one period later.
cd rigidBody(double fHz)
{
    const cd z = std::polar(1.0, 2.0 * std::numbers::pi * fHz * kT);
    return kT * kT * (z + 1.0) / (2.0 * kJ * (z - 1.0) * (z - 1.0)) / z;
}

/// (s²/ωa² + 2ζ s/ωa + 1)/(s²/ωr² + 2ζ s/ωr + 1): anti-resonance fa, resonance fr.
cd twoMass(double fHz, double faHz, double frHz, double zeta)
{
    const cd s(0.0, 2.0 * std::numbers::pi * fHz);
    const double wa = 2.0 * std::numbers::pi * faHz, wr = 2.0 * std::numbers::pi * frHz;
    return (s * s / (wa * wa) + 2.0 * zeta * s / wa + 1.0) / (s * s / (wr * wr) + 2.0 * zeta * s / wr + 1.0);
}

/// LinuxCNC's pid from error to output: P + I·T/(1 − z⁻¹) + D·(1 − z⁻¹)/T (written here, not taken from the code).
cd pid(const tuning::PositionPid& g, double fHz)
{
    const cd zi = std::polar(1.0, -2.0 * std::numbers::pi * fHz * kT);
    return g.p + g.i * kT / (1.0 - zi) + g.d * (1.0 - zi) / kT;
}

/// The audio-EQ cookbook notch at f0 with Q (written here from its definition).
cd notch(double f0, double q, double fHz)
{
    const double w0 = 2.0 * std::numbers::pi * f0 * kT, alpha = std::sin(w0) / (2.0 * q);
    const cd zi = std::polar(1.0, -2.0 * std::numbers::pi * fHz * kT);
    return (1.0 - 2.0 * std::cos(w0) * zi + zi * zi) /
           ((1.0 + alpha) - 2.0 * std::cos(w0) * zi + (1.0 - alpha) * zi * zi);
}

/// A measurement of the loop with `running` on the plant (1 Hz lines, 2..450 Hz).
PidLoopMeasurement measurement(const tuning::PositionPid& running, bool resonant)
{
    PidLoopMeasurement m;
    m.servoRateHz = kRateHz;
    m.fmaxHz = 450.0;
    m.running = running;
    for (double f = 2.0; f <= 450.0; f += 1.0) {
        const cd p = rigidBody(f) * (resonant ? twoMass(f, 160.0, 230.0, 0.03) : 1.0);
        m.freqHz.push_back(f);
        m.plant.push_back(p);
        m.loop.push_back(pid(running, f) * p);
    }
    return m;
}

/// Largest |L| over the lines from f0 to f1.
double peakDb(const std::vector<double>& f, const std::vector<cd>& l, double f0, double f1)
{
    double peak = 0.0;
    for (std::size_t k = 0; k < f.size(); ++k)
        if (f[k] >= f0 && f[k] <= f1)
            peak = std::max(peak, std::abs(l[k]));
    return 20.0 * std::log10(peak);
}

// Gains of a gentle loop (D-dominated, crossover ≈ 15 Hz on the rigid body): the resonance then leaves it a gain
// margin of about 5 dB (|L| at 230 Hz ≈ 15/(2·230) · 1/(2ζ) · |1 − (230/160)²|).
const tuning::PositionPid kRunning{kJ * std::pow(2.0 * std::numbers::pi * 15.0, 2) / 3.0, 0.0,
                                   kJ * 2.0 * std::numbers::pi * 15.0 / 2.0, 0.0, 0.0};

} // namespace

TEST(PidTune, NotchOnlyPutsANotchAtTheResonanceAndKeepsTheRunningGains)
{
    const auto m = measurement(kRunning, true);
    PidTuneRequest r;
    r.axis = "pid.0";
    r.scope = PidTuneScope::NotchOnly;
    r.driveInput = tuning::DriveInput::Torque;
    auto p = proposePidTune(m, r);
    ASSERT_TRUE(p) << p.error().detail;
    ASSERT_TRUE(p->notch) << p->notchRule;
    // The peak of |P|·ω² = |two-mass factor|/J lies within the resonance's half-power band 2ζ·fr (13.8 Hz) of fr.
    EXPECT_NEAR(p->notch->f0Hz, 230.0, 0.03 * 230.0);
    EXPECT_GE(p->notch->q, 0.5);
    EXPECT_LE(p->notch->q, 2.0);
    // The gains are the running ones, unchanged.
    EXPECT_EQ(p->gains.p, kRunning.p);
    EXPECT_EQ(p->gains.i, kRunning.i);
    EXPECT_EQ(p->gains.d, kRunning.d);
    EXPECT_TRUE(p->rules.empty());
    // The predicted loop is C·N·P with the notch written here, within rounding.
    for (std::size_t k = 0; k < m.freqHz.size(); ++k) {
        const cd expected = m.loop[k] * notch(p->notch->f0Hz, p->notch->q, m.freqHz[k]);
        EXPECT_NEAR(std::abs(p->predictedLoop[k] - expected), 0.0, 1e-9 * std::abs(expected)) << m.freqHz[k];
    }
    // At the resonance the loop gain falls by more than the 1 dB the rule asks of the gain margin.
    const double before = peakDb(m.freqHz, m.loop, 150.0, 300.0);
    const double after = peakDb(m.freqHz, p->predictedLoop, 150.0, 300.0);
    EXPECT_LT(after, before - 1.0) << "peak |L| 150..300 Hz before " << before << " dB, after " << after << " dB";
    EXPECT_GE(p->predicted.gainMarginDb, p->runningMargins.gainMarginDb + 1.0);
    EXPECT_GE(p->predicted.phaseMarginDeg, std::min(r.phaseMarginDeg, p->runningMargins.phaseMarginDeg - 3.0));
    EXPECT_NE(p->notchRule.find("the gains are not changed"), std::string::npos) << p->notchRule;
}

TEST(PidTune, NotchOnlyOnARigidBodyProposesNothing)
{
    PidTuneRequest r;
    r.axis = "pid.0";
    r.scope = PidTuneScope::NotchOnly;
    auto p = proposePidTune(measurement(kRunning, false), r);
    ASSERT_TRUE(p) << p.error().detail;
    EXPECT_EQ(p->input, tuning::DriveInput::Torque); // read from the −40 dB/decade slope
    EXPECT_FALSE(p->notch);
    EXPECT_FALSE(p->changesSomething());
    EXPECT_NE(p->notchRule.find("no notch"), std::string::npos) << p->notchRule;
}

/// The measurement of the same loop with AxisTune's notch `n` running after the pid: L = C·N·P, and the plant without
/// it, the lines at the notch's zero (|N| < 1e-3) left out (as measurePidLoop gives it).
PidLoopMeasurement measurementThroughNotch(const tuning::PositionPid& running, const tuning::BiquadNotch& n)
{
    const auto all = measurement(running, true);
    PidLoopMeasurement m = all;
    m.runningNotch = n;
    m.freqHz.clear(), m.loop.clear(), m.plant.clear();
    for (std::size_t k = 0; k < all.freqHz.size(); ++k) {
        const cd nk = notch(n.f0Hz, n.q, all.freqHz[k]);
        if (std::abs(nk) < 1e-3)
            continue;
        m.freqHz.push_back(all.freqHz[k]);
        m.plant.push_back(all.plant[k]);
        m.loop.push_back(all.loop[k] * nk);
    }
    return m;
}

// A second notch-only tune over the notch the first one proposed: the candidates are judged on C·N·P with the plant
// that has no notch, so the running notch is itself the best candidate and nothing better than it by 1 dB exists:
// the proposal keeps it (no change), and its predicted loop is the measured one (C·N·P, not C·N·N·P).
TEST(PidTune, NotchOnlyOverItsOwnNotchKeepsIt)
{
    PidTuneRequest r;
    r.axis = "pid.0";
    r.scope = PidTuneScope::NotchOnly;
    r.driveInput = tuning::DriveInput::Torque;
    auto first = proposePidTune(measurement(kRunning, true), r);
    ASSERT_TRUE(first && first->notch);
    const auto m = measurementThroughNotch(kRunning, *first->notch);
    auto p = proposePidTune(m, r);
    ASSERT_TRUE(p) << p.error().detail;
    ASSERT_TRUE(p->notch) << p->notchRule;
    EXPECT_EQ(p->notch->f0Hz, first->notch->f0Hz);
    EXPECT_EQ(p->notch->q, first->notch->q);
    EXPECT_FALSE(p->notchChanges());
    EXPECT_FALSE(p->changesSomething());
    EXPECT_NE(p->notchRule.find("no new notch; the running notch"), std::string::npos) << p->notchRule;
    for (std::size_t k = 0; k < m.freqHz.size(); ++k)
        EXPECT_NEAR(std::abs(p->predictedLoop[k] - m.loop[k]), 0.0, 1e-9 * std::abs(m.loop[k])) << m.freqHz[k];
}

// Gains without a notch (asked) over a running notch: the gains are designed for the plant alone, the proposal has no
// notch (the running one is removed when it is applied, and its rule says so), and the predicted loop is C·P.
TEST(PidTune, GainsWithoutANotchOverARunningNotchRemoveIt)
{
    const tuning::BiquadNotch running{150.0, 1.0};
    const auto m = measurementThroughNotch(kRunning, running);
    PidTuneRequest r;
    r.axis = "pid.0";
    r.driveInput = tuning::DriveInput::Torque;
    r.notch = false;
    auto p = proposePidTune(m, r);
    ASSERT_TRUE(p) << p.error().detail;
    EXPECT_FALSE(p->notch);
    EXPECT_TRUE(p->notchChanges());
    EXPECT_NE(p->notchRule.find("the running notch (150 Hz, Q 1) is removed"), std::string::npos) << p->notchRule;
    // The same gains as a design on the plant measured without any notch.
    auto plain = proposePidTune(measurement(kRunning, true), r);
    ASSERT_TRUE(plain);
    EXPECT_NEAR(p->gains.p, plain->gains.p, 1e-9 * plain->gains.p);
    EXPECT_NEAR(p->gains.d, plain->gains.d, 1e-9 * plain->gains.d);
    for (std::size_t k = 0; k < m.freqHz.size(); ++k) {
        const cd expected = pid(p->gains, m.freqHz[k]) * m.plant[k];
        EXPECT_NEAR(std::abs(p->predictedLoop[k] - expected), 0.0, 1e-9 * std::abs(expected)) << m.freqHz[k];
    }
}

TEST(PidTune, GainsAndNotchRaiseTheCrossoverAboveTheDesignWithoutANotch)
{
    const auto m = measurement(kRunning, true);
    PidTuneRequest r;
    r.axis = "pid.0";
    r.driveInput = tuning::DriveInput::Torque;
    r.notch = false;
    auto plain = proposePidTune(m, r);
    ASSERT_TRUE(plain) << plain.error().detail;
    EXPECT_FALSE(plain->notch);
    r.notch = true;
    auto notched = proposePidTune(m, r);
    ASSERT_TRUE(notched) << notched.error().detail;
    ASSERT_TRUE(notched->notch) << notched->notchRule;
    EXPECT_NEAR(notched->notch->f0Hz, 230.0, 0.03 * 230.0);
    // The rule: a notch only when the crossover rises by 10 % or more.
    EXPECT_GE(notched->predicted.crossoverHz, 1.1 * plain->predicted.crossoverHz)
        << "with notch " << notched->predicted.crossoverHz << " Hz, without " << plain->predicted.crossoverHz << " Hz";
    EXPECT_FALSE(notched->rules.empty());
    // Both meet the margins asked over the measured lines.
    for (const auto* p : {&*plain, &*notched}) {
        EXPECT_GE(p->predicted.phaseMarginDeg, r.phaseMarginDeg - 0.5);
        EXPECT_GE(p->predicted.gainMarginDb, r.gainMarginDb - 0.1);
    }
}

TEST(PidTune, RequestsOutsideTheirLimitsAreRefusedNamingTheField)
{
    PidTuneRequest r;
    r.axis = "pid.0";
    r.amplitudePct = 5.0;
    EXPECT_TRUE(checkPidTuneRequest(r));
    r.phaseMarginDeg = 85.0;
    auto st = checkPidTuneRequest(r);
    ASSERT_FALSE(st);
    EXPECT_NE(st.error().detail.find("phase margin"), std::string::npos);
    r.phaseMarginDeg = 50.0;
    r.fmaxHz = 1.0;
    st = checkPidTuneRequest(r);
    ASSERT_FALSE(st);
    EXPECT_NE(st.error().detail.find("fmin"), std::string::npos);
    r.fmaxHz = 0.0;
    r.amplitude = std::nan("");
    EXPECT_FALSE(checkPidTuneRequest(r));
    PidLoopMeasurement few;
    few.servoRateHz = kRateHz;
    few.freqHz = {10.0, 20.0};
    few.loop = few.plant = {cd(1.0), cd(0.5)};
    auto p = proposePidTune(few, r);
    ASSERT_FALSE(p);
    EXPECT_NE(p.error().detail.find("too few"), std::string::npos);
}
