// SPDX-License-Identifier: GPL-3.0-or-later
// End-to-end tests of the machining subcommands: lobes, spindle-speed, cutting-force, chatter-detect.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "tests/NumberText.h"
#include "tests/app/cli/CliRunner.h"

using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {

const std::string kSamples = std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/";

void writeFile(const std::filesystem::path& p, const std::string& text)
{
    std::ofstream f(p);
    f << text;
}

}  // namespace

TEST(CliMachining, LobesWritesCsvWithReferenceValues)
{
    const auto dir = makeTempDir("lobes");
    const auto out = dir / "lobes.csv";
    const auto r = runCli("lobes --tool " + kSamples + "tool-table1.json --cut " + kSamples +
                          "cut-table1.json --rpm-min 2800 --rpm-max 2955 --rpm-step 155 --steps-per-period 80 --out " +
                          out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::istringstream csv(readFileText(out));
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "rpm,limit_depth_m");
    std::vector<std::pair<double, double>> rows;
    while (std::getline(csv, line)) {
        const auto comma = line.find(',');
        rows.emplace_back(axistune::testutil::stod(line.substr(0, comma)),
                          axistune::testutil::stod(line.substr(comma + 1)));
    }
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_DOUBLE_EQ(rows[0].first, 2800.0);
    EXPECT_NEAR(rows[0].second, 0.958e-3, 0.03 * 0.958e-3);  // spec §5.1, k = 80
    EXPECT_DOUBLE_EQ(rows[1].first, 2955.0);
    EXPECT_NEAR(rows[1].second, 3.80e-3, 0.05 * 3.80e-3);
    std::filesystem::remove_all(dir);
}

TEST(CliMachining, LobesBadInputExitsWith2)
{
    const auto dir = makeTempDir("lobesbad");
    writeFile(dir / "tool.json", R"({"modes_x":[{"mass_kg":0.0,"damping_Ns_per_m":83,"stiffness_N_per_m":3e7}],
                                     "modes_y":[{"mass_kg":0.4,"damping_Ns_per_m":83,"stiffness_N_per_m":3e7}]})");
    writeFile(dir / "cut.json", R"({"teeth":4,"Kt_N_per_m2":0.98e9,"Kr_N_per_m2":0.294e9,"radial_immersion":1.5,"milling":"down"})");
    auto r = runCli("lobes --tool " + (dir / "tool.json").string() + " --cut " + kSamples +
                    "cut-table1.json --rpm-min 2800 --rpm-max 3000 --rpm-step 100");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("mass_kg"), std::string::npos) << r.err;
    r = runCli("lobes --tool " + kSamples + "tool-table1.json --cut " + (dir / "cut.json").string() +
               " --rpm-min 2800 --rpm-max 3000 --rpm-step 100");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("radial_immersion"), std::string::npos) << r.err;
    r = runCli("lobes --tool " + kSamples + "tool-table1.json --cut " + kSamples +
               "cut-table1.json --rpm-min 3000 --rpm-max 2800 --rpm-step 100");
    EXPECT_EQ(r.exitCode, 2);
    r = runCli("lobes --tool " + (dir / "missing.json").string() + " --cut " + kSamples +
               "cut-table1.json --rpm-min 2800 --rpm-max 3000 --rpm-step 100");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("missing.json"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}

TEST(CliMachining, SpindleSpeedPocketRule)
{
    const auto r = runCli("spindle-speed --chatter-hz 1390 --rpm 2800 --teeth 4");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // spec §6.3 Ch.4 exp: ratio 7.446 → ρ 7 → 2978.6 rpm.
    EXPECT_NE(r.out.find("\"lobe\": 7"), std::string::npos) << r.out;
    const auto p = r.out.find("\"pocket_rpm\": ");
    ASSERT_NE(p, std::string::npos);
    EXPECT_NEAR(axistune::testutil::stod(r.out.substr(p + 14)), 2978.57, 0.01);
    EXPECT_EQ(runCli("spindle-speed --chatter-hz -5 --rpm 2800 --teeth 4").exitCode, 2);
    EXPECT_EQ(runCli("spindle-speed --rpm 2800 --teeth 4").exitCode, 2);
}

TEST(CliMachining, SpindleSpeedWithLobeDiagram)
{
    const auto r = runCli("spindle-speed --chatter-hz 1581.5 --rpm 2800 --teeth 4 --tool " + kSamples +
                          "tool-table1.json --cut " + kSamples + "cut-table1.json --depth-mm 1.5");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto p = r.out.find("\"cost_optimal_rpm\": ");
    ASSERT_NE(p, std::string::npos) << r.out;
    EXPECT_NEAR(axistune::testutil::stod(r.out.substr(p + 20)), 2900.0, 30.0); // spec §5.1: argmin J_8 ≈ 2895–2905 rpm
}
