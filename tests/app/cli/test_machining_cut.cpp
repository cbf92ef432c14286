// SPDX-License-Identifier: GPL-3.0-or-later
// End-to-end: simulate-cut → chatter-detect / cutting-force (issue 10 items 3 and 4).
// The cut points come from the semi-discretization lobes (independent of the time simulation):
//   axistune-cli lobes --tool resources/samples/tool-table1.json --cut resources/samples/cut-table1.json
//       --rpm-min 1000 --rpm-max 3500 --rpm-step 50 --steps-per-period 160
// gives 1.07 mm at 1500 rpm. Stable: 0.5 mm (0.47 × limit); chattering: 2.0 mm (1.9 × limit).
#include "core/model/Number.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "tests/NumberText.h"
#include "tests/app/cli/CliRunner.h"

using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {

const std::string kSamples = std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/";

std::string cutArgs(double depthM, const std::filesystem::path& out)
{
    return "simulate-cut --machine vmc --axis X --tool " + kSamples + "tool-table1.json --cut " + kSamples +
           "cut-table1.json --rpm 1500 --depth-m " + axistune::model::formatShortest(depthM) +
           " --duration-s 1.2 --seed 3 --out " + out.string();
}

/// Column `name` of a capture CSV (skips "# " metadata lines).
std::vector<double> column(const std::filesystem::path& p, const std::string& name)
{
    std::ifstream f(p);
    std::string line;
    std::vector<std::string> header;
    std::vector<double> out;
    int idx = -1;
    while (std::getline(f, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        std::stringstream ss(line);
        std::string cell;
        std::vector<std::string> cells;
        while (std::getline(ss, cell, ','))
            cells.push_back(cell);
        if (idx < 0) {
            for (std::size_t i = 0; i < cells.size(); ++i)
                if (cells[i] == name)
                    idx = static_cast<int>(i);
            if (idx < 0)
                return {};
            continue;
        }
        out.push_back(axistune::testutil::stod(cells.at(static_cast<std::size_t>(idx))));
    }
    return out;
}

double meanFrom(const std::vector<double>& v, std::size_t from)
{
    double s = 0;
    for (std::size_t i = from; i < v.size(); ++i)
        s += v[i];
    return s / static_cast<double>(v.size() - from);
}

} // namespace

TEST(CliMachiningCut, DetectorTellsStableFromChatter)
{
    const auto dir = makeTempDir("cut");
    const auto stable = dir / "stable.csv", chatter = dir / "chatter.csv";
    auto r1 = runCli(cutArgs(0.5e-3, stable));
    ASSERT_EQ(r1.exitCode, 0) << r1.err;
    auto r2 = runCli(cutArgs(2.0e-3, chatter));
    ASSERT_EQ(r2.exitCode, 0) << r2.err;

    // The first 0.15 s are an air cut (the tool enters at 0.2 s): they set the force-energy floor (CD-2 gate).
    const std::string gate = " --baseline-s 0.15";
    auto d1 = runCli("chatter-detect --in " + stable.string() + " --stage " + kSamples + "stage.json" + gate);
    ASSERT_EQ(d1.exitCode, 0) << d1.err;
    auto d2 = runCli("chatter-detect --in " + chatter.string() + " --stage " + kSamples + "stage.json" + gate);
    ASSERT_EQ(d2.exitCode, 0) << d2.err;
    const auto j1 = nlohmann::json::parse(d1.out), j2 = nlohmann::json::parse(d2.out);
    EXPECT_FALSE(j1["chatter"].get<bool>()) << d1.out;
    EXPECT_TRUE(j1["intervals"].empty());
    ASSERT_TRUE(j2["chatter"].get<bool>()) << d2.out;
    // Chatter begins after the tool enters the material (0.2 s) and lasts to the end of the trace; its
    // frequency is near the tool mode (1380.6 Hz), between the mode and the Nyquist frequency (2 kHz).
    double flagged = 0, fAtLongest = 0, longest = 0;
    for (const auto& iv : j2["intervals"]) {
        const double len = iv["end_s"].get<double>() - iv["start_s"].get<double>();
        flagged += len;
        EXPECT_GE(iv["start_s"].get<double>(), 0.2);
        if (len > longest) {
            longest = len;
            fAtLongest = iv["frequency_Hz"].get<double>();
        }
        EXPECT_GT(iv["score"].get<double>(), 0.0);
    }
    EXPECT_GT(flagged, 0.5);
    EXPECT_GT(fAtLongest, 1300.0);
    EXPECT_LT(fAtLongest, 1800.0);
    // Without --stage: the stage of the capture's simulated machine (vmc X), same answer.
    auto d3 = runCli("chatter-detect --in " + chatter.string() + gate);
    ASSERT_EQ(d3.exitCode, 0) << d3.err;
    EXPECT_TRUE(nlohmann::json::parse(d3.out)["chatter"].get<bool>());
    std::filesystem::remove_all(dir);
}

TEST(CliMachiningCut, CuttingForceRecoversTheMeanForce)
{
    const auto dir = makeTempDir("cutforce");
    const auto cap = dir / "stable.csv", force = dir / "force.csv";
    auto r1 = runCli(cutArgs(0.5e-3, cap));
    ASSERT_EQ(r1.exitCode, 0) << r1.err;
    // A cut at constant feed is no identification opportunity (no reversal; the feed ramp has a constant
    // acceleration, collinear with F_DC, spec §1.8): the observer runs with the nominal stage ("fixed").
    {
        std::ofstream f(dir / "stage.json");
        f << R"({"screw_lead_m_per_rev": 0.012, "torque_constant_Nm_per_A": 0.50911,
                "motor": {"inertia_kgm2": 0.0011818, "coulomb_Nm": 0.305}, "load": {"inertia_kgm2": 0.00102133},
                "rls": {"method": "fixed"}})";
    }
    auto r2 = runCli("cutting-force --in " + cap.string() + " --stage " + (dir / "stage.json").string() + " --out " +
                     force.string());
    ASSERT_EQ(r2.exitCode, 0) << r2.err;
    const auto est = column(force, "cutting_force_N");
    const auto truth = column(cap, "cutting_force_N");
    ASSERT_EQ(est.size(), truth.size());
    ASSERT_GT(est.size(), 4000u);
    // Mean over the last half (0.6–1.2 s: 60 tooth periods at 100 Hz, constant feed).
    const std::size_t from = est.size() / 2;
    const double meanEst = meanFrom(est, from), meanTrue = meanFrom(truth, from);
    // The static mean force: a f_z N/(2π) ∫ (K_t sin φ cos φ + K_r sin² φ) dφ over [acos(2r−1), π] = −6.26 N on the
    // tool, i.e. +6.26 N on the table. The 4 kHz trace samples a force with entry/exit steps (harmonics of
    // 100 Hz alias at 4 kHz): 3 %.
    const double r = 7.0 / 12.0, st = std::acos(2 * r - 1), en = std::numbers::pi;
    const double integral = 0.980e9 * 0.5 * (std::pow(std::sin(en), 2) - std::pow(std::sin(st), 2)) +
                            0.294e9 * (0.5 * (en - st) - 0.25 * (std::sin(2 * en) - std::sin(2 * st)));
    const double tool = 0.5e-3 * 0.1e-3 * 4 / (2 * std::numbers::pi) * integral;
    EXPECT_NEAR(meanTrue, -tool, 0.03 * std::abs(tool));
    // Observer error budget at constant feed: the motor-side Coulomb friction (0.305 N·m = 160 N at
    // R = 1.91 mm/rad, 25× the cutting force) is compensated with the stage value, which the simulator's tanh
    // smoothing (0.03 rad/s) reaches exactly at the 5.2 rad/s feed; the J and B terms average out at constant
    // velocity; what is left is the same 4 kHz sampling of T_M and of the trace force: 3 % of the mean.
    EXPECT_NEAR(meanEst, meanTrue, 0.03 * std::abs(meanTrue));
    std::filesystem::remove_all(dir);
}

