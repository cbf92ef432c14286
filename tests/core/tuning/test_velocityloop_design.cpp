// SPDX-License-Identifier: GPL-3.0-or-later
// The headless velocity-loop design (core/tuning/VelocityLoopDesign.h, issue 18 item 1) against an independent
// computation: tests/data/velocity_loop/make_reference.py (Python standard library, margins by bisection on the
// continuous open loop) and its output reference.json, plant_rigid.csv, complementary.csv.
#include "core/io/FrfCsv.h"
#include "core/tuning/VelocityLoopDesign.h"

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <numbers>

using namespace axistune;
using namespace axistune::tuning;

namespace {

const std::string kDir = std::string(AXISTUNE_TEST_DATA_DIR) + "/velocity_loop/";

nlohmann::json reference()
{
    std::ifstream f(kDir + "reference.json");
    return nlohmann::json::parse(f);
}

dsp::FrequencyResponse readFrf(const std::string& name)
{
    auto r = io::readFrfCsvFile(kDir + name);
    EXPECT_TRUE(r.ok()) << (r ? "" : r.error().detail);
    return r ? *r : dsp::FrequencyResponse{};
}

VelocityLoopRequest runningRequest(const nlohmann::json& ref)
{
    VelocityLoopRequest r;
    r.running = {ref["running"]["kp"].get<double>(), ref["running"]["ki"].get<double>()};
    r.velocityPeriodS = ref["running"]["velocity_period_s"].get<double>();
    r.currentPeriodS = ref["running"]["current_period_s"].get<double>();
    return r;
}

// The design grid is 300 log-spaced lines (ratio 10^(3.3/299) = 1.0257); loopMargins interpolates linearly in
// log f. The interpolation error of a smooth curve is at most Δ²/8·|curvature| with Δ = ln 1.0257 = 0.0254: for the
// phase of L (the delay term ωτ ≈ 46° at the crossover) 0.004°, for log|L| a few 1e-5. The tolerances below are
// about five times these bounds.
void expectMargins(const LoopMargins& m, const nlohmann::json& ref)
{
    EXPECT_NEAR(m.crossoverHz, ref["crossover_Hz"].get<double>(), 1e-4 * ref["crossover_Hz"].get<double>());
    EXPECT_NEAR(m.phaseMarginDeg, ref["phase_margin_deg"].get<double>(), 0.02);
    EXPECT_NEAR(m.gainMarginDb, ref["gain_margin_dB"].get<double>(), 0.01);
    EXPECT_NEAR(m.phaseCrossoverHz, ref["phase_crossover_Hz"].get<double>(),
                2e-4 * ref["phase_crossover_Hz"].get<double>());
}

} // namespace

TEST(VelocityLoopDesign, InertiaRuleGainsAndMarginsMatchTheIndependentComputation)
{
    const auto ref = reference();
    const auto& c = ref["inertia"];
    auto req = runningRequest(ref);
    req.method = VelocityLoopRequest::Method::Inertia;
    req.jmKgm2 = c["Jm_kgm2"].get<double>();
    req.omegaLHz = c["bandwidth_Hz"].get<double>();
    req.k = c["k"].get<double>();
    auto d = designVelocityLoop(req);
    ASSERT_TRUE(d.ok()) << d.error().detail;
    // Closed-form gains: only rounding differs.
    EXPECT_NEAR(d->proposed.kpNmsPerRad, c["kp"].get<double>(), 1e-12 * c["kp"].get<double>());
    EXPECT_NEAR(d->proposed.kiNmPerRad, c["ki"].get<double>(), 1e-12 * c["ki"].get<double>());
    EXPECT_TRUE(d->rigidModel);
    EXPECT_NEAR(d->model.delayS, 1.5 * req.velocityPeriodS, 1e-18);
    expectMargins(d->marginsBefore, c["margins_before"]);
    expectMargins(d->marginsAfter, c["margins_after"]);
    EXPECT_NE(d->rule.find("chapter 5 rule"), std::string::npos);
    ASSERT_TRUE(d->predictedBefore && d->predictedAfter);
    const auto p = velocityLoopParameters(*d, false);
    EXPECT_EQ(p.size(), 2u);
    EXPECT_EQ(p.at("velocity.kp"), d->proposed.kpNmsPerRad);
}

