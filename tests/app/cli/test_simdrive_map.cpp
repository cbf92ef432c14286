// SPDX-License-Identifier: GPL-3.0-or-later
// `axistune-simdrive --write-map` writes the committed register map: every field (address, type, size),
// every enumeration and every parameter (address, type, limits) of resources/drives/axistune-sim.json
// — so a field added to the file by hand and not to the generator (or the other way) is caught.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/app/cli/CliRunner.h"

namespace {

nlohmann::json readJson(const std::string& path)
{
    std::ifstream f(path);
    std::stringstream s;
    s << f.rdbuf();
    return nlohmann::json::parse(s.str());
}

} // namespace

TEST(SimdriveMap, WriteMapGivesTheCommittedMap)
{
    const axistune::testing::ScopedTempDir dir("map");
    const std::string out = (dir / "map.json").string();
    const std::string cmd = std::string(AXISTUNE_SIMDRIVE) + " --write-map " + out + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const auto gen = readJson(out);
    const auto committed = readJson(std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/drives/axistune-sim.json");
    ASSERT_EQ(gen["fields"].size(), committed["fields"].size());
    for (const auto& [name, f] : committed["fields"].items()) {
        ASSERT_TRUE(gen["fields"].contains(name)) << name;
        const auto& g = gen["fields"][name];
        EXPECT_EQ(g["address"], f["address"]) << name;
        EXPECT_EQ(g["type"], f["type"]) << name;
        EXPECT_EQ(g.value("count", 0), f.value("count", 0)) << name;
    }
    EXPECT_EQ(gen["enums"], committed["enums"]);
    ASSERT_EQ(gen["parameters"].size(), committed["parameters"].size());
    for (std::size_t i = 0; i < committed["parameters"].size(); ++i) {
        const auto& c = committed["parameters"][i];
        const auto& g = gen["parameters"][i];
        EXPECT_EQ(g["key"], c["key"]) << i;
        EXPECT_EQ(g["address"], c["address"]) << c["key"];
        EXPECT_EQ(g["type"], c["type"]) << c["key"];
        EXPECT_EQ(g["min"], c["min"]) << c["key"];
        EXPECT_EQ(g["max"], c["max"]) << c["key"];
    }
}
