// SPDX-License-Identifier: GPL-3.0-or-later
// An identified rigid-body model (axistune-cli identify) as the simulator's plant: "sim:PRESET?model=…".
//  * the motor-side totals are the model referred through the screw lead (J = M·R², B = Fv·R²,
//    T_c = Fc·R; exact arithmetic, 1e-12);
//  * round trip: jogs at three speeds with reversals on the simulated axis with that plant, identified
//    again from the trace, give the model back within 2 % (the simulator's Coulomb friction is
//    tanh-smoothed and its axis is a two-mass system, not exactly the identified model's form);
//  * wrong kind, unknown option and missing file are refused with the reason.
#include "core/device/SimulatedDrive.h"
#include "core/device/TestRunner.h"
#include "core/ident/IdentificationJson.h"
#include "core/ident/MotionIdentification.h"
#include "tests/ScopedTempDir.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <nlohmann/json.hpp>

using namespace axistune;
using namespace axistune::device;

namespace {

constexpr double kM = 95.1089, kFv = 203.5034, kFc = 20.3935; // the EMPS benchmark's published model

std::string writeModel(ident::AxisMotion motion)
{
    ident::IdentificationResult r;
    r.inertia = {kM, 0.1};
    r.viscous = {kFv, 1.0};
    r.coulomb = {kFc, 0.1};
    r.offset = {-3.1648, 0.04};
    static const axistune::testing::ScopedTempDir dir("model"); // removed when the process ends
    const auto path = dir / (std::string("axistune-model-") + ident::axisMotionName(motion) + "-" +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".json");
    std::ofstream(path) << ident::identificationToJson(r, motion).dump(2);
    return path.string();
}

// The plant is not readable through the Drive (it is the machine); the simulator shows it.
const model::ParameterValues& plant(Drive& d, const std::string& axis)
{
    auto* sim = dynamic_cast<SimulatedDrive&>(d).simulator(axis);
    EXPECT_NE(sim, nullptr);
    return sim->parameters();
}

model::Capture jog(Drive& drive, double velocity)
{
    TestRequest req;
    req.axis = "X";
    auto& j = req.test.emplace<JogTest>();
    j.distance = 0.1;
    j.velocity = velocity;
    j.acceleration = 0.8;
    j.returnToStart = true;
    j.dwellS = 0.2;
    auto run = runTest(drive, req);
    EXPECT_TRUE(run.ok()) << (run.ok() ? "" : run.error().detail);
    return run.ok() ? *run->trace : model::Capture{};
}

} // namespace

TEST(IdentifiedPlant, ModelSetsTheMotorSideTotals)
{
    const auto path = writeModel(ident::AxisMotion::Linear);
    auto plain = connect({"sim:vmc", 1});
    auto d = connect({"sim:vmc?model=" + path + "&axis=X", 1});
    ASSERT_TRUE(plain.ok() && d.ok()) << (d.ok() ? "" : d.error().detail);
    const auto* v = &plant(**d, "X");
    const auto* before = &plant(**plain, "X");
    const double r = v->at("plant.screw_lead");
    EXPECT_NEAR(v->at("plant.inertia_motor") + v->at("plant.inertia_load"), kM * r * r, 1e-12 * kM * r * r);
    EXPECT_NEAR(v->at("plant.viscous_motor") + v->at("plant.viscous_load"), kFv * r * r, 1e-12 * kFv * r * r);
    EXPECT_NEAR(v->at("plant.coulomb_motor") + v->at("plant.coulomb_load"), kFc * r, 1e-12 * kFc * r);
    // The preset's motor/load split of the inertia is kept.
    EXPECT_NEAR(v->at("plant.inertia_motor") / v->at("plant.inertia_load"),
                before->at("plant.inertia_motor") / before->at("plant.inertia_load"), 1e-9);
    // Other axes keep the preset's plant.
    EXPECT_EQ(plant(**d, "Y").at("plant.inertia_load"), plant(**plain, "Y").at("plant.inertia_load"));
}

TEST(IdentifiedPlant, JogsOnTheModelledAxisIdentifyTheModelAgain)
{
    const auto path = writeModel(ident::AxisMotion::Linear);
    auto d = connect({"sim:vmc?model=" + path + "&axis=X", 1});
    ASSERT_TRUE(d.ok()) << d.error().detail;
    const double r = plant(**d, "X").at("plant.screw_lead");
    ident::MotionRecord rec;
    for (const double v : {0.03, 0.06, 0.12}) {
        const auto t = jog(**d, v);
        const auto* q = t.channel("motor_pos_m");
        const auto* f = t.channel("torque_Nm");
        const auto* ts = t.channel("t_s");
        ASSERT_TRUE(q && f && ts);
        rec.periodS = ts->data[1] - ts->data[0];
        rec.position.insert(rec.position.end(), q->data.begin(), q->data.end());
        for (double tau : f->data)
            rec.force.push_back(tau / r); // motor torque → force at the table
    }
    auto id = ident::identifyRigidBody(rec, {});
    ASSERT_TRUE(id.ok()) << id.error().detail;
    for (const auto& [e, truth, name] :
         {std::tuple{id->inertia, kM, "M"}, std::tuple{id->viscous, kFv, "Fv"}, std::tuple{id->coulomb, kFc, "Fc"}}) {
        EXPECT_NEAR(e.value, truth, std::max(3.0 * e.std, 0.02 * truth)) << name << " ± " << e.std;
        EXPECT_LT(std::abs(e.value - truth), 0.02 * truth) << name;
    }
    // The simulator has no constant force: the offset comes back as (nearly) zero.
    EXPECT_LT(std::abs(id->offset.value), 0.02 * kFc) << id->offset.value;
}

TEST(IdentifiedPlant, WrongKindUnknownOptionAndMissingFileAreRefused)
{
    const auto rotary = writeModel(ident::AxisMotion::Rotary);
    auto a = connect({"sim:vmc?model=" + rotary + "&axis=X", 1});
    ASSERT_FALSE(a.ok());
    EXPECT_NE(a.error().detail.find("rotary model cannot be applied to linear axis X"), std::string::npos)
        << a.error().detail;
    auto b = connect({"sim:vmc?modle=x.json", 1});
    ASSERT_FALSE(b.ok());
    EXPECT_NE(b.error().detail.find("unknown or empty option 'modle=x.json'"), std::string::npos) << b.error().detail;
    auto c = connect({"sim:vmc?model=/nonexistent/result.json&axis=X", 1});
    ASSERT_FALSE(c.ok());
    EXPECT_NE(c.error().detail.find("/nonexistent/result.json"), std::string::npos) << c.error().detail;
    auto e = connect({"sim:vmc?model=" + writeModel(ident::AxisMotion::Linear), 1});
    ASSERT_FALSE(e.ok()); // three linear axes: which one?
    EXPECT_NE(e.error().detail.find("give axis=NAME"), std::string::npos) << e.error().detail;
}
