// SPDX-License-Identifier: GPL-3.0-or-later
// Machine profile JSON and parameter CSV: round trips and clear errors.
#include "core/io/Profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

using namespace axistune;
using namespace axistune::io;

namespace {

const std::string kSample = std::string(AXISTUNE_SOURCE_RESOURCE_DIR) + "/samples/vmc-profile.json";

std::string errorOf(const std::string& text)
{
    auto p = profileFromJson(nlohmann::json::parse(text), "p.json");
    return p.ok() ? std::string("accepted") : p.error().detail;
}

}  // namespace

TEST(Profile, SampleExportImportExportIsIdentical)
{
    auto p = readProfileFile(kSample);
    ASSERT_TRUE(p.ok()) << p.error().detail;
    const std::string first = profileToText(*p);
    auto again = profileFromJson(nlohmann::json::parse(first), "first");
    ASSERT_TRUE(again.ok()) << again.error().detail;
    EXPECT_EQ(profileToText(*again), first);
    // The committed sample is already in canonical form.
    EXPECT_EQ(*readTextFile(kSample), first);
}

TEST(Profile, SampleHasTheVmcAxesAndValues)
{
    auto p = readProfileFile(kSample);
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(p->name, "vmc");
    ASSERT_EQ(p->axes.size(), 3u);
    EXPECT_EQ(p->axes[0].name, "X");
    EXPECT_EQ(p->axes[2].name, "Z");
    // Values of the simulator preset resources/machines/vmc.json, converted to SI.
    const auto& x = p->axes[0].parameters;
    EXPECT_DOUBLE_EQ(x.at("current.kp"), 35.7);
    EXPECT_DOUBLE_EQ(x.at("current.ki"), 1.03e5);
    EXPECT_DOUBLE_EQ(x.at("current.period"), 62.5e-6);
    EXPECT_DOUBLE_EQ(x.at("velocity.period"), 250e-6);
    EXPECT_DOUBLE_EQ(x.at("position.period"), 1e-3);
    EXPECT_DOUBLE_EQ(x.at("position.kp"), 30.0);
    EXPECT_DOUBLE_EQ(x.at("lostmotion.A"), 1.80e-6);  // spec lost-motion §4.4.1: A_X = 1.80 um/Nm
    EXPECT_DOUBLE_EQ(p->axes[1].parameters.at("lostmotion.B"), 17e-6);  // 17 um/(Nm m) -> 1/Nm
    EXPECT_DOUBLE_EQ(p->axes[1].parameters.at("lostmotion.screw_offset"), 0.2);
    EXPECT_TRUE(p->axes[0].models.count("motor"));
}

TEST(Profile, ErrorsNameTheFileAndField)
{
    EXPECT_NE(errorOf(R"({"format":"other","version":1})").find("p.json: field 'format'"), std::string::npos);
    EXPECT_NE(errorOf(R"({"format":"axistune-profile","version":2,"machine":{"name":"m"},"axes":[]})")
                  .find("profile version 2 is not supported"),
              std::string::npos);
    const std::string head = R"({"format":"axistune-profile","version":1,"machine":{"name":"m"},"axes":)";
    EXPECT_NE(errorOf(head + R"([{"name":"X","parameters":{"velocity.kp":"fast"}}]})").find("p.json axes[0] (axis 'X'): parameter 'velocity.kp'"),
              std::string::npos);
    EXPECT_NE(errorOf(head + R"([{"name":"X"},{"name":"X"}]})").find("duplicate axis name 'X'"), std::string::npos);
    EXPECT_NE(errorOf(head + R"([{"name":"X","models":{"thermal":{}}}]})").find("unknown kind 'thermal'"), std::string::npos);
    EXPECT_NE(errorOf(head + R"([{"name":"X","paramters":{}}]})").find("unknown field 'paramters'"), std::string::npos);
    auto missing = readProfileFile("/nonexistent/p.json");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
}

TEST(Profile, CsvRoundTripIsExactForAwkwardDoubles)
{
    MachineProfile p;
    p.name = "m";
    p.axes.push_back({"X", {{"a", 0.1}, {"b", 1.0 / 3.0}, {"c", -2.5e-300}, {"d", 6.02214076e23}}, {}});
    p.axes.push_back({"Y", {{"a", std::nextafter(1.0, 2.0)}}, {}});
    const auto csv = parametersToCsv(p);
    auto back = parametersFromCsv(csv, "p.csv");
    ASSERT_TRUE(back.ok()) << back.error().detail;
    ASSERT_EQ(back->axes.size(), 2u);
    EXPECT_EQ(back->axes[0].parameters, p.axes[0].parameters);
    EXPECT_EQ(back->axes[1].parameters, p.axes[1].parameters);
    EXPECT_EQ(parametersToCsv(*back), csv);
}

TEST(Profile, CsvErrorsNameLineAndColumn)
{
    const std::string head = "# format=axistune-parameters\nmachine,axis,key,value\n";
    auto e1 = parametersFromCsv(head + "m,X,a,1\nm,X,b,NaN\n", "p.csv");
    ASSERT_FALSE(e1.ok());
    EXPECT_NE(
        e1.error().detail.find("p.csv line 4, column 'value': not a number ('NaN') (a finite SI number is needed)"),
        std::string::npos)
        << e1.error().detail;
    auto e2 = parametersFromCsv(head + "m,X,a,1\nn,X,b,2\n", "p.csv");
    ASSERT_FALSE(e2.ok());
    EXPECT_NE(e2.error().detail.find("line 4, column 'machine'"), std::string::npos) << e2.error().detail;
    auto e3 = parametersFromCsv("machine,axis,key,value\nm,X,a,1\n", "p.csv");
    ASSERT_FALSE(e3.ok());
    EXPECT_NE(e3.error().detail.find("format=axistune-parameters"), std::string::npos);
    auto e4 = parametersFromCsv(head + "m,X,a\n", "p.csv");
    ASSERT_FALSE(e4.ok());
    EXPECT_NE(e4.error().detail.find("line 3"), std::string::npos);
}
