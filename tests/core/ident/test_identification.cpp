// SPDX-License-Identifier: GPL-3.0-or-later
// core/ident: IDIM-LS identification and closed-loop validation (docs/identification.md).
//  * the zero-phase filters against scipy.signal.sosfiltfilt (tests/data/ident/emps_reference.py);
//  * EMPS (real data, shared/data/real): the parameters within 0.5 % and the validation errors within
//    2 % of the independent reference script's; the identified model validates on the pulses record at
//    least as well (within 5 %) as the benchmark's published model does under the same simulation;
//  * analytic records: a force computed exactly from known parameters gives them back within 0.5 %;
//  * refusals: no reversal, unexcited inertia, jittery time stamps beyond the tolerance.
#include "core/dsp/IirDesign.h"
#include "core/ident/IdentificationInput.h"
#include "core/ident/IdentificationJson.h"
#include "core/ident/MotionIdentification.h"
#include "core/io/CaptureCsv.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>

using namespace axistune;

namespace {

const std::string kRealDir = AXISTUNE_REAL_DATA_DIR;
constexpr double kGtau = 35.15065188;

nlohmann::json reference()
{
    std::ifstream f(std::string(AXISTUNE_TEST_DATA_DIR) + "/ident/emps_reference.json");
    EXPECT_TRUE(f.good()) << "tests/data/ident/emps_reference.json missing";
    return nlohmann::json::parse(f);
}

model::Capture readReal(const std::string& name)
{
    const std::string path = kRealDir + "/" + name;
    EXPECT_TRUE(std::filesystem::exists(path))
        << path << " missing: configure with -DAXISTUNE_REAL_DATA_DIR=<shared/data/real>";
    auto c = io::readCaptureCsvFile(path);
    EXPECT_TRUE(c.ok()) << (c.ok() ? "" : c.error().detail);
    return c.ok() ? c.value() : model::Capture{};
}

ident::CaptureColumns empsColumns()
{
    ident::CaptureColumns c;
    c.position = "q_motor";
    c.force = "u_voltage";
    c.forceScale = kGtau;
    c.reference = "q_ref";
    return c;
}

void expectRel(double actual, double expected, double rel, const std::string& what)
{
    EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << what;
}

// q = a1 sin(w1 t) + a2 sin(w2 t), force from the model exactly (plus optional noise).
ident::MotionRecord analyticRecord(double m, double fv, double fc, double off, double a1, double f1, double a2,
                                   double f2, double seconds, double noise = 0.0)
{
    ident::MotionRecord r;
    r.periodS = 1e-3;
    const auto n = static_cast<std::size_t>(seconds / r.periodS);
    std::mt19937 rng(7);
    std::normal_distribution<double> nd(0.0, 1.0);
    const double w1 = 2 * std::numbers::pi * f1, w2 = 2 * std::numbers::pi * f2;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) * r.periodS;
        const double q = a1 * std::sin(w1 * t) + a2 * std::sin(w2 * t);
        const double v = a1 * w1 * std::cos(w1 * t) + a2 * w2 * std::cos(w2 * t);
        const double a = -a1 * w1 * w1 * std::sin(w1 * t) - a2 * w2 * w2 * std::sin(w2 * t);
        r.position.push_back(q);
        r.force.push_back(m * a + fv * v + fc * (v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0)) + off + noise * nd(rng));
        r.velocity.push_back(v);
    }
    return r;
}

} // namespace

TEST(IirDesign, ZeroPhaseFiltersMatchScipySosfiltfilt)
{
    const auto ref = reference()["filters"];
    const auto x = ref["input"].get<std::vector<double>>();
    auto b = dsp::butterworthLowPass(4, 0.2);
    auto c = dsp::chebyshev1LowPass(8, 0.05, 0.08);
    ASSERT_TRUE(b.ok() && c.ok());
    for (const auto& [sos, key] : {std::pair{*b, "butter4_0.2"}, std::pair{*c, "cheby1_8_0.05dB_0.08"}}) {
        auto y = dsp::filtfiltSos(sos, x);
        ASSERT_TRUE(y.ok());
        const auto expected = ref[key].get<std::vector<double>>();
        ASSERT_EQ(y->size(), expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i)
            ASSERT_NEAR((*y)[i], expected[i], 1e-9) << key << " sample " << i;
    }
    EXPECT_FALSE(dsp::butterworthLowPass(3, 0.2).ok());
    EXPECT_FALSE(dsp::butterworthLowPass(4, 1.0).ok());
    EXPECT_FALSE(dsp::filtfiltSos(*b, std::vector<double>(10, 1.0)).ok());
}

