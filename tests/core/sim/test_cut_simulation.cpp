// SPDX-License-Identifier: GPL-3.0-or-later
// The milling cut on a simulated feed axis (core/sim/CutSimulation): the process force reaches the trace
// with the table's sign, nothing before the tool engages, and the refusals name what is wrong.
#include "core/sim/CutSimulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace axistune;
using namespace axistune::sim;

namespace {

CutSimulationOptions stableCut()
{
    CutSimulationOptions o;
    auto& s = o.milling;
    s.modesX = s.modesY = {{0.40, 83.0, 30.1e6}};  // Table 1 tool (spec/chatter-stability-and-spindle-speed.md)
    s.teeth = 4;
    s.ktNPerM2 = 0.980e9;
    s.krNPerM2 = 0.294e9;
    s.radialImmersion = 7.0 / 12.0;
    s.spindleRpm = 1500;
    s.axialDepthM = 0.5e-3;  // below the lobe limit: stable
    s.feedPerToothM = 0.1e-3;
    o.durationS = 0.6;
    o.engageS = 0.2;
    return o;
}

} // namespace

TEST(CutSimulation, MeanTableForceIsMinusTheStaticChipForceAndZeroBeforeEngagement)
{
    auto def = loadPreset("vmc");
    ASSERT_TRUE(def);
    const auto o = stableCut();
    auto cap = simulateCut(*def->axis("X"), o);
    ASSERT_TRUE(cap) << cap.error().detail;
    const auto* t = cap->channel("t_s");
    const auto* f = cap->channel("cutting_force_N");
    ASSERT_TRUE(t && f && cap->channel("tool_x_m"));
    ASSERT_EQ(t->data.size(), f->data.size());
    // Down milling, engagement [acos(2r − 1), π]: mean F_x on the tool = a f_z N/(2π) ∫ (K_t sinφ cosφ + K_r sin²φ) dφ;
    // the table gets the opposite force.
    const auto& s = o.milling;
    const double pi = std::numbers::pi, st = std::acos(2 * s.radialImmersion - 1), en = pi;
    const double integral = s.ktNPerM2 * 0.5 * (std::pow(std::sin(en), 2) - std::pow(std::sin(st), 2)) +
                            s.krNPerM2 * (0.5 * (en - st) - 0.25 * (std::sin(2 * en) - std::sin(2 * st)));
    const double toolForce = s.axialDepthM * s.feedPerToothM * s.teeth / (2 * pi) * integral;
    double before = 0.0, mean = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < t->data.size(); ++i) {
        if (t->data[i] < o.engageS - 1e-3)
            before = std::max(before, std::abs(f->data[i]));
        if (t->data[i] >= 0.4) {  // 20 tooth periods after 0.2 s of settling
            mean += f->data[i];
            ++n;
        }
    }
    ASSERT_GT(n, 100);
    mean /= n;
    EXPECT_EQ(before, 0.0);
    EXPECT_NEAR(mean, -toolForce, 0.02 * std::abs(toolForce));
    EXPECT_EQ(cap->metadata.text("lost_motion"), "off");
}

TEST(CutSimulation, RefusesRotaryAxesAndBadTimes)
{
    auto rotary = loadPreset("two-inertia");
    ASSERT_TRUE(rotary);
    auto r = simulateCut(*rotary->axis("A"), stableCut());
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().detail.find("linear feed axis"), std::string::npos) << r.error().detail;
    auto vmc = loadPreset("vmc");
    auto o = stableCut();
    o.durationS = 0.0;
    auto d = simulateCut(*vmc->axis("X"), o);
    ASSERT_FALSE(d);
    EXPECT_NE(d.error().detail.find("duration"), std::string::npos);
    o = stableCut();
    o.milling.teeth = 0;
    auto m = simulateCut(*vmc->axis("X"), o);
    ASSERT_FALSE(m);
    EXPECT_NE(m.error().detail.find("teeth"), std::string::npos) << m.error().detail;
}
