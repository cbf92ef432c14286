// SPDX-License-Identifier: GPL-3.0-or-later
// The two-inertia suppression filter in the loop of the simulated `two-inertia` bench
// (spec/lost-motion-and-two-inertia.md §2.10, §4.10, §4.13): F_m set from the model FITTED to the
// measured sample response resources/samples/frf-two-inertia.csv (multi-sweep on the bench), a
// rectangular-jerk move of the thesis (10 rev/s, 200 rev/s², jerk 20 000 rev/s³), the load error
// y_L − y* measured with and without the filter, compared with tuning::predictLoadError (ideal motor
// tracking, load through (5.6)) as the independent prediction.
#include "core/io/FrfCsv.h"
#include "core/sim/AxisSimulator.h"
#include "core/tuning/TwoInertiaFilter.h"
#include "core/tuning/TwoInertiaPrediction.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace axistune;

namespace {

tuning::TwoInertiaParams fittedBench()
{
    auto frf = io::readFrfCsvFile(std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/frf-two-inertia.csv");
    EXPECT_TRUE(frf.ok());
    // The bench's velocity loop (resources/machines/two-inertia.json): K_P 11.24, K_I 1198, 250 µs / 62.5 µs.
    auto plant = tuning::plantFromVelocityLoop(*frf, {11.24, 1198.0}, 250e-6, 62.5e-6);
    EXPECT_TRUE(plant.ok());
    auto fit = tuning::fitTwoInertia(*plant, {});
    EXPECT_TRUE(fit.ok());
    return fit->params;
}

/// One S-curve move of `prof` on the bench: dwell 0.1 s, the move (cruise prof.cruiseS), dwell
/// prof.settleS; the maximum load error at the fresh command samples.
double benchLoadError(const model::ParameterValues& settings, const tuning::MotionProfile& prof)
{
    auto def = sim::loadPreset("two-inertia");
    EXPECT_TRUE(def.ok());
    auto s = sim::AxisSimulator::create(*def->axis("A"), 7);
    EXPECT_TRUE(s.ok());
    auto& sim = **s;
    EXPECT_TRUE(sim.setParameters(settings).ok());
    sim.setControlMode(sim::ControlMode::Position);
    sim::MotionProfile p(0.0);
    p.dwell(0.1);
    p.move(prof.vMax * (tuning::sCurveRampS(prof) + prof.cruiseS), prof.vMax, prof.aMax, prof.jerk);
    p.dwell(prof.settleS);
    sim.setPositionProfile(p);
    sim.startTrace();
    sim.run(p.duration());
    const auto cap = sim.takeTrace();
    const auto e = tuning::measuredLoadError(cap.channel("t_s")->data, cap.channel("position_cmd_rad")->data,
                                             cap.channel("table_pos_rad")->data);
    EXPECT_GT(e.tS.size(), cap.channel("t_s")->data.size() / 5);
    return e.maxAbs;
}

// The loop structure TI-3 asks for (§4.10): velocity feedforward and the torque feedforward, here
// J·a* with J = J_m + J_L of the fit (the spec's approximation of P_m⁻¹).
model::ParameterValues thesisLoop(const tuning::TwoInertiaParams& p, double kp, bool fullClosed)
{
    return {{"position.kp", kp},
            {"position.velocity_ff", 1.0},
            {"position.torque_ff", 1.0},
            {"velocity.inertia", p.jmKgm2 + p.jlKgm2},
            {"position.feedback", fullClosed ? 1.0 : 0.0}};
}

}  // namespace

TEST(TwoInertiaSuppression, FmFromTheFittedModelSuppressesTheLoadError)
{
    const auto p = fittedBench();
    const auto f = tuning::suppressionFilterFromModel(p, tuning::SuppressionMode::Semi, 0.0);
    // The fit recovers the bench (Table 5.1: 21.97 Hz, ζ₀ 0.0932) closely enough to be the filter's
    // start value.
    EXPECT_NEAR(f.f0Hz, 21.97, 0.3);
    EXPECT_NEAR(f.zeta, 0.0932, 0.01);
    const tuning::MotionProfile prof;  // 10 rev/s, 200 rev/s², 20 000 rev/s³, cruise 0.2 s, settle 0.5 s
    const auto pred = tuning::predictLoadError(p, f, prof);

    const auto base = thesisLoop(p, 30.0, false);  // the preset's K_p
    auto filtered = base;
    filtered.insert({{"suppression.mode", 1}, {"suppression.f0", f.f0Hz}, {"suppression.zeta", f.zeta}});
    const double off = benchLoadError(base, prof);
    const double on = benchLoadError(filtered, prof);
    std::printf("semi-closed load error max: without %.5f rad (predicted %.5f), with F_m %.5f rad (predicted %.6f)\n",
                off, pred.maxErrorWithoutFilter, on, pred.maxErrorWithFilter);
    // Without the filter the load error is the ideal-tracking prediction's within 15 %: the motor does
    // not track its command ideally (the velocity loop yields to the spring torque; 1 ms command
    // updates), which the prediction leaves out.
    EXPECT_NEAR(off, pred.maxErrorWithoutFilter, 0.15 * pred.maxErrorWithoutFilter);
    // With F_m the ideal-tracking prediction is almost zero; what remains is the motor's own tracking
    // error. The thesis's criterion for a working filter is ≤ 0.2× the conventional error (§2.13,
    // Fig. 5.15); its bench reached 0.086× (10.5° → 0.90°). Require 0.12×, between the two.
    EXPECT_LT(pred.maxErrorWithFilter, 0.01 * pred.maxErrorWithoutFilter);
    EXPECT_LT(on, 0.12 * off);
    EXPECT_LT(on, 0.12 * pred.maxErrorWithoutFilter);
}

// Full-closed with F_L from the fitted model (τ by the default rule, high-frequency gain 2.5) at the
// thesis's K_p = 15 s⁻¹ (§2.11): the thesis measured 10.8° → 1.76° (0.163×). Require ≤ 0.3×: F_L is in
// the loop, so the load error is not the ideal-tracking prediction's and the model-derived setting is
// not the hand-tuned optimum; Fig. 5.15 puts the full-closed window at ±5–12 % of the optimum.
TEST(TwoInertiaSuppression, FlFromTheFittedModelSuppressesTheLoadError)
{
    const auto p = fittedBench();
    const auto f = tuning::suppressionFilterFromModel(p, tuning::SuppressionMode::Full, 0.0);
    const tuning::MotionProfile prof;
    const auto base = thesisLoop(p, 15.0, true);
    auto filtered = base;
    filtered.insert({{"suppression.mode", 2}, {"suppression.f0", f.f0Hz}, {"suppression.zeta", f.zeta},
                     {"suppression.tau", f.tauS}});
    const double off = benchLoadError(base, prof);
    const double on = benchLoadError(filtered, prof);
    std::printf("full-closed load error max: without %.5f rad, with F_L (tau %.2f ms) %.5f rad\n", off,
                f.tauS * 1e3, on);
    EXPECT_LT(on, 0.3 * off);
}
