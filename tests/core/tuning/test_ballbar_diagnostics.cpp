// SPDX-License-Identifier: GPL-3.0-or-later
// Ball-bar diagnostics on synthetic circles built here from an exact geometric machine model with
// known injected errors. The first-order radial formulas of docs/ballbar.md are re-derived in this file
// (FirstOrder*) and checked against the exact geometry, independently of the code under test.
#include "core/tuning/BallBarDiagnostics.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

using namespace axistune;
using namespace axistune::tuning;
using io::BallBarTrace;
using io::CircleDirection;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

struct Machine {
    double radius = 0.1;
    double feedMmMin = 1000.0;
    bool ccw = true;
    double offsetX = 0.0, offsetY = 0.0; ///< machine circle centre minus ball-bar pivot [m]
    double scaleX = 0.0, scaleY = 0.0;   ///< ε per axis
    double squareness = 0.0;             ///< γ: x_actual += γ·y
    double lagX = 0.0, lagY = 0.0;       ///< τ per axis [s]
    double lostX = 0.0, lostY = 0.0;     ///< lost motion per axis [m] (step at reversal)
    double cyclicAmpX = 0.0, cyclicPitchX = 0.01;
    double spikeHeight = 0.0, spikeFwhmDeg = 1.0, spikeCentreDeg = 1.0; ///< radial bump after the Y 90° reversal
    double noise = 0.0;
    double stepDeg = 0.1;
    double startDeg = 0.0, spanDeg = 360.0;
    unsigned seed = 1;
};

double sgn(double v)
{
    return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
}

/// Exact geometry: axis positions from the commanded angle with lag, lost motion, scale, squareness and
/// cyclic error; the bar length is |p − pivot|; the angle column is the commanded angle.
BallBarTrace makeTrace(const Machine& m)
{
    BallBarTrace t;
    t.source = "synthetic";
    t.radiusM = m.radius;
    t.feedMPerS = m.feedMmMin * 1e-3 / 60.0;
    t.direction = m.ccw ? CircleDirection::Ccw : CircleDirection::Cw;
    const double sigma = m.ccw ? 1.0 : -1.0;
    const double omega = t.feedMPerS / m.radius;
    std::mt19937 rng(m.seed);
    std::normal_distribution<double> noise(0.0, 1.0);
    const int n = static_cast<int>(std::lround(m.spanDeg / m.stepDeg));
    for (int k = 0; k < n; ++k) {
        const double phi = (m.startDeg + sigma * k * m.stepDeg) * kDeg;
        const double phx = phi - sigma * omega * m.lagX, phy = phi - sigma * omega * m.lagY;
        double x = m.radius * std::cos(phx), y = m.radius * std::sin(phy);
        const double vx = -sigma * std::sin(phx), vy = sigma * std::cos(phy); // velocity signs
        x -= 0.5 * m.lostX * sgn(vx);
        y -= 0.5 * m.lostY * sgn(vy);
        x += m.cyclicAmpX * std::sin(2 * kPi * x / m.cyclicPitchX + 0.3);
        x *= 1.0 + m.scaleX;
        y *= 1.0 + m.scaleY;
        x += m.squareness * y;
        double dr = std::hypot(x + m.offsetX, y + m.offsetY) - m.radius;
        if (m.spikeHeight != 0.0) {
            const double d = sigma * std::remainder(phi - 0.5 * kPi, 2 * kPi) / kDeg - m.spikeCentreDeg;
            const double s = m.spikeFwhmDeg / (2.0 * std::sqrt(2.0 * std::log(2.0)));
            dr += m.spikeHeight * std::exp(-0.5 * d * d / (s * s));
        }
        t.angleRad.push_back(phi);
        t.deviationM.push_back(dr + m.noise * noise(rng));
    }
    return t;
}

/// Injected value within 10 % or within `floor` (1 µm for µm quantities), whichever is larger.
void expectWithin(double got, double want, double floor, const char* what)
{
    EXPECT_NEAR(got, want, std::max(0.1 * std::abs(want), floor)) << what;
}

