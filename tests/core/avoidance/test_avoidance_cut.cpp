// SPDX-License-Identifier: GPL-3.0-or-later
// Chatter avoidance in the loop on the simulated cut (core/avoidance/AvoidanceCut; issue 22 tests). The
// stability of the speeds reached is judged by the semi-discretization lobes (core/machining/StabilityLobes,
// k = 80), an independent method: the avoidance code never computes lobes. The cut runs on the vmc X axis;
// f_z = 0.1 mm; vibration = the tool's y acceleration (the thesis's evaluation channel).
#include "core/avoidance/AvoidanceCut.h"
#include "core/machining/StabilityLobes.h"
#include "core/sim/MachineDefinition.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune;

namespace {
constexpr double kPi = std::numbers::pi;

sim::MillingSetup setup(bool twoMode, double rpm, double depthM, double aeMm)
{
    sim::MillingSetup s;
    if (twoMode) // the cascade (5-1) as its modal sum, mode 2 a negative residue (tests/data/chatter/cascade_tool.py)
        s.modesX = s.modesY = {{0.5346547242, 96.45171224, 43499722.22}, {-0.5346547242, -76.99028028, -76990280.28}};
    else // Table 1(a)
        s.modesX = s.modesY = {{0.40, 83.0, 30.1e6}};
    s.teeth = 4;
    s.ktNPerM2 = 0.980e9;
    s.krNPerM2 = 0.294e9;
    s.radialImmersion = aeMm / 12.0;
    s.spindleRpm = rpm;
    s.axialDepthM = depthM;
    s.feedPerToothM = 0.1e-3;
    return s;
}

double limitDepthAt(const sim::MillingSetup& s, double rpm)
{
    machining::ToolModes tool;
    for (const auto& m : s.modesX)
        tool.modesX.push_back({m.massKg, m.dampingNsPerM, m.stiffnessNPerM});
    for (const auto& m : s.modesY)
        tool.modesY.push_back({m.massKg, m.dampingNsPerM, m.stiffnessNPerM});
    machining::CuttingConditions cut{s.teeth, s.ktNPerM2, s.krNPerM2, s.radialImmersion,
                                     machining::MillingDirection::Down};
    machining::LobeOptions lo;
    lo.stepsPerPeriod = 80;
    auto d = machining::limitDepth(tool, cut, rpm, lo);
    EXPECT_TRUE(d) << d.error().detail;
    return d ? *d : 0.0;
}

avoidance::AvoidanceCutResult run(const avoidance::AvoidanceCutOptions& o)
{
    auto def = sim::loadPreset("vmc");
    EXPECT_TRUE(def);
    auto r = avoidance::runAvoidanceCut(*def->axis("X"), o);
    EXPECT_TRUE(r) << r.error().detail;
    return r ? std::move(r).value() : avoidance::AvoidanceCutResult{};
}

double lastValue(const model::Capture& c, const std::string& name)
{
    const auto* ch = c.channel(name);
    return ch && !ch->data.empty() ? ch->data.back() : std::nan("");
}

double rmsLast(const model::Capture& c, double duration, double window)
{
    auto r = avoidance::channelRms(c, "tool_accel_y_m_s2", duration - window, duration);
    EXPECT_TRUE(r);
    return r ? *r : std::nan("");
}
} // namespace

TEST(AvoidanceCut, SpindleFollowsACommandChangeAndTheDelayFollowsTheSpeed)
{
    // First-order spindle loop (T = 2 ms): a command 2800 → 3000 rpm at the first controller sample reaches
    // 63.2 % of the step one time constant later; at the new speed the delay is one tooth period 60/(n N).
    avoidance::AvoidanceCutOptions o;
    o.cut.milling = setup(false, 2800.0, 0.5e-3, 7.0);
    o.cut.durationS = 0.2;
    o.cut.engageS = 0.05;
    auto def = sim::loadPreset("vmc");
    ASSERT_TRUE(def);
    o.cut.controllerPeriodS = 1e-4;
    o.cut.controller = [](const sim::CutProbe& p, std::span<double>) { return p.timeS >= 0.1 ? 3000.0 : 2800.0; };
    auto r = sim::simulateCut(*def->axis("X"), o.cut);
    ASSERT_TRUE(r) << r.error().detail;
    const auto* t = r->channel("t_s");
    const auto* n = r->channel("spindle_speed_rpm");
    const auto* cmd = r->channel("spindle_speed_cmd_rpm");
    ASSERT_TRUE(t && n && cmd);
    for (std::size_t i = 0; i < t->data.size(); ++i) {
        // The command changes at the sample at 0.1 s; the process channels hold the state at the end of the
        // current-loop period (62.5 µs) that starts at the trace instant.
        const double dt = t->data[i] + 62.5e-6 - 0.1;
        if (std::abs(dt - 0.002) < 2e-4) {
            EXPECT_NEAR(n->data[i], 2800.0 + 200.0 * (1.0 - std::exp(-dt / 0.002)), 0.5) << t->data[i];
        }
        if (dt > 0.02) {
            EXPECT_NEAR(n->data[i], 3000.0, 0.01);
            EXPECT_DOUBLE_EQ(cmd->data[i], 3000.0);
        }
        if (dt < 0.0) {
            EXPECT_DOUBLE_EQ(n->data[i], 2800.0);
        }
    }
}

