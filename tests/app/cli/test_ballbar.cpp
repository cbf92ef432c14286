// SPDX-License-Identifier: GPL-3.0-or-later
// End-to-end: axistune-cli ballbar and lost-motion on the reference traces of tests/data/ballbar
// (made by make_traces.py with the injected values in injected.json) and on malformed files.
#include "core/model/Number.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/app/cli/CliRunner.h"

using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {

const std::string kData = std::string(AXISTUNE_TEST_DATA_DIR) + "/ballbar/";

nlohmann::json injected()
{
    return nlohmann::json::parse(readFileText(kData + "injected.json"));
}

void expectWithin(double got, double want, double floor, const char* what)
{
    EXPECT_NEAR(got, want, std::max(0.1 * std::abs(want), floor)) << what;
}

std::string writeTemp(const std::filesystem::path& dir, const std::string& name, const std::string& text)
{
    const auto p = dir / name;
    std::ofstream(p) << text;
    return p.string();
}

std::string circleRows(int n)
{
    std::string s = "angle_deg,deviation_um\n";
    for (int i = 0; i < n; ++i)
        s += axistune::model::formatShortest(i * 360.0 / n) + "," + axistune::model::formatShortest(0.1 * (i % 3)) +
             "\n";
    return s;
}

} // namespace

TEST(CliBallBar, DiagnosticsOfCwAndCcwMatchInjectedErrors)
{
    const auto inj = injected();
    auto r = runCli("ballbar --in " + kData + "ccw.csv --in " + kData + "cw.csv");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    expectWithin(j["center_um"]["x"], inj["offset_um"][0], 1.0, "centre x");
    expectWithin(j["center_um"]["y"], inj["offset_um"][1], 1.0, "centre y");
    expectWithin(j["radius_deviation_um"], inj["radius_deviation_um"], 1.0, "radius deviation");
    expectWithin(j["backlash_x_um"], inj["backlash_x_um"], 1.0, "backlash x");
    expectWithin(j["backlash_y_um"], inj["backlash_y_um"], 1.0, "backlash y");
    expectWithin(j["scale_mismatch_ppm"], inj["scale_mismatch_ppm"], 0.0, "scale mismatch");
    expectWithin(j["squareness_um_per_m"], inj["squareness_um_per_m"], 0.0, "squareness");
    expectWithin(j["servo_mismatch_ms"], inj["servo_mismatch_ms"], 0.0, "servo mismatch");
    expectWithin(j["cyclic_error_um"]["x"], inj["cyclic_x"]["amplitude_um"], 0.0, "cyclic x");
    expectWithin(j["cyclic_error_um"]["pitch_x_mm"], inj["cyclic_x"]["pitch_mm"], 0.0, "cyclic pitch x");
    EXPECT_TRUE(j["cyclic_error_um"]["detected_x"].get<bool>());
    EXPECT_FALSE(j["cyclic_error_um"]["detected_y"].get<bool>());
    ASSERT_EQ(j["reversal_spikes"].size(), 2u); // one per run, after the Y reversal at 90°
    for (const auto& s : j["reversal_spikes"]) {
        EXPECT_EQ(s["axis"], "y");
        expectWithin(s["height_um"], inj["spike_y"]["height_um"], 1.0, "spike height");
        expectWithin(s["width_deg"], inj["spike_y"]["width_deg"], 0.0, "spike width");
        EXPECT_NEAR(std::abs(s["angle_deg"].get<double>() - 90.0), 1.5, 0.2);
    }
    EXPECT_GT(j["circularity_um"].get<double>(), 5.0);
    for (const auto& f : j["findings"])
        EXPECT_FALSE(f["rule"].get<std::string>().empty());
}

TEST(CliBallBar, PartialArcRefusesFullCircleDiagnosticsWithReason)
{
    auto r = runCli("ballbar --in " + kData + "partial.csv");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    // Not defined: left out and named with the reason (docs/formats.md "Undefined values"), never null.
    EXPECT_FALSE(j.contains("circularity_um"));
    EXPECT_FALSE(j.contains("squareness_um_per_m"));
    EXPECT_EQ(j["undefined"]["circularity_um"], "no full-circle run among the traces");
    EXPECT_EQ(j["undefined"]["squareness_um_per_m"], "no full-circle run among the traces");
    EXPECT_EQ(r.out.find("null"), std::string::npos) << r.out;
    ASSERT_FALSE(j["refused"].empty());
    EXPECT_NE(
        j["refused"][0].get<std::string>().find("refused: requires a full 360° circle, but the trace is a partial arc"),
        std::string::npos);
    EXPECT_NEAR(j["backlash_x_um"].get<double>(), 2.0, 0.2);
}

