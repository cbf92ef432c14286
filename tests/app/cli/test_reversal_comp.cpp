// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli reversal-comp end to end (docs/ballbar.md "Reversal compensation"): on sim:vmc the
// reversal spike of both axes falls by at least 70 % in the verification circle, and the reduction the
// model predicted before writing is within 20 % of the one measured (both are ratios of spikes the
// ball-bar diagnostics read from a circle; the measured one comes from the drive's circles, the
// predicted one from the model's). Over Modbus (axistune-simdrive on a free loopback port) the pulse
// round-trips through the registers and the circles are those of the embedded drive.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/NumberText.h"
#include "tests/app/cli/CliRunner.h"
#include "tests/app/cli/SimDriveProcess.h"

using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {

/// Radial deviation column of a ball-bar CSV (after the header line).
std::vector<double> deviations(const std::string& path)
{
    std::vector<double> out;
    std::istringstream in(readFileText(path));
    std::string line;
    bool data = false;
    while (std::getline(in, line)) {
        if (line.rfind("angle_deg", 0) == 0) {
            data = true;
            continue;
        }
        if (!data || line.empty())
            continue;
        const auto comma = line.find(',');
        out.push_back(axistune::testutil::stod(line.substr(comma + 1)));
    }
    return out;
}

void expectReductions(const nlohmann::json& j)
{
    ASSERT_EQ(j["axes"].size(), 2u);
    EXPECT_TRUE(j["written"].get<bool>());
    for (const auto& a : j["axes"]) {
        const double measured = a["measured_reduction_pct"].get<double>();
        const double predicted = a["predicted_reduction_pct"].get<double>();
        EXPECT_GE(measured, 70.0) << a.dump();                                 // the requirement
        EXPECT_LE(std::abs(predicted - measured), 0.2 * measured) << a.dump(); // "as predicted within 20 %"
        // The spike before is the friction spike of vmc (about 7.5 µm at 1000 mm/min on R 50 mm).
        EXPECT_GT(a["measured_spike_um"].get<double>(), 3.0) << a.dump();
        EXPECT_GT(a["amplitude_m_per_s"].get<double>(), 0.0);
        EXPECT_GT(a["time_constant_ms"].get<double>(), 0.0);
    }
}

} // namespace

