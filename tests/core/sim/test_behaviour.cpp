// SPDX-License-Identifier: GPL-3.0-or-later
// Behaviour of the simulated axes that issue 2 asks for: the two-inertia frequencies, lost motion at
// reversal and its compensation, the voltage-clamp counter against the voltage envelope, determinism.
#include "core/sim/AxisSimulator.h"
#include "tests/core/sim/SimTestUtil.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <numbers>
#include <cstring>
#include <numeric>

using namespace axistune;
using namespace axistune::sim;

namespace {

constexpr double kPi = std::numbers::pi;

std::unique_ptr<AxisSimulator> makeSim(const std::string& preset, const std::string& axis, std::uint64_t seed = 1)
{
    auto def = loadPreset(preset);
    EXPECT_TRUE(def.ok());
    auto s = AxisSimulator::create(*def->axis(axis), seed);
    EXPECT_TRUE(s.ok());
    return std::move(s).value();
}

double meanOver(const std::vector<double>& v, std::size_t a, std::size_t b, std::size_t stride = 1)
{
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = a - a % stride; i < b; i += stride, ++n)
        sum += v[i];
    return sum / static_cast<double>(n);
}

// Torque → motor velocity measured by torque injection with the velocity loop open (in closed loop the
// feedback cancels most of the torque at the resonance and what remains is dominated by the
// intra-sample shape of the current); the anti-resonance and the
// resonance are the natural frequencies of the numerator and denominator of s·P(s), found by a
// Levy (linearised least-squares) fit of a 2nd/2nd-order rational function to the measured points.
TEST(TwoInertiaPreset, AntiResonanceAndResonanceFrequencies)
{
    auto s = makeSim("two-inertia", "A");
    s->setNonlinearities({false, false, false, false, false});
    ASSERT_TRUE(s->setParameters({{"velocity.kp", 0.0}, {"velocity.ki", 0.0}}).ok());
    const double amp = 0.5;  // N·m
    std::vector<double> freqs;
    for (double f = 12.0; f <= 70.0; f += 2.0)
        freqs.push_back(f);
    Eigen::MatrixXd a(2 * freqs.size(), 5);
    Eigen::VectorXd rhs(2 * freqs.size());
    for (std::size_t k = 0; k < freqs.size(); ++k) {
        const double f = freqs[k];
        s->reset();
        s->setControlMode(ControlMode::Velocity);
        s->setTorqueInjection([amp, f](double t) { return amp * std::sin(2 * kPi * f * t); });
        s->run(1.0);
        s->startTrace();
        s->run(1.0);
        const auto cap = s->takeTrace();
        const auto& t = cap.channel("t_s")->data;
        const auto tq = simtest::fourierAt(cap.channel("torque_Nm")->data, t, 0, t.size(), f);
        const auto vel = simtest::fourierAt(cap.channel("motor_vel_rad_s")->data, t, 0, t.size(), f);
        const std::complex<double> jw(0.0, 2 * kPi * f);
        // The drive measures velocity as a backward difference of encoder samples over T: undo it.
        const double tv = t[1] - t[0];
        const std::complex<double> diff = (1.0 - std::exp(-jw * tv)) / (jw * tv);
        const std::complex<double> g = jw * vel / diff / tq;  // s · (ω/T)
        // b2 s² + b1 s + b0 − g (a2 s² + a1 s) = g   (a0 = 1)
        const std::complex<double> row[5] = {jw * jw, jw, 1.0, -g * jw * jw, -g * jw};
        for (int c = 0; c < 5; ++c) {
            a(2 * k, c) = row[c].real();
            a(2 * k + 1, c) = row[c].imag();
        }
        rhs(2 * k) = g.real();
        rhs(2 * k + 1) = g.imag();
    }
    const Eigen::VectorXd p = a.colPivHouseholderQr().solve(rhs);
    const double f0 = std::sqrt(p(2) / p(0)) / (2 * kPi);
    const double fp = std::sqrt(1.0 / p(3)) / (2 * kPi);
    EXPECT_NEAR(f0, 21.97, 0.3);  // spec/lost-motion-and-two-inertia.md §2.7: ω0 = √(K/J_L)
    EXPECT_NEAR(fp, 38.00, 0.3);  // ωp = √(1 + J_L/J_m) ω0
}

struct ReversalResult {
    double dxMeasured;  // change of the table error across the reversal [m]
    double dxModel;     // (A + B·x)·T of the plant, averaged over the same windows [m]
    double dTorque;     // torque change [N·m]
};