namespace {
/// Issue 22's adaptive cut: Table 1 tool, a_e 7 mm down, 4 flutes, a_p 1.5 mm from 2800 rpm, 1 s, tool in at 0.1 s.
avoidance::AvoidanceCutOptions table1Cut()
{
    avoidance::AvoidanceCutOptions base;
    base.cut.milling = setup(false, 2800.0, 1.5e-3, 7.0);
    base.cut.durationS = 1.0;
    base.cut.engageS = 0.1;
    return base;
}

/// The requirements on that cut: final speed in the 2955–3000 rpm pocket, which the lobes call stable at
/// 1.5 mm; the first estimate is the chatter line 1394.8 Hz (spec §5.1 [derived]) ± 15 Hz with ρ = 7; the RMS of
/// the last 0.3 s falls by at least 60 % against constant speed.
void expectTable1Pocket(const avoidance::AvoidanceCutResult& r, const avoidance::AvoidanceCutResult& constant)
{
    const auto base = table1Cut();
    ASSERT_FALSE(r.steps.empty());
    const double finalRpm = lastValue(r.capture, "spindle_speed_rpm");
    EXPECT_GE(finalRpm, 2955.0);
    EXPECT_LE(finalRpm, 3000.0);
    EXPECT_GT(limitDepthAt(base.cut.milling, finalRpm), 1.5e-3); // the lobes call it stable
    EXPECT_NEAR(r.steps.front().chatterHz.front(), 1394.8, 15.0);
    EXPECT_EQ(r.steps.front().rho, 7);
    const double rc = rmsLast(constant.capture, 1.0, 0.3), ra = rmsLast(r.capture, 1.0, 0.3);
    EXPECT_LE(ra, 0.4 * rc) << "constant " << rc << " avoided " << ra;
}
} // namespace

TEST(AvoidanceCut, AdaptiveTable1EndsInThe2955To3000Pocket)
{
    // Issue 22 / spec §5.1: Table 1 tool, a_e 7 mm down, 4 flutes, a_p 1.5 mm from 2800 rpm (SDM limit
    // 0.94 mm there). Accelerometer + Kalman (Table 3), stable-pocket rule (1-21)/(1-22).
    const auto base = table1Cut();
    EXPECT_LT(limitDepthAt(base.cut.milling, 2800.0), 1.5e-3);
    const auto constant = run(base);
    auto o = base;
    o.method = avoidance::Method::Adaptive;
    o.sensor = machining::AvoidanceSensor::Accelerometer;
    o.adaptive = machining::adaptiveTable3Accelerometer();
    const auto adaptive = run(o);
    expectTable1Pocket(adaptive, constant);
    // The capture carries the speed channels and the estimate.
    for (const char* ch : {"spindle_speed_rpm", "spindle_speed_cmd_rpm", "chatter_frequency_Hz", "avoid_power",
                           "avoid_cost", "tool_accel_y_m_s2"})
        EXPECT_NE(adaptive.capture.channel(ch), nullptr) << ch;
}

