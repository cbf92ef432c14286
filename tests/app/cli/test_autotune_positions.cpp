// SPDX-License-Identifier: GPL-3.0-or-later
// End to end, issue 18 item 4: `axistune-cli autotune --positions 3` on sim:long-axis, whose first resonance falls
// from about 219 Hz to 137 Hz over the travel (tests/core/sim/test_long_axis.cpp). Afterwards an ordinary
// `capture --test frf --at X` (the same hold-and-jog the tuner uses to move, device/MoveTo.h) with the applied
// parameters (--set: the embedded drive starts from its preset in every process) measures the loop at every
// position the tuner reports; the margins of L = T/(1-T) from dsp::loopMargins on that capture (independent of the
// tuner's prediction) are at least issue 18's 45 deg / 6 dB and within 3 deg / 1 dB of final.positions[] (issue 18,
// as for one position). A tune at one end alone (N = 1, `autotune --at`) keeps the margins there and violates them
// at the other end (the test shows it). The standard style (40 Hz required crossover): the notch step tries the notch
// designs for a moving resonance (core/autotune/AutoTunePositionsNotches.h) on every position's measured plant; on
// long-axis no notch at all gives the widest worst-case bandwidth (the collocated mode's peak keeps its phase away
// from -180 deg at every position), so the margins also hold between the measured positions (tested at +-0.375 m).
#include "core/dsp/LoopAnalysis.h"
#include "core/io/FrfCsv.h"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/app/cli/CliRunner.h"
#include "tests/app/cli/SimDriveProcess.h"

