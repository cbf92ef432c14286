// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli amplitude-map (core/autotune/AmplitudeMap.h; docs/cli.md "amplitude-map"): the map JSON of sim:vmc X at
// three amplitudes, and bad options exit 2. The flagging rule itself is checked against a linear reference run in
// tests/core/autotune/test_amplitudemap.cpp.
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/app/cli/CliRunner.h"

using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

TEST(AmplitudeMapCli, WritesTheMapOfVmcX)
{
    const auto dir = makeTempDir("amplitude-map");
    const auto out = (dir / "map.json").string();
    const auto r = runCli("amplitude-map --connect sim:vmc --axis X --amplitudes 5,10,20 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(readFileText(out));
    ASSERT_EQ(j["amplitudes"].size(), 3u);
    EXPECT_EQ(j["amplitudes"][2]["amplitude_pct"].get<double>(), 20.0);
    // 20 % of k_t*I_rated = 0.2 * 0.50911 N m/A * 15.30 A = 1.558 N m (the preset), the multisine's stated peak.
    EXPECT_NEAR(j["amplitudes"][2]["peak_Nm"].get<double>(), 0.2 * 0.50911 * 15.30, 1e-3);
    // Lines (m + 1/3) * 10 Hz from 20 Hz to 0.975 * 4 kHz (docs/multisine.md): 388.
    ASSERT_EQ(j["lines"].size(), 388u);
    EXPECT_NEAR(j["lines"][0]["f_Hz"].get<double>(), 23.333, 0.01);
    EXPECT_EQ(j["lines_compared"].get<int>(), 388);
    int flagged = 0;
    for (const auto& l : j["lines"]) {
        ASSERT_EQ(l["at"].size(), 3u);
        flagged += l["nonlinear"].get<bool>() ? 1 : 0;
        EXPECT_EQ(l["nonlinear"].get<bool>(), l["max_z"].get<double>() > j["threshold_sigmas"].get<double>());
    }
    EXPECT_EQ(flagged, j["nonlinear_lines"].get<int>());
    EXPECT_NEAR(j["nonlinear_fraction"].get<double>(), flagged / 388.0, 1e-12);
    EXPECT_NEAR(j["motion_time_s"].get<double>(), j["amplitudes"][0]["motion_time_s"].get<double>() * 3.0, 1e-9);
    std::filesystem::remove_all(dir);
}

TEST(AmplitudeMapCli, BadOptionsExit2)
{
    EXPECT_EQ(runCli("amplitude-map --connect sim:vmc --axis X --amplitudes 5,10").exitCode, 2);
    EXPECT_EQ(runCli("amplitude-map --connect sim:vmc --axis X --amplitudes 5,5,10").exitCode, 2);
    EXPECT_EQ(runCli("amplitude-map --connect sim:vmc --axis X --amplitudes 5,10,20 --periods 1").exitCode, 2);
    EXPECT_EQ(runCli("amplitude-map --connect sim:vmc --axis X --amplitudes 5,10,20 --fmin 100 --fmax 50").exitCode, 2);
    EXPECT_EQ(runCli("amplitude-map --connect sim:vmc --axis Q --amplitudes 5,10,20").exitCode, 2);
    // Above the embedded drive's FRF limit (50 % of rated torque): out of range, exit 2.
    EXPECT_EQ(runCli("amplitude-map --connect sim:vmc --axis X --amplitudes 5,10,80").exitCode, 2);
}