TEST(AvoidanceCut, AdaptiveWithTheStageDobEndsInThe2955To3000Pocket)
{
    // Issue 22, Method 2 (spec §3.2): the same cut as above, sensor = the feed-stage DOB on the linear encoder
    // and the thrust command (stage model M_tn 273 kg, D_tn 1e4 N s/m only), Table 4 Kalman parameters, G_F
    // 1000–2000 Hz, Q 2000 Hz. The observer force carries the regenerative comb f_c + k f_TPE (the tool's
    // resonance does not filter it as it does the acceleration), so the estimator gets the band f_n ± f_TPE/2
    // around the tool mode (docs/chatter-avoidance.md, "DOB path"): f_n = 1380.6 Hz (spec §1.6 [derived]),
    // f_TPE = 4 · 2800/60 = 186.67 Hz.
    const auto base = table1Cut();
    const auto constant = run(base);
    auto o = base;
    avoidance::applyMethodDefaults(o, avoidance::Method::Adaptive, machining::AvoidanceSensor::Dob);
    EXPECT_TRUE(o.toolModeBand);
    EXPECT_DOUBLE_EQ(o.adaptive.kalman.rv, 1e-6); // Table 4(a)
    EXPECT_DOUBLE_EQ(o.adaptive.kalman.p0, 1e3);
    EXPECT_DOUBLE_EQ(o.adaptive.samplePeriodS, 250e-6);
    const auto band = avoidance::toolModeBand(o.cut.milling);
    ASSERT_TRUE(band);
    EXPECT_NEAR(band->centreHz, 1380.6, 0.1);
    EXPECT_NEAR(band->widthHz, 4.0 * 2800.0 / 60.0, 1e-9);
    // Table 4's σ_th = 1e4 N² (|F̂_u| = 100 N, set for the thesis's a_p 3.5 mm cut) is never reached here: the
    // in-band self-excited force of this 1.5 mm cut peaks near 14 N.
    const auto table4 = run(o);
    EXPECT_LT(table4.triggerTimeS, 0.0);
    // σ_th = 100 N² (10 N): above the in-band level before the tool enters and after avoidance (≤ 7 N), below
    // the chatter's (docs/chatter-avoidance.md).
    o.adaptive.thresholdPower = 100.0;
    const auto dob = run(o);
    ASSERT_FALSE(dob.steps.empty());
    EXPECT_GE(dob.triggerTimeS, base.cut.engageS); // not on the observer's start transient
    expectTable1Pocket(dob, constant); // the simulated stage has no model error: no 40 Hz bias as in the thesis
}

TEST(AvoidanceCut, TwoModeCascadeToolHasTheSpecsLobes)
{
    // The cascade (5-1) held as a modal sum with a negative-residue second mode (cascade_tool.py: within 0.66 % of
    // the peak compliance): the SDM (k = 80) reproduces the spec's own reproduction (§5.3 [derived], Δt ≤ 40 µs):
    // critical depth 1.07 mm at 2800 rpm, minimum 0.94 mm, 2.0 mm stable at 2375–2400, 2625–2650, 3525–3675
    // (peak 6.14 mm at 3575 rpm) and 4125–4250 rpm (peak 3.33 mm at 4200 rpm). Tolerance 3 % (k = 80 against
    // the spec's finer step).
    const auto s = setup(true, 2800.0, 2.0e-3, 7.0);
    EXPECT_NEAR(limitDepthAt(s, 2800.0), 1.07e-3, 0.03 * 1.07e-3);
    EXPECT_NEAR(limitDepthAt(s, 3575.0), 6.14e-3, 0.03 * 6.14e-3);
    EXPECT_NEAR(limitDepthAt(s, 4200.0), 3.33e-3, 0.03 * 3.33e-3);
    for (double rpm : {2375.0, 2400.0, 2625.0, 2650.0, 3525.0, 3675.0, 4125.0, 4250.0})
        EXPECT_GT(limitDepthAt(s, rpm), 2.0e-3) << rpm;
    for (double rpm : {2300.0, 2500.0, 2700.0, 3000.0, 3400.0, 3800.0, 4050.0, 4350.0})
        EXPECT_LT(limitDepthAt(s, rpm), 2.0e-3) << rpm;
}