// Moves +20 mm at 1000 mm/min, reverses, moves back; compares the plateaus of table error and torque
// just before the deceleration and after the re-acceleration has settled.
ReversalResult runReversal(AxisSimulator& s, double start, double a, double b, double x0)
{
    const double feed = 1000e-3 / 60.0, acc = 0.5, dist = 0.02;
    s.reset(start);
    s.setControlMode(ControlMode::Position);
    MotionProfile p(start);
    p.dwell(0.2);
    p.move(dist, feed, acc);
    p.move(-dist, feed, acc);
    p.dwell(0.2);
    s.setPositionProfile(p);
    s.startTrace();
    s.run(p.duration());
    const auto cap = s.takeTrace();
    const auto& t = cap.channel("t_s")->data;
    const auto& cmd = cap.channel("position_cmd_m")->data;
    const auto& table = cap.channel("table_pos_m")->data;
    const auto& tq = cap.channel("torque_Nm")->data;
    const double fs = 1.0 / (t[1] - t[0]);
    const double tAcc = feed / acc;
    const double tMove = dist / feed + tAcc;  // one trapezoid
    const double tRev = 0.2 + tMove;
    // Windows: 0.3 s of constant velocity before the deceleration and after the settling.
    const auto idx = [&](double time) { return static_cast<std::size_t>(time * fs); };
    const std::size_t b0 = idx(tRev - tAcc - 0.35), b1 = idx(tRev - tAcc - 0.05);
    const std::size_t a0 = idx(tRev + tAcc + 0.25), a1 = idx(tRev + tAcc + 0.55);
    std::vector<double> err(table.size());
    for (std::size_t i = 0; i < err.size(); ++i)
        err[i] = table[i] - cmd[i];
    // The command is renewed once per position period: compare only at those instants (a trace
    // sample in between holds the last command while the table moves on).
    const auto stride = static_cast<std::size_t>(std::lround(s.parameter("position.period") * fs));
    ReversalResult r;
    r.dxMeasured = meanOver(err, a0, a1, stride) - meanOver(err, b0, b1, stride);
    r.dTorque = meanOver(tq, b0, b1, stride) - meanOver(tq, a0, a1, stride);
    std::vector<double> model(table.size());
    for (std::size_t i = 0; i < model.size(); ++i)
        model[i] = -(a + b * (x0 + cmd[i])) * tq[i];
    r.dxModel = meanOver(model, a0, a1, stride) - meanOver(model, b0, b1, stride);
    return r;
}

TEST(VmcLostMotion, ReversalProducesModelLostMotionAndCompensationRemovesIt)
{
    auto s = makeSim("vmc", "Y");  // the axis with a position-dependent B
    s->setNonlinearities({true, false, false, false, true});  // friction and lost motion only
    const double a = s->parameter("plant.lost_motion_A"), b = s->parameter("plant.lost_motion_B");
    const double x0 = s->parameter("plant.screw_offset");
    for (double start : {-0.1, 0.15}) {
        const auto r = runReversal(*s, start, a, b, x0);
        ASSERT_GT(r.dTorque, 0.5);  // 2 × Coulomb friction
        // Δx = (A + B·x)·ΔT with x = x0 + table position: the table lags behind in both directions.
        const double atReversal = (a + b * (x0 + start + 0.02)) * r.dTorque;
        EXPECT_NEAR(r.dxMeasured / r.dxModel, 1.0, 0.05) << "start " << start << " dx " << r.dxMeasured;
        EXPECT_NEAR(r.dxMeasured / atReversal, 1.0, 0.10) << "start " << start;

        ASSERT_TRUE(s->setParameters({{"lostmotion.mode", 2}, {"lostmotion.A", a}, {"lostmotion.B", b},
                                      {"lostmotion.screw_offset", x0}})
                        .ok());
        const auto c = runReversal(*s, start, a, b, x0);
        EXPECT_LT(std::abs(c.dxMeasured), 0.2 * std::abs(r.dxMeasured)) << "start " << start;
        ASSERT_TRUE(s->setParameters({{"lostmotion.mode", 0}}).ok());
    }
}

