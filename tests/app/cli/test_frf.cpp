// SPDX-License-Identifier: GPL-3.0-or-later
// End-to-end tests of `axistune-cli frf` (docs/frequency-response.md).
#include <cmath>
#include <complex>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <vector>

#include "tests/NumberText.h"
#include "tests/app/cli/CliRunner.h"

using axistune::testing::makeTempDir;
using axistune::testing::runCli;

namespace {

const std::string kData = AXISTUNE_TEST_DATA_DIR;

std::vector<std::vector<double>> readRows(const std::string& path, std::vector<std::string>* header = nullptr)
{
    std::ifstream f(path);
    std::vector<std::vector<double>> rows;
    std::string line;
    bool haveHeader = false;
    while (std::getline(f, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        std::stringstream ss(line);
        std::vector<std::string> cells;
        for (std::string c; std::getline(ss, c, ',');)
            cells.push_back(c);
        if (!line.empty() && line.back() == ',')
            cells.emplace_back();
        if (!haveHeader) {
            haveHeader = true;
            if (header)
                *header = cells;
            continue;
        }
        std::vector<double> r;
        for (const auto& c : cells)
            r.push_back(c.empty() ? std::nan("") : axistune::testutil::stod(c));
        rows.push_back(r);
    }
    return rows;
}

std::string writeText(const std::filesystem::path& p, const std::string& text)
{
    std::ofstream(p) << text;
    return p.string();
}

}  // namespace

TEST(CliFrf, WelchH1AndH2EqualScipyReference)
{
    const auto dir = makeTempDir("frf");
    for (const std::string est : {"h1", "h2"}) {
        const auto out = (dir / ("frf_" + est + ".csv")).string();
        const auto r = runCli("frf --in " + kData + "/welch/input.csv --input x --output y --nperseg 500 --noverlap 100"
                              " --estimator " + est + " --out " + out);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.out.find("\"points\":250"), std::string::npos) << r.out;
        std::vector<std::string> header;
        const auto got = readRows(out, &header);
        ASSERT_EQ(header, (std::vector<std::string>{"f_Hz", "re", "im", "mag_dB", "phase_deg", "coherence", "valid"}));
        const auto ref = readRows(kData + "/welch/ref_hann500_ov100.csv");
        ASSERT_EQ(got.size() + 1, ref.size());  // DC omitted
        const int re = est == "h1" ? 5 : 7;
        for (std::size_t i = 0; i < got.size(); ++i) {
            const auto& g = got[i];
            const auto& s = ref[i + 1];
            EXPECT_EQ(g[0], s[0]);
            const double mag = std::hypot(s[re], s[re + 1]);
            EXPECT_LE(std::hypot(g[1] - s[re], g[2] - s[re + 1]), 1e-9 * mag) << i;
            EXPECT_NEAR(g[3], 20 * std::log10(mag), 1e-8);
            EXPECT_NEAR(g[5], s[9], 1e-9 * s[9]);
            EXPECT_EQ(g[6], 1.0);
        }
    }
    std::filesystem::remove_all(dir);
}