TEST(CliMachiningCut, BadInputExitsWith2)
{
    const auto dir = makeTempDir("cutbad");
    auto r = runCli("simulate-cut --machine vmc --axis Q --tool " + kSamples + "tool-table1.json --cut " + kSamples +
                    "cut-table1.json --rpm 1500 --depth-m 1e-3 --out " + (dir / "x.csv").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--axis 'Q'"), std::string::npos) << r.err;
    r = runCli("simulate-cut --machine vmc --axis X --tool " + kSamples + "tool-table1.json --cut " + kSamples +
               "cut-table1.json --rpm -5 --depth-m 1e-3 --out " + (dir / "x.csv").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("spindle speed"), std::string::npos) << r.err;
    // A stage.json with a bad value names the file and the key.
    {
        std::ofstream f(dir / "stage.json");
        f << R"({"screw_lead_m_per_rev": 0.012, "torque_constant_Nm_per_A": 0.5, "motor": {"inertia_kgm2": -1}, "load": {"inertia_kgm2": 1}})";
    }
    {
        std::ofstream f(dir / "cap.csv");
        f << "t_s,current_A,motor_vel_rad_s,table_pos_m\n0,1,2,3\n0.001,1,2,3\n0.002,1,2,3\n";
    }
    r = runCli("cutting-force --in " + (dir / "cap.csv").string() + " --stage " + (dir / "stage.json").string() +
               " --out " + (dir / "f.csv").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("stage.json, motor, key 'inertia_kgm2'"), std::string::npos) << r.err;
    // A capture without the needed columns names the file and the column.
    {
        std::ofstream f(dir / "cap2.csv");
        f << "t_s,current_A\n0,1\n0.001,1\n0.002,1\n";
    }
    r = runCli("cutting-force --in " + (dir / "cap2.csv").string() + " --stage " + kSamples + "stage.json --out " +
               (dir / "f.csv").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("motor_vel_rad_s"), std::string::npos) << r.err;
    r = runCli("chatter-detect --in " + (dir / "cap2.csv").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("cap2.csv"), std::string::npos) << r.err;
    // A malformed number in a capture: the reader names the line and the column.
    {
        std::ofstream f(dir / "cap3.csv");
        f << "t_s,current_cmd_A,motor_pos_m,table_pos_m\n0,1,2,3\n0.001,x,2,3\n";
    }
    r = runCli("chatter-detect --in " + (dir / "cap3.csv").string() + " --stage " + kSamples + "stage.json");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("line 3"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}
