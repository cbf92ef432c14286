// SPDX-License-Identifier: GPL-3.0-or-later
// End-to-end: axistune-cli velocity-loop (issue 18 item 1) against tests/data/velocity_loop/reference.json (the
// independent computation of make_reference.py), on the simulated drive and on bad input.
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/app/cli/CliRunner.h"

using axistune::testing::runCli;

namespace {

const std::string kDir = std::string(AXISTUNE_TEST_DATA_DIR) + "/velocity_loop/";

nlohmann::json reference()
{
    std::ifstream f(kDir + "reference.json");
    return nlohmann::json::parse(f);
}

} // namespace

TEST(CliVelocityLoop, InertiaRuleMatchesTheReference)
{
    const auto ref = reference();
    const auto r = runCli("velocity-loop --loop-pi 0.8,75 --jm 1e-3");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const auto& c = ref["inertia"];
    EXPECT_EQ(j["method"], "inertia");
    EXPECT_NEAR(j["parameters"]["velocity.kp"].get<double>(), c["kp"].get<double>(), 1e-12 * c["kp"].get<double>());
    EXPECT_NEAR(j["parameters"]["velocity.ki"].get<double>(), c["ki"].get<double>(), 1e-12 * c["ki"].get<double>());
    EXPECT_FALSE(j["parameters"].contains("position.kp"));
    // Tolerances: the interpolation bound of the 300-line design grid (test_velocityloop_design.cpp).
    EXPECT_NEAR(j["proposal"]["margins"]["phase_margin_deg"].get<double>(),
                c["margins_after"]["phase_margin_deg"].get<double>(), 0.02);
    EXPECT_NEAR(j["proposal"]["margins"]["gain_margin_dB"].get<double>(),
                c["margins_after"]["gain_margin_dB"].get<double>(), 0.01);
    EXPECT_NEAR(j["proposal"]["margins_before"]["phase_margin_deg"].get<double>(),
                c["margins_before"]["phase_margin_deg"].get<double>(), 0.02);
    EXPECT_NE(j["proposal"]["rule"].get<std::string>().find("chapter 5"), std::string::npos);
    EXPECT_EQ(r.out.find("null"), std::string::npos);
}

TEST(CliVelocityLoop, MarginsRuleOnTheClosedLoopFile)
{
    const auto c = reference()["margins"];
    const auto r = runCli("velocity-loop --loop-pi 0.8,75 --jm 2e-3 --frf " + kDir +
                          "complementary.csv --crossover-hz 60 --phase-margin-deg 50 --with-position-gain");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"], "margins");
    EXPECT_EQ(j["margins_rule"]["frf"]["measurement"], "complementary");
    EXPECT_NEAR(j["parameters"]["velocity.kp"].get<double>(), c["kp"].get<double>(), 1e-9 * c["kp"].get<double>());
    EXPECT_NEAR(j["parameters"]["velocity.ki"].get<double>(), c["ki"].get<double>(), 1e-9 * c["ki"].get<double>());
    EXPECT_GT(j["parameters"]["position.kp"].get<double>(), 0.0);
}

TEST(CliVelocityLoop, ReadsTheRunningLoopFromTheDrive)
{
    // sim:vmc X runs velocity.kp 0.8, velocity.ki 75 (the reference's running PI): the margins before are the
    // reference's (same J_m and periods).
    const auto ref = reference();
    const auto r = runCli("velocity-loop --connect sim:vmc --axis X --jm 1e-3");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["running"]["velocity_kp_Nms_per_rad"].get<double>(), ref["running"]["kp"].get<double>());
    EXPECT_EQ(j["running"]["velocity_ki_Nm_per_rad"].get<double>(), ref["running"]["ki"].get<double>());
    EXPECT_NEAR(j["proposal"]["margins_before"]["phase_margin_deg"].get<double>(),
                ref["inertia"]["margins_before"]["phase_margin_deg"].get<double>(), 0.02);
}

TEST(CliVelocityLoop, BadInputExitsTwoWithTheReason)
{
    auto r = runCli("velocity-loop --jm 1e-3");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("running velocity PI"), std::string::npos) << r.err;
    r = runCli("velocity-loop --loop-pi 0.8,75");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("J_m"), std::string::npos) << r.err;
    r = runCli("velocity-loop --loop-pi 0.8,75 --jm 1e-3 --method fast");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--method"), std::string::npos) << r.err;
    // A file that does not say what it is.
    const auto dir = axistune::testing::makeTempDir("vl");
    {
        std::ofstream f(dir / "frf.csv");
        f << "f_Hz,re,im\n10,1,0\n20,0.5,0\n";
    }
    r = runCli("velocity-loop --loop-pi 0.8,75 --jm 1e-3 --frf " + (dir / "frf.csv").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("measurement"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("frf.csv"), std::string::npos) << r.err;
    // A crossover a PI cannot reach: refused with the reason, exit 2.
    r = runCli("velocity-loop --loop-pi 0.8,75 --jm 2e-3 --frf " + kDir +
               "plant_rigid.csv --crossover-hz 900 --phase-margin-deg 80");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("phase margin"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}

// pid-tune is for a position PID the NC closes: on a drive that closes its own loops (sim:) it is refused, naming why,
// with nothing moved or written; options outside their limits are refused naming the option (exit 2 each).
TEST(CliPidTuneRefusals, ADriveThatClosesItsOwnLoopsAndBadOptionsExitTwo)
{
    auto r = runCli("pid-tune --connect sim:vmc --axis X --amplitude-pct 5");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("PID the NC closes"), std::string::npos) << r.err;
    r = runCli("pid-tune --connect sim:vmc --axis X --amplitude-pct 5 --pm 90");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--pm"), std::string::npos) << r.err;
    r = runCli("pid-tune --connect sim:vmc --axis X --amplitude-pct 5 --gm 30");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--gm must lie in 3..20 dB"), std::string::npos) << r.err;
    r = runCli("pid-tune --connect sim:vmc --axis X --amplitude-pct 5 --fmin 100 --fmax 50");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("0 < --fmin < --fmax"), std::string::npos) << r.err;
    r = runCli("pid-tune --connect sim:vmc --axis X --amplitude-pct 5 --notch maybe");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--notch"), std::string::npos) << r.err;
    r = runCli("pid-tune --connect sim:vmc --axis X");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--amplitude"), std::string::npos) << r.err;
}
