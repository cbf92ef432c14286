// SPDX-License-Identifier: GPL-3.0-or-later
// The following error of a move predicted from measured plant lines (core/tuning/MovePrediction), against an
// independent time-domain simulation of the same discrete loop: LinuxCNC's pid computed step by step exactly as
// pid.N.do-pid-calcs does (integrator, backward-difference derivative, FF1/FF2 from backward differences of the
// command) around a rigid body under zero-order hold.
#include "core/sim/MotionProfile.h"
#include "core/tuning/MovePrediction.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune;
using namespace axistune::tuning;
using cd = std::complex<double>;

namespace {

constexpr double kT = 1e-3; // 1 kHz servo thread
constexpr double kJ = 2e-3; // command units: mm; output: torque per (mm/s²) × 1000

/// Exact discrete response of 1/(J s²) under zero-order hold: T²(z+1) / (2J(z−1)²).
cd rigidBody(double fHz)
{
    const cd z = std::polar(1.0, 2.0 * std::numbers::pi * fHz * kT);
    return kT * kT * (z + 1.0) / (2.0 * kJ * (z - 1.0) * (z - 1.0));
}

/// The loop simulated sample by sample as LinuxCNC 2.9's calc_pid computes it: returns the error pin at each period
/// (r[n−1] − y[n] with error-previous-target, else r[n] − y[n]); D acts on the difference of the command's and the
/// feedback's backward differences.
std::vector<double> simulate(const PositionPid& g, const std::vector<double>& r, bool errorPreviousTarget)
{
    double x = 0.0, v = 0.0, integral = 0.0, xPrev = 0.0, rPrev = r.front(), cdPrev = 0.0;
    std::vector<double> out;
    for (double rn : r) {
        const double e = (errorPreviousTarget ? rPrev : rn) - x;
        integral += e * kT;
        const double cmdD = (rn - rPrev) / kT;
        const double cmdDD = (cmdD - cdPrev) / kT;
        const double u = g.p * e + g.i * integral + g.d * (cmdD - (x - xPrev) / kT) + g.ff1 * cmdD + g.ff2 * cmdDD;
        xPrev = x;
        rPrev = rn;
        cdPrev = cmdD;
        out.push_back(e);
        x += kT * v + kT * kT / (2.0 * kJ) * u;
        v += kT / kJ * u;
    }
    return out;
}

std::vector<double> outAndBack(double distance, double velocity, double acceleration)
{
    sim::MotionProfile p;
    p.dwell(0.05);
    p.move(distance, velocity, acceleration);
    p.move(-distance, velocity, acceleration);
    p.dwell(0.05);
    std::vector<double> r;
    for (std::size_t i = 0; static_cast<double>(i) * kT <= p.duration(); ++i)
        r.push_back(p.at(static_cast<double>(i) * kT).position);
    r.back() = 0.0;
    return r;
}

struct Lines {
    std::vector<double> f;
    std::vector<cd> p;
};

Lines measuredLines(double fmin, double fmax, double spacing)
{
    Lines l;
    for (double f = fmin; f <= fmax + 1e-9; f += spacing) {
        l.f.push_back(f);
        l.p.push_back(rigidBody(f));
    }
    return l;
}

// A crossover near 20 Hz: P = J ω², D = 1.5 J ω, I = P ω / 8; FF2 80 % of J (an imperfect feedforward, so that the
// error is not only the FF1-free velocity lag).
const double kW = 2.0 * std::numbers::pi * 20.0;
const PositionPid kGains{kJ * kW * kW, kJ* kW* kW* kW / 8.0, 1.5 * kJ* kW, 0.0, 0.8 * kJ};

} // namespace

class MovePredictionLoop : public ::testing::TestWithParam<bool> {};

TEST_P(MovePredictionLoop, EqualsTheLoopSimulatedStepByStep)
{
    const bool ept = GetParam();
    const auto r = outAndBack(10.0, 100.0, 2000.0);
    const auto sim = simulate(kGains, r, ept);
    double peakSim = 0.0;
    for (double e : sim)
        peakSim = std::max(peakSim, std::abs(e));
    ASSERT_GT(peakSim, 0.002); // a following error worth predicting (mm)

    // Lines as multisine measures them: 2 to 450 Hz, 1 Hz apart.
    const auto lines = measuredLines(2.0, 450.0, 1.0);
    MovePredictionOptions o;
    o.errorPreviousTarget = ept;
    auto pred = predictMove(lines.f, lines.p, kGains, kT, r, o);
    ASSERT_TRUE(pred.ok()) << pred.error().detail;
    // The interpolation between 1 Hz lines and the rigid-body extrapolation below 2 Hz are the only differences
    // from the exact loop: within 1 % of the peak everywhere.
    double worst = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i)
        worst = std::max(worst, std::abs(pred->error[i] - sim[i]));
    EXPECT_LT(worst, 0.01 * peakSim);
    EXPECT_NEAR(pred->peakError, peakSim, 0.01 * peakSim);
    EXPECT_NEAR(pred->lowDecadeOrder, 2.0, 0.05); // the rigid body's slope over 2–20 Hz
}

INSTANTIATE_TEST_SUITE_P(ErrorPreviousTarget, MovePredictionLoop, ::testing::Bool(),
                         [](const auto& p) { return p.param ? "PreviousTarget" : "CurrentTarget"; });

TEST(MovePrediction, ABandThatDoesNotReachTheRigidBodyIsRefused)
{
    const auto r = outAndBack(10.0, 100.0, 2000.0);
    // A plant 1/(J s² + b s) with its friction corner b/(2πJ) at 30 Hz, measured from 10 Hz only: over its lowest
    // decade it falls as neither f⁻² nor f⁻¹, and most of the move's error lies below it.
    Lines lines;
    const double b = kJ * 2.0 * std::numbers::pi * 30.0;
    for (double f = 10.0; f <= 450.0; f += 1.0) {
        const cd s(0.0, 2.0 * std::numbers::pi * f);
        lines.f.push_back(f);
        lines.p.push_back(1.0 / (kJ * s * s + b * s));
    }
    auto pred = predictMove(lines.f, lines.p, kGains, kT, r);
    ASSERT_FALSE(pred.ok());
    EXPECT_NE(pred.error().detail.find("below the measured lines"), std::string::npos) << pred.error().detail;
    EXPECT_NE(pred.error().detail.find("lower --fmin"), std::string::npos) << pred.error().detail;
}

TEST(MovePrediction, AMoveThatDoesNotReturnIsRefused)
{
    const auto lines = measuredLines(2.0, 450.0, 1.0);
    std::vector<double> oneWay{0.0, 0.5, 1.0, 1.0};
    auto pred = predictMove(lines.f, lines.p, kGains, kT, oneWay);
    ASSERT_FALSE(pred.ok());
    EXPECT_NE(pred.error().detail.find("end where it starts"), std::string::npos);
    std::vector<double> bad{0.0, NAN, 0.0};
    EXPECT_FALSE(predictMove(lines.f, lines.p, kGains, kT, bad).ok());
}
