// SPDX-License-Identifier: GPL-3.0-or-later
// simulate-cut --avoid end to end (docs/chatter-avoidance.md): the summary JSON and the capture channels of an
// adaptive cut, and bad options refused with exit 2 and a message naming the option.
#include <filesystem>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/app/cli/CliRunner.h"

using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {
const std::string kSamples = std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/";
std::string base(const std::filesystem::path& dir, const std::string& tool = "tool-table1.json")
{
    return "simulate-cut --machine vmc --axis X --tool " + kSamples + tool + " --cut " + kSamples +
           "cut-table1.json --engage-s 0.1 --out " + (dir / "cut.csv").string() + " ";
}
} // namespace

TEST(CliChatterAvoidance, AdaptiveSummaryAndChannels)
{
    // Table 1 tool, a_e 7 mm, a_p 1.5 mm from 2800 rpm, accelerometer (Table 3): the first step is ρ = 7 from
    // the 1394.8 Hz chatter line (spec §5.1 [derived]) and the speed ends in the 2955–3000 rpm pocket.
    const auto dir = makeTempDir("avoid");
    const auto r = runCli(base(dir) + "--rpm 2800 --depth-m 1.5e-3 --duration-s 0.8 --avoid adaptive --sensor accel");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("avoid"), "adaptive");
    EXPECT_EQ(j.at("sensor"), "accelerometer");
    EXPECT_GE(j.at("final_spindle_rpm").get<double>(), 2955.0);
    EXPECT_LE(j.at("final_spindle_rpm").get<double>(), 3000.0);
    ASSERT_FALSE(j.at("steps").empty());
    EXPECT_EQ(j.at("steps")[0].at("rho").get<int>(), 7);
    EXPECT_TRUE(j.contains("onset_to_settled_s"));
    EXPECT_TRUE(j.at("triggered").get<bool>());
    EXPECT_TRUE(j.at("settled").get<bool>());
    const std::string csv = readFileText(dir / "cut.csv");
    for (const char* ch : {"spindle_speed_rpm", "spindle_speed_cmd_rpm", "chatter_frequency_Hz", "avoid_cost",
                           "avoid_power", "tool_accel_y_m_s2"})
        EXPECT_NE(csv.find(ch), std::string::npos) << ch;
    std::filesystem::remove_all(dir);
}

TEST(CliChatterAvoidance, DobRunWithTable4ThresholdReportsNoTrigger)
{
    // Same cut, DOB with Table 4 (σ_th 1e4 N²): the in-band force stays below 100 N, nothing triggers; the summary
    // says so with `triggered: false` and no onset (it used to fail writing a null onset).
    const auto dir = makeTempDir("avoiddob");
    const auto r = runCli(base(dir) + "--rpm 2800 --depth-m 1.5e-3 --duration-s 0.4 --avoid adaptive");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("sensor"), "dob");
    EXPECT_FALSE(j.at("triggered").get<bool>());
    EXPECT_FALSE(j.at("settled").get<bool>());
    EXPECT_FALSE(j.contains("onset_s"));
    EXPECT_TRUE(j.at("steps").empty());
    EXPECT_DOUBLE_EQ(j.at("final_spindle_rpm").get<double>(), 2800.0);
    std::filesystem::remove_all(dir);
}

TEST(CliChatterAvoidance, BadOptionsExit2WithTheOptionNamed)
{
    const auto dir = makeTempDir("avoidbad");
    const std::string b = base(dir) + "--depth-m 1e-3 --duration-s 0.2 ";
    struct Case {
        std::string args, mention;
    };
    const Case cases[] = {
        {"--avoid sometimes", "--avoid"},
        {"--avoid esc", "--esc-min-rpm"},                                                  // bounds are required
        {"--avoid esc --esc-start-s 0.1 --esc-min-rpm 2000 --esc-max-rpm 1000", "bounds"}, // min > max
        {"--avoid esc --esc-start-s 0.1 --esc-min-rpm 1000 --esc-max-rpm 3000 --esc-pc -1", "p_c"},
        {"--avoid esc --esc-min-rpm 1000 --esc-max-rpm 3000", "--esc-start-s"}, // default 5 s > duration
        {"--avoid adaptive --sensor laser", "--sensor"},
        {"--avoid adaptive --weights 1,0.5", "--weights"}, // multimode only
        {"--avoid multimode --weights 1,x", "--weights"},
        {"--avoid multimode --weights 0.5,1", "weights"}, // increasing
        {"--avoid multimode --nd 3", "N_d"},
        {"--avoid adaptive --sigma-th 0", "sigma_th"},
        {"--avoid none --esc-pc 3", "--esc-pc"},
        {"--avoid adaptive --sensor accel --dob-mass-kg 10", "--dob-mass-kg"},
        {"--avoid adaptive --dob-mass-kg -1", "M_tn"},
        {"--rpm 50000", "spindle"},                                        // beyond the spindle limit
        {"--avoid adaptive --sensor accel --tool-band on", "--tool-band"}, // adaptive + DOB only
        {"--avoid multimode --sensor dob --tool-band on", "--tool-band"},
        {"--avoid adaptive --tool-band maybe", "--tool-band"},
    };
    for (const auto& c : cases) {
        const auto r = runCli(b + (c.args.rfind("--rpm", 0) == 0 ? "" : "--rpm 2800 ") + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.mention), std::string::npos) << c.args << "\n" << r.err;
    }
    std::filesystem::remove_all(dir);
}
