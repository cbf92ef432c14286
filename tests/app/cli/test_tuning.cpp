// SPDX-License-Identifier: GPL-3.0-or-later
// End-to-end: axistune-cli current-loop and two-inertia (values from the spec checks C-A5 and §4.15).
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
#include <random>

using axistune::testing::makeTempDir;
using axistune::testing::runCli;

namespace {

const std::string kSamples = std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/";

// Table 5.1 torque → motor velocity with a 1.1 ms delay (5.1), (5.10), computed here independently.
std::complex<double> table51(double f)
{
    const double Jm = 0.00527, Jl = 0.0105, K = 200.0, C = 0.27, tau = 1.1e-3;
    const std::complex<double> s(0.0, 2.0 * std::numbers::pi * f);
    return std::exp(-s * tau) * (Jl * s * s + C * s + K) / (s * (Jm * Jl * s * s + C * (Jm + Jl) * s + K * (Jm + Jl)));
}

std::string writeFrf(const std::filesystem::path& dir, bool rigid)
{
    axistune::dsp::FrequencyResponse frf;
    std::mt19937 rng(7);
    std::normal_distribution<double> nd(0.0, 0.01);
    for (int i = 0; i < 2000; ++i) {
        const double f = std::pow(10.0, 3.0 * i / 1999.0);
        const std::complex<double> h = rigid ? 1.0 / (0.0157 * std::complex<double>(0.0, 2.0 * std::numbers::pi * f))
                                             : table51(f);
        frf.push(f, h * std::complex<double>(1.0 + nd(rng), nd(rng)), 0.98, true);
    }
    const auto path = (dir / (rigid ? "rigid.csv" : "two-inertia.csv")).string();
    EXPECT_TRUE(axistune::io::writeFrfCsvFile(path, frf).ok());
    return path;
}

}  // namespace

TEST(CliTuning, CurrentLoopRotarySample)
{
    const auto r = runCli("current-loop --motor " + kSamples + "motor-rotary.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_DOUBLE_EQ(j["alpha"].get<double>(), 1.0);
    EXPECT_NEAR(j["kp_V_per_A"].get<double>(), 35.7, 0.3);
    EXPECT_NEAR(j["ki_V_per_As"].get<double>(), 1.03e5, 0.03e5);
    EXPECT_NEAR(j["rise_time_s"].get<double>(), 98.3e-6, 1e-6);
    ASSERT_EQ(j["table"].size(), 11U);
    EXPECT_NEAR(j["table"][0]["rise_time_s"].get<double>(), 183.6e-6, 1e-6);
    EXPECT_TRUE(j["table"][0]["active_constraints"].is_array());
    // Schedule at I_max: factor 1 − δ = 0.76.
    const auto& last = j["schedule"].back();
    EXPECT_NEAR(last["current_A"].get<double>(), 56.57, 1e-9);
    EXPECT_NEAR(last["factor"].get<double>(), 0.76, 1e-12);
}

TEST(CliTuning, CurrentLoopLinearSampleWithPlots)
{
    const auto r = runCli("current-loop --motor " + kSamples + "motor-linear.json --alpha-step 0.2 --plots");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["alpha"].get<double>(), 0.8, 1e-12);
    EXPECT_NEAR(j["rise_time_s"].get<double>(), 120e-6, 1e-6);
    EXPECT_EQ(j["table"].size(), 6U);  // 0, 0.2, …, 1.0
    EXPECT_NEAR(j["schedule"].back()["factor"].get<double>(), 0.71, 1e-12);
    ASSERT_TRUE(j.contains("plots"));
    EXPECT_EQ(j["plots"]["stability_boundary"]["kp_V_per_A"].size(), 60U);
    EXPECT_EQ(j["plots"]["voltage_envelope"].size(), 6U);
    EXPECT_FALSE(j["plots"]["step_response"]["discrete_with_delay"].empty());
}