TEST(AvoidanceCut, MultiModeReachesAStableSpeedWhereTheConventionalRuleDoesNot)
{
    // Issue 22 / spec §5.3: the two-mode tool (5-1) (1435.6 Hz, 1909.9 Hz), a_e 7 mm, a_p 2.0 mm from 2800 rpm.
    const double duration = 1.2, depth = 2.0e-3;
    avoidance::AvoidanceCutOptions base;
    base.cut.milling = setup(true, 2800.0, depth, 7.0);
    base.cut.durationS = duration;
    base.cut.engageS = 0.1;
    EXPECT_LT(limitDepthAt(base.cut.milling, 2800.0), depth);
    auto conv = base;
    conv.method = avoidance::Method::Adaptive;
    conv.sensor = machining::AvoidanceSensor::Accelerometer;
    conv.adaptive = machining::adaptiveTable3Accelerometer();
    const auto conventional = run(conv);
    auto mm = base;
    mm.method = avoidance::Method::MultiMode;
    mm.sensor = machining::AvoidanceSensor::Accelerometer;
    mm.adaptive = machining::multiModeTable5Accelerometer();
    const auto multi = run(mm);
    const double convRpm = lastValue(conventional.capture, "spindle_speed_rpm");
    const double multiRpm = lastValue(multi.capture, "spindle_speed_rpm");
    EXPECT_LT(limitDepthAt(base.cut.milling, convRpm), depth) << "conventional ends at " << convRpm;
    EXPECT_GT(limitDepthAt(base.cut.milling, multiRpm), depth) << "multimode ends at " << multiRpm;
    ASSERT_FALSE(multi.steps.empty());
    EXPECT_LE(multi.steps.back().cost, 0.01); // the cost is met at the last step
    // The thesis's claim (spec §5.3): it ends with r₁, r₂ ≈ 6, 8 — both modes (1435.6 and 1909.9 Hz, §1.6(b)) on
    // a zero of the notch 1 − e^{−τs} — the pocket 3525–3675 rpm of the spec's own SDM reproduction.
    EXPECT_GE(multiRpm, 3525.0);
    EXPECT_LE(multiRpm, 3675.0);
    const double fTpe = 4.0 * multiRpm / 60.0;
    EXPECT_NEAR(1435.6 / fTpe, 6.0, 0.1);
    EXPECT_NEAR(1909.9 / fTpe, 8.0, 0.1);
    EXPECT_LE(rmsLast(multi.capture, duration, 0.3), 0.4 * rmsLast(conventional.capture, duration, 0.3));
    EXPECT_NE(multi.capture.channel("chatter_frequency2_Hz"), nullptr);
}

namespace {
/// |Σ x e^{−jωt}| over the samples, a single DFT line.
double lineAt(const std::vector<double>& t, const std::vector<double>& x, double t0, double fHz)
{
    std::complex<double> s = 0.0;
    double mean = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] >= t0)
            mean += x[i], ++n;
    mean /= static_cast<double>(n);
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] >= t0)
            s += (x[i] - mean) * std::exp(std::complex<double>(0.0, -2 * kPi * fHz * t[i]));
    return std::abs(s);
}
} // namespace