TEST(CliFrf, SweepMultiSweepAndConventional)
{
    // response 0.7·sin(θ − 40°) to excitation sin(θ): 2900 Hz multi-sweep (M = 1) and 500 Hz
    // conventional; the stdout JSON path is exercised too.
    const double fs = 4000, pi = std::numbers::pi;
    std::ostringstream t;
    t << "# fs_Hz=4000\n# amplitude=1\nfreq_Hz,phase_offset_deg,sample,excitation,response\n";
    t.precision(17);
    for (double psi : {0.0, 120.0, -120.0}) {
        for (int k = -3; k <= 1; ++k) {
            const double th = 2 * pi * 2900 * k / fs + psi * pi / 180;
            t << 2900 << ',' << psi << ',' << k << ',' << std::sin(th) << ',' << 0.7 * std::sin(th - 40 * pi / 180) << '\n';
        }
    }
    for (int k = 0; k < 40; ++k) {  // 5 whole periods of 500 Hz
        const double th = 2 * pi * 500 * k / fs;
        t << 500 << ',' << 0 << ',' << k << ',' << std::sin(th) << ',' << 0.7 * std::sin(th - 40 * pi / 180) << '\n';
    }
    const auto dir = makeTempDir("frfsweep");
    const auto in = writeText(dir / "sweep.csv", t.str());
    const auto out = (dir / "frf.csv").string();
    const auto r = runCli("frf --sweep " + in + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto rows = readRows(out);
    ASSERT_EQ(rows.size(), 2u);
    for (const auto& row : rows) {
        EXPECT_NEAR(std::hypot(row[1], row[2]), 0.7, 1e-12) << row[0];
        EXPECT_NEAR(row[4], -40.0, 1e-9) << row[0];
        EXPECT_TRUE(std::isnan(row[5]));  // coherence empty
        EXPECT_EQ(row[6], 1.0);
    }
    EXPECT_EQ(rows[0][0], 500.0);
    EXPECT_EQ(rows[1][0], 2900.0);
    const auto j = runCli("frf --sweep " + in);
    ASSERT_EQ(j.exitCode, 0) << j.err;
    EXPECT_NE(j.out.find("\"f_Hz\":[500.0,2900.0]"), std::string::npos) << j.out;
    // A sweep has no coherence: the column is left out and named (docs/formats.md "Undefined values").
    EXPECT_EQ(j.out.find("\"coherence\":["), std::string::npos) << j.out;
    EXPECT_NE(j.out.find("\"undefined\":{\"coherence\":\"coherence not estimated"), std::string::npos) << j.out;
    EXPECT_EQ(j.out.find("null"), std::string::npos) << j.out;
    std::filesystem::remove_all(dir);
}

TEST(CliFrf, ConventionalAboveNyquistMarkedInvalid)
{
    std::ostringstream t;
    t << "# fs_Hz=4000\nfreq_Hz,phase_offset_deg,sample,excitation,response\n";
    for (int k = 0; k < 40; ++k)
        t << 2900 << ",0," << k << ',' << std::sin(2 * std::numbers::pi * 2900 * k / 4000.0) << ",0.5\n";
    const auto dir = makeTempDir("frfinv");
    const auto out = (dir / "frf.csv").string();
    const auto r = runCli("frf --sweep " + writeText(dir / "s.csv", t.str()) + " --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto rows = readRows(out);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0][6], 0.0);
    std::filesystem::remove_all(dir);
}

TEST(CliFrf, BadInputGivesClearMessageAndExitCode2)
{
    const auto dir = makeTempDir("frfbad");
    auto capture = [&](const std::string& name, const std::string& body) { return writeText(dir / name, body); };
    // 64 rows at 1 kHz; `cell(row, col)` may replace one cell (row 0 = first data row = file line 2)
    auto makeCapture = [](int badRow, int badCol, const std::string& badCell) {
        std::ostringstream t;
        t.precision(17);
        t << "t_s,u_Nm,v_rad_s\n";
        for (int i = 0; i < 64; ++i) {
            std::ostringstream c[3];
            for (auto& x : c)
                x.precision(17);
            c[0] << i * 0.001;
            c[1] << std::sin(i * 0.3);
            c[2] << std::cos(i * 0.3);
            for (int k = 0; k < 3; ++k)
                t << (k ? "," : "") << (i == badRow && k == badCol ? badCell : c[k].str());
            t << '\n';
        }
        return t.str();
    };
    const auto ok = capture("ok.csv", makeCapture(-1, 0, ""));
    const auto o = " --out " + (dir / "o.csv").string();

    auto r = runCli("frf --in " + ok + " --input u_Nm --output nope --nperseg 16" + o);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("no column 'nope'"), std::string::npos) << r.err;

    r = runCli("frf --in " + capture("nonnum.csv", makeCapture(5, 1, "abc")) + " --input u_Nm --output v_rad_s --nperseg 16" + o);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("line 7"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("u_Nm"), std::string::npos) << r.err;

    r = runCli("frf --in " + capture("nan.csv", makeCapture(10, 2, "nan")) + " --input u_Nm --output v_rad_s --nperseg 16" + o);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("line 12"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("v_rad_s"), std::string::npos) << r.err;

    r = runCli("frf --in " + ok + " --input u_Nm --output v_rad_s --nperseg 128" + o);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("fewer than nperseg"), std::string::npos) << r.err;

    r = runCli("frf --in " + capture("jitter.csv", makeCapture(20, 0, "0.0205")) + " --input u_Nm --output v_rad_s --nperseg 16" + o);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("not uniformly sampled"), std::string::npos) << r.err;

    r = runCli("frf --in " + ok + " --sweep " + ok + o);
    EXPECT_EQ(r.exitCode, 2);
    r = runCli("frf --sweep " + capture("sweep.csv", "freq_Hz,phase_offset_deg,sample,excitation,response\n10,0,0,1,1\n") + o);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("fs_Hz"), std::string::npos) << r.err;
    r = runCli("frf --in " + (dir / "missing.csv").string() + " --input a --output b" + o);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("missing.csv"), std::string::npos);

    // success with the same file: fs from the time column
    r = runCli("frf --in " + ok + " --input u_Nm --output v_rad_s --nperseg 16" + o);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    // the time column steps 1 ms: 1 kHz (a whole number: a JSON integer)
    EXPECT_NE(r.out.find("\"fs_Hz\":1000,"), std::string::npos) << r.out;
    std::filesystem::remove_all(dir);
}