using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {

constexpr double kPm = 45.0, kGm = 6.0; // issue 18
// The outer positions of `--positions 3` on long-axis: its travel window 0.75 m less the move's servo lag v/K_p, v =
// 0.5 m/s the jog speed of a move (docs/drive-seam.md "Moving to a position") and K_p = 30 1/s the preset's position
// gain (resources/machines/long-axis.json).
constexpr double kLongAxisEnd = 0.75 - 0.5 / 30.0;

struct LoopFigures {
    double pm = NAN, gm = NAN;
};

/// Margins of the open velocity loop of a captured closed-loop FRF file (valid lines only).
LoopFigures marginsOfCapture(const std::string& path)
{
    LoopFigures out;
    auto t = axistune::io::readFrfCsvFile(path);
    EXPECT_TRUE(t.ok()) << path;
    if (!t.ok())
        return out;
    const auto l = axistune::dsp::openLoopFromClosedLoop(*t, axistune::dsp::LoopMeasurement::Complementary);
    axistune::dsp::FrequencyResponse valid;
    for (std::size_t i = 0; i < l.size(); ++i)
        if (l.valid[i] && t->valid[i])
            valid.push(l.freqHz[i], l.h[i], l.coherence[i], true);
    const auto m = axistune::dsp::loopMargins(valid);
    out.pm = m.phaseMarginDeg;
    out.gm = m.gainMarginDb;
    return out;
}

std::string setOptions(const nlohmann::json& params)
{
    std::string s;
    for (const auto& [k, v] : params.items())
        s += " --set " + k + "=" + nlohmann::json(v.get<double>()).dump();
    return s;
}

/// The ordinary capture the tests measure with, at position x, with `sets`, on `connect`.
LoopFigures captureAt(const std::filesystem::path& dir, double x, const std::string& sets,
                      const std::string& connect = "sim:long-axis")
{
    const auto out = (dir / "at.csv").string();
    const auto r = runCli("capture --connect " + connect + " --axis X --at " + nlohmann::json(x).dump() +
                          " --test frf --method multisine --fmin 20 --fmax 3900 --spacing-hz 10 --adaptive "
                          "--time-budget 5 --amplitude-pct 10" +
                          sets + " --out " + out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return marginsOfCapture(out);
}

} // namespace

TEST(AutotunePositions, LongAxisThreePositionsKeepTheMarginsAtEveryPositionMeasuredAfterwards)
{
    const auto dir = makeTempDir("autotune-positions");
    const auto result = (dir / "result.json").string();
    const auto r = runCli("autotune --connect sim:long-axis --axis X --positions 3 --out " + result);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(readFileText(result));
    ASSERT_EQ(j["outcome"], "applied") << j.value("reason", "");
    const auto& fin = j["final"];
    ASSERT_TRUE(fin.contains("positions"));
    ASSERT_EQ(fin["positions"].size(), 3u);
    // Spread over the drive's travel window of the preset, +-0.75 m (resources/machines/long-axis.json), inset from
    // its ends by the move's servo lag v/K_p (docs/tuning.md "Over the travel").
    const double expected[] = {-kLongAxisEnd, 0.0, kLongAxisEnd};
    ASSERT_TRUE(j.contains("resonance_map"));
    ASSERT_EQ(j["resonance_map"].size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(fin["positions"][i]["position"].get<double>(), expected[i], 1e-9);
        EXPECT_NEAR(j["resonance_map"][i]["position"].get<double>(), expected[i], 1e-9);
        ASSERT_TRUE(j["resonance_map"][i]["frequency_Hz"].is_number()) << j["resonance_map"].dump();
    }
    // The map shows the fall of issue 18 (at least 25 % from one end to the other).
    EXPECT_LE(j["resonance_map"][2]["frequency_Hz"].get<double>(),
              0.75 * j["resonance_map"][0]["frequency_Hz"].get<double>());
    // The worst position is what `final` reports at the top.
    double worstPm = 1e9;
    for (const auto& p : fin["positions"])
        worstPm = std::min(worstPm, p["phase_margin_deg"].get<double>());
    EXPECT_DOUBLE_EQ(fin["phase_margin_deg"].get<double>(), worstPm);
    // The standard style's required 40 Hz crossover is met: the worst position's re-measured closed velocity loop
    // is at least that wide (docs/tuning.md "Styles").
    EXPECT_GE(fin["velocity_bandwidth_Hz"].get<double>(), 40.0);
    // The notch step names the design it chose among every design it tried, with the rule.
    bool notchStep = false;
    for (const auto& s : j["steps"])
        if (s["name"] == "notches") {
            notchStep = true;
            EXPECT_TRUE(s["chosen"]["design"].is_string()) << s["chosen"].dump();
            EXPECT_EQ(s["measured"]["designs"].size(), 22u);
            EXPECT_NE(s["rule"].get<std::string>().find("chosen: '"), std::string::npos) << s["rule"];
        }
    EXPECT_TRUE(notchStep);

    const std::string sets = setOptions(fin["parameters"]);
    for (const auto& p : fin["positions"]) {
        const double x = p["position"].get<double>();
        const auto m = captureAt(dir, x, sets);
        std::cout << "long-axis --positions 3, at " << x << " m: measured PM " << m.pm << " deg, GM " << m.gm
                  << " dB; final " << p["phase_margin_deg"] << " deg, " << p["gain_margin_dB"] << " dB\n";
        EXPECT_GE(m.pm, kPm) << x;
        EXPECT_GE(m.gm, kGm) << x;
        EXPECT_NEAR(m.pm, p["phase_margin_deg"].get<double>(), 3.0) << x;
        EXPECT_NEAR(m.gm, p["gain_margin_dB"].get<double>(), 1.0) << x;
    }
    // Between the measured positions, where nothing was measured by the tuner: the margins hold there too with the
    // design it chose (none of its notches is tied to a resonance frequency that moves).
    for (const double x : {-0.375, 0.375}) {
        const auto m = captureAt(dir, x, sets);
        std::cout << "long-axis --positions 3, between the positions at " << x << " m: measured PM " << m.pm
                  << " deg, GM " << m.gm << " dB\n";
        EXPECT_GE(m.pm, kPm) << x;
        EXPECT_GE(m.gm, kGm) << x;
    }
    std::filesystem::remove_all(dir);
}

// Over Modbus: axistune-simdrive checks the measured table position against its travel window while a test runs and
// stops a jog that leaves it (docs/modbus.md). With the positions on the window's ends a move overshot them by about
// 19 um and the server stopped it ("left the travel window"); inset by the move's servo lag v/K_p (16.7 mm) the run
// completes. The server's window is set to the preset's 0.75 m (its default is 0.5 m). The server keeps the applied
// parameters, so the ordinary captures afterwards measure the tuned loop at each position without --set.
TEST(AutotunePositions, LongAxisThreePositionsOverModbusStayInsideTheServersTravelWindow)
{
    axistune::testing::SimDrive srv("--preset long-axis --travel-limit 0.75");
    ASSERT_GT(srv.port(), 0);
    const std::string uri = "modbus://127.0.0.1:" + std::to_string(srv.port());
    const auto dir = makeTempDir("autotune-positions-modbus");
    const auto result = (dir / "result.json").string();
    const auto r = runCli("autotune --connect " + uri + " --axis X --positions 3 --out " + result);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(readFileText(result));
    ASSERT_EQ(j["outcome"], "applied") << j.value("reason", "");
    const auto& fin = j["final"];
    ASSERT_EQ(fin["positions"].size(), 3u);
    const double expected[] = {-kLongAxisEnd, 0.0, kLongAxisEnd};
    for (std::size_t i = 0; i < 3; ++i) {
        const auto& p = fin["positions"][i];
        const double x = p["position"].get<double>();
        EXPECT_NEAR(x, expected[i], 1e-9);
        // The margins the run re-measured at every position, and an ordinary capture there afterwards.
        EXPECT_GE(p["phase_margin_deg"].get<double>(), kPm) << x;
        EXPECT_GE(p["gain_margin_dB"].get<double>(), kGm) << x;
        const auto m = captureAt(dir, x, "", uri);
        std::cout << "long-axis over Modbus --positions 3, at " << x << " m: measured PM " << m.pm << " deg, GM "
                  << m.gm << " dB; final " << p["phase_margin_deg"] << " deg, " << p["gain_margin_dB"] << " dB\n";
        EXPECT_GE(m.pm, kPm) << x;
        EXPECT_GE(m.gm, kGm) << x;
        EXPECT_NEAR(m.pm, p["phase_margin_deg"].get<double>(), 3.0) << x;
        EXPECT_NEAR(m.gm, p["gain_margin_dB"].get<double>(), 1.0) << x;
    }
    std::filesystem::remove_all(dir);
}

TEST(AutotunePositions, LongAxisTuneAtOneEndAloneViolatesTheMarginsAtTheOtherEnd)
{
    const auto dir = makeTempDir("autotune-one-end");
    const auto result = (dir / "result.json").string();
    const auto r = runCli("autotune --connect sim:long-axis --axis X --at -0.75 --out " + result);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(readFileText(result));
    ASSERT_EQ(j["outcome"], "applied") << j.value("reason", "");
    EXPECT_NEAR(j["at"]["position"].get<double>(), -0.75, 1e-9);
    const std::string sets = setOptions(j["final"]["parameters"]);
    const auto here = captureAt(dir, -0.75, sets);
    const auto there = captureAt(dir, 0.75, sets);
    std::cout << "long-axis tuned at -0.75 m alone: at -0.75 m PM " << here.pm << " deg, GM " << here.gm
              << " dB; at +0.75 m PM " << there.pm << " deg, GM " << there.gm << " dB\n";
    // Where it was tuned, the margins hold; at the other end they do not.
    EXPECT_GE(here.pm, kPm);
    EXPECT_GE(here.gm, kGm);
    EXPECT_TRUE(!(there.pm >= kPm) || !(there.gm >= kGm)) << there.pm << " deg, " << there.gm << " dB";
    std::filesystem::remove_all(dir);
}

TEST(AutotunePositions, RefusalsAndBadOptions)
{
    const auto dir = makeTempDir("autotune-positions-bad");
    const auto result = (dir / "result.json").string();
    // A rotary axis without a travel window: the drive cannot choose positions within it (nothing moved, exit 2).
    auto r = runCli("autotune --connect sim:two-inertia --axis A --positions 3 --out " + result);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("no finite travel window"), std::string::npos) << r.err;
    r = runCli("autotune --connect sim:long-axis --axis X --positions 0 --out " + result);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--positions: must be >= 1"), std::string::npos) << r.err;
    r = runCli("autotune --connect sim:long-axis --axis X --positions 3 --at 0.1 --out " + result);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("exclude each other"), std::string::npos) << r.err;
    r = runCli("autotune --connect sim:long-axis --axis X --positions 3 --amplitudes 5,10,20 --out " + result);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--amplitudes: it is for one position"), std::string::npos) << r.err;
    r = runCli("capture --connect sim:long-axis --axis X --at 0.9 --test hold --out " + (dir / "h.csv").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("outside the drive's travel window"), std::string::npos) << r.err;
    // The stiff style's 80 Hz crossover puts the 220 ... 136 Hz resonance within a factor 3 of it: refused with that
    // reason (exit 4), the parameters restored. (No notch design reaching the crossover at every position is refused
    // too: tests/core/autotune/test_autotune_positions.cpp, a velocity loop at 1 kHz.)
    r = runCli("autotune --connect sim:long-axis --axis X --positions 3 --style stiff --out " + result);
    EXPECT_EQ(r.exitCode, 4) << r.err;
    const auto j = nlohmann::json::parse(readFileText(result));
    EXPECT_EQ(j["outcome"], "refused");
    EXPECT_NE(j["reason"].get<std::string>().find("resonance too close to the required bandwidth"), std::string::npos)
        << j["reason"];
    EXPECT_TRUE(j["parameters_restored"].get<bool>());
    std::filesystem::remove_all(dir);
}
