// SPDX-License-Identifier: GPL-3.0-or-later
// Guarded input reading (core/model/InputLimits.h, docs/robustness.md): files that are not regular
// files, oversized files, JSON numbers outside the double range or denormal, deep nesting, invalid
// UTF-8 in paths, and the NaN check at the JSON output boundary.
#include "core/model/InputLimits.h"
#include "core/model/ResultJson.h"
#include "tests/ScopedTempDir.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <sys/stat.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

using namespace axistune;
using namespace axistune::model;
namespace fs = std::filesystem;

namespace {

axistune::testing::ScopedTempDir tempDir()
{
    return axistune::testing::ScopedTempDir("inputlimits");
}

std::string errorOf(const Result<nlohmann::json>& r)
{
    return r ? std::string() : r.error().detail;
}

} // namespace

TEST(InputLimits, DisplayPathEscapesInvalidUtf8Only)
{
    EXPECT_EQ(displayPath("run/µm-ステージ.csv"), "run/µm-ステージ.csv");
    EXPECT_EQ(displayPath(std::string("a\xff"
                                      "b.csv")),
              "a\\xFFb.csv");
    EXPECT_EQ(displayPath(std::string("\xc3")), "\\xC3");                   // truncated sequence
    EXPECT_EQ(displayPath(std::string("\xc0\xaf")), "\\xC0\\xAF");          // overlong '/'
    EXPECT_EQ(displayPath(std::string("\xed\xa0\x80")), "\\xED\\xA0\\x80"); // surrogate
}

TEST(InputLimits, RefusesFifoDeviceDirectoryAndOversizedFiles)
{
    const auto dir = tempDir();
    const auto fifo = dir / "pipe.json";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto r = readInputFile(fifo.string()); // no writer: opening it would block for ever
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::BadInput);
    EXPECT_NE(r.error().detail.find(fifo.string() + ": is not a regular file"), std::string::npos) << r.error().detail;

    auto z = readInputFile("/dev/zero");
    ASSERT_FALSE(z);
    EXPECT_NE(z.error().detail.find("/dev/zero: is not a regular file"), std::string::npos);

    auto d = readInputFile(dir.string());
    ASSERT_FALSE(d);
    EXPECT_NE(d.error().detail.find("is a directory"), std::string::npos);

    auto missing = readInputFile((dir / "nope.csv").string());
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);

    const auto big = dir / "big.csv";
    std::ofstream(big) << "0123456789A"; // 11 bytes
    auto b = readInputFile(big.string(), 10);
    ASSERT_FALSE(b);
    EXPECT_NE(b.error().detail.find("11 bytes, larger than the limit of 10 bytes"), std::string::npos)
        << b.error().detail;
    auto ok = readInputFile(big.string(), 11);
    ASSERT_TRUE(ok);
    EXPECT_EQ(*ok, "0123456789A");
}

TEST(InputLimits, JsonNumbersOutsideTheDoubleRangeNameLineAndKey)
{
    const std::string e1 = errorOf(parseJsonText("{\n  \"a\": 1,\n  \"resistance_ohm\": 1e309\n}", "m.json"));
    EXPECT_NE(e1.find("m.json line 3, key 'resistance_ohm': number 1e309 does not fit a double"), std::string::npos)
        << e1;
    const std::string e2 = errorOf(parseJsonText("{\"x\": [1, -1e309]}", "m.json"));
    EXPECT_NE(e2.find("key 'x': number -1e309 does not fit a double"), std::string::npos) << e2;
    const std::string e3 = errorOf(parseJsonText("{\"r\": 5e-324}", "m.json"));
    EXPECT_NE(e3.find("key 'r': number 5e-324 is denormal"), std::string::npos) << e3;
    // Keys and strings that look like numbers are not numbers.
    EXPECT_TRUE(parseJsonText("{\"1e309\": \"5e-324\"}", "m.json"));
    // The extremes that fit are kept exactly.
    auto r = parseJsonText("{\"big\": 1.7976931348623157e308, \"small\": 2.2250738585072014e-308}", "m.json");
    ASSERT_TRUE(r) << errorOf(r);
    EXPECT_EQ((*r)["big"].get<double>(), std::numeric_limits<double>::max());
    EXPECT_EQ((*r)["small"].get<double>(), std::numeric_limits<double>::min());
}