TEST(Identification, EmpsAgreesWithTheIndependentReference)
{
    const auto ref = reference();
    const auto cap = readReal("emps_DATA_EMPS.csv");
    auto rec = ident::motionRecordFromCapture(cap, "emps_DATA_EMPS.csv", empsColumns());
    ASSERT_TRUE(rec.ok()) << rec.error().detail; // ±24 ns jitter on 1 ms: within 0.1 %
    ident::IdentificationOptions o;
    o.asymmetric = true;
    auto r = ident::identifyRigidBody(*rec, o);
    ASSERT_TRUE(r.ok()) << r.error().detail;
    const auto th = ref["symmetric"]["theta"], sd = ref["symmetric"]["std"];
    const ident::Estimate* e[4] = {&r->inertia, &r->viscous, &r->coulomb, &r->offset};
    const char* names[4] = {"inertia", "viscous", "coulomb", "offset"};
    for (int i = 0; i < 4; ++i) {
        expectRel(e[i]->value, th[i].get<double>(), 0.005, names[i]);
        expectRel(e[i]->std, sd[i].get<double>(), 0.005, std::string(names[i]) + " std");
    }
    EXPECT_EQ(r->decimation, ref["symmetric"]["decimation"].get<int>());
    EXPECT_EQ(r->rows, ref["symmetric"]["rows"].get<std::size_t>());
    expectRel(r->condition, ref["symmetric"]["condition_number"].get<double>(), 0.005, "cond");
    expectRel(r->scaledCondition, ref["symmetric"]["condition_number_scaled"].get<double>(), 0.005, "scaled cond");
    expectRel(r->residualRms, ref["symmetric"]["residual_rms"].get<double>(), 0.005, "residual");
    ASSERT_TRUE(r->asymmetric.has_value());
    const auto ta = ref["asymmetric"]["theta"];
    const auto& a = *r->asymmetric;
    const ident::Estimate* ea[5] = {&a.inertia, &a.viscousPositive, &a.viscousNegative, &a.coulombPositive,
                                    &a.coulombNegative};
    for (int i = 0; i < 5; ++i)
        expectRel(ea[i]->value, ta[i].get<double>(), 0.005, "asymmetric " + std::to_string(i));
}

TEST(Identification, EmpsValidationOnThePulsesRecord)
{
    const auto ref = reference();
    const auto th = ref["symmetric"]["theta"];
    const auto rc = ref["controller"]; // the script's names
    auto ctrl = ident::controllerFromJson({{"kp_per_s", rc["kp"]},
                                           {"kv", rc["kv"]},
                                           {"saturation", rc["saturation"]},
                                           {"delay_samples", rc["delay"]},
                                           {"force_scale", rc["force_scale"]}},
                                          "reference");
    ASSERT_TRUE(ctrl.ok()) << ctrl.error().detail;
    const auto cap = readReal("emps_DATA_EMPS_PULSES.csv");
    auto cols = empsColumns();
    cols.extra = "pulses_N";
    auto rec = ident::validationRecordFromCapture(cap, "pulses", cols);
    ASSERT_TRUE(rec.ok()) << rec.error().detail;
    for (const std::string which : {"identified", "published"}) {
        const auto theta = which == "identified" ? th.get<std::vector<double>>()
                                                 : std::vector<double>{95.1089, 203.5034, 20.3935, -3.1648};
        const auto model = ident::RigidBodyModel::symmetric(theta[0], theta[1], theta[2], theta[3]);
        auto v = ident::validateClosedLoop(model, *ctrl, *rec, 100.0, ref["symmetric"]["border"].get<std::size_t>());
        ASSERT_TRUE(v.ok()) << v.error().detail;
        const auto rv = ref["validation"][which];
        expectRel(v->positionErrorRms, rv["position_error_rms_m"].get<double>(), 0.02, which + " rms");
        expectRel(v->positionErrorPctOfMotion, rv["position_error_pct_of_motion_rms"].get<double>(), 0.02,
                  which + " %");
        expectRel(v->benchmarkPositionPct, rv["benchmark_rel_err_position_pct"].get<double>(), 0.02,
                  which + " benchmark q");
        expectRel(v->benchmarkForcePct, rv["benchmark_rel_err_force_pct"].get<double>(), 0.02, which + " benchmark F");
    }
    // The bound the reference computes: the published model under the same simulation.
    EXPECT_LE(ref["validation"]["identified"]["benchmark_rel_err_force_pct"].get<double>(),
              1.05 * ref["validation"]["published"]["benchmark_rel_err_force_pct"].get<double>());
}