TEST(CliTuning, CurrentLoopBadMotorData)
{
    const auto dir = makeTempDir("tuning");
    auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return (dir / name).string();
    };
    const auto zeroL = write("zero.json", R"({"resistance_ohm":0.3,"inductance_q_H":0,"max_current_A":50,
        "max_voltage_V":200,"inductance_drop_at_max":0.2})");
    auto r = runCli("current-loop --motor " + zeroL);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("inductance_q_H"), std::string::npos) << r.err;
    const auto missing = write("missing.json", R"({"resistance_ohm":0.3,"inductance_q_H":0.002,"max_current_A":50,
        "inductance_drop_at_max":0.2})");
    r = runCli("current-loop --motor " + missing);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("max_voltage_V"), std::string::npos) << r.err;
    const auto emf = write("emf.json", R"({"resistance_ohm":0.3,"inductance_q_H":0.002,"max_current_A":50,
        "max_voltage_V":12,"inductance_drop_at_max":0.2,"back_emf_V_per_krpm":43.53})");
    r = runCli("current-loop --motor " + emf);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("back-EMF"), std::string::npos) << r.err;
    r = runCli("current-loop --motor " + (dir / "nonexistent.json").string());
    EXPECT_EQ(r.exitCode, 2);
    r = runCli("current-loop --motor " + kSamples + "motor-rotary.json --overshoot 0");
    EXPECT_EQ(r.exitCode, 2);
    std::filesystem::remove_all(dir);
}

TEST(CliTuning, TwoInertiaFitAndFilter)
{
    const auto dir = makeTempDir("tuning");
    const auto path = writeFrf(dir, false);
    auto r = runCli("two-inertia --frf " + path + " --mode full --tau-s 0.013");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["Jm_kgm2"].get<double>(), 0.00527, 0.03 * 0.00527);
    EXPECT_NEAR(j["JL_kgm2"].get<double>(), 0.0105, 0.03 * 0.0105);
    EXPECT_NEAR(j["K_Nm_per_rad"].get<double>(), 200.0, 6.0);
    EXPECT_NEAR(j["C_Nms_per_rad"].get<double>(), 0.27, 0.15 * 0.27);
    EXPECT_NEAR(j["delay_s"].get<double>(), 1.1e-3, 0.05e-3);
    EXPECT_NEAR(j["antiresonance_Hz"].get<double>(), 21.97, 0.3);
    EXPECT_NEAR(j["resonance_Hz"].get<double>(), 38.0, 0.3);
    EXPECT_NEAR(j["zeta_zero"].get<double>(), 0.0932, 0.015);
    EXPECT_NEAR(j["zeta_pole"].get<double>(), 0.161, 0.02);
    EXPECT_LT(j["fit_error"].get<double>(), 0.03);
    EXPECT_EQ(j["filter"]["mode"], "full");
    EXPECT_NEAR(j["filter"]["f0_Hz"].get<double>(), 21.97, 0.3);
    EXPECT_NEAR(j["filter"]["tau_s"].get<double>(), 0.013, 1e-12);
    EXPECT_NEAR(j["velocity_pi"]["kp_Nms_per_rad"].get<double>(), 11.24, 0.03 * 11.24);
    EXPECT_NEAR(j["position_gain"]["limit_per_s"].get<double>(), 33.0, 3.0);
    EXPECT_LT(j["load_error"]["with_filter_rad"].get<double>(), j["load_error"]["without_filter_rad"].get<double>());
    r = runCli("two-inertia --frf " + path + " --mode bogus");
    EXPECT_EQ(r.exitCode, 2);
    std::filesystem::remove_all(dir);
}

TEST(CliTuning, TwoInertiaWithoutResonanceIsBadInput)
{
    const auto dir = makeTempDir("tuning");
    const auto r = runCli("two-inertia --frf " + writeFrf(dir, true));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("anti-resonance"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}
