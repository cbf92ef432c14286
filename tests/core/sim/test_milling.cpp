// SPDX-License-Identifier: GPL-3.0-or-later
// Milling with regeneration (core/sim/Milling) and the load-torque hook of the axis simulator.
// Stability points from the semi-discretization lobes (core/machining/StabilityLobes, an independent
// method), computed with
//   axistune-cli lobes --tool resources/samples/tool-table1.json --cut resources/samples/cut-table1.json
//       --rpm-min 1000 --rpm-max 3500 --rpm-step 50 --steps-per-period 160
// which gives a limit of 1.07 mm at 1500 rpm and 0.94 mm at 2800 rpm (Table 1 tool of seed 000).
#include "core/sim/AxisSimulator.h"
#include "core/sim/Milling.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <vector>

#include "tests/core/sim/SimTestUtil.h"

using namespace axistune::sim;

namespace {
constexpr double kPi = std::numbers::pi;

MillingSetup table1(double rpm, double depthM)
{
    MillingSetup s;
    s.modesX = s.modesY = {{0.40, 83.0, 30.1e6}};
    s.teeth = 4;
    s.ktNPerM2 = 0.980e9;
    s.krNPerM2 = 0.294e9;
    s.radialImmersion = 7.0 / 12.0;
    s.upMilling = false;
    s.spindleRpm = rpm;
    s.axialDepthM = depthM;
    s.feedPerToothM = 0.1e-3;
    return s;
}

struct Run {
    std::vector<double> t, regen, fx;
};

/// Runs the process alone; `regen` is x(t) − x(t − τ), zero for a periodic (stable) response.
Run runProcess(const MillingSetup& s, double duration)
{
    auto p = MillingProcess::create(s);
    EXPECT_TRUE(p);
    auto proc = p.value();
    Run r;
    const double tau = proc.toothPeriodS(), h = 50e-6; // sampled at 20 kHz
    std::vector<double> xs;
    const auto lag = static_cast<std::size_t>(std::llround(tau / h));
    for (double t = h; t <= duration + 1e-12; t += h) {
        r.fx.push_back(proc.advanceTo(t));
        xs.push_back(proc.toolX());
        r.t.push_back(t);
        r.regen.push_back(xs.size() > lag ? xs.back() - xs[xs.size() - 1 - lag] : 0.0);
    }
    return r;
}

double maxAbs(const std::vector<double>& v, std::size_t from, std::size_t to)
{
    double m = 0;
    for (std::size_t i = from; i < to; ++i)
        m = std::max(m, std::abs(v[i]));
    return m;
}
} // namespace

TEST(Milling, RejectsBadSetup)
{
    auto s = table1(1500, 1e-3);
    s.modesX[0].massKg = 0.0;
    auto r = MillingProcess::create(s);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().detail.find("modes_x[0].mass_kg"), std::string::npos);
    s = table1(1500, 1e-3);
    s.radialImmersion = 1.2;
    EXPECT_FALSE(MillingProcess::create(s));
    s = table1(1500, 1e-3);
    s.modesY[0].stiffnessNPerM = -1.0;
    EXPECT_FALSE(MillingProcess::create(s));
    s = table1(-5, 1e-3);
    EXPECT_FALSE(MillingProcess::create(s));
}

TEST(Milling, MeanForceOfStableCutIsTheStaticChipForce)
{
    // Stable: the response becomes tooth-periodic, h = f_z sin φ, and the mean of F_x over a tooth period is
    // a f_z N/(2π) ∫ (K_t sin φ cos φ + K_r sin² φ) dφ over the engagement [acos(2r − 1), π] (down milling).
    const auto s = table1(1500, 0.5e-3);
    const auto r = runProcess(s, 0.4);
    const double st = std::acos(2 * s.radialImmersion - 1), en = kPi;
    const double integral = s.ktNPerM2 * 0.5 * (std::pow(std::sin(en), 2) - std::pow(std::sin(st), 2)) +
                            s.krNPerM2 * (0.5 * (en - st) - 0.25 * (std::sin(2 * en) - std::sin(2 * st)));
    const double expected = s.axialDepthM * s.feedPerToothM * s.teeth / (2 * kPi) * integral;
    // Mean over the last 40 tooth periods (0.4 − 0.1 s at 1500 rpm ×4 = 100 Hz): 6000 samples at 20 kHz.
    double mean = 0;
    const std::size_t n = r.fx.size(), m = 2000 * 3;
    for (std::size_t i = n - m; i < n; ++i)
        mean += r.fx[i];
    mean /= m;
    EXPECT_NEAR(mean, expected, 0.01 * std::abs(expected));
}

