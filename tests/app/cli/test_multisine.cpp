// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli capture --test frf --method multisine (issue 11, docs/multisine.md): the FRF file and
// summary of the embedded simulated drive, the 3.3 kHz mode of sim:dd-table above the observation
// Nyquist frequency, the same FRF over Modbus TCP through axistune-simdrive (test block with periods,
// phases and bands), and the option errors (exit 2).
#include "core/io/FrfCsv.h"

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/NumberText.h"
#include "tests/app/cli/CliRunner.h"
#include "tests/app/cli/SimDriveProcess.h"

using namespace axistune;
using axistune::testing::makeTempDir;
using axistune::testing::runCli;
using axistune::testing::SimDrive;

namespace {

double jsonNumber(const std::string& json, const std::string& key)
{
    const auto p = json.find("\"" + key + "\": ");
    return p == std::string::npos ? std::nan("") : axistune::testutil::stod(json.substr(p + key.size() + 4));
}

} // namespace

TEST(CliMultisine, DdTableLinearShowsThe3300HzModeWithACrestFactorBelowTwo)
{
    const auto dir = makeTempDir("multisine");
    const auto out = (dir / "frf.csv").string();
    auto r = runCli("capture --connect sim:dd-table --axis C --test frf --method multisine --fmin 20 --fmax 3900 "
                    "--spacing-hz 10 --linear --out " +
                    out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"method\": \"multisine\""), std::string::npos) << r.out;
    EXPECT_EQ(jsonNumber(r.out, "points"), 388.0);
    EXPECT_EQ(jsonNumber(r.out, "valid_points"), 388.0);
    EXPECT_LT(jsonNumber(r.out, "crest_factor"), 2.0);
    EXPECT_LE(jsonNumber(r.out, "motion_time_s"), 5.0);
    auto frf = io::readFrfCsvFile(out);
    ASSERT_TRUE(frf.ok()) << frf.error().detail;
    EXPECT_EQ(frf->metadata.text("method"), "multisine");
    EXPECT_EQ(frf->metadata.text("injection_hold_corrected"), "true");
    std::size_t peak = 0;
    for (std::size_t i = 0; i < frf->size(); ++i) {
        if (frf->freqHz[i] > 2600.0 && (frf->freqHz[peak] <= 2600.0 || std::abs(frf->h[i]) > std::abs(frf->h[peak])))
            peak = i;
    }
    EXPECT_NEAR(frf->freqHz[peak], 3300.0, 0.02 * 3300.0);
    EXPECT_LT(peak + 1, frf->size()); // a peak, not the end of the band
    std::filesystem::remove_all(dir);
}

// Over Modbus the request travels in the test block (method 3, periods, phases, two bands) and the
// server's drive evaluates it: the FRF equals the embedded drive's with the same seed.
TEST(CliMultisine, ModbusEqualsTheEmbeddedDriveWithTheSameSeed)
{
    SimDrive srv("--preset dd-table --seed 5");
    ASSERT_GT(srv.port(), 0) << srv.log();
    const auto dir = makeTempDir("multisine-modbus");
    const auto remote = (dir / "remote.csv").string(), local = (dir / "local.csv").string();
    const std::string args = " --axis C --test frf --method multisine --band 40:400:20 --band 400:3900:100 --periods 3 "
                             "--phases schroeder --amplitude-pct 4 --seed 5 --out ";
    auto r = runCli("capture --connect " + srv.uri() + args + remote);
    ASSERT_EQ(r.exitCode, 0) << r.err << srv.log();
    r = runCli("capture --connect sim:dd-table" + args + local);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(jsonNumber(r.out, "periods"), 3.0);
    auto a = io::readFrfCsvFile(remote);
    auto b = io::readFrfCsvFile(local);
    ASSERT_TRUE(a.ok() && b.ok());
    ASSERT_EQ(a->size(), b->size());
    ASSERT_EQ(b->size(), 18u + 35u); // 20 Hz lines 46.7 … 386.7 Hz, 100 Hz lines 406.7 … 3806.7 Hz
    for (std::size_t i = 0; i < b->size(); ++i) {
        EXPECT_EQ(a->freqHz[i], b->freqHz[i]);
        EXPECT_LE(std::abs(a->h[i] - b->h[i]), 1e-9 * std::abs(b->h[i])) << b->freqHz[i] << " Hz";
        EXPECT_EQ(a->valid[i], b->valid[i]);
    }
    EXPECT_EQ(a->metadata.text("method"), "multisine");
    EXPECT_EQ(a->metadata.text("phases"), "schroeder");
    EXPECT_EQ(a->metadata.number("periods").value(), 3.0);
    // A shaped spectrum does not fit the test block: refused before anything moves.
    {
        std::ofstream shape(dir / "shape.csv");
        shape << "f_Hz,mag_dB,phase_deg\n100,0,0\n1000,-20,0\n";
    }
    r = runCli("capture --connect " + srv.uri() + args + remote + " --shape-from " + (dir / "shape.csv").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("cannot be sent over Modbus"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}

TEST(CliMultisine, ShapedFromAPreviousFrfRuns)
{
    const auto dir = makeTempDir("multisine-shape");
    const auto shape = (dir / "shape.csv").string(), out = (dir / "frf.csv").string();
    {
        std::ofstream s(shape);
        s << "f_Hz,mag_dB,phase_deg\n100,0,0\n1000,-20,0\n3000,-60,0\n";
    }
    auto r = runCli("capture --connect sim:dd-table --axis C --test frf --method multisine --fmin 100 --fmax 3000 "
                    "--spacing-hz 50 --linear --shape-from " +
                    shape + " --shape-range-db 30 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_GT(jsonNumber(r.out, "valid_points"), 50.0);
    std::filesystem::remove_all(dir);
}

TEST(CliMultisine, BadOptionsExitTwo)
{
    const auto dir = makeTempDir("multisine-bad"); // nothing is written there, unless a refusal fails
    const std::string base =
        "capture --connect sim:dd-table --axis C --test frf --out " + (dir / "never-written.csv").string() + " ";
    struct Case {
        std::string args, message;
    };
    const Case cases[] = {
        {"--method multisine --band 10:100", "FMIN:FMAX:SPACING"},
        {"--method multisine --band a:100:10", "FMIN:FMAX:SPACING"},
        {"--method multisweep --periods 4", "only for --method multisine"},
        {"--method multisine --phases random", "clipping or schroeder"},
        {"--method multisine --periods -2", "--periods"},
        {"--method multisine --fmax 4000", "below the trace rate"},
        {"--method multisine --amplitude-pct 60", "refused"},
        {"--method multisine --shape-from /nonexistent/frf.csv", "--shape-from"},
    };
    for (const auto& c : cases) {
        auto r = runCli(base + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
    }
}
