// SPDX-License-Identifier: GPL-3.0-or-later
// Metadata of captures and FRFs (core/model/Metadata.h): numbers set in code stay doubles, a file's text comes
// back byte for byte, reading a number names the key, JSON keeps numbers as numbers. The expected texts are
// C's printf %.17g / shortest forms written out by hand; the suite also runs under de_DE.UTF-8 (scripts/test).
#include "core/model/Metadata.h"
#include "core/model/MetadataJson.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

namespace axistune::model {
namespace {

TEST(Metadata, ANumberSetInCodeStaysTheSameDouble)
{
    Metadata md;
    md.set("x", 0.1);
    md.set("fs_Hz", 4000.0);
    md.set("test", "step");
    ASSERT_TRUE(md.find("x")->isNumber());
    EXPECT_EQ(md.number("x").value(), 0.1); // exactly: no text in between
    EXPECT_EQ(md.text("x"), "0.1");         // the shortest text that reads back as 0.1 (%.17g gave 0.10000000000000001)
    EXPECT_EQ(md.text("fs_Hz"), "4000");
    EXPECT_FALSE(md.find("test")->isNumber());
    EXPECT_EQ(md.text("test"), "step");
    EXPECT_EQ(*md.find("test"), "step");
    md.set("x", "replaced");
    EXPECT_EQ(md.size(), 3u);
    EXPECT_EQ(md.text("x"), "replaced");
    EXPECT_TRUE(md.erase("x"));
    EXPECT_FALSE(md.erase("x"));
    EXPECT_FALSE(md.contains("x"));
    EXPECT_EQ(md.textOr("x", "none"), "none");
    EXPECT_FALSE(md.text("x").has_value());
}

TEST(Metadata, AFilesTextComesBackByteForByte)
{
    // Only the shortest spelling of a number becomes a number; every other text stays as it was written.
    struct Case {
        const char* text;
        bool number;
    };
    const Case cases[] = {{"100000", true},      {"1e+05", false}, {"1e+17", true},  {"-0", true},     {"4000", true},
                          {"0.5", true},         {"1e-06", true},  {"-12.25", true}, {"inf", true},    {"4.0", false},
                          {"4000.", false},      {"0012", false},  {"+5", false},    {"1E-06", false}, {"0.10", false},
                          {"3000:12000", false}, {"step", false},  {"4,0", false},   {"", false},      {" 5", false}};
    for (const auto& c : cases) {
        const auto v = MetadataValue::fromText(c.text);
        EXPECT_EQ(v.isNumber(), c.number) << c.text;
        EXPECT_EQ(v.text(), c.text);
    }
    // A text that spells a number still reads as one (a file written by hand, by another program).
    EXPECT_EQ(MetadataValue::fromText("4.0").number(), 4.0);
    EXPECT_EQ(MetadataValue::fromText("+5").number(), 5.0);
    EXPECT_FALSE(MetadataValue::fromText("4,0").number().has_value());
    // inf and nan are numbers (they come back as such) but not finite ones: number() has none.
    EXPECT_FALSE(MetadataValue::fromText("inf").number().has_value());
    EXPECT_FALSE(MetadataValue(std::numeric_limits<double>::quiet_NaN()).number().has_value());

    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> mant(-1.0, 1.0);
    std::uniform_int_distribution<int> ex(-60, 60);
    for (int i = 0; i < 2000; ++i) {
        const double x = std::ldexp(mant(rng), ex(rng));
        Metadata md;
        md.set("x", x);
        Metadata back;
        back.setFromText("x", md.text("x").value());
        EXPECT_TRUE(back.find("x")->isNumber());
        EXPECT_EQ(back.number("x").value(), x);
        EXPECT_EQ(back, md);
    }
}

TEST(Metadata, NumbersNameTheKey)
{
    Metadata md{{"fs_Hz", "4000"}, {"bad", "4,0"}, {"ticks", "8"}, {"big", std::numeric_limits<double>::infinity()}};
    EXPECT_EQ(md.number("fs_Hz").value(), 4000.0);
    const auto missing = md.number("current_period_s");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
    EXPECT_EQ(missing.error().detail, "metadata 'current_period_s' is missing");
    const auto bad = md.number("bad");
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().code, ErrorCode::BadInput);
    EXPECT_EQ(bad.error().detail, "metadata 'bad' is not a number ('4,0')");
    EXPECT_EQ(md.number("big").error().detail, "metadata 'big' is not a number ('inf')");
    EXPECT_FALSE(md.optionalNumber("none").value().has_value());
    EXPECT_FALSE(md.optionalNumber("bad"));
    EXPECT_EQ(md.integer("ticks").value(), 8);
    EXPECT_EQ(md.integer("none").error().detail, "metadata 'none' is missing");
    EXPECT_EQ(Metadata({{"n", "8.5"}}).integer("n").error().detail, "metadata 'n' is not a whole number ('8.5')");
    EXPECT_EQ(Metadata({{"n", 8.5}}).integer("n").error().detail, "metadata 'n' is not a whole number ('8.5')");
    Metadata counts;
    counts.set("n", 8); // an integer is a number
    counts.set("ticks", 1000000);
    EXPECT_EQ(counts.text("ticks"), "1000000"); // whole, as %.17g writes it (the shortest form is "1e+06")
    EXPECT_EQ(counts.integer("ticks").value(), 1000000);
    counts.set("size", std::size_t{3});
    EXPECT_EQ(counts.integer("n").value(), 8);
    EXPECT_EQ(counts.number("size").value(), 3.0);
    EXPECT_EQ(md.samplePeriodS().value(), 1.0 / 4000.0);
    EXPECT_FALSE(Metadata{}.samplePeriodS().value().has_value());
    EXPECT_EQ(Metadata({{"fs_Hz", -1.0}}).samplePeriodS().error().detail,
              "metadata 'fs_Hz' is not a positive number ('-1')");
    EXPECT_EQ(Metadata({{"fs_Hz", "4,0"}}).samplePeriodS().error().detail, "metadata 'fs_Hz' is not a number ('4,0')");
}

TEST(Metadata, JsonKeepsNumbersAsNumbers)
{
    Metadata md{{"fs_Hz", 4000.0},
                {"x", 0.1},
                {"test", "step"},
                {"id", "0012"},
                {"peak", std::numeric_limits<double>::infinity()}};
    const nlohmann::json j(md);
    EXPECT_TRUE(j.at("fs_Hz").is_number());
    EXPECT_EQ(j.dump(), R"({"fs_Hz":4000,"id":"0012","peak":"inf","test":"step","x":0.1})");
    EXPECT_EQ(j.at("fs_Hz").get<double>(), 4000.0);
    EXPECT_EQ(j.at("x").get<double>(), 0.1);
    EXPECT_EQ(j.at("test"), "step");
    EXPECT_EQ(j.at("id"), "0012");
    EXPECT_EQ(j.at("peak"), "inf"); // JSON has no infinity
    const auto back = metadataFromJson(nlohmann::json::parse(j.dump()));
    ASSERT_TRUE(back) << back.error().detail;
    EXPECT_EQ(*back, md);

    // Sessions stored by earlier versions hold every value as a string: numbers come back as numbers.
    const auto old = metadataFromJson(nlohmann::json{{"fs_Hz", "4000"}, {"test", "step"}});
    ASSERT_TRUE(old);
    EXPECT_TRUE(old->find("fs_Hz")->isNumber());
    EXPECT_EQ(old->number("fs_Hz").value(), 4000.0);

    const auto bad = metadataFromJson(nlohmann::json{{"fs_Hz", nlohmann::json::array({1, 2})}});
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().detail, "metadata 'fs_Hz' is neither a number nor a text");
    EXPECT_EQ(metadataFromJson(nlohmann::json::array()).error().detail, "metadata is not a JSON object");
}

} // namespace
} // namespace axistune::model
