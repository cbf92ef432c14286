// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli identify end to end on the EMPS records (shared/data/real): the result file against
// the independent reference (tests/data/ident/emps_reference.py, 0.5 %), the validation on the
// pulses record (2 % of the reference's), units, and exit 2 with the reason for bad input.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/app/cli/CliRunner.h"

using axistune::testing::runCli;

namespace {

const std::string kReal = AXISTUNE_REAL_DATA_DIR;
const std::string kData = AXISTUNE_TEST_DATA_DIR;

std::string empsArgs()
{
    return "identify --in " + kReal +
           "/emps_DATA_EMPS.csv --position q_motor --position-unit m --force u_voltage "
           "--force-scale 35.15065188";
}

nlohmann::json reference()
{
    std::ifstream f(kData + "/ident/emps_reference.json");
    return nlohmann::json::parse(f);
}

} // namespace

TEST(CliIdentify, EmpsResultAndValidationAgreeWithTheReference)
{
    ASSERT_TRUE(std::filesystem::exists(kReal + "/emps_DATA_EMPS.csv")) << kReal << ": real data missing";
    const auto r = runCli(empsArgs() + " --asymmetric --validate " + kReal +
                          "/emps_DATA_EMPS_PULSES.csv --reference q_ref "
                          "--extra pulses_N --controller " +
                          kData + "/ident/emps_controller.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const auto ref = reference();
    const char* keys[4] = {"inertia", "viscous", "coulomb", "offset"};
    for (int i = 0; i < 4; ++i) {
        const double expected = ref["symmetric"]["theta"][i].get<double>();
        EXPECT_NEAR(j[keys[i]]["value"].get<double>(), expected, 0.005 * std::abs(expected)) << keys[i];
        const double sd = ref["symmetric"]["std"][i].get<double>();
        EXPECT_NEAR(j[keys[i]]["std"].get<double>(), sd, 0.005 * sd) << keys[i];
    }
    EXPECT_EQ(j["units"]["inertia"], "kg");
    EXPECT_EQ(j["units"]["viscous"], "N*s/m");
    EXPECT_EQ(j["units"]["coulomb"], "N");
    EXPECT_NEAR(j["condition_number"].get<double>(), ref["symmetric"]["condition_number"].get<double>(),
                0.005 * ref["symmetric"]["condition_number"].get<double>());
    EXPECT_NEAR(j["asymmetric"]["coulomb_negative"]["value"].get<double>(), ref["asymmetric"]["theta"][4].get<double>(),
                0.005 * ref["asymmetric"]["theta"][4].get<double>());
    ASSERT_EQ(j["validation"].size(), 1u);
    const auto v = j["validation"][0];
    const auto rv = ref["validation"]["identified"];
    for (const auto& [mine, theirs] :
         {std::pair{"position_error_rms", "position_error_rms_m"},
          std::pair{"position_error_pct_of_motion_rms", "position_error_pct_of_motion_rms"},
          std::pair{"benchmark_rel_err_position_pct", "benchmark_rel_err_position_pct"},
          std::pair{"benchmark_rel_err_force_pct", "benchmark_rel_err_force_pct"}}) {
        EXPECT_NEAR(v[mine].get<double>(), rv[theirs].get<double>(), 0.02 * rv[theirs].get<double>()) << mine;
    }
}

TEST(CliIdentify, ControllerFromOptionsGivesTheSameValidation)
{
    const auto a = runCli(empsArgs() + " --validate " + kReal +
                          "/emps_DATA_EMPS_PULSES.csv --reference q_ref --extra pulses_N "
                          "--controller " +
                          kData + "/ident/emps_controller.json");
    const auto b = runCli(empsArgs() + " --validate " + kReal +
                          "/emps_DATA_EMPS_PULSES.csv --reference q_ref --extra pulses_N "
                          "--kp 160.18 --kv 243.45 --saturation 10 --delay 0");
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_EQ(nlohmann::json::parse(a.out)["validation"][0]["position_error_rms"],
              nlohmann::json::parse(b.out)["validation"][0]["position_error_rms"]);
}

TEST(CliIdentify, BadInputExitsTwoWithTheReason)
{
    auto r = runCli("identify --in " + kReal + "/emps_DATA_EMPS.csv --position q_motor --force u_voltage");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("give the position unit"), std::string::npos) << r.err;

    r = runCli(empsArgs() + " --validate " + kReal + "/emps_DATA_EMPS_PULSES.csv --reference q_ref");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--validate needs the record's controller"), std::string::npos) << r.err;

    r = runCli("identify --in " + kReal + "/emps_DATA_EMPS.csv --position q_motor --position-unit m --force torque");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("no column 'torque'"), std::string::npos) << r.err;

    // Time stamps with ±24 ns of jitter are refused when the tolerance is tighter than that.
    r = runCli(empsArgs() + " --time-tolerance 1e-6");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("not uniformly sampled"), std::string::npos) << r.err;

    // Only the first second (no reversal yet): refused, not fitted.
    const auto dir = axistune::testing::makeTempDir("ident");
    {
        std::ifstream in(kReal + "/emps_DATA_EMPS.csv");
        std::ofstream out(dir / "short.csv");
        std::string line;
        int rows = 0;
        while (std::getline(in, line) && rows < 700) {
            out << line << '\n';
            rows += line.empty() || line[0] == '#' ? 0 : 1;
        }
    }
    r = runCli("identify --in " + (dir / "short.csv").string() +
               " --position q_motor --position-unit m --force u_voltage");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("refused"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}