TEST(VelocityLoopDesign, MarginsRuleOnAPlantFileAndOnTheClosedLoopGiveTheSamePi)
{
    const auto ref = reference();
    const auto& c = ref["margins"];
    for (const char* file : {"plant_rigid.csv", "complementary.csv"}) {
        SCOPED_TRACE(file);
        auto req = runningRequest(ref);
        req.method = VelocityLoopRequest::Method::Frf;
        req.jmKgm2 = c["Jm_plant_kgm2"].get<double>();
        req.crossoverHz = c["crossover_Hz"].get<double>();
        req.phaseMarginDeg = c["phase_margin_deg"].get<double>();
        req.measured = readFrf(file);
        auto d = designVelocityLoop(req);
        ASSERT_TRUE(d.ok()) << d.error().detail;
        // The crossover is a measured line and the CSV holds 17 significant digits; the closed loop is inverted
        // exactly (T/(1 − T)/C_d): 1e-9 relative leaves room for the rounding of the inversion only.
        EXPECT_NEAR(d->proposed.kpNmsPerRad, c["kp"].get<double>(), 1e-9 * c["kp"].get<double>());
        EXPECT_NEAR(d->proposed.kiNmPerRad, c["ki"].get<double>(), 1e-9 * c["ki"].get<double>());
        // By construction of the rule the predicted open loop crosses at 60 Hz with 50° (grid = the lines).
        EXPECT_NEAR(d->marginsAfter.crossoverHz, 60.0, 1e-6);
        EXPECT_NEAR(d->marginsAfter.phaseMarginDeg, 50.0, 1e-6);
        ASSERT_TRUE(d->plant);
        EXPECT_EQ(d->fHz.size(), 200u);
    }
}

TEST(VelocityLoopDesign, RefusesWhatItCannotDesign)
{
    VelocityLoopRequest r;
    r.method = VelocityLoopRequest::Method::Frf;
    r.jmKgm2 = 1e-3;
    auto d = designVelocityLoop(r);
    ASSERT_FALSE(d.ok());
    EXPECT_NE(d.error().detail.find("measured response"), std::string::npos);
    r.method = VelocityLoopRequest::Method::Inertia;
    r.jmKgm2 = 0.0;
    d = designVelocityLoop(r);
    ASSERT_FALSE(d.ok());
    EXPECT_NE(d.error().detail.find("J_m"), std::string::npos);
    r.jmKgm2 = std::nan("");
    EXPECT_FALSE(designVelocityLoop(r).ok());
    r.jmKgm2 = 1e-3;
    r.velocityPeriodS = 0.0;
    EXPECT_FALSE(designVelocityLoop(r).ok());
    // A PI only lags (0 … −90°): 50° of phase margin on a plant that already lags 170° is out of reach.
    r.velocityPeriodS = 250e-6;
    r.method = VelocityLoopRequest::Method::Frf;
    dsp::FrequencyResponse lagging;
    lagging.metadata.set("measurement", "plant");
    for (int i = 1; i <= 100; ++i)
        lagging.push(5.0 * i, std::polar(1.0, -170.0 * std::numbers::pi / 180.0), 1.0, true);
    r.measured = lagging;
    r.crossoverHz = 60.0;
    d = designVelocityLoop(r);
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error().code, ErrorCode::OutOfRange);
    r.measured->metadata.set("measurement", "bode");
    d = designVelocityLoop(r);
    ASSERT_FALSE(d.ok());
    EXPECT_NE(d.error().detail.find("'bode'"), std::string::npos);
}

