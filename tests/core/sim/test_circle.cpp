// SPDX-License-Identifier: GPL-3.0-or-later
// Simulated circle test (core/sim/CircleTest.h): path, ball-bar geometry, ΔT from the torque plateaus,
// and the arbitrary position command of AxisSimulator. Expected values come from the injected
// parameters and an independent least-squares fit in the test, never from the code under test.
#include "core/sim/AxisSimulator.h"
#include "core/sim/CircleTest.h"

#include <Eigen/Dense>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune;
using namespace axistune::sim;

namespace {

constexpr double kPi = std::numbers::pi;

MachineDefinition vmc()
{
    auto m = loadPreset("vmc");
    EXPECT_TRUE(m.ok());
    return *m;
}

/// Least-squares coefficients of {1, cosθ, sinθ, cos2θ, sin2θ} of y(θ) (independent of core/tuning).
Eigen::VectorXd harmonicFit(const std::vector<double>& th, const std::vector<double>& y)
{
    Eigen::MatrixXd a(th.size(), 5);
    Eigen::VectorXd b(th.size());
    for (std::size_t i = 0; i < th.size(); ++i) {
        a.row(static_cast<Eigen::Index>(i)) << 1.0, std::cos(th[i]), std::sin(th[i]), std::cos(2 * th[i]),
            std::sin(2 * th[i]);
        b[static_cast<Eigen::Index>(i)] = y[i];
    }
    return a.colPivHouseholderQr().solve(b);
}

} // namespace

TEST(AxisSimulatorCommand, PositionCommandFunctionIsFollowed)
{
    const auto m = vmc();
    auto sim = AxisSimulator::create(*m.axis("X"), 3);
    ASSERT_TRUE(sim.ok());
    auto& s = **sim;
    s.setNonlinearities({false, false, false, false, false});
    s.setControlMode(ControlMode::Position);
    // A ramp at 10 mm/s with velocity feed-forward: the follow error settles to 0 (type-1 loop + ff = 1).
    s.setPositionCommand([](double t) { return MotionState{0.01 * t, 0.01, 0.0}; });
    s.run(1.0);
    EXPECT_NEAR(s.positionCommand(), 0.01 * (1.0 - s.parameter("position.period")), 1e-9);
    EXPECT_NEAR(s.motorPosition(), 0.01 * s.time(), 2e-6);
    // A profile set afterwards replaces the function.
    MotionProfile hold(0.02);
    s.setPositionProfile(hold);
    s.run(0.5);
    EXPECT_NEAR(s.positionCommand(), 0.02, 1e-12);
}

TEST(CircleTest, SquarenessAndScaleErrorsGiveTheirFirstOrderHarmonics)
{
    const auto m = vmc();
    CircleTestOptions o;
    o.radiusM = 0.05;
    auto base = runCircleTest(m, o);
    ASSERT_TRUE(base.ok()) << base.error().detail;
    o.squarenessPerM = 50e-6;
    o.scaleX = 30e-6;
    o.scaleY = -10e-6;
    auto err = runCircleTest(m, o);
    ASSERT_TRUE(err.ok());
    const auto& a = base->ballbar;
    const auto& b = err->ballbar;
    ASSERT_EQ(a.size(), b.size());
    // Full data arc of 360° (± the servo lag), strictly monotonic.
    EXPECT_NEAR(std::abs(a.angleRad.back() - a.angleRad.front()), 2 * kPi, 0.05);
    std::vector<double> diff(a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        diff[i] = b.deviationM[i] - a.deviationM[i];
    const auto c = harmonicFit(a.angleRad, diff);
    // Δr = R/2·(εx+εy) + R/2·(εx−εy)·cos2θ + γR/2·sin2θ (+ centre terms from the y offset of γ·y: none at cy = 0).
    EXPECT_NEAR(c[3], 0.5 * o.radiusM * (o.scaleX - o.scaleY), 0.02e-6);
    EXPECT_NEAR(c[4], 0.5 * o.radiusM * o.squarenessPerM, 0.02e-6);
    EXPECT_NEAR(c[0], 0.5 * o.radiusM * (o.scaleX + o.scaleY), 0.02e-6);
}

TEST(CircleTest, ReversalTorqueChangeIsTwiceCoulombFriction)
{
    const auto m = vmc();
    CircleTestOptions o;
    auto r = runCircleTest(m, o);
    ASSERT_TRUE(r.ok());
    const double expected = 2.0 * m.axis("X")->values.at("plant.coulomb_motor"); // 0.61 N·m, spec §4.4
    EXPECT_NEAR(r->dTxNm, expected, 0.05 * expected);
    EXPECT_NEAR(r->dTyNm, 2.0 * m.axis("Y")->values.at("plant.coulomb_motor"), 0.05 * expected);
    ASSERT_TRUE(r->ballbar.dTxNm.has_value());
    EXPECT_EQ(r->ballbar.plane, "XY");
    EXPECT_FALSE(r->traceX.channels.empty());
}

TEST(CircleTest, ClockwiseRunsTheOtherWay)
{
    CircleTestOptions o;
    o.direction = model::CircleDirection::Cw;
    auto r = runCircleTest(vmc(), o);
    ASSERT_TRUE(r.ok());
    const auto& t = r->ballbar.angleRad;
    EXPECT_LT(t.back(), t.front());
    EXPECT_NEAR(t.front() - t.back(), 2 * kPi, 0.05);
}

TEST(CircleTest, BadOptionsAreRefused)
{
    CircleTestOptions o;
    o.radiusM = 0.0;
    auto r = runCircleTest(vmc(), o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::BadInput);
    o = {};
    o.axisY = "Q";
    EXPECT_FALSE(runCircleTest(vmc(), o).ok());
}
