// SPDX-License-Identifier: GPL-3.0-or-later
// Backlash steps and reversal spikes told apart (docs/ballbar.md "Reversal spikes"): analytic traces
// built here (a kinematic play between motor and table, a motor transient after each reversal) and
// simulated circles of sim:vmc with the backlash only, friction only, and both. The expected values are
// the injected ones or, for the spike that a ball bar can see behind a backlash, the table's excursion
// computed here from the generated positions (or from the simulator's own position channels), never
// from the code under test.
#include "core/sim/CircleRun.h"
#include "core/sim/CircleTest.h"
#include "core/tuning/BallBarDiagnostics.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

using namespace axistune;
using namespace axistune::tuning;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

struct PlayMachine {
    double radius = 0.1;
    double playX = 0.0, playY = 0.0; ///< backlash [m]
    double spike = 0.0;              ///< peak of the motor's outward transient after every reversal [m]
    double spikePeakDeg = 1.0;       ///< travel angle of that peak
    double noise = 0.05e-6;
    double stepDeg = 0.05;
};

/// Motor transient a·x·exp((1 − x²)/2), x = d/d_p, after a reversal (d = travel angle since it): rises
/// from the reversal, peaks at d_p with a, and is gone (below 0.3 %) at 4 d_p.
double transient(const PlayMachine& m, double d)
{
    const double x = d / (m.spikePeakDeg * kDeg);
    return d <= 0.0 ? 0.0 : m.spike * x * std::exp(0.5 * (1.0 - x * x));
}

struct Generated {
    io::BallBarTrace trace;
    std::vector<double> tableX, tableY; ///< table positions of the recorded samples
};

/// CCW circle from 45° over 360° (a 90° pre-roll settles the play). The motor follows the command plus
/// the outward transient after each reversal of its axis; the table follows the motor through the play
/// (it stands still inside the gap). The angle column is the commanded angle.
Generated makePlayTrace(const PlayMachine& m)
{
    Generated g;
    io::BallBarTrace& t = g.trace;
    t.source = "play";
    t.radiusM = m.radius;
    t.feedMPerS = 1000.0 / 60000.0;
    t.direction = io::CircleDirection::Ccw;
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 1.0);
    const double r = m.radius;
    double tableX = r * std::cos(-45.0 * kDeg), tableY = r * std::sin(-45.0 * kDeg);
    const int n = static_cast<int>(std::lround(450.0 / m.stepDeg));
    for (int k = 0; k <= n; ++k) {
        const double phi = (-45.0 + k * m.stepDeg) * kDeg;
        // Travel since the last reversal of X (at 0, π) and of Y (at π/2, 3π/2); outward = sign at the reversal.
        const double dX = std::fmod(phi + 4 * kPi, kPi), dY = std::fmod(phi - 0.5 * kPi + 4 * kPi, kPi);
        const double outX = std::cos(phi - dX) > 0 ? 1.0 : -1.0, outY = std::sin(phi - dY) > 0 ? 1.0 : -1.0;
        const double motorX = r * std::cos(phi) + outX * transient(m, dX);
        const double motorY = r * std::sin(phi) + outY * transient(m, dY);
        tableX = std::clamp(tableX, motorX - 0.5 * m.playX, motorX + 0.5 * m.playX);
        tableY = std::clamp(tableY, motorY - 0.5 * m.playY, motorY + 0.5 * m.playY);
        if (phi < 45.0 * kDeg)
            continue;
        t.angleRad.push_back(phi);
        t.deviationM.push_back(std::hypot(tableX, tableY) - r + m.noise * noise(rng));
        g.tableX.push_back(tableX);
        g.tableY.push_back(tableY);
    }
    return g;
}

const ReversalSpike* spikeOf(const BallBarReport& rep, int axis, double nearDeg)
{
    for (const auto& s : rep.spikes)
        if (s.axis == axis && std::abs(std::remainder(s.angleRad - nearDeg * kDeg, 2 * kPi)) < 5 * kDeg)
            return &s;
    return nullptr;
}

} // namespace

TEST(BallBarSeparation, AnalyticPureBacklashIsAStepWithoutSpikes)
{
    PlayMachine m;
    m.playX = 8e-6, m.playY = 5e-6;
    const std::vector<io::BallBarTrace> runs{makePlayTrace(m).trace};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok()) << rep.error().detail;
    ASSERT_TRUE(rep->backlashM[0] && rep->backlashM[1]);
    // The table lags b/2 against its motion on both sides once the gap is crossed (1.0° after an X
    // reversal on R 100 mm: R d²/2 = b), well inside the 4° spike zone: the step is the play itself.
    EXPECT_NEAR(*rep->backlashM[0] * 1e6, 8.0, 0.1);
    EXPECT_NEAR(*rep->backlashM[1] * 1e6, 5.0, 0.1);
    EXPECT_TRUE(rep->backlashDetected[0]);
    EXPECT_TRUE(rep->backlashDetected[1]);
    for (const auto& s : rep->spikes)
        EXPECT_LT(std::abs(s.heightM), 1e-6) << "spike " << s.heightM * 1e6 << " um at " << s.angleRad / kDeg;
    // The trace is noise (0.05 µm) and the play: nothing reaches the 0.3 µm detection floor.
    EXPECT_TRUE(rep->spikes.empty());
    for (const auto& f : rep->findings)
        if (f.name == "backlash_x") {
            EXPECT_EQ(f.ruleId, "backlash");
        }
}

