// SPDX-License-Identifier: GPL-3.0-or-later
// End-to-end: axistune-cli notch on a dd-table-like velocity-loop FRF (modes 600 Hz, 1 kHz, 3.3 kHz,
// spec/current-loop-and-multisweep-frf.md §3.8) written here, existing notches, execution Nyquist,
// predicted FRF file, and bad input (exit 2 with file/line/field in the message).
#include "tests/app/cli/CliRunner.h"

#include "core/dsp/FrequencyResponse.h"
#include "core/io/FrfCsv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <numbers>

using axistune::testing::makeTempDir;
using axistune::testing::runCli;
using cd = std::complex<double>;

namespace {

constexpr double kPi = std::numbers::pi;
const double kModeHz[] = {600.0, 1000.0, 3300.0};

cd ddLoop(double f)
{
    const cd s(0.0, 2.0 * kPi * f);
    cd p = 1.0 / (1.238 * s);
    const double zeta[] = {0.03, 0.02, 0.015}, inertia[] = {4.0, 2.5, 2.0};
    for (int k = 0; k < 3; ++k) {
        const double w = 2.0 * kPi * kModeHz[k];
        p += s / (inertia[k] * (s * s + 2.0 * zeta[k] * w * s + w * w));
    }
    return (233.0 + 11700.0 / s) * p * std::exp(-s * 375e-6) / (1.0 + s / (2.0 * kPi * 1600.0));
}

std::string writeT(const std::filesystem::path& dir)
{
    axistune::dsp::FrequencyResponse frf;
    for (int i = 0; i < 800; ++i) {
        const double f = 10.0 * std::pow(390.0, i / 799.0);
        const cd l = ddLoop(f);
        frf.push(f, l / (1.0 + l), std::nan(""), true);
    }
    const auto path = (dir / "t.csv").string();
    EXPECT_TRUE(axistune::io::writeFrfCsvFile(path, frf).ok());
    return path;
}

std::string writeText(const std::filesystem::path& p, const std::string& text)
{
    std::ofstream(p) << text;
    return p.string();
}

}  // namespace

TEST(CliNotch, DdTableLoopThreeNotchesAndBetterMargins)
{
    const auto dir = makeTempDir("notch");
    const auto pred = (dir / "pred.csv").string();
    const auto r = runCli("notch --frf " + writeT(dir) + " --out-frf " + pred);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["resonances"].size(), 3U);
    ASSERT_EQ(j["notches"].size(), 3U);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(j["resonances"][k]["f_Hz"].get<double>(), kModeHz[k], 0.02 * kModeHz[k]);
        EXPECT_GT(j["resonances"][k]["peak_dB"].get<double>(), 6.0);
        EXPECT_GT(j["resonances"][k]["width_Hz"].get<double>(), 0.0);
    }
    for (const auto& n : j["notches"]) {
        EXPECT_LT(n["center_Hz"].get<double>(), 8000.0);
        EXPECT_GE(n["depth"].get<double>(), 0.0);
        EXPECT_LT(n["depth"].get<double>(), 1.0);
        EXPECT_GT(n["width_Hz"].get<double>(), 0.0);
    }
    EXPECT_GT(j["margins_after"]["gain_margin_dB"].get<double>(), j["margins_before"]["gain_margin_dB"].get<double>() + 3.0);
    EXPECT_LT(j["margins_after"]["peak_sensitivity_dB"].get<double>(), j["margins_before"]["peak_sensitivity_dB"].get<double>());
    EXPECT_GT(j["margins_after"]["phase_margin_deg"].get<double>(), j["margins_before"]["phase_margin_deg"].get<double>() - 2.0);
    // The predicted FRF file is the measured form T with the notches: check one point at the 1 kHz notch.
    auto p = axistune::io::readFrfCsvFile(pred);
    ASSERT_TRUE(p.ok()) << p.error().detail;
    EXPECT_EQ(p->size(), 800U);
}