TEST(AvoidanceCut, EscDithersAt13p86HzStaysInsideTheBoundsAndLowersTheVibration)
{
    // Issue 22 / spec §5.4, the seed's simulation (Sec. 6.4): Table 1 tool (the seed: "Table 1, Table 6"), from
    // 1700 rpm, a_p 2.5 mm, a_e 9 mm, p_c = 8·2π rad/s, ESC from 5 s, f'' = 1e5, a_c = 4 rad/s (Fig. 42: 1 and
    // 4), feed = Table 1(b)'s 0.5 mm/s, i.e. f_z = 0.5 mm/s / (4 · 1700/60 s⁻¹) = 4.41 µm; bounds 1200–2200 rpm,
    // accelerometer cost a_y². The Table 1 tool has no speed stable at 2.5 mm below 2925 rpm (SDM), so the ESC
    // can only reach a local minimum of the chatter level. The seed's 60–80 % is its experiments' result (Fig.
    // 50, the Ch.6 tool whose FRF is not given, Sec. 6.5.4); its simulation gives no number. Measured: 46 %;
    // asserted ≥ 35 % (docs/chatter-avoidance.md).
    const double duration = 7.0, fzSeed = 0.5e-3 / (4.0 * 1700.0 / 60.0);
    avoidance::AvoidanceCutOptions base;
    base.cut.milling = setup(false, 1700.0, 2.5e-3, 9.0);
    base.cut.milling.feedPerToothM = fzSeed;
    base.cut.durationS = duration;
    base.cut.engageS = 0.1;
    EXPECT_LT(limitDepthAt(base.cut.milling, 1725.0), 2.5e-3);
    const auto constant = run(base);
    // The cut is homogeneous in the feed (chip, force and limit cycle scale with f_z): the constant-speed RMS
    // at f_z = 0.1 mm is (0.1 mm/f_z) times this one, so a cost a_y² is (0.1 mm/f_z)² = 514 times the seed's
    // scale there and f'' must scale with it (why 1e5 is too small at f_z = 0.1 mm).
    auto coarse = base;
    coarse.cut.milling.feedPerToothM = 0.1e-3;
    const auto constantCoarse = run(coarse);
    const double rc = rmsLast(constant.capture, duration, 0.3);
    EXPECT_NEAR(rmsLast(constantCoarse.capture, duration, 0.3) / rc, 0.1e-3 / fzSeed, 0.02 * 0.1e-3 / fzSeed);
    auto o = base;
    o.method = avoidance::Method::Esc;
    o.sensor = machining::AvoidanceSensor::Accelerometer;
    o.esc.pcRadS = 8.0 * 2.0 * kPi;
    o.esc.startS = 5.0;
    o.esc.minRpm = 1200.0;
    o.esc.maxRpm = 2200.0;
    o.esc.curvature = 1e5;
    o.esc.ditherRadS = 4.0;
    const auto esc = run(o);
    EXPECT_NEAR(esc.escDesign.omegaPRadS / (2 * kPi), 13.856, 0.001);
    EXPECT_NEAR(esc.escDesign.hcRadS / (2 * kPi), 2.667, 0.001);
    EXPECT_NEAR(esc.escDesign.kcPerS, 134.04, 0.01);
    const auto* t = esc.capture.channel("t_s");
    const auto* cmd = esc.capture.channel("spindle_speed_cmd_rpm");
    const auto* n = esc.capture.channel("spindle_speed_rpm");
    ASSERT_TRUE(t && cmd && n);
    // The dither: the command's strongest line between 5 and 30 Hz after the start is at ω_p/2π = 13.86 Hz.
    double bestF = 0.0, best = 0.0;
    for (double f = 5.0; f <= 30.0; f += 0.02) {
        const double a = lineAt(t->data, cmd->data, 5.0, f);
        if (a > best)
            best = a, bestF = f;
    }
    EXPECT_NEAR(bestF, 13.856, 0.3);
    for (std::size_t i = 0; i < n->data.size(); ++i) {
        ASSERT_GE(n->data[i], 1200.0 - 1e-6) << t->data[i];
        ASSERT_LE(n->data[i], 2200.0 + 1e-6) << t->data[i];
        if (t->data[i] < 5.0) {
            ASSERT_DOUBLE_EQ(n->data[i], 1700.0);
        }
    }
    const double re = rmsLast(esc.capture, duration, 0.3);
    EXPECT_LE(re, 0.65 * rc) << "constant " << rc << " esc " << re;
    // Where it ends the lobes still call 2.5 mm unstable: a local minimum, not a stable pocket.
    EXPECT_LT(limitDepthAt(base.cut.milling, lastValue(esc.capture, "spindle_speed_rpm")), 2.5e-3);
}

TEST(AvoidanceCut, EscWithTheSeedCurvatureIsHeldByTheBounds)
{
    // With the seed's f'' = 1e5 at f_z = 0.1 mm (a cost 514 times the seed's scale, see above) the loop gain is
    // far too high: the speed runs to the bounds, which hold it (anti-windup, counted), never beyond (spec
    // §3.4.3: bound the speed).
    avoidance::AvoidanceCutOptions o;
    o.cut.milling = setup(false, 1700.0, 2.5e-3, 9.0);
    o.cut.durationS = 1.5;
    o.cut.engageS = 0.1;
    o.method = avoidance::Method::Esc;
    o.sensor = machining::AvoidanceSensor::Accelerometer;
    o.esc.startS = 0.5;
    o.esc.minRpm = 1500.0;
    o.esc.maxRpm = 1900.0;
    const auto esc = run(o);
    EXPECT_GT(esc.escBoundHits, 0u);
    const auto* n = esc.capture.channel("spindle_speed_rpm");
    ASSERT_TRUE(n);
    const auto [lo, hi] = std::minmax_element(n->data.begin(), n->data.end());
    EXPECT_GE(*lo, 1500.0 - 1e-6);
    EXPECT_LE(*hi, 1900.0 + 1e-6);
}