TEST(VelocityLoopDesign, OneParserOfLoopMeasurements)
{
    for (auto k : {LoopMeasurementKind::Plant, LoopMeasurementKind::Open, LoopMeasurementKind::Complementary,
                   LoopMeasurementKind::NegComplementary, LoopMeasurementKind::Sensitivity}) {
        auto back = parseLoopMeasurement(loopMeasurementName(k));
        ASSERT_TRUE(back.ok());
        EXPECT_EQ(*back, k);
    }
    EXPECT_FALSE(parseLoopMeasurement("closed").ok());
    dsp::FrequencyResponse f;
    EXPECT_EQ(*loopMeasurementOf(f, LoopMeasurementKind::Complementary), LoopMeasurementKind::Complementary);
    EXPECT_EQ(*loopMeasurementOf(f, LoopMeasurementKind::Plant), LoopMeasurementKind::Plant);
    f.metadata.set("measurement", "open");
    EXPECT_EQ(*loopMeasurementOf(f, LoopMeasurementKind::Plant), LoopMeasurementKind::Open);
    EXPECT_TRUE(loopFormOf(LoopMeasurementKind::Open)->open);
    EXPECT_EQ(loopFormOf(LoopMeasurementKind::Sensitivity)->closed, dsp::LoopMeasurement::Sensitivity);
    EXPECT_FALSE(loopFormOf(LoopMeasurementKind::Plant).ok());
}

TEST(VelocityLoopDesign, PlantFromAnOpenLoopDividesByTheDiscretePi)
{
    // L = C_d·P with C_d(z) = K_P + K_I·T_v/(1 − z⁻¹): P comes back exactly (1e-12 relative: one division).
    const VelocityPi pi{0.8, 75.0};
    const double tv = 250e-6;
    dsp::FrequencyResponse open;
    open.metadata.set("measurement", "open");
    std::vector<std::complex<double>> plant;
    for (int i = 1; i <= 50; ++i) {
        const double f = 10.0 * i;
        const std::complex<double> s(0.0, 2.0 * std::numbers::pi * f);
        const std::complex<double> zInv = std::exp(-s * tv);
        plant.push_back(1.0 / (1e-3 * s));
        open.push(f, (pi.kpNmsPerRad + pi.kiNmPerRad * tv / (1.0 - zInv)) * plant.back(), 1.0, true);
    }
    auto p = plantFromMeasurement(open, LoopMeasurementKind::Open, pi, tv, 62.5e-6);
    ASSERT_TRUE(p.ok()) << p.error().detail;
    for (std::size_t i = 0; i < plant.size(); ++i)
        EXPECT_NEAR(std::abs(p->h[i] - plant[i]), 0.0, 1e-12 * std::abs(plant[i]));
    EXPECT_EQ(p->metadata.text("measurement"), "plant");
}

TEST(VelocityLoopDesign, NotchSlotsGoToTheFreeSlots)
{
    // Slot 2 is taken; proposeNotches numbers the added notches 2, 3, 4 after the one existing: they go to the
    // free slots 1, 3, 4 in that order.
    NotchProposal prop;
    for (int s = 2; s <= 4; ++s) {
        ProposedNotch n;
        n.slot = s;
        n.resonanceHz = 100.0 * s;
        prop.notches.push_back(n);
    }
    std::map<int, dsp::NotchSpec> existing{{2, dsp::NotchSpec{500.0, 50.0, 0.1}}};
    const auto out = allocateNotchSlots(prop, existing, 4);
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out[0].slot, 1);
    EXPECT_EQ(out[0].resonanceHz, 200.0);
    EXPECT_EQ(out[1].slot, 3);
    EXPECT_EQ(out[2].slot, 4);
    // Only two slots on a drive with three: the third proposal is left out.
    EXPECT_EQ(allocateNotchSlots(prop, existing, 3).size(), 2u);
}

TEST(VelocityLoopDesign, MotorDataFromTheDrive)
{
    const auto ref = reference()["back_emf"];
    EXPECT_NEAR(backEmfFromTorqueConstant(ref["kt_Nm_per_A"].get<double>()), ref["ke_V_s_per_rad"].get<double>(),
                1e-15);
    MotorData base;
    base.resistanceOhm = 0.5;
    base.inductanceQH = 2e-3;
    base.maxCurrentA = 1.0;
    const auto m = motorFromDriveParameters({{"motor.torque_constant", ref["kt_Nm_per_A"].get<double>()},
                                             {"motor.max_current", 20.0},
                                             {"drive.max_voltage", 300.0}},
                                            base);
    EXPECT_NEAR(m.backEmfVPerKrpm, ref["V_per_krpm"].get<double>(), 1e-12 * ref["V_per_krpm"].get<double>());
    EXPECT_EQ(m.maxCurrentA, 20.0);
    EXPECT_EQ(m.maxVoltageV, 300.0);
    EXPECT_EQ(m.resistanceOhm, 0.5); // not offered by the drive: kept
    EXPECT_EQ(m.ratedCurrentA, 0.0);
}

