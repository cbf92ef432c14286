// SPDX-License-Identifier: GPL-3.0-or-later
// lobes --tool-frf-x/--tool-frf-y: tool modes fitted to a receptance FRF CSV give the same lobes as the
// equivalent tool.json. The FRFs are written here analytically, H = Σ 1/(k − mω² + jcω) in m/N.
#include "core/model/Number.h"

#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "tests/NumberText.h"
#include "tests/app/cli/CliRunner.h"

using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {

const std::string kSamples = std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/";

struct Mode {
    double m, c, k;
};

void writeFrfCsv(const std::filesystem::path& p, const std::vector<Mode>& modes)
{
    std::ofstream f(p);
    f << "f_Hz,re,im,mag_dB,phase_deg,coherence,valid\n";
    const auto g = [](double v) { return axistune::model::formatNumber(v, 17); };
    for (int i = 0; i < 400; ++i) {
        const double hz = 500.0 * std::pow(6.0, i / 399.0);
        const double w = 2.0 * std::numbers::pi * hz;
        std::complex<double> h = 0.0;
        for (const auto& m : modes)
            h += 1.0 / std::complex<double>(m.k - m.m * w * w, m.c * w);
        f << g(hz) << ',' << g(h.real()) << ',' << g(h.imag()) << ',' << g(20.0 * std::log10(std::abs(h))) << ','
          << g(std::arg(h) * 180.0 / std::numbers::pi) << ",,1\n";
    }
}

void writeFile(const std::filesystem::path& p, const std::string& text)
{
    std::ofstream f(p);
    f << text;
}

// The limit depth at the first row of a lobes CSV.
double firstLimit(const std::string& csvText)
{
    std::istringstream csv(csvText);
    std::string line;
    std::getline(csv, line);
    std::getline(csv, line);
    return axistune::testutil::stod(line.substr(line.find(',') + 1));
}

}  // namespace

TEST(CliLobesToolFrf, FittedTable1ToolMatchesToolJsonAt2800Rpm)
{
    const auto dir = makeTempDir("lobesfrf");
    writeFrfCsv(dir / "x.csv", {{0.40, 83.0, 30.1e6}});
    writeFrfCsv(dir / "y.csv", {{0.40, 83.0, 30.1e6}});
    const std::string common = " --cut " + kSamples + "cut-table1.json --rpm-min 2800 --rpm-max 2800 --rpm-step 10 --steps-per-period 40";
    auto ref = runCli("lobes --tool " + kSamples + "tool-table1.json" + common + " --out " + (dir / "ref.csv").string());
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    auto fit = runCli("lobes --tool-frf-x " + (dir / "x.csv").string() + " --tool-frf-y " + (dir / "y.csv").string() + common +
                      " --out " + (dir / "fit.csv").string());
    ASSERT_EQ(fit.exitCode, 0) << fit.err;
    const double a = firstLimit(readFileText(dir / "ref.csv"));
    const double b = firstLimit(readFileText(dir / "fit.csv"));
    EXPECT_GT(a, 0.5e-3);  // spec §5.1: 0.958 mm at k = 80
    EXPECT_NEAR(b, a, 0.01 * a);
    EXPECT_NE(fit.err.find("mass_kg="), std::string::npos) << fit.err;
    std::filesystem::remove_all(dir);
}

TEST(CliLobesToolFrf, TwoModesMatchToolJson)
{
    const auto dir = makeTempDir("lobesfrf2");
    writeFrfCsv(dir / "x.csv", {{0.40, 83.0, 30.1e6}, {0.15, 60.0, 50e6}});
    writeFrfCsv(dir / "y.csv", {{0.40, 83.0, 30.1e6}, {0.15, 60.0, 50e6}});
    writeFrfCsv(dir / "y1.csv", {{0.40, 83.0, 30.1e6}});
    writeFile(dir / "tool.json", R"({"modes_x":[{"mass_kg":0.4,"damping_Ns_per_m":83,"stiffness_N_per_m":30.1e6},
                                                {"mass_kg":0.15,"damping_Ns_per_m":60,"stiffness_N_per_m":50e6}],
                                     "modes_y":[{"mass_kg":0.4,"damping_Ns_per_m":83,"stiffness_N_per_m":30.1e6},
                                                {"mass_kg":0.15,"damping_Ns_per_m":60,"stiffness_N_per_m":50e6}]})");
    const std::string common = " --cut " + kSamples + "cut-table1.json --rpm-min 2800 --rpm-max 2800 --rpm-step 10";
    auto ref = runCli("lobes --tool " + (dir / "tool.json").string() + common + " --out " + (dir / "ref.csv").string());
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    auto fit = runCli("lobes --modes 2 --tool-frf-x " + (dir / "x.csv").string() + " --tool-frf-y " + (dir / "y.csv").string() +
                      common + " --out " + (dir / "fit.csv").string());
    ASSERT_EQ(fit.exitCode, 0) << fit.err;
    const double a = firstLimit(readFileText(dir / "ref.csv"));
    EXPECT_GT(a, 0.0);
    EXPECT_NEAR(firstLimit(readFileText(dir / "fit.csv")), a, 0.01 * a);
    // y1 has one mode only: with --modes 2 its fit must fail with a named error.
    auto bad = runCli("lobes --modes 2 --tool-frf-x " + (dir / "x.csv").string() + " --tool-frf-y " + (dir / "y1.csv").string() +
                      common);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("y1.csv"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("no resonance peak"), std::string::npos) << bad.err;
    std::filesystem::remove_all(dir);
}

