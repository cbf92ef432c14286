// SPDX-License-Identifier: GPL-3.0-or-later
// Bad tool and cutting data give clear errors naming the file and the key (STYLE.md: never a clamp).
#include "core/machining/MachiningJson.h"
#include "core/machining/StabilityLobes.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace axistune;
using namespace axistune::machining;

namespace {
const char* kTool = R"({"modes_x":[{"mass_kg":0.4,"damping_Ns_per_m":83,"stiffness_N_per_m":30.1e6}],
                        "modes_y":[{"mass_kg":0.4,"damping_Ns_per_m":83,"stiffness_N_per_m":30.1e6},
                                   {"mass_kg":0.1,"damping_Ns_per_m":20,"stiffness_N_per_m":50e6}]})";
const char* kCut = R"({"teeth":4,"Kt_N_per_m2":0.98e9,"Kr_N_per_m2":0.294e9,"radial_immersion":0.5,"milling":"up"})";

void expectError(const Error& e, ErrorCode code, const std::string& mustContain)
{
    EXPECT_EQ(e.code, code) << e.detail;
    EXPECT_NE(e.detail.find(mustContain), std::string::npos) << e.detail;
    EXPECT_NE(e.detail.find("src.json"), std::string::npos) << e.detail;
}
}  // namespace

TEST(MachiningJson, ParsesValidFiles)
{
    auto t = parseToolJson(kTool, "src.json");
    ASSERT_TRUE(t.ok()) << t.error().detail;
    EXPECT_EQ(t->modesX.size(), 1u);
    ASSERT_EQ(t->modesY.size(), 2u);
    EXPECT_DOUBLE_EQ(t->modesY[1].stiffnessNPerM, 50e6);
    auto c = parseCutJson(kCut, "src.json");
    ASSERT_TRUE(c.ok()) << c.error().detail;
    EXPECT_EQ(c->teeth, 4);
    EXPECT_EQ(c->milling, MillingDirection::Up);
    EXPECT_DOUBLE_EQ(c->radialImmersion, 0.5);
}

TEST(MachiningJson, BadToolData)
{
    expectError(parseToolJson(R"({"modes_x":[{"mass_kg":0,"damping_Ns_per_m":83,"stiffness_N_per_m":3e7}],
                                  "modes_y":[{"mass_kg":0.4,"damping_Ns_per_m":83,"stiffness_N_per_m":3e7}]})",
                              "src.json").error(),
                ErrorCode::OutOfRange, "modes_x[0].mass_kg");
    expectError(parseToolJson(R"({"modes_x":[{"mass_kg":0.4,"damping_Ns_per_m":83,"stiffness_N_per_m":3e7}],
                                  "modes_y":[{"mass_kg":0.4,"damping_Ns_per_m":83,"stiffness_N_per_m":-3e7}]})",
                              "src.json").error(),
                ErrorCode::OutOfRange, "modes_y[0].stiffness_N_per_m");
    expectError(parseToolJson(R"({"modes_x":[{"mass_kg":0.4,"stiffness_N_per_m":3e7}],"modes_y":[]})", "src.json").error(),
                ErrorCode::BadInput, "damping_Ns_per_m");
    expectError(parseToolJson(R"({"modes_x":[{"mass_kg":0.4,"damping_Ns_per_m":1,"stiffness_N_per_m":3e7}]})", "src.json")
                    .error(),
                ErrorCode::BadInput, "modes_y");
    expectError(parseToolJson(R"({"modes_x": [)", "src.json").error(), ErrorCode::BadInput, "not valid JSON");
    expectError(parseToolJson(R"({"modes_x":[{"mass_kg":"heavy","damping_Ns_per_m":1,"stiffness_N_per_m":3e7}],
                                  "modes_y":[{"mass_kg":0.4,"damping_Ns_per_m":83,"stiffness_N_per_m":3e7}]})",
                              "src.json").error(),
                ErrorCode::BadInput, "mass_kg");
}