// First-order radial deviation of each error alone (docs/ballbar.md), derived here independently:
// Δr ≈ e·u with u = (cosθ, sinθ) and e the position error vector.
double firstOrderOffset(double th, double ox, double oy)
{
    return ox * std::cos(th) + oy * std::sin(th);
}
double firstOrderScale(double th, double r, double ex, double ey)
{
    return r * (ex * std::cos(th) * std::cos(th) + ey * std::sin(th) * std::sin(th));
}
double firstOrderSquareness(double th, double r, double g)
{
    return g * r * std::sin(th) * std::cos(th);
}
double firstOrderServo(double th, double v, double sigma, double dtau)
{
    return 0.5 * sigma * v * dtau * std::sin(2 * th);
}
/// Lost motion L of X: the axis lags L/2 against its velocity ẋ = d(R cos θ)/dt = −σ ω R sin θ.
double firstOrderLostX(double th, double sigma, double lost)
{
    const double xdot = -sigma * std::sin(th);
    return -0.5 * lost * (xdot > 0 ? 1.0 : (xdot < 0 ? -1.0 : 0.0)) * std::cos(th);
}

} // namespace

TEST(BallBarGeometry, FirstOrderFormulasMatchExactGeometry)
{
    Machine base;
    base.stepDeg = 1.0;
    auto check = [&](const Machine& m, auto formula, const char* what) {
        const auto t = makeTrace(m);
        double worst = 0.0;
        for (std::size_t i = 0; i < t.size(); ++i)
            worst = std::max(worst, std::abs(t.deviationM[i] - formula(t.angleRad[i])));
        EXPECT_LT(worst, 2e-9) << what; // second-order terms: (10 µm)²/100 mm = 1 nm
    };
    Machine m = base;
    m.offsetX = 8e-6, m.offsetY = -5e-6;
    check(
        m, [&](double th) { return firstOrderOffset(th, 8e-6, -5e-6); }, "centre offset");
    m = base, m.scaleX = 60e-6, m.scaleY = -20e-6;
    check(
        m, [&](double th) { return firstOrderScale(th, 0.1, 60e-6, -20e-6); }, "scale");
    m = base, m.squareness = 80e-6;
    check(
        m, [&](double th) { return firstOrderSquareness(th, 0.1, 80e-6); }, "squareness");
    for (bool ccw : {true, false}) {
        m = base, m.ccw = ccw, m.lagX = 0.5e-3;
        const double v = 1000e-3 / 60.0;
        check(
            m, [&](double th) { return firstOrderServo(th, v, ccw ? 1.0 : -1.0, 0.5e-3); }, "servo mismatch");
    }
    for (bool ccw : {true, false}) {
        m = base, m.lostX = 3e-6, m.ccw = ccw;
        check(
            m, [&](double th) { return firstOrderLostX(th, ccw ? 1.0 : -1.0, 3e-6); }, "lost motion X");
    }
    // The code's basis agrees with the independent formula away from the reversal instants.
    for (double th = 0.01; th < 2 * kPi; th += 0.1) {
        for (double sigma : {1.0, -1.0})
            EXPECT_NEAR(3e-6 * lostMotionBasis(0, th, sigma), firstOrderLostX(th, sigma, 3e-6), 1e-18);
    }
    // The basis itself, by hand: CCW, just after the X reversal at 0° the trace is +L/2 (outward step).
    EXPECT_DOUBLE_EQ(lostMotionBasis(0, 1e-3, 1.0), 0.5 * std::cos(1e-3));
    EXPECT_DOUBLE_EQ(lostMotionBasis(0, -1e-3, 1.0), -0.5 * std::cos(1e-3));
    EXPECT_DOUBLE_EQ(lostMotionBasis(1, 0.5 * kPi - 1e-3, -1.0), 0.5 * std::sin(0.5 * kPi - 1e-3));
}