TEST(CliLostMotion, ThreeTablePositionsGiveAAndB)
{
    const auto lm = injected()["lost_motion_y"];
    auto r = runCli("lost-motion --ballbar " + kData + "lm_y_c200.csv " + kData + "lm_y_c400.csv " + kData +
                    "lm_y_c600.csv --axis y --screw-offset-m 0.05");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    expectWithin(j["A_m_per_Nm"], lm["A_m_per_Nm"], 0.0, "A");
    expectWithin(j["B_per_Nm"], lm["B_per_Nm"], 0.0, "B");
    ASSERT_EQ(j["points"].size(), 6u);
    EXPECT_NEAR(j["points"][0]["x_m"].get<double>(), 0.05 + 0.2 + 0.1, 1e-9);
    EXPECT_NEAR(j["points"][0]["dT_Nm"].get<double>(), 0.60, 1e-12);
    EXPECT_LT(j["residual_rms_m"].get<double>(), 0.2e-6);
    EXPECT_EQ(j["method"], "least-squares");
    for (const auto& p : j["predictions"]) {
        EXPECT_LT(p["proposed_circularity_um"].get<double>(), 0.5 * p["measured_circularity_um"].get<double>());
        EXPECT_LT(p["proposed_cut_in_um"].get<double>(), 0.5);
        EXPECT_GT(p["conventional_cut_in_um"].get<double>(), 2.0);
    }
    EXPECT_LT(j["predicted_circularity_um"].get<double>(), 3.0);
}

TEST(CliLostMotion, ThesisXExampleBFreeAndCompensatedTrace)
{
    // X in the three-position files: lost motion 1.1 µm at ΔT = 0.61 N·m → A = 1.80 µm/(N·m) (thesis §4.4.1).
    const auto dir = makeTempDir("lm");
    const auto comp = (dir / "comp.csv").string();
    auto r = runCli("lost-motion --ballbar " + kData + "lm_y_c400.csv --axis x --b-free --compensated-out " + comp);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"], "b-free");
    expectWithin(j["A_m_per_Nm"].get<double>() * 1e6, 1.80, 0.0, "A_X");
    EXPECT_EQ(j["B_per_Nm"].get<double>(), 0.0);
    const std::string text = readFileText(comp);
    EXPECT_EQ(text.rfind("file_index,angle_deg,measured_um,proposed_um,conventional_um\n", 0), 0u);
    EXPECT_GT(std::count(text.begin(), text.end(), '\n'), 1440);
    std::filesystem::remove_all(dir);
}

TEST(CliBallBar, MalformedTracesExitWithCodeTwoAndAClearMessage)
{
    const auto dir = makeTempDir("bbbad");
    const std::string meta = "# radius_mm=100\n# feed_mm_min=1000\n# direction=ccw\n# dT_x_Nm=0.6\n";
    struct Case {
        std::string file, text, message;
    };
    const Case cases[] = {
        {"nometa.csv", circleRows(360), "no metadata"},
        {"one.csv", meta + "angle_deg,deviation_um\n0,1.0\n", "has 1 sample"},
        {"nan.csv", meta + "angle_deg,deviation_um\n0,1.0\n1,nan\n",
         "line 7, column 'deviation_um': not a finite number"},
        {"order.csv", meta + "angle_deg,deviation_um\n0,1\n2,1\n1,1\n3,1\n4,1\n5,1\n6,1\n7,1\n",
         "line 8, column 'angle_deg': angles must be strictly increasing"},
        {"noradius.csv", "# feed_mm_min=1000\n# direction=ccw\n" + circleRows(360), "metadata 'radius_mm' missing"},
    };
    for (const auto& c : cases) {
        const auto path = writeTemp(dir, c.file, c.text);
        for (const auto& cmd : {"ballbar --in " + path, "lost-motion --axis x --ballbar " + path}) {
            auto r = runCli(cmd);
            EXPECT_EQ(r.exitCode, 2) << cmd << "\n" << r.err;
            EXPECT_NE(r.err.find(c.file), std::string::npos) << r.err;
            EXPECT_NE(r.err.find(c.message), std::string::npos) << cmd << ": " << r.err;
            EXPECT_TRUE(r.out.empty()) << r.out;
        }
    }
    // A well-formed trace without the torque change cannot give A and B.
    const auto path =
        writeTemp(dir, "nodt.csv", "# radius_mm=100\n# feed_mm_min=1000\n# direction=ccw\n" + circleRows(720));
    auto r = runCli("lost-motion --axis y --ballbar " + path);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("metadata 'dT_y_Nm' missing"), std::string::npos) << r.err;
    auto missing = runCli("ballbar --in " + (dir / "does-not-exist.csv").string());
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("cannot open"), std::string::npos) << missing.err;
    std::filesystem::remove_all(dir);
}