TEST(InputLimits, JsonNestingDepthIsLimited)
{
    const std::string ok = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
    EXPECT_TRUE(parseJsonText(ok, "d.json"));
    const std::string deep = std::string(kMaxJsonDepth + 1, '[') + std::string(kMaxJsonDepth + 1, ']');
    const std::string e = errorOf(parseJsonText(deep, "d.json"));
    EXPECT_NE(e.find("d.json line 1: nested deeper than 32 levels"), std::string::npos) << e;
    const std::string huge = std::string(1'000'000, '[');
    EXPECT_FALSE(parseJsonText(huge, "d.json"));
}

TEST(InputLimits, JsonSyntaxErrorsNameTheLine)
{
    const std::string e = errorOf(parseJsonText("{\n\"a\": 1,\n\"b\": }\n", "s.json"));
    EXPECT_NE(e.find("s.json line 3: not valid JSON"), std::string::npos) << e;
    EXPECT_NE(errorOf(parseJsonText("", "s.json")).find("s.json"), std::string::npos);
    EXPECT_FALSE(parseJsonText(std::string("{\"a\": \"\xff\"}"), "s.json"));
}

TEST(InputLimits, ResultJsonRefusesNanAndInfAndSurvivesInvalidUtf8)
{
    nlohmann::json j{{"a", {1.0, std::nan("")}}};
    auto r = dumpResultJson(j);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::Internal);
    EXPECT_NE(r.error().detail.find("result value /a/1 is not a finite number"), std::string::npos) << r.error().detail;
    nlohmann::json k{{"x", {{"y", -std::numeric_limits<double>::infinity()}}}};
    auto rk = dumpResultJson(k);
    ASSERT_FALSE(rk);
    EXPECT_NE(rk.error().detail.find("/x/y"), std::string::npos);
    nlohmann::json p{{"path", std::string("a\xff.csv")}, {"v", 1.5}};
    auto rp = dumpResultJson(p, -1);
    ASSERT_TRUE(rp);
    EXPECT_EQ(*rp, "{\"path\":\"a\xEF\xBF\xBD.csv\",\"v\":1.5}");
}

TEST(InputLimits, ResultJsonRefusesNullAndPutNumberLeavesUndefinedValuesOut)
{
    nlohmann::json n{{"m", {{"gain_margin_dB", nullptr}}}};
    auto rn = dumpResultJson(n);
    ASSERT_FALSE(rn);
    EXPECT_EQ(rn.error().code, ErrorCode::Internal);
    EXPECT_NE(rn.error().detail.find("result value /m/gain_margin_dB is not a finite number (NaN, Inf or null)"),
              std::string::npos)
        << rn.error().detail;

    nlohmann::json j = nlohmann::json::object();
    putNumber(j, "a", 1.5, "unused");
    putNumber(j, "b", std::numeric_limits<double>::infinity(), "no crossover");
    putNumber(j, "c", std::nan(""), "singular");
    putNumbers(j, "v", {1.0, 2.0}, "unused");
    putNumbers(j, "w", {1.0, std::nan(""), -std::numeric_limits<double>::infinity()}, "|H| = 0");
    EXPECT_FALSE(j.contains("b"));
    EXPECT_EQ(j["undefined"]["b"], "no crossover");
    putNumber(j, "b", 3.0, "unused"); // defined later: present, and no longer in "undefined"
    EXPECT_EQ(j["a"], 1.5);
    EXPECT_EQ(j["b"], 3.0);
    EXPECT_FALSE(j["undefined"].contains("b"));
    EXPECT_FALSE(j.contains("c"));
    EXPECT_FALSE(j.contains("w"));
    EXPECT_EQ(j["v"], nlohmann::json({1.0, 2.0}));
    EXPECT_EQ(j["undefined"]["c"], "singular");
    EXPECT_EQ(j["undefined"]["w"], "|H| = 0 (first at index 1)");
    putUndefined(j, "a", "withdrawn");
    EXPECT_FALSE(j.contains("a"));
    EXPECT_EQ(j["undefined"]["a"], "withdrawn");
    EXPECT_TRUE(dumpResultJson(j));
}

TEST(InputLimits, CsvLineLimits)
{
    EXPECT_TRUE(checkCsvLine("c.csv", 7, kMaxLineBytes));
    const auto s = checkCsvLine("c.csv", 7, kMaxLineBytes + 1);
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().detail.find("c.csv line 7: longer than 65536 bytes"), std::string::npos);
    const auto r = checkCsvLine("c.csv", kMaxCsvLines + 1, 10);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().detail.find("more than 20000000 lines"), std::string::npos);
}