TEST(BallBarDiagnostics, RecoversInjectedErrorsFromCwAndCcw)
{
    Machine m;
    m.offsetX = 5e-6, m.offsetY = -3e-6;
    m.scaleX = 40e-6, m.scaleY = -20e-6; // mismatch 60 ppm, mean +10 ppm → radius +1 µm
    m.squareness = 80e-6;
    m.lagX = 0.5e-3;                 // X lags Y by 0.5 ms
    m.lostX = 3e-6, m.lostY = -2e-6; // negative: inward step
    m.noise = 0.1e-6;
    Machine cw = m;
    cw.ccw = false, cw.startDeg = 360.0, cw.seed = 2;
    const std::vector<BallBarTrace> runs{makeTrace(m), makeTrace(cw)};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok()) << rep.error().detail;
    ASSERT_TRUE(rep->centerXM && rep->scaleMismatch && rep->squarenessRad && rep->servoMismatchS);
    expectWithin(*rep->centerXM * 1e6, 5.0, 1.0, "centre x um");
    expectWithin(*rep->centerYM * 1e6, -3.0, 1.0, "centre y um");
    expectWithin(*rep->radiusDeviationM * 1e6, 1.0, 1.0, "radius deviation um");
    expectWithin(*rep->scaleMismatch * 1e6, 60.0, 0.0, "scale mismatch ppm");
    expectWithin(*rep->squarenessRad * 1e6, 80.0, 0.0, "squareness um/m");
    expectWithin(*rep->servoMismatchS * 1e3, 0.5, 0.0, "servo mismatch ms");
    ASSERT_TRUE(rep->backlashM[0] && rep->backlashM[1]);
    expectWithin(*rep->backlashM[0] * 1e6, 3.0, 1.0, "backlash x um");
    expectWithin(*rep->backlashM[1] * 1e6, -2.0, 1.0, "backlash y um");
    EXPECT_NEAR(*rep->backlashM[0] * 1e6, 3.0, 0.3); // tighter than the 1 µm floor: the step model is exact
    EXPECT_NEAR(*rep->backlashM[1] * 1e6, -2.0, 0.3);
    for (const auto& s : rep->spikes)
        ADD_FAILURE() << "unexpected spike: axis " << s.axis << " at " << s.angleRad / kDeg << " deg, "
                      << s.heightM * 1e6 << " um";
    ASSERT_TRUE(rep->circularityM);
    // Circularity, independently: the injected errors other than the centre offset have no first
    // harmonic, so the least-squares circle is the injected one; peak-to-valley of the noise-free
    // traces minus the offset term, the larger of the two runs.
    double expected = 0.0;
    for (Machine mm : {m, cw}) {
        mm.noise = 0.0;
        const auto clean = makeTrace(mm);
        double lo = 1.0, hi = -1.0;
        for (std::size_t i = 0; i < clean.size(); ++i) {
            const double v = clean.deviationM[i] - firstOrderOffset(clean.angleRad[i], m.offsetX, m.offsetY);
            lo = std::min(lo, v), hi = std::max(hi, v);
        }
        expected = std::max(expected, hi - lo);
    }
    expectWithin(*rep->circularityM * 1e6, expected * 1e6, 1.0, "circularity um");
    for (int axis = 0; axis < 2; ++axis)
        EXPECT_FALSE(rep->cyclic[axis]->detected) << axis;
    for (const auto& f : rep->findings) {
        EXPECT_FALSE(f.rule.empty()) << f.name;
        EXPECT_FALSE(f.ruleId.empty()) << f.name; // the key a user interface words in its own language
    }
}

TEST(BallBarDiagnostics, SingleDirectionReportsSquarenessWithServoMismatchRefused)
{
    Machine m;
    m.squareness = -50e-6;
    m.noise = 0.05e-6;
    const std::vector<BallBarTrace> runs{makeTrace(m)};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok());
    expectWithin(*rep->squarenessRad * 1e6, -50.0, 0.0, "squareness");
    EXPECT_FALSE(rep->servoMismatchS.has_value());
    ASSERT_FALSE(rep->refused.empty());
    EXPECT_NE(rep->refused.front().text.find("both directions"), std::string::npos);
    EXPECT_EQ(rep->refused.front().id, "servo_mismatch.one_direction");
    EXPECT_EQ(rep->refused.front().args, std::vector<std::string>{"CCW"});
}