TEST(VelocityLoopDesign, StepOvershootOfACapture)
{
    // A step of 10 rad/s at sample 5 whose response peaks at 12.5 rad/s: 25 % overshoot; the trace starts one
    // sample before the step.
    model::Capture cap;
    cap.channels = {{"t_s", {}}, {"velocity_cmd_rad_s", {}}, {"motor_vel_rad_s", {}}};
    for (int k = 0; k < 20; ++k) {
        cap.channels[0].data.push_back(1e-3 * k);
        cap.channels[1].data.push_back(k >= 5 ? 10.0 : 0.0);
        cap.channels[2].data.push_back(k == 8 ? 12.5 : k >= 6 ? 10.0 : 0.0);
    }
    const auto s = normalisedStep(cap, 10.0);
    ASSERT_EQ(s.y.size(), 16u);
    EXPECT_NEAR(s.tMs.front(), -1.0, 1e-12);
    ASSERT_TRUE(stepOvershootPct(s));
    EXPECT_NEAR(*stepOvershootPct(s), 25.0, 1e-12);
    EXPECT_FALSE(stepOvershootPct(normalisedStep(cap, 0.0)));
}

TEST(VelocityLoopDesign, TwoInertiaProposalOnTable51)
{
    // Table 5.1 (spec/lost-motion-and-two-inertia.md §2.8): J_m 0.00527, J_L 0.0105 kg·m², K 200 N·m/rad,
    // C 0.27 N·m·s/rad; the thesis rule with ω_l = 2π·24, k = 10 gives K_P = 11.24 N·m·s/rad, K_I = 1198 N·m/rad
    // (the spec's printed figures: tolerance half a unit of their last digit).
    const TwoInertiaParams p{0.00527, 0.0105, 200.0, 0.27, 1.1e-3};
    const auto semi = twoInertiaProposal(p, SuppressionMode::Semi, 0.0);
    EXPECT_NEAR(semi.pi.kpNmsPerRad, 11.24, 0.005);
    EXPECT_NEAR(semi.pi.kiNmPerRad, 1198.0, 0.5);
    EXPECT_EQ(semi.parameters.at("velocity.kp"), semi.pi.kpNmsPerRad);
    EXPECT_EQ(semi.parameters.at("suppression.mode"), 1.0);
    EXPECT_EQ(semi.parameters.at("position.velocity_ff"), 1.0);
    EXPECT_EQ(semi.parameters.at("position.torque_ff"), 1.0);
    EXPECT_NEAR(semi.parameters.at("velocity.inertia"), 0.00527 + 0.0105, 1e-15);
    // F_m's f0 is the anti-resonance √(K/J_L)/2π = 21.96 Hz (spec §2.9); its zeta is the model's zero damping.
    EXPECT_NEAR(semi.parameters.at("suppression.f0"), std::sqrt(200.0 / 0.0105) / (2.0 * std::numbers::pi), 1e-9);
    EXPECT_FALSE(semi.parameters.count("suppression.tau"));
    const auto full = twoInertiaProposal(p, SuppressionMode::Full, 0.013);
    EXPECT_EQ(full.parameters.at("suppression.mode"), 2.0);
    EXPECT_NEAR(full.parameters.at("suppression.tau"), 0.013, 1e-15);
    // The policy's options: ω_l and k (the CLI's --bandwidth-hz, --k).
    const auto soft = twoInertiaProposal(p, SuppressionMode::Semi, 0.0, 12.0, 5.0);
    EXPECT_NEAR(soft.pi.kpNmsPerRad, 11.24 / 4.0, 0.005 / 4.0);
}