TEST(CliLobesToolFrf, BadFilesExitWith2)
{
    const auto dir = makeTempDir("lobesfrfbad");
    writeFrfCsv(dir / "x.csv", {{0.40, 83.0, 30.1e6}});
    writeFile(dir / "broken.csv", "f_Hz,re,im\n100,abc,0\n");
    const std::string common = " --cut " + kSamples + "cut-table1.json --rpm-min 2800 --rpm-max 2900 --rpm-step 100";
    auto r = runCli("lobes --tool-frf-x " + (dir / "x.csv").string() + " --tool-frf-y " + (dir / "broken.csv").string() + common);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("broken.csv"), std::string::npos) << r.err;
    r = runCli("lobes --tool-frf-x " + (dir / "x.csv").string() + " --tool-frf-y " + (dir / "missing.csv").string() + common);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("missing.csv"), std::string::npos) << r.err;
    r = runCli("lobes --tool-frf-x " + (dir / "x.csv").string() + common);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--tool-frf-y"), std::string::npos) << r.err;
    r = runCli("lobes --tool " + kSamples + "tool-table1.json --tool-frf-x " + (dir / "x.csv").string() + " --tool-frf-y " +
               (dir / "x.csv").string() + common);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("alternatives"), std::string::npos) << r.err;
    r = runCli("lobes" + common);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--tool"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}

TEST(CliLobesToolFrf, RigidYToolJsonIsAccepted)
{
    // The Insperger–Stépán one-direction benchmark (modes_y: []; m = 0.03993 kg, f_n = 922 Hz, ζ = 0.011 →
    // k = m(2πf_n)², c = 2ζ√(km)) at 7500 min⁻¹, the bottom of a lobe:
    // tests/data/machining/insperger_1dof_ref.out gives 0.3218 mm (120 steps); 3 % as in
    // tests/core/machining/test_one_direction_benchmark.cpp.
    const auto dir = makeTempDir("lobesrigidy");
    writeFile(dir / "tool.json", R"({"modes_x":[{"mass_kg":0.03993,"damping_Ns_per_m":5.0890,"stiffness_N_per_m":1.34005e6}],
                                     "modes_y":[]})");
    writeFile(dir / "cut.json", R"({"teeth":2,"Kt_N_per_m2":6e8,"Kr_N_per_m2":2e8,"radial_immersion":1.0,"milling":"down"})");
    auto r = runCli("lobes --tool " + (dir / "tool.json").string() + " --cut " + (dir / "cut.json").string() +
                    " --rpm-min 7500 --rpm-max 7500 --rpm-step 10 --steps-per-period 120 --out " + (dir / "l.csv").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NEAR(firstLimit(readFileText(dir / "l.csv")), 0.3218e-3, 0.03 * 0.3218e-3);
    std::filesystem::remove_all(dir);
}

// A tap-test FRF measured with an exponential window exp(−σt) is H(jω + σ) (docs/machining.md "Tap test");
// lobes takes the window's damping 2mσ back out of the fitted mode when the file carries
// exp_window_decay_1_s, so the lobes equal those of the unwindowed tool. Without the key the same file
// gives lobes ~10 % too optimistic (c_w = 83 + 2·0.40·10 = 91 N·s/m), which shows the correction acts.
TEST(CliLobesToolFrf, ExponentialWindowDampingIsRemovedFromTheFit)
{
    const auto dir = makeTempDir("lobesexp");
    const Mode mode{0.40, 83.0, 30.1e6};
    const double sigma = 10.0;
    auto write = [&](const std::filesystem::path& p, bool withKey) {
        std::ofstream f(p);
        if (withKey)
            f << "# exp_window_decay_1_s=" << axistune::model::formatNumber(sigma, 17) << "\n";
        f << "f_Hz,re,im,mag_dB,phase_deg,coherence,valid\n";
        const auto g = [](double v) { return axistune::model::formatNumber(v, 17); };
        for (int i = 0; i < 400; ++i) {
            const double hz = 500.0 * std::pow(6.0, i / 399.0);
            const std::complex<double> s(sigma, 2.0 * std::numbers::pi * hz);
            const std::complex<double> h = 1.0 / (mode.m * s * s + mode.c * s + mode.k);
            f << g(hz) << ',' << g(h.real()) << ',' << g(h.imag()) << ',' << g(20.0 * std::log10(std::abs(h))) << ','
              << g(std::arg(h) * 180.0 / std::numbers::pi) << ",,1\n";
        }
    };
    write(dir / "w.csv", true);
    write(dir / "w_nokey.csv", false);
    const std::string common = " --cut " + kSamples + "cut-table1.json --rpm-min 2800 --rpm-max 2800 --rpm-step 10 --steps-per-period 40";
    auto ref = runCli("lobes --tool " + kSamples + "tool-table1.json" + common + " --out " + (dir / "ref.csv").string());
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    auto fit = runCli("lobes --tool-frf-x " + (dir / "w.csv").string() + " --tool-frf-y " + (dir / "w.csv").string() +
                      common + " --out " + (dir / "fit.csv").string());
    ASSERT_EQ(fit.exitCode, 0) << fit.err;
    auto raw = runCli("lobes --tool-frf-x " + (dir / "w_nokey.csv").string() + " --tool-frf-y " +
                      (dir / "w_nokey.csv").string() + common + " --out " + (dir / "raw.csv").string());
    ASSERT_EQ(raw.exitCode, 0) << raw.err;
    const double a = firstLimit(readFileText(dir / "ref.csv"));
    EXPECT_NEAR(firstLimit(readFileText(dir / "fit.csv")), a, 0.01 * a);
    EXPECT_GT(firstLimit(readFileText(dir / "raw.csv")), 1.05 * a);
}