TEST(BallBarDiagnostics, ServoMismatchAloneIsNotMistakenForSquareness)
{
    Machine m;
    m.lagY = 0.8e-3; // Y lags: Δτ = τx − τy = −0.8 ms
    m.feedMmMin = 2000.0;
    Machine cw = m;
    cw.ccw = false;
    const std::vector<BallBarTrace> runs{makeTrace(m), makeTrace(cw)};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok());
    expectWithin(*rep->servoMismatchS * 1e3, -0.8, 0.0, "servo mismatch ms");
    EXPECT_NEAR(*rep->squarenessRad * 1e6, 0.0, 1.0);
}

TEST(BallBarDiagnostics, ReversalSpikeHeightAndWidth)
{
    Machine m;
    m.spikeHeight = 4e-6, m.spikeFwhmDeg = 1.2, m.spikeCentreDeg = 1.5;
    m.lostY = 1.5e-6;
    m.noise = 0.1e-6;
    m.stepDeg = 0.05;
    const std::vector<BallBarTrace> runs{makeTrace(m)};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok());
    ASSERT_EQ(rep->spikes.size(), 1u);
    const auto& s = rep->spikes.front();
    EXPECT_EQ(s.axis, 1);
    expectWithin(s.heightM * 1e6, 4.0, 1.0, "spike height um");
    EXPECT_NEAR(s.heightM * 1e6, 4.0, 0.4);
    EXPECT_NEAR(s.angleRad / kDeg, 91.5, 0.2);
    expectWithin(s.widthRad / kDeg, 1.2, 0.0, "spike width deg");
    expectWithin(*rep->backlashM[1] * 1e6, 1.5, 1.0, "backlash y");
}

TEST(BallBarDiagnostics, CyclicErrorAmplitudeAndPitch)
{
    Machine m;
    m.cyclicAmpX = 1.5e-6, m.cyclicPitchX = 0.012; // one screw lead
    m.noise = 0.1e-6;
    const std::vector<BallBarTrace> runs{makeTrace(m)};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok());
    ASSERT_TRUE(rep->cyclic[0]);
    EXPECT_TRUE(rep->cyclic[0]->detected);
    expectWithin(rep->cyclic[0]->amplitudeM * 1e6, 1.5, 0.0, "cyclic amplitude um");
    expectWithin(rep->cyclic[0]->pitchM * 1e3, 12.0, 0.0, "cyclic pitch mm");
    EXPECT_FALSE(rep->cyclic[1]->detected);
}

TEST(BallBarDiagnostics, PartialArcRefusesFullCircleDiagnosticsButKeepsReversals)
{
    Machine m;
    m.startDeg = -60.0, m.spanDeg = 220.0; // covers the X reversal at 0° and the Y reversal at 90°
    m.lostX = 2e-6;
    const auto t = makeTrace(m);
    auto s = requireFullCircle(t, {}, "circularity");
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().detail.find("circularity refused: requires a full 360° circle"), std::string::npos)
        << s.error().detail;
    EXPECT_NE(s.error().detail.find("covering 219.9°"), std::string::npos) << s.error().detail;
    const std::vector<BallBarTrace> runs{t};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok());
    EXPECT_FALSE(rep->circularityM.has_value());
    EXPECT_FALSE(rep->scaleMismatch.has_value());
    ASSERT_TRUE(rep->backlashM[0]);
    EXPECT_NEAR(*rep->backlashM[0] * 1e6, 2.0, 0.2);
    ASSERT_EQ(rep->runs.front().events.size(), 2u); // X at 0°, Y at 90°
    auto ev = fitReversal(t, 0, kPi, {});
    ASSERT_FALSE(ev.ok());
    EXPECT_NE(ev.error().detail.find("X reversal at 180° is not covered"), std::string::npos) << ev.error().detail;
}

TEST(BallBarDiagnostics, CircularityOfAPureEllipseIsAnalytic)
{
    // Δr = c·cos2θ after removing the circle: peak-to-valley 2c exactly.
    Machine m;
    m.scaleX = 50e-6, m.scaleY = -50e-6; // c = R·(εx−εy)/2 = 5 µm
    const auto t = makeTrace(m);
    auto c = circularityOf(t.angleRad, t.deviationM);
    ASSERT_TRUE(c.ok());
    EXPECT_NEAR(*c * 1e6, 10.0, 0.01);
}
