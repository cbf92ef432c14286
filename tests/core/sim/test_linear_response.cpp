// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated velocity loop of each preset, with noise and nonlinearities off, against the
// transfer function the test computes itself from the preset's parameters (LiftedModel.h):
// within 1 % in magnitude and 1° in phase from 10 Hz to 1.5 kHz (issue 2).
#include "core/sim/AxisSimulator.h"
#include "tests/core/sim/LiftedModel.h"
#include "tests/core/sim/SimTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace axistune;
using namespace axistune::sim;

namespace {

struct Case {
    std::string preset;
    std::string axis;
};

class LinearResponse : public ::testing::TestWithParam<Case> {};

TEST_P(LinearResponse, MatchesIndependentTransferFunction)
{
    auto def = loadPreset(GetParam().preset);
    ASSERT_TRUE(def.ok()) << def.error().detail;
    const AxisDefinition* axis = def->axis(GetParam().axis);
    ASSERT_NE(axis, nullptr);
    const auto model = simtest::buildLiftedVelocityLoop(*axis);

    auto created = AxisSimulator::create(*axis, 7);
    ASSERT_TRUE(created.ok()) << created.error().detail;
    AxisSimulator& s = **created;
    s.setNonlinearities({false, false, false, false, false});
    // Small enough that neither the voltage clamp nor the current limit acts.
    const double amp = 0.01 * axis->values.at("motor.torque_constant") * axis->values.at("motor.max_current")
                       / axis->values.at("velocity.kp");
    const double settle = 0.6, window = 0.2;  // every test frequency is a multiple of 1/window
    for (double f : {10.0, 20.0, 35.0, 50.0, 100.0, 200.0, 400.0, 700.0, 1000.0, 1300.0, 1500.0}) {
        s.reset(0.0);
        s.setControlMode(ControlMode::Velocity);
        s.setVelocityCommand([amp, f](double t) { return amp * std::sin(2.0 * std::numbers::pi * f * t); });
        s.run(settle);
        s.startTrace();
        s.run(window);
        const auto cap = s.takeTrace();
        ASSERT_EQ(s.voltageClampCount(), 0u);
        ASSERT_EQ(s.currentLimitCount(), 0u);
        const auto& t = cap.channel("t_s")->data;
        const std::size_t n = t.size();
        const auto in = simtest::fourierAt(cap.channel("velocity_cmd_rad_s")->data, t, 0, n, f);
        const auto out = simtest::fourierAt(cap.channel("motor_vel_rad_s")->data, t, 0, n, f);
        const auto hSim = out / in;
        const auto hModel = model.response(f);
        EXPECT_NEAR(std::abs(hSim) / std::abs(hModel), 1.0, 0.01) << GetParam().preset << " " << f << " Hz";
        EXPECT_NEAR(simtest::phaseDiffDeg(hSim, hModel), 0.0, 1.0) << GetParam().preset << " " << f << " Hz";
    }
}

INSTANTIATE_TEST_SUITE_P(Presets, LinearResponse,
                         ::testing::Values(Case{"vmc", "X"}, Case{"vmc", "Y"}, Case{"dd-table", "C"},
                                           Case{"two-inertia", "A"}),
                         [](const auto& p) {
                             std::string n = p.param.preset + "_" + p.param.axis;
                             for (auto& c : n)
                                 if (c == '-')
                                     c = '_';
                             return n;
                         });

// The independent model itself is checked against a closed form at low frequency: a rigid inertia
// under velocity PI, where the loop is C(s)/(J s + C(s)) to first order in ωT.
TEST(LiftedModel, TwoInertiaLowFrequencyApproachesUnity)
{
    auto def = loadPreset("two-inertia");
    ASSERT_TRUE(def.ok());
    const auto model = simtest::buildLiftedVelocityLoop(def->axes.front());
    EXPECT_NEAR(std::abs(model.response(0.5)), 1.0, 0.01);
}

}  // namespace
