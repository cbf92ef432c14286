// SPDX-License-Identifier: GPL-3.0-or-later
// lobes --tool-frf-x/-y on the real measured tool-tip receptance H11 (../shared/data/real, issue 19): the
// automatic fit is accepted and gives the limit depth the zero-order computation on the measured FRF gives
// (see tests/core/machining/test_tool_fit_real.cpp for the modes), and a fit over the whole file with one or
// two modes is refused with the reason and exit 2, never turned into lobes.
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>
#include <string>
#include <nlohmann/json.hpp>

#include "tests/app/cli/CliRunner.h"
#include "tests/core/machining/RealToolFrf.h"

using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {

const std::string kSamples = std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/";

std::string num(double v)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return {buf, r.ptr};
}

// H11 as an AxisTune FRF CSV (f_Hz,re,im,mag_dB,phase_deg,coherence,valid).
bool writeH11(const std::filesystem::path& p)
{
    const auto frf = axistune::testing::readRealToolFrf(1);
    if (frf.size() != 5001)
        return false;
    std::ofstream f(p);
    f << "f_Hz,re,im,mag_dB,phase_deg,coherence,valid\n";
    for (std::size_t i = 0; i < frf.size(); ++i) {
        const auto h = frf.h[i];
        const double mag = std::abs(h);
        f << num(frf.freqHz[i]) << ',' << num(h.real()) << ',' << num(h.imag()) << ','
          << num(mag > 0.0 ? 20.0 * std::log10(mag) : -400.0) << ',' << num(std::arg(h) * 180.0 / std::numbers::pi)
          << ",,1\n";
    }
    return static_cast<bool>(f);
}

double minLimit(const std::string& csvText)
{
    std::istringstream csv(csvText);
    std::string line;
    std::getline(csv, line);
    double best = INFINITY;
    while (std::getline(csv, line)) {
        const auto c = line.find(',');
        double d = 0.0;
        if (std::from_chars(line.data() + c + 1, line.data() + line.size(), d).ec == std::errc())
            best = std::min(best, d);
    }
    return best;
}

} // namespace

TEST(CliLobesRealFrf, AutomaticFitOfH11GivesLobes)
{
    const auto dir = makeTempDir("lobesreal");
    ASSERT_TRUE(writeH11(dir / "h11.csv")) << axistune::testing::kRealToolFrfCsv;
    const std::string frfs =
        " --tool-frf-x " + (dir / "h11.csv").string() + " --tool-frf-y " + (dir / "h11.csv").string();
    // Speeds around the first lobes' bottoms of the 1068 Hz mode with 4 teeth (the wizard's default cut).
    const std::string common =
        " --cut " + kSamples + "cut-table1.json --rpm-min 2000 --rpm-max 6000 --rpm-step 50 --steps-per-period 80";
    auto r = runCli("lobes" + frfs + common + " --out " + (dir / "lobes.csv").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("3 mode(s) in the automatic band"), std::string::npos) << r.err;
    // The zero-order limit computed on the measured H11 (test_tool_fit_real.cpp) is 1.733 mm; 10 %.
    const double amin = minLimit(readFileText(dir / "lobes.csv"));
    EXPECT_NEAR(amin, 1.733e-3, 0.10 * 1.733e-3);
    std::filesystem::remove_all(dir);
}

TEST(CliLobesRealFrf, WholeFileOneAndTwoModesAreRefusedWithExit2)
{
    const auto dir = makeTempDir("lobesrealbad");
    ASSERT_TRUE(writeH11(dir / "h11.csv"));
    const std::string frfs =
        " --tool-frf-x " + (dir / "h11.csv").string() + " --tool-frf-y " + (dir / "h11.csv").string();
    const std::string common = " --cut " + kSamples + "cut-table1.json --rpm-min 2000 --rpm-max 6000 --rpm-step 500";
    for (const char* modes : {"1", "2"}) {
        auto r = runCli("lobes --band 0:5000 --modes " + std::string(modes) + frfs + common + " --out " +
                        (dir / "l.csv").string());
        EXPECT_EQ(r.exitCode, 2) << modes << " mode(s): " << r.err;
        EXPECT_NE(r.err.find("refused"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("h11.csv"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "l.csv"));
    }
    auto bad = runCli("lobes --band 3000:900" + frfs + common);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--band"), std::string::npos) << bad.err;
    bad = runCli("lobes --band 900-3000" + frfs + common);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("FMIN:FMAX"), std::string::npos) << bad.err;
    std::filesystem::remove_all(dir);
}