TEST(Identification, AnalyticRecordGivesTheParametersBack)
{
    for (const double scale : {1.0, 0.01}) { // a linear axis in m/N, a rotary one in rad/N·m
        const double m = 95.0 * scale, fv = 200.0 * scale, fc = 20.0 * scale, off = -3.0 * scale;
        auto rec = analyticRecord(m, fv, fc, off, 0.1, 0.5, 0.02, 1.3, 20.0);
        for (const bool measuredVelocity : {false, true}) { // differentiate q, or the --velocity column
            auto input = rec;
            if (!measuredVelocity)
                input.velocity.clear();
            auto r = ident::identifyRigidBody(input, {});
            ASSERT_TRUE(r.ok()) << r.error().detail;
            expectRel(r->inertia.value, m, 0.005, "M");
            expectRel(r->viscous.value, fv, 0.005, "Fv");
            expectRel(r->coulomb.value, fc, 0.005, "Fc");
            expectRel(r->offset.value, off, 0.005, "offset");
        }
    }
}

TEST(Identification, RefusesWithoutReversalUnexcitedInertiaOrBadTime)
{
    // Always moving forward: Coulomb and the offset cannot be told apart.
    ident::MotionRecord fwd; // no velocity column: differentiated
    fwd.periodS = 1e-3;
    for (int k = 0; k < 20000; ++k) {
        const double t = k * 1e-3;
        fwd.position.push_back(0.05 * t + 0.01 * std::sin(std::numbers::pi * t));
        fwd.force.push_back(10.0 + 5.0 * std::cos(std::numbers::pi * t));
    }
    auto r1 = ident::identifyRigidBody(fwd, {});
    ASSERT_FALSE(r1.ok());
    EXPECT_NE(r1.error().detail.find("reverse"), std::string::npos) << r1.error().detail;

    // A slow motion under force noise: the inertia's standard deviation is far above 20 %.
    auto slow = analyticRecord(10.0, 50.0, 5.0, 0.0, 0.1, 0.02, 0.0, 1.0, 40.0, 2.0);
    auto r2 = ident::identifyRigidBody(slow, {});
    ASSERT_FALSE(r2.ok());
    EXPECT_NE(r2.error().detail.find("inertia is not identified"), std::string::npos) << r2.error().detail;

    // Time stamps: ±24 ns jitter on 1 ms is accepted, the rate from the median; a 2 ms step is not.
    std::vector<double> t;
    for (int k = 0; k < 100; ++k)
        t.push_back(k * 1e-3 + ((k % 3) - 1) * 24e-9);
    auto h = ident::uniformSamplePeriod(t, ident::kDefaultTimeTolerance);
    ASSERT_TRUE(h.ok()) << h.error().detail;
    EXPECT_NEAR(*h, 1e-3, 1e-7);
    t[5] += 1e-3;
    for (std::size_t k = 6; k < t.size(); ++k)
        t[k] += 1e-3;
    auto h2 = ident::uniformSamplePeriod(t, ident::kDefaultTimeTolerance);
    ASSERT_FALSE(h2.ok());
    EXPECT_NE(h2.error().detail.find("data rows 5 and 6"), std::string::npos) << h2.error().detail;
}

TEST(IdentificationJson, ResultRoundTripsAsASimulatorModel)
{
    auto rec = analyticRecord(2.0, 0.5, 0.3, 0.1, 1.0, 0.5, 0.2, 1.3, 20.0);
    auto r = ident::identifyRigidBody(rec, {});
    ASSERT_TRUE(r.ok()) << r.error().detail;
    const auto j = ident::identificationToJson(*r, ident::AxisMotion::Rotary);
    EXPECT_EQ(j["units"]["inertia"], "kg*m^2");
    EXPECT_EQ(j["units"]["viscous"], "N*m*s/rad");
    auto m = ident::identifiedModelFromJson(j, "mem");
    ASSERT_TRUE(m.ok()) << m.error().detail;
    EXPECT_EQ(m->motion, ident::AxisMotion::Rotary);
    EXPECT_DOUBLE_EQ(m->model.inertia, r->inertia.value);
    EXPECT_DOUBLE_EQ(m->model.coulombNegative, r->coulomb.value);
    auto bad = j;
    bad["inertia"]["value"] = -1.0;
    EXPECT_FALSE(ident::identifiedModelFromJson(bad, "mem").ok());
    EXPECT_FALSE(ident::controllerFromJson(nlohmann::json{{"kp_per_s", 1.0}}, "c.json").ok());
    // A validation without a position loop (kp = 0) is refused, not simulated.
    ident::ValidationRecord v;
    v.periodS = 1e-3;
    v.reference.assign(100, 0.0);
    v.position.assign(100, 0.0);
    v.command.assign(100, 0.0);
    auto noLoop = ident::validateClosedLoop(m->model, {0.0, 10.0, 10.0, 0, 1.0}, v, 100.0, 10);
    ASSERT_FALSE(noLoop.ok());
    EXPECT_NE(noLoop.error().detail.find("kp, kv"), std::string::npos) << noLoop.error().detail;
}
