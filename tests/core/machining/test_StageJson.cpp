// SPDX-License-Identifier: GPL-3.0-or-later
// stage.json reader: the sample in resources/samples, and errors that name the file and the key.
#include "core/machining/StageJson.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <string>
#include <nlohmann/json.hpp>

using namespace axistune::machining;

TEST(StageJson, SampleParses)
{
    auto d = readStageJsonFile(std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/stage.json");
    ASSERT_TRUE(d) << d.error().detail;
    EXPECT_DOUBLE_EQ(d->leadMPerRev, 0.012);
    EXPECT_DOUBLE_EQ(d->motor.coulomb, 0.305);
    EXPECT_TRUE(d->hasCoupling);
    EXPECT_EQ(d->rls.windowL, 100);
    EXPECT_EQ(d->rls.handover, Handover::Shadow);
    // 280 kg table: J_L / R² with R = 12 mm / 2π (vmc.json source).
    EXPECT_NEAR(d->twoMass().tableMassKg, 280.0, 0.01);
    auto mode = vibrationModeOf(d->twoMass());
    ASSERT_TRUE(mode);
    // Free-free two-inertia resonance √(K (1/J_M + 1/J_L)) / 2π = 124.8 Hz (vmc.json: "124 Hz coupling mode").
    EXPECT_NEAR(mode->frequencyHz(), std::sqrt(337.1 * (1 / 0.0011818 + 1 / 0.00102133)) / (2 * std::numbers::pi),
                1e-6);
}

TEST(StageJson, ErrorsNameTheKey)
{
    const std::string ok = R"({"screw_lead_m_per_rev": 0.01, "torque_constant_Nm_per_A": 0.5,
        "motor": {"inertia_kgm2": 0.001}, "load": {"inertia_kgm2": 0.001}})";
    EXPECT_TRUE(parseStageJson(ok, "s.json"));
    const struct {
        std::string text, needle;
    } bad[] = {
        {R"({"torque_constant_Nm_per_A": 0.5, "motor": {"inertia_kgm2": 1}, "load": {"inertia_kgm2": 1}})",
         "screw_lead_m_per_rev"},
        {R"({"screw_lead_m_per_rev": 0.01, "torque_constant_Nm_per_A": 0.5, "motor": {"inertia_kgm2": 0}, "load": {"inertia_kgm2": 1}})",
         "motor, key 'inertia_kgm2'"},
        {R"({"screw_lead_m_per_rev": 0.01, "torque_constant_Nm_per_A": 0.5, "motor": {"inertia_kgm2": 1}, "load": {"inertia_kgm2": 1, "coulomb_Nm": -1}})",
         "load, key 'coulomb_Nm'"},
        {R"({"screw_lead_m_per_rev": 0.01, "torque_constant_Nm_per_A": 0.5, "motor": {"inertia_kgm2": 1}, "load": {"inertia_kgm2": 1}, "rls": {"lamda": 0.9}})",
         "unknown key 'lamda'"},
        {R"({"screw_lead_m_per_rev": 0.01, "torque_constant_Nm_per_A": 0.5, "motor": {"inertia_kgm2": 1}, "load": {"inertia_kgm2": 1}, "rls": {"method": "x"}})",
         "key 'method'"},
        {R"({"screw_lead_m_per_rev": "a"})", "not a number"},
        {R"([1, 2])", "top level"},
        {R"({"screw_lead_m_per_rev": )", "not valid JSON"},
    };
    for (const auto& b : bad) {
        auto r = parseStageJson(b.text, "s.json");
        ASSERT_FALSE(r) << b.text;
        EXPECT_NE(r.error().detail.find("s.json"), std::string::npos) << r.error().detail;
        EXPECT_NE(r.error().detail.find(b.needle), std::string::npos) << r.error().detail;
    }
}