// Voltage envelope (spec/current-loop-and-multisweep-frf.md §2.5, delay-free): the current-command →
// voltage-command response H(s) = (α k_p s + k_i)(L s + R) / (L s² + (R + k_p) s + k_i); a sinusoidal
// current command of amplitude I_max/20 needs |H(jω)|·I_max/20 ≤ V_max at every frequency.
double envelopePeakVolts(double kp, double ki, double alpha, double l, double r, double iq)
{
    double peak = 0.0;
    for (double f = 1.0; f < 8000.0; f *= 1.01) {
        const std::complex<double> s(0.0, 2 * kPi * f);
        const auto h = (alpha * kp * s + ki) * (l * s + r) / (l * s * s + (r + kp) * s + ki);
        peak = std::max(peak, std::abs(h) * iq);
    }
    return peak;
}

TEST(VoltageClamp, CounterRisesOnlyOutsideTheVoltageEnvelope)
{
    auto def = loadPreset("vmc");
    ASSERT_TRUE(def.ok());
    AxisDefinition axis = *def->axis("X");
    axis.values["drive.max_voltage"] = 100.0;  // a smaller DC link makes the envelope bind
    axis.values["plant.motor.inductance_drop_at_max"] = 0.0;
    const double l = axis.values["plant.motor.inductance_q"], r = axis.values["plant.motor.resistance"];
    const double iq = axis.values["motor.max_current"] / 20.0, vmax = 100.0;
    struct Gains {
        double kp, ki, alpha;
        bool inside;
    };
    for (const Gains g : {Gains{15.0, 4.0e4, 1.0, true}, Gains{35.7, 1.03e5, 1.0, false}}) {
        const double peak = envelopePeakVolts(g.kp, g.ki, g.alpha, l, r, iq);
        if (g.inside)
            ASSERT_LT(peak, 0.8 * vmax);
        else
            ASSERT_GT(peak, 1.2 * vmax);
        auto created = AxisSimulator::create(axis, 3);
        ASSERT_TRUE(created.ok());
        auto& s = **created;
        s.setNonlinearities({false, false, false, false, false});
        ASSERT_TRUE(s.setParameters({{"current.kp", g.kp}, {"current.ki", g.ki}, {"current.alpha", g.alpha},
                                     {"velocity.kp", 0.0}, {"velocity.ki", 0.0}})
                        .ok());
        std::uint64_t clamps = 0;
        const double amp = iq * s.parameter("motor.torque_constant");
        for (double f : {50.0, 200.0, 500.0, 1000.0, 2000.0, 3000.0, 4000.0}) {
            s.reset();
            s.setTorqueInjection([amp, f](double t) { return amp * std::sin(2 * kPi * f * t); });
            s.run(0.05);
            clamps += s.voltageClampCount();
        }
        if (g.inside)
            EXPECT_EQ(clamps, 0u) << "kp " << g.kp;
        else
            EXPECT_GT(clamps, 0u) << "kp " << g.kp;
    }
}

TEST(Determinism, SameSeedSameTraceBitForBit)
{
    auto run = [](std::uint64_t seed) {
        auto s = makeSim("vmc", "Y", seed);
        s->setControlMode(ControlMode::Position);
        MotionProfile p(0.0);
        p.move(0.005, 0.02, 1.0);
        p.move(-0.005, 0.02, 1.0);
        s->setPositionProfile(p);
        s->startTrace();
        s->run(p.duration() + 0.05);
        return s->takeTrace();
    };
    const auto a = run(42), b = run(42), c = run(43);
    ASSERT_EQ(a.channels.size(), b.channels.size());
    bool differs = false;
    for (std::size_t i = 0; i < a.channels.size(); ++i) {
        ASSERT_EQ(a.channels[i].data.size(), b.channels[i].data.size());
        EXPECT_EQ(0, std::memcmp(a.channels[i].data.data(), b.channels[i].data.data(),
                                 a.channels[i].data.size() * sizeof(double)))
            << a.channels[i].name;
        differs = differs || a.channels[i].data != c.channels[i].data;
    }
    EXPECT_TRUE(differs) << "another seed must give other noise";
}

TEST(Parameters, WriteOutsideLimitsIsRefusedAndNamesKeyAndLimits)
{
    auto s = makeSim("vmc", "X");
    const double before = s->parameter("current.alpha");
    auto st = s->setParameters({{"current.alpha", 1.5}});
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(st.error().detail.find("current.alpha"), std::string::npos);
    EXPECT_NE(st.error().detail.find("[0, 1]"), std::string::npos) << st.error().detail;
    EXPECT_EQ(s->parameter("current.alpha"), before);
    // A period that is not a whole multiple of the current period is refused too.
    EXPECT_FALSE(s->setParameters({{"velocity.period", 300e-6}}).ok());
}

}  // namespace