TEST(MachiningJson, BadCutData)
{
    expectError(parseCutJson(R"({"teeth":4,"Kt_N_per_m2":0.98e9,"Kr_N_per_m2":0.294e9,"radial_immersion":1.2,"milling":"up"})",
                             "src.json").error(),
                ErrorCode::OutOfRange, "radial_immersion");
    expectError(parseCutJson(R"({"teeth":4,"Kt_N_per_m2":0.98e9,"Kr_N_per_m2":0.294e9,"radial_immersion":0,"milling":"up"})",
                             "src.json").error(),
                ErrorCode::OutOfRange, "radial_immersion");
    expectError(parseCutJson(R"({"teeth":0,"Kt_N_per_m2":0.98e9,"Kr_N_per_m2":0.294e9,"radial_immersion":0.5,"milling":"up"})",
                             "src.json").error(),
                ErrorCode::OutOfRange, "teeth");
    expectError(parseCutJson(R"({"teeth":2.5,"Kt_N_per_m2":0.98e9,"Kr_N_per_m2":0.294e9,"radial_immersion":0.5,"milling":"up"})",
                             "src.json").error(),
                ErrorCode::BadInput, "teeth");
    expectError(parseCutJson(R"({"teeth":4,"Kt_N_per_m2":-1,"Kr_N_per_m2":0.294e9,"radial_immersion":0.5,"milling":"up"})",
                             "src.json").error(),
                ErrorCode::OutOfRange, "Kt_N_per_m2");
    expectError(parseCutJson(R"({"teeth":4,"Kt_N_per_m2":0.98e9,"radial_immersion":0.5,"milling":"up"})", "src.json").error(),
                ErrorCode::BadInput, "Kr_N_per_m2");
    expectError(parseCutJson(R"({"teeth":4,"Kt_N_per_m2":0.98e9,"Kr_N_per_m2":0.294e9,"radial_immersion":0.5,"milling":"climb"})",
                             "src.json").error(),
                ErrorCode::BadInput, "milling");
}

TEST(MachiningJson, LobeInputsAreValidated)
{
    const ModalParameters m{0.4, 83.0, 30.1e6};
    CuttingConditions c;
    c.teeth = 4;
    c.ktNPerM2 = 0.98e9;
    c.krNPerM2 = 0.294e9;
    c.radialImmersion = 0.5;
    LobeOptions o;
    EXPECT_FALSE(stabilityLobes({{}, {}}, c, {3000.0}, o).ok()); // rigid in x and y
    EXPECT_TRUE(stabilityLobes({{m}, {}}, c, {3000.0}, o).ok()); // rigid in y only (issue 19)
    EXPECT_FALSE(stabilityLobes({{m}, {m}}, c, {-3000.0}, o).ok());
    o.stepsPerPeriod = 1;
    EXPECT_FALSE(stabilityLobes({{m}, {m}}, c, {3000.0}, o).ok());
    EXPECT_FALSE(rpmGrid(3000.0, 2000.0, 10.0).ok());
    EXPECT_FALSE(rpmGrid(2000.0, 3000.0, 0.0).ok());
    auto g = rpmGrid(2000.0, 3000.0, 250.0);
    ASSERT_TRUE(g.ok());
    EXPECT_EQ(g->size(), 5u);
}

TEST(StabilityLobes, ParallelEqualsSerialAndModesAdd)
{
    const ModalParameters m{0.40, 83.0, 30.1e6};
    CuttingConditions c;
    c.teeth = 4;
    c.ktNPerM2 = 0.98e9;
    c.krNPerM2 = 0.294e9;
    c.radialImmersion = 7.0 / 12.0;
    std::vector<double> rpms{2500, 2800, 3100, 3400, 3700};
    LobeOptions o;
    o.threads = 1;
    auto serial = stabilityLobes({{m}, {m}}, c, rpms, o);
    o.threads = 2;
    auto parallel = stabilityLobes({{m}, {m}}, c, rpms, o);
    ASSERT_TRUE(serial.ok() && parallel.ok());
    for (std::size_t i = 0; i < rpms.size(); ++i)
        EXPECT_NEAR((*serial)[i].limitDepthM, (*parallel)[i].limitDepthM, 1e-4 * (*serial)[i].limitDepthM);
    // Two identical modes in series with 2m, 2c, 2k each have the same compliance as one mode
    // (k, m, c) → identical multipliers.
    const ModalParameters half{0.80, 166.0, 60.2e6};
    auto one = monodromySpectralRadius({{m}, {m}}, c, 2800.0, 1e-3, 40);
    auto two = monodromySpectralRadius({{half, half}, {half, half}}, c, 2800.0, 1e-3, 40);
    ASSERT_TRUE(one.ok() && two.ok());
    EXPECT_NEAR(*one, *two, 1e-9);
}

TEST(MachiningJson, EmptyModeListIsARigidDirection)
{
    // The one-direction benchmark (Insperger–Stépán): flexible in x only.
    auto t = parseToolJson(R"({"modes_x":[{"mass_kg":0.03993,"damping_Ns_per_m":2.0,"stiffness_N_per_m":1.34e6}],
                               "modes_y":[]})",
                           "src.json");
    ASSERT_TRUE(t.ok()) << t.error().detail;
    EXPECT_EQ(t->modesX.size(), 1u);
    EXPECT_TRUE(t->modesY.empty());
    // Rigid in both directions leaves nothing to compute; a list that is not a list is still an error.
    expectError(parseToolJson(R"({"modes_x":[],"modes_y":[]})", "src.json").error(), ErrorCode::BadInput,
                "at least one mode");
    expectError(parseToolJson(R"({"modes_x":[],"modes_y":{"mass_kg":1}})", "src.json").error(), ErrorCode::BadInput,
                "modes_y");
}