TEST(CliFrf, MarginsOfAClosedLoopFrf)
{
    // T = L/(1+L) with L = 2π·50/s (integrator): crossover 50 Hz, phase margin 90°, no phase
    // crossover, peak sensitivity → 1 from below at high frequency.
    const auto dir = makeTempDir("frfmargins");
    std::ostringstream s;
    s.precision(17);
    s << "# fs_Hz=100000\nfreq_Hz,phase_offset_deg,sample,excitation,response\n";
    for (int i = 0; i < 60; ++i) {
        const double f = std::pow(10.0, 0.5 + 2.0 * i / 59);
        const std::complex<double> L = 2 * std::numbers::pi * 50 / std::complex<double>(0, 2 * std::numbers::pi * f);
        const auto T = L / (1.0 + L);
        for (double psi : {0.0, 120.0, -120.0}) {
            for (int k = 0; k < 3; ++k) {
                const double th = 2 * std::numbers::pi * f * k / 100000.0 + psi * std::numbers::pi / 180;
                s << f << ',' << psi << ',' << k << ',' << std::sin(th) << ',' << std::abs(T) * std::sin(th + std::arg(T)) << '\n';
            }
        }
    }
    const auto r = runCli("frf --sweep " + writeText(dir / "s.csv", s.str()) + " --margins complementary --out "
                          + (dir / "o.csv").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto pm = r.out.find("\"phase_margin_deg\":");
    ASSERT_NE(pm, std::string::npos) << r.out;
    EXPECT_NEAR(axistune::testutil::stod(r.out.substr(pm + 19)), 90.0, 1e-6);
    const auto pf = r.out.find("\"phase_margin_freq_Hz\":");
    ASSERT_NE(pf, std::string::npos);
    EXPECT_NEAR(axistune::testutil::stod(r.out.substr(pf + 23)), 50.0,
                1e-6); // log|L| is linear in log f: interpolation is exact
    // No phase crossover: no gain margin, left out and named (docs/formats.md "Undefined values").
    const auto m = nlohmann::json::parse(r.out)["margins"];
    EXPECT_FALSE(m.contains("gain_margin_dB")) << r.out;
    EXPECT_EQ(m["undefined"]["gain_margin_dB"].get<std::string>().rfind("no phase crossover", 0), 0u) << r.out;
    EXPECT_EQ(r.out.find("null"), std::string::npos) << r.out;
    std::filesystem::remove_all(dir);
}