TEST(CliNotch, ExistingNotchesKeptAndSlotsRespected)
{
    const auto dir = makeTempDir("notch");
    const auto ex = writeText(dir / "ex.json", R"([{"center_Hz": 1000, "width_Hz": 300, "depth": 0},
                                                   {"center_Hz": 250, "width_Hz": 50, "depth": 0.5},
                                                   {"center_Hz": 150, "width_Hz": 50, "depth": 0.5}])");
    const auto r = runCli("notch --frf " + writeT(dir) + " --existing " + ex);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["existing"].size(), 3U);
    EXPECT_EQ(j["existing"][0]["center_Hz"].get<double>(), 1000.0);
    EXPECT_EQ(j["existing"][0]["width_Hz"].get<double>(), 300.0);
    EXPECT_EQ(j["existing"][2]["depth"].get<double>(), 0.5);
    EXPECT_EQ(j["slots_free"].get<int>(), 1);
    ASSERT_EQ(j["notches"].size(), 1U);
    EXPECT_EQ(j["notches"][0]["slot"].get<int>(), 4);
    EXPECT_EQ(j["skipped"].size(), 2U);
}

TEST(CliNotch, NothingAtOrAboveTheExecutionNyquist)
{
    const auto dir = makeTempDir("notch");
    const auto r = runCli("notch --frf " + writeT(dir) + " --exec-rate-hz 4000 --max 4");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["resonances"].size(), 3U);
    ASSERT_EQ(j["notches"].size(), 2U);
    for (const auto& n : j["notches"])
        EXPECT_LT(n["center_Hz"].get<double>(), 2000.0);
    ASSERT_EQ(j["skipped"].size(), 1U);
    EXPECT_NEAR(j["skipped"][0]["f_Hz"].get<double>(), 3300.0, 66.0);

    const auto m1 = nlohmann::json::parse(runCli("notch --frf " + writeT(dir) + " --max 1").out);
    EXPECT_EQ(m1["notches"].size(), 1U);
}

TEST(CliNotch, BadInputExitsTwoWithFileLineField)
{
    const auto dir = makeTempDir("notch");
    const auto frf = writeT(dir);
    const auto notNumber = writeText(dir / "bad.csv", "f_Hz,re,im\n10,0.5,0.1\n20,abc,0.1\n");
    auto r = runCli("notch --frf " + notNumber);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("bad.csv"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("line 3"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("re"), std::string::npos) << r.err;

    const auto noCol = writeText(dir / "nocol.csv", "f_Hz,re\n10,0.5\n");
    r = runCli("notch --frf " + noCol);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("nocol.csv"), std::string::npos) << r.err;

    const auto decreasing = writeText(dir / "dec.csv", "f_Hz,re,im\n20,0.5,0.1\n10,0.5,0.1\n");
    r = runCli("notch --frf " + decreasing);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("dec.csv"), std::string::npos) << r.err;

    r = runCli("notch --frf " + (dir / "missing.csv").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;

    const auto few = writeText(dir / "few.csv", "f_Hz,re,im\n10,0.5,0.1\n20,0.5,0.1\n");
    r = runCli("notch --frf " + few);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("usable points"), std::string::npos) << r.err;

    const auto exMissing = writeText(dir / "ex1.json", R"([{"center_Hz": 1000, "depth": 0}])");
    r = runCli("notch --frf " + frf + " --existing " + exMissing);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("ex1.json"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("element 0"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("width_Hz"), std::string::npos) << r.err;

    const auto exAbove = writeText(dir / "ex2.json", R"([{"center_Hz": 9000, "width_Hz": 300, "depth": 0}])");
    r = runCli("notch --frf " + frf + " --existing " + exAbove);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("ex2.json"), std::string::npos) << r.err;

    const auto exText = writeText(dir / "ex3.json", R"([{"center_Hz": "1k", "width_Hz": 300, "depth": 0}])");
    r = runCli("notch --frf " + frf + " --existing " + exText);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("center_Hz"), std::string::npos) << r.err;

    const auto exTooMany = writeText(dir / "ex4.json", R"([{"center_Hz": 100, "width_Hz": 30, "depth": 0},
        {"center_Hz": 200, "width_Hz": 30, "depth": 0}, {"center_Hz": 300, "width_Hz": 30, "depth": 0},
        {"center_Hz": 400, "width_Hz": 30, "depth": 0}, {"center_Hz": 500, "width_Hz": 30, "depth": 0}])");
    r = runCli("notch --frf " + frf + " --existing " + exTooMany);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("slots"), std::string::npos) << r.err;

    EXPECT_EQ(runCli("notch --frf " + frf + " --max -2").exitCode, 2);
    EXPECT_EQ(runCli("notch --frf " + frf + " --exec-rate-hz 0").exitCode, 2);
    EXPECT_EQ(runCli("notch --frf " + frf + " --loop closed").exitCode, 2);
}