TEST(CliReversalComp, OnSimVmcTheSpikeFallsAsPredicted)
{
    const auto dir = makeTempDir("revcomp");
    const std::string out = (dir / "r.json").string(), ver = (dir / "v.csv").string();
    auto r = runCli("reversal-comp --connect sim:vmc --radius-mm 50 --feed-mm-min 1000 --verified-out " + ver +
                    " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(readFileText(out));
    expectReductions(j);
    // The verification circle written is a ball-bar CSV that `ballbar` reads, with no spike left above the
    // 30 % of the one before.
    r = runCli("ballbar --in " + ver);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto bb = nlohmann::json::parse(r.out);
    for (const auto& s : bb["reversal_spikes"])
        EXPECT_LT(std::abs(s["height_um"].get<double>()), 0.3 * 7.5) << s.dump();
    // A dry run writes nothing: the drive's circle afterwards (a new process) still has the spikes.
    r = runCli("reversal-comp --connect sim:vmc --dry-run");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_FALSE(nlohmann::json::parse(r.out)["written"].get<bool>());
    EXPECT_FALSE(nlohmann::json::parse(r.out)["axes"][0].contains("verified_spike_um"));
    std::filesystem::remove_all(dir);
}

TEST(CliReversalComp, AModelThatDoesNotShowTheSpikeOrBadOptionsAreRefused)
{
    // A model without friction shows no spike where the drive measured 7.5 µm: its prediction is refused.
    const auto dir = makeTempDir("revcomp-refused");
    std::string vmc = readFileText(std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/machines/vmc.json");
    const std::string friction = "\"plant.coulomb_motor\":          {\"value\": 0.305";
    const auto at = vmc.find(friction);
    ASSERT_NE(at, std::string::npos);
    vmc.replace(at, friction.size(), "\"plant.coulomb_motor\":          {\"value\": 0.0");
    const std::string model = (dir / "frictionless.json").string();
    std::ofstream(model) << vmc;
    auto r = runCli("reversal-comp --connect sim:vmc --model " + model);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("cannot be trusted"), std::string::npos) << r.err;
    r = runCli("reversal-comp --connect sim:vmc --model /nonexistent/machine.json");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--model '/nonexistent/machine.json'"), std::string::npos) << r.err;
    r = runCli("reversal-comp --connect sim:vmc --plane XA");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    r = runCli("reversal-comp --connect serial:/dev/ttyS0");
    EXPECT_EQ(r.exitCode, 2);
    // The registered connection forms (core/device/DriveRegistry.h).
    for (const char* form : {"expected sim:PRESET", "modbus://HOST:PORT", "replay:FILE"})
        EXPECT_NE(r.err.find(form), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}

TEST(CliReversalComp, OverModbusTheParametersRoundTripAndTheCirclesAreTheEmbeddedOnes)
{
    axistune::testing::SimDrive sd("--preset vmc");
    ASSERT_GT(sd.port(), 0) << sd.log();
    const auto dir = makeTempDir("revcomp-modbus");
    const std::string outM = (dir / "m.json").string(), outE = (dir / "e.json").string();
    const std::string befM = (dir / "bm.csv").string(), befE = (dir / "be.csv").string();
    const std::string verM = (dir / "vm.csv").string(), verE = (dir / "ve.csv").string();
    auto r = runCli("reversal-comp --connect " + sd.uri() + " --measured-out " + befM + " --verified-out " + verM +
                    " --out " + outM);
    ASSERT_EQ(r.exitCode, 0) << r.err << sd.log();
    const auto jm = nlohmann::json::parse(readFileText(outM));
    expectReductions(jm);
    // The pulse is in the drive's registers (f32: 7 significant digits).
    for (const auto& a : jm["axes"]) {
        const std::string axis = a["axis"];
        r = runCli("params --connect " + sd.uri() + " --axis " + axis +
                   " --get reversal.amplitude --get reversal.time_constant");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const auto p = nlohmann::json::parse(r.out)["parameters"];
        const double amp = a["amplitude_m_per_s"], tau = a["time_constant_ms"].get<double>() * 1e-3;
        EXPECT_NEAR(p["reversal.amplitude"].get<double>(), amp, 1e-6 * amp) << axis;
        EXPECT_NEAR(p["reversal.time_constant"].get<double>(), tau, 1e-6 * tau) << axis;
    }
    // The same on the embedded drive: the circle before is the same circle (to the CSV's 5 decimals), the
    // tuning the same pulse (to the f32 registers' 7 digits), the verification circle the same within
    // 0.05 µm sample by sample (measured: 0.013 µm at most, against spikes of 0.7-1 µm; the difference was
    // not traced further: the pulse and the parameters read over Modbus are f32-rounded).
    r = runCli("reversal-comp --connect sim:vmc --measured-out " + befE + " --verified-out " + verE + " --out " + outE);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto je = nlohmann::json::parse(readFileText(outE));
    const auto bm = deviations(befM), be = deviations(befE), vm = deviations(verM), ve = deviations(verE);
    ASSERT_EQ(bm.size(), be.size());
    ASSERT_EQ(vm.size(), ve.size());
    ASSERT_GT(bm.size(), 1000u);
    double worstBefore = 0.0, worstAfter = 0.0;
    for (std::size_t i = 0; i < bm.size(); ++i)
        worstBefore = std::max(worstBefore, std::abs(bm[i] - be[i]));
    for (std::size_t i = 0; i < vm.size(); ++i)
        worstAfter = std::max(worstAfter, std::abs(vm[i] - ve[i]));
    EXPECT_LT(worstBefore, 1e-4) << "um"; // the CSV's 5 decimals
    EXPECT_LT(worstAfter, 0.05) << "um";
    for (std::size_t k = 0; k < 2; ++k) {
        const auto& a = jm["axes"][k];
        const auto& b = je["axes"][k];
        EXPECT_NEAR(a["measured_spike_um"].get<double>(), b["measured_spike_um"].get<double>(), 1e-6);
        EXPECT_NEAR(a["amplitude_m_per_s"].get<double>(), b["amplitude_m_per_s"].get<double>(),
                    1e-6 * b["amplitude_m_per_s"].get<double>());
        EXPECT_NEAR(a["verified_spike_um"].get<double>(), b["verified_spike_um"].get<double>(), 0.05);
    }
    std::filesystem::remove_all(dir);
}
