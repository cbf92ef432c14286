// SPDX-License-Identifier: GPL-3.0-or-later
// The simulator's current-command mode (ControlMode::Current) and its current-rate trace against the
// discrete closed current loop the test writes itself from spec/current-loop-and-multisweep-frf.md §2.3:
//   e_k = i*_k − i_k,  x_k = x_{k−1} + k_i T e_k,  v_k = x_k + k_p (α i*_k − i_k),
//   u_k = v_{k−d} (d dead-time periods),  i_{k+1} = φ i_k + (1 − φ)/R · u_k,  φ = e^{−R T/L}
// (the RL circuit L di/dt = u − R i integrated exactly over a period with u held). With the back-EMF
// constant 0 the circuit does not see the motion, and with the nonlinearities off the simulator must
// give the same numbers to rounding (1e-9 of the step).
#include "core/sim/AxisSimulator.h"

#include <cmath>
#include <deque>
#include <gtest/gtest.h>

using namespace axistune;
using namespace axistune::sim;

namespace {

struct LoopCase {
    double kp, ki, alpha, deadTimeS, stepA;
};

/// The discrete loop above, for a step of `amp` at sample `k0`, over `n` samples: i_k.
std::vector<double> referenceStep(double r, double l, double h, const LoopCase& c, int dead, std::size_t k0,
                                  std::size_t n)
{
    const double phi = std::exp(-r * h / l), gamma = (1.0 - phi) / r;
    std::vector<double> out;
    std::deque<double> line(static_cast<std::size_t>(dead), 0.0);
    double i = 0.0, x = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        out.push_back(i);
        const double cmd = k >= k0 ? c.stepA : 0.0;
        x += c.ki * h * (cmd - i);
        double u = x + c.kp * (c.alpha * cmd - i);
        if (dead > 0) {
            line.push_back(u);
            u = line.front();
            line.pop_front();
        }
        i = phi * i + gamma * u;
    }
    return out;
}

std::unique_ptr<AxisSimulator> makeSim(const LoopCase& c)
{
    auto def = loadPreset("vmc");
    EXPECT_TRUE(def.ok());
    AxisDefinition axis = *def->axis("X");
    axis.values["plant.motor.back_emf_constant"] = 0.0;
    axis.values["current.kp"] = c.kp;
    axis.values["current.ki"] = c.ki;
    axis.values["current.alpha"] = c.alpha;
    axis.values["current.dead_time"] = c.deadTimeS;
    auto s = AxisSimulator::create(axis, 5);
    EXPECT_TRUE(s.ok()) << (s.ok() ? "" : s.error().detail);
    return std::move(s).value();
}

class CurrentStep : public ::testing::TestWithParam<LoopCase> {};

TEST_P(CurrentStep, MatchesTheDiscreteClosedLoopOfTheSpec)
{
    const LoopCase c = GetParam();
    auto sim = makeSim(c);
    sim->setNonlinearities({false, false, false, false, false});
    const double h = sim->currentPeriod();
    const std::size_t k0 = 8, n = 160; // 10 ms at 16 kHz
    sim->setControlMode(ControlMode::Current);
    const double tStep = static_cast<double>(k0) * h;
    sim->setCurrentCommand([&](double t) { return t >= tStep - 0.5 * h ? c.stepA : 0.0; });
    sim->startTrace(TraceRate::Current);
    sim->runTicks(static_cast<std::int64_t>(n));
    const auto cap = sim->takeTrace();
    EXPECT_EQ(sim->voltageClampCount(), 0u); // the comparison is of the linear loop

    std::vector<std::string> names;
    for (const auto& ch : cap.channels)
        names.push_back(ch.name);
    ASSERT_EQ(names, AxisSimulator::currentTraceChannelNames());
    ASSERT_EQ(cap.size(), n);
    EXPECT_DOUBLE_EQ(cap.metadata.number("fs_Hz").value(), 1.0 / 62.5e-6);
    const auto& t = cap.channel("t_s")->data;
    const auto& cmd = cap.channel("current_cmd_A")->data;
    const auto& i = cap.channel("current_A")->data;
    EXPECT_NEAR(t[1] - t[0], h, 1e-15);
    EXPECT_EQ(cmd[k0 - 1], 0.0);
    EXPECT_EQ(cmd[k0], c.stepA);

    const int dead = static_cast<int>(std::lround(c.deadTimeS / h));
    const auto ref = referenceStep(0.32, 2.19e-3, h, c, dead, k0, n);
    double worst = 0.0;
    for (std::size_t k = 0; k < n; ++k)
        worst = std::max(worst, std::abs(i[k] - ref[k]));
    const double size = std::abs(c.stepA);
    EXPECT_LE(worst, 1e-9 * size) << "largest difference " << worst << " A";
    // The reference settles on the command: the comparison covered the whole response.
    EXPECT_NEAR(ref.back(), c.stepA, 0.01 * size);
    // The voltage channel is the one the loop applied: R i at the end, within the settling left.
    EXPECT_NEAR(cap.channel("voltage_V")->data.back(), 0.32 * c.stepA, 0.02 * 0.32 * size + 0.05);
}