TEST(BallBarSeparation, AnalyticPureSpikesAreNotBacklash)
{
    PlayMachine m;
    m.spike = 5e-6;
    const std::vector<io::BallBarTrace> runs{makePlayTrace(m).trace};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok()) << rep.error().detail;
    for (int axis = 0; axis < 2; ++axis) {
        ASSERT_TRUE(rep->backlashM[axis]);
        EXPECT_FALSE(rep->backlashDetected[axis]) << axis << ": " << *rep->backlashM[axis] * 1e6 << " um";
        EXPECT_LT(std::abs(*rep->backlashM[axis]), 0.1e-6) << axis;
    }
    for (const auto& f : rep->findings)
        if (f.name == "backlash_x" || f.name == "backlash_y") {
            EXPECT_EQ(f.ruleId, "backlash.not_detected");
        }
    // One spike per reversal: 5 µm outward at 1° after it (radially |cos| ≈ 1 there).
    ASSERT_EQ(rep->spikes.size(), 4u);
    for (double at : {90.0, 180.0, 270.0, 360.0}) {
        const auto* s = spikeOf(*rep, at == 180.0 || at == 360.0 ? 0 : 1, at + 1.0);
        ASSERT_NE(s, nullptr) << at;
        EXPECT_NEAR(s->heightM * 1e6, 5.0, 0.25) << at;
        EXPECT_NEAR(std::remainder(s->angleRad / kDeg - at, 360.0), 1.0, 0.15) << at; // ± 3 samples: the top is flat
    }
}

TEST(BallBarSeparation, AnalyticBacklashAndSpikeAreBothReported)
{
    PlayMachine m;
    m.playX = 6e-6;
    m.spike = 5e-6;
    const Generated g = makePlayTrace(m);
    const std::vector<io::BallBarTrace> runs{g.trace};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok()) << rep.error().detail;
    EXPECT_NEAR(*rep->backlashM[0] * 1e6, 6.0, 0.15);
    EXPECT_TRUE(rep->backlashDetected[0]);
    EXPECT_FALSE(rep->backlashDetected[1]);
    // What the ball bar can see of the motor's transient behind the play: the table's excursion beyond
    // its lag after the reversal, +b/2 along X, computed here from the generated table positions.
    for (double at : {180.0, 360.0}) {
        double expected = 0.0;
        for (std::size_t i = 0; i < g.trace.size(); ++i) {
            const double d = g.trace.angleRad[i] - at * kDeg;
            if (d <= 0.0 || d > 4.0 * kDeg)
                continue;
            const double th = g.trace.angleRad[i], out = std::cos(at * kDeg);
            const double lagged = m.radius * std::cos(th) + out * 0.5 * m.playX; // table at +b/2 behind its motion
            expected = std::max(expected, out * (g.tableX[i] - lagged) * std::abs(std::cos(th)));
        }
        ASSERT_GT(expected, 3e-6) << "the transient must outlast the gap in this case";
        const auto* s = spikeOf(*rep, 0, at + 1.0);
        ASSERT_NE(s, nullptr) << at;
        EXPECT_NEAR(s->heightM, expected, 0.1 * expected) << at;
    }
    // Y has the spike alone (5 µm).
    for (double at : {90.0, 270.0}) {
        const auto* s = spikeOf(*rep, 1, at + 1.0);
        ASSERT_NE(s, nullptr) << at;
        EXPECT_NEAR(s->heightM * 1e6, 5.0, 0.25) << at;
    }
}

namespace {

sim::MachineDefinition vmcWith(double playX, bool friction, bool lostMotion)
{
    auto loaded = sim::loadPreset("vmc");
    EXPECT_TRUE(loaded.ok());
    sim::MachineDefinition m = *loaded;
    for (auto& a : m.axes) {
        a.values["plant.backlash"] = a.name == "X" ? playX : 0.0;
        if (!friction)
            a.values["plant.coulomb_motor"] = a.values["plant.coulomb_load"] = 0.0;
        if (!lostMotion)
            a.values["plant.lost_motion_A"] = a.values["plant.lost_motion_B"] = 0.0;
    }
    return m;
}

} // namespace

