// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/RegisterMap.h"
#include "core/sim/AxisParameters.h"

#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace axistune;
using namespace axistune::device;

namespace {

std::string mapText()
{
    std::ifstream f(std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/drives/axistune-sim.json");
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

} // namespace

TEST(RegisterMap, CommittedMapCarriesEveryDriveParameterOfTheCatalogue)
{
    auto m = loadRegisterMap("axistune-sim");
    ASSERT_TRUE(m.ok()) << m.error().detail;
    for (const auto kind : {sim::AxisKind::Linear, sim::AxisKind::Rotary}) {
        const std::string k = kind == sim::AxisKind::Linear ? "linear" : "rotary";
        int count = 0;
        for (const auto& meta : sim::axisParameterMetas(kind)) {
            if (sim::isPlantParameter(meta.key))
                continue;
            ++count;
            const auto* p = m->parameter(meta.key);
            ASSERT_NE(p, nullptr) << meta.key;
            EXPECT_TRUE(p->availableOn(k)) << meta.key;
            EXPECT_EQ(p->meta.siUnit, meta.siUnit) << meta.key;
            EXPECT_EQ(p->meta.minSi, meta.minSi) << meta.key;
            EXPECT_EQ(p->meta.maxSi, meta.maxSi) << meta.key;
            EXPECT_EQ(p->meta.writable, meta.writable) << meta.key;
            EXPECT_EQ(p->meta.writableDuringTest, meta.writableDuringTest) << meta.key;
            EXPECT_EQ(p->meta.integer, meta.integer) << meta.key;
        }
        int available = 0;
        for (const auto& p : m->parameters)
            available += p.availableOn(k) ? 1 : 0;
        EXPECT_EQ(available, count) << k; // nothing on the map that the axis does not have
    }
    EXPECT_FALSE(m->parameter("lostmotion.A")->availableOn("rotary"));
    EXPECT_EQ(m->wordOrder, WordOrder::HighWordFirst);
    EXPECT_LE(m->field("trace.window").count, 125);
}

TEST(RegisterMap, EncodingsFollowIeee754AndTheWordOrder)
{
    std::uint16_t w[4];
    encodeF32(1.0f, WordOrder::HighWordFirst, w); // 1.0f = 0x3F800000
    EXPECT_EQ(w[0], 0x3F80);
    EXPECT_EQ(w[1], 0x0000);
    encodeF32(-2.5f, WordOrder::LowWordFirst, w); // -2.5f = 0xC0200000
    EXPECT_EQ(w[0], 0x0000);
    EXPECT_EQ(w[1], 0xC020);
    EXPECT_EQ(decodeF32(w, WordOrder::LowWordFirst), -2.5f);
    encodeF64(1.0, WordOrder::HighWordFirst, w); // 1.0 = 0x3FF0000000000000
    EXPECT_EQ(w[0], 0x3FF0);
    EXPECT_EQ(w[3], 0x0000);
    encodeF64(0.1, WordOrder::LowWordFirst, w); // 0.1 = 0x3FB999999999999A
    EXPECT_EQ(w[0], 0x999A);
    EXPECT_EQ(w[3], 0x3FB9);
    EXPECT_EQ(decodeF64(w, WordOrder::LowWordFirst), 0.1);
    encodeU32(0x12345678u, WordOrder::HighWordFirst, w);
    EXPECT_EQ(w[0], 0x1234);
    EXPECT_EQ(w[1], 0x5678);
    std::uint16_t s[3];
    encodeString("ABC", 3, s);
    EXPECT_EQ(s[0], 0x4142); // 'A' in the high byte
    EXPECT_EQ(s[1], 0x4300);
    EXPECT_EQ(s[2], 0x0000);
    EXPECT_EQ(decodeString(s, 3), "ABC");
}

TEST(RegisterMap, OverlapsMissingFieldsAndOversizedWindowsAreNamed)
{
    auto j = nlohmann::json::parse(mapText());
    {
        auto bad = j;
        bad["parameters"][1]["address"] = bad["parameters"][0]["address"];
        auto m = parseRegisterMap(bad.dump(), "bad.json");
        ASSERT_FALSE(m.ok());
        EXPECT_NE(m.error().detail.find("bad.json"), std::string::npos);
        EXPECT_NE(m.error().detail.find("used by both"), std::string::npos) << m.error().detail;
    }
    {
        auto bad = j;
        bad["fields"].erase("heartbeat.counter");
        auto m = parseRegisterMap(bad.dump(), "bad.json");
        ASSERT_FALSE(m.ok());
        EXPECT_NE(m.error().detail.find("'heartbeat.counter' is missing"), std::string::npos) << m.error().detail;
    }
    {
        auto bad = j;
        bad["fields"]["trace.window"]["count"] = 126;
        auto m = parseRegisterMap(bad.dump(), "bad.json");
        ASSERT_FALSE(m.ok());
        EXPECT_NE(m.error().detail.find("trace.window"), std::string::npos) << m.error().detail;
    }
    {
        auto bad = j;
        bad["fields"]["status.torque"]["type"] = "f16";
        auto m = parseRegisterMap(bad.dump(), "bad.json");
        ASSERT_FALSE(m.ok());
        EXPECT_NE(m.error().detail.find("status.torque"), std::string::npos) << m.error().detail;
    }
}
