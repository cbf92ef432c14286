// SPDX-License-Identifier: GPL-3.0-or-later
// NC export: the vmc sample in every format against committed files made by the independent
// renderer tests/data/nc/make_expected.py, values checked by hand, unmapped keys listed.
#include "core/io/NcExport.h"
#include "core/io/Profile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace axistune;
using namespace axistune::io;

namespace {

const std::string kResources = AXISTUNE_SOURCE_RESOURCE_DIR;
const std::string kData = std::string(AXISTUNE_TEST_DATA_DIR) + "/nc/";

MachineProfile sample()
{
    auto p = readProfileFile(kResources + "/samples/vmc-profile.json");
    EXPECT_TRUE(p.ok()) << (p.ok() ? "" : p.error().detail);
    return p.ok() ? *p : MachineProfile{};
}

std::string exportFamily(const std::string& family, std::vector<std::string>* unmapped = nullptr)
{
    auto map = readNcMapFile(kResources + "/nc/" + family + ".json");
    EXPECT_TRUE(map.ok()) << (map.ok() ? "" : map.error().detail);
    if (!map.ok())
        return {};
    auto out = exportNc(sample(), *map);
    EXPECT_TRUE(out.ok()) << (out.ok() ? "" : out.error().detail);
    if (unmapped && out.ok())
        *unmapped = out->unmapped;
    return out.ok() ? out->text : std::string();
}

}  // namespace

TEST(NcExport, EveryFormatMatchesTheCommittedFile)
{
    for (const std::string family : {"fanuc", "siemens", "heidenhain"})
        EXPECT_EQ(exportFamily(family), *readTextFile(kData + "vmc." + family + ".expected")) << family;
    EXPECT_EQ(parametersToCsv(sample()), *readTextFile(kData + "vmc.csv.expected"));
    EXPECT_EQ(profileToText(sample()), *readTextFile(kData + "vmc.json.expected"));
}

TEST(NcExport, HandCheckedValues)
{
    // position.kp = 30 1/s: FANUC 1825 in 0.01/s = 3000; Siemens/Heidenhain kv in (m/min)/mm =
    // 30 / (1000/60) = 1.8; notches at 800 Hz, depth 0.1 = 10 %.
    const auto fanuc = exportFamily("fanuc");
    EXPECT_NE(fanuc.find("\nN01825A1P3000A2P3000A3P3000\n"), std::string::npos);
    EXPECT_NE(fanuc.find("\nN02113A1P800A2P800A3P800\n"), std::string::npos);
    EXPECT_NE(fanuc.find("\nN02359A1P10A2P10A3P10\n"), std::string::npos);
    EXPECT_EQ(fanuc.rfind("%\n", 0), 0u);
    const auto siemens = exportFamily("siemens");
    EXPECT_NE(siemens.find("\n$MA_POSCTRL_GAIN[0,AX2]=1.8000\n"), std::string::npos);
    EXPECT_NE(siemens.find("\nDO3:p1460[0]=0.8000\n"  /* velocity.kp 0.8 Nm*s/rad */), std::string::npos);
    const auto heidenhain = exportFamily("heidenhain");
    EXPECT_NE(heidenhain.find("\nMP1810.0:1.800\n"), std::string::npos);
    EXPECT_NE(heidenhain.find("\nMP2550.2:800\n"), std::string::npos);
}

TEST(NcExport, UnmappedKeysAreListedNotDropped)
{
    std::vector<std::string> unmapped;
    const auto text = exportFamily("fanuc", &unmapped);
    EXPECT_NE(std::find(unmapped.begin(), unmapped.end(), "current.kp"), unmapped.end());
    EXPECT_NE(std::find(unmapped.begin(), unmapped.end(), "lostmotion.A"), unmapped.end());
    EXPECT_EQ(std::find(unmapped.begin(), unmapped.end(), "position.kp"), unmapped.end());
    for (const auto& k : unmapped)
        EXPECT_NE(text.find("UNMAPPED " + k + ": "), std::string::npos) << k;
    EXPECT_NE(text.find("(UNMAPPED lostmotion.A: X=1.8e-06, Y=7e-07, Z=1.8e-06)"), std::string::npos);
    // Every parameter of every axis is either mapped or listed.
    auto map = readNcMapFile(kResources + "/nc/fanuc.json");
    ASSERT_TRUE(map.ok());
    for (const auto& a : sample().axes) {
        for (const auto& [key, v] : a.parameters) {
            bool mapped = false;
            for (const auto& e : map->entries)
                mapped = mapped || e.key == key;
            EXPECT_TRUE(mapped || std::find(unmapped.begin(), unmapped.end(), key) != unmapped.end()) << key;
        }
    }
}

TEST(NcExport, EveryMapCarriesTheVerifyNotice)
{
    for (const std::string family : {"fanuc", "siemens", "heidenhain"}) {
        const auto text = exportFamily(family);
        EXPECT_NE(text.find("VERIFY: TEMPLATE MAP"), std::string::npos) << family;
    }
}

TEST(NcExport, ValueFormatting)
{
    NcMapEntry e{"lostmotion.backlash", "1851", "m", "um", 1.0, 0, "", ""};
    EXPECT_EQ(*formatNcValue(e, 12.5e-6), "13");  // half away from zero
    EXPECT_EQ(*formatNcValue(e, -12.5e-6), "-13");
    e.decimals = 3;
    EXPECT_EQ(*formatNcValue(e, -1e-12), "0.000");  // no "-0.000"
    e.decimals = 0;
    auto huge = formatNcValue(e, 1e6);  // 1e12 um does not fit a 32-bit NC integer
    ASSERT_FALSE(huge.ok());
    EXPECT_EQ(huge.error().code, ErrorCode::OutOfRange);
}

TEST(NcExport, BadMapsAreRefusedWithTheFieldNamed)
{
    auto base = nlohmann::json::parse(*readTextFile(kResources + "/nc/fanuc.json"));
    auto m1 = base;
    m1["parameters"][0]["unit"] = "Hz";  // 1/s -> Hz: not the same quantity token
    auto r1 = ncMapFromJson(m1, "x.json");
    ASSERT_FALSE(r1.ok());
    EXPECT_NE(r1.error().detail.find("x.json parameters[0] (position.kp): units '1/s' -> 'Hz'"), std::string::npos)
        << r1.error().detail;
    auto m2 = base;
    m2.erase("verify");
    EXPECT_FALSE(ncMapFromJson(m2, "x.json").ok());
    auto m3 = base;
    m3["layout"] = "diagonal";
    auto r3 = ncMapFromJson(m3, "x.json");
    ASSERT_FALSE(r3.ok());
    EXPECT_NE(r3.error().detail.find("'diagonal'"), std::string::npos);
}