INSTANTIATE_TEST_SUITE_P(Loops, CurrentStep,
                         ::testing::Values(
                             // vmc: the Table 2.2 optimum α = 1 without dead time (the preset's setting), 5 A.
                             LoopCase{35.7, 1.03e5, 1.0, 0.0, 5.0},
                             // I-P-leaning PI with one period of dead time, a negative step.
                             LoopCase{15.0, 4.0e4, 0.5, 62.5e-6, -4.0},
                             // I-P (α = 0) with two periods of dead time.
                             LoopCase{10.0, 2.0e4, 0.0, 125e-6, 3.0}));

TEST(CurrentStepMode, VelocityTraceIsUntouchedAndHoldPositionStopsTheMotor)
{
    auto sim = makeSim({35.7, 1.03e5, 1.0, 0.0, 5.0});
    sim->setNonlinearities({false, false, false, false, false});
    EXPECT_EQ(sim->traceChannelNames().size(), 14u);
    sim->setControlMode(ControlMode::Current);
    sim->setCurrentCommand([](double) { return 5.0; });
    sim->run(0.005);
    // Open velocity loop: the motor side of the undamped two-inertia system under a torque step T,
    //   ω_m(t) = T t/J + T J_L/(J_m J ω_r) sin(ω_r t),  J = J_m + J_L,  ω_r² = K J/(J_m J_L)
    // (vmc: K 337.1 N·m/rad, 125 Hz). Within 10 %: the current needs ≈ 0.1 ms of the 5 ms to rise and
    // the coupling has 5 % damping.
    const double kt = 0.50911, jm = 1.1818e-3, jl = 1.02133e-3, k = 337.1, t = 0.005, torque = kt * 5.0;
    const double j = jm + jl, wr = std::sqrt(k * j / (jm * jl));
    const double expected = torque * t / j + torque * jl / (jm * j * wr) * std::sin(wr * t);
    EXPECT_NEAR(sim->motorVelocity(), expected, 0.1 * expected);
    sim->setCurrentCommand({});
    sim->holdPosition();
    const double held = sim->motorPosition();
    EXPECT_DOUBLE_EQ(sim->positionCommand(), held);
    sim->startTrace(); // the default rate is still the velocity trace
    sim->run(0.3);
    const auto cap = sim->takeTrace();
    EXPECT_EQ(cap.channels.size(), 14u);
    EXPECT_DOUBLE_EQ(cap.metadata.number("fs_Hz").value(), 1.0 / sim->tracePeriod());
    EXPECT_LT(std::abs(sim->motorVelocity()), 0.01);
    // The position loop brought the motor back to where it was held (lead 12 mm per revolution).
    EXPECT_NEAR(sim->motorPosition(), held, 1e-6);
}

} // namespace