TEST(Milling, BelowTheLobeLimitStableAboveChatters)
{
    const double limit = 1.07e-3; // SDM at 1500 rpm (file header)
    const auto stable = runProcess(table1(1500, 0.5 * limit), 0.6);
    const auto chatter = runProcess(table1(1500, 2.0 * limit), 0.6);
    const std::size_t n = stable.regen.size(), early = n / 6, late = n - n / 6;
    // Stable: the regenerative difference dies out (the first tooth period enters a clean surface).
    EXPECT_LT(maxAbs(stable.regen, late, n), 0.02 * maxAbs(stable.regen, 0, early));
    // Chatter: it grows to a limit cycle bounded by the tooth leaving the cut. The surface a tooth leaves where
    // it is out of the material stays for the next one (multiple regeneration), which bounds the cycle early:
    // 2.9× the level of 25–50 ms after entry (measured 1.38e-4 m against 4.7e-5 m); the stable cut decays
    // by orders of magnitude over the same time.
    EXPECT_GT(maxAbs(chatter.regen, late, n), 2.0 * maxAbs(chatter.regen, early / 4, early / 2));
    EXPECT_GT(maxAbs(chatter.regen, late, n), 1e4 * maxAbs(stable.regen, late, n));
    // The chatter frequency is near the tool mode (1380.6 Hz): the largest Fourier line of the difference
    // between 200 Hz and 5 kHz over the last 0.1 s lies within 1300–1700 Hz.
    double bestF = 0, bestA = 0;
    const std::size_t count = 2000;
    for (double f = 200; f <= 5000; f += 5) {
        const double a = std::abs(axistune::simtest::fourierAt(chatter.regen, chatter.t, n - count, count, f));
        if (a > bestA) {
            bestA = a;
            bestF = f;
        }
    }
    EXPECT_GT(bestF, 1300.0);
    EXPECT_LT(bestF, 1700.0);
}

TEST(Milling, LoadTorqueHookIsHeldByThePositionLoop)
{
    auto def = loadPreset("vmc");
    ASSERT_TRUE(def);
    auto created = AxisSimulator::create(*def->axis("X"), 1);
    ASSERT_TRUE(created);
    auto& sim = *created.value();
    Nonlinearities nl;
    nl.noise = nl.friction = nl.quantization = nl.lostMotion = false;
    sim.setNonlinearities(nl);
    sim.reset(0.0);
    sim.setControlMode(ControlMode::Position);
    const double load = 0.4; // N·m on the load side, positive drives the table in +x
    sim.setLoadTorque([load](double) { return load; });
    sim.run(1.0);
    // The integrators of the loops cancel the load: the motor torque settles at −load (static balance).
    EXPECT_NEAR(sim.torque(), -load, 0.005 * load);
    // Semi-closed: the motor encoder holds 0 and the table yields by R·load/K (0.4/337.1 rad × 12 mm/2π).
    const double r = sim.parameter("plant.screw_lead"), k = sim.parameter("plant.coupling_stiffness");
    EXPECT_NEAR(sim.tablePosition(), r * load / k, 0.01 * r * load / k);
    sim.setLoadTorque(nullptr); // an empty function switches the hook off
    sim.run(1.0);
    EXPECT_NEAR(sim.torque(), 0.0, 0.005 * load);
}

TEST(Milling, RigidDirectionHasNoModes)
{
    // modes_y = [] (issue 19): the tool does not move in y; rigid in both directions is refused.
    auto s = table1(1500, 0.5e-3);
    s.modesY.clear();
    auto p = MillingProcess::create(s);
    ASSERT_TRUE(p) << p.error().detail;
    auto proc = p.value();
    double maxX = 0.0;
    for (double t = 50e-6; t <= 0.05; t += 50e-6) {
        proc.advanceTo(t);
        maxX = std::max(maxX, std::abs(proc.toolX()));
        ASSERT_EQ(proc.toolY(), 0.0);
    }
    EXPECT_GT(maxX, 0.0);
    s.modesX.clear();
    auto none = MillingProcess::create(s);
    ASSERT_FALSE(none);
    EXPECT_NE(none.error().detail.find("at least one mode"), std::string::npos) << none.error().detail;
}

TEST(Milling, DelayFollowsTheActualSpindleSpeed)
{
    // Eq. (1-7): the delay is the time the spindle took for the last 2π/N. At constant speed it is one tooth
    // period 60/(n N); after a command change and the spindle's settling (T = 2 ms) it is that of the new speed.
    auto p = MillingProcess::create(table1(2800, 0.5e-3));
    ASSERT_TRUE(p);
    auto proc = p.value();
    proc.advanceTo(0.05);
    EXPECT_NEAR(proc.delayS(), 60.0 / (2800.0 * 4), 1e-9);
    proc.setSpindleCommandRpm(3000.0);
    proc.advanceTo(0.15);
    EXPECT_NEAR(proc.spindleRpm(), 3000.0, 1e-6);
    EXPECT_NEAR(proc.delayS(), 60.0 / (3000.0 * 4), 1e-8);
    // Commands beyond the spindle limits are limited and counted, never passed on.
    proc.setSpindleCommandRpm(1e6);
    EXPECT_DOUBLE_EQ(proc.spindleCommandRpm(), 20000.0);
    EXPECT_EQ(proc.commandLimitCount(), 1u);
}