TEST(BallBarSeparation, SimulatedPureBacklashIsAStepWithoutSpikes)
{
    sim::CircleTestOptions o; // R 50 mm, 1000 mm/min, CCW from 45°
    auto run = sim::runCircleTest(vmcWith(8e-6, false, false), o);
    ASSERT_TRUE(run.ok()) << run.error().detail;
    const std::vector<io::BallBarTrace> runs{run->ballbar};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok()) << rep.error().detail;
    // Kinematic play of 8 µm on X: a step of 8 µm (0.2 µm: the servo lag of the motor is in the smooth
    // part, the noise of the 24-bit encoder and the current far below), none on Y.
    EXPECT_NEAR(*rep->backlashM[0] * 1e6, 8.0, 0.2);
    EXPECT_TRUE(rep->backlashDetected[0]);
    EXPECT_FALSE(rep->backlashDetected[1]) << *rep->backlashM[1] * 1e6;
    for (const auto& s : rep->spikes)
        ADD_FAILURE() << "spike " << s.heightM * 1e6 << " um at " << s.angleRad / kDeg << " deg";
}

TEST(BallBarSeparation, SimulatedFrictionSpikesAreNotBacklash)
{
    sim::CircleTestOptions o;
    auto run = sim::runCircleTest(vmcWith(0.0, true, false), o);
    ASSERT_TRUE(run.ok()) << run.error().detail;
    const std::vector<io::BallBarTrace> runs{run->ballbar};
    auto rep = analyzeBallBar(runs);
    ASSERT_TRUE(rep.ok()) << rep.error().detail;
    for (int axis = 0; axis < 2; ++axis)
        EXPECT_FALSE(rep->backlashDetected[axis]) << axis << ": " << *rep->backlashM[axis] * 1e6 << " um";
    // The friction spikes (about 7.5 µm, docs/ballbar.md) at every reversal, outward.
    ASSERT_EQ(rep->spikes.size(), 4u);
    for (const auto& s : rep->spikes)
        EXPECT_GT(s.heightM, 3e-6) << s.angleRad / kDeg;
}

TEST(BallBarSeparation, SimulatedBacklashAndFrictionAreBothReported)
{
    // The play is kinematic (docs/simulator.md "Backlash"): it does not act back on the motor of a
    // semi-closed axis, so with the same seed the motor moves exactly as without it. Once the nut has
    // crossed the gap the table is the motor's position ∓ b/2: the friction spike that peaks after the
    // crossing is the same spike, and the step grows by the play. That is what a separation must report.
    sim::CircleTestOptions o;
    auto friction = sim::runCircleTest(vmcWith(0.0, true, false), o);
    auto mixed = sim::runCircleTest(vmcWith(8e-6, true, false), o);
    ASSERT_TRUE(friction.ok() && mixed.ok());
    const std::vector<io::BallBarTrace> a{friction->ballbar}, b{mixed->ballbar};
    auto repF = analyzeBallBar(a);
    auto repM = analyzeBallBar(b);
    ASSERT_TRUE(repF.ok() && repM.ok());
    // The X motor motion is identical in both runs (the play does not feed back).
    const auto* motorF = friction->traceX.channel("motor_pos_m");
    const auto* motorM = mixed->traceX.channel("motor_pos_m");
    ASSERT_TRUE(motorF && motorM && motorF->data.size() == motorM->data.size());
    for (std::size_t i = 0; i < motorF->data.size(); i += 97)
        ASSERT_EQ(motorF->data[i], motorM->data[i]) << i;
    EXPECT_NEAR((*repM->backlashM[0] - *repF->backlashM[0]) * 1e6, 8.0, 0.2);
    EXPECT_TRUE(repM->backlashDetected[0]);
    EXPECT_FALSE(repM->backlashDetected[1]);
    // The friction spike of X starts at the reversal, while the nut is still inside the gap: the table
    // stands still until the nut has crossed it, so the part of the spike before the crossing is hidden
    // and the visible peak comes later. (The exact height behind a play is checked on the analytic trace,
    // AnalyticBacklashAndSpikeAreBothReported.) Here: a spike is reported at each X reversal, no higher
    // than without the play (+2 % for the noise), at least half of it, and not earlier.
    for (double at : {0.0, 180.0}) {
        const auto* sf = spikeOf(*repF, 0, at + 1.0);
        const auto* sm = spikeOf(*repM, 0, at + 1.0);
        ASSERT_TRUE(sf && sm) << at;
        EXPECT_GT(sf->heightM, 3e-6) << at;
        EXPECT_LE(sm->heightM, 1.02 * sf->heightM) << at;
        EXPECT_GE(sm->heightM, 0.5 * sf->heightM) << at;
        EXPECT_GE(std::remainder(sm->angleRad - sf->angleRad, 2 * kPi), 0.0) << at;
    }
    // Y (no play) reads the same in both runs.
    for (double at : {90.0, 270.0}) {
        const auto* sf = spikeOf(*repF, 1, at + 1.0);
        const auto* sm = spikeOf(*repM, 1, at + 1.0);
        ASSERT_TRUE(sf && sm) << at;
        EXPECT_NEAR(sm->heightM, sf->heightM, 0.01 * sf->heightM) << at;
    }
}
